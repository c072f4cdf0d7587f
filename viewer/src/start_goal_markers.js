// The path's start and goal drawn apart: translucent copies of the robot at the first state
// (green) and the last (red), so both ends of the motion are in view whatever state is shown.
import * as THREE from 'three';

const COLOURS = { start: 0x2e9e4f, goal: 0xc0392b };

export function createStartGoalMarkers(scene, robot) {
  const group = new THREE.Group();
  group.name = 'start and goal';
  scene.add(group);
  const materials = Object.fromEntries(Object.entries(COLOURS).map(([end, colour]) => [end,
    new THREE.MeshStandardMaterial({ color: colour, transparent: true, opacity: 0.28, depthWrite: false, roughness: 0.8 })]));
  return {
    group,
    /// Leaves the robot at restorePositions; returns the number of copied meshes.
    rebuild(states, handOnly, restorePositions) {
      group.clear();
      for (const [end, index] of [['start', 0], ['goal', states.length - 1]]) {
        robot.setConfiguration(states[index]);
        for (const mesh of robot.visualMeshes(handOnly)) {
          const copy = new THREE.Mesh(mesh.geometry, materials[end]);
          copy.matrixAutoUpdate = false;
          copy.matrix.copy(mesh.matrixWorld);
          copy.userData.end = end;
          group.add(copy);
        }
      }
      robot.setConfiguration(restorePositions);
      return group.children.length;
    },
    setVisible(visible) {
      group.visible = visible;
    },
  };
}

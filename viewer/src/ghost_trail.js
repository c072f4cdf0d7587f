// Translucent copies of the robot (or its hand) at every N-th path state: the shape of the whole
// motion at a glance. Copies share the robot's geometry and are frozen at their world pose. A
// page of several paths gives each path's trail the path's colour.
import * as THREE from 'three';

export function createGhostTrail(scene, robot, colour = 0x5a7bb5) {
  const group = new THREE.Group();
  group.name = 'ghost trail';
  scene.add(group);
  const material = new THREE.MeshStandardMaterial({
    color: colour, transparent: true, opacity: 0.18, depthWrite: false, roughness: 0.9,
  });
  return {
    group,
    /// mode: 'off' | 'hand' | 'robot'. Leaves the robot at restorePositions.
    rebuild(states, every, mode, restorePositions) {
      group.clear();
      if (mode === 'off' || states.length === 0) return 0;
      const step = Math.max(1, Math.floor(every));
      const indices = [];
      for (let i = 0; i < states.length; i += step) indices.push(i);
      if (indices[indices.length - 1] !== states.length - 1) indices.push(states.length - 1);
      for (const index of indices) {
        robot.setConfiguration(states[index]);
        for (const mesh of robot.visualMeshes(mode === 'hand')) {
          const ghost = new THREE.Mesh(mesh.geometry, material);
          ghost.matrixAutoUpdate = false;
          ghost.matrix.copy(mesh.matrixWorld);
          group.add(ghost);
        }
      }
      robot.setConfiguration(restorePositions);
      return indices.length;
    },
  };
}

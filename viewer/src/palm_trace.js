// The palm's path through space: a line through the palm frame's origin at every state, the
// workspace view of the joint-space path (the arm's part of the motion at a glance), in the
// path's colour when the page shows several.
import * as THREE from 'three';

export function createPalmTrace(scene, robot, colour = 0x7b3fa0) {
  // Drawn over everything: the palm frame's origin is inside the palm's own geometry.
  const material = new THREE.LineBasicMaterial({ color: colour, depthTest: false, transparent: true });
  let line = null;
  return {
    /// Leaves the robot at restorePositions; returns the number of points.
    rebuild(states, restorePositions) {
      if (line) scene.remove(line);
      const points = states.map((state) => {
        robot.setConfiguration(state);
        robot.object.updateMatrixWorld(true);
        return robot.palmPosition().clone();
      });
      robot.setConfiguration(restorePositions);
      line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(points), material);
      line.name = 'palm trace';
      line.renderOrder = 10;
      scene.add(line);
      return points.length;
    },
    setVisible(visible) {
      if (line) line.visible = visible;
    },
  };
}

// The robot from the URDF text in the viewer data, placed at the task's base pose, posed by
// configurations in the path's joint order. Coupled (mimic) joints follow their source through
// urdf-loader, exactly as the URDF defines them.
import * as THREE from 'three';
import URDFLoader from 'urdf-loader';

export function createRobot(scene, robotData, base, notes) {
  const loader = new URDFLoader();
  loader.loadMeshCb = (path, manager, done) => {
    notes.push(`robot mesh ${path} not shown (the viewer draws the URDF's primitives)`);
    done(null);
  };
  const robot = loader.parse(robotData.urdf);
  robot.position.fromArray(base.position);
  robot.quaternion.fromArray(base.quaternion);
  scene.add(robot);

  const names = robotData.joint_names;
  for (const name of names) if (!robot.joints[name]) throw new Error(`the URDF has no joint ${name}`);
  const palm = robotData.palm_link ? robot.links[robotData.palm_link] : null;

  return {
    object: robot,
    names,
    palm,
    /// Positions in the order of robot.joint_names (rad / m).
    setConfiguration(positions) {
      for (let i = 0; i < names.length; i += 1) robot.setJointValue(names[i], positions[i]);
      robot.updateMatrixWorld(true);
    },
    setJoint(name, value) {
      robot.setJointValue(name, value);
    },
    jointValue(name) {
      const joint = robot.joints[name];
      if (!joint) throw new Error(`no joint ${name}`);
      return joint.angle;
    },
    jointType(name) {
      return robot.joints[name].jointType;
    },
    /// The visual meshes of the whole robot, or of the hand (the palm link and all below it).
    visualMeshes(handOnly) {
      const root = handOnly && palm ? palm : robot;
      const meshes = [];
      root.traverse((child) => { if (child.isMesh) meshes.push(child); });
      return meshes;
    },
    palmPosition() {
      robot.updateMatrixWorld(true);
      return (palm || robot).getWorldPosition(new THREE.Vector3());
    },
    /// Unit vector along the forearm towards the hand: from the first ancestor of the palm at
    /// least 5 cm away (fixed joints often stack frames at one point).
    handDirection() {
      robot.updateMatrixWorld(true);
      const at = (palm || robot).getWorldPosition(new THREE.Vector3());
      for (let node = (palm || robot).parent; node; node = node.parent) {
        const from = node.getWorldPosition(new THREE.Vector3());
        if (from.distanceTo(at) > 0.05) return at.sub(from).normalize();
      }
      return new THREE.Vector3(1, 0, 0);
    },
  };
}

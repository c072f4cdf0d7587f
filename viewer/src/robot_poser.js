// The robot from the URDF text in the viewer data, placed at the task's base pose, posed by
// configurations in the path's joint order. Coupled (mimic) joints follow their source through
// urdf-loader, exactly as the URDF defines them. Visual meshes (STL, OBJ, COLLADA) come from the
// folder (robot.mesh_files maps each URDF reference to its copy); a link whose visual cannot be
// loaded shows its collision geometry instead.
import * as THREE from 'three';
import URDFLoader from 'urdf-loader';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { ColladaLoader } from 'three/examples/jsm/loaders/ColladaLoader.js';

/// Loads one mesh file; calls done(object) or failed(reason).
export function loadMeshFile(url, manager, material, done, failed) {
  const onError = (error) => failed(error && error.message ? error.message : String(error));
  if (/\.stl$/i.test(url)) new STLLoader(manager).load(url, (geometry) => done(new THREE.Mesh(geometry, material)), undefined, onError);
  else if (/\.obj$/i.test(url)) {
    new OBJLoader(manager).load(url, (group) => {
      group.traverse((child) => { if (child.isMesh) child.material = material; });
      done(group);
    }, undefined, onError);
  } else if (/\.dae$/i.test(url)) new ColladaLoader(manager).load(url, (collada) => done(collada.scene), undefined, onError);
  else failed('the viewer draws STL, OBJ and COLLADA meshes');
}

/// Links whose visual stayed empty (a mesh that did not load) show their collision geometry.
function showCollidersOfEmptyVisuals(robot) {
  let fallbacks = 0;
  for (const link of Object.values(robot.links)) {
    const parts = link.children.filter((c) => c.isURDFVisual || c.isURDFCollider);
    const missing = parts.some((c) => c.isURDFVisual && c.children.length === 0);
    for (const c of parts) if (c.isURDFCollider) c.visible = missing;
    if (missing) fallbacks += 1;
  }
  return fallbacks;
}

export function createRobot(scene, robotData, base, notes, onChange = () => {}) {
  const meshFiles = robotData.mesh_files || {};
  const status = { pending: 0, loaded: 0, failed: 0, fallbackLinks: 0 };
  const loader = new URDFLoader();
  loader.parseCollision = true;
  // References reach the callback as the URDF writes them (package://, file://, relative).
  loader.packages = (name) => `package://${name}`;
  loader.workingPath = '';
  let robot = null;
  const settle = () => {
    status.pending -= 1;
    if (status.pending === 0 && robot) {
      status.fallbackLinks = showCollidersOfEmptyVisuals(robot);
      onChange();
    }
  };
  loader.loadMeshCb = (path, manager, material, onComplete) => {
    status.pending += 1;
    const failed = (reason) => {
      status.failed += 1;
      notes.push(`robot mesh ${path} not shown (${reason}): its collision geometry is drawn instead`);
      onComplete(null);
      settle();
    };
    const url = meshFiles[path];
    if (!url) {
      failed('not found when pmdplan view wrote the folder: a package:// path needs --package-path or PMDPLAN_PACKAGE_PATH');
      return;
    }
    loadMeshFile(url, manager, material, (object) => {
      status.loaded += 1;
      onComplete(object);
      settle();
    }, (reason) => failed(`${reason}; serve the folder with pmdplan view --serve to load meshes`));
  };
  robot = loader.parse(robotData.urdf);
  status.fallbackLinks = showCollidersOfEmptyVisuals(robot);
  robot.position.fromArray(base.position);
  robot.quaternion.fromArray(base.quaternion);
  scene.add(robot);
  for (const [name, value] of Object.entries(robotData.held_joints || {})) robot.setJointValue(name, value);

  const names = robotData.joint_names;
  for (const name of names) if (!robot.joints[name]) throw new Error(`the URDF has no joint ${name}`);
  const palm = robotData.palm_link ? robot.links[robotData.palm_link] : null;

  return {
    object: robot,
    /// Robot meshes: pending, loaded, failed, and links drawn from collision geometry instead.
    meshStatus() { return { ...status }; },
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

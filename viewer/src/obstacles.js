// The task's obstacles from the viewer data: primitives built here, meshes loaded from the
// folder (which needs the folder served over HTTP: browsers refuse file:// fetches).
import * as THREE from 'three';
import { loadMeshFile } from './robot_poser.js';

const OBSTACLE_COLOUR = 0xc9c1b3;
const TARGET_COLOUR = 0x4f9a45;

function primitiveGeometry(shape) {
  switch (shape.type) {
    case 'box': return new THREE.BoxGeometry(shape.size[0], shape.size[1], shape.size[2]);
    // three.js cylinders run along y; the task's along z.
    case 'cylinder': return new THREE.CylinderGeometry(shape.radius, shape.radius, shape.length, 48).rotateX(Math.PI / 2);
    case 'sphere': return new THREE.SphereGeometry(shape.radius, 32, 16);
    default: return null;
  }
}

function loadMesh(shape, material, parent, notes, onChange) {
  const url = shape.file;
  loadMeshFile(url, undefined, material, (object) => {
    object.scale.set(shape.scale[0], shape.scale[1], shape.scale[2]);
    parent.add(object);
    onChange();
  }, (reason) => {
    notes.push(`mesh ${url} not shown (${reason}; serve the folder with pmdplan view --serve to load meshes)`);
    onChange();
  });
}

/// Adds the obstacles to `scene`; returns {group, byName}. Problems go into `notes`; `onChange` is
/// called when a mesh arrives later.
export function addObstacles(scene, task, notes, onChange) {
  const group = new THREE.Group();
  group.name = 'obstacles';
  const byName = new Map();
  for (const obstacle of task.obstacles) {
    const isTarget = obstacle.name === task.target;
    const material = new THREE.MeshStandardMaterial({
      color: isTarget ? TARGET_COLOUR : OBSTACLE_COLOUR, roughness: 0.85, metalness: 0.0,
    });
    const holder = new THREE.Group();
    holder.name = obstacle.name;
    holder.position.fromArray(obstacle.position);
    holder.quaternion.fromArray(obstacle.quaternion);
    const geometry = primitiveGeometry(obstacle.shape);
    if (geometry) {
      holder.add(new THREE.Mesh(geometry, material));
      const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 30),
        new THREE.LineBasicMaterial({ color: 0x6f6a60, transparent: true, opacity: 0.5 }));
      holder.add(edges);
    } else if (obstacle.shape.type === 'mesh') {
      loadMesh(obstacle.shape, material, holder, notes, onChange);
    } else {
      notes.push(`obstacle ${obstacle.name}: unknown shape ${obstacle.shape.type}`);
    }
    group.add(holder);
    byName.set(obstacle.name, holder);
  }
  scene.add(group);
  return { group, byName };
}

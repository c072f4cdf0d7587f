// Per state, from the viewer data (the exact checker's answers, computed by `pmdplan view`): the
// links in collision drawn red, and the robot's clearance to the obstacles shown next to the state.
import * as THREE from 'three';
import { byId } from './dom.js';

const COLLIDING = new THREE.MeshStandardMaterial({ color: 0xe0201b, emissive: 0x600000, roughness: 0.6 });

export function createCollisionHighlight(robotObject, path) {
  const label = byId('clearance-label');
  const original = new Map();  // mesh -> its own material while it is red
  const clearance = path.clearance || [];
  const colliding = path.colliding_links || [];
  let minimum = Infinity;
  clearance.forEach((value) => { minimum = Math.min(minimum, value); });
  return {
    show(state) {
      for (const [mesh, material] of original) mesh.material = material;
      original.clear();
      const links = colliding[state] || [];
      for (const name of links) {
        const link = robotObject.links ? robotObject.links[name] : null;
        if (!link) continue;
        link.traverse((child) => {
          // Only the link's own meshes: child links have their own entries.
          if (child.isMesh && !original.has(child)) {
            original.set(child, child.material);
            child.material = COLLIDING;
          }
        });
      }
      if (clearance.length === 0) label.textContent = '';
      else if (links.length > 0) label.textContent = `in collision: ${links.join(', ')}`;
      else label.textContent = `clearance ${(1000 * clearance[state]).toFixed(1)} mm (path minimum ${(1000 * minimum).toFixed(1)} mm)`;
      label.classList.toggle('colliding', links.length > 0);
    },
    collidingMeshes: () => original.size,
  };
}

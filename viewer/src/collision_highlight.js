// Per state, from the viewer data (the grasp rule's answers, computed by `pmdplan view`): the links
// in collision drawn red, the links in allowed grasp contact (a hand link touching the target
// while the hand closes) drawn cyan, and the robot's clearance over the pairs that count shown
// next to the state; and the path's verdict by the same rule as `pmdplan validate`.
import * as THREE from 'three';
import { byId } from './dom.js';

const COLLIDING = new THREE.MeshStandardMaterial({ color: 0xe0201b, emissive: 0x600000, roughness: 0.6 });
const CONTACT = new THREE.MeshStandardMaterial({ color: 0x00b8d4, emissive: 0x003a44, roughness: 0.6 });
export const COLLISION_COLOUR = '#e0201b';
export const CONTACT_COLOUR = '#00b8d4';

const mm = (metres) => `${(1000 * metres).toFixed(1)} mm`;

/// What a state is: its collisions, or its allowed grasp contact and clearance, or its clearance
/// ('' when the data has no clearance). `withMinimum` adds the path's minimum over its free states.
export function stateText(path, state, target, withMinimum = false) {
  if (!path.clearance) return '';
  const links = path.colliding_links[state] || [];
  if (links.length) return `in collision: ${links.join(', ')}`;
  const contact = (path.contact_links || [])[state] || [];
  const closing = path.closing_from_state != null && state > path.closing_from_state;
  let text = `clearance ${mm(path.clearance[state])}`;
  const touching = contact.length === 1 ? '1 hand link' : `${contact.length} hand links`;
  if (contact.length) text = `grasp contact (allowed): ${touching} on ${target} · ${text} from the other obstacles`;
  else if (closing) text = `closing · ${text} from the other obstacles`;
  if (!withMinimum) return text;
  let minimum = Infinity;
  let collidingStates = 0;
  path.clearance.forEach((value, i) => {
    if ((path.colliding_links[i] || []).length) collidingStates += 1;
    else minimum = Math.min(minimum, value);
  });
  return collidingStates ? `${text} (the path collides in ${collidingStates} states)` : `${text} (path minimum ${mm(minimum)})`;
}

/// The path's judgement (`pmdplan validate --json` of it), as one line.
export function validationText(path) {
  const v = path.validation;
  if (!v) return '';
  const phases = v.closing_from != null ? `approach to point ${v.closing_from}, then closing with grasp contact allowed; ` : '';
  return v.valid ? `exact check: valid (${phases}${v.states_checked} states at ${v.tolerance_mm} mm)`
    : `exact check: INVALID: ${v.problems.join('; ')}`;
}

export function createCollisionHighlight(robotObject, path, target) {
  const label = byId('clearance-label');
  const verdict = byId('validation-label');
  verdict.textContent = validationText(path);
  verdict.classList.toggle('invalid', Boolean(path.validation && !path.validation.valid));
  const original = new Map();  // mesh -> its own material while it is drawn red or cyan
  const colliding = path.colliding_links || [];
  const contact = path.contact_links || [];
  const paint = (names, material) => {
    for (const name of names) {
      const link = robotObject.links ? robotObject.links[name] : null;
      if (!link) continue;
      link.traverse((child) => {
        // Only the link's own meshes: child links have their own entries.
        if (child.isMesh && !original.has(child)) {
          original.set(child, child.material);
          child.material = material;
        }
      });
    }
  };
  let contactMeshes = 0;
  return {
    show(state) {
      for (const [mesh, material] of original) mesh.material = material;
      original.clear();
      const links = colliding[state] || [];
      paint(links, COLLIDING);
      const collidingCount = original.size;
      paint(contact[state] || [], CONTACT);
      contactMeshes = original.size - collidingCount;
      label.textContent = stateText(path, state, target, true);
      label.title = (contact[state] || []).length ? `touching ${target}: ${contact[state].join(', ')}` : '';
      label.classList.toggle('colliding', links.length > 0);
      label.classList.toggle('contact', links.length === 0 && contactMeshes > 0);
    },
    collidingMeshes: () => original.size - contactMeshes,
    contactMeshes: () => contactMeshes,
  };
}

// The scene's objects by name with a legend: each obstacle's colour, whether it is the task's
// target, a show / hide box and an opacity slider; and what the path's drawings mean.
import { byId, element } from './dom.js';
import { COLLISION_COLOUR, CONTACT_COLOUR } from './collision_highlight.js';

function setOpacity(holder, opacity) {
  holder.traverse((child) => {
    if (!child.material) return;
    child.material.transparent = opacity < 1 || child.isLineSegments;
    child.material.opacity = child.isLineSegments ? 0.5 * opacity : opacity;
    child.material.depthWrite = opacity >= 1;
    child.material.needsUpdate = true;
  });
}

function swatch(colour) {
  return element('span', { class: 'swatch', style: `background:${colour}` });
}

/// `obstacles` from addObstacles; returns the names listed (for the test).
export function createObjectPanel(obstacles, task, view) {
  const table = byId('object-table');
  const names = [];
  for (const [name, holder] of obstacles.byName) {
    let colour = '#999';
    holder.traverse((child) => { if (child.isMesh && child.material.color) colour = `#${child.material.color.getHexString()}`; });
    const shown = element('input', { type: 'checkbox', title: `show ${name}` });
    shown.checked = true;
    const opacity = element('input', { type: 'range', min: '0.1', max: '1', step: '0.05', value: '1', title: `opacity of ${name}` });
    shown.addEventListener('change', () => { holder.visible = shown.checked; view.requestRender(); });
    opacity.addEventListener('input', () => { setOpacity(holder, Number(opacity.value)); view.requestRender(); });
    const label = name === task.target ? `${name} (target)` : name;
    table.append(element('tr', { 'data-object': name }, element('td', {}, swatch(colour)), element('td', {}, label),
      element('td', {}, shown), element('td', {}, opacity)));
    names.push(name);
  }
  byId('drawing-legend').replaceChildren(
    swatch('#2e9e4f'), ' start  ', swatch('#c0392b'), ' goal  ', swatch('#7b3fa0'), ' palm trace  ', swatch('#5a7bb5'), ' ghosts  ',
    swatch(COLLISION_COLOUR), ' in collision  ', swatch(CONTACT_COLOUR), ' grasp contact (allowed)');
  return names;
}

// The viewer data's warnings (a path whose ends are not the task's start and goal, ...), shown in
// a banner over the scene.
import { byId, element } from './dom.js';

export function showPathWarnings(warnings) {
  const box = byId('warnings');
  box.hidden = !warnings || warnings.length === 0;
  box.replaceChildren(...(warnings || []).map((text) => element('p', {}, `⚠ ${text}`)));
}

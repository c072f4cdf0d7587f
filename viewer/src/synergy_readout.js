// The current hand posture in synergy terms, as the library computed it for every path state:
// own-axis values (thumb base), the coefficient along each PMD, and the distance from the
// subspace of the own axes plus the first k PMDs (k chosen here; the planner's count by default).
import { byId, element, meter, signed } from './dom.js';

export function createSynergyReadout(synergies) {
  const table = byId('synergy-table');
  const choice = byId('distance-directions');
  const distanceValue = byId('distance-value');
  const note = byId('synergy-note');
  const rows = [];
  const addRow = (label, centred) => {
    const value = element('td', { class: 'value' });
    const bar = meter(centred);
    table.append(element('tr', {}, element('td', {}, label), value, element('td', { class: 'bar' }, bar.node)));
    return { value, bar };
  };
  const ownAxisRows = synergies.own_axis_joints.map((name) => addRow(`${name} (own axis)`, false));
  synergies.sigma.forEach((sigma, i) => rows.push({ sigma, ...addRow(`PMD ${i + 1}`, true) }));
  for (let k = 0; k <= synergies.sigma.length; k += 1) choice.append(element('option', { value: String(k) }, String(k)));
  choice.value = String(synergies.planner_directions);

  let lastState = 0;
  let explorerActive = false;
  const readout = synergies.readout;
  function show(state) {
    lastState = state;
    if (explorerActive) return;
    readout.own_axis[state].forEach((v, a) => {
      ownAxisRows[a].value.textContent = v.toFixed(3);
      ownAxisRows[a].bar.set(v);
    });
    readout.coefficients[state].forEach((c, i) => {
      rows[i].value.textContent = signed(c, 3);
      rows[i].bar.set(c / (3 * rows[i].sigma));  // full bar: three standard deviations
    });
    distanceValue.textContent = readout.distance_from_subspace[state][Number(choice.value)].toFixed(4);
    note.textContent = 'Normalised joint units (each joint scaled to [0, 1] by its limits); bars span ±3 σ of each PMD.';
  }
  choice.addEventListener('change', () => show(lastState));
  return {
    show,
    /// While the explorer poses the hand, the readout shows the explorer's own values.
    setExplorerActive(active, ownAxis, coefficients) {
      explorerActive = active;
      if (!active) {
        show(lastState);
        return;
      }
      ownAxis.forEach((v, a) => {
        ownAxisRows[a].value.textContent = v.toFixed(3);
        ownAxisRows[a].bar.set(v);
      });
      coefficients.forEach((c, i) => {
        rows[i].value.textContent = signed(c, 3);
        rows[i].bar.set(c / (3 * rows[i].sigma));
      });
      distanceValue.textContent = '—';
      note.textContent = 'The explorer poses the hand: the values are its sliders (a posture in the subspace, up to clamping at the joint limits).';
    },
    current(state) {
      return {
        ownAxis: readout.own_axis[state],
        coefficients: readout.coefficients[state],
        distance: readout.distance_from_subspace[state][Number(choice.value)],
        directions: Number(choice.value),
      };
    },
  };
}

// Sliders for the own axes (thumb base) and each PMD that pose the hand at b + sum s_i d_i, as in
// the paper's Fig. 8 and 9: the hand moving along one direction, or a combination of two. Values
// beyond a joint limit are clamped for display, and the note says which joints were.
import { byId, element, signed } from './dom.js';

const SIGMAS_EACH_WAY = 3;
const SLIDER_STEPS = 600;

export function createSynergyExplorer(synergies, onPosture) {
  const container = byId('explorer-sliders');
  const toggle = byId('explore');
  const note = byId('explorer-note');
  const n = synergies.joint_names.length;
  const ownAxisIndex = synergies.own_axis_joints.map((name) => synergies.joint_names.indexOf(name));

  const sliders = [];
  const addSlider = (label, share, low, high, value) => {
    const input = element('input', { type: 'range', min: '0', max: String(SLIDER_STEPS), step: '1' });
    const shown = element('span', { class: 'value' });
    const title = element('span', {}, label);
    if (share) title.append(element('br'), element('span', { class: 'share' }, share));
    container.append(element('label', {}, title, input, shown));
    const slider = {
      input, low, high,
      get value() { return low + (high - low) * Number(input.value) / SLIDER_STEPS; },
      set value(v) {
        input.value = String(Math.round((Math.min(high, Math.max(low, v)) - low) / (high - low) * SLIDER_STEPS));
        shown.textContent = signed(this.value, 3);
      },
    };
    input.addEventListener('input', () => {
      shown.textContent = signed(slider.value, 3);
      if (!toggle.checked) toggle.checked = true;
      apply();
    });
    slider.value = value;
    sliders.push(slider);
    return slider;
  };
  const ownAxisSliders = synergies.own_axis_joints.map((name, a) =>
    addSlider(name, 'own axis', 0, 1, synergies.mean[ownAxisIndex[a]]));
  const pmdSliders = synergies.sigma.map((sigma, i) => addSlider(`PMD ${i + 1}`,
    `${(100 * synergies.variance_fraction[i]).toFixed(1)} % of variance`, -SIGMAS_EACH_WAY * sigma, SIGMAS_EACH_WAY * sigma, 0));

  /// Joint values (rad) of the model's joints for the sliders' coefficients.
  function posture() {
    const p = synergies.mean.slice();
    pmdSliders.forEach((slider, i) => {
      const s = slider.value;
      const d = synergies.directions[i];
      for (let j = 0; j < n; j += 1) p[j] += s * d[j];
    });
    ownAxisSliders.forEach((slider, a) => { p[ownAxisIndex[a]] = slider.value; });
    const clamped = [];
    const values = p.map((unit, j) => {
      const u = Math.min(1, Math.max(0, unit));
      if (u !== unit) clamped.push(synergies.joint_names[j]);
      return synergies.lower[j] + u * (synergies.upper[j] - synergies.lower[j]);
    });
    return { values, clamped };
  }

  function apply() {
    if (!toggle.checked) {
      note.textContent = 'Off: the hand follows the path.';
      onPosture(null);
      return;
    }
    const { values, clamped } = posture();
    note.textContent = clamped.length ? `Clamped at a limit: ${clamped.join(', ')}.` : 'Within the joint limits.';
    onPosture({
      joints: synergies.joint_names, values,
      ownAxis: ownAxisSliders.map((s) => s.value), coefficients: pmdSliders.map((s) => s.value),
    });
  }

  toggle.addEventListener('change', apply);
  byId('explorer-mean').addEventListener('click', () => {
    ownAxisSliders.forEach((slider, a) => { slider.value = synergies.mean[ownAxisIndex[a]]; });
    pmdSliders.forEach((slider) => { slider.value = 0; });
    apply();
  });
  return {
    /// Sets the sliders from a path state's readout (values beyond ±3 σ stop at the slider's end).
    setFrom(ownAxis, coefficients) {
      ownAxisSliders.forEach((slider, a) => { slider.value = ownAxis[a]; });
      pmdSliders.forEach((slider, i) => { slider.value = coefficients[i]; });
      apply();
    },
    active: () => toggle.checked,
    refresh: apply,
  };
}

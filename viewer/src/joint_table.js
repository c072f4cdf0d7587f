// The joint readout: every active joint of the current state in degrees (metres for prismatic
// joints), arm and hand apart, the coupled joints under their sources.
import { element, meter } from './dom.js';

export function createJointTable(table, robotData, robot) {
  const hand = new Set(robotData.hand_joints);
  const rows = [];
  const addGroup = (title) => table.append(element('tr', { class: 'group' }, element('td', { colspan: '3' }, title)));
  const addRow = (name, lower, upper, label, mimic) => {
    const value = element('td', { class: 'value' });
    const bar = meter(false);
    table.append(element('tr', mimic ? { class: 'mimic' } : {}, element('td', {}, label), value, element('td', { class: 'bar' }, bar.node)));
    rows.push({ name, lower, upper, value, bar });
  };
  const mimicOf = new Map();
  for (const [joint, [source]] of Object.entries(robotData.mimic)) {
    if (!mimicOf.has(source)) mimicOf.set(source, []);
    mimicOf.get(source).push(joint);
  }
  let group = null;
  robotData.joint_names.forEach((name, i) => {
    const inHand = hand.has(name);
    if (group !== inHand) {
      addGroup(inHand ? 'hand' : 'arm');
      group = inHand;
    }
    addRow(name, robotData.lower[i], robotData.upper[i], name, false);
    for (const mimic of mimicOf.get(name) || []) {
      const [, multiplier, offset] = robotData.mimic[mimic];
      const a = multiplier * robotData.lower[i] + offset;
      const b = multiplier * robotData.upper[i] + offset;
      addRow(mimic, Math.min(a, b), Math.max(a, b), `${mimic} (= ${name})`, true);
    }
  });
  return {
    update() {
      for (const row of rows) {
        const value = robot.jointValue(row.name);
        row.value.textContent = robot.jointType(row.name) === 'prismatic'
          ? `${(value * 1000).toFixed(1)} mm` : (value * 180 / Math.PI).toFixed(1);
        row.bar.set(row.upper > row.lower ? (value - row.lower) / (row.upper - row.lower) : 0);
      }
    },
  };
}

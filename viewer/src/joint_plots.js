// Joint positions and velocities against time for a timed trajectory (path.timing): one canvas
// each, a line per joint of the chosen group, velocities as a fraction of each joint's limit (the
// dashed lines at ±1 are the limits), and a cursor at the state shown.
import { byId, element } from './dom.js';

const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b', '#e377c2', '#7f7f7f',
  '#bcbd22', '#393b79', '#637939', '#843c39'];
const MARGIN = { left: 38, right: 8, top: 8, bottom: 18 };

function drawPlot(canvas, times, series, range, cursorTime, limitLines) {
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth, height = canvas.clientHeight;
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  const g = canvas.getContext('2d');
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  g.clearRect(0, 0, width, height);
  const duration = times[times.length - 1] || 1;
  const x = (t) => MARGIN.left + (width - MARGIN.left - MARGIN.right) * (t / duration);
  const y = (v) => MARGIN.top + (height - MARGIN.top - MARGIN.bottom) * (1 - (v - range[0]) / (range[1] - range[0]));
  g.strokeStyle = '#c9ced6';
  g.lineWidth = 1;
  g.strokeRect(MARGIN.left, MARGIN.top, width - MARGIN.left - MARGIN.right, height - MARGIN.top - MARGIN.bottom);
  g.fillStyle = '#555';
  g.font = '10px sans-serif';
  g.fillText(range[1].toFixed(2), 2, MARGIN.top + 8);
  g.fillText(range[0].toFixed(2), 2, height - MARGIN.bottom);
  g.fillText('0 s', MARGIN.left, height - 4);
  g.fillText(`${duration.toFixed(2)} s`, width - MARGIN.right - 36, height - 4);
  if (limitLines) {
    g.setLineDash([4, 3]);
    g.strokeStyle = '#999';
    for (const v of limitLines) {
      g.beginPath();
      g.moveTo(x(0), y(v));
      g.lineTo(x(duration), y(v));
      g.stroke();
    }
    g.setLineDash([]);
  }
  series.forEach((values, k) => {
    g.strokeStyle = COLOURS[k % COLOURS.length];
    g.lineWidth = 1.4;
    g.beginPath();
    values.forEach((v, i) => (i ? g.lineTo(x(times[i]), y(v)) : g.moveTo(x(times[i]), y(v))));
    g.stroke();
  });
  g.strokeStyle = '#000';
  g.beginPath();
  g.moveTo(x(cursorTime), MARGIN.top);
  g.lineTo(x(cursorTime), height - MARGIN.bottom);
  g.stroke();
}

function extent(series, minimum) {
  let low = Infinity, high = -Infinity;
  for (const values of series) for (const v of values) { low = Math.min(low, v); high = Math.max(high, v); }
  if (minimum) { low = Math.min(low, minimum[0]); high = Math.max(high, minimum[1]); }
  if (!(high > low)) { low -= 1; high += 1; }
  const pad = 0.05 * (high - low);
  return [low - pad, high + pad];
}

/// Null when the path is not timed (the panel stays hidden).
export function createJointPlots(path, robotData) {
  const timing = path.timing;
  const panel = byId('plots-panel');
  if (!timing) {
    panel.hidden = true;
    return null;
  }
  panel.hidden = false;
  const groupSelect = byId('plot-group');
  const names = robotData.joint_names;
  const hand = new Set(robotData.hand_joints || []);
  const groups = [
    ['arm', names.map((n, j) => j).filter((j) => !hand.has(names[j]))],
    ['hand', names.map((n, j) => j).filter((j) => hand.has(names[j]))],
    ...names.map((n, j) => [n, [j]]),
  ].filter(([, joints]) => joints.length > 0);
  groupSelect.replaceChildren(...groups.map(([label], i) => element('option', { value: String(i) }, label)));
  const legend = byId('plot-legend');
  const positionCanvas = byId('position-plot');
  const velocityCanvas = byId('velocity-plot');
  let state = 0;

  function draw() {
    const joints = groups[Number(groupSelect.value) || 0][1];
    const positions = joints.map((j) => path.states.map((q) => q[j]));
    const velocities = joints.map((j) => timing.velocities.map((v) => v[j] / timing.velocity_limits[j]));
    const time = timing.times[state];
    drawPlot(positionCanvas, timing.times, positions, extent(positions), time, null);
    drawPlot(velocityCanvas, timing.times, velocities, [-1.1, 1.1], time, [-1, 1]);
    legend.replaceChildren(...joints.map((j, k) => element('span', { style: `color:${COLOURS[k % COLOURS.length]}` }, `■ ${names[j]} `)));
  }
  groupSelect.addEventListener('change', draw);
  window.addEventListener('resize', draw);
  return {
    show(index) {
      state = index;
      draw();
    },
    /// The largest |velocity| / limit over the trajectory (for the test).
    peakVelocityFraction() {
      let peak = 0;
      timing.velocities.forEach((v) => v.forEach((value, j) => { peak = Math.max(peak, Math.abs(value) / timing.velocity_limits[j]); }));
      return peak;
    },
  };
}

// The glove live: `pmdplan glove stream --serve` publishes every glove posture as a server-sent
// event (/events: `posture` with the hand joints' positions, `end` when the stream stops). This
// module subscribes, poses the robot's hand with each posture, and shows on the page that the view
// is live, the frame rate, and the latency from the moment pmdplan read the frame off the serial
// line (or the recording) to its arrival here.
import { byId, element } from './dom.js';

const RATE_WINDOW_MS = 1000;
const KEPT_RECEIPTS = 5000;
const BADGE_STYLE = 'position:absolute;top:10px;right:10px;padding:4px 10px;border-radius:4px;font:bold 13px/1.4 monospace;'
  + 'color:#fff;background:#b03a2e;box-shadow:0 1px 3px rgba(0,0,0,.3);pointer-events:none;white-space:pre';

/// The page around a still path becomes the live page: no timeline, no ghosts or start and goal
/// copies of the still state, no synergy readout or explorer of it (the live posture is not one of
/// its states, and it would override the explorer's).
function liveLayout() {
  for (const id of ['play', 'timeline', 'state-label', 'clearance-label', 'validation-label', 'synergy-panel', 'explorer-panel']) byId(id).hidden = true;
  for (const [id, value] of [['ghost-mode', 'off'], ['show-ends', false], ['show-palm-trace', false]]) {
    const input = byId(id);
    if (typeof value === 'boolean') input.checked = value;
    else input.value = value;
    input.dispatchEvent(new Event('change'));
  }
}

export function startLiveGlove(live, { robot, view, jointTable }) {
  liveLayout();
  const badge = element('div', { id: 'live-badge', style: BADGE_STYLE });
  byId('view').append(badge);
  const status = {
    connected: false,
    ended: null,
    frames: 0,
    lastFrame: -1,
    fps: 0,
    latencyMs: null,
    /// {frame, receivedMs, readMs} of the latest frames (Date.now() clock), for tests and benchmarks.
    receipts: [],
  };
  let posture = null;
  const arrivals = [];

  const show = () => {
    if (status.ended !== null) {
      badge.style.background = '#59606b';
      badge.textContent = `stream ended · ${status.frames} frames\n${status.ended}`;
    } else if (!status.connected) {
      badge.textContent = 'LIVE · connecting…';
    } else {
      // Below the clocks' resolution (the page's and pmdplan's wall clocks) a latency is "< 0.1".
      const latency = status.latencyMs === null ? '–' : status.latencyMs < 0.05 ? '< 0.1' : status.latencyMs.toFixed(1);
      badge.textContent = `● LIVE · ${status.fps.toFixed(1)} fps · latency ${latency} ms\n${live.source}`
        + (live.project_pmds === null ? '' : ` · first ${live.project_pmds} PMDs`);
    }
  };
  const apply = () => {
    if (!posture) return;
    live.hand_joints.forEach((name, j) => robot.setJoint(name, posture[j]));
    robot.object.updateMatrixWorld(true);
  };

  const events = new EventSource(live.events);
  events.addEventListener('open', () => { status.connected = true; show(); });
  events.addEventListener('posture', (event) => {
    // Wall-clock milliseconds with a fraction, as pmdplan's read_ms (Date.now() has whole ones, which
    // made sub-millisecond latencies negative).
    const receivedMs = performance.timeOrigin + performance.now();
    const data = JSON.parse(event.data);
    if (data.positions.length !== live.hand_joints.length)
      throw new Error(`live posture ${data.frame} has ${data.positions.length} values for ${live.hand_joints.length} hand joints`);
    posture = data.positions;
    apply();
    jointTable.update();
    view.requestRender();
    status.frames += 1;
    status.lastFrame = data.frame;
    status.latencyMs = receivedMs - data.read_ms;
    status.receipts.push({ frame: data.frame, receivedMs, readMs: data.read_ms });
    if (status.receipts.length > KEPT_RECEIPTS) status.receipts.shift();
    arrivals.push(receivedMs);
    while (arrivals.length && arrivals[0] < receivedMs - RATE_WINDOW_MS) arrivals.shift();
    status.fps = arrivals.length > 1 ? (arrivals.length - 1) * 1000 / (arrivals[arrivals.length - 1] - arrivals[0]) : 0;
    show();
  });
  events.addEventListener('end', (event) => {
    status.ended = JSON.parse(event.data).reason;
    events.close();
    show();
  });
  events.addEventListener('error', () => {
    if (status.ended !== null) return;
    status.connected = false;
    show();
  });
  show();
  byId('view-hand').click();
  return {
    status,
    /// Puts the live posture back after something else posed the robot (the path player).
    reapply: apply,
  };
}

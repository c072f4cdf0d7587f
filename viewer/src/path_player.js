// The path as an animation: a slider over the states (waypoints marked), play / pause, speed,
// loop, and keys: arrows step one state, shift + arrows one waypoint, space plays, Home / End.
// A timed trajectory (path.timing) plays in real time: at 1× each state shows at its
// time_from_start; a path without times plays at a fixed number of states a second.
import { byId, element } from './dom.js';

const STATES_PER_SECOND = 30;

export function createPathPlayer(path, view, onState) {
  const slider = byId('timeline');
  const playButton = byId('play');
  const speed = byId('speed');
  const loop = byId('loop');
  const label = byId('state-label');
  const marks = byId('waypoint-marks');
  const count = path.states.length;
  const waypoints = path.waypoint_states;

  slider.max = String(count - 1);
  for (const state of waypoints) marks.append(element('option', { value: String(state) }));

  let state = 0;
  let playing = false;
  let position = 0;      // fractional state while playing (untimed) or seconds (timed)
  let lastTime = null;
  const times = path.timing ? path.timing.times : null;
  const duration = times ? times[count - 1] : count - 1;
  /// The last state at or before `t` seconds.
  function stateAtTime(t) {
    let low = 0, high = count - 1;
    while (low < high) {
      const middle = Math.ceil((low + high) / 2);
      if (times[middle] <= t) low = middle;
      else high = middle - 1;
    }
    return low;
  }
  const positionOf = (index) => (times ? times[index] : index);
  const stateOf = (value) => (times ? stateAtTime(value) : Math.round(value));

  function waypointText(index) {
    const at = waypoints.indexOf(index);
    if (at >= 0) return `waypoint ${at + 1} of ${waypoints.length}`;
    const next = waypoints.findIndex((w) => w > index);
    return `segment ${next} of ${waypoints.length - 1}`;
  }
  function go(index) {
    state = Math.max(0, Math.min(count - 1, Math.round(index)));
    slider.value = String(state);
    const clock = times ? `t = ${times[state].toFixed(2)} s of ${duration.toFixed(2)} s · ` : '';
    label.textContent = `${clock}state ${state + 1} of ${count} · ${waypointText(state)}`;
    onState(state);
    view.requestRender();
  }
  function setPlaying(on) {
    playing = on;
    playButton.textContent = on ? 'Pause' : 'Play';
    if (on) {
      if (state >= count - 1) go(0);
      position = positionOf(state);
      lastTime = null;
      view.requestRender();
    }
  }
  view.onBeforeRender((time) => {
    if (!playing) return false;
    if (lastTime !== null) {
      position += (time - lastTime) / 1000 * (times ? 1 : STATES_PER_SECOND) * Number(speed.value);
      if (position >= duration) {
        if (loop.checked) position %= duration;
        else {
          go(count - 1);
          setPlaying(false);
          return false;
        }
      }
      if (stateOf(position) !== state) go(stateOf(position));
    }
    lastTime = time;
    return true;
  });

  slider.addEventListener('input', () => {
    setPlaying(false);
    go(Number(slider.value));
  });
  playButton.addEventListener('click', () => setPlaying(!playing));
  window.addEventListener('keydown', (event) => {
    const target = event.target;
    // Typing into a number field or choosing from a list keeps its keys.
    if (target instanceof HTMLSelectElement || (target instanceof HTMLInputElement && target.type !== 'range' && target.type !== 'checkbox')) return;
    if (target instanceof HTMLInputElement && target.type === 'range' && target !== slider) return;
    let next = null;
    if (event.key === 'ArrowRight' || event.key === 'ArrowLeft') {
      const forward = event.key === 'ArrowRight';
      if (event.shiftKey) {
        const candidates = forward ? waypoints.filter((w) => w > state) : waypoints.filter((w) => w < state);
        next = candidates.length ? (forward ? candidates[0] : candidates[candidates.length - 1]) : state;
      } else {
        next = state + (forward ? 1 : -1);
      }
    } else if (event.key === 'Home') next = 0;
    else if (event.key === 'End') next = count - 1;
    else if (event.key === ' ') {
      event.preventDefault();
      setPlaying(!playing);
      return;
    }
    if (next === null) return;
    event.preventDefault();
    setPlaying(false);
    go(next);
  });
  return {
    go,
    get state() { return state; },
    get playing() { return playing; },
    get timed() { return times !== null; },
    setPlaying,
  };
}

// Several paths of one task in one scene (`pmdplan view a.json b.json`, or a bench folder's paths
// of one seed): the first path is the robot drawn as it is, every other path a copy of the robot
// in its own colour, with ghosts and a palm trace in that colour. A legend names each path with a
// show / hide box and its state and clearance at the moment shown. One slider plays them all in
// sync: by time when every path is a timed trajectory, otherwise by normalised progress (the same
// fraction of each path's states).
import * as THREE from 'three';
import { byId, element } from './dom.js';
import { createRobot } from './robot_poser.js';
import { createGhostTrail } from './ghost_trail.js';
import { createPalmTrace } from './palm_trace.js';
import { hiddenPathsFromUrl } from './url_state.js';
import { stateText } from './collision_highlight.js';

// Neither green nor red (the start and the goal) nor the robot's own orange.
export const PATH_COLOURS = [0x3a6fc4, 0x9b4dca, 0x17a2a2, 0xd63384, 0x8a6d3b, 0x34495e];
const OVERLAY_OPACITY = 0.6;

const hex = (colour) => `#${colour.toString(16).padStart(6, '0')}`;

/// The colour of path `k`, or undefined when the page shows one path (its drawings keep theirs).
export function pathColour(data, k) {
  return data.overlay_paths && data.overlay_paths.length ? PATH_COLOURS[k % PATH_COLOURS.length] : undefined;
}

/// The last state at or before `t` seconds (the last state after the end).
export function stateAtTime(times, t) {
  let low = 0, high = times.length - 1;
  while (low < high) {
    const middle = Math.ceil((low + high) / 2);
    if (times[middle] <= t) low = middle;
    else high = middle - 1;
  }
  return low;
}

/// The timeline the slider plays, that of the longest path (by duration when every path is
/// timed, else by states), and each path's state at each of its steps.
export function syncTimeline(paths) {
  const timed = paths.every((path) => path.timing);
  const length = (path) => (timed ? path.timing.duration : path.states.length);
  let leader = 0;
  paths.forEach((path, k) => { if (length(path) > length(paths[leader])) leader = k; });
  const lead = paths[leader];
  const count = lead.states.length;
  return {
    timed,
    leaderPath: lead,
    stateOf(k, index) {
      if (k === leader) return index;
      const path = paths[k];
      if (timed) return stateAtTime(path.timing.times, lead.timing.times[index]);
      return count > 1 ? Math.round((index / (count - 1)) * (path.states.length - 1)) : 0;
    },
  };
}

function tint(object, material) {
  object.traverse((child) => { if (child.isMesh) child.material = material; });
}

/// `primary`: the first path's {robot, ghosts, trace}, made by the page; `onVisibility` is called
/// when a path is shown or hidden. Paths the address hides start hidden.
export function createPathSet(view, data, primary, onVisibility = () => {}) {
  const paths = [data.path, ...(data.overlay_paths || [])];
  const timeline = syncTimeline(paths);
  const members = paths.map((path, k) => {
    if (k === 0) return { path, ...primary, shown: true };
    const colour = PATH_COLOURS[k % PATH_COLOURS.length];
    // Behind the first robot where they coincide (the base), and not hiding one another.
    const material = new THREE.MeshStandardMaterial({ color: colour, transparent: true, opacity: OVERLAY_OPACITY, roughness: 0.7,
      depthWrite: false, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
    // Their mesh notes would repeat the first robot's.
    const robot = createRobot(view.scene, data.robot, data.task.base, [], () => {
      tint(robot.object, material);
      view.requestRender();
    });
    tint(robot.object, material);
    const ghosts = createGhostTrail(view.scene, robot, colour);
    const trace = createPalmTrace(view.scene, robot, colour);
    trace.rebuild(path.states, path.states[0]);
    return { path, robot, ghosts, trace, shown: true, ghostCount: 0 };
  });
  let tracesOn = true;
  let shownState = 0;
  const cells = [];
  const show = (index) => {
    shownState = index;
    members.forEach((member, k) => {
      const state = timeline.stateOf(k, index);
      if (k > 0) member.robot.setConfiguration(member.path.states[state]);
      if (cells[k]) cells[k].textContent = `state ${state + 1} of ${member.path.states.length} · ${stateText(member.path, state, data.task.target)}`;
    });
  };
  const applyVisibility = (member) => {
    member.robot.object.visible = member.shown;
    member.ghosts.group.visible = member.shown;
    member.trace.setVisible(member.shown && tracesOn);
  };

  const panel = byId('paths-panel');
  panel.hidden = paths.length < 2;
  if (paths.length > 1) {
    const table = byId('path-table');
    const hidden = hiddenPathsFromUrl();
    members.forEach((member, k) => {
      const box = element('input', { type: 'checkbox', title: `show ${member.path.name}` });
      member.shown = !hidden.includes(k);
      box.checked = member.shown;
      applyVisibility(member);
      box.addEventListener('change', () => {
        member.shown = box.checked;
        applyVisibility(member);
        onVisibility();
        view.requestRender();
      });
      const swatch = element('span', { class: 'swatch', style: `background:${hex(PATH_COLOURS[k % PATH_COLOURS.length])}` });
      const cell = element('div', { class: 'path-state' });
      cells.push(cell);
      table.append(element('tr', { 'data-path': String(k) }, element('td', {}, box), element('td', {}, swatch),
        element('td', { class: 'path-name' }, member.path.name, k === 0 ? ' (solid)' : '', cell)));
    });
    const sync = timeline.timed
      ? 'One slider plays every path by time (all are timed trajectories).'
      : 'One slider plays every path by progress: the same fraction of each path\'s states.';
    byId('path-sync').textContent = `${sync} Ghosts and palm traces are in their path's colour. The first path's robot `
      + 'is drawn solid; the synergy readout, joint plots and red links are of the first path.';
  }

  return {
    /// The path the slider runs along: its states, waypoints and times are the player's.
    timelinePath: timeline.leaderPath,
    timed: timeline.timed,
    count: paths.length,
    names: paths.map((path) => path.name || ''),
    /// The state of path `k` shown at slider position `index`.
    stateOf: (k, index) => timeline.stateOf(k, index),
    statesShown: () => members.map((member, k) => timeline.stateOf(k, shownState)),
    show,
    /// The other paths' ghosts, as many as the first path's `every` gives it.
    rebuildGhosts(every, mode) {
      const firstCount = paths[0].states.length;
      members.forEach((member, k) => {
        if (k === 0) return;
        const states = member.path.states;
        const own = Math.max(1, Math.round((every * (states.length - 1)) / Math.max(1, firstCount - 1)));
        member.ghostCount = member.ghosts.rebuild(states, own, mode, states[timeline.stateOf(k, shownState)]);
      });
    },
    ghostCounts: () => members.map((member) => member.ghostCount ?? null),
    hidden: () => members.flatMap((member, k) => (member.shown ? [] : [k])),
    setTracesVisible(on) {
      tracesOn = on;
      members.forEach(applyVisibility);
    },
  };
}

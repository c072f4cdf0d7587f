// pmdplan viewer: the robot, the task's obstacles and a planned path from the viewer data that
// `pmdplan view` writes (viewer-data.js), with the synergy readout and explorer. The page reports
// itself through window.pmdplanViewer (ready, error, and what a test needs to read).
import * as THREE from 'three';
import { byId, element } from './dom.js';
import { createSceneView, frameBox } from './scene_view.js';
import { addObstacles } from './obstacles.js';
import { createRobot } from './robot_poser.js';
import { createGhostTrail } from './ghost_trail.js';
import { createJointTable } from './joint_table.js';
import { createSynergyReadout } from './synergy_readout.js';
import { createSynergyExplorer } from './synergy_explorer.js';
import { createPathPlayer } from './path_player.js';
import { createJointPlots } from './joint_plots.js';
import { ghostSpacing } from './ghost_spacing.js';
import { showPathWarnings } from './path_warnings.js';
import { createStartGoalMarkers } from './start_goal_markers.js';
import { createPalmTrace } from './palm_trace.js';
import { createObjectPanel } from './object_panel.js';
import { createCollisionHighlight } from './collision_highlight.js';
import { stateFromUrl, writeStateToUrl } from './url_state.js';
import { startLiveGlove } from './live_glove.js';
import { createPathSet, pathColour, syncTimeline } from './path_set.js';

const api = { ready: false, error: null };
window.pmdplanViewer = api;

// Obstacles larger than this (floors, walls) do not decide where the camera looks.
const LARGE_OBSTACLE = 1.5;
const SCENE_VIEW_DIRECTION = new THREE.Vector3(1.0, 0.45, 0.55);
const GHOSTS_BY_DEFAULT = 8;

function showError(message) {
  api.error = message;
  const box = byId('error');
  box.hidden = false;
  box.textContent = `The viewer cannot show this folder:\n\n${message}`;
}

function checkData(data) {
  if (!data) throw new Error('viewer-data.js is missing or empty. A viewer folder is written by: pmdplan view PATH.json --out DIR');
  if (data.format !== 'pmdplan-viewer-data' || data.version !== 1)
    throw new Error(`viewer-data.js: expected format pmdplan-viewer-data version 1, found ${data.format} ${data.version}`);
  const joints = data.robot.joint_names.length;
  allPaths(data).forEach((path, k) => {
    const key = k === 0 ? 'path' : `overlay_paths[${k - 1}]`;
    path.states.forEach((state, i) => {
      if (state.length !== joints) throw new Error(`viewer-data.js: ${key}.states[${i}] has ${state.length} values for ${joints} joints`);
    });
    if (path.states.length === 0) throw new Error(`viewer-data.js: ${key} has no states`);
  });
}

const allPaths = (data) => [data.path, ...(data.overlay_paths || [])];

function sceneBox(robot, data, obstacles) {
  const box = new THREE.Box3();
  for (const state of [data.path.states[0], data.path.states[data.path.states.length - 1]]) {
    robot.setConfiguration(state);
    box.union(new THREE.Box3().setFromObject(robot.object));
  }
  for (const obstacle of obstacles.group.children) {
    const obstacleBox = new THREE.Box3().setFromObject(obstacle);
    const size = obstacleBox.getSize(new THREE.Vector3());
    if (!obstacleBox.isEmpty() && Math.max(size.x, size.y, size.z) < LARGE_OBSTACLE) box.union(obstacleBox);
  }
  return box;
}

function describe(data, notes) {
  byId('title').textContent = data.title;
  const s = data.path.statistics;
  const statistics = s.status === 'not_run' ? '' : ` · ${s.path_nodes} path nodes, length ${s.path_length.toFixed(3)}`;
  const timing = data.path.timing;
  byId('subtitle').textContent = timing
    ? `timed trajectory: ${timing.duration.toFixed(3)} s, ${data.path.states.length} points, blend tolerance ${timing.blend_tolerance} rad`
    : `${data.path.waypoint_count} waypoints, ${data.path.states.length} states${statistics}`;
  if (data.live) byId('subtitle').textContent = `live: ${data.live.source}`;
  const lines = [
    ...(data.overlay_paths ? allPaths(data).map((path) => `path: ${path.name}`)
      : [`path: ${data.sources.path_file} (${data.path.planner}, seed ${data.path.seed})`]),
    `task: ${data.task.name} (${data.sources.task_file})${data.task.description ? ' · ' + data.task.description : ''}`,
    `robot: ${data.robot.name}`,
    data.synergies ? `synergies: ${data.sources.synergy_file} · ${data.synergies.provenance}` : 'no synergy model',
    ...notes,
  ];
  const box = byId('provenance');
  box.replaceChildren(...lines.flatMap((line, i) => (i ? [element('br'), line] : [line])));
}

function start(data) {
  checkData(data);
  showPathWarnings(data.warnings);
  const initialState = stateFromUrl(syncTimeline(allPaths(data)).leaderPath.states.length) ?? 0;  // before anything poses (and rewrites it)
  const notes = [];
  const view = createSceneView(byId('view'));
  const obstacles = addObstacles(view.scene, data.task, notes, () => {
    describe(data, notes);
    view.requestRender();
  });
  const objectNames = createObjectPanel(obstacles, data.task, view);
  const robot = createRobot(view.scene, data.robot, data.task.base, notes, () => {
    describe(data, notes);
    view.requestRender();
  });
  api.robotMeshes = () => robot.meshStatus();
  const jointTable = createJointTable(byId('joint-table'), data.robot, robot);
  const ghosts = createGhostTrail(view.scene, robot, pathColour(data, 0));
  const trace = createPalmTrace(view.scene, robot, pathColour(data, 0));
  // Several paths: one slider over the longest; `shown()` is the first path's state at it.
  const paths = createPathSet(view, data, { robot, ghosts, trace }, () => writeStateToUrl(player.state, paths.hidden()));
  const shown = () => paths.stateOf(0, player.state);
  const states = data.path.states;
  const plots = createJointPlots(data.path, data.robot);
  const highlight = createCollisionHighlight(robot.object, data.path, data.task.target);

  let explorerPosture = null;
  let player = null;
  let live = null;
  const readout = data.synergies ? createSynergyReadout(data.synergies) : null;
  function pose(position) {
    const state = paths.stateOf(0, position);
    robot.setConfiguration(states[state]);
    if (explorerPosture) explorerPosture.joints.forEach((name, j) => robot.setJoint(name, explorerPosture.values[j]));
    if (live) live.reapply();
    robot.object.updateMatrixWorld(true);
    jointTable.update();
    if (readout) readout.show(state);
    if (plots) plots.show(state);
    highlight.show(state);
    paths.show(position);
    writeStateToUrl(position, paths.hidden());
  }
  let explorer = null;
  if (data.synergies) {
    explorer = createSynergyExplorer(data.synergies, (posture) => {
      explorerPosture = posture;
      readout.setExplorerActive(Boolean(posture), posture?.ownAxis, posture?.coefficients);
      if (player) pose(player.state);
      view.requestRender();
    });
    byId('explorer-from-path').addEventListener('click', () => {
      const current = readout.current(shown());
      byId('explore').checked = true;
      explorer.setFrom(current.ownAxis, current.coefficients);
    });
  } else {
    byId('synergy-panel').hidden = true;
    byId('explorer-panel').hidden = true;
  }
  const box = sceneBox(robot, data, obstacles);
  player = createPathPlayer(paths.timelinePath, view, pose);

  const ghostMode = byId('ghost-mode');
  const ghostEvery = byId('ghost-every');
  ghostEvery.value = String(Math.max(1, Math.round((states.length - 1) / GHOSTS_BY_DEFAULT)));
  let ghostCount = 0;
  const rebuildGhosts = () => {
    const spacing = ghostSpacing(ghostEvery.value, states.length);
    ghostEvery.value = String(spacing.every);
    byId('ghost-note').textContent = spacing.note;
    ghostCount = ghosts.rebuild(states, spacing.every, ghostMode.value, states[shown()]);
    paths.rebuildGhosts(spacing.every, ghostMode.value);
    pose(player.state);
    view.requestRender();
  };
  ghostMode.addEventListener('change', rebuildGhosts);
  ghostEvery.addEventListener('change', rebuildGhosts);

  byId('view-scene').addEventListener('click', () => frameBox(view, box, SCENE_VIEW_DIRECTION));
  byId('view-hand').addEventListener('click', () => {
    // From ahead of the fingers and to the side, a little above: the fingers, not the forearm.
    const forward = robot.handDirection();
    const up = new THREE.Vector3(0, 0, 1);
    const side = new THREE.Vector3().crossVectors(forward, up);
    if (side.lengthSq() < 1e-6) side.set(1, 0, 0);
    const direction = forward.clone().multiplyScalar(0.7).add(side.normalize()).addScaledVector(up, 0.5);
    const palm = robot.palmPosition();
    frameBox(view, new THREE.Box3().setFromCenterAndSize(palm, new THREE.Vector3(0.35, 0.35, 0.35)), direction);
  });

  const ends = createStartGoalMarkers(view.scene, robot);
  const endsToggle = byId('show-ends');
  let endCopies = 0;
  const rebuildEnds = () => {
    endCopies = ends.rebuild(states, ghostMode.value === 'hand', states[shown()]);
    ends.setVisible(endsToggle.checked);
    pose(player.state);
    view.requestRender();
  };
  endsToggle.addEventListener('change', rebuildEnds);
  ghostMode.addEventListener('change', rebuildEnds);

  const traceToggle = byId('show-palm-trace');
  const tracePoints = trace.rebuild(states, states[0]);
  paths.setTracesVisible(traceToggle.checked);
  traceToggle.addEventListener('change', () => {
    paths.setTracesVisible(traceToggle.checked);
    view.requestRender();
  });

  rebuildGhosts();
  rebuildEnds();
  player.go(initialState);
  if (explorer) explorer.refresh();
  frameBox(view, box, SCENE_VIEW_DIRECTION);
  describe(data, notes);

  // Descriptors, not Object.assign: the getters must stay live.
  Object.defineProperties(api, Object.getOwnPropertyDescriptors({
    stateCount: paths.timelinePath.states.length,
    waypointStates: paths.timelinePath.waypoint_states.slice(),
    pathCount: paths.count,
    pathNames: paths.names,
    pathStates: () => paths.statesShown(),
    pathStateCounts: allPaths(data).map((path) => path.states.length),
    overlayGhostCounts: () => paths.ghostCounts(),
    jointNames: data.robot.joint_names.slice(),
    get state() { return player.state; },
    get playing() { return player.playing; },
    get renderCount() { return view.renderCount; },
    get ghostCount() { return ghostCount; },
    get endsShown() { return endsToggle.checked ? endCopies : 0; },
    palmTracePoints: tracePoints,
    objectNames,
    collidingMeshes: () => highlight.collidingMeshes(),
    contactMeshes: () => highlight.contactMeshes(),
    clearanceText: () => document.getElementById('clearance-label').textContent,
    validationText: () => document.getElementById('validation-label').textContent,
    closingFromState: data.path.closing_from_state ?? null,
    timed: Boolean(data.path.timing),
    duration: data.path.timing ? data.path.timing.duration : null,
    stateTime: (index) => (data.path.timing ? data.path.timing.times[index] : null),
    peakVelocityFraction: () => (plots ? plots.peakVelocityFraction() : null),
    notes,
    warnings: (data.warnings || []).slice(),
    setState: (index) => player.go(index),
    jointValue: (name) => robot.jointValue(name),
    synergyReadout: () => (readout ? readout.current(shown()) : null),
  }));
  if (data.live) {
    live = startLiveGlove(data.live, { robot, view, jointTable });
    api.live = live.status;
  }
  const waitForFirstFrame = () => {
    if (view.renderCount > 0) api.ready = true;
    else requestAnimationFrame(waitForFirstFrame);
  };
  requestAnimationFrame(waitForFirstFrame);
}

try {
  start(window.pmdplanViewerData);
} catch (error) {
  showError(error && error.message ? error.message : String(error));
  console.error(error);
}

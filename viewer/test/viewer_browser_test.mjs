// The viewer in a real browser: `pmdplan view PATH --serve 0`, Debian's chromium (headless,
// SwiftShader WebGL) opens it, waits until it reports ready, and checks what a person would see:
// the canvas is not blank, moving the slider changes a finger joint and the image, the coupled
// distal joint follows, keys step, the synergy readout and explorer work, play advances. The
// page also has to work opened straight from the disk (file://). With --trajectory, the timed
// trajectory of the same path plays in real time with its joint plots. Several paths on one page
// (path_set_check.mjs) play in sync, by progress, or by time for trajectories. Screenshots go to --work.
// The checks come in parts, each with its own browser, so that ctest runs them side by side
// (tests/cli/view_cli_test.cpp runs one part per test); without --part all of them run.
//
//   node viewer/test/viewer_browser_test.mjs --cli build/pmdplan --path PATH.json --work DIR [--trajectory T.json]
//        [--part motion|display|collisions|paths|trajectory]
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launchChromium } from './chromium.mjs';
import { decodePng, imageContent, changedShare } from './png_image.mjs';
import { log, elapsed, serveViewer, openViewer, canvasAfterRender, hidingChange, renderCount, viewerValue } from './viewer_page.mjs';
import { checkPathSet, checkTimedPathSet } from './path_set_check.mjs';

function options() {
  const args = process.argv.slice(2);
  const value = (name) => {
    const i = args.indexOf(name);
    return i >= 0 ? args[i + 1] : undefined;
  };
  const o = { cli: value('--cli'), path: value('--path'), work: value('--work'), trajectory: value('--trajectory'),
    part: value('--part') };
  if (!o.cli || !o.path || !o.work || (o.part && !(o.part in PARTS)) || (o.part === 'trajectory' && !o.trajectory)) {
    console.error(`usage: viewer_browser_test.mjs --cli PMDPLAN --path PATH.json --work DIR [--trajectory T.json] [--part ${Object.keys(PARTS).join('|')}] (trajectory needs --trajectory)`);
    process.exit(2);
  }
  return o;
}

/// The straight segment from the path's start to its goal passes through the can: along it the
/// page draws the colliding links red and says so; the planned path shows its clearance instead.
async function checkCollisions(browser, o) {
  const path = JSON.parse(readFileSync(o.path, 'utf8'));
  path.points = [path.points[0], path.points[path.points.length - 1]];
  const straight = join(o.work, 'straight.path.json');
  writeFileSync(straight, JSON.stringify(path));
  const { server, url } = await serveViewer(o.cli, straight, resolve(o.work, 'straight-viewer'));
  try {
    const { page, problems } = await openViewer(browser, url);
    const clearance = await viewerValue(page, () => window.pmdplanViewer.clearanceText());
    assert.ok(clearance.startsWith('clearance '), `the start state shows its clearance: ${clearance}`);
    const count = await viewerValue(page, () => window.pmdplanViewer.stateCount);
    let hit = -1;
    for (let state = 0; state < count && hit < 0; ++state) {
      await viewerValue(page, (i) => window.pmdplanViewer.setState(i), state);
      if ((await viewerValue(page, () => window.pmdplanViewer.collidingMeshes())) > 0) hit = state;
    }
    assert.ok(hit >= 0, 'no state of the straight segment through the can is drawn in collision');
    const text = await viewerValue(page, () => window.pmdplanViewer.clearanceText());
    assert.ok(text.startsWith('in collision: '), `the label says so: ${text}`);
    await page.screenshot({ path: join(o.work, 'viewer-collision.png') });
    log(`straight segment: state ${hit} of ${count} drawn in collision (${text}); screenshot viewer-collision.png`);
    assert.deepEqual(problems, [], `the collision page reported problems:\n${problems.join('\n')}`);
    await page.close();
  } finally {
    server.kill('SIGTERM');
  }
}

/// A timed trajectory: the clock in the label, plots drawn, playback in real time (the trajectory's
/// time advances with the wall clock at 1×), velocities within the limits.
async function checkTrajectory(browser, o) {
  const folder = resolve(o.work, 'trajectory-viewer');
  const { server, url } = await serveViewer(o.cli, o.trajectory, folder);
  try {
    const { page, problems } = await openViewer(browser, url);
    const info = await viewerValue(page, () => ({ timed: window.pmdplanViewer.timed, duration: window.pmdplanViewer.duration,
      count: window.pmdplanViewer.stateCount, peak: window.pmdplanViewer.peakVelocityFraction() }));
    assert.equal(info.timed, true, 'the trajectory viewer knows the path is timed');
    assert.ok(info.duration > 0.1, `a trajectory of ${info.duration} s`);
    assert.ok(info.peak <= 1 + 1e-4 && info.peak > 0.1, `peak velocity / limit ${info.peak}`);
    assert.equal(await page.locator('#plots-panel').isVisible(), true, 'the joint plots are shown');
    for (const id of ['#position-plot', '#velocity-plot']) {
      const plot = imageContent(decodePng(await page.locator(id).screenshot()));
      assert.ok(plot.foregroundShare > 0.01 && plot.distinctColours > 5, `${id} looks empty`);
    }
    // At 0.25× the play takes four times the trajectory's duration: long enough that a slow
    // frame (software WebGL on a busy machine) hardly counts.
    await page.locator('#loop').uncheck();
    await page.locator('#speed').selectOption('0.25');
    const before = await viewerValue(page, () => performance.now());
    await page.locator('#play').click();
    await page.waitForFunction(() => !window.pmdplanViewer.playing, null, { timeout: 60_000 });
    const wall = ((await viewerValue(page, () => performance.now())) - before) / 1000;
    const last = await viewerValue(page, () => window.pmdplanViewer.state);
    assert.equal(last, info.count - 1, 'playing ends at the last state');
    const ratio = (0.25 * wall) / info.duration;
    log(`trajectory: ${info.duration.toFixed(3)} s played at 0.25x in ${wall.toFixed(3)} s of wall clock (ratio to real time ${ratio.toFixed(2)}), peak velocity ${(100 * info.peak).toFixed(1)} % of a limit`);
    assert.ok(ratio > 0.9 && ratio < 2.0, `real-time playback: ${info.duration} s of trajectory at 0.25x took ${wall} s`);
    const label = await page.locator('#state-label').innerText();
    assert.ok(label.includes(`of ${info.duration.toFixed(2)} s`), `the label shows the clock: ${label}`);
    const frames = await renderCount(page);
    await page.locator('#timeline').fill(String(Math.floor(info.count / 2)));
    await page.waitForFunction((n) => window.pmdplanViewer.renderCount > n, frames);
    await page.screenshot({ path: join(o.work, 'viewer-trajectory.png') });
    log(`screenshot ${join(o.work, 'viewer-trajectory.png')}`);
    assert.deepEqual(problems, [], `the trajectory page reported problems:\n${problems.join('\n')}`);
    await page.close();
  } finally {
    server.kill('SIGTERM');
  }
}

/// The planned path's page over HTTP: `check` runs on it (checkMotion or checkDisplay), then the
/// page must have reported no problem.
async function checkPage(browser, o, check) {
  const folder = resolve(o.work, 'viewer');
  const { server, url } = await serveViewer(o.cli, o.path, folder);
  log(`pmdplan view serves ${url}`);
  try {
    const { page, problems } = await openViewer(browser, url);
    log('viewer ready over HTTP');
    const count = await viewerValue(page, () => window.pmdplanViewer.stateCount);
    const waypoints = await viewerValue(page, () => window.pmdplanViewer.waypointStates);
    assert.ok(count >= 3, `expected a path of several states, found ${count}`);
    await check(page, o, { count, waypoints, middle: Math.floor(count / 2), folder });
    assert.deepEqual(problems, [], `the page reported problems:\n${problems.join('\n')}`);
    await page.close();
  } finally {
    server.kill('SIGTERM');
  }
}

const jointOf = (page) => (name) => viewerValue(page, (n) => window.pmdplanViewer.jointValue(n), name);

/// What moves: the first frame, the slider (fingers, coupled joint, picture, clearance, joint
/// table, synergy readout), the keys, the synergy explorer, play and pause.
async function checkMotion(page, o, { count, waypoints, middle }) {
  // The first frame: the robot and the scene, not a blank canvas.
  const first = await canvasAfterRender(page, 0);
  const content = imageContent(first.image);
  assert.ok(content.foregroundShare > 0.05 && content.distinctColours > 20,
    `the canvas looks blank: ${(100 * content.foregroundShare).toFixed(1)} % non-background, ${content.distinctColours} colours`);
  writeFileSync(join(o.work, 'viewer-start.png'), first.png);
  log(`canvas ${first.image.width}x${first.image.height}: ${(100 * content.foregroundShare).toFixed(1)} % drawn, ${content.distinctColours} colours`);

  // Moving the slider moves the fingers, the coupled distal joint with them, and the picture.
  const joint = jointOf(page);
  const startMedium = await page.evaluate(() => window.pmdplanViewer.jointValue('index_medium'));
  const startReadout = await viewerValue(page, () => window.pmdplanViewer.synergyReadout());
  const clearanceStart = await viewerValue(page, () => window.pmdplanViewer.clearanceText());
  const frames = await renderCount(page);
  await page.locator('#timeline').fill(String(middle));
  const moved = await canvasAfterRender(page, frames);
  assert.equal(await viewerValue(page, () => window.pmdplanViewer.state), middle, 'the slider sets the state');
  const middleMedium = await joint('index_medium');
  assert.ok(Math.abs(middleMedium - startMedium) > 1e-3, `index_medium did not move: ${startMedium} -> ${middleMedium}`);
  assert.ok(Math.abs((await joint('index_distal')) - middleMedium) < 1e-12, 'index_distal follows index_medium (mimic)');
  const change = changedShare(first.image, moved.image);
  assert.ok(change > 0.002, `the image hardly changed when the slider moved (${(100 * change).toFixed(3)} % of pixels)`);
  log(`slider to state ${middle}: index_medium ${startMedium.toFixed(4)} -> ${middleMedium.toFixed(4)} rad, ${(100 * change).toFixed(2)} % of pixels changed`);
  // The clearance is the state's: another state, another figure.
  const clearanceMiddle = await viewerValue(page, () => window.pmdplanViewer.clearanceText());
  assert.ok(/^clearance \d+\.\d mm \(path minimum/.test(clearanceMiddle), `a clearance for the state: ${clearanceMiddle}`);
  assert.notEqual(clearanceMiddle, clearanceStart, 'the clearance follows the state');
  log(`clearance at the start "${clearanceStart}", at state ${middle} "${clearanceMiddle}"`);
  const jointText = await page.locator('#joint-table').innerText();
  assert.ok(jointText.includes((middleMedium * 180 / Math.PI).toFixed(1)), 'the joint table shows the current index_medium');

  // The synergy readout follows the state.
  const middleReadout = await viewerValue(page, () => window.pmdplanViewer.synergyReadout());
  assert.notDeepEqual(middleReadout.coefficients, startReadout.coefficients, 'the PMD coefficients change along the path');
  assert.ok(middleReadout.distance >= 0, 'a distance from the subspace is shown');
  const shownDistance = await page.locator('#distance-value').innerText();
  assert.equal(shownDistance, middleReadout.distance.toFixed(4));

  // Keys: one state, one waypoint.
  await page.locator('#timeline').focus();
  await page.keyboard.press('ArrowRight');
  assert.equal(await viewerValue(page, () => window.pmdplanViewer.state), middle + 1, 'ArrowRight steps one state');
  await page.keyboard.press('Shift+ArrowRight');
  const nextWaypoint = waypoints.find((w) => w > middle + 1);
  assert.equal(await viewerValue(page, () => window.pmdplanViewer.state), nextWaypoint, 'Shift+ArrowRight goes to the next waypoint');
  await page.keyboard.press('Home');
  assert.equal(await viewerValue(page, () => window.pmdplanViewer.state), 0, 'Home goes to the start');

  // The synergy explorer poses the hand along PMD 1; switching it off gives the path back.
  const pathMedium = await joint('index_medium');
  const pmd1 = page.locator('#explorer-sliders input').nth(1);
  await pmd1.fill(await pmd1.getAttribute('max'));
  assert.equal(await page.locator('#explore').isChecked(), true, 'moving an explorer slider switches the explorer on');
  const exploredMedium = await joint('index_medium');
  assert.ok(Math.abs(exploredMedium - pathMedium) > 1e-3, 'PMD 1 moves index_medium');
  await page.locator('#explore').uncheck();
  assert.ok(Math.abs((await joint('index_medium')) - pathMedium) < 1e-12, 'without the explorer the hand follows the path');
  log(`explorer: PMD 1 at +3 sigma moves index_medium ${pathMedium.toFixed(4)} -> ${exploredMedium.toFixed(4)} rad`);
  // "From the path state" sets the sliders to the state's coefficients: with every PMD, the hand
  // comes back to (nearly: slider steps) the path's posture.
  await page.locator('#explorer-from-path').click();
  assert.equal(await page.locator('#explore').isChecked(), true);
  const rebuilt = await joint('index_medium');
  assert.ok(Math.abs(rebuilt - pathMedium) < 0.02, `from the path state: index_medium ${rebuilt} vs the path's ${pathMedium}`);
  await page.locator('#explore').uncheck();

  // Play advances the animation; pause stops it.
  await page.locator('#play').click();
  await page.waitForFunction(() => window.pmdplanViewer.state > 3, null, { timeout: 20_000 });
  await page.locator('#play').click();
  assert.equal(await viewerValue(page, () => window.pmdplanViewer.playing), false, 'pause stops the animation');
  log(`play reached state ${await viewerValue(page, () => window.pmdplanViewer.state)}`);
  assert.ok((await viewerValue(page, () => window.pmdplanViewer.ghostCount)) >= 2, 'a ghost trail is drawn');
}

/// What is drawn besides the hand: start and goal copies, the palm trace, the objects by name;
/// the state in the address, a refused ghost spacing; the page from the disk (file://).
async function checkDisplay(page, o, { middle, folder }) {
  // From the middle of the motion, so that the state is in the address.
  let frames = await renderCount(page);
  await page.locator('#timeline').fill(String(middle));
  await page.waitForFunction((n) => window.pmdplanViewer.renderCount > n, frames);
  assert.equal(await viewerValue(page, () => window.pmdplanViewer.state), middle, 'the slider sets the state');
  assert.ok((await viewerValue(page, () => window.pmdplanViewer.ghostCount)) >= 2, 'a ghost trail is drawn');
  // Start (green) and goal (red) are drawn apart; switching them off changes the picture.
  assert.ok((await viewerValue(page, () => window.pmdplanViewer.endsShown)) >= 2, 'start and goal copies are drawn');
  const ghostsOff = () => page.locator('#ghost-mode').selectOption('off');
  const endsChange = await hidingChange(page, join(o.work, 'viewer-start-goal.png'), ghostsOff,
    () => page.locator('#show-ends').uncheck());
  assert.ok(endsChange > 0.002, `hiding start and goal hardly changed the image (${(100 * endsChange).toFixed(3)} %)`);
  log(`start / goal copies: ${(100 * endsChange).toFixed(2)} % of pixels; screenshot viewer-start-goal.png`);
  // The palm trace: one point per state; hiding it changes the picture.
  const count = await viewerValue(page, () => window.pmdplanViewer.stateCount);
  assert.equal(await viewerValue(page, () => window.pmdplanViewer.palmTracePoints), count, 'a palm trace point per state');
  const traceChange = await hidingChange(page, join(o.work, 'viewer-palm-trace.png'), ghostsOff,
    () => page.locator('#show-palm-trace').uncheck(), true);
  assert.ok(traceChange > 0.0002, `hiding the palm trace hardly changed the image (${(100 * traceChange).toFixed(3)} %)`);
  log(`palm trace: ${(100 * traceChange).toFixed(2)} % of pixels; screenshot viewer-palm-trace.png`);
  await page.locator('#show-palm-trace').check();
  await page.locator('#show-ends').check();
  await page.locator('#ghost-mode').selectOption('hand');
  // Objects by name: hiding the target and making the table transparent change the picture.
  const objects = await viewerValue(page, () => window.pmdplanViewer.objectNames);
  assert.ok(objects.includes('table') && objects.includes('goal_can'), `objects listed: ${objects}`);
  assert.ok((await page.locator('#object-table').innerText()).includes('goal_can (target)'), 'the target is named in the legend');
  const allShown = { image: decodePng(await page.locator('#view canvas').screenshot()) };
  const objectFrames = await renderCount(page);
  await page.locator('tr[data-object="goal_can"] input[type=checkbox]').uncheck();
  await page.locator('tr[data-object="table"] input[type=range]').fill('0.3');
  const changedObjects = await canvasAfterRender(page, objectFrames);
  const objectChange = changedShare(allShown.image, changedObjects.image);
  assert.ok(objectChange > 0.01, `hiding the can and a transparent table hardly changed the image (${(100 * objectChange).toFixed(3)} %)`);
  await page.screenshot({ path: join(o.work, 'viewer-objects.png') });
  log(`objects ${objects.join(', ')}: can hidden, table at 30 % opacity, ${(100 * objectChange).toFixed(2)} % of pixels; screenshot viewer-objects.png`);
  await page.locator('tr[data-object="goal_can"] input[type=checkbox]').check();
  await page.locator('tr[data-object="table"] input[type=range]').fill('1');
  // The state is in the address: a reload opens the same state.
  assert.ok((await viewerValue(page, () => window.location.hash)).startsWith('#state='), 'the state is in the URL');
  const shownState = await viewerValue(page, () => window.pmdplanViewer.state);
  await page.reload();
  await page.waitForFunction(() => window.pmdplanViewer && window.pmdplanViewer.ready, null, { timeout: 60_000 });
  assert.equal(await viewerValue(page, () => window.pmdplanViewer.state), shownState, 'a reload keeps the state from the URL');
  await page.screenshot({ path: join(o.work, 'viewer-url-state.png') });
  log(`state ${shownState} kept in the URL across a reload; screenshot viewer-url-state.png`);
  // "every 0" is refused: the field gets a usable spacing back, a note says why, and the trail
  // stays at most 40 ghosts (plus the last state).
  await page.locator('#ghost-every').fill('0');
  await page.locator('#ghost-every').dispatchEvent('change');
  const refused = await viewerValue(page, () => ({ value: document.getElementById('ghost-every').value,
    note: document.getElementById('ghost-note').textContent, ghosts: window.pmdplanViewer.ghostCount }));
  assert.ok(Number(refused.value) >= 1, `every 0 was kept: ${refused.value}`);
  assert.ok(refused.note.includes('refused'), `no note for every 0: ${refused.note}`);
  assert.ok(refused.ghosts <= 41, `every 0 drew ${refused.ghosts} ghosts`);
  await page.locator('#ghost-note').screenshot({ path: join(o.work, 'viewer-ghosts-refused.png') });
  log(`every 0 refused: every ${refused.value}, ${refused.ghosts} ghosts ("${refused.note}")`);

  // The screenshot a person would see, in the middle of the motion.
  frames = await renderCount(page);
  await page.locator('#timeline').fill(String(middle));
  await page.waitForFunction((n) => window.pmdplanViewer.renderCount > n, frames);
  await page.screenshot({ path: join(o.work, 'viewer.png') });
  log(`screenshot ${join(o.work, 'viewer.png')}`);

  // The same folder opened from the disk, as a person double-clicking index.html would.
  const fromDisk = await openViewer(page.context().browser(), pathToFileURL(join(folder, 'index.html')).href);
  assert.deepEqual(fromDisk.problems, [], `from file://:\n${fromDisk.problems.join('\n')}`);
  await fromDisk.page.close();
  log('viewer ready from file://');
}

const PARTS = {
  motion: (browser, o) => checkPage(browser, o, checkMotion),
  display: (browser, o) => checkPage(browser, o, checkDisplay),
  collisions: checkCollisions,
  paths: checkPathSet,
  trajectory: async (browser, o) => {
    await checkTrajectory(browser, o);
    await checkTimedPathSet(browser, o);
  },
};

async function main() {
  const o = options();
  mkdirSync(o.work, { recursive: true });
  const browser = await launchChromium();
  try {
    log(`chromium ${browser.version()} started`);
    for (const [name, part] of Object.entries(PARTS)) {
      if ((o.part ?? name) !== name || (name === 'trajectory' && !o.trajectory)) continue;
      await part(browser, o);
      log(`part ${name} passed`);
    }
  } finally {
    await browser.close();
  }
  log(o.part ? `viewer checks of part ${o.part} passed` : 'all viewer checks passed');
}

main().catch((error) => {
  console.error(`[${elapsed()} s] FAILED: ${error.stack || error}`);
  process.exit(1);
});

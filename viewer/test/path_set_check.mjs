// Several paths on one page (`pmdplan view A B C`): the planned path, the straight segment from
// its start to its goal (through the can) and the planned path with its goal moved by 0.57 deg.
// The page lists the three in a legend, warns that the third does not end at the task's goal,
// plays them in sync with one slider (by progress: none is timed), shows each path's own state and
// clearance, draws each path's copy of the robot and ghosts in its colour and hides a path on
// request. Screenshots: viewer-paths.png (the canvas, all three mid-motion), viewer-paths-page.png
// (the page with the Paths legend), viewer-ends-warning.png.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { log, serveViewer, openViewer, hidingChange, viewerValue } from './viewer_page.mjs';

function writePaths(o) {
  const planned = JSON.parse(readFileSync(o.path, 'utf8'));
  const last = planned.points.length - 1;
  const straight = { ...planned, planner: 'straight', points: [planned.points[0], planned.points[last]] };
  const moved = structuredClone(planned);
  moved.planner = 'moved goal';
  moved.points[last].positions[0] += 0.01;
  const files = [o.path, join(o.work, 'paths-straight.path.json'), join(o.work, 'paths-moved-goal.path.json')];
  writeFileSync(files[1], JSON.stringify(straight));
  writeFileSync(files[2], JSON.stringify(moved));
  return files;
}

const pathRow = (page, k) => page.locator(`#path-table tr[data-path="${k}"]`);

export async function checkPathSet(browser, o) {
  const files = writePaths(o);
  const { server, url } = await serveViewer(o.cli, files, resolve(o.work, 'paths-viewer'));
  try {
    const { page, problems } = await openViewer(browser, url);
    const info = await viewerValue(page, () => ({ paths: window.pmdplanViewer.pathCount, names: window.pmdplanViewer.pathNames,
      counts: window.pmdplanViewer.pathStateCounts, count: window.pmdplanViewer.stateCount }));
    assert.equal(info.paths, 3, 'three paths on the page');
    assert.equal(await page.locator('#paths-panel').isVisible(), true, 'the paths legend is shown');
    assert.equal(await page.locator('#path-table tr').count(), 3, 'one legend row per path');
    ['paths-straight.path.json', 'paths-moved-goal.path.json'].forEach((file, i) => {
      assert.ok(info.names[i + 1].includes(file), `path ${i + 1} is named after its file: ${info.names[i + 1]}`);
    });
    assert.ok((await pathRow(page, 1).innerText()).includes('straight, seed'), 'the legend names the planner');
    assert.equal(info.count, Math.max(...info.counts), 'the slider runs along the path of the most states');

    // The moved goal: a warning on the page, naming the file.
    assert.equal(await page.locator('#warnings').isVisible(), true, 'the ends warning is shown');
    const warning = await page.locator('#warnings').innerText();
    assert.ok(warning.includes("paths-moved-goal.path.json: the path's last point is not task can_on_table's goal"),
      `the warning names the file and the goal: ${warning}`);
    await page.locator('#warnings').screenshot({ path: join(o.work, 'viewer-ends-warning.png') });
    log(`ends warning shown: "${warning.trim()}"; screenshot viewer-ends-warning.png`);

    // In sync by progress: at the end every path is at its last state; in the middle each is at
    // the same fraction of its own states.
    await viewerValue(page, (i) => window.pmdplanViewer.setState(i), info.count - 1);
    assert.deepEqual(await viewerValue(page, () => window.pmdplanViewer.pathStates()), info.counts.map((n) => n - 1),
      'the end of the slider is the end of every path');
    const middle = Math.floor(info.count / 2);
    await viewerValue(page, (i) => window.pmdplanViewer.setState(i), middle);
    const states = await viewerValue(page, () => window.pmdplanViewer.pathStates());
    states.forEach((state, k) => {
      const off = Math.abs(state / (info.counts[k] - 1) - middle / (info.count - 1));
      assert.ok(off <= 0.5 / (info.counts[k] - 1) + 1e-9, `path ${k} at state ${state} of ${info.counts[k]}, slider at ${middle} of ${info.count}`);
    });
    const rowText = await pathRow(page, 2).innerText();
    assert.ok(rowText.includes(`state ${states[2] + 1} of ${info.counts[2]}`), `the legend shows path 2's own state: ${rowText}`);
    assert.ok(/clearance \d+\.\d mm|in collision/.test(rowText), `the legend shows path 2's clearance: ${rowText}`);

    // The straight segment passes through the can: its row says so at some moment.
    const hit = await viewerValue(page, (count) => {
      for (let i = 0; i < count; i += 1) {
        window.pmdplanViewer.setState(i);
        if (document.querySelector('#path-table tr[data-path="1"] .path-state').textContent.includes('in collision')) return i;
      }
      return -1;
    }, info.count);
    assert.ok(hit >= 0, 'the straight path is never shown in collision in the legend');
    log(`3 paths of ${info.counts.join(' / ')} states in sync; the straight one in collision at slider state ${hit}`);

    // Each path's copy and ghosts in its colour; hiding the straight path changes the picture.
    const ghosts = await viewerValue(page, () => window.pmdplanViewer.overlayGhostCounts());
    assert.ok(ghosts[1] >= 2 && ghosts[2] >= 2, `the other paths have ghost trails: ${ghosts}`);
    const change = await hidingChange(page, join(o.work, 'viewer-paths.png'),
      () => viewerValue(page, (i) => window.pmdplanViewer.setState(i), middle + 1),
      () => pathRow(page, 1).locator('input[type=checkbox]').uncheck());
    assert.ok(change > 0.002, `hiding the straight path hardly changed the image (${(100 * change).toFixed(3)} %)`);
    // The hidden path is in the address: a reload keeps it hidden.
    assert.ok((await viewerValue(page, () => window.location.hash)).endsWith('&hide=1'), 'the hidden path is in the URL');
    await page.reload();
    await page.waitForFunction(() => window.pmdplanViewer && window.pmdplanViewer.ready, null, { timeout: 60_000 });
    assert.equal(await pathRow(page, 1).locator('input[type=checkbox]').isChecked(), false, 'a reload keeps the path hidden');
    assert.equal(await viewerValue(page, () => window.pmdplanViewer.state), middle + 1, 'and the state');
    await pathRow(page, 1).locator('input[type=checkbox]').check();
    assert.ok(!(await viewerValue(page, () => window.location.hash)).includes('hide'), 'shown again: gone from the URL');
    await page.screenshot({ path: join(o.work, 'viewer-paths-page.png') });
    log(`hiding the straight path: ${(100 * change).toFixed(2)} % of pixels; screenshots viewer-paths.png, viewer-paths-page.png`);

    // Play moves every path.
    await viewerValue(page, () => window.pmdplanViewer.setState(0));
    await page.locator('#play').click();
    await page.waitForFunction(() => window.pmdplanViewer.pathStates().every((state) => state > 0), null, { timeout: 20_000 });
    await page.locator('#play').click();
    assert.deepEqual(problems, [], `the paths page reported problems:\n${problems.join('\n')}`);
    await page.close();
  } finally {
    server.kill('SIGTERM');
  }
}

/// Two timed trajectories of the planned path, the second at half the speed limits: the slider
/// runs along the longer, each shows its state at the slider's time, the shorter stays at its
/// last state once it has finished. Screenshot: viewer-paths-timed.png.
export async function checkTimedPathSet(browser, o) {
  const slow = join(o.work, 'paths-slow.trajectory.json');
  execFileSync(o.cli, ['time', o.path, '-o', slow, '--velocity-scale', '0.5', '--acceleration-scale', '0.5']);
  const { server, url } = await serveViewer(o.cli, [o.trajectory, slow], resolve(o.work, 'paths-timed-viewer'));
  try {
    const { page, problems } = await openViewer(browser, url);
    const times = await viewerValue(page, () => [window.pmdplanViewerData.path.timing.times,
      window.pmdplanViewerData.overlay_paths[0].timing.times]);
    const [fast, slower] = times;
    // Half the limits: sqrt(2) times as long where the accelerations bind, twice where the velocities do.
    assert.ok(slower[slower.length - 1] > 1.3 * fast[fast.length - 1], 'half the limits: a longer trajectory');
    const count = await viewerValue(page, () => window.pmdplanViewer.stateCount);
    assert.equal(count, slower.length, 'the slider runs along the longer trajectory');
    assert.ok((await page.locator('#path-sync').innerText()).includes('by time'), 'the legend says the paths play by time');
    const atOrBefore = (list, t) => list.reduce((last, time, j) => (time <= t ? j : last), 0);
    for (const i of [0, Math.floor(count / 4), Math.floor(count / 2), Math.floor((3 * count) / 4), count - 1]) {
      await viewerValue(page, (index) => window.pmdplanViewer.setState(index), i);
      const states = await viewerValue(page, () => window.pmdplanViewer.pathStates());
      assert.deepEqual(states, [atOrBefore(fast, slower[i]), i], `at ${slower[i]} s`);
    }
    assert.equal(atOrBefore(fast, slower[count - 1]), fast.length - 1, 'the shorter one ends at its last state');
    const label = await page.locator('#state-label').innerText();
    assert.ok(label.includes(`of ${slower[count - 1].toFixed(2)} s`), `the clock is the longer trajectory's: ${label}`);
    await viewerValue(page, (index) => window.pmdplanViewer.setState(index), Math.floor(count / 3));
    await page.waitForFunction(() => window.pmdplanViewer.renderCount > 0);
    await page.screenshot({ path: join(o.work, 'viewer-paths-timed.png') });
    log(`timed paths of ${fast[fast.length - 1].toFixed(3)} s and ${slower[slower.length - 1].toFixed(3)} s in sync by time; screenshot viewer-paths-timed.png`);
    assert.deepEqual(problems, [], `the timed paths page reported problems:\n${problems.join('\n')}`);
    await page.close();
  } finally {
    server.kill('SIGTERM');
  }
}

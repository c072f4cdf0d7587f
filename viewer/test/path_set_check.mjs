// Several paths on one page (`pmdplan view A B C`): the planned path, the straight segment from
// its start to its goal (through the can) and the planned path with its goal moved by 0.57 deg.
// The page lists the three in a legend, warns that the third does not end at the task's goal,
// plays them in sync with one slider (by progress: none is timed), shows each path's own state and
// clearance, draws each path's copy of the robot and ghosts in its colour and hides a path on
// request. Screenshots: viewer-paths.png (all three mid-motion), viewer-ends-warning.png.
import assert from 'node:assert/strict';
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
    log(`hiding the straight path: ${(100 * change).toFixed(2)} % of pixels; screenshot viewer-paths.png`);
    await pathRow(page, 1).locator('input[type=checkbox]').check();

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

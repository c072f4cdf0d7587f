// A grasp path in a real browser (docs/grasp_goals.md): the closing phase's hand-target contact is
// drawn as allowed contact (cyan, "grasp contact (allowed)"), never red, and its clearance is from
// the other obstacles, never FCL's -1000 mm; the page's verdict is `pmdplan validate`'s. The same
// path viewed with the sleeved task (an obstacle that is not the target, inside the can's surface)
// is drawn red where the closing hand touches it and judged invalid. Screenshots go to --work.
//
//   node viewer/test/grasp_browser_test.mjs --cli PMDPLAN --path PATH.json --task TASK.yaml
//        --sleeved-task SLEEVED.yaml --work DIR
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { launchChromium } from './chromium.mjs';
import { log, elapsed, serveViewer, openViewer, viewerValue } from './viewer_page.mjs';

function options() {
  const args = process.argv.slice(2);
  const value = (name) => {
    const i = args.indexOf(name);
    return i >= 0 ? args[i + 1] : undefined;
  };
  const o = { cli: value('--cli'), path: value('--path'), task: value('--task'), sleeved: value('--sleeved-task'),
    work: value('--work') };
  if (!o.cli || !o.path || !o.task || !o.sleeved || !o.work) {
    console.error('usage: grasp_browser_test.mjs --cli PMDPLAN --path PATH.json --task TASK.yaml --sleeved-task T.yaml --work DIR');
    process.exit(2);
  }
  return o;
}

/// Every closing state as the page shows it: {state, colliding, contact, text}.
async function closingStates(page) {
  return viewerValue(page, () => {
    const viewer = window.pmdplanViewer;
    const shown = [];
    for (let state = viewer.closingFromState + 1; state < viewer.stateCount; ++state) {
      viewer.setState(state);
      shown.push({ state, colliding: viewer.collidingMeshes(), contact: viewer.contactMeshes(), text: viewer.clearanceText() });
    }
    return shown;
  });
}

async function checkGrasp(browser, o) {
  const { server, url } = await serveViewer(o.cli, [o.path, '--task', o.task], resolve(o.work, 'grasp-viewer'));
  try {
    const { page, problems } = await openViewer(browser, url);
    const verdict = await viewerValue(page, () => window.pmdplanViewer.validationText());
    assert.ok(verdict.startsWith('exact check: valid (approach to point'), `the page's verdict: ${verdict}`);
    assert.ok(await viewerValue(page, () => window.pmdplanViewer.closingFromState) > 0, 'the closing phase is known');
    const states = await closingStates(page);
    for (const shown of states) {
      assert.equal(shown.colliding, 0, `closing state ${shown.state} drawn in collision: ${shown.text}`);
      assert.ok(!/clearance -|minimum -/.test(shown.text), `closing state ${shown.state} shows a negative clearance: ${shown.text}`);
    }
    const last = states[states.length - 1];
    assert.ok(last.contact > 0, 'the goal hand touching the can is drawn as grasp contact');
    assert.match(last.text, /^grasp contact \(allowed\): \d+ hand links? on goal_can · clearance \d+\.\d mm from the other obstacles \(path minimum \d+\.\d mm\)$/);
    const label = await page.locator('#clearance-label').evaluate((element) => ({ className: element.className, title: element.title }));
    assert.equal(label.className, 'contact');
    assert.ok(label.title.includes('thumb_proximal_link'), `the label names the links touching the can: ${label.title}`);
    // Close to the hand, no ghosts, no goal copy over it: the cyan links on the can.
    await page.locator('#ghost-mode').selectOption('off');
    await page.locator('#show-ends').uncheck();
    await page.locator('#view-hand').click();
    await page.screenshot({ path: join(o.work, 'viewer-grasp.png') });
    log(`grasp path: ${states.length} closing states, none in collision; at the goal "${last.text}"; "${verdict}"`);
    assert.deepEqual(problems, [], `the grasp page reported problems:\n${problems.join('\n')}`);
    await page.close();
  } finally {
    server.kill('SIGTERM');
  }
}

async function checkSleeved(browser, o) {
  const { server, url } = await serveViewer(o.cli, [o.path, '--task', o.sleeved], resolve(o.work, 'sleeved-viewer'));
  try {
    const { page, problems } = await openViewer(browser, url);
    const verdict = await viewerValue(page, () => window.pmdplanViewer.validationText());
    assert.ok(verdict.startsWith('exact check: INVALID: segment') && verdict.includes('closing') && verdict.includes('- sleeve'),
      `the page's verdict: ${verdict}`);
    const hit = (await closingStates(page)).find((shown) => shown.colliding > 0);
    assert.ok(hit, 'no closing state is drawn in collision with the sleeve');
    assert.ok(hit.text.startsWith('in collision: '), `the label says so: ${hit.text}`);
    await page.locator('#ghost-mode').selectOption('off');
    await page.locator('#show-ends').uncheck();
    await viewerValue(page, (state) => window.pmdplanViewer.setState(state), hit.state);
    await page.locator('#view-hand').click();
    await page.screenshot({ path: join(o.work, 'viewer-grasp-sleeve.png') });
    log(`sleeved task: closing state ${hit.state} drawn in collision ("${hit.text}"); "${verdict}"`);
    assert.deepEqual(problems, [], `the sleeved page reported problems:\n${problems.join('\n')}`);
    await page.close();
  } finally {
    server.kill('SIGTERM');
  }
}

async function main() {
  const o = options();
  mkdirSync(o.work, { recursive: true });
  const browser = await launchChromium();
  try {
    await checkGrasp(browser, o);
    await checkSleeved(browser, o);
  } finally {
    await browser.close();
  }
  log('all grasp viewer checks passed');
}

main().catch((error) => {
  console.error(`[${elapsed()} s] FAILED: ${error.stack || error}`);
  process.exit(1);
});

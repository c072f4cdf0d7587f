// The glove live in a real browser: socat's pseudo-terminal pair stands in for the glove, this
// script writes 'G' replies into one end, `pmdplan glove stream --device <other end> --serve 0`
// publishes each posture, and Debian's chromium shows the page. Checks: the page says it is live,
// the hand's joints take the recorded posture of the frame it got and move between two moments
// (and so does the picture); unplugging (socat killed) ends the stream on the page and keeps the
// recording. Prints the latency from the serial write to the page's receipt (never asserted).
// Screenshots go to --work.
//
//   node viewer/test/live_glove_browser_test.mjs --cli build/pmdplan --calibration CAL.yaml --sample REC.csv --work DIR
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { closeSync, existsSync, mkdirSync, openSync, readFileSync, writeFileSync, writeSync } from 'node:fs';
import { join } from 'node:path';
import { launchChromium } from './chromium.mjs';
import { decodePng, changedShare } from './png_image.mjs';

const started = Date.now();
const log = (message) => console.log(`[${((Date.now() - started) / 1000).toFixed(1)} s] ${message}`);
const sleep = (ms) => new Promise((done) => setTimeout(done, ms));

function options() {
  const args = process.argv.slice(2);
  const value = (name) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : undefined; };
  const o = { cli: value('--cli'), calibration: value('--calibration'), sample: value('--sample'), work: value('--work') };
  if (!o.cli || !o.calibration || !o.sample || !o.work) {
    console.error('usage: live_glove_browser_test.mjs --cli PMDPLAN --calibration CAL.yaml --sample REC.csv --work DIR');
    process.exit(2);
  }
  return o;
}

/// The raw frames of a glove CSV (time_s first, then the 22 sensors in the glove's order).
function gloveFrames(file) {
  const lines = readFileSync(file, 'utf8').split('\n').filter((line) => line && !line.startsWith('#'));
  return lines.slice(1).map((line) => line.split(',').slice(1).map(Number));
}

const reply = (frame) => Buffer.from([0x47, ...frame, 0]);

async function waitFor(condition, what, ms = 20_000) {
  const until = Date.now() + ms;
  while (!(await condition())) {
    if (Date.now() > until) throw new Error(`timed out waiting for ${what}`);
    await sleep(10);
  }
}

/// Data rows of the posture recording, as numbers (time_s first).
function postureRows(file) {
  const lines = readFileSync(file, 'utf8').split('\n').filter((line) => line && !line.startsWith('#'));
  return { header: lines[0].split(','), rows: lines.slice(1).map((line) => line.split(',').map(Number)) };
}

function percentile(sorted, p) { return sorted[Math.min(sorted.length - 1, Math.floor(p * sorted.length))]; }

async function main() {
  const o = options();
  mkdirSync(o.work, { recursive: true });
  const frames = gloveFrames(o.sample);
  const glovePath = join(o.work, 'glove'), hostPath = join(o.work, 'host');
  const socat = spawn('socat', ['-d', '-d', `pty,raw,echo=0,link=${glovePath}`, `pty,raw,echo=0,link=${hostPath}`], { stdio: 'ignore' });
  await waitFor(() => existsSync(glovePath) && existsSync(hostPath), 'socat\'s pseudo-terminals', 10_000);
  const recording = join(o.work, 'live.csv');
  const stream = spawn(o.cli, ['glove', 'stream', '--device', hostPath, '--poll-rate', '0', '--timeout', '60',
    '--calibration', o.calibration, '-o', recording, '--serve', '0', '--out', join(o.work, 'live-viewer')], { stdio: ['ignore', 'pipe', 'pipe'] });
  let out = '', err = '', exitCode = null;
  stream.stdout.on('data', (chunk) => { out += chunk; });
  stream.stderr.on('data', (chunk) => { err += chunk; });
  const exited = new Promise((done) => stream.on('exit', (code) => { exitCode = code; done(code); }));
  await waitFor(() => /streaming from/.test(out) || exitCode !== null, 'pmdplan glove stream to start', 30_000);
  assert.equal(exitCode, null, `pmdplan glove stream ended before streaming:\n${out}${err}`);
  const url = out.match(/http:\/\/127\.0\.0\.1:\d+\//)[0];
  log(`pmdplan serves the live viewer at ${url}`);

  const gloveFd = openSync(glovePath, 'r+');
  const writtenMs = [];
  let sent = 0;
  const send = (count) => {
    for (let k = 0; k < count; k += 1) {
      writtenMs[sent] = Date.now();
      writeSync(gloveFd, reply(frames[sent % frames.length]));
      sent += 1;
    }
  };

  const browser = await launchChromium();
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    const problems = [];
    page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
    await page.goto(url);
    await page.waitForFunction(() => window.pmdplanViewer && (window.pmdplanViewer.ready || window.pmdplanViewer.error), null, { timeout: 60_000 });
    assert.equal(await page.evaluate(() => window.pmdplanViewer.error), null);
    await page.waitForFunction(() => window.pmdplanViewer.live && window.pmdplanViewer.live.connected, null, { timeout: 20_000 });
    const handJoints = await page.evaluate(() => window.pmdplanViewerData.live.hand_joints);

    // Two moments: frame 30 and frame 110 of the recording (a closing hand against an opener one).
    const moment = async (frame, file) => {
      send(frame + 1 - sent);
      await page.waitForFunction((n) => window.pmdplanViewer.live.lastFrame === n, frame, { timeout: 20_000 }).catch(async (error) => {
        const live = await page.evaluate(() => JSON.stringify({ ...window.pmdplanViewer.live, receipts: undefined }));
        throw new Error(`${error.message}\nthe page's live status: ${live}\n${problems.join('\n')}\npmdplan:\n${out}${err}`);
      });
      // The frame's render is requested on arrival and drawn at the next animation frame.
      await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
      const joints = await page.evaluate((names) => names.map((name) => window.pmdplanViewer.jointValue(name)), handJoints);
      const png = await page.locator('#view canvas').screenshot();
      await page.screenshot({ path: join(o.work, file) });
      return { joints, image: decodePng(png) };
    };
    const first = await moment(30, 'live-glove-frame30.png');
    const badge = await page.locator('#live-badge').textContent();
    assert.match(badge, /LIVE · [\d.]+ fps · latency (< )?[\d.]+ ms/, `the page does not show that it is live: ${badge}`);
    const second = await moment(110, 'live-glove-frame110.png');
    const moved = Math.max(...first.joints.map((value, j) => Math.abs(value - second.joints[j])));
    const changed = changedShare(first.image, second.image);
    log(`between frames 30 and 110 the hand's joints moved up to ${moved.toFixed(3)} rad; ${(100 * changed).toFixed(2)} % of the canvas changed`);
    assert.ok(moved > 0.05, `the hand's joints did not move (${moved} rad)`);
    assert.ok(changed > 0.002, `the picture did not change (${changed})`);

    // Latency: 300 frames at 100 Hz, each timed from its write into the pseudo-terminal.
    const base = sent;
    for (let k = 0; k < 300; k += 1) {
      send(1);
      await sleep(10);
    }
    await page.waitForFunction((n) => window.pmdplanViewer.live.lastFrame === n, sent - 1, { timeout: 20_000 });
    const receipts = await page.evaluate(() => window.pmdplanViewer.live.receipts);
    const serialToPage = [], serialToRead = [], readToPage = [];
    for (const r of receipts) {
      if (r.frame < base) continue;
      serialToPage.push(r.receivedMs - writtenMs[r.frame]);
      serialToRead.push(r.readMs - writtenMs[r.frame]);
      readToPage.push(r.receivedMs - r.readMs);
    }
    for (const list of [serialToPage, serialToRead, readToPage]) list.sort((a, b) => a - b);
    const fps = await page.evaluate(() => window.pmdplanViewer.live.fps);
    console.log(`LATENCY serial write -> page receipt over ${serialToPage.length} frames at 100 Hz: median ${percentile(serialToPage, 0.5)} ms, `
      + `p95 ${percentile(serialToPage, 0.95)} ms, max ${serialToPage[serialToPage.length - 1]} ms `
      + `(serial write -> pmdplan's read: median ${percentile(serialToRead, 0.5).toFixed(1)} ms, p95 ${percentile(serialToRead, 0.95).toFixed(1)} ms; `
      + `pmdplan's read -> page: median ${percentile(readToPage, 0.5).toFixed(1)} ms, p95 ${percentile(readToPage, 0.95).toFixed(1)} ms); `
      + `page rate ${fps.toFixed(1)} fps`);
    writeFileSync(join(o.work, 'latency.json'),
      JSON.stringify({ serialToPageMs: serialToPage, serialToReadMs: serialToRead, readToPageMs: readToPage }) + '\n');
    assert.equal(serialToPage.length, 300, 'the page missed frames');

    // Unplug: the stream ends, the page says so, the recording is kept.
    closeSync(gloveFd);
    socat.kill('SIGTERM');
    await page.waitForFunction(() => window.pmdplanViewer.live.ended !== null, null, { timeout: 20_000 });
    const ended = await page.evaluate(() => window.pmdplanViewer.live.ended);
    assert.match(ended, /closed/, `the page's end reason: ${ended}`);
    await page.screenshot({ path: join(o.work, 'live-glove-ended.png') });
    assert.equal(await exited, 2, `pmdplan glove stream after the unplug:\n${out}${err}`);
    assert.match(err, /frames kept in/);
    const { header, rows } = postureRows(recording);
    assert.equal(rows.length, sent, 'the recording does not hold every frame sent');
    for (const name of handJoints) assert.ok(header.includes(name), `the recording has no column ${name}`);
    // What the page showed at frame 30 is what the recording holds for frame 30.
    handJoints.forEach((name, j) => assert.ok(Math.abs(first.joints[j] - rows[30][header.indexOf(name)]) < 1e-9,
      `${name} on the page at frame 30: ${first.joints[j]}, recorded ${rows[30][header.indexOf(name)]}`));
    assert.deepEqual(problems, []);
    log(`live glove: ${sent} frames through the page; screenshots in ${o.work}`);
  } finally {
    await browser.close();
    socat.kill('SIGKILL');
    stream.kill('SIGKILL');
  }
}

main().catch((error) => {
  console.error(error && error.stack ? error.stack : String(error));
  process.exit(1);
});

// The viewer page as the browser tests drive it: `pmdplan view ... --serve 0` started and its
// address read, the page opened until it reports ready (its errors collected), and frames and
// screenshots of the canvas waited for.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { decodePng, changedShare } from './png_image.mjs';

const started = Date.now();
const seconds = () => ((Date.now() - started) / 1000).toFixed(1);
export const log = (message) => console.log(`[${seconds()} s] ${message}`);
export const elapsed = seconds;

/// Starts `pmdplan view --serve 0` and resolves with the process and the address it prints.
export function serveViewer(cli, paths, folder) {
  const server = spawn(cli, ['view', ...[paths].flat(), '--out', folder, '--serve', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  return new Promise((resolveAddress, reject) => {
    let out = '', err = '';
    const timer = setTimeout(() => reject(new Error(`pmdplan view printed no address within 30 s:\n${out}${err}`)), 30_000);
    server.stdout.on('data', (chunk) => {
      out += chunk;
      const match = out.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (match) {
        clearTimeout(timer);
        resolveAddress({ server, url: match[0] });
      }
    });
    server.stderr.on('data', (chunk) => { err += chunk; });
    server.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`pmdplan view exited with ${code} before serving:\n${out}${err}`));
    });
  });
}

export async function openViewer(browser, url) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const problems = [];
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('console', (message) => { if (message.type() === 'error') problems.push(`console error: ${message.text()}`); });
  page.on('requestfailed', (request) => problems.push(`request failed: ${request.url()}`));
  await page.goto(url);
  await page.waitForFunction(() => window.pmdplanViewer && (window.pmdplanViewer.ready || window.pmdplanViewer.error),
    null, { timeout: 60_000 });
  const error = await page.evaluate(() => window.pmdplanViewer.error);
  assert.equal(error, null, `the viewer reports an error: ${error}`);
  return { page, problems };
}

/// Waits until the page has drawn a frame after `before` frames, then shoots the canvas.
export async function canvasAfterRender(page, before) {
  await page.waitForFunction((n) => window.pmdplanViewer.renderCount > n, before, { timeout: 20_000 });
  const png = await page.locator('#view canvas').screenshot();
  return { png, image: decodePng(png) };
}

/// The share of the canvas that changes when `hide` runs, after `prepare` (which must cause a
/// frame, unless `prepared` says it is already shown); the shot before hiding goes to `file`.
export async function hidingChange(page, file, prepare, hide, prepared = false) {
  let frames = await renderCount(page);
  await prepare();
  const shown = prepared ? { png: await page.locator('#view canvas').screenshot() } : await canvasAfterRender(page, frames);
  if (prepared) shown.image = decodePng(shown.png);
  writeFileSync(file, shown.png);
  frames = await renderCount(page);
  await hide();
  const hidden = await canvasAfterRender(page, frames);
  return changedShare(shown.image, hidden.image);
}

export const renderCount = (page) => page.evaluate(() => window.pmdplanViewer.renderCount);
export const viewerValue = (page, fn, argument) => page.evaluate(fn, argument);


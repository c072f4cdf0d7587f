// Pictures for the documentation, taken with the same headless chromium as the browser test.
//
//   node viewer/tools/capture.mjs --viewer DIR --out viewer.png [--state 0.5] [--view scene|hand]
//       a viewer folder written by `pmdplan view` (opened from the disk), at a fraction of the path
//   node viewer/tools/capture.mjs --svg FIGURE.svg --out figure.png
//       an SVG figure (from `pmdplan synergies ... --plots DIR`) as PNG at its own size
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launchChromium } from '../test/chromium.mjs';

function options() {
  const args = process.argv.slice(2);
  const value = (name, fallback) => {
    const i = args.indexOf(name);
    return i >= 0 ? args[i + 1] : fallback;
  };
  const o = { viewer: value('--viewer'), svg: value('--svg'), out: value('--out'),
    state: Number(value('--state', '0.5')), view: value('--view', 'scene') };
  if (!o.out || !!o.viewer === !!o.svg || !(o.state >= 0 && o.state <= 1) || !['scene', 'hand'].includes(o.view)) {
    console.error('usage: capture.mjs (--viewer DIR [--state 0..1] [--view scene|hand] | --svg FILE) --out FILE.png');
    process.exit(2);
  }
  return o;
}

async function captureViewer(browser, o) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.goto(pathToFileURL(resolve(o.viewer, 'index.html')).href);
  await page.waitForFunction(() => window.pmdplanViewer && (window.pmdplanViewer.ready || window.pmdplanViewer.error),
    null, { timeout: 60_000 });
  const error = await page.evaluate(() => window.pmdplanViewer.error);
  if (error) throw new Error(`the viewer reports: ${error}`);
  const frames = await page.evaluate(() => window.pmdplanViewer.renderCount);
  await page.evaluate((f) => window.pmdplanViewer.setState(Math.round(f * (window.pmdplanViewer.stateCount - 1))), o.state);
  if (o.view === 'hand') await page.locator('#view-hand').click();
  await page.waitForFunction((n) => window.pmdplanViewer.renderCount > n, frames, { timeout: 30_000 });
  await page.screenshot({ path: o.out });
}

async function captureSvg(browser, o) {
  const text = readFileSync(o.svg, 'utf8');
  const width = Number(text.match(/<svg[^>]*\swidth="([\d.]+)"/)?.[1]);
  const height = Number(text.match(/<svg[^>]*\sheight="([\d.]+)"/)?.[1]);
  if (!(width > 0 && height > 0)) throw new Error(`${o.svg}: no width and height on its <svg> element`);
  const page = await browser.newPage({ viewport: { width: Math.ceil(width), height: Math.ceil(height) } });
  await page.goto(pathToFileURL(resolve(o.svg)).href);
  await page.screenshot({ path: o.out });
}

const o = options();
const browser = await launchChromium();
try {
  await (o.viewer ? captureViewer(browser, o) : captureSvg(browser, o));
  console.log(`wrote ${o.out}`);
} finally {
  await browser.close();
}

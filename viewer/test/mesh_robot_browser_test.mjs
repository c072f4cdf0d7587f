// A robot drawn from meshes in a real browser: `pmdplan view` copies the URDF's visual meshes
// (package:// references included) into the folder, the viewer loads them with three's loaders,
// and a link whose mesh is missing falls back to its collision geometry. Screenshots go to --work.
//
//   node viewer/test/mesh_robot_browser_test.mjs --cli PMDPLAN --path PATH.json --task TASK.yaml
//        --package-path DIR --work DIR
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdirSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { launchChromium } from './chromium.mjs';
import { decodePng, imageContent } from './png_image.mjs';

const args = process.argv.slice(2);
const option = (name) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : undefined; };
const o = { cli: option('--cli'), path: option('--path'), task: option('--task'), packages: option('--package-path'), work: option('--work') };
if (!o.cli || !o.path || !o.task || !o.packages || !o.work) {
  console.error('usage: mesh_robot_browser_test.mjs --cli PMDPLAN --path PATH.json --task TASK.yaml --package-path DIR --work DIR');
  process.exit(2);
}

function serve(folder) {
  const server = spawn(o.cli, ['view', o.path, '--task', o.task, '--package-path', o.packages, '--out', folder, '--serve', '0'],
    { stdio: ['ignore', 'pipe', 'pipe'] });
  return new Promise((resolveUrl, reject) => {
    let text = '';
    const timer = setTimeout(() => reject(new Error(`pmdplan view printed no address:\n${text}`)), 30_000);
    const read = (chunk) => {
      text += chunk;
      const match = text.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (match) { clearTimeout(timer); resolveUrl({ server, url: match[0] }); }
    };
    server.stdout.on('data', read);
    server.stderr.on('data', read);
    server.on('exit', (code) => { clearTimeout(timer); reject(new Error(`pmdplan view exited with ${code}:\n${text}`)); });
  });
}

/// Opens the viewer, waits until every robot mesh has loaded or failed, shoots the canvas.
async function meshesSettled(browser, url, shot) {
  const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
  await page.goto(url);
  await page.waitForFunction(() => window.pmdplanViewer && (window.pmdplanViewer.error ||
    (window.pmdplanViewer.ready && window.pmdplanViewer.robotMeshes().pending === 0)), null, { timeout: 60_000 });
  assert.equal(await page.evaluate(() => window.pmdplanViewer.error), null);
  const before = await page.evaluate(() => window.pmdplanViewer.renderCount);
  await page.waitForFunction((n) => window.pmdplanViewer.renderCount > n, before, { timeout: 20_000 }).catch(() => {});
  const status = await page.evaluate(() => window.pmdplanViewer.robotMeshes());
  const png = await page.locator('#view canvas').screenshot();
  writeFileSync(join(o.work, shot), png);
  await page.close();
  return { status, content: imageContent(decodePng(png)) };
}

async function main() {
  mkdirSync(o.work, { recursive: true });
  const folder = resolve(o.work, 'mesh-viewer');
  const { server, url } = await serve(folder);
  const browser = await launchChromium();
  try {
    const whole = await meshesSettled(browser, url, 'mesh-robot.png');
    console.log(`meshes: ${JSON.stringify(whole.status)}; ${(100 * whole.content.foregroundShare).toFixed(1)} % drawn`);
    assert.ok(whole.status.loaded >= 10, `expected the toy hand's meshes to load: ${JSON.stringify(whole.status)}`);
    assert.equal(whole.status.failed, 0);
    assert.equal(whole.status.fallbackLinks, 0);
    assert.ok(whole.content.foregroundShare > 0.02, 'the canvas looks blank');

    // One mesh gone from the folder: that link is drawn from its collision boxes instead.
    const meshDirectory = join(folder, 'robot-meshes');
    const palm = readdirSync(meshDirectory).find((name) => name.endsWith('-palm.stl'));
    assert.ok(palm, 'the palm mesh was copied into the folder');
    rmSync(join(meshDirectory, palm));
    const partial = await meshesSettled(browser, url, 'mesh-robot-fallback.png');
    console.log(`without ${palm}: ${JSON.stringify(partial.status)}`);
    assert.equal(partial.status.failed, 1);
    assert.equal(partial.status.fallbackLinks, 1);
    assert.equal(partial.status.loaded, whole.status.loaded - 1);
  } finally {
    await browser.close();
    server.kill();
  }
}

main().then(() => console.log('mesh robot browser test passed'), (error) => {
  console.error(error);
  process.exit(1);
});

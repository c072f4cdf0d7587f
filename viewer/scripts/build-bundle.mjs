// Builds the viewer into dist/: the page (static/), and src/ bundled with three.js and
// urdf-loader into one classic script (an ES module would not load from file://), plus the
// notices of the bundled packages. `--check` builds in memory and fails if dist/ differs, so a
// test can tell that the committed bundle matches its sources.
//
//   npm --prefix viewer ci && npm --prefix viewer run build      (or: node viewer/scripts/build-bundle.mjs)
import * as esbuild from 'esbuild';
import { readFileSync, writeFileSync, mkdirSync, existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const dist = join(root, 'dist');
const check = process.argv.includes('--check');

const BUNDLED_PACKAGES = ['three', 'urdf-loader'];

function notices() {
  const parts = ['Third-party software bundled into pmdplan-viewer.js\n'];
  for (const name of BUNDLED_PACKAGES) {
    const directory = join(root, 'node_modules', name);
    const manifest = JSON.parse(readFileSync(join(directory, 'package.json'), 'utf8'));
    const repository = typeof manifest.repository === 'string' ? manifest.repository : manifest.repository?.url ?? '';
    parts.push(`\n==== ${name} ${manifest.version} (${manifest.license}) ${repository}\n`);
    const licence = ['LICENSE', 'LICENSE.md', 'LICENSE.txt'].map((f) => join(directory, f)).find((f) => existsSync(f));
    parts.push(licence ? `\n${readFileSync(licence, 'utf8').trim()}\n`
      : `\nLicensed under the ${manifest.license} licence (https://spdx.org/licenses/${manifest.license}.html);` +
        ' the package ships no licence file of its own.\n');
  }
  return parts.join('');
}

async function build() {
  const result = await esbuild.build({
    entryPoints: [join(root, 'src', 'main.js')],
    bundle: true,
    format: 'iife',
    minify: true,
    target: ['chrome100', 'firefox100', 'safari15'],
    legalComments: 'none',  // the notices go, whole, into THIRD_PARTY_NOTICES.txt
    write: false,
    logLevel: 'warning',
  });
  return {
    'pmdplan-viewer.js': result.outputFiles[0].text,
    'index.html': readFileSync(join(root, 'static', 'index.html'), 'utf8'),
    'viewer.css': readFileSync(join(root, 'static', 'viewer.css'), 'utf8'),
    'THIRD_PARTY_NOTICES.txt': notices(),
  };
}

const files = await build();
if (check) {
  const stale = Object.entries(files).filter(([name, text]) => {
    const file = join(dist, name);
    return !existsSync(file) || readFileSync(file, 'utf8') !== text;
  });
  if (stale.length) {
    console.error(`viewer/dist is out of date (${stale.map(([n]) => n).join(', ')}): run npm --prefix viewer run build`);
    process.exit(1);
  }
  console.log('viewer/dist matches its sources');
} else {
  mkdirSync(dist, { recursive: true });
  for (const [name, text] of Object.entries(files)) writeFileSync(join(dist, name), text);
  const size = Buffer.byteLength(files['pmdplan-viewer.js']);
  console.log(`wrote ${dist}: pmdplan-viewer.js ${(size / 1024).toFixed(0)} KiB`);
}

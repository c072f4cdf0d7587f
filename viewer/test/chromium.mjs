// Debian's chromium, headless, driven by playwright-core: the one place that knows the flags a
// root shell in a container needs (no sandbox) and how WebGL runs without a GPU (SwiftShader).
import { chromium } from 'playwright-core';
import { existsSync } from 'node:fs';

export const CHROMIUM_PATH = process.env.PMDPLAN_CHROMIUM || '/usr/bin/chromium';

const FLAGS = [
  '--no-sandbox',                      // root in a container: the setuid sandbox cannot start
  '--enable-unsafe-swiftshader',       // WebGL on the CPU when there is no GPU
  '--use-angle=swiftshader',
  '--ignore-gpu-blocklist',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-default-apps',
  '--no-first-run',
  '--mute-audio',
];

/// playwright-core gives every launch a fresh temporary profile (user data dir) of its own.
export async function launchChromium() {
  if (!existsSync(CHROMIUM_PATH))
    throw new Error(`no chromium at ${CHROMIUM_PATH}: install it with scripts/install-deps (Debian package chromium) or set PMDPLAN_CHROMIUM`);
  return chromium.launch({ executablePath: CHROMIUM_PATH, headless: true, args: FLAGS, timeout: 60_000 });
}

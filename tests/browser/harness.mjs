// What the browser test, the screenshot and the benchmark share: `quaternia explore` on a free
// loopback port, and Debian's chromium driven headless by playwright-core. Playwright never
// downloads a browser here; the flags keep chromium off the network (this is a closed one).
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

export const CHROMIUM = process.env.QUATERNIA_CHROMIUM || '/usr/bin/chromium';

// Starts `binary explore --port 0`, resolves to { url, stop } once it prints its URL.
export function startServer(binary, extraArguments = []) {
  return new Promise((resolve, reject) => {
    const server = spawn(binary, ['explore', '--port', '0', ...extraArguments],
                         { stdio: ['ignore', 'pipe', 'inherit'] });
    let output = '';
    const timer = setTimeout(() => reject(new Error('server did not start: ' + output)), 20000);
    server.on('exit', (code) => reject(new Error(`server exited with ${code}: ${output}`)));
    server.stdout.on('data', (chunk) => {
      output += chunk;
      const match = /(http:\/\/\S+)/.exec(output);
      if (!match) return;
      clearTimeout(timer);
      server.removeAllListeners('exit');
      // Never leave the server behind, whatever ends this script.
      process.on('exit', () => server.kill('SIGTERM'));
      resolve({ url: match[1], stop: () => server.kill('SIGTERM'), process: server });
    });
  });
}

// Launches headless chromium with a fresh profile (Playwright passes it as --user-data-dir);
// resolves to { context, close }.
export async function launchBrowser() {
  const profile = mkdtempSync(join(tmpdir(), 'quaternia-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  return {
    context,
    close: async () => {
      await context.close();
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

// Options --name value from process.argv.
export function option(name, fallback) {
  const index = process.argv.indexOf('--' + name);
  return index >= 0 ? process.argv[index + 1] : fallback;
}

// Resolves once the page shows its final refinement (body[data-state=final]).
export async function waitForFinal(page, timeout = 60000) {
  await page.waitForSelector('body[data-state=final]', { timeout });
}

// The bytes of the image the page shows.
export async function shownImage(page) {
  const base64 = await page.evaluate(async () => {
    const bytes = new Uint8Array(await (await fetch(document.getElementById('view').src)).arrayBuffer());
    let text = '';
    for (const b of bytes) text += String.fromCharCode(b);
    return btoa(text);
  });
  return Buffer.from(base64, 'base64');
}

// The explorer in a real browser (Debian's headless chromium): load the page, drag a slider and
// see the image change, click the Mandelbrot map and see c change, copy the CLI command and
// render it with `quaternia render` to the same picture, byte for byte.
// Usage: node explore_test.mjs --binary build/quaternia [--screenshot docs/explorer.png]
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { launchBrowser, option, shownImage, startServer, waitForFinal } from './harness.mjs';

const binary = option('binary', 'build/quaternia');
const screenshot = option('screenshot', null);
const server = await startServer(binary);
const { context, close } = await launchBrowser();
const work = mkdtempSync(join(tmpdir(), 'quaternia-browser-'));
const step = (text) => console.log('browser test: ' + text);

try {
  const page = await context.newPage();
  await page.setViewportSize(screenshot ? { width: 1280, height: 760 } : { width: 900, height: 560 });
  page.on('pageerror', (error) => { throw error; });
  // A small final size keeps the test quick; screenshots fit the window.
  await page.goto(server.url + (screenshot ? '' : '?size=240x160'));
  await waitForFinal(page);
  const first = await shownImage(page);
  step(`page loaded, final image ${first.length} bytes`);

  if (screenshot) {
    await page.waitForFunction(() => document.body.dataset.map === 'ready');
    await page.screenshot({ path: screenshot });
    step('wrote ' + screenshot);
  } else {
    // Drag the slider of c's i component with the mouse.
    const slider = page.locator('#ctl-fractal_c-1');
    await slider.scrollIntoViewIfNeeded();
    const box = await slider.boundingBox();
    const before = await page.evaluate(() => JSON.parse(document.body.dataset.c));
    await page.mouse.move(box.x + box.width * 0.5, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * 0.62, box.y + box.height / 2, { steps: 8 });
    await page.mouse.up();
    await page.waitForFunction((old) => document.body.dataset.c !== old, JSON.stringify(before));
    await waitForFinal(page);
    const dragged = await shownImage(page);
    assert.notDeepEqual(dragged, first, 'dragging the slider changes the image');
    step('slider drag changed the image');

    // Click the Mandelbrot map near the rabbit's c.
    const map = page.locator('#map');
    await map.scrollIntoViewIfNeeded();
    const mapBox = await map.boundingBox();
    // The map shows centre (-0.6, 0), 3.2 wide, 288 x 216 canvas pixels.
    const scale = 3.2 / 288;
    const x = 144 + (-0.12 + 0.6) / scale, y = 108 - 0.74 / scale;
    await map.click({ position: { x: x * mapBox.width / 288, y: y * mapBox.height / 216 } });
    await page.waitForFunction(() => JSON.parse(document.body.dataset.c)[2] === 0);
    const c = await page.evaluate(() => JSON.parse(document.body.dataset.c));
    assert.ok(Math.abs(c[0] + 0.12) < 0.02 && Math.abs(c[1] - 0.74) < 0.02, `c = ${c}`);
    assert.match(await page.locator('#c-value').textContent(), /c = -0\.1/);
    await waitForFinal(page);
    const shown = await shownImage(page);
    step(`map click set c = ${c}`);

    // Copy the CLI command and render it.
    await page.click('#copy-cli');
    await page.waitForFunction(() => document.body.dataset.cli);
    const command = await page.evaluate(() => document.body.dataset.cli);
    step('copied: ' + command);
    assert.match(command, /^quaternia render .* -o quaternia\.png$/);
    const output = join(work, 'cli.png');
    execFileSync('sh', ['-c', command.replace(/^quaternia /, '"$0" ')
                                     .replace(/-o quaternia\.png$/, '-o "$1"'), binary, output]);
    assert.ok(readFileSync(output).equals(shown),
              'quaternia render of the copied command gives the PNG the page shows');
    step('quaternia render reproduced the page\'s image byte for byte');
  }
  console.log('browser test: passed');
} finally {
  await close();
  server.stop();
  rmSync(work, { recursive: true, force: true });
}

// Explorer timings in headless chromium: time to first frame at 640x360 (a quarter-resolution
// frame, 160x90 with one sample, arrives first) and frames shown per second while dragging to
// orbit. Medians of several runs. Usage: node explore_bench.mjs --binary build/quaternia [--runs 5]
import { launchBrowser, option, startServer, waitForFinal } from './harness.mjs';

const binary = option('binary', 'build/quaternia');
const runs = +option('runs', 5);
const median = (values) => values.slice().sort((a, b) => a - b)[Math.floor(values.length / 2)];
const server = await startServer(binary);
const { context, close } = await launchBrowser();
try {
  const firstFrame = [], firstFrameScript = [], firstRender = [], fps = [];
  for (let run = 0; run < runs; ++run) {
    const page = await context.newPage();
    await page.setViewportSize({ width: 980, height: 400 });
    await page.goto(server.url + '?size=640x360');
    await page.waitForFunction(() => window.exploreTiming && window.exploreTiming.firstFrameMs !== null);
    const timing = await page.evaluate(() => window.exploreTiming);
    firstFrame.push(timing.firstFrameSinceNavigationMs);
    firstFrameScript.push(timing.firstFrameMs);
    firstRender.push(timing.firstRenderMs);
    await waitForFinal(page);

    // Drag across the view for 3 s, a mouse event every 16 ms (60 Hz).
    const box = await page.locator('#viewport').boundingBox();
    const y = box.y + box.height / 2;
    await page.mouse.move(box.x + 100, y);
    await page.mouse.down();
    const before = await page.evaluate(() => window.exploreTiming.frames.length);
    const start = Date.now();
    let x = 100;
    while (Date.now() - start < 3000) {
      x = 100 + ((x - 100 + 3) % 400);
      await page.mouse.move(box.x + x, y);
      await page.waitForTimeout(16);
    }
    const seconds = (Date.now() - start) / 1000;
    const after = await page.evaluate(() => window.exploreTiming.frames.length);
    await page.mouse.up();
    fps.push((after - before) / seconds);
    await page.close();
  }
  console.log(JSON.stringify({
    size: '640x360', runs,
    first_frame_ms_since_navigation: median(firstFrame),
    first_frame_ms_since_script: median(firstFrameScript),
    first_frame_server_render_ms: median(firstRender),
    drag_frames_per_second: median(fps),
  }));
} finally {
  await close();
  server.stop();
}

// tests/web/stroke_latency.mjs — how long a painted stroke's elements take to appear, measured
// in the browser. Starts `tessera studio`, opens it in headless chromium, and paints, with
// mouse events at 60 Hz, a stroke of sticks_2d that grows about 100 elements on a fresh
// 60 x 40 canvas, `--runs` times (3). The front end records each segment it sends
// (stroke_sender.js): the time of its pointer events, when it was sent, when its job had
// ended and the session was read back, and when the frame with its elements was drawn.
// Prints, per run and overall: pointer event -> elements drawn (from the segment's first and
// last events), the parts of it (waiting for the previous segment, server, drawing), and the
// time from the pointer's release to the stroke's last elements on screen. Then, `--runs`
// times, "fill the rest" of a canvas sized for ~2,000 poisson_disk_2d dots after one paint
// stroke: the time from the click on "Fill the rest" to the filled canvas drawn.
//   node tests/web/stroke_latency.mjs [--runs N] [--json FILE]     (TESSERA_BIN=build/bin/tessera)
import { writeFileSync } from 'node:fs';
import { startServer, launchBrowser, openStudio, waitIdle, newCanvas, choose, setTool, setWidth, drawStroke, withTimeout } from './studio_harness.mjs';

const args = process.argv.slice(2);
const runs = +(args[args.indexOf('--runs') + 1] || 3) || 3;
const jsonOut = args.includes('--json') ? args[args.indexOf('--json') + 1] : null;

const stats = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const q = (p) => s[Math.min(s.length - 1, Math.floor(p * s.length))];
  return { n: s.length, mean: s.reduce((a, b) => a + b, 0) / s.length, median: q(0.5), p90: q(0.9), max: s[s.length - 1] };
};
const fmt = (st) => `mean ${st.mean.toFixed(0)} · median ${st.median.toFixed(0)} · p90 ${st.p90.toFixed(0)} · max ${st.max.toFixed(0)} ms (n=${st.n})`;

const server = await startServer();
let browser = null;
const results = [];
const fills = [];
try {
  browser = await launchBrowser();
  const { page } = await openStudio(browser, server.url);
  for (let run = 0; run < runs; ++run) {
    await newCanvas(page, 'box:0,0,60,40');
    await choose(page, 'sticks_2d');
    await setTool(page, 'paint');
    await setWidth(page, 4);
    const before = await page.evaluate(() => window.__tessera.metrics.paint.length);
    // 75 pointer moves at 60 Hz along a gentle wave, 37.5 units long (about 100 elements).
    const pts = Array.from({ length: 76 }, (_, i) => [10 + i * 0.5, 20 + 3 * Math.sin(i / 12)]);
    const clients = await page.evaluate((p) => p.map((q) => window.__tessera.view.worldToClient([q[0], q[1], 0])), pts);
    await page.mouse.move(...clients[0]);
    await page.mouse.down();
    for (const c of clients.slice(1)) {
      await page.mouse.move(c[0], c[1]);
      await page.waitForTimeout(16);
    }
    const releasedAt = await page.evaluate(() => performance.now());
    await page.mouse.up();
    await withTimeout(waitIdle(page, 120000), 130000, 'the stroke being applied');
    const segments = await page.evaluate((b) => window.__tessera.metrics.paint.slice(b), before);
    const elements = await page.evaluate(() => window.__tessera.store.state.view.model.elements.length);
    const ok = segments.filter((s) => !s.error);
    results.push({
      run,
      elements,
      segments: segments.length,
      errors: segments.length - ok.length,
      fromFirstEvent: ok.map((s) => s.drawnAt - s.firstEventAt),
      fromLastEvent: ok.map((s) => s.drawnAt - s.lastEventAt),
      waiting: ok.map((s) => s.sentAt - s.lastEventAt),
      server: ok.map((s) => s.doneAt - s.sentAt),
      post: ok.map((s) => s.postMs),
      job: ok.map((s) => s.jobMs),
      read: ok.map((s) => s.readMs),
      drawing: ok.map((s) => s.drawnAt - s.doneAt),
      perElementFirst: ok.map((s) => ({ added: s.added, ms: s.drawnAt - s.firstEventAt })),
      releaseToLast: Math.max(...ok.map((s) => s.drawnAt)) - releasedAt,
      firstElementsAfter: ok.length ? ok[0].drawnAt - ok[0].firstEventAt : null,
    });
    const r = results[results.length - 1];
    console.log(`run ${run + 1}: ${elements} elements in ${r.segments} segments (${r.errors} failed); first elements on screen ${r.firstElementsAfter.toFixed(0)} ms after the press; last ${r.releaseToLast.toFixed(0)} ms after the release`);
  }
  for (let run = 0; run < runs; ++run) {
    // poisson_disk_2d: 110 dots in 10 x 10, so a side of sqrt(2000 / 1.1) holds ~2,000.
    const side = Math.sqrt(2000 / 1.1);
    await newCanvas(page, `box:0,0,${side.toFixed(2)},${side.toFixed(2)}`);
    await choose(page, 'poisson_disk_2d');
    await setTool(page, 'paint');
    await setWidth(page, 4);
    await drawStroke(page, Array.from({ length: 30 }, (_, i) => [0.3 * side + i * 0.4 * side / 29, 0.5 * side]));
    await withTimeout(waitIdle(page, 120000), 130000, 'the stroke being applied');
    const ms = await page.evaluate(
      () =>
        new Promise((resolve) => {
          const t0 = performance.now();
          document.getElementById('fill').click();
          const check = () => {
            if (window.__tessera.busy()) requestAnimationFrame(check);
            else requestAnimationFrame(() => resolve(performance.now() - t0));
          };
          requestAnimationFrame(check);
        }),
    );
    const elements = await page.evaluate(() => window.__tessera.store.state.view.model.elements.length);
    fills.push({ run, ms, elements });
    console.log(`fill run ${run + 1}: ${elements} elements on screen ${ms.toFixed(0)} ms after the click`);
  }
} finally {
  if (browser) await browser.close().catch(() => {});
  await server.stop();
}

const all = (key) => results.flatMap((r) => r[key]);
const weighted = results.flatMap((r) => r.perElementFirst.flatMap((s) => Array(s.added || 0).fill(s.ms)));
console.log('\nstroke latency, 60 x 40 canvas, sticks_2d, brush width 4, pointer events at 60 Hz:');
console.log(`  elements per stroke: ${results.map((r) => r.elements).join(', ')}`);
console.log(`  pointer event -> its elements drawn (segment's first event): ${fmt(stats(all('fromFirstEvent')))}`);
console.log(`  pointer event -> its elements drawn (segment's last event):  ${fmt(stats(all('fromLastEvent')))}`);
console.log(`  per element (first event of its segment -> drawn):           ${fmt(stats(weighted))}`);
console.log(`    waiting for the previous segment: ${fmt(stats(all('waiting')))}`);
console.log(`    server (POST op, job, GET session): ${fmt(stats(all('server')))}`);
console.log(`      POST /ops (paint in the request): ${fmt(stats(all('post')))}`);
console.log(`      a paint job (large segments):   ${fmt(stats(all('job')))}`);
console.log(`      GET /sessions/ID (no changes):  ${fmt(stats(all('read')))}`);
console.log(`    drawing (next frames):            ${fmt(stats(all('drawing')))}`);
console.log(`  release -> last elements drawn: ${results.map((r) => r.releaseToLast.toFixed(0)).join(', ')} ms`);
if (fills.length)
  console.log(`fill the rest, ~2,000 poisson_disk_2d dots, click -> drawn: ${fmt(stats(fills.map((f) => f.ms)))}; elements ${fills.map((f) => f.elements).join(', ')}`);
if (jsonOut) writeFileSync(jsonOut, `${JSON.stringify({ strokes: results, fills }, null, 1)}\n`);

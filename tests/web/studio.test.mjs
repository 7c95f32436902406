// tests/web/studio.test.mjs — the studio in a real browser (docs/studio.md, "Front end").
// Run by ctest as `studio_browser` (through run_studio_test.sh, which skips it with exit code
// 77 when node, /usr/bin/chromium or the built bundle are missing), or by hand:
//   TESSERA_BIN=build/bin/tessera node --test tests/web/studio.test.mjs
//
// Starts `tessera studio --port 0` over the source tree, opens it in headless chromium
// (playwright-core, Debian's browser), and as a designer would: makes a 40 x 30 canvas, picks
// sticks_2d and paints a stroke with the mouse, picks poisson_disk_2d and paints another, draws
// a direction stroke, clicks "Fill the rest", waits for the job, exports JSON from the Export
// menu and checks the downloaded file:
//   - element count within 15% of the density's: the canvas area, each place counted at the
//     density (elements per area of its exemplar) of the palette entry of the nearest element;
//   - sticks near a stroke (paint or direction) point along it: the angle between the
//     element's orientation quaternion (its yaw; the exemplar's sticks lie along +x) and the
//     stroke's tangent, as lines, is within 15 degrees for at least 85% of them and in the median;
//   - no two elements of different palette entries closer than 0.8 of their summed weights
//     (per sample pair: types[].weights x element scale, as Eq. 3 of the paper).
// Screenshots go to $TESSERA_STUDIO_SCREENSHOTS (default BUILD/studio_screenshots/).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import {
  buildDir, sourceDir, startServer, launchBrowser, openStudio, waitIdle, newCanvas, choose, setTool, setWidth,
  drawStroke, withTimeout,
} from './studio_harness.mjs';

const shots = process.env.TESSERA_STUDIO_SCREENSHOTS || join(buildDir, 'studio_screenshots');
const CANVAS = { w: 40, h: 30 };

// Strokes in canvas coordinates.
const wave = (x0, x1, y, amp, n) => Array.from({ length: n + 1 }, (_, i) => {
  const t = i / n;
  return [x0 + (x1 - x0) * t, y + amp * Math.sin(t * Math.PI * 1.5)];
});
const line = (a, b, n) => Array.from({ length: n + 1 }, (_, i) => [a[0] + ((b[0] - a[0]) * i) / n, a[1] + ((b[1] - a[1]) * i) / n]);
const STICKS_STROKE = wave(4, 36, 8, 2.5, 40);
const DOTS_STROKE = line([3, 26], [12, 21], 14);
const DIRECTION_STROKE = line([21, 13], [37, 26], 24);

test('studio: paint, direct, fill and export in a real browser', { timeout: 300000 }, async (t) => {
  mkdirSync(shots, { recursive: true });
  const server = await startServer();
  let browser = null;
  t.after(async () => {
    if (browser) await browser.close().catch(() => {});
    await server.stop();
  });
  browser = await launchBrowser();
  const { page, errors } = await openStudio(browser, server.url);
  const shot = (name) => page.screenshot({ path: join(shots, name), timeout: 15000 });

  await t.test('palette lists the built-in exemplars with thumbnails', async () => {
    const names = await page.$$eval('.swatch', (els) => els.map((e) => e.dataset.name));
    assert.ok(names.includes('sticks_2d') && names.includes('poisson_disk_2d'), `palette: ${names}`);
    const drawn = await page.$eval('.swatch[data-name="sticks_2d"] canvas', (c) => {
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let lit = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] > 150) ++lit;
      return lit / (d.length / 4);
    });
    assert.ok(drawn > 0.05, `the sticks thumbnail is drawn (${(drawn * 100).toFixed(1)}% lit)`);
    await shot('01_palette.png');
  });

  await newCanvas(page, `box:0,0,${CANVAS.w},${CANVAS.h}`);
  await setWidth(page, 4);

  await t.test('painting grows elements along the stroke while it is drawn', async () => {
    await choose(page, 'sticks_2d');
    await setTool(page, 'paint');
    await drawStroke(page, STICKS_STROKE, { stepMs: 25 });
    await waitIdle(page);
    const segments = await page.evaluate(() => window.__tessera.metrics.paint.filter((m) => m.stroke === 1));
    assert.ok(segments.length >= 3, `the stroke went out in ${segments.length} segments while drawn`);
    assert.ok(segments.every((s) => !s.error), JSON.stringify(segments.filter((s) => s.error)));
    // The first segment's elements were drawn before the pointer was released.
    const painted = await page.evaluate(() => window.__tessera.store.state.view.model.elements.length);
    assert.ok(painted > 20, `${painted} sticks painted`);
    await choose(page, 'poisson_disk_2d');
    await drawStroke(page, DOTS_STROKE, { stepMs: 25 });
    await waitIdle(page);
    await shot('02_painted.png');
  });

  await t.test('a direction stroke and fill the rest', async () => {
    await setTool(page, 'direction');
    await drawStroke(page, DIRECTION_STROKE, { stepMs: 10 });
    await waitIdle(page);
    const ops = await page.evaluate(() => window.__tessera.store.state.ops.map((o) => o.op));
    assert.equal(ops[ops.length - 1], 'direction');
    await page.click('#fill');
    // The status bar shows the job with its fraction while it runs.
    await page.waitForSelector('#job:not([hidden])', { timeout: 10000 });
    await waitIdle(page, 240000);
    const message = await page.textContent('#status-message');
    assert.match(message, /^Filled/, `status: ${message}`);
    await shot('03_filled.png');
  });

  let exported = null;
  await t.test('export JSON downloads the arrangement', async () => {
    await page.click('#export-button');
    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: 30000 }),
      page.click('#export-items button[data-format="json"]'),
    ]);
    const file = join(shots, 'studio_export.json');
    await withTimeout(download.saveAs(file), 30000, 'saving the download');
    exported = JSON.parse(readFileSync(file, 'utf8'));
    assert.equal(exported.format, 'tessera');
    assert.ok(exported.elements.length > 0);
  });

  // The palette entry of each type, from the session (per sample of the same arrangement).
  const view = await page.evaluate(() => {
    const v = window.__tessera.store.state.view;
    return { palette: v.palette, sampleEntries: v.sampleEntries, types: v.model.types.map((x) => x.name),
      elements: v.model.elements.map((e) => ({ type: e.type, n: e.samples.length })) };
  });
  const entryOfType = new Map();
  let k = 0;
  for (const e of view.elements) {
    entryOfType.set(view.types[e.type], view.palette[view.sampleEntries[k]]);
    k += e.n;
  }
  const elements = exported.elements.map((e) => ({
    type: e.type,
    entry: entryOfType.get(e.type),
    samples: (e.samples || [e.position]).map((p) => [p[0], p[1]]),
    scale: e.scale || 1,
    q: e.orientation || [Math.cos((e.angle || 0) / 2), 0, 0, Math.sin((e.angle || 0) / 2)],
  }));
  const report = { elements: elements.length };

  await t.test('element count near the density of the palette entries', () => {
    const density = {};
    for (const name of ['sticks_2d', 'poisson_disk_2d']) {
      const ex = JSON.parse(readFileSync(join(sourceDir, 'examples', `${name}.json`), 'utf8'));
      const area = (ex.domain.max[0] - ex.domain.min[0]) * (ex.domain.max[1] - ex.domain.min[1]);
      density[name] = ex.elements.length / area;
    }
    // Each cell of a fine grid counts at the density of the nearest element's entry.
    const centres = elements.map((e) => [centroid(e.samples), e.entry]);
    const cell = 0.25;
    let expected = 0;
    for (let y = cell / 2; y < CANVAS.h; y += cell)
      for (let x = cell / 2; x < CANVAS.w; x += cell) {
        let best = Infinity;
        let entry = null;
        for (const [c, en] of centres) {
          const d = (c[0] - x) ** 2 + (c[1] - y) ** 2;
          if (d < best) {
            best = d;
            entry = en;
          }
        }
        expected += cell * cell * density[entry];
      }
    report.expected = Math.round(expected);
    const ratio = elements.length / expected;
    report.count_ratio = +ratio.toFixed(3);
    assert.ok(Math.abs(ratio - 1) <= 0.15, `${elements.length} elements, density says ${expected.toFixed(0)} (ratio ${ratio.toFixed(2)})`);
  });

  await t.test('sticks near a stroke point along it (within 15 degrees)', () => {
    const strokes = [STICKS_STROKE, DIRECTION_STROKE];
    const angles = [];
    for (const e of elements) {
      if (e.entry !== 'sticks_2d') continue;
      const c = centroid(e.samples);
      let best = null;
      for (const s of strokes) {
        const near = nearestOnPolyline(s, c);
        if (near.distance <= 1.5 && near.interior && (!best || near.distance < best.distance)) best = near;
      }
      if (!best) continue;
      const yaw = 2 * Math.atan2(e.q[3], e.q[0]);
      angles.push(lineAngle(yaw, Math.atan2(best.tangent[1], best.tangent[0])));
    }
    angles.sort((a, b) => a - b);
    const within = angles.filter((a) => a <= 15).length / angles.length;
    report.aligned = { sticks_near_strokes: angles.length, within_15deg: +within.toFixed(3), median_deg: +angles[Math.floor(angles.length / 2)].toFixed(2) };
    assert.ok(angles.length >= 20, `only ${angles.length} sticks near the strokes`);
    assert.ok(within >= 0.85, `${(within * 100).toFixed(0)}% of ${angles.length} sticks within 15 degrees of the stroke (median ${report.aligned.median_deg})`);
    assert.ok(report.aligned.median_deg <= 15);
  });

  await t.test('no two elements of different palette entries closer than 0.8 of their summed weights', () => {
    const weights = new Map(exported.types.map((ty) => [ty.name, ty.weights || []]));
    const samples = [];
    elements.forEach((e, i) => e.samples.forEach((p, s) => samples.push({ p, i, entry: e.entry, w: (weights.get(e.type)[s] ?? weights.get(e.type)[0]) * e.scale })));
    assert.ok(samples.every((s) => Number.isFinite(s.w) && s.w > 0), 'every type has its weights in the export');
    const maxW = Math.max(...samples.map((s) => s.w));
    const grid = new Map();
    const key = (x, y) => `${Math.floor(x / (4 * maxW))},${Math.floor(y / (4 * maxW))}`;
    for (const s of samples) {
      const kk = key(s.p[0], s.p[1]);
      if (!grid.has(kk)) grid.set(kk, []);
      grid.get(kk).push(s);
    }
    let worst = Infinity;
    const bad = [];
    for (const s of samples) {
      const gx = Math.floor(s.p[0] / (4 * maxW));
      const gy = Math.floor(s.p[1] / (4 * maxW));
      for (let dx = -1; dx <= 1; ++dx)
        for (let dy = -1; dy <= 1; ++dy)
          for (const o of grid.get(`${gx + dx},${gy + dy}`) || []) {
            if (o.entry === s.entry || o.i <= s.i) continue;
            const ratio = Math.hypot(o.p[0] - s.p[0], o.p[1] - s.p[1]) / (s.w + o.w);
            worst = Math.min(worst, ratio);
            if (ratio < 0.8) bad.push([s.i, o.i, ratio.toFixed(3)]);
          }
    }
    report.cross_entry_min_ratio = Number.isFinite(worst) ? +worst.toFixed(3) : null;
    assert.equal(bad.length, 0, `${bad.length} close pairs of different entries: ${JSON.stringify(bad.slice(0, 5))}`);
  });

  await t.test('undo and redo step back and forth on the same session', async () => {
    const state = () => page.evaluate(() => ({ id: window.__tessera.store.state.session.id, elements: window.__tessera.store.state.view.model.elements }));
    const before = await state();
    await page.click('#undo');
    await waitIdle(page, 30000);
    const undone = await state();
    assert.ok(undone.elements.length < before.elements.length, `undo of the fill: ${undone.elements.length} elements (was ${before.elements.length})`);
    assert.equal(undone.id, before.id, 'undo keeps the session (the server swaps its state back, no replay)');
    await page.click('#redo');
    await waitIdle(page, 30000);
    const redone = await state();
    assert.deepEqual(redone.elements, before.elements, 'redo gives the same arrangement back');
  });

  await t.test('session file round trip, erase, merged and loaded palette entries', async () => {
    const count = () => page.evaluate(() => window.__tessera.store.state.view.model.elements.length);
    const before = await count();
    const [download] = await Promise.all([page.waitForEvent('download', { timeout: 30000 }), page.click('#session-save')]);
    const sessionPath = join(shots, 'studio_session.brush.json');
    await withTimeout(download.saveAs(sessionPath), 30000, 'saving the session file');
    const file = JSON.parse(readFileSync(sessionPath, 'utf8'));
    assert.equal(file.format, 'tessera-brush');
    assert.deepEqual(file.ops.map((o) => o.op).slice(-2), ['direction', 'fill']);
    await page.setInputFiles('#session-load', sessionPath);
    await page.waitForFunction(() => /^Opened a session/.test(document.getElementById('status-message').textContent), null, { timeout: 240000 });
    await waitIdle(page);
    assert.equal(await count(), before, 'the opened session file replays to the same arrangement');

    await setTool(page, 'erase');
    await setWidth(page, 3);
    await drawStroke(page, line([2, 15], [38, 15], 18), { stepMs: 10 });
    await waitIdle(page);
    const erased = await count();
    assert.ok(erased < before, `erase: ${erased} elements left of ${before}`);

    await page.click('.swatch[data-name="sticks_2d"]');
    await page.click('.swatch[data-name="poisson_disk_2d"]', { modifiers: ['Control'] });
    await page.click('#palette-merge');
    const merged = 'sticks_2d + poisson_disk_2d';
    await page.waitForFunction((n) => window.__tessera.store.state.active === n, merged, { timeout: 10000 });
    await setTool(page, 'paint');
    await drawStroke(page, line([4, 15], [30, 15], 16), { stepMs: 25 });
    await waitIdle(page);
    const painted = await count();
    assert.ok(painted > erased, `painting with the merged entry: ${painted} elements (was ${erased})`);
    const types = await page.evaluate(() => window.__tessera.store.state.view.model.types.map((x) => x.name));
    assert.ok(types.some((n) => /\(sticks_2d \+ poisson_disk_2d\)/.test(n)), `types keep their names per entry: ${types}`);
    // The entry is a mix: the stroke grows sticks and dots together, not one of them.
    const paintedTypes = await page.evaluate((from) => {
      const m = window.__tessera.store.state.view.model;
      return [...new Set(m.elements.slice(from).map((e) => m.types[e.type].name))];
    }, erased);
    for (const kind of ['stick', 'dot'])
      assert.ok(paintedTypes.some((n) => n.startsWith(kind) && /sticks_2d \+ poisson_disk_2d/.test(n)),
        `the merged stroke painted ${kind}s too: ${paintedTypes}`);

    await page.setInputFiles('#palette-file', join(sourceDir, 'examples', 'two_class_2d.json'));
    await page.waitForSelector('.swatch[data-name="two_class_2d 2"].active', { timeout: 10000 });
    await shot('05_merged_entry.png');
  });

  await t.test('a 3D canvas shows the elements with three.js', async () => {
    await newCanvas(page, 'box:0,0,16,16,0,8');
    await choose(page, 'spheres_3d');
    await setTool(page, 'paint');
    await setWidth(page, 3);
    await drawStroke(page, line([3, 3, 4], [13, 12, 4], 16).map((p) => [p[0], p[1], 4]), { stepMs: 25 });
    await waitIdle(page);
    const n = await page.evaluate(() => window.__tessera.store.state.view.model.elements.length);
    assert.ok(n > 5, `${n} spheres painted on the drawing plane`);
    await shot('04_3d.png');
  });

  assert.deepEqual(errors.filter((e) => !/favicon/.test(e)), [], 'no errors in the page');
  writeFileSync(join(shots, 'studio_test_report.json'), `${JSON.stringify(report, null, 1)}\n`);
  console.log(`studio test figures: ${JSON.stringify(report)}`);
});

function centroid(pts) {
  const c = [0, 0];
  for (const p of pts) {
    c[0] += p[0] / pts.length;
    c[1] += p[1] / pts.length;
  }
  return c;
}

// The nearest point of a polyline: distance, tangent there, and whether it lies away from
// the ends (elements past a stroke's end are not "along" it).
function nearestOnPolyline(points, c) {
  let best = { distance: Infinity };
  let along = 0;
  let total = 0;
  for (let i = 0; i + 1 < points.length; ++i) total += Math.hypot(points[i + 1][0] - points[i][0], points[i + 1][1] - points[i][1]);
  for (let i = 0; i + 1 < points.length; ++i) {
    const a = points[i];
    const b = points[i + 1];
    const d = [b[0] - a[0], b[1] - a[1]];
    const len2 = d[0] ** 2 + d[1] ** 2;
    const t = Math.max(0, Math.min(1, ((c[0] - a[0]) * d[0] + (c[1] - a[1]) * d[1]) / len2));
    const q = [a[0] + t * d[0], a[1] + t * d[1]];
    const dist = Math.hypot(c[0] - q[0], c[1] - q[1]);
    const s = along + t * Math.sqrt(len2);
    if (dist < best.distance) best = { distance: dist, tangent: d, interior: s > 1.5 && s < total - 1.5 };
    along += Math.sqrt(len2);
  }
  return best;
}

// The angle between two directions taken as lines (0..90 degrees).
function lineAngle(a, b) {
  let d = Math.abs(a - b) % Math.PI;
  if (d > Math.PI / 2) d = Math.PI - d;
  return (d * 180) / Math.PI;
}

// tests/web/studio_harness.mjs — what the studio's browser test and the stroke latency
// benchmark share: starting `tessera studio --port 0` and reading its port, launching Debian's
// chromium headless through playwright-core (never a downloaded browser), waiting with a
// bound, and drawing strokes on the canvas with real mouse events.
import { spawn } from 'node:child_process';
import { createRequire } from 'node:module';
import { existsSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
export const sourceDir = resolve(process.env.TESSERA_SOURCE_DIR || join(here, '..', '..'));
export const tesseraBin = resolve(process.env.TESSERA_BIN || join(sourceDir, 'build', 'bin', 'tessera'));
export const buildDir = resolve(process.env.TESSERA_BUILD_DIR || dirname(dirname(tesseraBin)));

// playwright-core from web/node_modules (the front end's dev dependency).
const require = createRequire(join(sourceDir, 'web', 'package.json'));
export const { chromium } = require('playwright-core');

export function withTimeout(promise, ms, what) {
  let timer;
  const timeout = new Promise((_, reject) => {
    timer = setTimeout(() => reject(new Error(`timed out after ${ms} ms: ${what}`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

// Starts the server over the source tree; resolves {url, stop()} once it printed its address.
export async function startServer({ timeoutMs = 20000 } = {}) {
  if (!existsSync(tesseraBin)) throw new Error(`${tesseraBin} does not exist (make build)`);
  const child = spawn(tesseraBin, ['studio', '--port', '0', '--root', sourceDir, '--quiet'], {
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let stderr = '';
  child.stderr.on('data', (d) => (stderr += d));
  const killAtExit = () => child.kill('SIGKILL');
  process.on('exit', killAtExit);
  const stop = async () => {
    process.off('exit', killAtExit);
    if (child.exitCode !== null || child.signalCode !== null) return;
    const exited = new Promise((r) => child.once('exit', r));
    child.kill('SIGTERM');
    try {
      await withTimeout(exited, 5000, 'the studio server stopping');
    } catch {
      child.kill('SIGKILL');
      await exited;
    }
  };
  try {
    const url = await withTimeout(
      new Promise((resolveUrl, reject) => {
        let out = '';
        child.stdout.on('data', (d) => {
          out += d;
          const line = out.split('\n')[0];
          const m = /(http:\/\/[^\s]+)/.exec(line);
          if (out.includes('\n') && m) resolveUrl(m[1]);
          else if (out.includes('\n')) reject(new Error(`unexpected first line: ${line}`));
        });
        child.once('exit', (code) => reject(new Error(`the server exited (${code}): ${stderr}`)));
      }),
      timeoutMs,
      'the studio server printing its address',
    );
    return { url, stop, child, stderr: () => stderr };
  } catch (e) {
    await stop();
    throw e;
  }
}

export async function launchBrowser() {
  return chromium.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-gpu'],
    timeout: 30000,
  });
}

// Opens the studio and waits until its palette and first canvas are there.
export async function openStudio(browser, url, { width = 1400, height = 860 } = {}) {
  const context = await browser.newContext({ viewport: { width, height }, acceptDownloads: true });
  const page = await context.newPage();
  page.setDefaultTimeout(30000);
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('dialog', (d) => d.accept()); // "Start a new canvas? The current one is dropped."

  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  await page.goto(url, { timeout: 30000 });
  await page.waitForFunction(() => window.__tessera && window.__tessera.ready, null, { timeout: 30000 });
  return { page, context, errors };
}

// Waits until the front end has nothing queued or running, then for a drawn frame.
export async function waitIdle(page, timeoutMs = 120000) {
  await page.waitForFunction(() => !window.__tessera.busy(), null, {
    timeout: timeoutMs,
    polling: 100,
  });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

export async function newCanvas(page, canvas) {
  await page.fill('#canvas-text', canvas);
  await page.click('#canvas-new');
  await page.waitForFunction((c) => window.__tessera.store.state.view && window.__tessera.store.state.view.canvas === c, canvas, { timeout: 30000 });
  await waitIdle(page);
  // The view shows the new canvas's domain (a 3D view loads a mesh first).
  await page.waitForFunction((c) => window.__tessera.view && window.__tessera.view.loadedCanvas === c, canvas, { timeout: 30000 });
}

export async function choose(page, name) {
  await page.click(`.swatch[data-name="${name}"]`);
  await page.waitForFunction((n) => window.__tessera.store.state.active === n, name, { timeout: 5000 });
}

export async function setTool(page, tool) {
  await page.click(`.tool[data-tool="${tool}"]`);
}

export async function setWidth(page, width) {
  await page.evaluate((w) => {
    const input = document.getElementById('width');
    input.value = String(w);
    input.dispatchEvent(new Event('input'));
  }, width);
}

// Draws a polyline of world points with the mouse: press at the first, move through the
// others (`stepMs` apart, as a hand would), release at the last.
export async function drawStroke(page, points, { stepMs = 16 } = {}) {
  const clients = await page.evaluate((pts) => pts.map((p) => window.__tessera.view.worldToClient([p[0], p[1], p[2] || 0])), points);
  await page.mouse.move(clients[0][0], clients[0][1]);
  await page.mouse.down();
  for (const [x, y] of clients.slice(1)) {
    await page.mouse.move(x, y);
    if (stepMs) await page.waitForTimeout(stepMs);
  }
  await page.mouse.up();
}

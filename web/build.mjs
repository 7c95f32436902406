// web/build.mjs — bundles the studio front end into web/dist/ (docs/studio.md, "Front end").
// esbuild bundles src/main.js (with three.js and its OrbitControls) into dist/app.js;
// index.html and style.css are copied next to it. Nothing is fetched at run time.
// Usage: node web/build.mjs [--dev]   (--dev: no minification, inline source map)
import { build } from 'esbuild';
import { copyFile, mkdir } from 'node:fs/promises';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const dist = join(here, 'dist');
const dev = process.argv.includes('--dev');

await mkdir(dist, { recursive: true });
await build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  format: 'esm',
  target: ['es2020'],
  outfile: join(dist, 'app.js'),
  minify: !dev,
  sourcemap: dev ? 'inline' : false,
  legalComments: 'none',
  logLevel: 'warning',
});
await copyFile(join(here, 'index.html'), join(dist, 'index.html'));
await copyFile(join(here, 'style.css'), join(dist, 'style.css'));
console.log(`studio web: wrote ${dist}/app.js, index.html, style.css`);

// main.js — the studio front end: builds the state, the session, the palette, the tools, the
// two views and the bars, and wires the page's controls to them (docs/studio.md, "Front end").
import { api } from './api.js';
import { createStore } from './store.js';
import { createSession } from './session.js';
import { createPalette } from './palette.js';
import { createTools } from './tools.js';
import { createView2D } from './view2d.js';
import { createView3D } from './view3d.js';
import { createStatusbar } from './statusbar.js';
import { createExportMenu } from './export_menu.js';
import { CANVAS_PRESETS, defaultCanvas } from './canvas_presets.js';
import { downloadJson, readJsonFile } from './files.js';

const $ = (id) => document.getElementById(id);

const store = createStore({
  entries: [], selected: [], active: null,
  tool: 'paint', width: 5, iterations: 8, planeHeight: 0.5, pickSurface: true,
  showField: true, showStrokes: true, showSamples: false,
  stroking: false, session: null, view: null, groups: [], ops: [], redo: [], job: null, busy: false, message: null, pointer: null,
});
const metrics = { paint: [] };
const session = createSession(store);
const palette = createPalette(store, session, { list: $('palette'), fileInput: $('palette-file'), mergeButton: $('palette-merge') });
const tools = createTools(store, session, palette, metrics);
const views = { 2: createView2D($('view2d'), store), 3: createView3D($('view3d'), store) };
let current = null;

createStatusbar(store, session, {
  message: $('status-message'), job: $('job'), stage: $('job-stage'), bar: $('job-bar'), fraction: $('job-fraction'),
  cancel: $('job-cancel'), counts: $('status-counts'), cursor: $('status-cursor'),
});
createExportMenu(store, session, { button: $('export-button'), items: $('export-items') });

// For the browser test and the latency benchmark (tests/web/).
window.__tessera = {
  store, metrics, session, ready: false,
  get view() {
    return current;
  },
  // Nothing queued, running, or being drawn and sent (a stroke waits between its segments).
  busy: () => store.state.busy || session.queue.pending > 0 || store.state.stroking,
};

const message = (text, kind = '') => store.set({ message: { text, kind } });
const fail = (e) => message(e.message || String(e), 'error');

function showView(dimension) {
  const next = views[dimension];
  if (current === next) return;
  if (current) current.hide();
  current = next;
  current.show();
  tools.attach(current);
  $('plane-param').hidden = dimension !== 3;
  $('stage-hint').textContent = dimension === 3
    ? 'left: tool · right drag: orbit · middle drag: pan · wheel: zoom'
    : 'left: tool · right drag or space+drag: pan · wheel: zoom';
}

store.on('view', (s) => {
  if (!s.view) return;
  const switching = !current || current !== views[s.view.dimension];
  showView(s.view.dimension);
  if (switching) current.fit();
});
store.on('session', (s) => {
  if (!s.session) return;
  $('canvas-text').value = s.session.canvas;
  const preset = CANVAS_PRESETS.findIndex((p) => p.canvas === s.session.canvas);
  $('canvas-preset').value = preset >= 0 ? String(preset) : 'custom';
});

// Canvas picker.
for (const [i, p] of CANVAS_PRESETS.entries()) $('canvas-preset').append(new Option(p.label, String(i)));
$('canvas-preset').append(new Option('Custom…', 'custom'));
$('canvas-preset').addEventListener('change', () => {
  const p = CANVAS_PRESETS[+$('canvas-preset').value];
  if (p) $('canvas-text').value = p.canvas;
});
function newCanvas(text) {
  const options = { iterations: store.state.iterations };
  return session.newCanvas(text.trim(), options).catch(fail);
}
$('canvas-new').addEventListener('click', () => {
  if (store.state.ops.length && !confirm('Start a new canvas? The current one is dropped (save the session first to keep it).')) return;
  newCanvas($('canvas-text').value);
});
$('canvas-text').addEventListener('keydown', (e) => {
  if (e.key === 'Enter') $('canvas-new').click();
});

// Choosing an entry of the other dimension on an untouched canvas switches the canvas.
store.on('active', (s) => {
  const entry = palette.entry(s.active);
  if (!entry || !s.session || entry.dimension === s.session.dimension) return;
  if (!s.ops.length && !session.queue.pending) newCanvas(defaultCanvas(entry.dimension));
  else message(`${entry.name} is ${entry.dimension}D: choose a ${entry.dimension}D canvas to paint it`, 'error');
});

// Tools and parameters.
function setTool(tool) {
  store.set({ tool });
  for (const b of document.querySelectorAll('.tool')) b.classList.toggle('on', b.dataset.tool === tool);
}
for (const b of document.querySelectorAll('.tool')) b.addEventListener('click', () => setTool(b.dataset.tool));
setTool('paint');
$('fill').addEventListener('click', () => tools.fill());
$('optimize').addEventListener('click', () => tools.optimize());

function slider(id, key, format) {
  const input = $(id);
  const out = $(`${id}-value`);
  const update = () => {
    store.set({ [key]: +input.value });
    out.textContent = format(+input.value);
  };
  input.addEventListener('input', update);
  update();
}
slider('width', 'width', (v) => v.toFixed(1));
slider('iterations', 'iterations', (v) => String(v));
slider('plane', 'planeHeight', (v) => `${Math.round(v * 100)}%`);
for (const [id, key] of [['show-field', 'showField'], ['show-strokes', 'showStrokes'], ['show-samples', 'showSamples'], ['pick-surface', 'pickSurface']]) {
  $(id).addEventListener('change', () => store.set({ [key]: $(id).checked }));
  store.state[key] = $(id).checked;
}
$('fit-view').addEventListener('click', () => current && current.fit());

// Undo, redo, busy state.
store.on(['groups', 'redo', 'busy'], (s) => {
  $('undo').disabled = !s.groups.length;
  $('redo').disabled = !s.redo.length;
  $('fill').disabled = s.busy && !tools.drawing;
  document.body.classList.toggle('busy', s.busy);
});
$('undo').addEventListener('click', () => session.undo().catch(fail));
$('redo').addEventListener('click', () => session.redo().catch(fail));
window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLInputElement && e.target.type === 'text') return;
  const key = e.key.toLowerCase();
  if ((e.ctrlKey || e.metaKey) && key === 'z') {
    e.preventDefault();
    (e.shiftKey ? session.redo() : session.undo()).catch(fail);
  } else if ((e.ctrlKey || e.metaKey) && key === 'y') {
    e.preventDefault();
    session.redo().catch(fail);
  } else if (!e.ctrlKey && !e.metaKey && !e.altKey) {
    if (key === 'b') setTool('paint');
    else if (key === 'd') setTool('direction');
    else if (key === 'e') setTool('erase');
    else if (key === 'f') tools.fill();
    else if (key === '[' || key === ']') {
      const w = $('width');
      w.value = String(+w.value + (key === ']' ? 0.5 : -0.5));
      w.dispatchEvent(new Event('input'));
    }
  }
});

// Session files.
$('session-save').addEventListener('click', async () => {
  try {
    const file = await session.saveFile();
    downloadJson(file, `${store.state.session.id}.brush.json`);
    message(`Saved the session (${file.ops.length} operations)`, 'ok');
  } catch (e) {
    fail(e);
  }
});
$('session-load').addEventListener('change', async () => {
  const input = $('session-load');
  const file = input.files[0];
  input.value = '';
  if (!file) return;
  try {
    const doc = await readJsonFile(file);
    await palette.adopt(doc);
    await session.openFile(doc);
  } catch (e) {
    fail(e);
  }
});

// Start: the built-in palette and a first canvas.
(async () => {
  try {
    const status = await api.status();
    document.title = `tessera studio ${status.version}`;
    await palette.loadBuiltIns();
    const first = palette.entry('sticks_2d') || store.state.entries.find((e) => e.dimension === 2) || store.state.entries[0];
    await session.newCanvas(defaultCanvas(first ? first.dimension : 2), { iterations: store.state.iterations });
    if (first) palette.select(first.name, false);
    message(`Ready: ${store.state.entries.length} palette entries. Choose one and paint on the canvas.`);
    window.__tessera.ready = true;
  } catch (e) {
    fail(e);
  }
})();



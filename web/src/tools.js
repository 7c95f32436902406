// tools.js — what the pointer does on the canvas, per tool: the paint brush (elements grown
// along the stroke while it is drawn, stroke_sender.js), the direction brush (sets the element
// field along a stroke) and the erase brush; and the buttons "Fill the rest" and "Optimize".
// Works for both views: they hand over world points ([x, y, 0] in 2D, [x, y, z] in 3D).
import { createStrokeSender } from './stroke_sender.js';

// The views draw in the animation frame they asked for on the store's change; a callback
// asked for after theirs runs in that same frame, after the drawing.
const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));

export function createTools(store, session, palette, metrics) {
  let drawing = null; // {tool, points, entry}
  let painting = null; // the palette entry of the paint stroke being sent (outlives `drawing`)
  let currentView = null;

  const message = (text, kind = '') => store.set({ message: { text, kind } });

  function activeEntry() {
    const entry = palette.entry(store.state.active);
    const s = store.state.session;
    if (!entry) {
      message('Choose a palette entry to paint with (left panel)', 'error');
      return null;
    }
    if (!s || entry.dimension !== s.dimension) {
      message(`${entry.name} is ${entry.dimension}D and the canvas ${s ? s.dimension : '?'}D: choose a ${entry.dimension}D canvas (top bar)`, 'error');
      return null;
    }
    return entry;
  }

  // Stroke points are rounded (the server echoes them in session files) and thinned: a new
  // point is kept once it is a tenth of the brush width (or 3 pixels) from the last one.
  const round = (p) => p.map((v) => Math.round(v * 1000) / 1000);
  function minStep() {
    return Math.max(store.state.width * 0.1, 0.05);
  }
  const dimensioned = (p) => (store.state.session.dimension === 3 ? p : [p[0], p[1]]);

  const sender = createStrokeSender({
    metrics: metrics.paint,
    send: (segment) =>
      session.apply(
        { op: 'paint', palette: painting.name, stroke: segment.map(dimensioned), width: store.state.width },
        { entry: painting, label: 'paint' },
      ),
    afterDraw: nextFrame,
  });

  function start(point, event) {
    if (drawing || !store.state.session) return;
    const tool = store.state.tool;
    const entry = tool === 'paint' ? activeEntry() : null;
    if (tool === 'paint' && !entry) return;
    const p = round(point);
    drawing = { tool, points: [p], entry };
    if (tool === 'paint') {
      painting = entry;
      store.set({ stroking: true });
      session.beginGroup();
      sender.begin(p, event.timeStamp);
    }
    showLive();
  }

  function move(point, event) {
    if (!drawing) return;
    const p = round(point);
    const last = drawing.points[drawing.points.length - 1];
    if (Math.hypot(p[0] - last[0], p[1] - last[1], p[2] - last[2]) < minStep()) return;
    drawing.points.push(p);
    if (drawing.tool === 'paint') sender.add(p, event.timeStamp);
    showLive();
  }

  async function end(point, event) {
    if (!drawing) return;
    move(point, event);
    const d = drawing;
    drawing = null;
    try {
      if (d.tool === 'paint') {
        await sender.end();
        await session.endGroup();
        const added = metrics.paint.filter((m) => m.stroke === metrics.paint[metrics.paint.length - 1].stroke).reduce((a, m) => a + (m.added || 0), 0);
        message(`Painted ${added} elements of ${d.entry.name}`, 'ok');
      } else if (d.tool === 'direction') {
        store.set({ stroking: true });
        const stroke = d.points.length > 1 ? d.points : [d.points[0], d.points[0]];
        await session.apply({ op: 'direction', stroke: stroke.map(dimensioned) });
        message('Direction stroke set', 'ok');
      } else if (d.tool === 'erase') {
        store.set({ stroking: true });
        const r = await session.apply({ op: 'erase', stroke: d.points.map(dimensioned), width: store.state.width });
        message(`Erased ${r.report.removed} elements`, 'ok');
      }
    } catch (e) {
      message(e.message, 'error');
    } finally {
      if (currentView) currentView.setLive(null);
      store.set({ stroking: false });
    }
  }

  function showLive() {
    if (!currentView || !drawing) return;
    const op = { op: drawing.tool, stroke: drawing.points, width: store.state.width, palette: drawing.entry && drawing.entry.name };
    currentView.setLive(op);
  }

  async function fill() {
    const v = store.state.view;
    const empty = !v || !v.model.elements.length;
    let names = [];
    if (empty) {
      const chosen = store.state.selected.map((n) => palette.entry(n)).filter(Boolean);
      const s = store.state.session;
      const fit = chosen.filter((e) => s && e.dimension === s.dimension);
      if (!fit.length) {
        message('The canvas is empty: choose the palette entries to fill it with', 'error');
        return;
      }
      try {
        await session.serial(async () => {
          for (const e of fit) await session.ensureEntry(e);
        });
      } catch (e) {
        message(e.message, 'error');
        return;
      }
      names = fit.map((e) => e.name);
    }
    try {
      const r = await session.apply(names.length ? { op: 'fill', palette: names } : { op: 'fill' }, { label: 'fill' });
      if (r.state === 'done') message(`Filled: ${r.report.added} elements added, ${r.report.iterations} iterations, ${r.report.seconds.toFixed(1)} s`, 'ok');
      else message(`Fill ${r.state}`, r.state === 'cancelled' ? '' : 'error');
    } catch (e) {
      message(e.message, 'error');
    }
  }

  async function optimize() {
    try {
      const r = await session.apply({ op: 'optimize', iterations: store.state.iterations }, { label: 'optimize' });
      if (r.state === 'done') message(`Optimized: ${r.report.iterations} iterations, energy ${r.report.energy.toFixed(3)}`, 'ok');
      else message(`Optimize ${r.state}`);
    } catch (e) {
      message(e.message, 'error');
    }
  }

  return {
    attach(view) {
      currentView = view;
      view.handlers.start = start;
      view.handlers.move = move;
      view.handlers.end = end;
    },
    fill,
    optimize,
    get drawing() {
      return !!drawing;
    },
  };
}

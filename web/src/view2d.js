// view2d.js — the 2D canvas view (HTML canvas 2D): the domain, the direction field as faint
// streamlines, the strokes drawn so far, the elements (their samples' discs and the chains of
// their element graphs, coloured by type), and on top the stroke being drawn and the brush.
// Left button: the current tool; right or middle button (or space + left): pan; wheel: zoom.
import { traceStreamlines } from './streamlines.js';
import { withAlpha } from './colors.js';
import { strokeStyle } from './stroke_style.js';

export function createView2D(canvas, store) {
  const ctx = canvas.getContext('2d');
  let dpr = window.devicePixelRatio || 1;
  let scale = 10; // CSS pixels per world unit
  let ox = 0; // CSS pixel of world x = 0
  let oy = 0; // CSS pixel of world y = 0 (y grows upwards in the world)
  let fitted = false;
  let fittedCanvas = null; // the canvas text the view was last fitted to
  let live = null; // the stroke being drawn: {kind, points, width, color}
  let cursor = null; // world point under the pointer
  let pan = null;
  let spaceDown = false;
  let frame = 0;
  let streamCache = { key: null, lines: [] };
  const handlers = { start: null, move: null, end: null };

  const toScreen = (p) => [ox + p[0] * scale, oy - p[1] * scale];
  const toWorld = (sx, sy) => [(sx - ox) / scale, (oy - sy) / scale, 0];

  function bounds() {
    const v = store.state.view;
    if (v && v.model) return v.model.bounds;
    return { min: [0, 0, 0], max: [60, 40, 0] };
  }

  function fit() {
    const b = bounds();
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    const bw = Math.max(b.max[0] - b.min[0], 1e-6);
    const bh = Math.max(b.max[1] - b.min[1], 1e-6);
    if (!w || !h) return;
    scale = Math.min((w - 60) / bw, (h - 60) / bh);
    ox = (w - bw * scale) / 2 - b.min[0] * scale;
    oy = (h + bh * scale) / 2 + b.min[1] * scale;
    fitted = true;
    const v = store.state.view;
    fittedCanvas = v ? v.canvas : null;
    request();
  }

  function resize() {
    dpr = window.devicePixelRatio || 1;
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    if (!w || !h) return;
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
    if (!fitted) fit();
    request();
  }

  function request() {
    if (frame) return;
    frame = requestAnimationFrame(() => {
      frame = 0;
      draw();
    });
  }

  function draw() {
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = '#121417';
    ctx.fillRect(0, 0, w, h);
    const v = store.state.view;
    if (!v || !v.model || v.dimension !== 2) return;
    drawDomain(v.model);
    drawGrid(v.model.bounds);
    if (store.state.showField) drawField(v);
    if (store.state.showStrokes) for (const s of store.state.ops || []) drawStroke(s, 0.28);
    drawElements(v.model);
    if (live) drawStroke(live, 0.9, true);
    drawCursor();
    store.state.lastDrawAt = performance.now();
    store.state.drawnVersion = v.fetchedAt;
  }

  function domainPath(d, b) {
    ctx.beginPath();
    if (d && d.type === 'polygon' && Array.isArray(d.outer)) {
      for (const ring of [d.outer, ...(d.holes || [])]) {
        ring.forEach((p, i) => {
          const [x, y] = toScreen(p);
          if (i === 0) ctx.moveTo(x, y);
          else ctx.lineTo(x, y);
        });
        ctx.closePath();
      }
    } else {
      const [x0, y0] = toScreen(b.min);
      const [x1, y1] = toScreen(b.max);
      ctx.rect(x0, y1, x1 - x0, y0 - y1);
    }
  }

  function drawDomain(model) {
    domainPath(model.domain, model.bounds);
    ctx.fillStyle = '#1b1e23';
    ctx.fill('evenodd');
    ctx.strokeStyle = '#3d444d';
    ctx.lineWidth = 1;
    ctx.stroke();
  }

  function drawGrid(b) {
    const spanPx = (b.max[0] - b.min[0]) * scale;
    if (spanPx <= 0) return;
    const steps = [1, 2, 5, 10, 20, 50, 100, 200, 500];
    const step = steps.find((s) => s * scale >= 48) || 1000;
    ctx.save();
    domainPath(store.state.view.model.domain, b);
    ctx.clip('evenodd');
    ctx.strokeStyle = 'rgba(255,255,255,0.035)';
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (let x = Math.ceil(b.min[0] / step) * step; x <= b.max[0]; x += step) {
      const [sx] = toScreen([x, 0]);
      ctx.moveTo(Math.round(sx) + 0.5, toScreen([0, b.min[1]])[1]);
      ctx.lineTo(Math.round(sx) + 0.5, toScreen([0, b.max[1]])[1]);
    }
    for (let y = Math.ceil(b.min[1] / step) * step; y <= b.max[1]; y += step) {
      const [, sy] = toScreen([0, y]);
      ctx.moveTo(toScreen([b.min[0], 0])[0], Math.round(sy) + 0.5);
      ctx.lineTo(toScreen([b.max[0], 0])[0], Math.round(sy) + 0.5);
    }
    ctx.stroke();
    ctx.restore();
  }

  function drawField(v) {
    const key = v.fetchedAt;
    if (streamCache.key !== key) {
      const points = [];
      const dirs = [];
      let k = 0;
      for (const e of v.model.elements)
        for (const p of e.samples) {
          const d = v.directions[k++];
          if (d) {
            points.push(p);
            dirs.push(d);
          }
        }
      streamCache = { key, lines: traceStreamlines(points, dirs, v.model.bounds, { lines: 36 }) };
    }
    ctx.strokeStyle = 'rgba(200,215,235,0.16)';
    ctx.lineWidth = 1;
    ctx.lineCap = 'round';
    ctx.beginPath();
    for (const line of streamCache.lines) {
      line.forEach((p, i) => {
        const [x, y] = toScreen(p);
        if (i === 0) ctx.moveTo(x, y);
        else ctx.lineTo(x, y);
      });
    }
    ctx.stroke();
  }

  function drawStroke(op, alpha, isLive = false) {
    if (!op.stroke || !op.stroke.length) return;
    const style = strokeStyle(op, store.state);
    const pts = op.stroke.map(toScreen);
    ctx.lineCap = 'round';
    ctx.lineJoin = 'round';
    if (style.band) {
      ctx.strokeStyle = withAlpha(style.color, (isLive ? 0.16 : 0.06) * (alpha > 0.5 ? 1 : 1));
      ctx.lineWidth = Math.max(style.width * scale, 2);
      polyline(pts);
    }
    ctx.strokeStyle = withAlpha(style.color, alpha * (isLive ? 0.9 : 0.55));
    ctx.lineWidth = isLive ? 1.6 : 1.1;
    ctx.setLineDash(style.dash || []);
    polyline(pts);
    ctx.setLineDash([]);
    if (style.arrow && pts.length > 1) arrowHead(pts, withAlpha(style.color, alpha * 0.8));
  }

  function polyline(pts) {
    ctx.beginPath();
    pts.forEach(([x, y], i) => (i === 0 ? ctx.moveTo(x, y) : ctx.lineTo(x, y)));
    if (pts.length === 1) ctx.lineTo(pts[0][0] + 0.01, pts[0][1]);
    ctx.stroke();
  }

  function arrowHead(pts, color) {
    const [x1, y1] = pts[pts.length - 1];
    let k = pts.length - 2;
    while (k > 0 && Math.hypot(x1 - pts[k][0], y1 - pts[k][1]) < 8) --k;
    const [x0, y0] = pts[k];
    const a = Math.atan2(y1 - y0, x1 - x0);
    ctx.fillStyle = color;
    ctx.beginPath();
    ctx.moveTo(x1, y1);
    ctx.lineTo(x1 - 9 * Math.cos(a - 0.4), y1 - 9 * Math.sin(a - 0.4));
    ctx.lineTo(x1 - 9 * Math.cos(a + 0.4), y1 - 9 * Math.sin(a + 0.4));
    ctx.closePath();
    ctx.fill();
  }

  function drawElements(model) {
    ctx.lineCap = 'round';
    ctx.lineJoin = 'round';
    const showSamples = store.state.showSamples;
    for (const e of model.elements) {
      const t = model.types[e.type];
      const pts = e.samples.map(toScreen);
      const w = (t.weights[0] || 0.2) * e.scale * scale;
      if (pts.length > 1) {
        // an outline, then the body along the element graph
        for (const [color, width] of [['rgba(0,0,0,0.55)', 2 * w + 1.5], [t.color, 2 * w]]) {
          ctx.strokeStyle = color;
          ctx.lineWidth = Math.max(width, 1);
          ctx.beginPath();
          for (const [a, b] of t.graph) {
            if (!pts[a] || !pts[b]) continue;
            ctx.moveTo(pts[a][0], pts[a][1]);
            ctx.lineTo(pts[b][0], pts[b][1]);
          }
          ctx.stroke();
        }
      } else {
        ctx.fillStyle = t.color;
        ctx.strokeStyle = 'rgba(0,0,0,0.55)';
        ctx.lineWidth = 0.75;
        ctx.beginPath();
        ctx.arc(pts[0][0], pts[0][1], Math.max(w, 1), 0, Math.PI * 2);
        ctx.fill();
        ctx.stroke();
      }
      if (showSamples) {
        ctx.fillStyle = 'rgba(255,255,255,0.85)';
        for (const [x, y] of pts) ctx.fillRect(x - 1, y - 1, 2, 2);
      }
    }
  }

  function drawCursor() {
    if (!cursor || pan) return;
    const [x, y] = toScreen(cursor);
    const tool = store.state.tool;
    const r = tool === 'direction' ? 4 : Math.max((store.state.width / 2) * scale, 3);
    ctx.strokeStyle = tool === 'erase' ? 'rgba(240,120,110,0.9)' : 'rgba(255,255,255,0.75)';
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.arc(x, y, r, 0, Math.PI * 2);
    ctx.stroke();
    ctx.beginPath();
    ctx.moveTo(x - 3, y);
    ctx.lineTo(x + 3, y);
    ctx.moveTo(x, y - 3);
    ctx.lineTo(x, y + 3);
    ctx.stroke();
  }

  // Input.
  const local = (event) => {
    const r = canvas.getBoundingClientRect();
    return [event.clientX - r.left, event.clientY - r.top];
  };

  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('pointerdown', (event) => {
    canvas.focus();
    const [sx, sy] = local(event);
    if (event.button === 1 || event.button === 2 || (event.button === 0 && spaceDown)) {
      pan = { sx, sy, ox, oy };
      canvas.setPointerCapture(event.pointerId);
      return;
    }
    if (event.button !== 0 || !handlers.start) return;
    canvas.setPointerCapture(event.pointerId);
    handlers.start(toWorld(sx, sy), event);
  });
  canvas.addEventListener('pointermove', (event) => {
    const [sx, sy] = local(event);
    cursor = toWorld(sx, sy);
    store.set({ pointer: cursor });
    if (pan) {
      ox = pan.ox + sx - pan.sx;
      oy = pan.oy + sy - pan.sy;
      request();
      return;
    }
    const events = event.getCoalescedEvents ? event.getCoalescedEvents() : [event];
    if (handlers.move && event.buttons & 1)
      for (const e of events.length ? events : [event]) {
        const [cx, cy] = local(e);
        handlers.move(toWorld(cx, cy), event);
      }
    request();
  });
  const up = (event) => {
    if (pan) {
      pan = null;
      return;
    }
    if (event.button === 0 && handlers.end) handlers.end(toWorld(...local(event)), event);
  };
  canvas.addEventListener('pointerup', up);
  canvas.addEventListener('pointercancel', up);
  canvas.addEventListener('pointerleave', () => {
    cursor = null;
    request();
  });
  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    const [sx, sy] = local(event);
    const [wx, wy] = toWorld(sx, sy);
    const factor = Math.exp(-event.deltaY * 0.0015);
    scale = Math.min(Math.max(scale * factor, 0.2), 2000);
    ox = sx - wx * scale;
    oy = sy + wy * scale;
    request();
  }, { passive: false });
  window.addEventListener('keydown', (e) => {
    if (e.code === 'Space' && e.target === canvas) {
      spaceDown = true;
      e.preventDefault();
    }
  });
  window.addEventListener('keyup', (e) => {
    if (e.code === 'Space') spaceDown = false;
  });
  new ResizeObserver(resize).observe(canvas);

  // A new canvas (not an undo, which keeps the canvas text) is fitted into the view.
  store.on('view', (st) => {
    if (st.view && st.view.dimension === 2 && st.view.canvas !== fittedCanvas && !canvas.hidden) fit();
  });
  store.on(['view', 'showField', 'showStrokes', 'showSamples', 'ops', 'tool', 'width'], request);

  return {
    element: canvas,
    handlers,
    fit,
    request,
    setLive(stroke) {
      live = stroke;
      request();
    },
    // For tests and the latency benchmark: where a world point is on the page.
    worldToClient(p) {
      const r = canvas.getBoundingClientRect();
      const [x, y] = toScreen(p);
      return [r.left + x, r.top + y];
    },
    show() {
      canvas.hidden = false;
      resize();
    },
    hide() {
      canvas.hidden = true;
    },
    get loadedCanvas() {
      return fittedCanvas;
    },
  };
}

// colors.js — a colour per element type, as tessera's pictures choose it (docs/format.md,
// types[i].color): the type's `color`, else the colour its name names ("red", "dark green"),
// else the next colour of Tableau 10 not yet taken in this document.

const TABLEAU10 = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f', '#edc948', '#b07aa1', '#ff9da7', '#9c755f', '#bab0ac'];

function cssColor(name) {
  if (!name) return null;
  const compact = String(name).toLowerCase().replace(/[\s_-]/g, '');
  if (typeof CSS !== 'undefined' && CSS.supports && CSS.supports('color', compact)) return compact;
  return null;
}

// Colours for the types of one document, in order.
export function typeColors(types) {
  const taken = new Set();
  const out = types.map((t) => {
    const c = cssColor(t.color) || cssColor(t.name);
    if (c) taken.add(c);
    return c;
  });
  let next = 0;
  for (let i = 0; i < out.length; ++i) {
    if (out[i]) continue;
    while (next < TABLEAU10.length - 1 && taken.has(TABLEAU10[next])) ++next;
    out[i] = TABLEAU10[next % TABLEAU10.length];
    taken.add(out[i]);
    ++next;
  }
  return out;
}

// A CSS colour as [r, g, b] in 0..1 (for three.js), resolved by a canvas.
const cache = new Map();
export function rgb(color) {
  if (cache.has(color)) return cache.get(color);
  const ctx = document.createElement('canvas').getContext('2d');
  ctx.fillStyle = '#000';
  ctx.fillStyle = color;
  const hex = ctx.fillStyle; // normalised to #rrggbb
  const v = hex.startsWith('#') ? [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16) / 255) : [0.6, 0.6, 0.6];
  cache.set(color, v);
  return v;
}

export function withAlpha(color, alpha) {
  const [r, g, b] = rgb(color);
  return `rgba(${Math.round(r * 255)},${Math.round(g * 255)},${Math.round(b * 255)},${alpha})`;
}

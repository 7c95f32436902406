// thumbnail.js — a small picture of an exemplar drawn from its elements (palette swatches):
// 2D elements as their samples' discs and chains, 3D ones seen from above, shaded by height.
import { withAlpha } from './colors.js';

export function drawThumbnail(canvas, model) {
  const size = canvas.width;
  const ctx = canvas.getContext('2d');
  ctx.clearRect(0, 0, size, size);
  ctx.fillStyle = '#111316';
  ctx.fillRect(0, 0, size, size);
  const { min, max } = model.bounds;
  const span = Math.max(max[0] - min[0], max[1] - min[1]) || 1;
  const pad = size * 0.06;
  const k = (size - 2 * pad) / span;
  const ox = pad + ((size - 2 * pad) - (max[0] - min[0]) * k) / 2;
  const oy = pad + ((size - 2 * pad) - (max[1] - min[1]) * k) / 2;
  const X = (p) => ox + (p[0] - min[0]) * k;
  const Y = (p) => size - (oy + (p[1] - min[1]) * k);
  const zspan = max[2] - min[2] || 1;
  const order = model.elements.slice();
  if (model.dimension === 3) order.sort((a, b) => a.samples[0][2] - b.samples[0][2]);
  ctx.lineCap = 'round';
  ctx.lineJoin = 'round';
  for (const e of order) {
    const t = model.types[e.type];
    const w = Math.max(t.weights[0] * e.scale * k, 0.8);
    const shade = model.dimension === 3 ? 0.45 + 0.55 * ((e.samples[0][2] - min[2]) / zspan) : 1;
    const color = withAlpha(t.color, shade);
    if (e.samples.length > 1) {
      ctx.strokeStyle = color;
      ctx.lineWidth = 2 * w;
      ctx.beginPath();
      for (const [a, b] of t.graph) {
        const p = e.samples[a];
        const q = e.samples[b];
        if (!p || !q) continue;
        ctx.moveTo(X(p), Y(p));
        ctx.lineTo(X(q), Y(q));
      }
      ctx.stroke();
    } else {
      ctx.fillStyle = color;
      ctx.beginPath();
      ctx.arc(X(e.samples[0]), Y(e.samples[0]), w, 0, Math.PI * 2);
      ctx.fill();
    }
  }
}

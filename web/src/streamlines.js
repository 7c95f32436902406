// streamlines.js — the element field of a 2D canvas shown as streamlines: the samples'
// directions o(s) are averaged onto a grid (Gaussian weights within two cells), and evenly
// spaced streamlines are traced through it (seeds on a grid, a line stops where it comes
// closer than half the spacing to another one, or where no sample is near), in the spirit
// of Jobard and Lefer's evenly spaced streamlines.

// points: [[x, y]], dirs: [[dx, dy]]; bounds {min, max}. Returns an array of polylines.
export function traceStreamlines(points, dirs, bounds, { lines = 30 } = {}) {
  if (points.length < 2) return [];
  const W = bounds.max[0] - bounds.min[0];
  const H = bounds.max[1] - bounds.min[1];
  const span = Math.max(W, H);
  if (!(span > 0)) return [];
  const field = gridField(points, dirs, bounds, span / 90);
  const sep = span / lines;
  const step = field.h * 0.5;
  const occupied = new SpatialHash(sep * 0.5);
  const out = [];
  for (let y = bounds.min[1] + sep / 2; y < bounds.max[1]; y += sep) {
    for (let x = bounds.min[0] + sep / 2; x < bounds.max[0]; x += sep) {
      if (!field.at(x, y) || occupied.near(x, y, sep * 0.9)) continue;
      const forward = trace(field, x, y, step, 1, occupied, sep * 0.5, bounds);
      const backward = trace(field, x, y, step, -1, occupied, sep * 0.5, bounds);
      const line = backward.reverse().concat([[x, y]], forward);
      if (line.length < 6) continue;
      for (const p of line) occupied.add(p[0], p[1]);
      out.push(line);
    }
  }
  return out;
}

function trace(field, x, y, step, sign, occupied, stopDistance, bounds) {
  const line = [];
  let prev = field.at(x, y);
  if (!prev) return line;
  prev = [prev[0] * sign, prev[1] * sign];
  for (let k = 0; k < 600; ++k) {
    // Midpoint (RK2) step, keeping the direction continuous with the previous one.
    const d1 = aligned(field.at(x, y), prev);
    if (!d1) break;
    const mx = x + d1[0] * step * 0.5;
    const my = y + d1[1] * step * 0.5;
    const d2 = aligned(field.at(mx, my), d1);
    if (!d2) break;
    x += d2[0] * step;
    y += d2[1] * step;
    if (x < bounds.min[0] || y < bounds.min[1] || x > bounds.max[0] || y > bounds.max[1]) break;
    if (occupied.near(x, y, stopDistance)) break;
    line.push([x, y]);
    prev = d2;
  }
  return line;
}

function aligned(d, prev) {
  if (!d) return null;
  return d[0] * prev[0] + d[1] * prev[1] < 0 ? null : d;
}

function gridField(points, dirs, bounds, h) {
  const nx = Math.max(2, Math.ceil((bounds.max[0] - bounds.min[0]) / h) + 1);
  const ny = Math.max(2, Math.ceil((bounds.max[1] - bounds.min[1]) / h) + 1);
  const vx = new Float32Array(nx * ny);
  const vy = new Float32Array(nx * ny);
  const wsum = new Float32Array(nx * ny);
  const reach = 2;
  const sigma2 = (1.2 * h) ** 2;
  for (let i = 0; i < points.length; ++i) {
    const d = dirs[i];
    if (!d) continue;
    const gx = (points[i][0] - bounds.min[0]) / h;
    const gy = (points[i][1] - bounds.min[1]) / h;
    for (let j = Math.max(0, Math.floor(gy) - reach); j <= Math.min(ny - 1, Math.ceil(gy) + reach); ++j)
      for (let k = Math.max(0, Math.floor(gx) - reach); k <= Math.min(nx - 1, Math.ceil(gx) + reach); ++k) {
        const w = Math.exp(-(((k - gx) * h) ** 2 + ((j - gy) * h) ** 2) / sigma2);
        vx[j * nx + k] += w * d[0];
        vy[j * nx + k] += w * d[1];
        wsum[j * nx + k] += w;
      }
  }
  const node = (k, j) => {
    const i = j * nx + k;
    return wsum[i] > 0.05 ? [vx[i], vy[i]] : null;
  };
  return {
    h,
    at(x, y) {
      const gx = (x - bounds.min[0]) / h;
      const gy = (y - bounds.min[1]) / h;
      const k = Math.floor(gx);
      const j = Math.floor(gy);
      if (k < 0 || j < 0 || k >= nx - 1 || j >= ny - 1) return null;
      const fx = gx - k;
      const fy = gy - j;
      let sx = 0;
      let sy = 0;
      const corners = [[k, j, (1 - fx) * (1 - fy)], [k + 1, j, fx * (1 - fy)], [k, j + 1, (1 - fx) * fy], [k + 1, j + 1, fx * fy]];
      for (const [a, b, w] of corners) {
        const v = node(a, b);
        if (!v) return null;
        sx += w * v[0];
        sy += w * v[1];
      }
      const n = Math.hypot(sx, sy);
      return n > 1e-9 ? [sx / n, sy / n] : null;
    },
  };
}

class SpatialHash {
  constructor(cell) {
    this.cell = cell;
    this.map = new Map();
  }
  key(i, j) {
    return i * 73856093 + j * 19349663;
  }
  add(x, y) {
    const k = this.key(Math.floor(x / this.cell), Math.floor(y / this.cell));
    if (!this.map.has(k)) this.map.set(k, []);
    this.map.get(k).push([x, y]);
  }
  near(x, y, r) {
    const i0 = Math.floor((x - r) / this.cell);
    const i1 = Math.floor((x + r) / this.cell);
    const j0 = Math.floor((y - r) / this.cell);
    const j1 = Math.floor((y + r) / this.cell);
    for (let i = i0; i <= i1; ++i)
      for (let j = j0; j <= j1; ++j) {
        const list = this.map.get(this.key(i, j));
        if (!list) continue;
        for (const p of list) if ((p[0] - x) ** 2 + (p[1] - y) ** 2 < r * r) return true;
      }
    return false;
  }
}

// exemplar.js — tessera JSON documents (docs/format.md) in the browser: read into a light
// model for drawing, the brushing defaults of sample weights and element graphs
// (tessera/brush.hpp), and the merge of several exemplars into one (palette entries saved
// together: elements side by side, type names kept).
import { typeColors } from './colors.js';

// A light model: {dimension, domain, types: [{name, color, weights, graph}], elements:
// [{type, samples: [[x, y, z]], radius, scale, angle, locked}], bounds: {min, max}}.
export function readDocument(doc) {
  if (!doc || doc.format !== 'tessera') throw new Error('not a tessera JSON document ("format": "tessera")');
  const dimension = doc.dimension === 3 ? 3 : 2;
  const typeList = Array.isArray(doc.types) ? doc.types.map((t) => ({ ...t })) : [];
  const typeIndex = new Map(typeList.map((t, i) => [t.name, i]));
  const elements = [];
  for (const e of doc.elements || []) {
    let name = e.type;
    if (name === undefined) name = typeList.length === 1 ? typeList[0].name : 'default';
    if (!typeIndex.has(name)) {
      typeIndex.set(name, typeList.length);
      typeList.push({ name });
    }
    const points = e.samples ? e.samples : [e.position];
    const samples = points.map((p) => [p[0], p[1], dimension === 3 ? p[2] : 0]);
    elements.push({
      id: e.id,
      type: typeIndex.get(name),
      samples,
      radius: e.radius || 0,
      scale: e.scale || 1,
      orientation: e.orientation || null,
      angle: e.angle,
      locked: !!e.locked,
    });
  }
  const colors = typeColors(typeList);
  const types = typeList.map((t, i) => ({ ...t, color: colors[i] }));
  const model = { dimension, domain: doc.domain, types, elements };
  for (let t = 0; t < types.length; ++t) {
    if (!types[t].weights || !types[t].weights.length) types[t].weights = defaultWeights(model, t);
    if (!types[t].graph || !types[t].graph.length) types[t].graph = chainGraph(model, t);
  }
  model.bounds = bounds(model);
  return model;
}

function sampleCount(model, type) {
  const e = model.elements.find((el) => el.type === type);
  return e ? e.samples.length : 1;
}

// brush_sample_weights(): the element radius, else half the 10% quantile of the distance
// from the type's samples to the nearest sample of another element.
function defaultWeights(model, type) {
  const count = sampleCount(model, type);
  const withRadius = model.elements.find((e) => e.type === type && e.radius > 0);
  if (withRadius) return new Array(count).fill(withRadius.radius);
  const all = [];
  model.elements.forEach((e, k) => e.samples.forEach((p) => all.push([p, k])));
  const nearest = [];
  model.elements.forEach((e, k) => {
    if (e.type !== type) return;
    for (const p of e.samples) {
      let best = Infinity;
      for (const [q, j] of all) {
        if (j === k) continue;
        const d = (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 + (p[2] - q[2]) ** 2;
        if (d < best) best = d;
      }
      if (Number.isFinite(best)) nearest.push(Math.sqrt(best));
    }
  });
  if (!nearest.length) return new Array(count).fill(0.5);
  nearest.sort((a, b) => a - b);
  return new Array(count).fill(Math.max(0.5 * nearest[Math.floor(nearest.length / 10)], 1e-9));
}

// brush_element_graph(): a chain through the samples in id order.
function chainGraph(model, type) {
  const count = sampleCount(model, type);
  const edges = [];
  for (let i = 0; i + 1 < count; ++i) edges.push([i, i + 1]);
  return edges;
}

function bounds(model) {
  const d = model.domain;
  if (d && Array.isArray(d.min) && Array.isArray(d.max))
    return { min: [d.min[0], d.min[1], d.min[2] || 0], max: [d.max[0], d.max[1], d.max[2] || 0] };
  if (d && d.type === 'polygon' && Array.isArray(d.outer)) {
    const xs = d.outer.map((p) => p[0]);
    const ys = d.outer.map((p) => p[1]);
    return { min: [Math.min(...xs), Math.min(...ys), 0], max: [Math.max(...xs), Math.max(...ys), 0] };
  }
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (const e of model.elements)
    for (const p of e.samples)
      for (let a = 0; a < 3; ++a) {
        min[a] = Math.min(min[a], p[a]);
        max[a] = Math.max(max[a], p[a]);
      }
  if (!model.elements.length) return { min: [0, 0, 0], max: [1, 1, 0] };
  return { min, max };
}

// The area (2D) or volume (3D) of a document's domain box.
export function domainMeasure(doc) {
  const d = doc.domain;
  if (!d || !d.min || !d.max) return null;
  let m = 1;
  for (let a = 0; a < doc.dimension; ++a) m *= d.max[a] - d.min[a];
  return m;
}

// Several exemplars as one: each placed to the right of the previous one's domain box,
// elements and types kept (a type named like an earlier one but differing in sample count
// is renamed "name (entry)"). Domains become the box around all; ids are dropped (renumbered
// by the reader). Only box-like domains are merged; others use their elements' bounds.
export function mergeExemplars(docs, names) {
  if (docs.length < 2) throw new Error('choose two palette entries or more to merge');
  const dimension = docs[0].dimension;
  if (docs.some((d) => d.dimension !== dimension)) throw new Error('cannot merge 2D and 3D exemplars');
  const types = [];
  const typeByName = new Map();
  const elements = [];
  const attributes = [];
  let offset = 0;
  let min = null;
  let max = null;
  docs.forEach((doc, k) => {
    const model = readDocument(doc);
    const b = model.bounds;
    const shift = offset - b.min[0];
    const rename = new Map();
    model.types.forEach((t, ti) => {
      const count = sampleCount(model, ti);
      let name = t.name;
      const known = typeByName.get(name);
      if (known && known.count !== count) name = `${t.name} (${names[k]})`;
      rename.set(ti, name);
      if (!typeByName.has(name)) {
        const source = (doc.types || []).find((s) => s.name === t.name) || { name: t.name };
        const copy = { ...source, name };
        delete copy.mesh; // a mesh path is relative to its own file: not carried over
        delete copy.depends_on;
        typeByName.set(name, { count });
        types.push(copy);
      }
    });
    for (const e of model.elements) {
      const out = { type: rename.get(e.type) };
      const pts = e.samples.map((p) => {
        const q = [p[0] + shift, p[1]];
        if (dimension === 3) q.push(p[2]);
        return q;
      });
      if (pts.length === 1) out.position = pts[0];
      else out.samples = pts;
      if (e.radius > 0) out.radius = e.radius;
      if (e.orientation) out.orientation = e.orientation;
      else if (typeof e.angle === 'number') out.angle = e.angle;
      if (e.scale && e.scale !== 1) out.scale = e.scale;
      elements.push(out);
    }
    const lo = [b.min[0] + shift, b.min[1], b.min[2]];
    const hi = [b.max[0] + shift, b.max[1], b.max[2]];
    min = min ? min.map((v, a) => Math.min(v, lo[a])) : lo;
    max = max ? max.map((v, a) => Math.max(v, hi[a])) : hi;
    offset = hi[0];
  });
  const dims = dimension === 3 ? 3 : 2;
  return {
    format: 'tessera',
    version: 1,
    description: `merged in tessera studio from ${names.join(', ')}`,
    dimension,
    domain: { type: 'box', min: min.slice(0, dims), max: max.slice(0, dims) },
    types,
    ...(attributes.length ? { attributes } : {}),
    elements,
  };
}

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

// Several exemplars as one mixed exemplar (the paper's palette: "select and even mix
// elements ... save multiple selected exemplars as a new input exemplar"). The exemplars are
// laid over one another in the box of the largest, each repeated to cover it, so that every
// neighbourhood of the result holds elements of all of them and a stroke painted with it
// grows the mixture (laid side by side, growth from one seed would copy only one of them).
// Where an element would come closer to an element of an earlier exemplar than 0.9 of their
// summed sample weights (or to another copy of its own exemplar than its own closest pair),
// it is left out, so the mix has no overlaps; the earlier exemplars win, so list the large
// elements first. Types keep their names (a name met again with another sample count
// becomes "name (entry)"); ids are dropped (renumbered by the reader).
export function mergeExemplars(docs, names) {
  if (docs.length < 2) throw new Error('choose two palette entries or more to merge');
  const dimension = docs[0].dimension;
  if (docs.some((d) => d.dimension !== dimension)) throw new Error('cannot merge 2D and 3D exemplars');
  const dims = dimension === 3 ? 3 : 2;
  const models = docs.map((d) => readDocument(d));
  const extent = (b) => Array.from({ length: dims }, (_, a) => Math.max(b.max[a] - b.min[a], 1e-9));
  const measure = (b) => extent(b).reduce((m, x) => m * x, 1);
  const target = models.reduce((best, m) => (measure(m.bounds) > measure(best.bounds) ? m : best)).bounds;
  const types = [];
  const typeByName = new Map();
  const kept = []; // {samples, weights, source}
  models.forEach((model, k) => {
    const rename = typeNames(model, docs[k], names[k], types, typeByName);
    const own = closestPair(model);
    for (const copy of coveringCopies(model.bounds, target, dims))
      for (const e of model.elements) {
        const samples = e.samples.map((p) => p.map((x, a) => x + (copy[a] || 0)));
        if (!insideBox(centroid(samples), target, dims)) continue;
        const weights = model.types[e.type].weights;
        if (collides(samples, weights, kept, k, own)) continue;
        kept.push({ samples, weights, source: k, element: e, type: rename.get(e.type) });
      }
  });
  return {
    format: 'tessera',
    version: 1,
    description: `mixed in tessera studio from ${names.join(', ')}`,
    dimension,
    domain: { type: 'box', min: target.min.slice(0, dims), max: target.max.slice(0, dims) },
    types,
    elements: kept.map((k) => elementOut(k, dims)),
  };
}

// The merged names of a model's types (added to `types` once).
function typeNames(model, doc, entryName, types, typeByName) {
  const rename = new Map();
  model.types.forEach((t, ti) => {
    const count = sampleCount(model, ti);
    let name = t.name;
    const known = typeByName.get(name);
    if (known && known.count !== count) name = `${t.name} (${entryName})`;
    rename.set(ti, name);
    if (!typeByName.has(name)) {
      const source = (doc.types || []).find((s) => s.name === t.name) || { name: t.name };
      const copy = { ...source, name, weights: t.weights };
      delete copy.mesh; // a mesh path is relative to its own file: not carried over
      delete copy.depends_on;
      typeByName.set(name, { count });
      types.push(copy);
    }
  });
  return rename;
}

// Offsets of the copies of box `b` (repeated with its own period) that cover box `target`.
function coveringCopies(b, target, dims) {
  let copies = [[]];
  for (let a = 0; a < dims; ++a) {
    const period = Math.max(b.max[a] - b.min[a], 1e-9);
    const first = Math.floor((target.min[a] - b.min[a]) / period);
    const last = Math.ceil((target.max[a] - b.max[a]) / period);
    const next = [];
    for (const c of copies) for (let i = first; i <= Math.max(first, last); ++i) next.push([...c, i * period]);
    copies = next;
  }
  return copies;
}

const centroid = (pts) => pts[0].map((_, a) => pts.reduce((s, p) => s + p[a], 0) / pts.length);
const insideBox = (p, b, dims) => p.slice(0, dims).every((x, a) => x >= b.min[a] && x < b.max[a]);

// The closest distance between samples of two elements of a model.
function closestPair(model) {
  let best = Infinity;
  model.elements.forEach((e, i) =>
    model.elements.forEach((f, j) => {
      if (j <= i) return;
      for (const p of e.samples) for (const q of f.samples) best = Math.min(best, dist(p, q));
    }),
  );
  return Number.isFinite(best) ? best : 0;
}

const dist = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1], (p[2] || 0) - (q[2] || 0));

function collides(samples, weights, kept, source, own) {
  for (const k of kept)
    for (let i = 0; i < samples.length; ++i)
      for (let j = 0; j < k.samples.length; ++j) {
        const d = dist(samples[i], k.samples[j]);
        if (k.source === source ? d < 0.999 * own : d < 0.9 * ((weights[i] || 0) + (k.weights[j] || 0))) return true;
      }
  return false;
}

function elementOut(k, dims) {
  const e = k.element;
  const out = { type: k.type };
  const pts = k.samples.map((p) => p.slice(0, dims));
  if (pts.length === 1) out.position = pts[0];
  else out.samples = pts;
  if (e.radius > 0) out.radius = e.radius;
  if (e.orientation) out.orientation = e.orientation;
  else if (typeof e.angle === 'number') out.angle = e.angle;
  if (e.scale && e.scale !== 1) out.scale = e.scale;
  return out;
}

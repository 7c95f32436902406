// canvas_presets.js — the canvases offered in the top bar (any --domain form can be typed
// instead; docs/studio.md, POST /api/sessions) and what a canvas text tells before the
// server answers: its dimension and, for boxes, its extent.

export const CANVAS_PRESETS = [
  { label: '2D · 60 × 40', canvas: 'box:0,0,60,40' },
  { label: '2D · 40 × 40', canvas: 'box:0,0,40,40' },
  { label: '2D · 30 × 20', canvas: 'box:0,0,30,20' },
  { label: '2D · disk with a hole', canvas: 'polygon:examples/domain_disk_with_hole.json' },
  { label: '3D · box 20 × 20 × 12', canvas: 'box:0,0,20,20,0,12' },
  { label: '3D · bowl (mesh volume)', canvas: 'mesh:examples/scenes/bowl.obj' },
  { label: '3D · blob (surface)', canvas: 'shell:examples/blob.obj,1' },
];

export function canvasDimension(text) {
  const [kind, rest = ''] = text.split(/:(.*)/s);
  if (kind === 'mesh' || kind === 'shell') return 3;
  if (kind === 'box') {
    const n = rest.split(',').length;
    return n === 3 || n === 6 ? 3 : 2;
  }
  return 2;
}

// The mesh file a 3D canvas is made of (mesh:FILE[,res], shell:FILE,t[,res]), or null.
export function canvasMeshFile(text) {
  const m = /^(mesh|shell):([^,]+)/.exec(text);
  return m ? m[2] : null;
}

export function defaultCanvas(dimension) {
  return dimension === 3 ? 'box:0,0,20,20,0,12' : 'box:0,0,60,40';
}

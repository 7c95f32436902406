// stroke_style.js — how a stroke is drawn in both views: paint strokes as a faint band of the
// brush width in their palette entry's colour, direction strokes as a blue line with an
// arrow, erase strokes as a red band.

export function strokeStyle(op, state) {
  const width = op.width || state.width || 1;
  if (op.op === 'paint') {
    const entry = (state.entries || []).find((e) => e.name === op.palette);
    return { color: entry ? entry.color : '#e0a040', band: true, width };
  }
  if (op.op === 'erase') return { color: '#e0605a', band: true, width, dash: [5, 4] };
  return { color: '#7fb8ff', band: false, width, arrow: true };
}

// statusbar.js — the status bar: the last message, the running job's stage and fraction with
// its Cancel button (DELETE /api/jobs/ID), the element count and the pointer's position.

export function createStatusbar(store, session, el) {
  const { message, job, stage, bar, fraction, cancel, counts, cursor } = el;

  store.on('message', (s) => {
    message.textContent = s.message ? s.message.text : '';
    message.className = `message ${s.message ? s.message.kind : ''}`;
    message.title = message.textContent;
  });
  store.on('job', (s) => {
    const j = s.job;
    job.hidden = !j;
    if (!j) return;
    const f = Math.max(0, Math.min(1, j.fraction || 0));
    const iter = j.iterations ? ` · iteration ${Math.max(j.iteration, 0)}/${j.iterations}` : '';
    stage.textContent = j.state === 'running' ? `${j.label || ''}${j.stage && j.stage !== j.label ? ` · ${j.stage}` : ''}${iter}` : `${j.label || 'job'} ${j.state}`;
    bar.style.width = `${(j.state === 'done' ? 1 : f) * 100}%`;
    fraction.textContent = `${Math.round((j.state === 'done' ? 1 : f) * 100)}%`;
    cancel.disabled = j.state !== 'running';
  });
  store.on('view', (s) => {
    const v = s.view;
    if (!v) return;
    const n = v.model.elements.length;
    const locked = v.model.elements.filter((e) => e.locked).length;
    counts.textContent = `${n} elements (${locked} painted) · ${v.canvas}`;
  });
  store.on('pointer', (s) => {
    const p = s.pointer;
    cursor.textContent = p ? p.slice(0, s.session && s.session.dimension === 3 ? 3 : 2).map((x) => x.toFixed(2)).join(', ') : '';
  });
  cancel.addEventListener('click', () => {
    cancel.disabled = true;
    session.cancel().catch((e) => store.set({ message: { text: e.message, kind: 'error' } }));
  });
}

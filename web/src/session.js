// session.js — the canvas being painted, as a server session (docs/studio.md, "Sessions and
// jobs"): making it, adding palette entries to it, applying operations one at a time
// (following the jobs of the long ones), reading its arrangement back, undo and redo, and
// session files.
//
// Undo and redo are the server's (POST /api/sessions/ID/undo and /redo): each operation
// carries the group of its gesture (a painted stroke is sent as several paint operations
// while it is drawn, one group), and the server keeps the canvas as it was before each group,
// so an undo is a swap, not a replay. The groups are mirrored here for the buttons and for
// drawing the strokes; a session file's operations, replayed when it is opened, are where its
// session starts and are not undone.
import { api } from './api.js';
import { followJob } from './jobs.js';
import { readDocument } from './exemplar.js';
import { canvasDimension } from './canvas_presets.js';
import { createQueue } from './store.js';

// Steps the server keeps per session (apps/studio/session_history.hpp, max_undo_steps).
const MAX_UNDO_STEPS = 64;

export function createSession(store) {
  const queue = createQueue();
  let openGroup = null; // the ops of the gesture in progress
  let groupId = 0; // the server's undo group of the gesture in progress (or of a lone op)
  let baseOps = []; // ops no longer undoable (an opened file's, the steps past the server's bound)

  const message = (text, kind = '') => store.set({ message: { text, kind, at: performance.now() } });
  const setBusy = () => store.set({ busy: queue.pending > 0 });

  // Everything that talks to the server about this session goes through the queue.
  function serial(task) {
    const run = queue.run(async () => {
      setBusy();
      try {
        return await task();
      } finally {
        setTimeout(setBusy, 0);
      }
    });
    setBusy();
    return run;
  }

  async function waitJob(jobId, label) {
    store.set({ job: { id: jobId, label, state: 'running', fraction: 0 } });
    try {
      const job = await followJob(jobId, (j) => store.set({ job: { ...j, label } }));
      store.set({ job: { ...job, label } });
      return job;
    } finally {
      setTimeout(() => {
        if (store.state.job && store.state.job.id === jobId) store.set({ job: null });
      }, 600);
    }
  }

  async function refresh() {
    const s = store.state.session;
    if (!s) return;
    const t0 = performance.now();
    const view = await api.session(s.id);
    const model = readDocument(view.arrangement);
    store.set({
      view: {
        sessionId: view.id,
        canvas: view.canvas,
        dimension: view.dimension,
        model,
        directions: view.directions || [],
        sampleEntries: view.exemplars || [],
        palette: view.palette.map((p) => p.name),
        options: view.options,
        fetchedAt: performance.now(),
        fetchMs: performance.now() - t0,
      },
    });
  }

  // Appends what an operation answered it added (its "changes", docs/studio.md "Live
  // painting") to the view, instead of reading the whole session back. False when the view
  // is not the canvas the changes follow (then the caller reads the session).
  function appendChanges(changes) {
    const view = store.state.view;
    if (!changes || !view || !view.model) return false;
    const model = view.model;
    const names = (changes.arrangement.types || []).map((t) => t.name);
    if (changes.first_element !== model.elements.length || changes.first_sample !== view.directions.length) return false;
    if (names.length !== model.types.length || names.some((n, i) => n !== model.types[i].name)) return false;
    const added = changes.arrangement.elements && changes.arrangement.elements.length ? readDocument(changes.arrangement).elements : [];
    const bounds = { min: [...model.bounds.min], max: [...model.bounds.max] };
    for (const e of added)
      for (const p of e.samples)
        for (let a = 0; a < 3; ++a) {
          bounds.min[a] = Math.min(bounds.min[a], p[a]);
          bounds.max[a] = Math.max(bounds.max[a], p[a]);
        }
    store.set({
      view: {
        ...view,
        model: { ...model, elements: model.elements.concat(added), bounds },
        directions: view.directions.concat(changes.directions),
        sampleEntries: view.sampleEntries.concat(changes.exemplars),
        fetchedAt: performance.now(),
        fetchMs: 0,
      },
    });
    return true;
  }

  function setGroups(groups, redo = store.state.redo) {
    const kept = groups.slice();
    while (kept.length > MAX_UNDO_STEPS) baseOps = baseOps.concat(kept.shift());
    store.set({ groups: kept, redo, ops: baseOps.concat(kept.flat()) });
  }

  async function replaceSession(created, canvas, dimension, entries) {
    const old = store.state.session;
    store.set({ session: { id: created.id, canvas, dimension, entries: new Set(entries) } });
    if (old && old.id !== created.id) api.deleteSession(old.id).catch(() => {});
  }

  // A new, empty canvas (the old session is dropped).
  function newCanvas(canvas, options) {
    return serial(async () => {
      const created = await api.createSession(canvas, options);
      await replaceSession(created, canvas, created.dimension, []);
      baseOps = [];
      setGroups([], []);
      await refresh();
      message(`New ${created.dimension}D canvas ${canvas}`);
    });
  }

  // Adds a palette entry ({name, path} or {name, exemplar}) to the session once.
  async function ensureEntry(entry) {
    const s = store.state.session;
    if (s.entries.has(entry.name)) return;
    const body = entry.path ? { name: entry.name, path: entry.path } : { name: entry.name, exemplar: entry.exemplar };
    await api.addPalette(s.id, body);
    s.entries.add(entry.name);
  }

  // Applies one operation (inside the queue). Short ones answer their report at once; long
  // ones run as a job that this follows. Resolves with {report, state}.
  async function applyNow(op, label) {
    const s = store.state.session;
    const t0 = performance.now();
    const group = openGroup ? groupId : ++groupId;
    const answer = await api.op(s.id, { ...op, group });
    const t1 = performance.now();
    let result;
    if (answer.job) {
      const job = await waitJob(answer.job, label || op.op);
      if (job.state === 'failed') throw new Error(job.error || `${op.op} failed`);
      result = { report: job.report, state: job.state };
    } else {
      result = { report: answer.report, state: 'done', changes: answer.changes };
    }
    if (result.state === 'done') {
      if (openGroup) openGroup.push(op);
      else setGroups([...store.state.groups, [op]], []);
    }
    const t2 = performance.now();
    if (!appendChanges(result.changes)) await refresh();
    // Where the time went (the stroke latency benchmark prints it).
    result.timings = { postMs: t1 - t0, jobMs: t2 - t1, readMs: performance.now() - t2 };
    return result;
  }

  function apply(op, { entry, label } = {}) {
    return serial(async () => {
      if (entry) await ensureEntry(entry);
      return applyNow(op, label);
    });
  }

  // A gesture's operations form one undo step.
  function beginGroup() {
    return serial(async () => {
      openGroup = [];
      ++groupId;
    });
  }
  function endGroup() {
    return serial(async () => {
      const group = openGroup;
      openGroup = null;
      if (group && group.length) setGroups([...store.state.groups, group], []);
    });
  }

  // The session file of the current session.
  function sessionFile() {
    return api.sessionFile(store.state.session.id);
  }

  // Replaces the session with one made from `file` (its ops replayed as one job).
  async function loadFrom(file, label) {
    const created = await api.loadSession(file);
    await replaceSession(created, file.canvas, created.dimension, Object.keys(file.palette || {}));
    if (created.job) {
      const job = await waitJob(created.job, label);
      if (job.state !== 'done') throw new Error(job.error || `replay ${job.state}`);
    }
  }

  function undo() {
    return serial(async () => {
      const groups = store.state.groups;
      if (!groups.length) return;
      const last = groups[groups.length - 1];
      await api.undo(store.state.session.id);
      setGroups(groups.slice(0, -1), [...store.state.redo, last]);
      await refresh();
      message(`Undid ${describe(last)}`);
    });
  }

  function redo() {
    return serial(async () => {
      const redoStack = store.state.redo;
      if (!redoStack.length) return;
      const group = redoStack[redoStack.length - 1];
      await api.redo(store.state.session.id);
      setGroups([...store.state.groups, group], redoStack.slice(0, -1));
      await refresh();
      message(`Redid ${describe(group)}`);
    });
  }

  function saveFile() {
    return serial(() => sessionFile());
  }

  // Opens a session file (an object already parsed).
  function openFile(file) {
    return serial(async () => {
      await loadFrom(file, 'open');
      baseOps = Array.isArray(file.ops) ? file.ops : [];
      setGroups([], []);
      const ops = baseOps;
      await refresh();
      message(`Opened a session: ${file.canvas}, ${ops.length} operations`, 'ok');
    });
  }

  function exportAs(format) {
    return serial(() => api.exportFile(store.state.session.id, format));
  }

  function cancel() {
    const job = store.state.job;
    if (job && job.id && job.state === 'running') return api.cancelJob(job.id);
    return Promise.resolve();
  }

  return {
    newCanvas, ensureEntry, apply, beginGroup, endGroup, undo, redo, saveFile, openFile, exportAs, cancel, refresh,
    serial, dimensionOf: canvasDimension,
    get queue() {
      return queue;
    },
  };
}

function describe(group) {
  const kinds = [...new Set(group.map((op) => op.op))];
  return kinds.length === 1 && kinds[0] === 'paint' ? 'a paint stroke' : kinds.join(' + ');
}

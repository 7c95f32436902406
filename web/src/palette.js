// palette.js — the element palette (left panel): the built-in exemplars (GET /api/palette)
// as thumbnails drawn from their elements, exemplar files loaded from the disk (read here and
// sent inline), and entries saved from a selection of several (merged here, sent inline).
// Click chooses the entry to paint with; shift or ctrl click selects several.
import { api } from './api.js';
import { readDocument, mergeExemplars } from './exemplar.js';
import { drawThumbnail } from './thumbnail.js';

export function createPalette(store, session, el) {
  const { list, fileInput, mergeButton } = el;

  function entryColor(model) {
    return model.types.length ? model.types[0].color : '#e0a040';
  }

  function addEntry(entry) {
    const entries = store.state.entries.filter((e) => e.name !== entry.name);
    store.set({ entries: [...entries, entry] });
    return entry;
  }

  function makeEntry(name, doc, extra) {
    const model = readDocument(doc);
    return { name, doc, model, dimension: model.dimension, color: entryColor(model), elements: model.elements.length, ...extra };
  }

  async function loadBuiltIns() {
    const { examples } = await api.palette();
    const loaded = await Promise.all(
      examples.map(async (ex) => {
        try {
          const doc = await api.file(ex.path);
          return makeEntry(ex.name, doc, { kind: 'example', path: ex.path });
        } catch (e) {
          return null; // listed but unreadable: left out
        }
      }),
    );
    store.set({ entries: [...loaded.filter(Boolean), ...store.state.entries.filter((e) => e.kind !== 'example')] });
  }

  function uniqueName(base) {
    const names = new Set(store.state.entries.map((e) => e.name));
    let name = base.slice(0, 90) || 'entry';
    for (let k = 2; names.has(name); ++k) name = `${base.slice(0, 86)} ${k}`;
    return name;
  }

  // Sends an inline entry to the session at once when it fits the canvas, so that a file the
  // server refuses is reported now, not at the first stroke.
  async function checkInline(entry) {
    const s = store.state.session;
    if (!s || s.dimension !== entry.dimension) return true;
    try {
      await session.serial(() => session.ensureEntry(entry));
      return true;
    } catch (e) {
      store.set({ entries: store.state.entries.filter((x) => x !== entry), message: { text: `${entry.name}: ${e.message}`, kind: 'error' } });
      return false;
    }
  }

  async function addFile(file) {
    let doc;
    try {
      doc = JSON.parse(await file.text());
      readDocument(doc);
    } catch (e) {
      store.set({ message: { text: `${file.name}: ${e.message}`, kind: 'error' } });
      return;
    }
    const name = uniqueName(file.name.replace(/\.json$/i, ''));
    const entry = addEntry(makeEntry(name, doc, { kind: 'file', exemplar: doc }));
    if (await checkInline(entry)) {
      select(entry.name, false);
      store.set({ message: { text: `Added ${name} (${entry.elements} elements) to the palette`, kind: 'ok' } });
    }
  }

  async function mergeSelection() {
    const chosen = store.state.selected.map((n) => store.state.entries.find((e) => e.name === n)).filter(Boolean);
    let doc;
    try {
      doc = mergeExemplars(chosen.map((e) => e.doc), chosen.map((e) => e.name));
    } catch (e) {
      store.set({ message: { text: e.message, kind: 'error' } });
      return;
    }
    const name = uniqueName(chosen.map((e) => e.name).join(' + '));
    const entry = addEntry(makeEntry(name, doc, { kind: 'merged', exemplar: doc }));
    if (await checkInline(entry)) {
      select(entry.name, false);
      store.set({ message: { text: `Saved ${name} as a palette entry`, kind: 'ok' } });
    }
  }

  function select(name, additive) {
    let selected = store.state.selected;
    if (!additive) selected = [name];
    else if (selected.includes(name)) selected = selected.filter((n) => n !== name);
    else selected = [...selected, name];
    const active = selected.includes(name) ? name : selected[selected.length - 1] || null;
    store.set({ selected, active });
  }

  function render() {
    const { entries, selected, active, session: s } = store.state;
    list.replaceChildren();
    for (const entry of entries) {
      const item = document.createElement('button');
      item.className = 'swatch';
      item.dataset.name = entry.name;
      item.title = `${entry.name} — ${entry.dimension}D, ${entry.elements} elements, ${entry.model.types.map((t) => t.name).join(', ')}` +
        (entry.kind === 'example' ? `\n${entry.path}` : entry.kind === 'merged' ? '\nsaved from a selection' : '\nfrom a file');
      if (selected.includes(entry.name)) item.classList.add('selected');
      if (active === entry.name) item.classList.add('active');
      if (s && s.dimension !== entry.dimension) item.classList.add('incompatible');
      const canvas = document.createElement('canvas');
      canvas.width = canvas.height = 112;
      drawThumbnail(canvas, entry.model);
      const label = document.createElement('span');
      label.className = 'name';
      label.textContent = entry.name;
      const dim = document.createElement('span');
      dim.className = 'dim';
      dim.textContent = `${entry.dimension}D`;
      item.append(canvas, label, dim);
      item.addEventListener('click', (event) => select(entry.name, event.shiftKey || event.ctrlKey || event.metaKey));
      list.append(item);
    }
    const chosen = selected.map((n) => entries.find((e) => e.name === n)).filter(Boolean);
    mergeButton.disabled = chosen.length < 2 || chosen.some((e) => e.dimension !== chosen[0].dimension);
  }

  fileInput.addEventListener('change', async () => {
    for (const file of fileInput.files) await addFile(file);
    fileInput.value = '';
  });
  mergeButton.addEventListener('click', mergeSelection);
  store.on(['entries', 'selected', 'active', 'session'], render);

  return {
    loadBuiltIns,
    select,
    // Palette entries named by a session file that the palette does not know yet (paths are
    // relative to the root, as the server writes them).
    async adopt(file) {
      for (const [name, source] of Object.entries(file.palette || {})) {
        if (store.state.entries.some((e) => e.name === name)) continue;
        try {
          if (typeof source === 'object') addEntry(makeEntry(name, source, { kind: 'file', exemplar: source }));
          else addEntry(makeEntry(name, await api.file(source), { kind: 'example', path: source }));
        } catch {
          /* the server reports it when the session is loaded */
        }
      }
    },
    entry: (name) => store.state.entries.find((e) => e.name === name),
  };
}

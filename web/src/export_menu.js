// export_menu.js — the Export menu: every format of POST /api/sessions/ID/export; the file
// the server writes is downloaded as it names it.
import { EXPORT_FORMATS } from './api.js';
import { downloadBlob } from './files.js';

export function createExportMenu(store, session, { button, items }) {
  for (const f of EXPORT_FORMATS) {
    const b = document.createElement('button');
    b.dataset.format = f.format;
    b.innerHTML = `<span>${f.label}</span><span class="fmt-note">.${f.format}${f.note ? ` · ${f.note}` : ''}</span>`;
    b.addEventListener('click', async () => {
      items.hidden = true;
      try {
        const file = await session.exportAs(f.format);
        downloadBlob(file.blob, file.filename || `arrangement.${f.format}`);
        store.set({ message: { text: `Exported ${file.filename} (${(file.blob.size / 1024).toFixed(1)} KiB)`, kind: 'ok' } });
      } catch (e) {
        store.set({ message: { text: `Export ${f.format}: ${e.message}`, kind: 'error' } });
      }
    });
    items.append(b);
  }
  button.addEventListener('click', (e) => {
    e.stopPropagation();
    items.hidden = !items.hidden;
  });
  document.addEventListener('click', (e) => {
    if (!items.contains(e.target)) items.hidden = true;
  });
}

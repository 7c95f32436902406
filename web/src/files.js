// files.js — downloads (exports, session files) and reading a chosen file as JSON.

export function downloadBlob(blob, filename) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

export function downloadJson(doc, filename) {
  downloadBlob(new Blob([JSON.stringify(doc, null, 1)], { type: 'application/json' }), filename);
}

export async function readJsonFile(file) {
  try {
    return JSON.parse(await file.text());
  } catch (e) {
    throw new Error(`${file.name}: not JSON (${e.message})`);
  }
}

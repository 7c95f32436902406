// api.js — the studio server's JSON API (docs/studio.md, "API"): one function per route.
// Every failure throws an ApiError carrying the HTTP status and the server's one-line message.

export class ApiError extends Error {
  constructor(status, message) {
    super(message);
    this.status = status;
  }
}

async function request(method, path, body) {
  const init = { method, headers: {} };
  if (body !== undefined) {
    init.headers['Content-Type'] = 'application/json';
    init.body = typeof body === 'string' ? body : JSON.stringify(body);
  }
  let res;
  try {
    res = await fetch(path, init);
  } catch (e) {
    throw new ApiError(0, `the studio server cannot be reached (${e.message})`);
  }
  return res;
}

async function json(method, path, body) {
  const res = await request(method, path, body);
  const text = await res.text();
  let doc = null;
  try {
    doc = text ? JSON.parse(text) : null;
  } catch {
    doc = null;
  }
  if (!res.ok) throw new ApiError(res.status, (doc && doc.error) || `${method} ${path}: HTTP ${res.status}`);
  return doc;
}

// Answers a file download: its bytes and the name the server suggests.
async function download(method, path, body) {
  const res = await request(method, path, body);
  if (!res.ok) {
    let message = `${method} ${path}: HTTP ${res.status}`;
    try {
      message = (await res.json()).error || message;
    } catch { /* not JSON */ }
    throw new ApiError(res.status, message);
  }
  const disposition = res.headers.get('Content-Disposition') || '';
  const match = /filename="([^"]+)"/.exec(disposition);
  return { blob: await res.blob(), filename: match ? match[1] : null, type: res.headers.get('Content-Type') };
}

const enc = encodeURIComponent;

export const api = {
  status: () => json('GET', '/api/status'),
  palette: () => json('GET', '/api/palette'),
  file: (path) => json('GET', `/api/files?path=${enc(path)}`),
  fileText: async (path) => {
    const res = await request('GET', `/api/files?path=${enc(path)}`);
    if (!res.ok) throw new ApiError(res.status, `${path}: HTTP ${res.status}`);
    return res.text();
  },
  createSession: (canvas, options) => json('POST', '/api/sessions', options ? { canvas, options } : { canvas }),
  loadSession: (sessionFile) => json('POST', '/api/sessions/load', sessionFile),
  session: (id) => json('GET', `/api/sessions/${enc(id)}`),
  deleteSession: (id) => json('DELETE', `/api/sessions/${enc(id)}`),
  addPalette: (id, entry) => json('POST', `/api/sessions/${enc(id)}/palette`, entry),
  op: (id, op) => json('POST', `/api/sessions/${enc(id)}/ops`, op),
  undo: (id) => json('POST', `/api/sessions/${enc(id)}/undo`, {}),
  redo: (id) => json('POST', `/api/sessions/${enc(id)}/redo`, {}),
  sessionFile: (id) => json('GET', `/api/sessions/${enc(id)}/file`),
  exportFile: (id, format) => download('POST', `/api/sessions/${enc(id)}/export`, { format }),
  job: (id) => json('GET', `/api/jobs/${enc(id)}`),
  cancelJob: (id) => json('DELETE', `/api/jobs/${enc(id)}`),
  jobEventsUrl: (id) => `/api/jobs/${enc(id)}/events`,
};

// The export formats of POST /api/sessions/ID/export (apps/studio/session_ops.cpp).
export const EXPORT_FORMATS = [
  { format: 'json', label: 'tessera JSON', note: 'everything' },
  { format: 'csv', label: 'CSV', note: 'samples, pose' },
  { format: 'ply', label: 'PLY points', note: 'for instancing' },
  { format: 'usda', label: 'USD', note: 'point instancer' },
  { format: 'gltf', label: 'glTF', note: '.gltf' },
  { format: 'glb', label: 'glTF binary', note: '.glb' },
  { format: 'obj', label: 'OBJ', note: 'meshes' },
  { format: 'png', label: 'PNG picture', note: '' },
  { format: 'svg', label: 'SVG picture', note: '' },
];

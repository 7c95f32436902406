// jobs.js — following a server job (docs/studio.md, "Jobs"): its progress events through
// EventSource on /api/jobs/ID/events, polling GET /api/jobs/ID when the stream fails, and
// cancelling with DELETE /api/jobs/ID.
import { api } from './api.js';

const ENDED = new Set(['done', 'failed', 'cancelled']);

// Resolves with the job's final state ({state: done | failed | cancelled, report, error, ...});
// `onUpdate` gets every state seen. Rejects only when the job cannot be followed at all
// (polling failing for `timeoutMs`).
export function followJob(id, onUpdate = () => {}, { timeoutMs = 30 * 60 * 1000 } = {}) {
  return new Promise((resolve, reject) => {
    let finished = false;
    let source = null;
    let pollTimer = null;
    const started = performance.now();
    const finish = (job) => {
      if (finished) return;
      finished = true;
      if (source) source.close();
      clearTimeout(pollTimer);
      resolve(job);
    };
    const seen = (job) => {
      if (finished) return;
      onUpdate(job);
      if (ENDED.has(job.state)) finish(job);
    };
    const poll = async () => {
      if (finished) return;
      try {
        seen(await api.job(id));
      } catch (e) {
        if (performance.now() - started > timeoutMs) {
          finished = true;
          reject(e);
          return;
        }
      }
      if (!finished) pollTimer = setTimeout(poll, 120);
    };
    if (typeof EventSource === 'undefined') {
      poll();
      return;
    }
    source = new EventSource(api.jobEventsUrl(id));
    source.addEventListener('job', (event) => {
      try {
        seen(JSON.parse(event.data));
      } catch { /* a malformed event: the next one or the poll will tell */ }
    });
    source.onerror = () => {
      // The stream ended (after the last event) or failed (503: too many streams): ask.
      source.close();
      source = null;
      poll();
    };
  });
}

export const cancelJob = (id) => api.cancelJob(id);

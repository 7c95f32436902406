// stroke_sender.js — a paint stroke sent while it is drawn: the points are collected as the
// pointer moves and sent in segments (by default each new point as soon as the segment
// before has been drawn; or every `intervalMs` or `maxPoints` new points, whichever comes
// first; one segment in flight at a time, each starting at the last point of the one before)
// as paint operations, so elements appear along the stroke while the user is still drawing.
// A small segment's paint answers with the elements it added (docs/studio.md, "Live
// painting"), so a point's elements are drawn about one round trip and one frame after it. Records, per segment, the time from its pointer events to its
// elements being drawn (window.__tessera.metrics.paint; tests/web/stroke_latency.mjs).

export function createStrokeSender({ send, afterDraw, intervalMs = 0, maxPoints = 1, metrics }) {
  let points = [];
  let times = [];
  let sent = 0; // points[0..sent) have been sent
  let inFlight = null;
  let lastSendAt = 0;
  let ended = false;
  let timer = null;
  let onIdle = null;
  let stroke = 0;

  function pending() {
    return points.length - sent;
  }

  function maybeSend(force = false) {
    if (inFlight || !pending()) return;
    const now = performance.now();
    if (!force && pending() < maxPoints && now - lastSendAt < intervalMs) return;
    const from = Math.max(sent - 1, 0);
    const segment = points.slice(from);
    const record = {
      stroke,
      points: pending(),
      firstEventAt: times[sent],
      lastEventAt: times[times.length - 1],
      sentAt: now,
    };
    sent = points.length;
    lastSendAt = now;
    inFlight = send(segment)
      .then(async (result) => {
        record.doneAt = performance.now();
        await afterDraw();
        record.drawnAt = performance.now();
        record.added = result && result.report ? result.report.added : 0;
        if (result && result.timings) Object.assign(record, result.timings);
        if (metrics) metrics.push(record);
      })
      .catch((e) => {
        record.error = e.message;
        if (metrics) metrics.push(record);
      })
      .finally(() => {
        inFlight = null;
        if (pending()) maybeSend(ended);
        else if (ended) finish();
      });
  }

  function finish() {
    clearInterval(timer);
    timer = null;
    const done = onIdle;
    onIdle = null;
    if (done) done();
  }

  return {
    begin(point, timeStamp) {
      ++stroke;
      points = [point];
      times = [timeStamp ?? performance.now()];
      sent = 0;
      ended = false;
      lastSendAt = performance.now();
      timer = setInterval(() => maybeSend(false), Math.max(intervalMs / 3, 16));
    },
    add(point, timeStamp) {
      points.push(point);
      times.push(timeStamp ?? performance.now());
      maybeSend(false);
    },
    // Sends what is left; resolves when every segment has been applied and drawn.
    end() {
      ended = true;
      return new Promise((resolve) => {
        onIdle = resolve;
        if (inFlight) return;
        if (pending()) maybeSend(true);
        else finish();
      });
    },
    get points() {
      return points;
    },
  };
}

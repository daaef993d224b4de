// The live page's commands: POST /command, one at a time; the frames acknowledge them.
import { api } from './common.js';

// One request at a time (the server then applies them in the order sent), ids increasing. A push
// or a gain replaces a queued one of its kind: the latest wins.
export function commandQueue(onError) {
  const queue = [];
  const sentAt = new Map();  // id -> performance.now() when sent, until a frame acknowledges it
  let busy = false, nextId = 1, lastPush = 0, timer = 0;
  async function pump() {
    if (busy || !queue.length || api.stopped) return;
    const item = queue[0];
    if (item.key === 'push') {  // at most about 60 pushes a second
      const wait = lastPush + 16 - performance.now();
      if (wait > 0) {
        if (!timer) timer = setTimeout(() => { timer = 0; pump(); }, wait);
        return;
      }
      lastPush = performance.now();
    }
    queue.shift();
    busy = true;
    const id = nextId++;
    const body = { id, ...item.body };
    api.lastSent = id;
    item.sent?.(id);
    sentAt.set(id, performance.now());
    try {
      const r = await fetch('/command', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) });
      if (!r.ok) {
        sentAt.delete(id);
        let why = `${r.status} ${r.statusText}`;
        try { why = (await r.json()).error || why; } catch { /* not JSON */ }
        item.refused?.();
        onError(`${body.command}: ${why}`);
      }
    } catch (e) {
      sentAt.delete(id);
      item.refused?.();
      if (!api.stopped) onError(`${body.command}: the program did not answer (${e.message})`);
    }
    busy = false;
    pump();
  }
  return {
    /// Queues `body` (a command without its id). `key`: replaces a queued command with the same
    /// key. `sent(id)` is called when it goes, `refused()` when the server refuses it.
    send(body, { key = null, sent = null, refused = null } = {}) {
      const queued = key && queue.find((c) => c.key === key);
      if (queued) Object.assign(queued, { body, sent, refused });
      else queue.push({ body, key, sent, refused });
      pump();
    },
    drop(key) {
      for (let i = queue.length - 1; i >= 0; --i) if (queue[i].key === key) queue.splice(i, 1);
    },
    /// A frame has applied every command up to `id`: their latencies.
    acknowledged(id, now) {
      for (const [sent, at] of sentAt) {
        if (sent > id) continue;
        api.latencies.push(now - at);
        if (api.latencies.length > 1000) api.latencies.shift();
        sentAt.delete(sent);
      }
    },
  };
}

// The live page's frames: the event stream (/events), the frame rate, the program's exit.
import { api } from './common.js';

/// Follows /events: each frame becomes api.lastFrame (drawn by the page's loop, which clears
/// `fresh`), acknowledges commands and feeds the plots (`plotsDirty`). When the stream ends,
/// `stopped()` is called once.
export function openStream(commands, plots, stopped) {
  const state = { fresh: false, plotsDirty: true };
  let lastT = -Infinity;
  const arrivals = [];
  /// api.fps: the frames that arrived in the last second before `now`.
  state.count = (now) => {
    while (arrivals.length && arrivals[0] < now - 1000) arrivals.shift();
    api.fps = arrivals.length;
  };
  const source = new EventSource('/events');
  let silence = 0;
  source.onmessage = (message) => {
    let frame;
    try {
      frame = JSON.parse(message.data);
    } catch (e) {
      console.error(`opspace live: a frame that is not JSON: ${message.data.slice(0, 80)}`);
      return;
    }
    const now = performance.now();
    clearTimeout(silence);
    silence = 0;
    if (frame.t < lastT - 1e-9) plots.clear();  // a reset: the run starts again at t = 0
    lastT = frame.t;
    api.frames += 1;
    api.lastFrame = frame;
    if (!api.firstFrame) api.firstFrame = frame;  // the run waits for the page: t = 0 (check_live.mjs)
    if (api.trace) api.trace.push(frame);  // the test's record (check_live.mjs)
    arrivals.push(now);
    state.count(now);
    if (Number.isFinite(frame.command)) commands.acknowledged(frame.command, now);
    if (frame.samples && frame.samples.length) { plots.add(frame.samples); state.plotsDirty = true; }
    state.fresh = true;
  };
  // The stream ends when the program exits: EventSource would try to reconnect, so after an
  // error with no frame for 2 s the page closes it and says so.
  source.onerror = () => {
    if (api.stopped || silence) return;
    silence = setTimeout(() => {
      source.close();
      api.stopped = true;
      stopped();
    }, source.readyState === EventSource.CLOSED ? 0 : 2000);
  };
  return state;
}

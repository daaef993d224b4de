// What the live page's modules share: the test hook (window.opspaceLive), speeds, formats.

// The test hook (web/test/check_live.mjs, web/test/bench_live.mjs).
export const api = {
  ready: false, stopped: false, frames: 0, lastFrame: null, latencies: [], fps: 0,
  samples: 0, plotDraws: 0, commandErrors: [], lastSent: 0, trace: null, firstFrame: null,
  plotLabels: [],  // per plot at its last draw: {width, height, boxes: [{text, left, right, top, bottom}]}
};
window.opspaceLive = api;

export const SPEEDS = [0.1, 0.25, 0.5, 1];
export const SIDE = 360;  // the width of the side panel, px

export const number = (v, digits = 3) => (Number.isFinite(v) ? v.toFixed(digits) : '-');
export const trimmed = (v) => (Number.isFinite(v) ? String(Number(v.toPrecision(4))) : '-');

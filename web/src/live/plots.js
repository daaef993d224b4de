// The live page's plots: the samples of the last `window` seconds, one small canvas per plot.
import { el } from '../scene.js';
import { api, number, trimmed } from './common.js';

/// Writes `text` at (x, y) with the context's alignment and records its box (CSS pixels of the
/// canvas) in `boxes`, for the check that no label is clipped (window.opspaceLive.plotLabels).
function label(ctx, text, x, y, boxes) {
  ctx.fillText(text, x, y);
  const m = ctx.measureText(text);
  boxes.push({ text, left: x - m.actualBoundingBoxLeft, right: x + m.actualBoundingBoxRight,
    top: y - m.actualBoundingBoxAscent, bottom: y + m.actualBoundingBoxDescent });
}

/// The plots, under `parent`; `fields` ({series, value}: the subtitle's) show the latest value
/// of plot series `series` as the legends do.
export function buildPlots(data, parent, fields = []) {
  const window_ = data.window || 10;
  const plots = [];
  let column = 1;  // samples are [t, values of plot 0's series, plot 1's, ...]
  (data.plots || []).forEach((p, i) => {
    const box = el('div', { class: 'plot' });
    box.append(el('div', { class: 'title' }, p.unit ? `${p.title} (${p.unit})` : p.title));
    const keys = el('div', { class: 'keys' });
    // Each series' latest value beside its name: id value-PLOT-SERIES.
    const values = p.series.map((s, k) => {
      const key = el('span');
      const value = el('span', { class: 'value', id: `value-${i}-${k}` }, '-');
      key.append(el('span', { class: 'swatch', style: `background:${s.color}` }), document.createTextNode(s.label), value);
      keys.append(key);
      return value;
    });
    const canvas = el('canvas');
    box.append(keys, canvas);
    parent.append(box);
    plots.push({ ...p, canvas, values, first: column });
    column += p.series.length;
  });
  let rows = [];
  const minStep = window_ / 1500;  // thinning: more points than pixels are not drawn anyway
  function add(samples) {
    for (const s of samples) {
      const last = rows[rows.length - 1];
      if (last && s[0] >= last[0] && s[0] - last[0] < minStep) continue;
      rows.push(s);
      api.samples += 1;
    }
    const end = rows.length ? rows[rows.length - 1][0] : 0;
    let drop = 0;
    while (drop < rows.length && rows[drop][0] < end - window_ - minStep) ++drop;
    if (drop) rows = rows.slice(drop);
  }
  function clear() { rows = []; }
  function draw(t) {
    const end = Math.max(window_, t), start = end - window_;
    const latest = rows[rows.length - 1];
    for (const f of fields) f.value.textContent = latest ? trimmed(latest[1 + f.series]) : '-';
    api.plotLabels = [];
    for (const p of plots) {
      p.values.forEach((value, k) => { value.textContent = latest ? trimmed(latest[p.first + k]) : '-'; });
      const ratio = window.devicePixelRatio || 1;
      const w = Math.max(1, Math.round(p.canvas.clientWidth * ratio)), h = Math.max(1, Math.round(p.canvas.clientHeight * ratio));
      if (p.canvas.width !== w || p.canvas.height !== h) { p.canvas.width = w; p.canvas.height = h; }
      const ctx = p.canvas.getContext('2d');
      ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
      const W = w / ratio, H = h / ratio;
      ctx.clearRect(0, 0, W, H);
      let lo = Infinity, hi = -Infinity;
      for (const r of rows) {
        if (r[0] < start) continue;
        for (let k = 0; k < p.series.length; ++k) {
          const v = r[p.first + k];
          if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
        }
      }
      if (!(hi >= lo)) { lo = -1; hi = 1; }
      const pad = Math.max((hi - lo) * 0.08, Math.abs(hi) * 1e-3, 1e-9);
      lo -= pad; hi += pad;
      ctx.font = '10px ui-monospace, monospace';
      // A value a thousandth of the span from 0 is 0 on this axis: joint 2's '-0.000001938' was
      // a 12-character label for a curve that touches 0.
      const tick = (v) => (Math.abs(v) < (hi - lo) * 1e-3 ? '0' : trimmed(v));
      const high = tick(hi - pad), low = tick(lo + pad);
      // The left margin fits the wider value label (a fixed 48 px clipped it), up to half the
      // canvas.
      const widest = Math.max(ctx.measureText(high).width, ctx.measureText(low).width);
      const left = Math.min(Math.ceil(widest) + 8, Math.floor(W / 2)), right = 6, top = 8, bottom = 16;
      const x = (s) => left + ((s - start) / window_) * (W - left - right);
      const y = (v) => top + ((hi - v) / (hi - lo)) * (H - top - bottom);
      ctx.strokeStyle = '#e1e3e8';
      ctx.lineWidth = 1;
      ctx.beginPath();
      for (const v of [lo + pad, hi - pad]) { ctx.moveTo(left, y(v)); ctx.lineTo(W - right, y(v)); }
      ctx.stroke();
      ctx.fillStyle = '#666';
      ctx.textAlign = 'right';
      ctx.textBaseline = 'middle';
      const boxes = [];
      label(ctx, high, left - 4, y(hi - pad), boxes);
      label(ctx, low, left - 4, y(lo + pad), boxes);
      ctx.textBaseline = 'bottom';
      label(ctx, `${number(end, 1)} s`, W - right, H, boxes);
      ctx.textAlign = 'left';
      label(ctx, `${number(start, 1)} s`, left, H, boxes);
      api.plotLabels.push({ width: W, height: H, boxes });
      ctx.save();
      ctx.beginPath();
      ctx.rect(left, 0, W - left - right, H - bottom);
      ctx.clip();
      ctx.lineWidth = 1.5;
      for (let k = p.series.length - 1; k >= 0; --k) {  // the first series on top
        ctx.strokeStyle = p.series[k].color;
        ctx.beginPath();
        let pen = false;
        for (const r of rows) {
          if (r[0] < start - minStep) continue;
          const v = r[p.first + k];
          if (!Number.isFinite(v)) { pen = false; continue; }
          if (pen) ctx.lineTo(x(r[0]), y(v)); else ctx.moveTo(x(r[0]), y(v));
          pen = true;
        }
        ctx.stroke();
      }
      ctx.restore();
    }
    api.plotDraws += 1;
  }
  return { add, clear, draw };
}

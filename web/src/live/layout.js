// The live page's layout: its style, the stage, the head-up panel and the side panel.
import { el } from '../scene.js';
import { SIDE, SPEEDS, trimmed } from './common.js';
import { buildPlots } from './plots.js';

const PLOT_HEIGHT = 110;

const CSS = `
html, body { margin: 0; height: 100%; overflow: hidden; font: 13px system-ui, sans-serif; color: #1d2330; background: #f4f5f7; }
#stage { position: absolute; left: 0; top: 0; bottom: 0; right: ${SIDE}px; touch-action: none; }
#stage canvas { width: 100%; height: 100%; display: block; }
#hud { position: absolute; top: 8px; left: 10px; background: rgba(255,255,255,0.88); padding: 6px 10px; border-radius: 6px; max-width: 46%; }
#hud h1 { font-size: 15px; margin: 0 0 2px 0; }
#hud .sub { margin: 0 0 4px 0; color: #555; }
#hud .sub .value { font: 600 13px ui-monospace, monospace; color: #1d2330; }
#readout { margin: 4px 0 0 0; font: 13px ui-monospace, monospace; white-space: pre-wrap; }
#legend { list-style: none; margin: 4px 0 0 0; padding: 0; font-size: 12px; }
.swatch { display: inline-block; width: 10px; height: 10px; margin-right: 6px; border-radius: 2px; }
#error { display: none; margin-top: 6px; padding: 6px 8px; border-radius: 4px; background: #c0392b; color: #fff; font-weight: 600; }
#error button { margin-left: 8px; }
#stopped { display: none; position: absolute; left: calc((100% - ${SIDE}px) / 2); bottom: 16px; transform: translateX(-50%); padding: 8px 14px; border-radius: 6px; background: #1d2330; color: #fff; font-weight: 600; }
#push-label { display: none; position: absolute; pointer-events: none; padding: 1px 6px; border-radius: 4px; background: rgba(255,255,255,0.9); border: 1px solid #d35400; color: #a04000; font: 600 13px ui-monospace, monospace; transform: translate(8px, -50%); }
#side { position: absolute; right: 0; top: 0; bottom: 0; width: ${SIDE}px; overflow-y: auto; padding: 8px 10px; box-sizing: border-box; background: #fff; border-left: 1px solid #d6d8de; }
#side h2 { font-size: 13px; margin: 10px 0 4px 0; }
#side p { margin: 4px 0; color: #555; line-height: 1.35; }
#note { color: #1d2330; background: #fdf2e9; border-left: 3px solid #e67e22; padding: 4px 6px; }
.buttons { display: flex; gap: 6px; align-items: center; flex-wrap: wrap; }
.row { display: grid; grid-template-columns: 96px 1fr 64px; gap: 6px; align-items: center; margin: 2px 0; }
.row input[type=range], .row select { width: 100%; }
.num { font: 12px ui-monospace, monospace; text-align: right; }
#status { min-height: 1.3em; font-size: 12px; color: #555; }
#status.bad { color: #c0392b; font-weight: 600; }
.plot { margin: 6px 0; }
.plot .title { font-weight: 600; }
.plot .keys { font-size: 11px; color: #444; }
.plot .keys > span { margin-right: 10px; white-space: nowrap; }
.plot .keys .value { margin-left: 4px; font: 600 11px ui-monospace, monospace; }
.plot canvas { display: block; width: 100%; height: ${PLOT_HEIGHT}px; background: #fafbfc; border: 1px solid #e1e3e8; border-radius: 3px; box-sizing: border-box; }
#no-webgl { padding: 2em; }
`;

/// The subtitle's line: its text, each "{K}" in it a field that shows plot series K's latest
/// value (docs/live.md): what the run shows, measured, rather than what it should do.
function subtitleLine(text) {
  const line = el('p', { class: 'sub', id: 'subtitle' });
  const fields = [];
  for (const part of text.split(/(\{\d+\})/)) {
    const field = part.match(/^\{(\d+)\}$/);
    if (!field) {
      line.append(document.createTextNode(part));
      continue;
    }
    const value = el('span', { class: 'value', 'data-series': field[1] }, '-');
    fields.push({ series: Number(field[1]), value });
    line.append(value);
  }
  return { line, fields };
}

/// Builds the page's elements and adds them to the document: the ones the other modules use.
export function buildPage(data) {
  document.title = `${data.title} (live)`;
  document.head.append(el('style', {}, CSS));
  // No icon: otherwise Chromium asks the server for /favicon.ico.
  document.head.append(el('link', { rel: 'icon', href: 'data:,' }));
  const laws = data.laws || [];
  const gains = data.gains || [];

  // The stage, with the head-up panel over it.
  const stage = el('div', { id: 'stage' });
  const hud = el('div', { id: 'hud' });
  hud.append(el('h1', {}, data.title));
  const subtitle = subtitleLine(data.subtitle || '');
  if (data.subtitle) hud.append(subtitle.line);
  const readout = el('div', { id: 'readout' });
  readout.textContent = 't = 0.000 s   real time x0.00\nconnecting...';
  hud.append(readout);
  const legend = el('ul', { id: 'legend' });
  for (const m of data.markers || []) {
    const li = el('li');
    li.append(el('span', { class: 'swatch', style: `background:${m.color}` }), document.createTextNode(m.label || m.name));
    legend.append(li);
  }
  if (data.ghost) {
    const li = el('li', { id: 'ghost-key' });
    li.append(el('span', { class: 'swatch', style: `background:${data.ghost.color};opacity:0.5` }), document.createTextNode(data.ghost.label),
      el('span', { id: 'ghost-when' }));
    legend.append(li);
  }
  hud.append(legend);
  const errorBox = el('div', { id: 'error' });
  const errorText = el('span', { id: 'error-text' });
  const errorReset = el('button', { id: 'error-reset', type: 'button' }, 'Reset');
  errorBox.append(errorText, errorReset);
  hud.append(errorBox);
  const stopped = el('div', { id: 'stopped' }, 'the program has stopped: run it again and reload this page');
  const pushLabel = el('div', { id: 'push-label' });

  // The side panel: controls, then the plots.
  const side = el('div', { id: 'side' });
  const buttons = el('div', { class: 'buttons' });
  const pause = el('button', { id: 'pause', type: 'button' }, 'Pause');
  const reset = el('button', { id: 'reset', type: 'button' }, 'Reset');
  const speed = el('select', { id: 'speed', title: 'simulated seconds per wall-clock second' });
  for (const s of SPEEDS) speed.append(el('option', { value: String(s) }, `${s}x`));
  speed.value = '1';
  buttons.append(pause, reset, el('span', {}, 'speed'), speed);
  side.append(buttons);
  let law = null;
  if (laws.length > 1) {
    const row = el('div', { class: 'row' });
    law = el('select', { id: 'law' });
    laws.forEach((name, i) => law.append(el('option', { value: String(i) }, name)));
    law.value = String(data.law || 0);
    row.append(el('span', {}, 'control law'), law, el('span'));
    row.style.gridTemplateColumns = '96px 1fr';
    side.append(row);
  }
  const sliders = {};
  if (gains.length) side.append(el('h2', {}, 'gains'));
  for (const g of gains) {
    const row = el('div', { class: 'row' });
    const input = el('input', { id: `gain-${g.name}`, type: 'range', min: String(g.min), max: String(g.max), step: 'any', value: String(g.value) });
    const shown = el('span', { class: 'num' }, trimmed(g.value));
    row.append(el('span', { title: g.name }, g.label || g.name), input, shown);
    side.append(row);
    sliders[g.name] = { input, shown, held: false, pending: 0 };
  }
  const status = el('div', { id: 'status' });
  side.append(status, el('p', {}, 'Drag the arm to pull it with a spring; drag elsewhere to turn the view, wheel to zoom.'));
  if (data.note) side.append(el('p', { id: 'note' }, data.note));
  const plots = buildPlots(data, side, subtitle.fields);
  document.body.append(stage, hud, stopped, pushLabel, side);

  function say(text, bad = false) {
    status.textContent = text;
    status.className = bad ? 'bad' : '';
  }
  return {
    stage, hud, readout, errorBox, errorText, errorReset, stopped, pushLabel,
    side, pause, reset, speed, law, sliders, say, plots,
  };
}

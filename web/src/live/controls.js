// The live page's controls: the commands they send, and what each frame shows in them.
import { api, number, SPEEDS, trimmed } from './common.js';

/// Wires `page`'s controls to `commands`. Each shows the server's value from the frames, except
/// while the person holds it or until the frames have applied the command it sent (`pending`:
/// its id, Infinity while queued). Returns show(frame) and disable().
export function wireControls(data, page, commands) {
  const { readout, errorBox, errorText, errorReset, side, pause, reset, speed, law, sliders } = page;
  const laws = data.laws || [];
  const speedState = { pending: 0 }, lawState = { pending: 0 };
  const tracked = (state) => ({
    sent: (id) => { state.pending = id; },
    refused: () => { state.pending = 0; },
  });
  const settled = (state, frame) => frame.command >= state.pending;
  pause.addEventListener('click', () => {
    const f = api.lastFrame;
    commands.send({ command: f && f.paused ? 'resume' : 'pause' });
  });
  const doReset = () => commands.send({ command: 'reset' });
  reset.addEventListener('click', doReset);
  errorReset.addEventListener('click', doReset);
  speed.addEventListener('change', () => {
    speedState.pending = Infinity;
    commands.send({ command: 'speed', value: Number(speed.value) }, { key: 'speed', ...tracked(speedState) });
  });
  if (law) {
    law.addEventListener('change', () => {
      lawState.pending = Infinity;
      commands.send({ command: 'law', value: Number(law.value) }, { key: 'law', ...tracked(lawState) });
    });
  }
  for (const [name, s] of Object.entries(sliders)) {
    s.input.addEventListener('pointerdown', () => { s.held = true; });
    s.input.addEventListener('pointerup', () => { s.held = false; });
    s.input.addEventListener('input', () => {
      s.pending = Infinity;
      s.shown.textContent = trimmed(Number(s.input.value));
      commands.send({ command: 'gain', name, value: Number(s.input.value) }, { key: `gain ${name}`, ...tracked(s) });
    });
  }
  window.addEventListener('keydown', (e) => {
    if (e.key === ' ' && e.target === document.body) { pause.click(); e.preventDefault(); }
  });

  return {
    /// The frame's time, real-time factor, law, error, and the server's values in the controls.
    show(frame) {
      const lawName = laws[frame.law] !== undefined ? laws[frame.law] : `law ${frame.law}`;
      const latency = api.latencies.length ? `   command ${api.latencies[api.latencies.length - 1].toFixed(0)} ms` : '';
      readout.textContent = `t = ${number(frame.t)} s   real time x${number(frame.rtf, 2)}${frame.paused ? '   PAUSED' : ''}\n` +
        `${laws.length ? lawName : ''}${latency}`;
      errorBox.style.display = frame.error ? 'block' : 'none';
      errorText.textContent = frame.error ? `stopped: ${frame.error}` : '';
      pause.textContent = frame.paused ? 'Resume' : 'Pause';
      if (settled(speedState, frame) && Number.isFinite(frame.speed)) {
        const nearest = SPEEDS.reduce((a, b) => (Math.abs(b - frame.speed) < Math.abs(a - frame.speed) ? b : a));
        speed.value = String(nearest);
      }
      if (law && settled(lawState, frame)) law.value = String(frame.law);
      for (const [name, s] of Object.entries(sliders)) {
        const v = frame.gains && frame.gains[name];
        if (!Number.isFinite(v) || s.held || !settled(s, frame)) continue;
        s.input.value = String(v);
        s.shown.textContent = trimmed(v);
      }
    },
    /// The program has stopped: no control sends anything any more.
    disable() {
      for (const c of side.querySelectorAll('button, select, input')) c.disabled = true;
      errorReset.disabled = true;
    },
  };
}

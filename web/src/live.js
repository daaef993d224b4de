// The opspace live lab page (`PROGRAM ... --live`, docs/live.md). esbuild bundles this file with
// three.js into build/<preset>/web/opspace-live.js, which the program's HTTP server inlines into
// the page it serves at / after a <script id="opspace-live-data" type="application/json"> block:
// the robot's shapes, the control laws, gains, plots and markers. The page then follows the
// simulation through Server-Sent Events (/events, one JSON frame per message, about 60 a
// second) and sends the person's commands (pause, reset, speed, law, gains, pushes with the
// mouse) as JSON to POST /command. The protocol is in docs/live.md ("Protocol").
// This file puts the page together; its parts are in live/: common.js (the test hook
// window.opspaceLive), layout.js, plots.js, commands.js, view.js (with ghost.js), push.js,
// controls.js and stream.js.
import { api } from './live/common.js';
import { commandQueue } from './live/commands.js';
import { wireControls } from './live/controls.js';
import { buildPage } from './live/layout.js';
import { installPush } from './live/push.js';
import { openStream } from './live/stream.js';
import { buildView } from './live/view.js';

function main() {
  const data = JSON.parse(document.getElementById('opspace-live-data').textContent);
  api.data = data;
  const page = buildPage(data);
  const { say, plots } = page;
  const commands = commandQueue((why) => { api.commandErrors.push(why); say(`refused: ${why}`, true); });
  const view = buildView(data, page);
  const push = installPush(view, commands);  // before the view's OrbitControls: see push.js
  view.startOrbit();
  const controls = wireControls(data, page, commands);

  const stream = openStream(commands, plots, () => {
    push.release();
    page.stopped.style.display = 'block';
    page.pushLabel.style.display = 'none';
    controls.disable();
    say('the program has stopped');
  });

  // The loop: the latest frame, drawn once per animation frame.
  let framed = false, lastPlotDraw = 0;
  // Drawing keeps the page's thread at most half busy: where a draw is slow (software WebGL,
  // 25-30 ms), a frame from the program that arrives mid-draw waits for it, which is the
  // command latency the page measures; with a GPU a draw takes a millisecond and nothing is
  // skipped. A scene that did not change is not drawn again.
  let lastDrawEnd = -Infinity, drawCost = 0, changed = true;
  function tick(now) {
    if (stream.fresh && api.lastFrame) {
      stream.fresh = false;
      changed = true;
      view.shown = api.lastFrame;
      view.show(view.shown);
      controls.show(view.shown);
      if (!framed) {
        framed = true;
        view.frameView();
      }
      view.placePushLabel(api.lastFrame);
      if (!api.ready) {
        api.ready = true;
        say('connected');
      }
    }
    if (stream.plotsDirty && now - lastPlotDraw > 50) {  // plots at 20 Hz: the eye does not need more
      stream.plotsDirty = false;
      lastPlotDraw = now;
      plots.draw(api.lastFrame ? api.lastFrame.t : 0);
    }
    stream.count(now);
    if (view.controls.update()) changed = true;
    if (changed && now - lastDrawEnd >= drawCost) {  // idle as long as the last draw took
      const start = performance.now();
      view.render();
      lastDrawEnd = performance.now();
      drawCost = lastDrawEnd - start;
      changed = false;
    }
    if (!api.stopped) view.placePushLabel(api.lastFrame);
    requestAnimationFrame(tick);
  }
  view.render();
  plots.draw(0);
  requestAnimationFrame(tick);

  /// The pixel (CSS, page coordinates) where body i's origin is drawn.
  api.screenOf = (i) => view.bodyOrigin(i);
  /// The body drawn at a pixel (page coordinates): its index, -1 for the base, null for none.
  api.bodyAt = (x, y) => {
    const hit = push.pick({ clientX: x, clientY: y });
    return hit ? hit.body : null;
  };
  api.send = (body) => commands.send(body);
  /// The plots (add, clear, draw): the check feeds them values whose labels are wide.
  api.plots = plots;
  api.render = () => view.render();
}

try {
  main();
} catch (e) {
  console.error(`opspace live: ${e.stack || e}`);
}

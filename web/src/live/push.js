// The live page's pushes: picking a point of the arm with the mouse and dragging it on a spring.
import * as THREE from 'three';
import { api } from './common.js';

/// Adds the push's listeners to `view.canvas`. Call it before view.startOrbit(): this
/// pointerdown listener then runs before OrbitControls' own, and can turn them off before they
/// start turning the view. Returns pick(event) and release() (which ends a drag, if any).
export function installPush(view, commands) {
  const { canvas, camera, robot } = view;
  const raycaster = new THREE.Raycaster();
  let drag = null;  // { body, local: the point in the body's frame, plane, target, pointerId }
  function ray(event) {
    const r = canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    return raycaster;
  }
  function bodyOf(object) {
    for (let o = object; o; o = o.parent) {
      const i = robot.bodies.indexOf(o);
      if (i >= 0) return i;
    }
    return -1;
  }
  function pick(event) {
    const hits = ray(event).intersectObject(robot.root, true);  // the base hides what is behind it
    return hits.length ? { body: bodyOf(hits[0].object), point: hits[0].point } : null;
  }
  function sendPush() {
    if (!drag) return;
    commands.send({ command: 'push', body: drag.body, point: drag.local, target: drag.target.toArray() }, { key: 'push' });
  }
  canvas.addEventListener('pointerdown', (event) => {
    if (event.button !== 0 || drag || !view.shown || api.stopped) return;
    const hit = pick(event);
    if (!hit || hit.body < 0) return;
    // The body's pose as drawn, which the hit point is on (the last frame received may be newer).
    const p = view.shown.poses, o = 7 * hit.body;
    const turn = new THREE.Quaternion(p[o + 3], p[o + 4], p[o + 5], p[o + 6]).invert();
    const local = hit.point.clone().sub(new THREE.Vector3(p[o], p[o + 1], p[o + 2])).applyQuaternion(turn);
    const normal = camera.getWorldDirection(new THREE.Vector3());
    drag = {
      body: hit.body, local: local.toArray(), plane: new THREE.Plane().setFromNormalAndCoplanarPoint(normal, hit.point),
      target: hit.point.clone(), pointerId: event.pointerId,
    };
    view.controls.enabled = false;
    canvas.setPointerCapture(event.pointerId);
    canvas.style.cursor = 'grabbing';
    sendPush();
    event.preventDefault();
  });
  canvas.addEventListener('pointermove', (event) => {
    if (!drag) {
      if (event.buttons === 0 && view.shown) {
        const hit = pick(event);
        canvas.style.cursor = hit && hit.body >= 0 ? 'grab' : '';
      }
      return;
    }
    if (event.pointerId !== drag.pointerId) return;
    if (ray(event).ray.intersectPlane(drag.plane, drag.target)) sendPush();
  });
  function release(event) {
    if (!drag || (event && event.pointerId !== drag.pointerId)) return;
    drag = null;
    view.controls.enabled = true;
    canvas.style.cursor = '';
    commands.drop('push');
    commands.send({ command: 'release' });
  }
  for (const type of ['pointerup', 'pointercancel', 'lostpointercapture']) canvas.addEventListener(type, release);
  window.addEventListener('blur', () => release());
  return { pick, release };
}

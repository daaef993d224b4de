// The live page's 3D view: the arm, its markers, the push's spring and force label, the camera.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { baseScene, buildRobot, el, setPose } from '../scene.js';
import { SIDE } from './common.js';
import { buildGhost } from './ghost.js';

/// The view in `page.stage`. Its `controls` (OrbitControls) come with startOrbit(), once the
/// push's listeners are on the canvas; `shown` is the frame drawn (set by the page's loop).
export function buildView(data, page) {
  const { stage, hud, pushLabel } = page;
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch (e) {
    stage.append(el('p', { id: 'no-webgl' }, 'This browser could not create a WebGL context: the arm cannot be drawn (the plots and controls still work).'));
    console.warn(`opspace live: WebGL unavailable: ${e.message}`);
  }
  const scene = baseScene();
  const robot = buildRobot(data, 1);
  scene.add(robot.root);
  const markers = {};
  for (const m of data.markers || []) {
    const mesh = new THREE.Mesh(new THREE.SphereGeometry(m.radius || 0.02, 20, 14),
      new THREE.MeshBasicMaterial({ color: new THREE.Color(m.color), transparent: true, opacity: 0.8 }));
    mesh.visible = false;
    scene.add(mesh);
    markers[m.name] = mesh;
  }
  const ghost = buildGhost(data, scene);
  // The push: a spring from the pulled point to the mouse's point, and a ball at the mouse.
  const springGeometry = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]);
  const spring = new THREE.Line(springGeometry, new THREE.LineBasicMaterial({ color: 0xd35400 }));
  const handle = new THREE.Mesh(new THREE.SphereGeometry(0.012, 16, 10), new THREE.MeshBasicMaterial({ color: 0xd35400 }));
  spring.visible = handle.visible = false;
  scene.add(spring, handle);

  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  const view = new THREE.Vector3(...(data.view || [1, -1, 0.7])).normalize();
  camera.position.copy(view).multiplyScalar(3);
  const canvas = renderer ? renderer.domElement : el('canvas');
  if (renderer) {
    renderer.setPixelRatio(window.devicePixelRatio);
    stage.append(canvas);
  }

  // As the replay page: the scene is framed in the larger free area beside or below the panel.
  function freeArea(w, h) {
    const right = hud.offsetLeft + hud.offsetWidth + 8, bottom = hud.offsetTop + hud.offsetHeight + 8;
    const beside = { x: right, y: 0, w: Math.max(1, w - right), h };
    const below = { x: 0, y: bottom, w, h: Math.max(1, h - bottom) };
    const size = (a) => Math.min(a.w, a.h);
    return size(beside) >= size(below) ? beside : below;
  }
  const stageSize = () => [stage.clientWidth || window.innerWidth - SIDE, stage.clientHeight || window.innerHeight];
  function resize() {
    const [w, h] = stageSize();
    if (renderer) renderer.setSize(w, h, false);
    camera.aspect = w / h;
    const area = freeArea(w, h);
    camera.setViewOffset(w, h, w / 2 - (area.x + area.w / 2), h / 2 - (area.y + area.h / 2), w, h);
    camera.updateProjectionMatrix();
  }
  /// The pixel (CSS, page coordinates) where a world point is drawn.
  function screenOf(point) {
    const at = point.clone().project(camera);
    const r = canvas.getBoundingClientRect();
    return { x: r.left + ((at.x + 1) / 2) * r.width, y: r.top + ((1 - at.y) / 2) * r.height };
  }

  const it = {
    canvas, camera, robot, controls: null, shown: null,
    startOrbit() {
      it.controls = new OrbitControls(camera, canvas);
      window.addEventListener('resize', resize);
      resize();
      it.controls.update();
    },
    /// Frames the arm as it stands at the first frame, with room for it to move: the box around
    /// its shapes, its markers and the base, grown by half.
    frameView() {
      robot.root.updateMatrixWorld(true);
      const box = new THREE.Box3().setFromObject(robot.root);
      for (const m of Object.values(markers)) if (m.visible) box.expandByPoint(m.position);
      box.expandByPoint(new THREE.Vector3(0, 0, 0));
      const center = box.getCenter(new THREE.Vector3());
      const radius = Math.max(0.3, box.getSize(new THREE.Vector3()).length() / 2) * 1.2;
      const [w, h] = stageSize();
      const area = freeArea(w, h);
      const shrink = Math.max(1, h / 1.45 / Math.min(area.w, area.h));
      camera.position.copy(center).addScaledVector(view, (radius / Math.tan((20 * Math.PI) / 180)) * 1.45 * shrink);
      it.controls.target.copy(center);
      it.controls.update();
    },
    /// A frame's poses, markers and push.
    show(frame) {
      const p = frame.poses;
      if (p && p.length >= 7 * data.bodies) for (let i = 0; i < data.bodies; ++i) setPose(robot.bodies[i], p, 7 * i);
      for (const [name, mesh] of Object.entries(markers)) {
        const at = frame.markers && frame.markers[name];
        mesh.visible = Array.isArray(at) && at.length === 3;
        if (mesh.visible) mesh.position.set(at[0], at[1], at[2]);
      }
      if (ghost) ghost.show(frame);
      const push = frame.push;
      spring.visible = handle.visible = !!push;
      if (push) {
        springGeometry.attributes.position.setXYZ(0, ...push.point);
        springGeometry.attributes.position.setXYZ(1, ...push.target);
        springGeometry.attributes.position.needsUpdate = true;
        springGeometry.computeBoundingSphere();
        handle.position.set(...push.target);
      }
    },
    /// The force label at the mouse's point of `frame`'s push, hidden when there is none.
    placePushLabel(frame) {
      const push = frame && frame.push;
      if (!push) { pushLabel.style.display = 'none'; return; }
      const at = screenOf(new THREE.Vector3(...push.target));
      const f = push.force || [0, 0, 0];
      pushLabel.textContent = `${Math.hypot(f[0], f[1], f[2]).toFixed(1)} N`;
      pushLabel.style.left = `${at.x}px`;
      pushLabel.style.top = `${at.y}px`;
      pushLabel.style.display = 'block';
    },
    /// The pixel (CSS, page coordinates) where body i's origin is drawn.
    bodyOrigin(i) {
      const p = it.shown.poses;
      return screenOf(new THREE.Vector3(p[7 * i], p[7 * i + 1], p[7 * i + 2]));
    },
    render() {
      if (renderer) renderer.render(scene, camera);
    },
  };
  return it;
}

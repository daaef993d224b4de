// The live page's ghost (docs/live.md, "The ghost"): a reference's tip path for the law in force,
// unpushed from t = 0, drawn as a faint line, and a faint ball where that run's tip is at the
// frame's time (hidden past the path's end, which the legend then says). data.ghost: {label,
// color, step, paths: one [x, y, z, ...] per law}.
import * as THREE from 'three';
import { api } from './common.js';

/// The ghost's objects, added to `scene`, or null when the page has no ghost.
export function buildGhost(data, scene) {
  const ghost = data.ghost;
  if (!ghost || !Array.isArray(ghost.paths) || !ghost.paths.length || !(ghost.step > 0)) return null;
  const color = new THREE.Color(ghost.color || '#8e44ad');
  const lines = ghost.paths.map((xyz) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(xyz, 3));
    const line = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color, transparent: true, opacity: 0.5 }));
    line.visible = false;
    scene.add(line);
    return line;
  });
  // Larger than the target's sphere (0.02 m): a halo around it when the reference holds its tip.
  const ball = new THREE.Mesh(new THREE.SphereGeometry(0.024, 16, 10),
    new THREE.MeshBasicMaterial({ color, transparent: true, opacity: 0.45, depthWrite: false }));
  ball.visible = false;
  scene.add(ball);
  api.ghost = { law: -1, visible: false, position: null };
  // Past the reference's run (its last point), the legend says so: a reset compares from t = 0.
  const when = document.getElementById('ghost-when');

  /// The path of law `law` at time t: linear between its points, null past its ends.
  function at(law, t) {
    const xyz = ghost.paths[law], n = xyz ? xyz.length / 3 : 0, s = t / ghost.step;
    if (n < 2 || !(s >= 0) || s > n - 1) return null;
    const k = Math.min(Math.floor(s), n - 2), w = s - k;
    return [0, 1, 2].map((i) => xyz[3 * k + i] + w * (xyz[3 * k + 3 + i] - xyz[3 * k + i]));
  }
  return {
    /// Shows the path of `frame`'s law and the ball at its time.
    show(frame) {
      lines.forEach((line, i) => { line.visible = i === frame.law; });
      const p = at(frame.law, frame.t);
      ball.visible = p !== null;
      if (p) ball.position.set(p[0], p[1], p[2]);
      const end = ((ghost.paths[frame.law] || []).length / 3 - 1) * ghost.step;
      if (when) when.textContent = p || !(end > 0) ? '' : ` (its run ended at ${end.toFixed(0)} s: Reset to compare from t = 0)`;
      api.ghost = { law: frame.law, t: frame.t, visible: ball.visible, position: p };
    },
  };
}

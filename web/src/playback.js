// Playback of a recording: play, pause, scrub, speed; the robot at each frame with its CoM,
// ZMP and ground forces.
import * as THREE from 'three';
import { getRecording } from './api.js';

const $ = (id) => document.getElementById(id);

function marker(colour, radius) {
  const m = new THREE.Mesh(new THREE.SphereGeometry(radius, 16, 12),
    new THREE.MeshBasicMaterial({ color: colour, depthTest: false }));
  m.renderOrder = 11;
  return m;
}

export function createPlayback(view, robot, names, onFrame) {
  const markers = new THREE.Group();
  const com = marker(0xd01010, 0.025);
  const comGround = marker(0xd01010, 0.012);
  const zmp = marker(0x1040d0, 0.02);
  markers.add(com, comGround, zmp);
  view.scene.add(markers);
  const arrows = [];
  const state = { rec: null, frame: 0, playing: false, t: 0, last: null, base: null };

  // Moves the camera with the robot's base (horizontally), so a walk stays in view.
  function follow() {
    const base = robot.bodies[0].position.clone().setZ(0);
    if (state.base && $('follow').checked) {
      const delta = base.clone().sub(state.base);
      view.camera.position.add(delta);
      view.controls.target.add(delta);
    }
    state.base = base;
  }

  function frameAt(t) {
    const time = state.rec.time;
    let lo = 0;
    let hi = time.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (time[mid] <= t) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  function show(k) {
    const rec = state.rec;
    state.frame = k;
    robot.setPoses(rec.poses[k]);
    follow();
    $('scrub').value = String(k);
    $('time').textContent = `t = ${rec.time[k].toFixed(3)} s (frame ${k} of ${rec.time.length})`;
    document.body.dataset.frame = String(k);
    com.visible = comGround.visible = !!rec.com;
    if (rec.com) {
      com.position.set(...rec.com[k]);
      comGround.position.set(rec.com[k][0], rec.com[k][1], 0.002);
    }
    zmp.visible = !!rec.zmp;
    if (rec.zmp) zmp.position.set(rec.zmp[k][0], rec.zmp[k][1], 0.003);
    rec.forces.forEach((f, i) => {
      const v = new THREE.Vector3(...f.force[k]);
      const len = v.length() / 1000; // 1 m per kN
      arrows[i].visible = len > 1e-4;
      if (len > 1e-4) {
        arrows[i].position.set(...f.origin[k]);
        arrows[i].setDirection(v.normalize());
        arrows[i].setLength(len, Math.min(0.08, len * 0.3), 0.03);
      }
    });
    onFrame(k);
  }

  async function load(name) {
    state.rec = await getRecording(name);
    arrows.forEach((a) => a.removeFromParent());
    arrows.length = 0;
    state.rec.forces.forEach(() => {
      const a = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 0.1, 0x10a040);
      markers.add(a);
      arrows.push(a);
    });
    $('scrub').max = String(state.rec.time.length - 1);
    state.t = state.rec.time[0];
    show(0);
  }

  $('playback').hidden = false;
  const select = $('recording-name');
  names.forEach((n) => select.add(new Option(n, n)));
  select.onchange = () => load(select.value);
  $('scrub').oninput = (e) => {
    const k = Number(e.target.value);
    state.t = state.rec.time[k];
    show(k);
  };
  $('play').onclick = () => {
    state.playing = !state.playing;
    state.last = null;
    $('play').textContent = state.playing ? 'pause' : 'play';
  };
  $('show-markers').onchange = (e) => { markers.visible = e.target.checked; };
  view.onFrame((now) => {
    if (!state.playing || !state.rec) return;
    if (state.last !== null) {
      const time = state.rec.time;
      state.t += ((now - state.last) / 1000) * Number($('speed').value);
      if (state.t > time[time.length - 1]) state.t = time[0];
      const k = frameAt(state.t);
      if (k !== state.frame) show(k);
    }
    state.last = now;
  });
  return {
    load: () => load(names[0]),
    frame: () => (state.rec ? state.frame : null),
    name: () => select.value,
    seekTime(t) { if (state.rec) { state.t = t; show(frameAt(t)); } },
    recording: () => state.rec,
    show,
  };
}

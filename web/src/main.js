// The page of `biped view`: the robot, its SSV model and a recording in one viewport, the
// playback and the modelling tool in the side panel.
import { getJson, getText } from './api.js';
import { createViewport } from './viewport.js';
import { createRobot } from './robot.js';
import { createSsvLayer } from './ssv.js';
import { createPlayback } from './playback.js';
import { createEditor } from './editor.js';
import { createPlot } from './plot.js';
import * as THREE from 'three';

const $ = (id) => document.getElementById(id);

function listPairs(pairs, dA) {
  $('d-a').textContent = `(d_a = ${dA} m)`;
  const shown = pairs.filter((p) => p.distance !== null).sort((a, b) => a.distance - b.distance).slice(0, 8);
  $('pairs').replaceChildren(...shown.map((p) => {
    const li = document.createElement('li');
    li.textContent = `${p.a} – ${p.b}: ${(p.distance * 1000).toFixed(1)} mm`;
    li.style.color = p.distance <= 0 ? '#c00' : p.distance < dA ? '#c60' : '#282';
    return li;
  }));
}

async function main() {
  const scene = await getJson('/api/scene');
  $('robot-label').textContent = scene.robot;
  scene.warnings.forEach((w) => console.warn(w));
  const view = createViewport($('viewport'));
  const robot = createRobot(view.scene, scene);
  robot.setPoses(scene.neutral);
  view.frame(new THREE.Box3().setFromObject(robot.root));
  $('reset-view').onclick = () => view.frame(new THREE.Box3().setFromObject(robot.root));
  $('show-robot').onchange = (e) => { robot.root.visible = e.target.checked; };
  const layer = scene.ssv ? createSsvLayer(view.scene, robot) : null;
  if (layer) robot.setOpacity(0.45);
  const showPairs = (pairs, dA) => {
    layer.showPairs(pairs, dA);
    listPairs(pairs, dA);
  };

  let editor = null;
  // The query naming the shown frame of the recording ('' for the neutral pose).
  const at = () => {
    const k = playback ? playback.frame() : null;
    return k === null ? '' : `?frame=${k}&recording=${encodeURIComponent(playback.name())}`;
  };
  let playback = null;
  let plot = null;
  let asking = false;
  let again = false;
  // The pair distances of the shown frame, asked one at a time (the latest frame wins).
  async function distances() {
    if (!layer) return;
    if (asking) { again = true; return; }
    asking = true;
    try {
      const d = await getJson(`/api/distances${at()}`);
      showPairs(d.pairs, d.activation_distance);
    } finally {
      asking = false;
      if (again) { again = false; distances(); }
    }
  }
  if (scene.recordings.length > 0) {
    playback = createPlayback(view, robot, scene.recordings, () => {
      if (editor) editor.refresh();
      if (plot) plot.draw();
      distances();
    });
    await playback.load();
    plot = createPlot(playback);
    await plot.init();
  }
  if (scene.ssv) {
    const text = await getText('/api/ssv');
    editor = createEditor(view, layer, scene.ssv, text, at, showPairs);
    $('show-ssv').onchange = (e) => layer.setVisible(e.target.checked);
    await distances();
  }
  window.bipedView = { scene, view, robot, playback, editor, plot };
  document.body.dataset.ready = '1';
}

main().catch((e) => {
  console.error(e);
  document.body.dataset.ready = 'error';
  $('panel').prepend(Object.assign(document.createElement('pre'), { id: 'fatal', textContent: String(e) }));
});

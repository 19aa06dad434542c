// The SSV modelling tool: select a segment, edit its entries through numeric fields and
// handles in the viewport (TransformControls), create / copy / delete / mirror entries;
// every edit is checked by the server (same loader as `biped ssv model`), which answers the
// expanded model and the pair distances; save writes the file.
import * as THREE from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import { checkSsv, putSsv } from './api.js';
import { kindOf, mirrored, pairsText, splice, vertices } from './format.js';

const $ = (id) => document.getElementById(id);
const TEMPLATES = {
  point: { point: [0, 0, 0], radius: 0.03 },
  line: { line: [[0, 0, 0], [0, 0, -0.1]], radius: 0.03 },
  triangle: { triangle: [[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0]], radius: 0.02 },
};

export function createEditor(view, layer, model, text, at, showPairs) {
  const s = { model, text, pending: text, segment: null, entries: null, entry: 0, vertex: 0,
    mode: 'vertex', seq: 0, busy: false };
  const handle = new THREE.Mesh(new THREE.SphereGeometry(0.012, 12, 8),
    new THREE.MeshBasicMaterial({ color: 0xff6600, depthTest: false }));
  handle.renderOrder = 12;
  view.scene.add(handle);
  const gizmo = new TransformControls(view.camera, view.renderer.domElement);
  gizmo.setSize(0.7);
  view.scene.add(gizmo.getHelper());
  gizmo.addEventListener('dragging-changed', (e) => {
    view.controls.enabled = !e.value;
    if (!e.value) fromHandle(true);
  });
  gizmo.addEventListener('objectChange', () => fromHandle(false));

  const segment = () => s.model.segments.find((g) => g.name === s.segment);
  const editable = () => segment() && segment().source.kind === 'ssvs';

  function error(msg) {
    $('error').hidden = !msg;
    $('error').textContent = msg || '';
  }

  function redraw() {
    layer.show(s.model, s.segment);
    placeHandle();
  }

  // Checks the candidate text; a stale answer (an edit came after it) is dropped.
  async function check(candidate) {
    s.pending = candidate === undefined ? splice(s.text, segment().source.span, s.entries) : candidate;
    const seq = ++s.seq;
    s.busy = true;
    $('status').textContent = 'checking…';
    try {
      const answer = await checkSsv(s.pending, at());
      if (seq !== s.seq) return;
      s.model = answer.ssv;
      s.text = s.pending;
      error(null);
      $('status').textContent = 'unsaved changes';
      document.body.dataset.dirty = '1';
      redraw();
      renderPairs();
      showPairs(answer.pairs, s.model.activation_distance);
    } catch (e) {
      if (seq !== s.seq) return;
      error(e.message);
      $('status').textContent = 'not valid';
    } finally {
      if (seq === s.seq) s.busy = false;
    }
  }

  async function save() {
    try {
      const answer = await putSsv(s.pending);
      s.model = answer.ssv;
      s.text = s.pending;
      error(null);
      $('status').textContent = 'saved';
      document.body.dataset.dirty = '0';
      document.body.dataset.saved = String(Number(document.body.dataset.saved || 0) + 1);
      redraw();
      renderPairs();
    } catch (e) {
      error(e.message);
      $('status').textContent = 'not saved';
    }
  }

  function frameGroup() {
    const g = segment();
    return g ? layer.frames()[g.body] : null;
  }

  // The handle at the selected vertex (or, for the radius, one radius along the body x axis).
  function placeHandle() {
    const frame = frameGroup();
    const e = editable() && s.entries[s.entry];
    if (!frame || !e) {
      gizmo.detach();
      handle.visible = false;
      return;
    }
    frame.updateMatrixWorld(true);
    const v = vertices(e)[Math.min(s.vertex, vertices(e).length - 1)];
    const local = new THREE.Vector3(...v);
    if (s.mode === 'radius') local.x += e.radius;
    handle.position.copy(frame.localToWorld(local));
    handle.visible = true;
    gizmo.attach(handle);
    gizmo.showY = gizmo.showZ = s.mode !== 'radius';
  }

  function fromHandle(final) {
    const frame = frameGroup();
    const e = editable() && s.entries[s.entry];
    if (!frame || !e) return;
    const local = frame.worldToLocal(handle.position.clone());
    const round = (x) => Math.round(x * 1e4) / 1e4;
    const vs = vertices(e);
    const k = Math.min(s.vertex, vs.length - 1);
    if (s.mode === 'radius') {
      e.radius = round(Math.max(0, local.x - vs[k][0]));
    } else {
      vs[k][0] = round(local.x);
      vs[k][1] = round(local.y);
      vs[k][2] = round(local.z);
    }
    renderEntries();
    if (final || !s.busy) check();
  }

  function field(value, set) {
    const input = document.createElement('input');
    input.type = 'number';
    input.step = '0.005';
    input.value = String(value);
    input.onchange = () => {
      set(input.value === '' ? NaN : Number(input.value));
      check();
    };
    return input;
  }

  function renderEntries() {
    const box = $('entries');
    box.replaceChildren();
    if (!editable()) return;
    s.entries.forEach((e, i) => {
      const div = document.createElement('div');
      div.className = `entry${i === s.entry ? ' selected' : ''}`;
      div.dataset.index = String(i);
      div.onclick = () => { if (s.entry !== i) { s.entry = i; s.vertex = 0; renderEntries(); placeHandle(); } };
      const title = document.createElement('div');
      title.textContent = `${i}: ${kindOf(e)}${e.mirror_copy ? ` (+ copy mirrored about ${e.mirror_copy})` : ''}`;
      div.append(title);
      vertices(e).forEach((v, j) => {
        const row = document.createElement('div');
        const label = document.createElement('span');
        label.className = `vertex${i === s.entry && j === s.vertex ? ' active' : ''}`;
        label.textContent = `v${j} `;
        label.onclick = () => { s.entry = i; s.vertex = j; renderEntries(); placeHandle(); };
        row.append(label, ...v.map((x, a) => field(x, (y) => { v[a] = y; })));
        div.append(row);
      });
      const r = document.createElement('div');
      r.append('radius ', field(e.radius, (y) => { e.radius = y; }));
      r.querySelector('input').className = 'radius';
      div.append(r);
      box.append(div);
    });
  }

  // The selected segment's pairs from the file's `pairs = [...]` array: remove one, add one.
  function renderPairs() {
    const box = $('segment-pairs');
    box.replaceChildren();
    const list = s.model.pair_list;
    if (!s.segment) return;
    if (!list) {
      box.textContent = 'pairs: written as [[pair]] tables, edit them in the file';
      return;
    }
    const edit = (pairs) => check(s.text.slice(0, list.span[0]) + pairsText(pairs) + s.text.slice(list.span[1]));
    box.append('pairs: ');
    list.pairs.forEach(([a, b], i) => {
      if (a !== s.segment && b !== s.segment) return;
      const x = document.createElement('button');
      x.className = 'pair';
      x.title = 'remove this pair';
      x.textContent = `${a === s.segment ? b : a} ×`;
      x.onclick = () => edit(list.pairs.filter((_, j) => j !== i));
      box.append(x);
    });
    const other = document.createElement('select');
    other.id = 'pair-with';
    s.model.segments.filter((g) => g.name !== s.segment).forEach((g) => other.add(new Option(g.name, g.name)));
    const add = document.createElement('button');
    add.textContent = 'add pair';
    add.onclick = () => edit([...list.pairs, [s.segment, other.value]]);
    box.append(' with ', other, add);
  }

  function select(name) {
    s.segment = name;
    const g = segment();
    s.entries = g && g.source.kind === 'ssvs' ? structuredClone(g.source.entries) : null;
    s.entry = 0;
    s.vertex = 0;
    const info = !g ? '' : g.source.kind === 'ssvs' ? `on body ${s.model.bodies[g.body].name}, ${g.ssvs.length} SSVs`
      : `${g.source.kind.replace('_', ' ')} ${g.source.of}: edit that segment`;
    $('segment-info').textContent = info;
    renderEntries();
    renderPairs();
    redraw();
  }

  function edit(change) {
    if (!editable()) return;
    change();
    s.entry = Math.max(0, Math.min(s.entry, s.entries.length - 1));
    renderEntries();
    check();
  }

  $('model').hidden = false;
  $('ssv-file').textContent = model.file;
  const list = $('segment');
  model.segments.forEach((g) => list.add(new Option(g.name, g.name)));
  list.onchange = () => select(list.value);
  document.querySelectorAll('[data-add]').forEach((b) => {
    b.onclick = () => edit(() => { s.entries.push(structuredClone(TEMPLATES[b.dataset.add])); s.entry = s.entries.length - 1; });
  });
  $('copy-entry').onclick = () => edit(() => { s.entries.splice(s.entry + 1, 0, structuredClone(s.entries[s.entry])); s.entry += 1; });
  $('delete-entry').onclick = () => edit(() => { s.entries.splice(s.entry, 1); });
  document.querySelectorAll('[data-mirror]').forEach((b) => {
    b.onclick = () => edit(() => {
      const m = mirrored(s.entries[s.entry], b.dataset.mirror);
      if ($('mirror-copy').checked) s.entries.splice(s.entry + 1, 0, m);
      else s.entries[s.entry] = m;
    });
  });
  document.querySelectorAll('input[name=handle]').forEach((r) => {
    r.onchange = () => { s.mode = r.value; placeHandle(); };
  });
  $('save').onclick = save;
  list.value = model.segments[0]?.name;
  select(list.value);
  return {
    state: s,
    select: (name) => { list.value = name; select(name); },
    refresh: placeHandle,
    // Screen position of the handle (page pixels), for tests and tutorials.
    handleScreen() {
      const p = handle.position.clone().project(view.camera);
      const rect = view.renderer.domElement.getBoundingClientRect();
      return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
    },
  };
}

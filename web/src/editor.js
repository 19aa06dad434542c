// The SSV modelling tool: select a segment, edit its entries through numeric fields and
// handles in the viewport (TransformControls), create / copy / delete / mirror entries;
// every edit is checked by the server (same loader as `biped ssv model`), which answers the
// expanded model and the pair distances; save writes the file.
import { checkSsv, putSsv } from './api.js';
import { addPairTable, cut, detached, mirrored, pairsText, splice, vertices } from './format.js';
import { createHandle } from './handle.js';
import { renderEntries as renderEntriesInto, renderKeep, renderPairs as renderPairsInto } from './panels.js';

const $ = (id) => document.getElementById(id);
const TEMPLATES = {
  point: { point: [0, 0, 0], radius: 0.03 },
  line: { line: [[0, 0, 0], [0, 0, -0.1]], radius: 0.03 },
  triangle: { triangle: [[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0]], radius: 0.02 },
};

export function createEditor(view, layer, model, text, at, showPairs) {
  const s = { model, text, pending: text, segment: null, entries: null, entry: 0, vertex: 0,
    mode: 'vertex', seq: 0, busy: false };
  const handle = createHandle(view, (final) => fromHandle(final));

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
    s.pending = candidate === undefined ? splice(s.text, segment().source, s.entries) : candidate;
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
    const e = editable() && s.entries && s.entries[s.entry];
    if (!frame || !e) {
      handle.hide();
      return;
    }
    const vs = vertices(e);
    handle.place(frame, vs[Math.min(s.vertex, vs.length - 1)], e.radius, s.mode === 'radius');
  }

  function fromHandle(final) {
    const frame = frameGroup();
    const e = editable() && s.entries && s.entries[s.entry];
    if (!frame || !e) return;
    const local = handle.local(frame);
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

  function pick(i, j) {
    s.entry = i;
    s.vertex = j;
    renderEntries();
    placeHandle();
  }

  function renderEntries() {
    renderEntriesInto($('entries'), editable() ? s : { entries: null }, pick, () => check());
  }

  function renderVersion() {
    const g = segment();
    renderKeep($('keep'), s.model, g, (keep) =>
      check(s.text.slice(0, g.source.span[0]) + `[${keep.join(', ')}]` + s.text.slice(g.source.span[1])));
  }

  // The new text of a pair edit of the panel: the array's new pairs, a table cut or added.
  function pairEdit({ list, cut: span, add }) {
    const array = s.model.pair_list;
    if (list) return s.text.slice(0, array.span[0]) + pairsText(list) + s.text.slice(array.span[1]);
    if (span) return cut(s.text, span);
    return addPairTable(s.text, s.model.pair_tables, ...add);
  }

  function renderPairs() {
    renderVersion();
    renderDetach();
    renderPairsInto($('segment-pairs'), s.model, s.segment, (change) => check(pairEdit(change)));
  }

  // A mirrored segment can be detached: made explicit with its current (mirrored) SSVs.
  function renderDetach() {
    const g = segment();
    $('detach-row').hidden = !g || g.source.kind !== 'mirror_of' || !g.source.lines;
  }

  async function detach() {
    const g = segment();
    if (!g || g.source.kind !== 'mirror_of' || !g.source.lines) return;
    await check(detached(s.text, g.source.lines, g.ssvs));
    if (segment().source.kind === 'ssvs') select(g.name);
  }

  function select(name) {
    s.segment = name;
    const g = segment();
    s.entries = g && g.source.kind === 'ssvs' ? structuredClone(g.source.entries) : null;
    s.entry = 0;
    s.vertex = 0;
    const info = !g ? '' : g.source.kind === 'ssvs' ? `on body ${s.model.bodies[g.body].name}, ${g.ssvs.length} SSVs`
      : g.source.kind === 'version_of' ? `version of ${g.source.of}: the SSVs it keeps below`
        : `mirror of ${g.source.of}: edit that segment${g.source.lines ? ', or detach this one' : ''}`;
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
  $('detach').onclick = detach;
  $('read-only').hidden = !model.read_only;
  $('read-only').textContent = model.read_only ? 'the robot description\'s model: edits are checked, not saved (--ssv FILE edits a file)' : '';
  list.value = model.segments[0]?.name;
  select(list.value);
  return {
    state: s,
    select: (name) => { list.value = name; select(name); },
    refresh: placeHandle,
    // Screen position of the handle (page pixels), for tests and tutorials.
    // `offset` (metres, world axes) moves the point from the handle.
    handleScreen(offset = [0, 0, 0]) {
      const p = handle.marker.position.clone().add(new handle.marker.position.constructor(...offset))
        .project(view.camera);
      const rect = view.renderer.domElement.getBoundingClientRect();
      return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
    },
  };
}

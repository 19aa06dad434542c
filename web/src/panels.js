// The editor's side-panel lists: the selected segment's entries with numeric fields, and
// its pairs from the file's `pairs = [...]` array.
import { kindOf, vertices } from './format.js';

function field(value, set) {
  const input = document.createElement('input');
  input.type = 'number';
  input.step = '0.005';
  input.value = String(value);
  input.onchange = () => set(input.value === '' ? NaN : Number(input.value));
  return input;
}

function vertexRow(v, label, active, pick, changed) {
  const row = document.createElement('div');
  const name = document.createElement('span');
  name.className = `vertex${active ? ' active' : ''}`;
  name.textContent = `${label} `;
  name.onclick = pick;
  row.append(name, ...v.map((x, a) => field(x, (y) => { v[a] = y; changed(); })));
  return row;
}

// One box per entry of `s.entries`; `pick(i, j)` selects entry i's vertex j, `changed()`
// follows a typed value.
export function renderEntries(box, s, pick, changed) {
  box.replaceChildren();
  if (!s.entries) return;
  s.entries.forEach((e, i) => {
    const div = document.createElement('div');
    div.className = `entry${i === s.entry ? ' selected' : ''}`;
    div.dataset.index = String(i);
    div.onclick = () => { if (s.entry !== i) pick(i, 0); };
    const title = document.createElement('div');
    title.textContent = `${i}: ${kindOf(e)}${e.mirror_copy ? ` (+ copy mirrored about ${e.mirror_copy})` : ''}`;
    div.append(title);
    vertices(e).forEach((v, j) => {
      div.append(vertexRow(v, `v${j}`, i === s.entry && j === s.vertex, () => pick(i, j), changed));
    });
    const r = document.createElement('div');
    const radius = field(e.radius, (y) => { e.radius = y; changed(); });
    radius.className = 'radius';
    r.append('radius ', radius);
    div.append(r);
    box.append(div);
  });
}

// The pairs of segment `name` with remove buttons, and a choice to add one, from the file's
// `pairs = [...]` array and its `[[pair]]` tables. `edit` receives `{ list }` (the array's new
// pairs), `{ cut }` (the span of a table to remove) or `{ add: [a, b] }` (a new table).
export function renderPairs(box, model, name, edit) {
  box.replaceChildren();
  const list = model.pair_list;
  const tables = model.pair_tables;
  if (!name) return;
  if (!tables) {
    box.textContent = 'pairs: written neither as pairs = [...] nor as [[pair]] tables, edit them in the file';
    return;
  }
  box.append('pairs: ');
  const button = ([a, b], remove) => {
    if (a !== name && b !== name) return;
    const x = document.createElement('button');
    x.className = 'pair';
    x.title = 'remove this pair';
    x.textContent = `${a === name ? b : a} ×`;
    x.onclick = remove;
    box.append(x);
  };
  if (list) list.pairs.forEach((p, i) => button(p, () => edit({ list: list.pairs.filter((_, j) => j !== i) })));
  tables.forEach((t) => button([t.a, t.b], () => edit({ cut: t.span })));
  const other = document.createElement('select');
  other.id = 'pair-with';
  model.segments.filter((g) => g.name !== name).forEach((g) => other.add(new Option(g.name, g.name)));
  const add = document.createElement('button');
  add.textContent = 'add pair';
  add.onclick = () => edit(list ? { list: [...list.pairs, [name, other.value]] } : { add: [name, other.value] });
  box.append(' with ', other, add);
}

// A version segment's kept SSVs: one checkbox per SSV of the full segment; `edit(keep)`
// receives the new index list.
export function renderKeep(box, model, g, edit) {
  box.replaceChildren();
  if (!g || g.source.kind !== 'version_of' || !g.source.span) return;
  const full = model.segments.find((f) => f.name === g.source.of);
  if (!full) return;
  box.append(`keeps of ${full.name}: `);
  full.ssvs.forEach((v, i) => {
    const label = document.createElement('label');
    const box1 = document.createElement('input');
    box1.type = 'checkbox';
    box1.dataset.keep = String(i);
    box1.checked = g.source.keep.includes(i);
    box1.onchange = () => {
      const keep = full.ssvs.map((_, j) => j).filter((j) => (j === i ? box1.checked : g.source.keep.includes(j)));
      edit(keep);
    };
    label.append(box1, `${i} ${v.kind} `);
    box.append(label);
  });
}

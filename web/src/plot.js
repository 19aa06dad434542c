// Time plots of chosen signals of the recording, stacked one band per signal (each with its
// own range and colour, named in the legend), with a cursor at the shown frame across all of
// them; clicking a plot seeks there. `#signal` picks the first signal, `#signal-add` adds one.
import { getSignal } from './api.js';

const $ = (id) => document.getElementById(id);
const PREFERRED = ['L_z', 'tau_z', 'ground.tau_n', 'L_G.z', 'com.z', 'zmp.y'];
export const COLOURS = ['#1565c0', '#c62828', '#2e7d32', '#6a1b9a', '#ef6c00', '#00838f'];
const LEFT = 45;
const RIGHT = 5;
const BOTTOM = 14;

// Draws one band: the signal `values` over `time` into rows [top, top + h) of the canvas.
function band(ctx, { values, colour }, x, top, h) {
  const finite = values.filter(Number.isFinite);
  let lo = finite.length ? Math.min(...finite) : 0;
  let hi = finite.length ? Math.max(...finite) : 1;
  if (hi - lo < 1e-12) { lo -= 1; hi += 1; }
  const y = (v) => top + h - 4 - ((v - lo) / (hi - lo)) * (h - 12);
  ctx.fillStyle = '#555';
  ctx.fillText(hi.toPrecision(3), 2, top + 10);
  ctx.fillText(lo.toPrecision(3), 2, top + h - 4);
  ctx.strokeStyle = '#e3e6ea';
  ctx.beginPath();
  ctx.moveTo(LEFT, top + h - 0.5);
  ctx.lineTo(ctx.canvas.width - RIGHT, top + h - 0.5);
  ctx.stroke();
  ctx.strokeStyle = colour;
  ctx.beginPath();
  let pen = false;
  values.forEach((v, i) => {
    if (!Number.isFinite(v)) { pen = false; return; }
    if (pen) ctx.lineTo(x(i), y(v)); else ctx.moveTo(x(i), y(v));
    pen = true;
  });
  ctx.stroke();
}

export function createPlot(playback) {
  const canvas = $('plot');
  const ctx = canvas.getContext('2d');
  // The plotted signals in order: { name, values, colour }.
  const s = { signals: [], time: null };

  function draw() {
    const rec = playback.recording();
    if (s.time && rec && rec.time !== s.time) {
      // Another recording is shown: its columns replace the plotted ones.
      if (!s.reloading) {
        s.reloading = true;
        plot(s.signals.map((g) => g.name)).finally(() => { s.reloading = false; });
      }
      return;
    }
    const n = s.signals.length;
    const h = n <= 1 ? 126 : 72;
    const height = BOTTOM + Math.max(n, 1) * h;
    if (canvas.height !== height) canvas.height = height;
    const w = canvas.width;
    ctx.clearRect(0, 0, w, canvas.height);
    canvas.dataset.signals = s.signals.map((g) => g.name).join(',');
    canvas.dataset.polylines = '0';
    if (!s.time || n === 0) return;
    const t0 = s.time[0];
    const t1 = s.time[s.time.length - 1] || t0 + 1;
    const x = (i) => ((s.time[i] - t0) / (t1 - t0 || 1)) * (w - LEFT - RIGHT) + LEFT;
    ctx.font = '10px sans-serif';
    s.signals.forEach((g, i) => band(ctx, g, x, i * h, h));
    canvas.dataset.polylines = String(n);
    ctx.fillStyle = '#555';
    ctx.fillText(`${t0.toFixed(2)} s`, LEFT, canvas.height - 2);
    ctx.fillText(`${t1.toFixed(2)} s`, w - 45, canvas.height - 2);
    const k = playback.frame();
    if (k !== null) {
      ctx.strokeStyle = '#d00';
      ctx.beginPath();
      ctx.moveTo(x(k), 0);
      ctx.lineTo(x(k), canvas.height - BOTTOM + 2);
      ctx.stroke();
    }
  }

  function legend() {
    const items = s.signals.map((g, i) => {
      const item = document.createElement('span');
      item.className = 'legend';
      item.dataset.signal = g.name;
      item.style.color = g.colour;
      item.textContent = `■ ${g.name}`;
      if (i > 0) {
        const x = document.createElement('button');
        x.title = `remove ${g.name} from the plot`;
        x.textContent = '×';
        x.onclick = () => { s.signals.splice(i, 1); recolour(); };
        item.append(x);
      }
      return item;
    });
    $('plot-legend').replaceChildren(...items);
  }

  function recolour() {
    s.signals.forEach((g, i) => { g.colour = COLOURS[i % COLOURS.length]; });
    legend();
    draw();
  }

  // Plots `names` (fetching the columns not yet loaded) of the shown recording.
  async function plot(names) {
    const rec = playback.recording();
    const known = new Map(s.time === rec.time ? s.signals.map((g) => [g.name, g]) : []);
    const signals = [];
    for (const name of names.filter((c) => rec.columns.includes(c))) {
      signals.push(known.get(name) || { name, values: await getSignal(playback.name(), name) });
    }
    s.signals = signals;
    s.time = rec.time;
    recolour();
  }

  canvas.onclick = (e) => {
    if (!s.time) return;
    const rect = canvas.getBoundingClientRect();
    const px = ((e.clientX - rect.left) / rect.width) * canvas.width;
    const t0 = s.time[0];
    const t1 = s.time[s.time.length - 1];
    playback.seekTime(t0 + ((px - LEFT) / (canvas.width - LEFT - RIGHT)) * (t1 - t0));
  };

  return {
    async init() {
      const rec = playback.recording();
      const columns = rec.columns.filter((c) => c !== 'time' && c !== 't');
      const select = $('signal');
      const more = $('signal-add');
      columns.forEach((c) => { select.add(new Option(c, c)); more.add(new Option(c, c)); });
      select.value = PREFERRED.find((p) => columns.includes(p)) || columns[0];
      select.onchange = () => plot([select.value, ...s.signals.slice(1).map((g) => g.name)
        .filter((n) => n !== select.value)]);
      more.onchange = () => {
        const name = more.value;
        more.value = '';
        if (name && !s.signals.some((g) => g.name === name)) plot([...s.signals.map((g) => g.name), name]);
      };
      $('plot-section').hidden = false;
      await plot([select.value]);
    },
    // The plotted signals' names (for tests and scripts).
    signals: () => s.signals.map((g) => g.name),
    // Reloads the plotted signals after the shown recording changed.
    reload: () => plot(s.signals.map((g) => g.name)),
    draw,
  };
}

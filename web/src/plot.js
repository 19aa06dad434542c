// A time plot of one chosen signal of the recording with a cursor at the shown frame;
// clicking the plot seeks there.
import { getSignal } from './api.js';

const $ = (id) => document.getElementById(id);
const PREFERRED = ['L_z', 'tau_z', 'ground.tau_n', 'L_G.z', 'com.z', 'zmp.y'];

export function createPlot(playback) {
  const canvas = $('plot');
  const ctx = canvas.getContext('2d');
  const s = { values: null, time: null };

  function draw() {
    const { width: w, height: h } = canvas;
    ctx.clearRect(0, 0, w, h);
    if (!s.values || s.values.length === 0) return;
    const finite = s.values.filter(Number.isFinite);
    let lo = Math.min(...finite);
    let hi = Math.max(...finite);
    if (hi - lo < 1e-12) { lo -= 1; hi += 1; }
    const t0 = s.time[0];
    const t1 = s.time[s.time.length - 1] || t0 + 1;
    const x = (t) => ((t - t0) / (t1 - t0 || 1)) * (w - 50) + 45;
    const y = (v) => h - 15 - ((v - lo) / (hi - lo)) * (h - 25);
    ctx.fillStyle = '#555';
    ctx.font = '10px sans-serif';
    ctx.fillText(hi.toPrecision(3), 2, 12);
    ctx.fillText(lo.toPrecision(3), 2, h - 15);
    ctx.fillText(`${t0.toFixed(2)} s`, 45, h - 2);
    ctx.fillText(`${t1.toFixed(2)} s`, w - 45, h - 2);
    ctx.strokeStyle = '#1565c0';
    ctx.beginPath();
    s.values.forEach((v, i) => {
      if (!Number.isFinite(v)) return;
      if (i === 0) ctx.moveTo(x(s.time[i]), y(v)); else ctx.lineTo(x(s.time[i]), y(v));
    });
    ctx.stroke();
    const k = playback.frame();
    if (k !== null) {
      ctx.strokeStyle = '#d00';
      ctx.beginPath();
      ctx.moveTo(x(s.time[k]), 0);
      ctx.lineTo(x(s.time[k]), h - 12);
      ctx.stroke();
    }
    s.x = x;
  }

  async function choose(column) {
    s.values = await getSignal(playback.name(), column);
    s.time = playback.recording().time;
    draw();
  }

  canvas.onclick = (e) => {
    if (!s.time) return;
    const rect = canvas.getBoundingClientRect();
    const px = ((e.clientX - rect.left) / rect.width) * canvas.width;
    const t0 = s.time[0];
    const t1 = s.time[s.time.length - 1];
    playback.seekTime(t0 + ((px - 45) / (canvas.width - 50)) * (t1 - t0));
  };

  return {
    async init() {
      const rec = playback.recording();
      const columns = rec.columns.filter((c) => c !== 'time' && c !== 't');
      const select = $('signal');
      columns.forEach((c) => select.add(new Option(c, c)));
      select.value = PREFERRED.find((p) => columns.includes(p)) || columns[0];
      select.onchange = () => choose(select.value);
      $('plot-section').hidden = false;
      await choose(select.value);
    },
    draw,
  };
}

// What the browser test files share: chromium launched as scripts/test_view.sh expects, the
// console problems of a page, pixel statistics of the viewport, and the neutral pose added to
// a served collision model (so that `biped ssv model` can evaluate the saved file).
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';

const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

// A browser and a page at `url`, ready (the page sets body[data-ready]); console errors and
// page errors not `expected(message)` are pushed to `problems`.
export async function openPage(url, problems, viewport = { width: 1280, height: 800 }, expected = () => false) {
  const browser = await chromium.launch({
    executablePath: CHROMIUM,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  try {
    const page = await browser.newPage({ viewport });
    page.on('console', (m) => { if (m.type() === 'error' && !expected(m)) problems.push(`console: ${m.text()}`); });
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    await page.goto(url);
    await page.waitForFunction(() => document.body.dataset.ready, null, { timeout: 60000 });
    return { browser, page };
  } catch (e) {
    await browser.close();
    throw e;
  }
}

// The viewport's pixels (RGBA), scaled to 320 pixels wide.
export function canvasPixels(page) {
  return page.evaluate(() => {
    const gl = window.bipedView.view.renderer.domElement;
    const c = document.createElement('canvas');
    c.width = 320;
    c.height = Math.round((320 * gl.height) / gl.width);
    const ctx = c.getContext('2d');
    ctx.drawImage(gl, 0, 0, c.width, c.height);
    return Array.from(ctx.getImageData(0, 0, c.width, c.height).data);
  });
}

// The share of pixels that differ between two images of canvasPixels.
export function changedShare(a, b) {
  let changed = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 30) changed += 1;
  }
  return changed / (a.length / 4);
}

// Roll-pitch-yaw (extrinsic x-y-z) of a unit quaternion [x, y, z, w].
function rpy([x, y, z, w]) {
  return [Math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y)),
    Math.asin(Math.max(-1, Math.min(1, 2 * (w * y - z * x)))),
    Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))];
}

// The text of the model served at `url` with a `[pose.neutral]` of the server's neutral pose
// (the Lola model's collision bodies are its body frames), and the scene.
export async function withNeutralPose(url) {
  const scene = await (await fetch(`${url}api/scene`)).json();
  const text = await (await fetch(`${url}api/ssv`)).text();
  if (text.includes('[pose.')) return { scene, text };
  const lines = scene.ssv.bodies.map((b) => {
    assert.deepEqual(b.offset.position, [0, 0, 0]);
    const p = scene.neutral[b.body];
    return `${b.name} = { position = [${p.position.join(', ')}], rpy = [${rpy(p.quaternion).join(', ')}] }`;
  });
  return { scene, text: `${text}\n[pose.neutral]\n${lines.join('\n')}\n` };
}

// Replaces the served model by `text` (it must load).
export async function putModel(url, text) {
  const put = await fetch(`${url}api/ssv`, { method: 'PUT', body: text });
  const answer = await put.text();
  assert.equal(put.status, 200, answer);
  return JSON.parse(answer).ssv;
}

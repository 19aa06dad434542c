// Browser tests of `biped view`: Debian's chromium driven by playwright-core against a
// running server. Set by scripts/test_view.sh: VIEW_URL (the server), VIEW_SSV (the model
// file it edits), BIPED (the CLI binary), OUT (screenshot folder).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { canvasPixels as pixelsOf, changedShare, openPage, putModel, withNeutralPose } from './helpers.js';

const { VIEW_URL, VIEW_SSV, BIPED, OUT } = process.env;
let browser;
let page;
const problems = [];
// Set while a test makes the server refuse an edit: the browser logs that 422 answer.
let refusalExpected = false;

const canvasPixels = () => pixelsOf(page);
function distinctColours(px) {
  const set = new Set();
  for (let i = 0; i < px.length; i += 4) set.add((px[i] << 16) | (px[i + 1] << 8) | px[i + 2]);
  return set.size;
}
const shot = (name) => page.locator('#viewport').screenshot({ path: join(OUT, name) });
const status = () => page.locator('#status').textContent();
const ssvModel = (file) => execFileSync(BIPED, ['ssv', 'model', file], { encoding: 'utf8' });

// `biped ssv model` evaluates a named posture: the file gets the neutral pose the server
// reports, written through the API.
async function addNeutralPose() {
  await putModel(VIEW_URL, (await withNeutralPose(VIEW_URL)).text);
}

before(async () => {
  mkdirSync(OUT, { recursive: true });
  await addNeutralPose();
  // The 422 answer of a refused edit is logged by the browser while a test expects it.
  const refusal = (m) => refusalExpected && /status of 422/.test(m.text()) && m.location().url.includes('/api/ssv');
  ({ browser, page } = await openPage(VIEW_URL, problems, { width: 1280, height: 800 }, refusal));
});

after(async () => {
  if (browser) await browser.close();
});

test('the page loads and the robot renders', async () => {
  assert.equal(await page.evaluate(() => document.body.dataset.ready), '1');
  await page.waitForTimeout(500);
  await shot('robot.png');
  const px = await canvasPixels();
  assert.ok(distinctColours(px) > 50, `the viewport is nearly blank (${distinctColours(px)} colours)`);
  // Without the robot and its SSVs the picture is the ground and the sky only: they are
  // what covers a good share of the viewport.
  await page.locator('#show-robot').uncheck();
  await page.locator('#show-ssv').uncheck();
  await page.waitForTimeout(300);
  const empty = await canvasPixels();
  await page.locator('#show-robot').check();
  await page.locator('#show-ssv').check();
  await page.waitForTimeout(300);
  const share = changedShare(empty, await canvasPixels());
  assert.ok(share > 0.02, `the robot covers only ${(share * 100).toFixed(2)} % of the viewport`);
  const pairs = await page.locator('#pairs li').count();
  assert.ok(pairs > 0, 'closest pairs are listed');
});

test('scrubbing the recording moves the robot', async () => {
  const before = await canvasPixels();
  const last = await page.locator('#scrub').getAttribute('max');
  await page.locator('#scrub').focus();
  await page.keyboard.press('End');
  await page.waitForFunction((k) => document.body.dataset.frame === k, last);
  await page.waitForTimeout(300);
  await shot('scrubbed.png');
  const share = changedShare(before, await canvasPixels());
  assert.ok(share > 0.005, `only ${(share * 100).toFixed(2)} % of the pixels changed`);
  // The whole page mid-step (what the README shows), then back to the start.
  const mid = String(Math.round(Number(last) * 0.45));
  await page.locator('#scrub').fill(mid);
  await page.waitForFunction((k) => document.body.dataset.frame === k, mid);
  await page.waitForTimeout(300);
  await page.screenshot({ path: join(OUT, 'page.png') });
  await page.keyboard.press('Home');
  await page.waitForFunction(() => document.body.dataset.frame === '0');
});

test('a numeric edit is saved and the file loads with biped ssv model', async () => {
  await page.locator('#segment').selectOption('pelvis');
  const radius = page.locator('.entry[data-index="0"] input.radius');
  await radius.fill('0.061');
  await radius.press('Enter');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'unsaved changes')
    .catch(async (e) => { throw new Error(`${e.message}: ${await page.locator('#status').textContent()} ${await page.locator('#error').textContent()} ${await page.evaluate(() => JSON.stringify(window.bipedView.editor.state.entries[0]))}`); });
  await page.locator('#save').click();
  await page.waitForFunction(() => document.body.dataset.saved === '1');
  assert.equal(await status(), 'saved');
  const text = readFileSync(VIEW_SSV, 'utf8');
  assert.match(text, /radius = 0\.061/);
  assert.match(text, /# SSV collision model of the Lola-like biped/, 'comments are kept');
  assert.match(ssvModel(VIEW_SSV), /closest pair: /);
});

test('a handle drag moves the vertex and is saved', async () => {
  const before = await page.evaluate(() => window.bipedView.editor.state.entries[0].triangle[0].slice());
  const at = await page.evaluate(() => window.bipedView.editor.handleScreen());
  await page.mouse.move(at.x, at.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i += 1) await page.mouse.move(at.x + 4 * i, at.y - 3 * i);
  await page.mouse.up();
  await page.waitForFunction(() => document.getElementById('status').textContent === 'unsaved changes')
    .catch(async (e) => { throw new Error(`${e.message}: ${await page.locator('#status').textContent()} ${await page.locator('#error').textContent()} ${await page.evaluate(() => JSON.stringify(window.bipedView.editor.state.entries[0]))}`); });
  const moved = await page.evaluate(() => window.bipedView.editor.state.entries[0].triangle[0].slice());
  assert.notDeepEqual(moved, before, 'the vertex moved');
  await shot('editing.png');
  await page.locator('#save').click();
  await page.waitForFunction(() => document.body.dataset.saved === '2');
  const text = readFileSync(VIEW_SSV, 'utf8');
  const written = `[${moved.map((x) => (Number.isInteger(x) ? x.toFixed(1) : String(x))).join(', ')}]`;
  assert.ok(text.includes(written), `${written} is in the file`);
  assert.match(ssvModel(VIEW_SSV), /closest pair: /);
});

test('the radius handle drags the radius', async () => {
  await page.locator('input[name=handle][value=radius]').check();
  const before = await page.evaluate(() => window.bipedView.editor.state.entries[0].radius);
  // The handle's x arrow on screen: from the marker towards the body's x axis.
  const { from, dir } = await page.evaluate(() => {
    const ed = window.bipedView.editor;
    const a = ed.handleScreen();
    const b = ed.handleScreen([0.05, 0, 0]);
    const n = Math.hypot(b.x - a.x, b.y - a.y);
    return { from: a, dir: { x: (b.x - a.x) / n, y: (b.y - a.y) / n } };
  });
  const grab = { x: from.x + 30 * dir.x, y: from.y + 30 * dir.y };
  await page.mouse.move(grab.x, grab.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i += 1) await page.mouse.move(grab.x + 3 * i * dir.x, grab.y + 3 * i * dir.y);
  await page.mouse.up();
  await page.waitForFunction(() => document.getElementById('status').textContent === 'unsaved changes');
  const after = await page.evaluate(() => window.bipedView.editor.state.entries[0].radius);
  assert.ok(after > before, `radius ${before} -> ${after}`);
  await page.locator('input[name=handle][value=vertex]').check();
  await page.locator('#save').click();
  await page.waitForFunction(() => document.body.dataset.saved === '3');
  assert.match(readFileSync(VIEW_SSV, 'utf8'), new RegExp(`radius = ${String(after).replace('.', '\\.')}`));
});

test('entries are created, copied, mirrored and deleted, a pair added, and saved', async () => {
  const checked = async (action) => {
    const seq = await page.evaluate(() => window.bipedView.editor.state.seq);
    await action();
    await page.waitForFunction((n) => {
      const s = window.bipedView.editor.state;
      return s.seq > n && !s.busy && document.getElementById('status').textContent === 'unsaved changes';
    }, seq);
  };
  const count = () => page.evaluate(() => {
    const s = window.bipedView.editor.state;
    return s.model.segments.find((g) => g.name === 'r_forearm').ssvs.length;
  });
  await page.locator('#segment').selectOption('r_forearm');
  const n = await count();
  await checked(() => page.locator('[data-add="point"]').click());
  assert.equal(await count(), n + 1);
  await page.locator('#mirror-copy').check();
  await checked(() => page.locator('[data-mirror="xz"]').click());
  assert.equal(await count(), n + 2);
  const [point, image] = await page.evaluate(() => window.bipedView.editor.state.entries.slice(-2).map((e) => e.point));
  assert.deepEqual(image, [point[0], -point[1], point[2]]);
  await checked(() => page.locator('#copy-entry').click());
  assert.equal(await count(), n + 3);
  await checked(() => page.locator('#delete-entry').click());
  assert.equal(await count(), n + 2);
  await page.locator('#pair-with').selectOption('l_upper_arm');
  await checked(() => page.locator('#segment-pairs button', { hasText: 'add pair' }).click());
  await page.locator('#save').click();
  await page.waitForFunction(() => document.body.dataset.saved === '4');
  const report = JSON.parse(execFileSync(BIPED, ['ssv', 'model', VIEW_SSV, '--json'], { encoding: 'utf8' }));
  assert.ok(report.pairs.some((p) => p.a === 'r_forearm' && p.b === 'l_upper_arm'), 'the new pair is evaluated');
});

test('a version keeps fewer SSVs after unticking one, and is saved', async () => {
  await page.locator('#segment').selectOption('r_thigh_inner');
  const kept = () => page.evaluate(() => window.bipedView.editor.state.model.segments
    .find((g) => g.name === 'r_thigh_inner').source.keep);
  const before = await kept();
  await page.locator('#keep input[data-keep="3"]').uncheck();
  await page.waitForFunction(() => document.getElementById('status').textContent === 'unsaved changes');
  assert.deepEqual(await kept(), before.filter((k) => k !== 3));
  await page.locator('#save').click();
  await page.waitForFunction(() => document.body.dataset.saved === '5');
  assert.match(readFileSync(VIEW_SSV, 'utf8'), new RegExp(`keep = \\[${before.filter((k) => k !== 3).join(', ')}\\]`));
  assert.match(ssvModel(VIEW_SSV), /closest pair: /);
});

test('a bad edit shows the located error and leaves the file as it was', async () => {
  await page.locator('#segment').selectOption('pelvis');
  const saved = readFileSync(VIEW_SSV);
  refusalExpected = true;
  const radius = page.locator('.entry[data-index="0"] input.radius');
  await radius.fill('-0.2');
  await radius.press('Enter');
  await page.locator('#error').waitFor({ state: 'visible' });
  const located = new RegExp(`^${VIEW_SSV.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}:\\d+: .*radius`);
  assert.match(await page.locator('#error').textContent(), located);
  await page.locator('#save').click();
  await page.waitForFunction(() => document.getElementById('status').textContent === 'not saved');
  assert.match(await page.locator('#error').textContent(), located);
  assert.deepEqual(readFileSync(VIEW_SSV), saved, 'the file is unchanged');
  refusalExpected = false;
});

test('no console errors', () => {
  assert.deepEqual(problems, []);
});

// The plot of several signals, pairs written as [[pair]] tables and the detaching of a mirrored
// segment, against the server of scripts/test_view.sh on VIEW_TABLES_URL (a copy of the Lola
// model, VIEW_TABLES_SSV, whose pairs the test first rewrites as [[pair]] tables; the walk).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { openPage, putModel, withNeutralPose } from './helpers.js';

const { VIEW_TABLES_URL: URL, VIEW_TABLES_SSV: SSV, BIPED, OUT } = process.env;
const MARK = '# The pairs as [[pair]] tables (written by web/tests/panels.test.js).';
let browser;
let page;
const problems = [];
const modelJson = (file) => JSON.parse(execFileSync(BIPED, ['ssv', 'model', file, '--json'], { encoding: 'utf8' }));
const hasPair = (report, a, b) => report.pairs.some((p) => (p.a === a && p.b === b) || (p.a === b && p.b === a));

// The file's `pairs = [...]` array becomes [[pair]] tables at its end.
async function pairsAsTables() {
  const { scene, text } = await withNeutralPose(URL);
  const { pairs, span } = scene.ssv.pair_list;
  const key = text.lastIndexOf('pairs', span[0]);
  const tables = pairs.map(([a, b]) => `[[pair]]\na = "${a}"\nb = "${b}"\n`).join('\n');
  const model = await putModel(URL, `${text.slice(0, key)}${text.slice(span[1] + 1)}\n${MARK}\n${tables}`);
  assert.equal(model.pair_list, null);
  assert.equal(model.pair_tables.length, pairs.length);
}

before(async () => {
  await pairsAsTables();
  ({ browser, page } = await openPage(URL, problems));
});

after(async () => {
  if (browser) await browser.close();
});

// How many pixels of the plot canvas have the colour `hex` (within a tolerance).
const plotPixels = (hex) => page.evaluate((c) => {
  const canvas = document.getElementById('plot');
  const px = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
  const [r, g, b] = [1, 3, 5].map((i) => parseInt(c.slice(i, i + 2), 16));
  let n = 0;
  for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - r) + Math.abs(px[i + 1] - g) + Math.abs(px[i + 2] - b) < 60) n += 1;
  return n;
}, hex);

test('two signals are plotted in their colours with a legend, and a click seeks', async () => {
  const plot = page.locator('#plot');
  assert.equal(await plot.getAttribute('data-signals'), 'L_z');
  const one = await plot.screenshot({ path: join(OUT, 'plot_one.png') });
  await page.locator('#signal-add').selectOption('min_distance');
  await page.waitForFunction(() => document.getElementById('plot').dataset.polylines === '2');
  assert.equal(await plot.getAttribute('data-signals'), 'L_z,min_distance');
  assert.deepEqual(await page.locator('#plot-legend .legend').evaluateAll((l) => l.map((e) => e.dataset.signal)),
    ['L_z', 'min_distance']);
  const two = await plot.screenshot({ path: join(OUT, 'plot_two.png') });
  assert.ok(!one.equals(two), 'the plot changed');
  assert.ok(await plotPixels('#1565c0') > 30, 'the first signal is drawn');
  assert.ok(await plotPixels('#c62828') > 30, 'the second signal is drawn');
  // A click at three quarters of the time axis seeks the 3-D view there.
  const box = await plot.boundingBox();
  await plot.click({ position: { x: 45 / 360 * box.width + 0.75 * (box.width * (310 / 360)), y: box.height / 2 } });
  await page.waitForFunction(() => Number(document.body.dataset.frame) > 0);
  const frames = Number(await page.locator('#scrub').getAttribute('max')) + 1;
  const frame = Number(await page.evaluate(() => document.body.dataset.frame));
  assert.ok(Math.abs(frame / frames - 0.75) < 0.05, `frame ${frame} of ${frames}`);
  await page.locator('#plot-legend .legend[data-signal="min_distance"] button').click();
  await page.waitForFunction(() => document.getElementById('plot').dataset.polylines === '1');
  await page.locator('#scrub').focus();
  await page.keyboard.press('Home');
  await page.waitForFunction(() => document.body.dataset.frame === '0');
});

// Runs `action` and waits for the server's answer to the edit it makes.
async function checked(action) {
  const seq = await page.evaluate(() => window.bipedView.editor.state.seq);
  await action();
  await page.waitForFunction((n) => {
    const s = window.bipedView.editor.state;
    return s.seq > n && !s.busy && document.getElementById('status').textContent === 'unsaved changes';
  }, seq).catch(async (e) => {
    const why = await page.evaluate(() => [window.bipedView.editor.state.seq, window.bipedView.editor.state.busy,
      document.getElementById('status').textContent, document.getElementById('error').textContent]);
    throw new Error(`${e.message}: ${JSON.stringify(why)}`);
  });
}
let saves = 0;
async function save() {
  saves += 1;
  await page.locator('#save').click();
  await page.waitForFunction((n) => document.body.dataset.saved === String(n), saves);
}

test('a [[pair]] table is removed and one added, the rest of the file kept', async () => {
  const before = readFileSync(SSV, 'utf8');
  await page.locator('#segment').selectOption('r_forearm');
  await checked(() => page.locator('#segment-pairs button.pair', { hasText: 'torso ×' }).click());
  await page.locator('#pair-with').selectOption('l_upper_arm');
  await checked(() => page.locator('#segment-pairs button', { hasText: 'add pair' }).click());
  await save();
  const text = readFileSync(SSV, 'utf8');
  const removed = '[[pair]]\na = "r_forearm"\nb = "torso"\n';
  const added = '[[pair]]\na = "r_forearm"\nb = "l_upper_arm"\n';
  assert.ok(before.includes(removed) && !text.includes(removed), 'the pair table is gone');
  assert.ok(text.includes(added), 'the new pair table is written');
  // Exactly the removed table's lines are cut, and the new table follows the last one.
  assert.equal(text, `${before.replace(removed, '')}\n${added}`);
  for (const kept of ['# SSV collision model of the Lola-like biped', MARK, '# Left side: mirror images',
    '[pose.neutral]']) assert.ok(text.includes(kept), `${kept} is kept`);
  const report = modelJson(SSV);
  assert.ok(hasPair(report, 'r_forearm', 'l_upper_arm'), 'the new pair is evaluated');
  assert.ok(!hasPair(report, 'r_forearm', 'torso'), 'the removed pair is not');
});

test('a mirrored segment is detached into its own SSVs, edited and saved', async () => {
  await page.locator('#segment').selectOption('l_forearm');
  const mirrored = await page.evaluate(() => window.bipedView.editor.state.model.segments
    .find((g) => g.name === 'l_forearm').ssvs);
  assert.ok(await page.locator('#detach').isVisible(), 'detach is offered');
  await checked(() => page.locator('#detach').click());
  const g = await page.evaluate(() => window.bipedView.editor.state.model.segments.find((s) => s.name === 'l_forearm'));
  assert.equal(g.source.kind, 'ssvs');
  const flat = (ssvs) => ssvs.flatMap((v) => [v.kind, v.radius, ...v.points.flat()]);
  const same = (a, b) => a.length === b.length && a.every((x, i) => (typeof x === 'string' ? x === b[i] : Math.abs(x - b[i]) < 1e-12));
  assert.ok(same(flat(g.ssvs), flat(mirrored)), 'the same SSVs, now explicit');
  assert.ok(!(await page.locator('#detach').isVisible()), 'nothing left to detach');
  const radius = page.locator('.entry[data-index="0"] input.radius');
  await radius.fill('0.047');
  await checked(() => radius.press('Enter'));
  await save();
  const text = readFileSync(SSV, 'utf8');
  assert.ok(!text.includes('mirror_of = "r_forearm"'), 'the mirror_of line is gone');
  assert.match(text, /name = "l_forearm"\nbody = "l_forearm"\nssvs = \[\n {2}\{ [^\n]*radius = 0\.047 \},\n/);
  const report = modelJson(SSV);
  assert.ok(report.pairs.some((p) => p.a === 'l_forearm' || p.b === 'l_forearm'), 'l_forearm is still paired');
});

test('no console errors on the panel page', () => {
  assert.deepEqual(problems, []);
});

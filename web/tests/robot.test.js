// A described robot in the page: VIEW_G1_URL is the server of scripts/test_view.sh started
// with `--robot g1` alone, so the bundled G1 SSV model is shown, edits are checked and a save
// is refused with a message naming --ssv (the file stays as it is).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { canvasPixels, changedShare, openPage } from './helpers.js';

const { VIEW_G1_URL, OUT } = process.env;
let browser;
let page;
const problems = [];
// The browser logs the 403 answer of the refused save.
const refusal = (m) => /status of 403/.test(m.text()) && m.location().url.includes('/api/ssv');

before(async () => {
  ({ browser, page } = await openPage(VIEW_G1_URL, problems, { width: 1000, height: 700 }, refusal));
});

after(async () => {
  if (browser) await browser.close();
});

test('the G1 description shows its SSV model', async () => {
  const scene = await page.evaluate(() => window.bipedView.scene);
  assert.equal(scene.bodies.length, 30);
  assert.equal(await page.locator('#segment option').count(), scene.ssv.segments.length);
  assert.ok(await page.locator('#read-only').isVisible(), 'the page says the model is not saved');
  await page.waitForTimeout(300);
  await page.locator('#viewport').screenshot({ path: join(OUT, 'g1.png') });
  const shown = await canvasPixels(page);
  await page.locator('#show-ssv').uncheck();
  await page.waitForTimeout(300);
  const hidden = await canvasPixels(page);
  await page.locator('#show-ssv').check();
  const share = changedShare(hidden, shown);
  assert.ok(share > 0.01, `the SSVs cover only ${(share * 100).toFixed(2)} % of the viewport`);
});

test('an edit is checked but its save is refused, naming --ssv', async () => {
  const file = await page.evaluate(() => window.bipedView.scene.ssv.file);
  const before = readFileSync(file);
  await page.locator('#segment').selectOption('left_knee_link');
  const radius = page.locator('.entry[data-index="0"] input.radius');
  await radius.fill('0.051');
  await radius.press('Enter');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'unsaved changes');
  await page.locator('#save').click();
  await page.waitForFunction(() => document.getElementById('status').textContent === 'not saved');
  assert.match(await page.locator('#error').textContent(), /--ssv/);
  assert.deepEqual(readFileSync(file), before, 'the bundled file is unchanged');
});

test('no console errors on the G1 page', () => {
  assert.deepEqual(problems, []);
});

// A URDF robot in the page: its STL mesh and primitives are drawn. VIEW_URDF_URL is the
// server of scripts/test_view.sh that shows the small URDF robot it writes.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

const { VIEW_URDF_URL, OUT } = process.env;
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
let browser;
let page;
const problems = [];

before(async () => {
  browser = await chromium.launch({
    executablePath: CHROMIUM,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(VIEW_URDF_URL);
  await page.waitForFunction(() => document.body.dataset.ready, null, { timeout: 60000 });
});

after(async () => {
  if (browser) await browser.close();
});

test('the URDF mesh is loaded and drawn with the primitives', async () => {
  // The STL arrives after the page is ready: wait for its triangles.
  await page.waitForFunction(() => {
    let triangles = 0;
    window.bipedView.robot.root.traverse((o) => {
      if (o.isMesh && o.geometry.attributes.normal && !o.geometry.index) triangles += o.geometry.attributes.position.count / 3;
    });
    return triangles === 12;
  }, null, { timeout: 30000 });
  await page.waitForTimeout(300);
  await page.locator('#viewport').screenshot({ path: join(OUT, 'urdf.png') });
  const shapes = await page.evaluate(() => window.bipedView.scene.bodies.map((b) => b.geometry.map((g) => g.shape.type)));
  assert.deepEqual(shapes.flat().sort(), ['cylinder', 'mesh', 'sphere']);
});

test('no console errors on the URDF page', () => {
  assert.deepEqual(problems, []);
});

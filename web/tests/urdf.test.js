// A URDF robot in the page: its STL mesh and primitives are drawn. VIEW_URDF_URL is the
// server of scripts/test_view.sh that shows the small URDF robot it writes.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { openPage } from './helpers.js';

const { VIEW_URDF_URL, OUT } = process.env;
let browser;
let page;
const problems = [];

before(async () => {
  ({ browser, page } = await openPage(VIEW_URDF_URL, problems, { width: 1000, height: 700 }));
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

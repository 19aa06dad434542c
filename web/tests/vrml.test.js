// A VRML97 mesh in the page: VIEW_VRML_URL is the server of scripts/test_view.sh that shows a
// robot whose one visual is the box.wrl it writes (an IndexedFaceSet cube).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { canvasPixels, changedShare, openPage } from './helpers.js';

const { VIEW_VRML_URL, OUT } = process.env;
let browser;
let page;
const problems = [];

before(async () => {
  ({ browser, page } = await openPage(VIEW_VRML_URL, problems, { width: 1000, height: 700 }));
});

after(async () => {
  if (browser) await browser.close();
});

test('the VRML97 box is loaded and drawn', async () => {
  const shapes = await page.evaluate(() => window.bipedView.scene.bodies.map((b) => b.geometry.map((g) => g.shape)));
  assert.deepEqual(shapes.flat().map((s) => [s.type, s.format]), [['mesh', 'wrl']]);
  // The file arrives after the page is ready: wait for the cube's 12 triangles.
  await page.waitForFunction(() => {
    let triangles = 0;
    window.bipedView.robot.root.traverse((o) => {
      if (!o.isMesh) return;
      const g = o.geometry;
      triangles += (g.index ? g.index.count : g.attributes.position.count) / 3;
    });
    return triangles === 12;
  }, null, { timeout: 30000 });
  await page.waitForTimeout(300);
  await page.locator('#viewport').screenshot({ path: join(OUT, 'vrml.png') });
  const shown = await canvasPixels(page);
  await page.evaluate(() => { window.bipedView.robot.root.visible = false; });
  await page.waitForTimeout(300);
  await page.locator('#viewport').screenshot({ path: join(OUT, 'vrml_hidden.png') });
  const hidden = await canvasPixels(page);
  await page.evaluate(() => { window.bipedView.robot.root.visible = true; });
  const share = changedShare(hidden, shown);
  assert.ok(share > 0.01, `the VRML box covers only ${(share * 100).toFixed(2)} % of the viewport`);
});

test('no console errors on the VRML page', () => {
  assert.deepEqual(problems, []);
});

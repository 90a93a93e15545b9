// The 3D surface drawn by the page (web/src/plots/surface.js): it turns with the arrow keys and
// by dragging, and the pointer shows the nearest grid point's values with their names and units.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { colours, openPage, plotted, useBrowser } from './support.mjs';

useBrowser();

test('the 3D surface turns with the keys and by dragging, and shows a grid point under the pointer', async () => {
  const page = await openPage();
  await plotted(page);
  const surface = page.locator('#plot-before-3d');
  const overlay = page.locator('#plot-before-3d canvas:last-child');
  await surface.scrollIntoViewIfNeeded();
  assert.ok(await colours(page, '#plot-before-3d') > 30);
  // The drawing itself: without the pointer's box (on the other canvas) or a focus ring.
  const shot = async () => {
    await page.evaluate(() => document.activeElement && document.activeElement.blur());
    return page.locator('#plot-before-3d canvas:first-child').screenshot();
  };
  const start = await shot();
  await overlay.focus();
  for (let i = 0; i < 6; i++) await page.keyboard.press('ArrowLeft');
  await page.waitForTimeout(200);
  const turned = await shot();
  assert.ok(!turned.equals(start), 'the arrow keys turn it');
  await overlay.dblclick();
  await page.waitForTimeout(200);
  assert.ok((await shot()).equals(start), 'a double click resets the view');
  const box = await overlay.boundingBox();
  await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.5);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.4, box.y + box.height * 0.45, { steps: 4 });
  await page.mouse.up();
  await page.waitForTimeout(200);
  assert.ok(!(await shot()).equals(start), 'dragging turns it');
  await overlay.dblclick();

  // Sweep the pointer over the plot until it is near a grid point.
  let text = '';
  for (let y = 0.3; y < 0.8 && !text; y += 0.04) {
    for (let x = 0.2; x < 0.7 && !text; x += 0.03) {
      await page.mouse.move(box.x + box.width * x, box.y + box.height * y);
      text = await overlay.getAttribute('data-hover');
    }
  }
  assert.match(text, /^x = -?\d+\.\d\d mm along the gash; r = \d+\.\d\d mm; deviation -?\d+\.\d{3} µm$/);
  await page.mouse.move(box.x + 2, box.y + 2);
  assert.equal(await overlay.getAttribute('data-hover'), '', 'away from the surface, nothing is shown');
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

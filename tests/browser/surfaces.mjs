// The 3D surfaces in the browser tests: opening them ("3D surfaces"), and checking that each is a
// Plotly surface drawn by WebGL, whose scene shows the surface and nothing cut off at its edges.
import assert from 'node:assert/strict';
import { after_, regions } from './support.mjs';

// Ticks "3D surfaces" (if it is not yet) and waits for the plots to be drawn.
export async function show3d(page) {
  if (await page.isChecked('#show-3d')) return;
  await after_(page, 'draws', () => page.check('#show-3d'));
}

// The scene's viewport within its plot (CSS px from the plot's top left), where WebGL draws it.
export function sceneBox(page, selector) {
  return page.evaluate((sel) => {
    const gd = document.querySelector(sel);
    const { l, t, w, h } = gd._fullLayout._size;
    const d = gd._fullLayout.scene.domain;
    return { x: l + d.x[0] * w, y: t + (1 - d.y[1]) * h, width: (d.x[1] - d.x[0]) * w, height: (d.y[1] - d.y[0]) * h };
  }, selector);
}

async function withSurfaceHidden(page, selector, look) {
  const restyle = (visible) => page.evaluate(async ([sel, v]) => {
    await window.Plotly.restyle(document.querySelector(sel), { hidesurface: !v });
    await new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
  }, [selector, visible]);
  await restyle(false);
  try { return await look(); } finally { await restyle(true); }
}

// Each plot is a Plotly surface on a WebGL canvas; its scene shows many colours, and clearly more
// ink than the same scene with the surface hidden (the box, grid lines, ticks and titles alone);
// and nothing touches the scene's edges, where WebGL would cut it off (a title, a tick label).
export async function surfacesDrawn(page, selectors) {
  await show3d(page);
  const out = [];
  for (const selector of selectors) {
    await page.locator(selector).scrollIntoViewIfNeeded();
    await page.mouse.move(0, 0);  // no hover label, no mode bar
    const facts = await page.evaluate((sel) => {
      const gd = document.querySelector(sel);
      const canvas = gd.querySelector('.gl-container canvas');
      return {
        visible: !gd.hidden && gd.offsetHeight > 0, type: gd._fullData && gd._fullData[0].type,
        webgl: Boolean(canvas && (canvas.getContext('webgl') || canvas.getContext('experimental-webgl'))),
      };
    }, selector);
    assert.deepEqual(facts, { visible: true, type: 'surface', webgl: true }, selector);
    const box = await sceneBox(page, selector);
    const [scene] = await regions(page, selector, [box], 3);
    const [empty] = await withSurfaceHidden(page, selector, () => regions(page, selector, [box], 3));
    assert.ok(scene.colours > 30, `${selector}: ${scene.colours} colours`);
    assert.ok(scene.inked > empty.inked + 0.02,
              `${selector}: the surface is drawn (${scene.inked.toFixed(3)} inked, ${empty.inked.toFixed(3)} without it)`);
    assert.equal(scene.edge, 0, `${selector}: nothing is cut off at the scene's edges`);
    out.push(scene);
  }
  return out;
}

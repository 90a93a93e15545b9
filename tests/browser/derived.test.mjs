// Item 6, "derived values stay derived": the paper example loads the setting angle and the centre
// distance as derived (fields empty), so that they follow the wheel, the hand and the gash; a
// field stays derived until the user types over it, and is derived again once cleared.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { afterResult, base, openPage, shots, tab2, useBrowser } from './support.mjs';

useBrowser();
const desk = { viewport: { width: 1366, height: 768 } };  // the engineer's screen
const status = (page) => page.textContent('#status');

test('the paper example loads gamma_m and E_t as derived, with a note that they equal the paper\'s', async () => {
  const page = await openPage(base, desk);
  assert.equal(await page.inputValue('[data-field="setup.settingAngle"]'), '');
  assert.equal(await page.inputValue('[data-field="setup.centerDistance"]'), '');
  assert.match(await page.textContent('[data-derived="settingAngle"]'), /12\.6258/);
  assert.match(await page.textContent('[data-derived="centerDistance"]'), /69\.4462/);
  assert.equal(await page.isVisible('#paper-note'), true);
  assert.match(await page.textContent('#paper-note'), /equal to the paper's 12\.626° and 69\.446 mm/);
  await page.locator('fieldset[data-group="setup"]').screenshot({ path: path.join(shots, 'derived-setup.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a larger wheel changes Tab. 2: the centre distance follows it', async () => {
  const page = await openPage(base, desk);
  const before = await tab2(page, 'nominal');
  await afterResult(page, () => page.fill('[data-field="wheel.outerDiameter"]', '120'));
  const now = await tab2(page, 'nominal');
  assert.notEqual(now.Y, before.Y, 'C_y moves out with the wheel radius');
  assert.equal(now.Y, '49.50831');  // E_t 79.64672 mm, from the boundary equation (wheel rim at the gash root)
  assert.match(await page.textContent('[data-derived="centerDistance"]'), /79\.6467/);
  assert.equal(await page.isVisible('#paper-note'), false, 'the derived E_t no longer equals the paper\'s');
  await page.context().close();
});

test('left hand computes: the setting angle follows the hand', async () => {
  const page = await openPage(base, desk);
  await afterResult(page, () => page.selectOption('[data-field="hob.hand"]', 'left'));
  assert.doesNotMatch(await status(page), /no contact|Not computed/);
  assert.match(await page.textContent('[data-derived="settingAngle"]'), /−?-?12\.6258/);
  const t = await tab2(page, 'nominal');
  assert.equal(t.X, '−22.40001 − 139.5089 φ₁');
  assert.equal(t.B, '−0.2203625');
  await page.context().close();
});

test('a straight gash computes: no error blamed on the wheel diameter', async () => {
  const page = await openPage(base, desk);
  await afterResult(page, () => page.selectOption('[data-field="hob.gash"]', 'straight'));
  assert.doesNotMatch(await status(page), /Outer diameter|wheel|Not computed/);
  assert.equal(await page.locator('.field-message').count(), 0);
  const t = await tab2(page, 'nominal');
  assert.equal(t.X, '1 s');
  assert.equal(t.A, '0');
  await page.context().close();
});

test('a typed value is used until the field is cleared; then it is derived again', async () => {
  const page = await openPage(base, desk);
  const derived = await tab2(page, 'nominal');
  await afterResult(page, () => page.fill('[data-field="setup.settingAngle"]', '12.626'));
  await afterResult(page, () => page.fill('[data-field="setup.centerDistance"]', '69.446'));
  // The paper's own Tab. 2, from its rounded setting angle and centre distance.
  assert.deepEqual(await tab2(page, 'nominal'), { X: '22.4003 + 139.5089 φ₁', Y: '39.30757', Z: '−116.446', A: '1 φ₁', B: '0.2203653' });
  // (A wheel 2 mm larger: its rim 1 mm past the gash root, within the clearance taken as set on
  // purpose; 120 mm would put it 10 mm into the hob, which is refused.)
  await afterResult(page, () => page.fill('[data-field="wheel.outerDiameter"]', '102'));
  assert.equal((await tab2(page, 'nominal')).Y, '39.30757', 'a typed centre distance stays as typed');
  await afterResult(page, () => page.fill('[data-field="setup.settingAngle"]', ''));
  await afterResult(page, () => page.fill('[data-field="setup.centerDistance"]', ''));
  assert.equal((await tab2(page, 'nominal')).Y, '40.32693', 'cleared, they are derived for the new wheel');
  await afterResult(page, () => page.fill('[data-field="wheel.outerDiameter"]', '100'));
  assert.deepEqual(await tab2(page, 'nominal'), derived);
  await page.context().close();
});

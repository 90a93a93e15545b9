// Item 6, "errors": a refused input's message is prominent, at the field, in its label's words
// (the JSON path only in the tooltip); the status stays in view while scrolling; the results are
// marked stale while an error stands; a broken link's warning stays until the user changes
// something.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { afterError, afterResult, base, count, openPage, plotted, shots, useBrowser } from './support.mjs';

useBrowser();
const desk = { viewport: { width: 1366, height: 768 } };  // the engineer's screen
const inView = (page, selector) => page.evaluate((s) => {
  const r = document.querySelector(s).getBoundingClientRect();
  return r.height > 0 && r.top >= 0 && r.bottom <= window.innerHeight;
}, selector);
const toBottom = (page) => page.evaluate(() => window.scrollTo(0, document.body.scrollHeight));

test('a refused field says so at the field, in red, in the label\'s words', async () => {
  const page = await openPage(base, desk);
  await afterError(page, () => page.fill('[data-field="hob.pitchDiameter"]', '90'));
  const note = page.locator('label:has([data-field="hob.pitchDiameter"]) .field-message');
  assert.equal((await note.textContent()).trim(),
    'Pitch diameter dp must be smaller than the outer diameter da (80 mm); got 90 mm.');  // d<sub>p</sub>, d<sub>a</sub>
  // Its title too is in words (it was the calculator's message, paths and all).
  assert.equal(await note.getAttribute('title'), 'Pitch diameter d_p must be smaller than the outer diameter d_a (80 mm); got 90 mm.');
  const style = await note.evaluate((el) => { const s = getComputedStyle(el); return { color: s.color, size: parseFloat(s.fontSize), weight: Number(s.fontWeight) }; });
  assert.equal(style.color, 'rgb(197, 48, 48)', 'red, not grey');
  assert.ok(style.size >= 13 && style.weight >= 600, JSON.stringify(style));
  assert.equal(await page.getAttribute('[data-field="hob.pitchDiameter"]', 'aria-invalid'), 'true');
  assert.match(await page.textContent('#status'), /^Not computed: Pitch diameter d_p must be smaller than the outer diameter d_a \(80 mm\)/);
  assert.doesNotMatch(await page.textContent('#status'), /hob\./);
  await page.locator('fieldset[data-group="hob"]').screenshot({ path: path.join(shots, 'field-message.png') });
  await page.context().close();
});

test('while an error stands the results are marked stale, and the status stays in view', async () => {
  const page = await openPage(base, desk);
  assert.equal(await page.isVisible('#stale-banner'), false);
  await afterError(page, () => page.fill('[data-field="wheel.outerDiameter"]', '0'));
  assert.equal(await page.isVisible('#stale-banner'), true);
  assert.match(await page.textContent('#stale-banner'), /Results shown are for the last valid input/);
  assert.equal(await page.evaluate(() => document.querySelector('#results').classList.contains('stale')), true);
  await toBottom(page);
  assert.ok(await page.evaluate(() => window.scrollY) > 1000, 'scrolled down');
  assert.equal(await inView(page, '#status'), true, 'the status is in view at the bottom of the page');
  assert.match(await page.textContent('#status'), /^Not computed: Outer diameter d_w must be positive; got 0 mm\./);
  await page.screenshot({ path: path.join(shots, 'stale-scrolled.png') });
  await page.evaluate(() => window.scrollTo(0, 0));
  await afterResult(page, () => page.fill('[data-field="wheel.outerDiameter"]', '100'));
  assert.equal(await page.isVisible('#stale-banner'), false);
  assert.equal(await page.evaluate(() => document.querySelector('#results').classList.contains('stale')), false);
  await page.context().close();
});

test('an error without its own field is shown at its group of fields, in words', async () => {
  const page = await openPage(base, desk);
  await afterError(page, () => page.fill('[data-field="setup.centerDistance"]', '100'));
  const note = page.locator('fieldset[data-group="setup"] > .field-message');
  assert.match(await note.textContent(), /^Universal machine settings: no contact between the wheel and the tooth face/);
  assert.match(await note.getAttribute('title'), /^Universal machine settings: no contact/);
  // Paths inside a message are named as on screen, too.
  await afterResult(page, () => page.fill('[data-field="setup.centerDistance"]', ''));
  await afterError(page, () => page.fill('[data-field="setup.settingAngle"]', '60'));
  assert.match(await page.textContent('label:has([data-field="wheel.outerDiameter"]) .field-message'),
    /^Outer diameter dw: the wheel rim .* Give the centre distance Et or change the wheel\.$/);
  await page.context().close();
});

test('a broken link\'s warning stays in view until the user changes something', async () => {
  const page = await openPage(`${base}#case=%7B%22format`, desk);
  await plotted(page);
  assert.equal(await page.isVisible('#notice'), true);
  assert.match(await page.textContent('#notice'), /The link holds no readable case.*The paper example is loaded instead/);
  await toBottom(page);
  assert.equal(await inView(page, '#notice'), true, 'the warning is in view at the bottom of the page');
  await page.evaluate(() => window.scrollTo(0, 0));
  const results = await count(page, 'results');
  await afterResult(page, () => page.fill('[data-field="setup.tilt"]', '16'));
  assert.ok(await count(page, 'results') > results);
  assert.equal(await page.isVisible('#notice'), false, 'a change of an input ends it');
  await page.context().close();
});

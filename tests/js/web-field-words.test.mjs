// Refusals in the words on screen (web/src/field-words.js): the field's label in place of its
// JSON path, and the paths inside the message named as on screen too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pathWords, wordedError } from '../../web/src/field-words.js';

const names = {
  'hob.pitchDiameter': { text: 'Pitch diameter d_p', html: 'Pitch diameter <i>d<sub>p</sub></i>' },
  'hob.outerDiameter': { text: 'Outer diameter d_a', html: 'Outer diameter <i>d<sub>a</sub></i>' },
  'hob.gashLead': { text: 'Gash lead L_c', html: 'Gash lead <i>L<sub>c</sub></i>' },
  'hob.gashHelixAngle': { text: 'Gash helix angle β_c', html: 'Gash helix angle <i>β<sub>c</sub></i>' },
  'grid.radial': { text: 'Radial lines', html: 'Radial lines' },
  setup: { text: 'Universal machine settings', html: 'Universal machine settings' },
  'axes.X': { text: 'Run axis X', html: 'Run axis X' },
};

test('a field\'s message starts with its label; a reason that starts with a verb follows it directly', () => {
  const w = wordedError({ field: 'hob.pitchDiameter', message: 'hob.pitchDiameter: must be smaller than hob.outerDiameter (80 mm); got 90 mm.' }, names);
  assert.equal(w.text, 'Pitch diameter d_p must be smaller than the outer diameter d_a (80 mm); got 90 mm.');
  assert.equal(w.html, 'Pitch diameter <i>d<sub>p</sub></i> must be smaller than the outer diameter <i>d<sub>a</sub></i> (80 mm); got 90 mm.');
});

test('any other reason follows a colon; a group of fields is named by its legend', () => {
  const w = wordedError({ field: 'setup', message: 'setup: no contact between the wheel and the tooth face at r = 31.25 mm.' }, names);
  assert.equal(w.text, 'Universal machine settings: no contact between the wheel and the tooth face at r = 31.25 mm.');
});

test('several paths in one message, with no article where one is there or a value follows', () => {
  const lead = wordedError({ field: 'hob.gashLead', message: 'hob.gashLead: a helical gash needs hob.gashLead or hob.gashHelixAngle.' }, names);
  assert.equal(lead.text, 'Gash lead L_c: a helical gash needs the gash lead L_c or the gash helix angle β_c.');
  const grid = wordedError({ field: 'hob.pitchDiameter', message: 'hob.pitchDiameter: needs grid.radial = 5 rows of the hob.outerDiameter.' }, names);
  assert.equal(grid.text, 'Pitch diameter d_p needs radial lines = 5 rows of the outer diameter d_a.');
});

test('an element of a list is named in words, counted from 1 (a coefficient by its a_k)', () => {
  const w = wordedError({ field: 'axes.X[2]', message: 'axes.X[2]: must be a finite number.' }, names);
  assert.equal(w.text, 'Run axis X, coefficient a2 must be a finite number.');
  const m = wordedError({ field: 'passes[1].measured[2][3]', message: 'passes[1].measured[2][3]: must be a number; got a string.' }, names);
  assert.equal(m.text, 'Pass 2, measured grid, row 3, value 4 must be a number; got a string.');
});

test('a field with no name on screen is named in words: no path of the case reaches the page', () => {
  const cases = {
    'passes[0].axes.X[1]': 'Pass 1, run axis X, coefficient a1',
    'inspection.gashDeviations[3]': "Inspection, gash 4's deviation",
    'inspection.gashTopographies[0][1][2]': "Inspection, gash 1's topography, row 2, value 3",
    'inspection.tolerances.checks.gashLead.B': 'Inspection, tolerance table, gash lead, class B',
    'inspection.uncertainty': 'Inspection, measuring uncertainty U95',
    'correction.probeNoise': 'Correction options, probe noise σ',
    'job.hobSerial': 'Job, hob serial number',
    'measuredPoints[4]': 'Measured point 5',
    'wheel.measuredProfile[3].R': 'Wheel, wheel file, point 4, R',
    format: 'Case format',
  };
  for (const [path, words] of Object.entries(cases)) assert.equal(pathWords(path), words, path);
  const w = wordedError({ field: 'correction.method', message: 'correction.method: must be one of "nonlinear", "linear"; got "x".' }, names);
  assert.equal(w.text, 'Correction options, method must be one of "nonlinear", "linear"; got "x".');
  // A path inside the reason, named on screen or not; a member's name as a plain word stays a word.
  const r = wordedError({ field: 'grid.radial', message: 'grid.radial: the grid of the hob needs passes[0].axes.X and hob.gashLead.' }, names);
  assert.equal(r.text, 'Radial lines: the grid of the hob needs the pass 1, run axis X and the gash lead L_c.');
  const path = /\b[a-z]\w*(\.[A-Za-z]\w*|\[\d+\])+/;
  for (const t of [w.text, r.text, ...Object.values(cases)]) assert.doesNotMatch(t, path);
});

test('the page\'s own text in a message is escaped in the HTML', () => {
  const w = wordedError({ field: 'hob.pitchDiameter', message: 'hob.pitchDiameter: must be <b>"x"</b> & more.' }, names);
  assert.equal(w.html, 'Pitch diameter <i>d<sub>p</sub></i> must be &#60;b&#62;&#34;x&#34;&#60;/b&#62; &#38; more.');
});

test('a message that does not start with its field is left as it is', () => {
  assert.equal(wordedError({ field: 'measured[0]', message: 'measured[0]: must be a list.' }, names).text, 'Measured grid, row 1 must be a list.');
  assert.equal(wordedError({ field: '', message: 'The case is not valid JSON.' }, names), null);
  assert.equal(wordedError({ field: 'hob.pitchDiameter', message: 'Something else.' }, names), null);
});

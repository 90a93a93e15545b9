// Lines for tests/js/page-units.test.mjs: those marked are what the check must find, the others
// what it must let be. Not loaded by anything.
const a = `RMS ${c.rmsBefore} µm`; // hand-typed
const b = ['profile slope deviation fHα (largest over the teeth)', 'µm', g.left.profileSlope]; // hand-typed
const d = `side relief ${g.sideReliefAngle}°`; // hand-typed
const e = `sum of squares ${x} µm²`; // hand-typed
const f = `${fieldLabel('correction.rmsBefore')} ${c.rmsBefore} ${fieldUnit('correction.rmsBefore')}`;
const h = Math.max(a, b) + ' µm';
const k = `${c.rmsBefore} ${unit}`; // µm in a comment is no unit on the page

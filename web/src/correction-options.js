// The correction's options as the page edits them (pure, with Node tests): the method, whether the
// wheel's profile is corrected too (`wheel`, a dresser path), the probe
// noise sigma (µm) and the machine's resolution per axis (µm for X, Y, Z; deg for A, B), held in
// state.tuning as the case's `correction` member holds them (docs/case-format.md). A blank input
// means the calculator's default, so it is left out of the case.
import { SIMULATED_NOISE } from './probe-noise.js';

// The options' fields the page has inputs for; a refusal of one of them is shown at its input.
export const OPTION_FIELD = /^correction\.(method|probeNoise|wheel|resolution(\.[XYZAB])?|truncation|amplification)$/;

// state.tuning with one input's text applied: key is 'method', 'probeNoise' or 'resolution.X'..
// A number that is not one is kept as text, so that the calculator names the field.
export function withOption(tuning, key, text, defaultMethod) {
  const next = structuredClone(tuning);
  const value = (t) => (t.trim() === '' ? undefined : Number.isFinite(Number(t)) ? Number(t) : t);
  if (key === 'method') {
    if (text === defaultMethod) delete next.method; else next.method = text;
  } else if (key === 'wheel') {
    if (text === true || text === 'true') next.wheel = true; else delete next.wheel;
  } else if (key === 'probeNoise') {
    const v = value(text);
    if (v === undefined) delete next.probeNoise; else next.probeNoise = v;
  } else if (key.startsWith('resolution.')) {
    const axis = key.slice('resolution.'.length);
    const resolution = { ...(next.resolution || {}) };
    const v = value(text);
    if (v === undefined) delete resolution[axis]; else resolution[axis] = v;
    if (Object.keys(resolution).length) next.resolution = resolution; else delete next.resolution;
  }
  return next;
}

// What the inputs show for state.tuning: the method, and each number as text ('' = default);
// simulated is true when the probe noise is the page's own for a simulated grid.
export function optionTexts(tuning, defaultMethod) {
  const text = (v) => (v === undefined || v === null ? '' : String(v));
  const resolution = {};
  for (const [axis, v] of Object.entries(tuning.resolution || {})) resolution[axis] = text(v);
  return {
    method: tuning.method || defaultMethod, probeNoise: text(tuning.probeNoise), resolution,
    simulated: tuning.probeNoise === SIMULATED_NOISE, wheel: tuning.wheel === true,
  };
}

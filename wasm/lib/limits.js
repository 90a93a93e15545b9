// Names, units and limits. Those the C++ core owns (the case format, the grid limit, the degree
// range, the default grid, the axes with their kinds and units, the result fields' units) come
// from the module's limits() once the calculator is ready (the result's units: web/src/result-fields.js):
// setModuleLimits fills the bindings below, in place, before the page or the CLI reads a case.
// Shared by the page and the CLI; the page's own words (the axes' descriptions) are web/src/limits.js.

export let CASE_FORMAT;                  // 'hobsharp-case/1'
export const AXES = [];                  // 'X' .. 'B', in the module's order
export const AXIS_UNIT = {};             // axis -> 'mm' or 'rad'
export const DEGREE = {};                // {min, max, default}
// {min, max, radial, axial}: lines in each direction; a grid has at least its two ends.
export const GRID = { min: 2 };
// The correction's options: {methods, defaultMethod, probeNoise: {default, max, unit},
// resolution: {X: {default, min, max, unit}, ...}}.
export const CORRECTION = {};
// The inspection's checks, classes and default tolerance table: {checks, classes, maxGashes,
// maxGashDeviation, defaultTolerances} (docs/inspection.md).
export const INSPECTION = {};
let rotary = new Set();
export const isRotary = (axis) => rotary.has(axis);

// limits: what Module.limits() returns (docs/api.md). Refuses a shape it cannot use.
export function setModuleLimits(limits) {
  const { format, maxGridLines, degree, defaultGrid, axes, correction, inspection } = limits || {};
  if (typeof format !== 'string' || !(maxGridLines >= GRID.min) || !degree || !defaultGrid || !Array.isArray(axes)) {
    throw new Error('The calculator gave no limits the page can use.');
  }
  CASE_FORMAT = format;
  Object.assign(DEGREE, { min: degree.min, max: degree.max, default: degree.default });
  Object.assign(GRID, { max: maxGridLines, radial: defaultGrid.radial, axial: defaultGrid.axial });
  AXES.splice(0, AXES.length, ...axes.map((a) => a.name));
  for (const key of Object.keys(AXIS_UNIT)) delete AXIS_UNIT[key];
  for (const a of axes) AXIS_UNIT[a.name] = a.unit;
  rotary = new Set(axes.filter((a) => a.kind === 'rotary').map((a) => a.name));
  for (const key of Object.keys(CORRECTION)) delete CORRECTION[key];
  if (correction) Object.assign(CORRECTION, structuredClone(correction));
  for (const key of Object.keys(INSPECTION)) delete INSPECTION[key];
  if (inspection) Object.assign(INSPECTION, structuredClone(inspection));
}

const SUPERSCRIPT = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
// k as a superscript (k ≥ 2; 1 is written without one): ², ³, ..., ¹⁰.
export const superscript = (k) => (k <= 1 ? '' : String(k).split('').map((d) => SUPERSCRIPT[d]).join(''));

// The unit of coefficient a_k of an axis, per (motion unit)^k: mm or rad per rad^k (helical gash)
// or per mm^k (straight gash).
export function coefficientUnit(axis, k, per) {
  const base = AXIS_UNIT[axis];
  return k === 0 ? base : `${base}/${per}${superscript(k)}`;
}

// Names, units and limits that the C++ core owns, copied here in one place (and nowhere else in
// the page), so that they can be read from the module instead once it exports them.

export const CASE_FORMAT = 'hobsharp-case/1';

// The five CNC axes (Eq. 9): three slides in mm, two rotations in rad.
export const AXES = ['X', 'Y', 'Z', 'A', 'B'];
export const AXIS_UNIT = { X: 'mm', Y: 'mm', Z: 'mm', A: 'rad', B: 'rad' };
export const AXIS_NAMES = {
  X: 'C<sub>x</sub> horizontal stroke', Y: 'C<sub>y</sub> radial infeed', Z: 'C<sub>z</sub> wheel axial',
  A: 'ψ<sub>a</sub> hob rotation', B: 'ψ<sub>b</sub> wheel swivel',
};
export const isRotary = (axis) => AXIS_UNIT[axis] === 'rad';

// Polynomial degree and measuring grid (lines in each direction), with the defaults the core
// uses when a field is left out.
export const DEGREE = { min: 1, max: 6 };
export const GRID = { min: 2, max: 201, radial: 5, axial: 9 };

const SUPERSCRIPT = ['', '', '²', '³', '⁴', '⁵', '⁶'];
export const superscript = (k) => SUPERSCRIPT[k] ?? `^${k}`;

// The unit of coefficient a_k of an axis, per (motion unit)^k: mm or rad per rad^k (helical gash)
// or per mm^k (straight gash).
export function coefficientUnit(axis, k, per) {
  const base = AXIS_UNIT[axis];
  return k === 0 ? base : `${base}/${per}${superscript(k)}`;
}

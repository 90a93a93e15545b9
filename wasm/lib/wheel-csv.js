// A wheel's points as a user's file comes (pure, with Node tests): the dressed wheel's offset,
// `R (mm), offset (µm)`, or a measured axial profile, `R (mm), Z (mm)` (the case's
// wheel.profileOffset and wheel.measuredProfile, docs/case-format.md). A header names every column
// with its unit: R_mm, R (mm), R [mm]; offset in µm (um) or mm. Other columns (the page's own
// profile export has r_mm, the tooth-face radius) are left out. Semicolons with decimal commas,
// a BOM and # comments are read. Points in falling R are turned round.
import { MAX_MEASURED_BYTES } from './csv.js';

// The most points a wheel file may hold, counted before they are read: a dresser's or a
// measuring machine's profile is a few hundred points, and the calculator fits the wheel to
// every one of them: 1,000 points take it 0.6 s, 4,000 take 3.4 s, 12,000 more memory than it has.
export const MAX_WHEEL_POINTS = 2000;
const count = (n) => n.toLocaleString('en-US');

const toNumber = (cell) => {
  const t = cell.replace(/^\u2212/, '-').replace(/^\+/, '');
  if (t === '' || !/^-?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(t)) return NaN;
  return Number(t);
};

const splitCells = (line, semicolon) =>
  (semicolon ? line.split(/[;\t]/).map((c) => c.trim().replace(',', '.')) : line.split(/[,\t]/).map((c) => c.trim()));

// "R (mm)", "R_mm", "R [mm]", "offset (µm)" -> {name, unit}; unit '' when none is written.
function column(cell) {
  const m = /^([A-Za-z]+)\s*(?:[_ ]\s*|\s*)(?:\(\s*([^)]*)\s*\)|\[\s*([^\]]*)\s*\]|([µμu]m|mm))?$/.exec(cell.trim());
  if (!m) return { name: cell.trim(), unit: '' };
  const unit = (m[2] || m[3] || m[4] || '').trim().replace(/^[μu]m$/, 'µm');
  return { name: m[1], unit };
}

// The column of `name` (R is the wheel radius, r the tooth-face radius: case matters for R only).
const find = (columns, name) =>
  columns.findIndex((c) => (name === 'R' ? c.name === 'R' : c.name.toLowerCase() === name.toLowerCase()));

// text -> {kind: 'profileOffset' | 'measuredProfile', points: {R, offset} | {R, Z}, notes};
// throws an Error naming the line (and column) of what cannot be read.
export function readWheelCsv(text) {
  if (text.length > MAX_MEASURED_BYTES) {
    throw new Error(`The file is ${(text.length / 1048576).toFixed(1)} MB; a wheel's points are a few kB (the limit is ${MAX_MEASURED_BYTES / 1048576} MB). Is this the right file?`);
  }
  const lines = [];
  text.replace(/^\uFEFF/, '').split(/\r?\n/).forEach((raw, i) => {
    const l = raw.trim();
    if (l !== '' && !l.startsWith('#')) lines.push({ n: i + 1, text: l });
  });
  if (lines.length === 0) throw new Error('The wheel file is empty.');
  if (lines.length - 1 > MAX_WHEEL_POINTS) {
    throw new Error(`The wheel file has ${count(lines.length - 1)} points; at most ${count(MAX_WHEEL_POINTS)} are read (a dressed wheel's profile is a few hundred).`);
  }
  const semicolon = /;/.test(lines[0].text);
  const notes = semicolon ? ['semicolons with decimal commas'] : [];
  const header = { n: lines[0].n, columns: splitCells(lines[0].text, semicolon).map(column) };
  if (header.columns.every((c) => Number.isFinite(toNumber(c.name)))) {
    throw new Error(`Line ${header.n}: no header. The first line names the columns with their units: "R (mm), offset (µm)" for a dressed wheel's offset, or "R (mm), Z (mm)" for a measured profile.`);
  }
  const iR = find(header.columns, 'R');
  const iOffset = find(header.columns, 'offset');
  const iZ = find(header.columns, 'Z');
  if (iR < 0 || (iOffset < 0 && iZ < 0)) {
    throw new Error(`Line ${header.n}: the header names ${header.columns.map((c) => `"${c.name}"`).join(', ')}; it needs "R (mm)" and either "offset (µm)" (a dressed wheel) or "Z (mm)" (a measured profile).`);
  }
  if (iOffset >= 0 && iZ >= 0) throw new Error(`Line ${header.n}: the header names both "offset" and "Z"; give a dressed wheel's offset or a measured profile, not both.`);
  const kind = iOffset >= 0 ? 'profileOffset' : 'measuredProfile';
  const iValue = kind === 'profileOffset' ? iOffset : iZ;
  const units = { [iR]: ['mm'], [iValue]: kind === 'profileOffset' ? ['µm', 'mm'] : ['mm'] };
  for (const j of [iR, iValue]) {
    const c = header.columns[j];
    if (c.unit === '') throw new Error(`Line ${header.n}, column ${j + 1}: "${c.name}" has no unit; write ${c.name} (${units[j][0]}).`);
    if (!units[j].includes(c.unit)) throw new Error(`Line ${header.n}, column ${j + 1}: ${c.name} in "${c.unit}"; it must be in ${units[j].join(' or ')}.`);
  }
  const scale = kind === 'profileOffset' && header.columns[iOffset].unit === 'mm' ? 1000 : 1;
  if (scale !== 1) notes.push('offsets in mm, taken ×1000 to µm');
  const left = header.columns.filter((_, j) => j !== iR && j !== iValue).map((c) => c.name);
  if (left.length) notes.push(`column${left.length > 1 ? 's' : ''} ${left.join(', ')} left out`);
  const R = [], V = [];
  for (const { n, text: l } of lines.slice(1)) {
    const cells = splitCells(l, semicolon);
    for (const j of [iR, iValue]) {
      const v = toNumber(cells[j] === undefined ? '' : cells[j]);
      if (!Number.isFinite(v)) {
        throw new Error(`Line ${n}, column ${j + 1}: "${(cells[j] || '').slice(0, 20)}" is not a number (${header.columns[j].unit}).`);
      }
    }
    R.push(toNumber(cells[iR]));
    V.push(toNumber(cells[iValue]) * scale);
  }
  if (R.length < 2) throw new Error(`The wheel file has ${R.length} point${R.length === 1 ? '' : 's'}; it needs at least 2.`);
  const falling = R.every((v, k) => k === 0 || v < R[k - 1]);
  if (falling) { R.reverse(); V.reverse(); notes.push('points in falling R, turned round'); }
  const k = R.findIndex((v, i) => i > 0 && !(v > R[i - 1]));
  if (k > 0) {
    const n = lines[1 + k].n;  // (a falling list was turned only when it fell throughout)
    throw new Error(`Line ${n}: R = ${R[k]} mm does not follow the line before (R = ${R[k - 1]} mm); R must rise (or fall) steadily.`);
  }
  const points = kind === 'profileOffset' ? { R, offset: V } : { R, Z: V };
  return { kind, points, notes };
}

// The case's wheel member with these points instead of any dressed or measured wheel before.
export function withWheelPoints(extra, imported) {
  const next = structuredClone(extra || {});
  const wheel = { ...(next.wheel || {}) };
  delete wheel.profileOffset;
  delete wheel.measuredProfile;
  if (imported) wheel[imported.kind] = structuredClone(imported.points);
  if (Object.keys(wheel).length) next.wheel = wheel; else delete next.wheel;
  return next;
}

// The wheel the case gives, in words: {kind, text} or null for the conjugate wheel.
export function wheelSource(extra) {
  const w = (extra && extra.wheel) || {};
  const numbers = (list) => Array.isArray(list) && list.length > 0 && list.every(Number.isFinite);
  // Loops, not Math.min(...list): a list of 150,000 values overflows the stack.
  const lo = (list) => list.reduce((m, v) => Math.min(m, v), Infinity);
  const hi = (list) => list.reduce((m, v) => Math.max(m, v), -Infinity);
  const range = (R) => `R ${lo(R)} to ${hi(R)} mm`;
  if (w.profileOffset && numbers(w.profileOffset.R) && numbers(w.profileOffset.offset)) {
    const { R, offset } = w.profileOffset;
    return { kind: 'profileOffset', text: `a dressed wheel: an offset at ${R.length} points, ${range(R)}, ${lo(offset)} to ${hi(offset)} µm (+ = more wheel).` };
  }
  if (w.measuredProfile && numbers(w.measuredProfile.R)) return { kind: 'measuredProfile', text: `a measured wheel: ${w.measuredProfile.R.length} profile points, ${range(w.measuredProfile.R)}.` };
  if (w.profileOffset || w.measuredProfile) return { kind: w.profileOffset ? 'profileOffset' : 'measuredProfile', text: 'a wheel the calculator cannot read (see the message below).' };
  return null;
}

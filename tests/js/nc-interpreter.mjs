// A test-only reader of the NC programs (written apart from wasm/lib/nc-program.js, from the
// controls' manuals as docs/nc-programs.md quotes them): it parses the text and moves five axes
// X, Y, Z, A, B as the control would, so the tests can compare the positions with the axes to run.
//
//   readSinumerik(text) -> { start, segments: [{ PL, poly: {X: [a0..a5], ...} }], length,
//                            at(p) (p from 0 to length, the sum of the PLs) }
//     POLY blocks after a G1 block: X=PO(end, a2 .. a5) or PO[X]=(end, a2, a3), PL=length (1 when
//     missing); a0 is the axis position at the end of the preceding block and
//     a1 = (end - a0 - a2 PL^2 - ... - a5 PL^5) / PL. An axis a block leaves out stays.
//   readHeidenhain(text) -> { start, blocks: [{ end, K: {X: [K3, K2, K1]} }], at(i, t) }
//     L X.. Y.. Z.. A.. B.. then SPL blocks: X(t) = K3X t^3 + K2X t^2 + K1X t + X (X the end
//     point) with t from 1 (the start) to 0 (the end); the start must lie within 1 µm of the
//     previous end (the control's own check, an Error here); a block names two to five axes.
// Both throw an Error naming the line for anything they do not take.
export const AXES = ['X', 'Y', 'Z', 'A', 'B'];

// A Sinumerik number: 12.5, -.25, 1.5EX-9.
const SINUMERIK_NUMBER = '[-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:EX[-+]?\\d+)?';
const sinumerikNumber = (s, where) => {
  if (!new RegExp(`^${SINUMERIK_NUMBER}$`).test(s)) throw new Error(`${where}: "${s}" is not a number`);
  return Number(s.replace('EX', 'e'));
};

export function readSinumerik(text) {
  const pos = {};
  let poly = false;
  let start = null;
  const segments = [];
  const lines = text.split('\n');
  lines.forEach((raw, i) => {
    const where = `line ${i + 1}`;
    let line = raw.replace(/;.*$/, '').trim();
    if (!line) return;
    line = line.replace(/^N\d+\s*/, '');
    const words = {};
    let PL = 1;
    let motion = false;
    // PO words first: X=PO(...) and PO[X]=(...)
    line = line.replace(/([XYZAB])=PO\(([^)]*)\)|PO\[([XYZAB])\]=\(([^)]*)\)/g, (_, a1, v1, a2, v2) => {
      const axis = a1 || a2;
      const values = (v1 ?? v2).split(',').map((v) => sinumerikNumber(v.trim(), where));
      if (values.length > 5) throw new Error(`${where}: more than 5 values for ${axis}`);
      words[axis] = { end: values[0], high: values.slice(1) };
      motion = true;
      return ' ';
    });
    for (const token of line.split(/\s+/).filter(Boolean)) {
      let m;
      if (token === 'POLY') poly = true;
      else if (/^G0*1$/.test(token) || /^G0+$/.test(token)) poly = false;
      else if (token === 'G90') { /* absolute */ }
      else if (/^M\d+$/.test(token)) { /* program end */ }
      else if ((m = token.match(new RegExp(`^PL=(${SINUMERIK_NUMBER})$`)))) PL = sinumerikNumber(m[1], where);
      else if ((m = token.match(new RegExp(`^([XYZAB])=?(${SINUMERIK_NUMBER})$`)))) {
        words[m[1]] = { end: sinumerikNumber(m[2], where), high: [] };
        motion = true;
      } else throw new Error(`${where}: "${token}" is not read`);
    }
    if (!motion) return;
    if (!poly) {
      for (const [a, w] of Object.entries(words)) {
        if (w.high.length) throw new Error(`${where}: polynomial without POLY`);
        pos[a] = w.end;
      }
      return;
    }
    if (AXES.some((a) => pos[a] === undefined)) throw new Error(`${where}: POLY before every axis has a position`);
    if (!(PL > 0)) throw new Error(`${where}: PL must be positive`);
    if (!start) start = { ...pos };
    const segment = { PL, poly: {} };
    for (const a of AXES) {
      const a0 = pos[a];
      const w = words[a];
      if (!w) {
        segment.poly[a] = [a0];
        continue;
      }
      const a1 = (w.end - a0 - w.high.reduce((s, c, k) => s + c * PL ** (k + 2), 0)) / PL;
      segment.poly[a] = [a0, a1, ...w.high];
      pos[a] = w.end;
    }
    segments.push(segment);
  });
  if (!segments.length) throw new Error('no POLY block');
  const length = segments.reduce((s, g) => s + g.PL, 0);
  const value = (c, p) => c.reduceRight((s, a) => s * p + a, 0);
  const at = (p) => {
    let i = 0, p0 = 0;
    while (i < segments.length - 1 && p > p0 + segments[i].PL) p0 += segments[i++].PL;
    return Object.fromEntries(AXES.map((a) => [a, value(segments[i].poly[a], p - p0)]));
  };
  return { start, segments, length, at };
}

// A HEIDENHAIN K word's value: a signed mantissa (8 decimals at most, below 10 in size) and an
// optional exponent (-255 .. 255): K3X+1.275 E-2.
function kValue(mantissa, exponent, where) {
  const m = Number(mantissa);
  if (!(Math.abs(m) <= 9.99999999) || (mantissa.split('.')[1] || '').length > 8) throw new Error(`${where}: K mantissa ${mantissa} out of range`);
  const e = exponent === undefined ? 0 : Number(exponent);
  if (!(Number.isInteger(e) && Math.abs(e) <= 255)) throw new Error(`${where}: K exponent ${exponent} out of range`);
  return Number(`${mantissa}e${e}`);
}
const coordinate = (s, where) => {
  if (!/^[-+]\d+(\.\d{1,4})?$/.test(s) || Math.abs(Number(s)) > 99999.9999) throw new Error(`${where}: coordinate ${s} not as the TNC takes it`);
  return Number(s);
};

export function readHeidenhain(text) {
  const lines = text.trimEnd().split('\n');
  let name;
  const pos = {};
  let start = null;
  const blocks = [];
  lines.forEach((raw, i) => {
    const where = `line ${i + 1}`;
    const m = raw.match(/^(\d+) (.*)$/);
    if (!m || Number(m[1]) !== i) throw new Error(`${where}: block number ${i} expected`);
    const body = m[2];
    if (i === 0) {
      const b = body.match(/^BEGIN PGM (\w+) MM$/);
      if (!b) throw new Error(`${where}: BEGIN PGM expected`);
      name = b[1];
      return;
    }
    if (i === lines.length - 1) {
      if (body !== `END PGM ${name} MM`) throw new Error(`${where}: END PGM ${name} MM expected`);
      return;
    }
    if (body.startsWith(';')) return;
    if (body.startsWith('L ')) {
      for (const [, a, v] of body.slice(2).matchAll(/([XYZAB])([-+][\d.]+)/g)) pos[a] = coordinate(v, where);
      return;
    }
    if (!body.startsWith('SPL ')) throw new Error(`${where}: "${body.slice(0, 20)}" is not read`);
    if (AXES.some((a) => pos[a] === undefined)) throw new Error(`${where}: SPL before a linear block to its start`);
    if (!start) start = { ...pos };
    const firstK = body.indexOf(' K');
    const ends = {};
    for (const [, a, v] of body.slice(4, firstK < 0 ? undefined : firstK).matchAll(/([XYZAB])([-+][\d.]+)/g)) ends[a] = coordinate(v, where);
    const K = {};
    for (const [, order, a, mantissa, exponent] of body.slice(firstK).matchAll(/K([123])([XYZAB])([-+]\d+(?:\.\d+)?)(?: ?E([-+]?\d+))?/g)) {
      (K[a] = K[a] || {})[order] = kValue(mantissa, exponent, where);
    }
    // The manual's spline takes two to five axes: a block of one axis is not a program the control runs.
    if (Object.keys(ends).length < 2) throw new Error(`${where}: an SPL block takes two to five axes, this one ${Object.keys(ends).length}`);
    const block = { end: {}, K: {} };
    for (const a of AXES) {
      const has = ends[a] !== undefined;
      const k = K[a];
      if (has !== Boolean(k) || (k && !(k[3] !== undefined && k[2] !== undefined && k[1] !== undefined))) {
        throw new Error(`${where}: axis ${a} needs its end point and K3, K2, K1 together`);
      }
      if (!has) {
        block.end[a] = pos[a];
        block.K[a] = [0, 0, 0];
        continue;
      }
      block.end[a] = ends[a];
      block.K[a] = [k[3], k[2], k[1]];
      const begin = k[3] + k[2] + k[1] + ends[a];
      if (Math.abs(begin - pos[a]) > 0.001) throw new Error(`${where}: axis ${a} starts ${begin}, ${Math.abs(begin - pos[a])} from the previous end`);
      pos[a] = ends[a];
    }
    blocks.push(block);
  });
  if (!blocks.length) throw new Error('no SPL block');
  const at = (i, t) => Object.fromEntries(AXES.map((a) => {
    const [k3, k2, k1] = blocks[i].K[a];
    return [a, k3 * t ** 3 + k2 * t ** 2 + k1 * t + blocks[i].end[a]];
  }));
  // The derivative of the five axes with t in block i.
  const slope = (i, t) => Object.fromEntries(AXES.map((a) => {
    const [k3, k2, k1] = blocks[i].K[a];
    return [a, 3 * k3 * t * t + 2 * k2 * t + k1];
  }));
  return { name, start, blocks, at, slope };
}

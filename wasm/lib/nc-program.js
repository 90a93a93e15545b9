// NC programs that run the five axes X, Y, Z (mm) and A, B (deg) as polynomials of one parameter
// that runs linearly with the hob rotation (deg; the travel in mm on a straight gash), so every
// axis keeps its coupling to A whatever the feed (docs/nc-programs.md gives each syntax's source
// and limits). Pure: no DOM, no file system; the CLI (wasm/cli.mjs) and the page share it.
//
//   ncProgram({ axes, helical, motion, dialect, header, digits })
//     axes     {X: [a0, a1, ...], ..., B: [...]}: mm or deg per (deg or mm)^k, Maclaurin in the
//              hob rotation (deg) or the travel (mm)
//     motion   {min, max}: the motion range in deg (helical) or mm (straight)
//     dialect  'sinumerik' (POLY, degree <= 5), 'sinumerik-cubic' (POLY, degree <= 3) or
//              'heidenhain' (SPL, cubic)
//     header   {job, hob, axesWords, date, rounding: {rmsRounded, resolutionFloor} (µm) | null}
//     digits   significant digits of a polynomial coefficient (limits().correction.coefficientDigits)
//   returns {text, dialect, fileName, pieces, degree, largestDeviation: {linear (µm), rotary (deg)}}
//
// Axes of a higher degree than the control takes are split into pieces of its degree, Hermite
// pieces that match value and slope (and curvature, quintic) of the axes at every join, as many
// as keep each piece within SPLIT_TOLERANCE of the axes; the program's deviation from the axes
// (the pieces and the digits written) is measured and stated in the program.

import { polynomialAt } from './polynomial.js';

export const NC_DIALECTS = ['sinumerik', 'sinumerik-cubic', 'heidenhain'];
const AXES = ['X', 'Y', 'Z', 'A', 'B'];
const ROTARY = new Set(['A', 'B']);
const LINEAR_AXES = ['X', 'Y', 'Z'];

// The dialects: the highest degree a block takes, the decimals of a position, and the file's extension.
const DIALECT = {
  sinumerik: { degree: 5, positionDecimals: 6, extension: 'mpf', title: 'Siemens SINUMERIK 840D sl, polynomial interpolation POLY, up to degree 5 (X=PO(end,a2,a3,a4,a5))' },
  'sinumerik-cubic': { degree: 3, positionDecimals: 6, extension: 'mpf', title: 'Siemens SINUMERIK, polynomial interpolation POLY, up to degree 3 (PO[X]=(end,a2,a3))' },
  heidenhain: { degree: 3, positionDecimals: 4, extension: 'h', title: 'HEIDENHAIN TNC, spline interpolation SPL (cubic, t from 1 to 0)' },
};
// What a piece may deviate from the axes it replaces before the digits are written: far below
// the machine's resolution (0.1 µm, 1e-4 deg): mm for X, Y, Z and deg for A, B.
export const SPLIT_TOLERANCE = { linear: 1e-5, rotary: 1e-6 };
const MAX_PIECES = 2000;
// HEIDENHAIN positions: +-99999.9999 (4 decimals); K: mantissa +-9.99999999 (8 decimals),
// exponent -255 ... 255. SINUMERIK's PL (0.0001 ... 99999.9999) is 1 here: each block's parameter
// runs over [0, 1].
const POSITION_MAX = 99999.9999;
const K_DECIMALS = 8;
// A coefficient whose term moves its axis by less than this over its block (mm or deg) is left out.
const NEGLIGIBLE = 1e-8;

// --- polynomials (coefficients a0..an) -------------------------------------------------------

// The k-th derivative of a polynomial's coefficients.
function derivative(c, k = 1) {
  let d = c.slice();
  for (let i = 0; i < k; i++) d = d.slice(1).map((a, j) => a * (j + 1));
  return d;
}
// The coefficients of c(u + p) in p (Taylor shift by repeated synthetic division).
function shifted(c, u) {
  const b = c.slice();
  const n = b.length - 1;
  for (let i = 0; i < n; i++) for (let j = n - 1; j >= i; j--) b[j] += u * b[j + 1];
  return b;
}
const degreeOf = (c) => {
  let n = c.length - 1;
  while (n > 0 && c[n] === 0) n--;
  return n;
};

// The local polynomial (in p = x - u0, p in [0, h]) of degree `degree` that replaces c on
// [u0, u0 + h]: c itself shifted when its degree allows, else the Hermite piece matching value
// and slope (cubic) or value, slope and curvature (quintic) at both ends.
function piece(c, u0, h, degree) {
  const local = shifted(c, u0);
  if (degreeOf(c) <= degree) {
    const out = local.slice(0, degree + 1);
    while (out.length < degree + 1) out.push(0);
    return out;
  }
  const u1 = u0 + h;
  const F0 = polynomialAt(c, u1), F1 = polynomialAt(derivative(c), u1), F2 = polynomialAt(derivative(c, 2), u1);
  const [q0, q1, q2] = local;
  if (degree === 3) {
    // A = a2 h^2, B = a3 h^3: A + B = r0, 2 A + 3 B = r1 h.
    const r0 = F0 - (q0 + q1 * h), r1 = F1 - q1;
    const A = 3 * r0 - r1 * h, B = r1 * h - 2 * r0;
    return [q0, q1, A / h ** 2, B / h ** 3];
  }
  // Quintic: q2 = c''(u0) / 2; A = a3 h^3, B = a4 h^4, C = a5 h^5 from the three end conditions.
  const r0 = F0 - (q0 + q1 * h + q2 * h * h), r1 = F1 - (q1 + 2 * q2 * h), r2 = F2 - 2 * q2;
  const A = 10 * r0 - 4 * r1 * h + r2 * h * h / 2;
  const B = -15 * r0 + 7 * r1 * h - r2 * h * h;
  const C = 6 * r0 - 3 * r1 * h + r2 * h * h / 2;
  return [q0, q1, q2, A / h ** 3, B / h ** 4, C / h ** 5];
}

// --- numbers as the controls take them ---------------------------------------------------------

// x to `decimals` decimals, trailing zeros dropped, no negative zero: 22.4003, -0.5, 0.
export function fixed(x, decimals) {
  let s = x.toFixed(decimals);
  if (s.includes('.')) s = s.replace(/0+$/, '').replace(/\.$/, '');
  return s === '-0' ? '0' : s;
}
// x to `digits` significant digits, as a Sinumerik program writes a REAL: plain decimals, or a
// mantissa with EX and the power of ten for a very small or large value (-2.621091EX-9).
export function sinumerikReal(x, digits) {
  if (x === 0) return '0';
  const [m, e] = x.toExponential(digits - 1).split('e');
  const exponent = Number(e);
  if (exponent >= -4 && exponent < 8) return fixed(Number(x.toPrecision(digits)), Math.max(0, digits - 1 - exponent));
  return `${fixed(Number(m), digits - 1)}EX${exponent}`;
}
// A HEIDENHAIN spline parameter K: a signed mantissa of up to 8 decimals, with the exponent
// written after it when the value is not between 1 and 10 in size (K3X-2.62109123 E-3).
export function heidenhainK(x) {
  if (x === 0) return '+0.0';
  const [m, e] = x.toExponential(K_DECIMALS).split('e');
  // Always with a decimal point, as the manuals write every K (K3X+1.2750 E2, K2B-0.413 E+2).
  const mantissa = fixed(Number(m), K_DECIMALS).replace(/^(-?\d+)$/, '$1.0');
  const exponent = Number(e);
  return `${mantissa.startsWith('-') ? '' : '+'}${mantissa}${exponent === 0 ? '' : ` E${exponent > 0 ? '+' : ''}${exponent}`}`;
}
const signed = (s) => (s.startsWith('-') ? s : `+${s}`);
// A comment's text as plain printable ASCII on one line: what every control shows.
export function commentText(s, max = 100) {
  return String(s).normalize('NFKD').replace(/[\u0300-\u036f]/g, '').replace(/µ/g, 'u').replace(/[\r\n\t]+/g, ' ')
    .replace(/[^\x20-\x7e]/g, '?').replace(/;/g, ',').trim().slice(0, max);
}

// --- the pieces and the program's own reading of them ------------------------------------------

// The pieces' bounds u_0 < ... < u_n over [lo, hi]: n equal lengths.
const bounds = (lo, hi, n) => Array.from({ length: n + 1 }, (_, i) => (i === n ? hi : lo + (hi - lo) * i / n));

// The largest deviation of pieces (local polynomials per axis, over bounds u) from the axes,
// sampled at 24 points per piece: {linear (mm), rotary (deg)}.
function deviationOf(axes, u, pieces) {
  const worst = { linear: 0, rotary: 0 };
  for (let i = 0; i < pieces.length; i++) {
    const h = u[i + 1] - u[i];
    for (let s = 0; s <= 24; s++) {
      const p = h * s / 24;
      for (const a of AXES) {
        const d = Math.abs(pieces[i].at(a, p) - polynomialAt(axes[a], u[i] + p));
        const kind = ROTARY.has(a) ? 'rotary' : 'linear';
        if (d > worst[kind]) worst[kind] = d;
      }
    }
  }
  return worst;
}

// The fewest pieces of `degree` whose deviation from the axes is within SPLIT_TOLERANCE.
function pieceCount(axes, lo, hi, degree) {
  const exact = (n) => {
    const u = bounds(lo, hi, n);
    const ps = u.slice(0, -1).map((u0, i) => {
      const local = Object.fromEntries(AXES.map((a) => [a, piece(axes[a], u0, u[i + 1] - u0, degree)]));
      return { at: (a, p) => polynomialAt(local[a], p) };
    });
    const d = deviationOf(axes, u, ps);
    return d.linear <= SPLIT_TOLERANCE.linear && d.rotary <= SPLIT_TOLERANCE.rotary;
  };
  if (AXES.every((a) => degreeOf(axes[a]) <= degree)) return 1;
  let hiN = 1;
  while (!exact(hiN)) {
    hiN *= 2;
    if (hiN > MAX_PIECES) throw new Error(`The axes need more than ${MAX_PIECES} pieces of degree ${degree} to stay within ${SPLIT_TOLERANCE.linear * 1000} µm and ${SPLIT_TOLERANCE.rotary} deg; a program for this control is not written.`);
  }
  let loN = Math.floor(hiN / 2);
  while (hiN - loN > 1) {
    const mid = Math.floor((loN + hiN) / 2);
    if (exact(mid)) hiN = mid; else loN = mid;
  }
  return hiN;
}

// --- the program -------------------------------------------------------------------------------

function headerLines(d, o, n, deviation, unit) {
  const h = o.header || {};
  const lines = [`HobSharp NC program: ${d.title}`];
  const job = h.job && typeof h.job === 'object' ? h.job : null;
  if (job) {
    const parts = [['job', job.number], ['customer', job.customer], ['hob serial', job.hobSerial], ['operator', job.operator]]
      .filter(([, v]) => v !== undefined && v !== null && String(v).trim() !== '').map(([k, v]) => `${k} ${commentText(v, 40)}`);
    if (parts.length) lines.push(`Job: ${parts.join(', ')}`);
    if (job.notes && String(job.notes).trim()) lines.push(`Notes: ${commentText(job.notes)}`);
  } else {
    lines.push('Job: (none given)');
  }
  if (h.hob) lines.push(`Hob: ${commentText(h.hob, 120)}`);
  if (h.axesWords) lines.push(`Axes: ${commentText(h.axesWords, 120)}`);
  if (h.date) lines.push(`Date: ${commentText(h.date, 40)}`);
  const per = o.helical ? 'deg of hob rotation' : 'mm of travel';
  const lo = o.motion.min;
  lines.push(`Units: X Y Z mm, A B deg. Motion range ${fixed(lo, 4)} to ${fixed(o.motion.max, 4)} ${unit} (${o.helical ? 'hob rotation' : 'travel'}).`);
  if (o.dialect === 'heidenhain') {
    lines.push(`${n} SPL block${n > 1 ? 's' : ''}, each ${fixed((o.motion.max - lo) / n, 6)} ${per}; t runs from 1 at a block's start to 0 at its end.`);
  } else {
    lines.push(`${n} POLY block${n > 1 ? 's' : ''} of degree ${d.degree} at most, each ${fixed((o.motion.max - lo) / n, 6)} ${per}; p runs from 0 at a block's start to PL = 1 at its end,`);
    lines.push(`linearly with it, so a2 .. a${d.degree} are mm or deg over the block, of the size of the motion itself.`);
  }
  lines.push(`Largest deviation of this program from the axes: ${fixed(deviation.linear * 1000, 4)} um (X Y Z), ${sinumerikReal(deviation.rotary, 2).replace('EX', 'e')} deg (A B).`);
  const r = h.rounding;
  if (r && Number.isFinite(r.rmsRounded)) {
    lines.push(`Rounding (the correction's figures): face on the identified machine with these coefficients ${sinumerikReal(r.rmsRounded, 3).replace('EX', 'e')} um rms;`);
    if (Number.isFinite(r.resolutionFloor)) lines.push(`the floor the axes' position resolution sets ${sinumerikReal(r.resolutionFloor, 3).replace('EX', 'e')} um rms.`);
  }
  lines.push('Feed: the machine\'s grinding feed, modal, programmed before this program.');
  return lines;
}

// The program for a dialect. Throws an Error naming what the control cannot take.
export function ncProgram(o) {
  const d = DIALECT[o.dialect];
  if (!d) throw new Error(`NC program: the control must be one of ${NC_DIALECTS.join(', ')}; got ${o.dialect}.`);
  const digits = o.digits || 10;
  const lo = o.motion.min, hi = o.motion.max;
  if (!(Number.isFinite(lo) && Number.isFinite(hi) && hi > lo)) throw new Error('NC program: the motion range is empty.');
  const axes = {};
  for (const a of AXES) {
    const c = o.axes[a];
    if (!Array.isArray(c) || !c.length || !c.every(Number.isFinite)) throw new Error(`NC program: axis ${a} has no finite coefficients.`);
    axes[a] = c.slice();
  }
  const unit = o.helical ? 'deg' : 'mm';
  const sinumerik = o.dialect !== 'heidenhain';
  const n = pieceCount(axes, lo, hi, d.degree);
  const u = bounds(lo, hi, n);
  const position = (x) => fixed(x, d.positionDecimals);
  const start = Object.fromEntries(AXES.map((a) => [a, Number(position(polynomialAt(axes[a], lo)))]));
  if (AXES.some((a) => Math.abs(start[a]) > POSITION_MAX)) throw new Error(`NC program: a position beyond +-${POSITION_MAX}.`);
  const body = [];
  // The program's reading of its own blocks, from the numbers written (for the deviation).
  const read = [];
  let at = { ...start };
  if (sinumerik) {
    const block = (i, text) => `N${(i + 1) * 10} ${text}`;
    body.push(block(0, `G90 G1 ${AXES.map((a) => `${a}${position(start[a])}`).join(' ')}`));
    // Each block's parameter runs from 0 to PL = 1 over the block, linearly with the hob rotation
    // (p = (rotation - u_i) / h): its coefficients are mm or deg over the block, not per deg^k. A
    // per-degree a5 is about 1e-9 mm/deg^5, which a control that rounds a coefficient to its
    // position resolution, as SINUMERIK does with decimals beyond an address's places
    // (docs/nc-programs.md), would write as 0.
    const PL = 1;
    for (let i = 0; i < n; i++) {
      const h = u[i + 1] - u[i];
      const words = [];
      const polys = {};
      for (const a of AXES) {
        const local = piece(axes[a], u[i], h, d.degree).map((c, k) => c * h ** k);
        const end = Number(position(polynomialAt(local, PL)));
        // a2 .. a5 to the digits, each left out when its term over the block is negligible, and
        // the trailing zeros dropped (the control takes them as 0).
        const high = local.slice(2).map((c, j) => (Math.abs(c) * PL ** (j + 2) < NEGLIGIBLE ? 0 : Number(c.toPrecision(digits))));
        while (high.length && high[high.length - 1] === 0) high.pop();
        const a0 = at[a];
        const a1 = (end - a0 - high.reduce((s, c, j) => s + c * PL ** (j + 2), 0)) / PL;
        polys[a] = [a0, a1, ...high];
        if (end === a0 && !high.length) continue;   // the axis stays where it is
        const values = [position(end), ...high.map((c) => sinumerikReal(c, digits))].join(',');
        words.push(d.degree === 5 ? `${a}=PO(${values})` : `PO[${a}]=(${values})`);
        at[a] = end;
      }
      body.push(block(i + 1, `${i === 0 ? 'POLY ' : ''}${words.join(' ')} PL=${PL}`));
      read.push({ at: (a, p) => polynomialAt(polys[a], p / h) });
    }
    body.push(block(n + 1, 'G1 ; polynomial interpolation off'));
    body.push(block(n + 2, 'M30'));
  } else {
    body.push(`L ${AXES.map((a) => `${a}${signed(position(start[a]))}`).join(' ')}`);
    for (let i = 0; i < n; i++) {
      const h = u[i + 1] - u[i];
      const ends = [], ks = [], polys = {};
      for (const a of AXES) {
        // The cubic in p = h (1 - t) written in t: X(t) = K3 t^3 + K2 t^2 + K1 t + X(end).
        const local = piece(axes[a], u[i], h, 3);
        const end = Number(position(polynomialAt(local, h)));
        const [, , c2, c3] = local;
        // d/dt = -h d/dp: K3 and K2 from the piece, K1 such that t = 1 is the start written.
        const K3 = -c3 * h ** 3;
        const K2 = 3 * c3 * h ** 3 + c2 * h * h;
        const k3 = Math.abs(K3) < NEGLIGIBLE ? 0 : Number(heidenhainK(K3).replace(' ', ''));
        const k2 = Math.abs(K2) < NEGLIGIBLE ? 0 : Number(heidenhainK(K2).replace(' ', ''));
        const K1 = at[a] - end - k3 - k2;
        const k1 = Math.abs(K1) < NEGLIGIBLE ? 0 : Number(heidenhainK(K1).replace(' ', ''));
        polys[a] = { end, k3, k2, k1 };
      }
      // An axis that stays where it is is left out, unless fewer than two would be written: the
      // spline takes two to five axes, and the manual's example writes a still axis with K = 0.
      const moving = AXES.filter((a) => !(polys[a].end === at[a] && polys[a].k3 === 0 && polys[a].k2 === 0 && polys[a].k1 === 0));
      const still = AXES.filter((a) => !moving.includes(a));
      const written = AXES.filter((a) => moving.includes(a) || still.indexOf(a) < 2 - moving.length);
      for (const a of written) {
        const q = polys[a];
        ends.push(`${a}${signed(position(q.end))}`);
        ks.push(`K3${a}${heidenhainK(q.k3)} K2${a}${heidenhainK(q.k2)} K1${a}${heidenhainK(q.k1)}`);
        at[a] = q.end;
      }
      if (AXES.some((a) => Math.abs(at[a]) > POSITION_MAX)) throw new Error(`NC program: a position beyond +-${POSITION_MAX}.`);
      body.push(`SPL ${ends.join(' ')} ${ks.join(' ')}`);
      read.push({ at: (a, p) => { const t = 1 - p / h; const q = polys[a]; return ((q.k3 * t + q.k2) * t + q.k1) * t + q.end; } });
    }
  }
  const deviation = deviationOf(axes, u, read);
  const largestDeviation = { linear: deviation.linear * 1000, rotary: deviation.rotary };
  const name = programName(o.header, o.dialect);
  const comments = headerLines(d, o, n, deviation, unit);
  let text;
  if (sinumerik) {
    text = [...comments.map((c) => `; ${c}`), ...body].join('\n') + '\n';
  } else {
    const lines = [`BEGIN PGM ${name} MM`, ...comments.map((c) => `; ${c}`), ...body, `END PGM ${name} MM`];
    text = lines.map((l, i) => `${i} ${l}`).join('\n') + '\n';
  }
  return { text, dialect: o.dialect, fileName: `${name}.${d.extension}`, pieces: n, degree: d.degree, largestDeviation };
}

// The program's name, also its file's: letters, digits and underscores, from the job number or
// the hob's module (to 4 significant digits: M8_11, not a derived case's M8_110317242852) and the
// date (HOBSHARP_M7_20261126), at most 24 characters (SINUMERIK's limit; HEIDENHAIN's name is
// kept the same). The date is whole or left out: a long job number cut it to "202612", which
// reads as another date. The cubic SINUMERIK program ends in _P3 (POLY degree 3): both SINUMERIK
// dialects write .mpf, and one name for two programs let the second download replace the first.
const NAME_MOST = 24;
export function programName(header = {}, dialect = 'sinumerik') {
  const job = header && header.job && header.job.number !== undefined ? String(header.job.number) : '';
  const date = header && header.date ? String(header.date).replace(/[^0-9]/g, '') : '';
  const module = header && Number.isFinite(header.module) ? `M${String(Number(header.module.toPrecision(4))).replace('.', '_')}` : '';
  const suffix = dialect === 'sinumerik-cubic' ? '_P3' : '';
  const most = NAME_MOST - suffix.length;
  const clean = (t) => t.toUpperCase().replace(/[^A-Z0-9_]/g, '_').replace(/_+/g, '_');
  const base = clean(['HOBSHARP', job ? commentText(job, 20) : module].filter(Boolean).join('_')).slice(0, most).replace(/_$/, '');
  return (date && base.length + 1 + date.length <= most ? `${base}_${date}` : base) + suffix;
}

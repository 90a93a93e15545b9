// A topography as an ISO 5436-2 X3P file (pure, with Node tests): the openGPS container that
// surface-measuring software reads and writes. An .x3p is a zip holding main.xml (Record1: the
// axes; Record2: who, what and when; Record3: the grid's size and a link to its points; Record4:
// the checksum file's name), bindata/data.bin (the points, little-endian, x index fastest) and
// md5checksum.hex (the MD5 of main.xml). Element names follow the openGPS schema
// ISO5436_2_XML.xsd (namespace http://www.opengps.eu/2008/ISO5436_2); docs/x3p.md gives the
// sources.
//
// The face's grid maps onto X3P's axes: X = x along the gash (columns), Y = r, the radius (rows,
// root to tip), Z = the normal deviation (plus = excess material). X3P gives every coordinate in
// metres: x and r are written as offset + index * increment (mm / 1000), the deviation as
// float64 metres (µm / 1e6).
import { Unzip, UnzipInflate, unzipSync, zipSync } from 'fflate';
import { XMLParser, XMLValidator } from 'fast-xml-parser';
import { md5 } from '@noble/hashes/legacy.js';
import { passBound } from './pass-bound.js';

export const X3P_NAMESPACE = 'http://www.opengps.eu/2008/ISO5436_2';
export const MAIN_FILE = 'main.xml';
export const CHECKSUM_FILE = 'md5checksum.hex';
export const DATA_FILE = 'bindata/data.bin';
// The largest .x3p the page takes: a grid of at most 201 x 201 float64 points is 323 kB.
export const MAX_X3P_BYTES = 16 * 1024 * 1024;
// The largest main.xml, and point file, read out of the zip (their sizes as the zip declares them).
const MAX_MAIN_BYTES = 8 * 1024 * 1024;
const MAX_DATA_BYTES = 16 * 1024 * 1024;
// The most lines and points a file may declare (SizeX, SizeY); the face grid has at most 201 x 201,
// which the check against the case's grid enforces.
const MAX_LINES = 10000;
const MAX_POINTS = 1000000;
// How far a file's x or r line may lie from the face grid's, mm (the same as a CSV's positions).
export const X3P_POSITION_TOLERANCE = 0.01;
// Deviations this large (m) are no grinding error: the file holds µm or mm where X3P wants metres.
const IMPLAUSIBLE_METRES = 0.01;

const MM_PER_M = 1000;
const UM_PER_M = 1e6;

// The double next to v, up (+1) or down (-1).
function nextDouble(v, dir) {
  if (v === 0) return dir * Number.MIN_VALUE;
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, v);
  view.setBigInt64(0, view.getBigInt64(0) + BigInt((v > 0) === (dir > 0) ? 1 : -1));
  return view.getFloat64(0);
}

// A stored height (m) in µm: of the doubles within one unit in the last place of m x 1e6 that
// write back as the same m, the one with the shortest decimal form. So a value of up to 15
// significant digits (as a measuring machine or a person writes it) reads back exactly, and any
// other within one unit in the last place; written again, the file holds the same m.
export function metresToMicrons(m) {
  const v = m * UM_PER_M;
  const same = [v, nextDouble(v, 1), nextDouble(v, -1)].filter((c) => Number.isFinite(c) && c / UM_PER_M === m);
  return same.reduce((best, c) => (String(c).length < String(best).length ? c : best), same[0] ?? v);
}

const hex = (bytes) => Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
export const md5Hex = (bytes) => hex(md5(bytes));

const escapeXml = (text) => String(text).replace(/[<>&"']/g, (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;', "'": '&apos;' })[c]);
// A number as xsd:double text that reads back to the same double.
const num = (v) => String(v);

// The step of equally spaced lines, mm; throws when they are not equally spaced (an X3P matrix
// axis is offset + index * increment).
function incrementOf(lines, name) {
  if (lines.length < 2) throw new Error(`The ${name} grid has ${lines.length} line; an X3P surface needs at least 2.`);
  const step = (lines[lines.length - 1] - lines[0]) / (lines.length - 1);
  const tol = 1e-9 * lines.reduce((m, v) => Math.max(m, Math.abs(v)), 1);
  lines.forEach((v, i) => {
    if (Math.abs(v - (lines[0] + i * step)) > tol) throw new Error(`The ${name} grid's lines are not equally spaced (line ${i + 1} at ${v} mm).`);
  });
  return step;
}

// main.xml for a grid of sizeX x sizeY points with the data file's MD5.
function mainXml({ r, x, dataMd5, date, comment, kind }) {
  const dx = incrementOf(x, 'axial');
  const dr = incrementOf(r, 'radial');
  const axis = (name, type, dataType, increment, offset) =>
    `      <${name}>\n        <AxisType>${type}</AxisType>\n        <DataType>${dataType}</DataType>\n` +
    `        <Increment>${num(increment)}</Increment>\n        <Offset>${num(offset)}</Offset>\n      </${name}>\n`;
  return '<?xml version="1.0" encoding="UTF-8"?>\n' +
    `<p:ISO5436_2 xmlns:p="${X3P_NAMESPACE}" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" ` +
    `xsi:schemaLocation="${X3P_NAMESPACE} ${X3P_NAMESPACE}/ISO5436_2.xsd">\n` +
    '  <Record1>\n    <Revision>ISO5436 - 2000</Revision>\n    <FeatureType>SUR</FeatureType>\n    <Axes>\n' +
    axis('CX', 'I', 'D', dx / MM_PER_M, x[0] / MM_PER_M) +
    axis('CY', 'I', 'D', dr / MM_PER_M, r[0] / MM_PER_M) +
    axis('CZ', 'A', 'D', 1, 0) +
    '    </Axes>\n  </Record1>\n' +
    `  <Record2>\n    <Date>${escapeXml(date)}</Date>\n    <Creator>HobSharp</Creator>\n` +
    '    <Instrument>\n      <Manufacturer>HobSharp</Manufacturer>\n      <Model>hob sharpening calculator</Model>\n' +
    '      <Serial>not applicable</Serial>\n      <Version>1</Version>\n    </Instrument>\n' +
    `    <ProbingSystem>\n      <Type>Software</Type>\n      <Identification>HobSharp ${escapeXml(kind)}</Identification>\n    </ProbingSystem>\n` +
    `    <Comment>${escapeXml(comment)}</Comment>\n  </Record2>\n` +
    `  <Record3>\n    <MatrixDimension>\n      <SizeX>${x.length}</SizeX>\n      <SizeY>${r.length}</SizeY>\n      <SizeZ>1</SizeZ>\n    </MatrixDimension>\n` +
    `    <DataLink>\n      <PointDataLink>${DATA_FILE}</PointDataLink>\n      <MD5ChecksumPointData>${dataMd5}</MD5ChecksumPointData>\n    </DataLink>\n  </Record3>\n` +
    `  <Record4>\n    <ChecksumFile>${CHECKSUM_FILE}</ChecksumFile>\n  </Record4>\n</p:ISO5436_2>\n`;
}

// The comment each kind of topography carries in Record2.
export const X3P_KINDS = {
  measured: 'measured normal deviation of the rake face, as given to HobSharp',
  predicted: 'normal deviation of the rake face predicted after the correction on the identified machine (re-simulated with the identified machine error)',
  simulated: 'normal deviation of the rake face simulated for the axes run',
};

// {r: [mm], x: [mm], values: rows (one per r) of µm (one per x)} -> the .x3p as bytes.
// kind: a key of X3P_KINDS; date: a Date (Record2's Date, and the zip entries' time).
export function writeX3p({ r, x, values, kind = 'measured', date = new Date(), note = '' }) {
  if (!Array.isArray(values) || values.length !== r.length || values.some((row) => !Array.isArray(row) || row.length !== x.length)) {
    throw new Error(`The topography is not ${r.length} rows of ${x.length} values.`);
  }
  const points = new Float64Array(r.length * x.length);
  values.forEach((row, j) => row.forEach((v, i) => {
    if (!Number.isFinite(v)) throw new Error(`The topography's value at row ${j + 1}, column ${i + 1} is not a number.`);
    points[j * x.length + i] = v / UM_PER_M;
  }));
  const data = new Uint8Array(points.byteLength);
  const view = new DataView(data.buffer);
  points.forEach((v, k) => view.setFloat64(k * 8, v, true));
  const comment = `${X3P_KINDS[kind] || kind}. X: axial position along the gash; Y: radius, root to tip; ` +
    `Z: normal deviation, plus = excess material. Metres.${note ? ` ${note}` : ''}`;
  const main = new TextEncoder().encode(mainXml({ r, x, dataMd5: md5Hex(data), date: date.toISOString(), comment, kind }));
  const checksum = new TextEncoder().encode(`${md5Hex(main)} *${MAIN_FILE}\n`);
  return zipSync({ [MAIN_FILE]: main, [DATA_FILE]: data, [CHECKSUM_FILE]: checksum }, { level: 6, mtime: date });
}

// ---- reading ----

const fail = (where, text) => { throw new Error(`${where}: ${text}`); };

// The element at path (names below the root) or an Error naming it; each element appears once.
function element(root, path, { optional = false } = {}) {
  let node = root;
  const names = path.split('/');
  for (let k = 0; k < names.length; k += 1) {
    const here = names.slice(0, k + 1).join('/');
    node = node && typeof node === 'object' ? node[names[k]] : undefined;
    if (node === undefined) {
      if (optional) return undefined;
      fail(`${MAIN_FILE}, ${here}`, 'missing.');
    }
    if (Array.isArray(node)) fail(`${MAIN_FILE}, ${here}`, `appears ${node.length} times; the format has it once.`);
  }
  return node;
}
const text = (root, path, options) => {
  const v = element(root, path, options);
  if (v === undefined) return undefined;
  if (typeof v === 'object') fail(`${MAIN_FILE}, ${path}`, 'holds elements where a value belongs.');
  return String(v).trim();
};
const NUMBER = /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/;
function number(root, path, { optional = false, fallback } = {}) {
  const t = text(root, path, { optional });
  if (t === undefined) return fallback;
  if (!NUMBER.test(t) || !Number.isFinite(Number(t))) fail(`${MAIN_FILE}, ${path}`, `"${t.slice(0, 30)}" is not a number.`);
  return Number(t);
}
function count(root, path) {
  const t = text(root, path);
  if (!/^\d+$/.test(t)) fail(`${MAIN_FILE}, ${path}`, `"${t.slice(0, 30)}" is not a whole number.`);
  return Number(t);
}

// The document's text, checked before any XML parser sees it: UTF-8, no DOCTYPE (so no entity
// can be declared, and none expanded: the "billion laughs"), well formed.
function parseMain(bytes) {
  let xml;
  try {
    xml = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    fail(MAIN_FILE, 'is not UTF-8 text.');
  }
  xml = xml.replace(/^\uFEFF/, '');
  const declared = /<!(DOCTYPE|ENTITY)/i.exec(xml);
  if (declared) {
    const line = xml.slice(0, declared.index).split('\n').length;
    fail(`${MAIN_FILE}, line ${line}`, `a <!${declared[1].toUpperCase()}> declaration; X3P has none, and the page expands no entities.`);
  }
  let doc;
  try {
    const valid = XMLValidator.validate(xml);
    if (valid !== true) fail(`${MAIN_FILE}, line ${valid.err.line}`, `${valid.err.msg} The XML is not well formed (cut short?).`);
    doc = new XMLParser({
      ignoreAttributes: true, removeNSPrefix: true, parseTagValue: false, ignoreDeclaration: true,
      ignorePiTags: true, isArray: (name) => name === 'Datum',
    }).parse(xml);
  } catch (e) {
    if (e.message.startsWith(MAIN_FILE)) throw e;
    fail(MAIN_FILE, `${e.message}; the XML is not read.`);
  }
  const roots = Object.keys(doc);
  if (roots.length !== 1 || roots[0] !== 'ISO5436_2') fail(MAIN_FILE, `the root element is ${roots.map((r) => `<${r}>`).join(', ') || 'missing'}, not <ISO5436_2>.`);
  if (Array.isArray(doc.ISO5436_2) || typeof doc.ISO5436_2 !== 'object') fail(`${MAIN_FILE}, ISO5436_2`, 'holds no records.');
  return doc.ISO5436_2;
}

function axisOf(root, name) {
  const at = `Record1/Axes/${name}`;
  const axisType = text(root, `${at}/AxisType`);
  const dataType = text(root, `${at}/DataType`, { optional: true });
  if (!['I', 'A'].includes(axisType)) fail(`${MAIN_FILE}, ${at}/AxisType`, `"${axisType}" is neither I (incremental) nor A (absolute).`);
  if (dataType !== undefined && !['I', 'L', 'F', 'D'].includes(dataType)) fail(`${MAIN_FILE}, ${at}/DataType`, `"${dataType}" is none of I, L, F, D.`);
  return {
    axisType, dataType,
    increment: number(root, `${at}/Increment`, { optional: name === 'CZ', fallback: 1 }),
    offset: number(root, `${at}/Offset`, { optional: true, fallback: 0 }),
  };
}

// The most bytes an entry the reader needs may hold (-1: an entry it does not read).
const limitOf = (name) => (name === MAIN_FILE || name === CHECKSUM_FILE ? MAX_MAIN_BYTES : name.startsWith('bindata/') ? MAX_DATA_BYTES : -1);
// The zip is fed to the inflater in pieces this large: one piece inflates to at most about
// 1032 times as much (deflate's largest ratio), 1 MB, before the count of bytes is checked (larger
// pieces inflate more per check, and fflate takes longer per byte on them).
const PIECE_BYTES = 1024;
const zipError = (e) => new Error(`The file is not a readable X3P container (zip): ${e.message}.`);

// The zip's entries that the reader needs, each no larger than its limit; throws naming the file.
// The central directory gives the entries and the sizes they declare; each entry is then inflated
// piece by piece, counting its bytes, and refused as soon as it runs past its declared size: a
// deflate stream can run on far beyond what its entry declares (4 MB that inflate to 4 GB), and
// is never inflated to its end.
function entriesOf(bytes) {
  if (!(bytes instanceof Uint8Array)) bytes = new Uint8Array(bytes);
  if (bytes.length > MAX_X3P_BYTES) {
    throw new Error(`The file is ${(bytes.length / 1048576).toFixed(1)} MB; an X3P topography of at most 201 × 201 points is a few hundred kB (the limit is ${MAX_X3P_BYTES / 1048576} MB).`);
  }
  if (bytes.length < 4 || bytes[0] !== 0x50 || bytes[1] !== 0x4b) {
    throw new Error('The file is not an X3P container: an .x3p is a zip archive, and this does not start as one.');
  }
  const declared = new Map();
  try {
    unzipSync(bytes, { filter: (f) => { if (limitOf(f.name) >= 0 && !declared.has(f.name)) declared.set(f.name, f.originalSize); return false; } });
  } catch (e) {
    throw zipError(e);
  }
  const tooLarge = [...declared].find(([name, size]) => size > limitOf(name));
  if (tooLarge) throw new Error(`${tooLarge[0]} in the X3P container is larger than a topography needs; refused.`);
  const files = {};
  let failure = null;
  const unzip = new Unzip((file) => {
    const size = declared.get(file.name);
    if (size === undefined || failure || files[file.name]) return;  // not started: its bytes are passed over
    const out = new Uint8Array(size);
    let n = 0;
    file.ondata = (error, chunk, final) => {
      if (failure) return;
      if (error) { failure = zipError(error); return; }
      if (n + chunk.length > size) {
        failure = new Error(`${file.name} in the X3P container inflates to more than the ${size} bytes its entry declares: a damaged or hostile file; refused.`);
        return;
      }
      out.set(chunk, n);
      n += chunk.length;
      if (!final) return;
      if (n !== size) failure = new Error(`${file.name} in the X3P container inflates to ${n} bytes, not the ${size} its entry declares: the file is damaged; refused.`);
      else files[file.name] = out;
    };
    file.start();
  });
  unzip.register(UnzipInflate);
  try {
    for (let k = 0; k < bytes.length && !failure; k += PIECE_BYTES) unzip.push(bytes.subarray(k, k + PIECE_BYTES), k + PIECE_BYTES >= bytes.length);
  } catch (e) {
    failure = failure || zipError(e);
  }
  if (failure) throw failure;
  if (!files[MAIN_FILE]) throw new Error(`The X3P container holds no ${MAIN_FILE} (the document that describes the surface).`);
  return files;
}

// The points of Record3 as a Float64Array of z in the file's units (before CZ's increment and
// offset), x index fastest.
function pointsOf(root, files, size, cz) {
  const link = element(root, 'Record3/DataLink', { optional: true });
  const list = element(root, 'Record3/DataList', { optional: true });
  if (link === undefined && list === undefined) fail(`${MAIN_FILE}, Record3`, 'has neither DataLink nor DataList: no points.');
  const z = new Float64Array(size);
  if (list !== undefined) {
    const datum = list && list.Datum;
    if (!Array.isArray(datum)) fail(`${MAIN_FILE}, Record3/DataList`, 'holds no Datum.');
    if (datum.length !== size) fail(`${MAIN_FILE}, Record3/DataList`, `holds ${datum.length} Datum elements; MatrixDimension gives ${size}.`);
    datum.forEach((d, k) => {
      const t = typeof d === 'object' ? '' : String(d).trim();
      if (t === '') fail(`${MAIN_FILE}, Record3/DataList/Datum[${k + 1}]`, 'is empty: a point the instrument did not measure. The correction needs every grid point.');
      const v = t.split(';').pop();
      if (!NUMBER.test(v)) fail(`${MAIN_FILE}, Record3/DataList/Datum[${k + 1}]`, `"${t.slice(0, 30)}" is not a number.`);
      z[k] = Number(v);
    });
    return z;
  }
  const path = text(root, 'Record3/DataLink/PointDataLink');
  const stated = text(root, 'Record3/DataLink/MD5ChecksumPointData').toLowerCase();
  const data = files[path];
  if (!data) fail(`${MAIN_FILE}, Record3/DataLink/PointDataLink`, `names ${path}, which the container does not hold.`);
  if (md5Hex(data) !== stated) fail(path, `its MD5 is ${md5Hex(data)}, but Record3/DataLink/MD5ChecksumPointData says ${stated}: the points are damaged.`);
  const width = { I: 2, L: 4, F: 4, D: 8 }[cz.dataType];
  if (data.length !== size * width) fail(path, `holds ${data.length} bytes; ${size} points of type ${cz.dataType} take ${size * width}.`);
  const view = new DataView(data.buffer, data.byteOffset, data.byteLength);
  const get = { I: (k) => view.getInt16(k * 2, true), L: (k) => view.getInt32(k * 4, true), F: (k) => view.getFloat32(k * 4, true), D: (k) => view.getFloat64(k * 8, true) }[cz.dataType];
  for (let k = 0; k < size; k += 1) z[k] = get(k);
  const validLink = text(root, 'Record3/DataLink/ValidPointsLink', { optional: true });
  if (validLink !== undefined) {
    const valid = files[validLink];
    if (!valid) fail(`${MAIN_FILE}, Record3/DataLink/ValidPointsLink`, `names ${validLink}, which the container does not hold.`);
    const validMd5 = text(root, 'Record3/DataLink/MD5ChecksumValidPoints', { optional: true });
    if (validMd5 !== undefined && md5Hex(valid) !== validMd5.toLowerCase()) fail(validLink, `its MD5 does not match Record3/DataLink/MD5ChecksumValidPoints.`);
    for (let k = 0; k < size; k += 1) {
      if (!((valid[k >> 3] || 0) & (1 << (k & 7)))) z[k] = NaN;
    }
  }
  return z;
}

// An .x3p's bytes -> {r: [mm], x: [mm], values: rows (one per r) of µm, meta: {revision, date,
// creator, instrument, comment}, notes: [sentences]}. Throws an Error whose message starts with
// the file or element where the container goes wrong (main.xml, Record1/Axes/CX/AxisType, ...).
export function readX3p(bytes) {
  const files = entriesOf(bytes);
  const main = files[MAIN_FILE];
  const root = parseMain(main);
  // Record4: the checksum file, as md5sum writes it ("<32 hex digits> *main.xml").
  const checksumName = text(root, 'Record4/ChecksumFile');
  const sums = files[checksumName];
  if (!sums) fail(`${MAIN_FILE}, Record4/ChecksumFile`, `names ${checksumName}, which the container does not hold.`);
  const stated = new TextDecoder().decode(sums).trim().split(/\s+/)[0].toLowerCase();
  if (!/^[0-9a-f]{32}$/.test(stated)) fail(checksumName, 'does not start with an MD5 checksum (32 hexadecimal digits).');
  if (stated !== md5Hex(main)) fail(checksumName, `says ${stated}, but ${MAIN_FILE}'s MD5 is ${md5Hex(main)}: the document is damaged or was changed.`);
  // Record1: a surface on a grid, in metres.
  const revision = text(root, 'Record1/Revision');
  const feature = text(root, 'Record1/FeatureType');
  if (feature !== 'SUR') fail(`${MAIN_FILE}, Record1/FeatureType`, `is ${feature}; a rake-face topography is a surface, SUR (PRF is a profile, PCL a point cloud).`);
  const cx = axisOf(root, 'CX'), cy = axisOf(root, 'CY'), cz = axisOf(root, 'CZ');
  if (cx.axisType !== 'I') fail(`${MAIN_FILE}, Record1/Axes/CX/AxisType`, 'is A (absolute, a position per point); the page reads a grid, I (incremental).');
  if (cy.axisType !== 'I') fail(`${MAIN_FILE}, Record1/Axes/CY/AxisType`, 'is A (absolute, a position per point); the page reads a grid, I (incremental).');
  if (cz.axisType !== 'A') fail(`${MAIN_FILE}, Record1/Axes/CZ/AxisType`, 'is I; the heights are absolute, A.');
  if (cz.dataType === undefined) fail(`${MAIN_FILE}, Record1/Axes/CZ/DataType`, 'missing.');
  [['CX', cx], ['CY', cy]].forEach(([name, a]) => {
    if (!(a.increment > 0)) fail(`${MAIN_FILE}, Record1/Axes/${name}/Increment`, `is ${a.increment}; the lines' spacing must be positive.`);
  });
  if (element(root, 'Record1/Axes/Rotation', { optional: true }) !== undefined) {
    const rot = ['r11', 'r12', 'r13', 'r21', 'r22', 'r23', 'r31', 'r32', 'r33'].map((n) => number(root, `Record1/Axes/Rotation/${n}`));
    if (rot.some((v, k) => Math.abs(v - ([0, 4, 8].includes(k) ? 1 : 0)) > 1e-12)) {
      fail(`${MAIN_FILE}, Record1/Axes/Rotation`, 'is not the identity; the page reads the grid in the face\'s own axes only.');
    }
  }
  // Record3: the grid's size and its points.
  if (element(root, 'Record3/ListDimension', { optional: true }) !== undefined) fail(`${MAIN_FILE}, Record3/ListDimension`, 'a list of points; the page reads a matrix, MatrixDimension.');
  const sizeX = count(root, 'Record3/MatrixDimension/SizeX');
  const sizeY = count(root, 'Record3/MatrixDimension/SizeY');
  const sizeZ = count(root, 'Record3/MatrixDimension/SizeZ');
  if (sizeZ !== 1) fail(`${MAIN_FILE}, Record3/MatrixDimension/SizeZ`, `is ${sizeZ}; a topography has one layer.`);
  if (sizeX < 2 || sizeY < 2 || sizeX > MAX_LINES || sizeY > MAX_LINES || sizeX * sizeY > MAX_POINTS) fail(`${MAIN_FILE}, Record3/MatrixDimension`, `${sizeX} × ${sizeY} points is no face grid (2 to 201 lines each way).`);
  const raw = pointsOf(root, files, sizeX * sizeY, cz);
  const scale = ['I', 'L'].includes(cz.dataType) ? cz.increment : 1;
  const values = [];
  for (let j = 0; j < sizeY; j += 1) {
    const row = [];
    for (let i = 0; i < sizeX; i += 1) {
      const m = raw[j * sizeX + i] * scale + cz.offset;
      if (!Number.isFinite(m)) fail(`${MAIN_FILE}, Record3`, `the point at x index ${i}, y index ${j} is missing (not measured). The correction needs every grid point.`);
      row.push(metresToMicrons(m));
    }
    values.push(row);
  }
  let largest = 0;  // a loop: a file's values are never spread into a call (a million would overflow the stack)
  for (const row of values) for (const v of row) largest = Math.max(largest, Math.abs(v));
  largest /= UM_PER_M;
  if (largest > IMPLAUSIBLE_METRES) {
    fail(`${MAIN_FILE}, Record1/Axes/CZ`, `deviations up to ${Number(largest.toPrecision(3))} m: no grinding error is that large. X3P stores metres; were these written in µm or mm?`);
  }
  const x = Array.from({ length: sizeX }, (_, i) => (cx.offset + i * cx.increment) * MM_PER_M);
  const r = Array.from({ length: sizeY }, (_, j) => (cy.offset + j * cy.increment) * MM_PER_M);
  const meta = {
    revision,
    date: text(root, 'Record2/Date', { optional: true }),
    creator: text(root, 'Record2/Creator', { optional: true }),
    instrument: ['Manufacturer', 'Model'].map((n) => text(root, `Record2/Instrument/${n}`, { optional: true })).filter(Boolean).join(' '),
    comment: text(root, 'Record2/Comment', { optional: true }),
  };
  const notes = [`an X3P surface of ${sizeX} × ${sizeY} points (${cz.dataType === 'D' ? 'float64' : { F: 'float32', L: 'int32', I: 'int16' }[cz.dataType]})`];
  if (meta.instrument) notes.push(`from ${meta.instrument}`);
  return { r, x, values, meta, notes };
}

const fmt = (v) => String(Math.round(v * 1e4) / 1e4);

// The values of a read X3P on the face grid {r, x} (mm), or an Error naming the axis whose
// lines differ: X3P's Y lines must be the grid's radial lines and its X lines the axial ones,
// each within X3P_POSITION_TOLERANCE.
export function x3pOnGrid(read, grid) {
  const check = (lines, gridLines, axis, what, name) => {
    if (lines.length !== gridLines.length) {
      throw new Error(`${MAIN_FILE}, Record3/MatrixDimension/Size${axis}: ${lines.length} ${what} lines, but the grid has ${gridLines.length}. Set the grid lines (Polynomials and measuring grid) to the measured positions.`);
    }
    const k = lines.findIndex((v, i) => Math.abs(v - gridLines[i]) > X3P_POSITION_TOLERANCE);
    if (k >= 0) {
      throw new Error(`${MAIN_FILE}, Record1/Axes/C${axis}: ${what} line ${k + 1} is at ${name} = ${fmt(lines[k])} mm, but the grid's is at ${name} = ${fmt(gridLines[k])} mm ` +
        `(the file's lines run from ${fmt(lines[0])} to ${fmt(lines[lines.length - 1])} mm, the grid's from ${fmt(gridLines[0])} to ${fmt(gridLines[gridLines.length - 1])} mm; X3P gives metres). ` +
        'Set the grid lines (Polynomials and measuring grid) to the measured positions.');
    }
  };
  check(read.r, grid.r, 'Y', 'radial', 'r');
  check(read.x, grid.x, 'X', 'axial', 'x');
  return read.values;
}

// The grid as CSV text with its positions, as the page's own export writes it (a header row of
// x positions, a first column of r positions): what the CSV box shows for an X3P read, full
// precision, so that the box's grid is the file's.
export function x3pGridCsv({ r, x, values }) {
  return [`r \\ x,${x.join(',')}`, ...values.map((row, j) => `${r[j]},${row.join(',')}`)].join('\n');
}

// The topographies a result can be written as: measured (the grid the case gave), predicted
// after the correction (correction.residual), simulated for the axes run (when nothing was
// measured). -> [{kind, label, values, note}]; the predicted one's note gives the bound on what the
// pass leaves (correction.predictedRmsHigh) in the unit the module gives it (unitOf: a result path
// to its unit): the grid is the identified machine's face.
export function x3pTopographies(result, caseObject, unitOf = () => '') {
  const out = [];
  const measured = caseObject && Array.isArray(caseObject.measured) ? caseObject.measured : null;
  if (measured) out.push({ kind: 'measured', label: 'measured', values: measured });
  if (result && result.correction && Array.isArray(result.correction.residual)) {
    const high = passBound(result.correction), unit = unitOf('correction.predictedRmsHigh');
    const note = high !== null && unit
      ? `The pass leaves at most ${Number(high.toPrecision(3))} ${unit} rms on the probe grid (the bound); this grid is the face on the identified machine, re-simulated.` : '';
    out.push({ kind: 'predicted', label: 'predicted (corrected, identified machine)', values: result.correction.residual, note });
  }
  if (!measured && result && result.topography) out.push({ kind: 'simulated', label: 'simulated', values: result.topography.normal });
  return out;
}

// The file name of an exported topography: hobsharp-<kind>-<day>.x3p.
export function x3pFileName(kind, date = new Date()) {
  return `hobsharp-${kind}-${date.toISOString().slice(0, 10)}.x3p`;
}

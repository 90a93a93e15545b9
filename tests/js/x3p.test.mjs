// The topography as an ISO 5436-2 X3P container (wasm/lib/x3p.js): the round trip, the
// container as md5sum and the openGPS schema's element names have it, and every malformed file
// refused with a message naming the file or element.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { deflateRawSync } from 'node:zlib';
import { unzipSync, zipSync, strToU8, strFromU8 } from 'fflate';
import {
  readX3p, writeX3p, x3pOnGrid, x3pGridCsv, x3pTopographies, metresToMicrons, md5Hex,
  MAIN_FILE, DATA_FILE, CHECKSUM_FILE, X3P_NAMESPACE,
} from '../../wasm/lib/x3p.js';
import { readMeasured } from '../../wasm/lib/measured-grid.js';
import { runOnX3p, zipWithStream } from './hostile-files.mjs';

const grid = { r: [19, 24.25, 29.5, 34.75, 40], x: [-70, -52.5, -35, -17.5, 0, 17.5, 35, 52.5, 70] };
// Values with full double precision (as the simulation gives) and short ones (as a machine writes).
const full = grid.r.map((_, j) => grid.x.map((_, i) => Math.sin(0.7 * i + j) * 3.3 + j / 7));
const short = [[0.5, -1.25, 2, 0, 3.1, -0.001, 12.75, -8.5, 4.4], [1, 2, 3, 4, 5, 6, 7, 8, 9],
  [-0.3, 0.3, -0.7, 0.7, 1.1, -1.1, 0, 2.2, -2.2], [9.87, 6.54, 3.21, 0.12, -3.45, -6.78, -9.01, 1.5, 2.5], [0, 0, 0, 0, 1e-3, 0, 0, 0, -1e-3]];
const date = new Date('2026-11-23T12:00:00Z');
const md5 = (bytes) => createHash('md5').update(bytes).digest('hex');
const files = (bytes) => unzipSync(bytes);
const rezip = (entries) => zipSync(entries);
const withMain = (bytes, edit, { fixChecksum = true } = {}) => {
  const f = files(bytes);
  const main = strToU8(edit(strFromU8(f[MAIN_FILE])));
  return rezip({ ...f, [MAIN_FILE]: main, ...(fixChecksum ? { [CHECKSUM_FILE]: strToU8(`${md5(main)} *main.xml\n`) } : {}) });
};

test('write then read gives the same grid: values of up to 15 digits exactly, any other within one unit in the last place', () => {
  const back = readX3p(writeX3p({ ...grid, values: short, date }));
  assert.deepEqual(back.values, short);
  const backFull = readX3p(writeX3p({ ...grid, values: full, date }));
  backFull.values.forEach((row, j) => row.forEach((v, i) => {
    assert.ok(Math.abs(v - full[j][i]) <= Math.abs(full[j][i]) * 2.3e-16, `row ${j}, column ${i}: ${v} against ${full[j][i]}`);
  }));
  // The positions are the grid's, to the metre conversion.
  back.r.forEach((r, j) => assert.ok(Math.abs(r - grid.r[j]) < 1e-9));
  back.x.forEach((x, i) => assert.ok(Math.abs(x - grid.x[i]) < 1e-9));
  assert.deepEqual(x3pOnGrid(back, grid), short);
  // Written again, the file's points are the same bytes: the stored precision is kept.
  const once = files(writeX3p({ ...grid, values: full, date }));
  const twice = files(writeX3p({ ...grid, values: backFull.values, date }));
  assert.deepEqual(twice[DATA_FILE], once[DATA_FILE]);
  assert.equal(strFromU8(twice[MAIN_FILE]), strFromU8(once[MAIN_FILE]));
});

test('the container: main.xml, bindata/data.bin and md5checksum.hex as md5sum writes it; the schema\'s elements; metres', () => {
  const f = files(writeX3p({ ...grid, values: short, date, kind: 'predicted' }));
  assert.deepEqual(Object.keys(f).sort(), [DATA_FILE, CHECKSUM_FILE, MAIN_FILE].sort());
  assert.equal(strFromU8(f[CHECKSUM_FILE]), `${md5(f[MAIN_FILE])} *main.xml\n`);
  assert.equal(md5Hex(f[MAIN_FILE]), md5(f[MAIN_FILE]), 'the page\'s MD5 is Node\'s');
  const xml = strFromU8(f[MAIN_FILE]);
  assert.match(xml, new RegExp(`^<\\?xml version="1.0" encoding="UTF-8"\\?>\\n<p:ISO5436_2 xmlns:p="${X3P_NAMESPACE}"`));
  assert.match(xml, /<Record1>\s*<Revision>ISO5436 - 2000<\/Revision>\s*<FeatureType>SUR<\/FeatureType>\s*<Axes>\s*<CX>\s*<AxisType>I<\/AxisType>\s*<DataType>D<\/DataType>\s*<Increment>0.0175<\/Increment>\s*<Offset>-0.07<\/Offset>\s*<\/CX>\s*<CY>\s*<AxisType>I<\/AxisType>\s*<DataType>D<\/DataType>\s*<Increment>0.00525<\/Increment>\s*<Offset>0.019<\/Offset>\s*<\/CY>\s*<CZ>\s*<AxisType>A<\/AxisType>\s*<DataType>D<\/DataType>/);
  assert.match(xml, /<Record2>\s*<Date>2026-11-23T12:00:00.000Z<\/Date>\s*<Creator>HobSharp<\/Creator>\s*<Instrument>\s*<Manufacturer>[^<]+<\/Manufacturer>\s*<Model>[^<]+<\/Model>\s*<Serial>[^<]+<\/Serial>\s*<Version>[^<]+<\/Version>\s*<\/Instrument>\s*<ProbingSystem>\s*<Type>Software<\/Type>\s*<Identification>HobSharp predicted<\/Identification>\s*<\/ProbingSystem>\s*<Comment>normal deviation of the rake face predicted after the correction on the identified machine/);
  assert.match(xml, new RegExp(`<Record3>\\s*<MatrixDimension>\\s*<SizeX>9</SizeX>\\s*<SizeY>5</SizeY>\\s*<SizeZ>1</SizeZ>\\s*</MatrixDimension>\\s*<DataLink>\\s*<PointDataLink>bindata/data.bin</PointDataLink>\\s*<MD5ChecksumPointData>${md5(f[DATA_FILE])}</MD5ChecksumPointData>\\s*</DataLink>\\s*</Record3>\\s*<Record4>\\s*<ChecksumFile>md5checksum.hex</ChecksumFile>\\s*</Record4>\\s*</p:ISO5436_2>\\n$`));
  // The points: float64 little-endian metres, x index fastest, rows root to tip.
  assert.equal(f[DATA_FILE].length, 45 * 8);
  const view = new DataView(f[DATA_FILE].buffer, f[DATA_FILE].byteOffset);
  assert.equal(view.getFloat64(0, true), 0.5e-6);
  assert.equal(view.getFloat64(8, true), -1.25e-6, 'the second point is the next x');
  assert.equal(view.getFloat64(9 * 8, true), 1e-6, 'the tenth point is the next r');
});

test('a file written by another program: an inline DataList, no Record2, int32 heights with an increment, a validity mask', () => {
  const list = `<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="${X3P_NAMESPACE}">
  <Record1><Revision>ISO25178-72:2017/DAM1</Revision><FeatureType>SUR</FeatureType>
    <Axes><CX><AxisType>I</AxisType><DataType>D</DataType><Increment>0.01</Increment><Offset>-0.01</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>0.002</Increment><Offset>0.03</Offset></CY>
      <CZ><AxisType>A</AxisType><DataType>D</DataType><Increment>1</Increment><Offset>0</Offset></CZ>
      <Rotation><r11>1.0</r11><r12>0.0</r12><r13>0.0</r13><r21>0.0</r21><r22>1.0</r22><r23>0.0</r23><r31>0.0</r31><r32>0.0</r32><r33>1.0</r33></Rotation></Axes></Record1>
  <!-- a comment -->
  <Record3><MatrixDimension><SizeX>3</SizeX><SizeY>2</SizeY><SizeZ>1</SizeZ></MatrixDimension>
    <DataList><Datum>1.5E-0006</Datum><Datum>-2e-6</Datum><Datum>0</Datum><Datum>3.25e-6</Datum><Datum>4e-6</Datum><Datum>-0.5e-6</Datum></DataList></Record3>
  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>`;
  const main = strToU8(list);
  const read = readX3p(rezip({ [MAIN_FILE]: main, [CHECKSUM_FILE]: strToU8(`${md5(main).toUpperCase()}  main.xml\n`) }));
  assert.deepEqual(read.values, [[1.5, -2, 0], [3.25, 4, -0.5]]);
  assert.deepEqual(x3pOnGrid(read, { r: [30, 32], x: [-10, 0, 10] }), read.values);
  // int32 heights of 0.1 µm: z = value x CZ increment + CZ offset.
  const ints = new Uint8Array(6 * 4);
  const dv = new DataView(ints.buffer);
  [15, -20, 0, 33, 40, -5].forEach((v, k) => dv.setInt32(k * 4, v, true));
  const valid = new Uint8Array([0b00111111]);
  const linked = list.replace(/<DataList>.*<\/DataList>/s, `<DataLink><PointDataLink>bindata/z.bin</PointDataLink><MD5ChecksumPointData>${md5(ints)}</MD5ChecksumPointData>` +
    `<ValidPointsLink>bindata/valid.bin</ValidPointsLink><MD5ChecksumValidPoints>${md5(valid)}</MD5ChecksumValidPoints></DataLink>`)
    .replace('<CZ><AxisType>A</AxisType><DataType>D</DataType><Increment>1</Increment><Offset>0</Offset></CZ>', '<CZ><AxisType>A</AxisType><DataType>L</DataType><Increment>1e-7</Increment><Offset>1e-6</Offset></CZ>');
  const m2 = strToU8(linked);
  const entries = { [MAIN_FILE]: m2, [CHECKSUM_FILE]: strToU8(`${md5(m2)} *main.xml`), 'bindata/z.bin': ints, 'bindata/valid.bin': valid };
  assert.deepEqual(readX3p(rezip(entries)).values, [[2.5, -1, 1], [4.3, 5, 0.5]]);
  // A point the mask marks invalid is a point not measured: refused, naming it.
  const holes = new Uint8Array([0b00111011]);
  const m3 = strToU8(linked.replace(md5(valid), md5(holes)));
  assert.throws(() => readX3p(rezip({ ...entries, [MAIN_FILE]: m3, [CHECKSUM_FILE]: strToU8(`${md5(m3)} *main.xml`), 'bindata/valid.bin': holes })),
    /^Error: main\.xml, Record3: the point at x index 2, y index 0 is missing \(not measured\)/);
});

test('the grid check: positions beyond 0.01 mm of the grid\'s lines, or another count of lines, are refused naming the axis', () => {
  const read = readX3p(writeX3p({ ...grid, values: short, date }));
  assert.throws(() => x3pOnGrid(read, { ...grid, x: grid.x.map((x, i) => (i === 3 ? x + 0.02 : x)) }),
    /^Error: main\.xml, Record1\/Axes\/CX: axial line 4 is at x = -17\.5 mm, but the grid's is at x = -17\.48 mm/);
  assert.throws(() => x3pOnGrid(read, { ...grid, r: grid.r.map((r) => r + 1) }), /^Error: main\.xml, Record1\/Axes\/CY: radial line 1 is at r = 19 mm, but the grid's is at r = 20 mm/);
  assert.throws(() => x3pOnGrid(read, { r: grid.r, x: grid.x.slice(0, 7) }), /^Error: main\.xml, Record3\/MatrixDimension\/SizeX: 9 axial lines, but the grid has 7\. Set the grid lines \(Polynomials and measuring grid\) to the measured positions\.$/);
  assert.doesNotThrow(() => x3pOnGrid(read, { ...grid, x: grid.x.map((x) => x + 0.009) }));
});

test("the CSV the box shows for an X3P is read by the CSV import as the same grid, with the grid's positions", () => {
  const read = readX3p(writeX3p({ ...grid, values: full, date }));
  const csv = x3pGridCsv({ ...grid, values: read.values });
  const back = readMeasured(csv, grid);
  assert.deepEqual(back.values, read.values);
  assert.deepEqual(back.notes, ['a header row of 9 x positions (mm)', 'a first column of 5 r positions (mm)']);
});

test('the topographies a result offers: measured and predicted with a measurement, simulated without', () => {
  const result = { topography: { normal: full }, correction: { residual: short } };
  assert.deepEqual(x3pTopographies(result, { measured: short }).map((t) => t.kind), ['measured', 'predicted']);
  assert.deepEqual(x3pTopographies({ topography: { normal: full } }, {}).map((t) => [t.kind, t.values]), [['simulated', full]]);
  // The predicted grid is the identified machine's face; its note carries the bound on what the pass leaves.
  const bounded = { topography: { normal: full }, correction: { residual: short, predictedRmsHigh: 0.44612 } };
  const micrometres = (path) => (path === 'correction.predictedRmsHigh' ? 'µm' : '');
  assert.equal(x3pTopographies(bounded, {}, micrometres)[0].note,
    "The pass leaves at most 0.446 µm rms on the probe grid (the bound); this grid is the face on the identified machine, re-simulated.");
  assert.equal(x3pTopographies({ ...bounded, correction: { ...bounded.correction, stop: true } }, {}, micrometres)[0].note, '', 'no pass after a stop, no bound');
  assert.equal(x3pTopographies(bounded, {})[0].note, '', 'no unit from the module, no figure');
  for (const none of [{ runKept: true }, { usable: false }]) {
    assert.equal(x3pTopographies({ ...bounded, correction: { ...bounded.correction, ...none } }, {}, micrometres)[0].note, '', JSON.stringify(none));
  }
  const read = readX3p(writeX3p({ ...grid, values: short, kind: 'predicted', date, note: x3pTopographies(bounded, {}, micrometres)[0].note }));
  assert.match(read.meta.comment, /Metres\. The pass leaves at most 0\.446 µm rms/);
});

test('metresToMicrons picks the shortest of the doubles that store as the same metres', () => {
  assert.equal(metresToMicrons(0.1 / 1e6), 0.1);
  assert.equal(metresToMicrons(3.3 / 1e6), 3.3);
  assert.equal(metresToMicrons(0), 0);
  assert.equal(metresToMicrons(-12.345678901234 / 1e6), -12.345678901234);
});

// ---- malformed files: each refused with a message naming the file or the element ----

const good = () => writeX3p({ ...grid, values: short, date });
const refuses = (bytes, pattern) => assert.throws(() => readX3p(bytes), pattern);

test('garbage, an empty file, a zip without main.xml, a zip that is cut short', () => {
  const garbage = new Uint8Array(10 * 1024 * 1024);
  for (let k = 0; k < garbage.length; k += 1) garbage[k] = (k * 2654435761) >>> 24;
  refuses(garbage, /^Error: The file is not an X3P container: an \.x3p is a zip archive/);
  refuses(new Uint8Array(0), /^Error: The file is not an X3P container/);
  refuses(new Uint8Array(17 * 1024 * 1024).fill(0x50), /^Error: The file is 17\.0 MB; an X3P topography of at most 201 × 201 points is a few hundred kB/);
  const f = files(good());
  refuses(rezip({ [DATA_FILE]: f[DATA_FILE], [CHECKSUM_FILE]: f[CHECKSUM_FILE] }), /^Error: The X3P container holds no main\.xml/);
  const whole = good();
  refuses(whole.slice(0, whole.length - 30), /^Error: The file is not a readable X3P container \(zip\)/);
  // Garbage that starts as a zip does.
  const pk = garbage.slice(0, 4096); pk[0] = 0x50; pk[1] = 0x4b;
  refuses(pk, /^Error: The file is not a readable X3P container \(zip\)/);
});

test('a truncated main.xml, a DOCTYPE with entities (the "billion laughs"), a wrong root', () => {
  refuses(withMain(good(), (xml) => xml.slice(0, xml.indexOf('</Record2>'))), /^Error: main\.xml, line \d+: .*The XML is not well formed \(cut short\?\)\./);
  const bomb = (xml) => xml.replace('<p:ISO5436_2', '<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">' +
    '<!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">]>\n<p:ISO5436_2').replace('<Creator>HobSharp', '<Creator>&lol3;');
  const started = Date.now();
  refuses(withMain(good(), bomb), /^Error: main\.xml, line 2: a <!DOCTYPE> declaration; X3P has none, and the page expands no entities\./);
  assert.ok(Date.now() - started < 1000);
  refuses(withMain(good(), (xml) => xml.replace('<Comment>', `<Comment>${'<a>'.repeat(200000)}${'</a>'.repeat(200000)}`)), /^Error: main\.xml: .*; the XML is not read\./);
  refuses(withMain(good(), (xml) => xml.replace(/p:ISO5436_2/g, 'p:Surface')), /^Error: main\.xml: the root element is <Surface>, not <ISO5436_2>\./);
  const latin1 = withMain(good(), (xml) => xml);
  const f = files(latin1);
  const bad = new Uint8Array([...f[MAIN_FILE].slice(0, 100), 0xff, ...f[MAIN_FILE].slice(100)]);
  refuses(rezip({ ...f, [MAIN_FILE]: bad, [CHECKSUM_FILE]: strToU8(`${md5(bad)} *main.xml`) }), /^Error: main\.xml: is not UTF-8 text\./);
});

test('a wrong MD5: of main.xml (md5checksum.hex), of the points (MD5ChecksumPointData), a missing checksum file', () => {
  refuses(withMain(good(), (xml) => xml.replace('<Creator>HobSharp', '<Creator>Someone else'), { fixChecksum: false }),
    /^Error: md5checksum\.hex: says [0-9a-f]{32}, but main\.xml's MD5 is [0-9a-f]{32}: the document is damaged or was changed\./);
  const f = files(good());
  const data = f[DATA_FILE].slice(); data[3] ^= 1;
  refuses(rezip({ ...f, [DATA_FILE]: data }), /^Error: bindata\/data\.bin: its MD5 is [0-9a-f]{32}, but Record3\/DataLink\/MD5ChecksumPointData says [0-9a-f]{32}: the points are damaged\./);
  refuses(rezip({ [MAIN_FILE]: f[MAIN_FILE], [DATA_FILE]: f[DATA_FILE] }), /^Error: main\.xml, Record4\/ChecksumFile: names md5checksum\.hex, which the container does not hold\./);
  refuses(rezip({ ...f, [CHECKSUM_FILE]: strToU8('not a checksum') }), /^Error: md5checksum\.hex: does not start with an MD5 checksum/);
  refuses(rezip({ [MAIN_FILE]: f[MAIN_FILE], [CHECKSUM_FILE]: f[CHECKSUM_FILE] }), /^Error: main\.xml, Record3\/DataLink\/PointDataLink: names bindata\/data\.bin, which the container does not hold\./);
});

test('wrong axes, units, types and sizes: each refused naming the element', () => {
  const cases = [
    [(x) => x.replace('<FeatureType>SUR', '<FeatureType>PRF'), /^Error: main\.xml, Record1\/FeatureType: is PRF; a rake-face topography is a surface, SUR/],
    [(x) => x.replace('<AxisType>I</AxisType>', '<AxisType>A</AxisType>'), /^Error: main\.xml, Record1\/Axes\/CX\/AxisType: is A \(absolute/],
    [(x) => x.replace(/(<CY>\s*<AxisType>)I/, '$1Q'), /^Error: main\.xml, Record1\/Axes\/CY\/AxisType: "Q" is neither I \(incremental\) nor A \(absolute\)\./],
    [(x) => x.replace(/(<CZ>\s*<AxisType>)A/, '$1I'), /^Error: main\.xml, Record1\/Axes\/CZ\/AxisType: is I; the heights are absolute, A\./],
    [(x) => x.replace(/<CX>[\s\S]*?<\/CX>/, ''), /^Error: main\.xml, Record1\/Axes\/CX: missing\./],
    [(x) => x.replace('<Increment>0.0175</Increment>', '<Increment>17,5</Increment>'), /^Error: main\.xml, Record1\/Axes\/CX\/Increment: "17,5" is not a number\./],
    [(x) => x.replace('<Increment>0.0175</Increment>', '<Increment>0</Increment>'), /^Error: main\.xml, Record1\/Axes\/CX\/Increment: is 0; the lines' spacing must be positive\./],
    [(x) => x.replace('<SizeZ>1</SizeZ>', '<SizeZ>2</SizeZ>'), /^Error: main\.xml, Record3\/MatrixDimension\/SizeZ: is 2; a topography has one layer\./],
    [(x) => x.replace('<SizeX>9</SizeX>', '<SizeX>10</SizeX>'), /^Error: bindata\/data\.bin: holds 360 bytes; 50 points of type D take 400\./],
    [(x) => x.replace('<SizeX>9</SizeX>', '<SizeX>100000</SizeX>'), /^Error: main\.xml, Record3\/MatrixDimension: 100000 × 5 points is no face grid/],
    [(x) => x.replace('<SizeY>5</SizeY>', '<SizeY>five</SizeY>'), /^Error: main\.xml, Record3\/MatrixDimension\/SizeY: "five" is not a whole number\./],
    [(x) => x.replace('</Axes>', '<Rotation><r11>0</r11><r12>1</r12><r13>0</r13><r21>1</r21><r22>0</r22><r23>0</r23><r31>0</r31><r32>0</r32><r33>1</r33></Rotation></Axes>'),
      /^Error: main\.xml, Record1\/Axes\/Rotation: is not the identity/],
    [(x) => x.replace('<Record1>', '<Record1><Revision>x</Revision>'), /^Error: main\.xml, Record1\/Revision: appears 2 times; the format has it once\./],
    [(x) => x.replace(/<DataLink>[\s\S]*<\/DataLink>/, ''), /^Error: main\.xml, Record3: has neither DataLink nor DataList: no points\./],
  ];
  for (const [edit, pattern] of cases) refuses(withMain(good(), edit), pattern);
});

test('heights written in µm where X3P wants metres are refused; positions in mm land beyond the grid and are refused naming CX', () => {
  // The same file with the heights' unit wrong: the points are µm, 1e6 times too large.
  const f = files(good());
  const wrong = new Uint8Array(f[DATA_FILE].length);
  const src = new DataView(f[DATA_FILE].buffer, f[DATA_FILE].byteOffset), dst = new DataView(wrong.buffer);
  for (let k = 0; k < 45; k += 1) dst.setFloat64(k * 8, src.getFloat64(k * 8, true) * 1e6, true);
  const main = strToU8(strFromU8(f[MAIN_FILE]).replace(md5(f[DATA_FILE]), md5(wrong)));
  refuses(rezip({ [MAIN_FILE]: main, [DATA_FILE]: wrong, [CHECKSUM_FILE]: strToU8(`${md5(main)} *main.xml`) }),
    /^Error: main\.xml, Record1\/Axes\/CZ: deviations up to 12\.8 m: no grinding error is that large\. X3P stores metres; were these written in µm or mm\?/);
  // Positions in mm: every line 1000 times too far.
  const mm = readX3p(withMain(good(), (x) => x.replace('<Increment>0.0175</Increment>', '<Increment>17.5</Increment>').replace('<Offset>-0.07</Offset>', '<Offset>-70</Offset>')));
  assert.throws(() => x3pOnGrid(mm, grid), /^Error: main\.xml, Record1\/Axes\/CX: axial line 1 is at x = -70000 mm, but the grid's is at x = -70 mm .*X3P gives metres/);
});

test('a zip whose main.xml claims to be huge is not inflated', () => {
  const f = files(good());
  const bigMain = new Uint8Array(9 * 1024 * 1024).fill(0x20);  // deflates to a few kB
  refuses(rezip({ ...f, [MAIN_FILE]: bigMain }), /^Error: main\.xml in the X3P container is larger than a topography needs; refused\./);
});

test('a points entry whose deflate stream runs on past its declared size is refused at that size, quickly, not inflated to the end', () => {
  const f = files(good());
  // 64 MB of zeros after the true points: the entry declares only the points' bytes.
  const bomb = runOnX3p(f, DATA_FILE, 64 * 1024 * 1024);
  assert.ok(bomb.length < 200 * 1024, `the bomb is ${bomb.length} bytes`);
  const started = performance.now();
  refuses(bomb, /^Error: bindata\/data\.bin in the X3P container inflates to more than the 360 bytes its entry declares: a damaged or hostile file; refused\./);
  assert.ok(performance.now() - started < 2000, `refused after ${performance.now() - started} ms`);
  // main.xml likewise (a document that runs on into blanks).
  refuses(runOnX3p(f, MAIN_FILE, 16 * 1024 * 1024), /^Error: main\.xml in the X3P container inflates to more than the \d+ bytes its entry declares/);
  // A stream that ends short of its declared size is damaged too.
  const short = new Uint8Array(f[DATA_FILE].subarray(0, 100));
  refuses(zipWithStream(f, DATA_FILE, new Uint8Array(deflateRawSync(short)), 360), /^Error: bindata\/data\.bin in the X3P container inflates to 100 bytes, not the 360 its entry declares: the file is damaged; refused\./);
  // The declared size itself is capped, whatever the stream.
  refuses(zipWithStream(f, DATA_FILE, new Uint8Array([3, 0]), 64 * 1024 * 1024), /^Error: bindata\/data\.bin in the X3P container is larger than a topography needs; refused\./);
});

test('the writer refuses a topography that is not the grid, or not finite', () => {
  assert.throws(() => writeX3p({ ...grid, values: short.slice(1) }), /^Error: The topography is not 5 rows of 9 values\./);
  const nan = short.map((row) => [...row]); nan[2][3] = NaN;
  assert.throws(() => writeX3p({ ...grid, values: nan }), /^Error: The topography's value at row 3, column 4 is not a number\./);
  assert.throws(() => writeX3p({ r: [1, 2, 4], x: [0, 1], values: [[0, 0], [0, 0], [0, 0]] }), /^Error: The radial grid's lines are not equally spaced \(line 2 at 2 mm\)\./);
});

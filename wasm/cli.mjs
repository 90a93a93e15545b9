#!/usr/bin/env node
// node wasm/cli.mjs case.json  - evaluates a hobsharp-case/1 file and prints the result as JSON,
// exactly as the C++ writer wrote it (core/result_model.h). On bad input it prints the message on
// stderr and exits with 1 (2 for a usage error).
//   --points file.csv    the measurement as the measuring machine's points (docs/measured-points.md;
//                        wasm/lib/points-csv.js): replaces the case's `measured` and
//                        `measuredPoints`
//   --points-out prefix  writes prefix-measured.csv and prefix-predicted.csv: the measured points
//                        and the face the identified machine leaves at them after the correction
//                        (correction.pointResidual; needs --points or
//                        the case's measuredPoints off the grid)
//   --nc CONTROL         prints the NC program of the axes to run instead of the JSON (CONTROL:
//                        sinumerik, sinumerik-cubic or heidenhain; docs/nc-programs.md), the
//                        same axes and program the page offers under "Axes to run"
// The X3P options (wasm/cli-x3p.mjs) read the measured grid from an .x3p and write the result's
// topographies as .x3p files.
import { readFileSync, writeFileSync } from 'node:fs';
import { loadHobSharp } from './hobsharp.mjs';
import { pointsToCsv, readPoints } from './lib/points-csv.js';
import { X3P_USAGE, caseWithMeasuredX3p, takeX3pOptions, writeResultX3p } from './cli-x3p.mjs';
import { NC_DIALECTS } from './lib/nc-program.js';
import { setModuleLimits } from './lib/limits.js';
import { programFor } from './lib/axes-to-run.js';

const usage = (why = '') => {
  process.stderr.write(`${why}usage: node wasm/cli.mjs case.json [--points points.csv] [--points-out prefix] [--nc ${NC_DIALECTS.join('|')}] ${X3P_USAGE}\n`);
  process.exit(2);
};
const argv = [...process.argv];
let x3p = {};
try {
  x3p = takeX3pOptions(argv);
} catch (e) {
  usage(`${e.message}\n`);
}
const args = argv.slice(2);
let file, pointsFile, pointsOut, nc;
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--points' && i + 1 < args.length) pointsFile = args[++i];
  else if (args[i] === '--nc' && i + 1 < args.length) {
    nc = args[++i];
    if (!NC_DIALECTS.includes(nc)) usage(`--nc: the control must be one of ${NC_DIALECTS.join(', ')}; got ${nc}.\n`);
  }
  else if (args[i] === '--points-out' && i + 1 < args.length) pointsOut = args[++i];
  else if (!args[i].startsWith('--') && file === undefined) file = args[i];
  else usage();
}
if (!file) usage();
if (pointsFile && x3p.measured) usage('--points and --measured-x3p both give the measurement; give one.\n');

const read = (name) => {
  try {
    return readFileSync(name, 'utf8');
  } catch (e) {
    process.stderr.write(`${name}: ${e.code === 'ENOENT' ? 'no such file' : e.message}\n`);
    process.exit(1);
  }
};
let text = read(file);
if (pointsFile) {
  const csv = read(pointsFile);
  let caseObject;
  try {
    caseObject = JSON.parse(text);
  } catch (e) {
    process.stderr.write(`${file}: not JSON (${e.message})\n`);
    process.exit(1);
  }
  try {
    const { points, warnings, skippedText } = readPoints(csv);
    // What the page shows beside the points: a unit that looks wrong, the lines skipped.
    for (const w of warnings) process.stderr.write(`${pointsFile}: warning: ${w.text}\n`);
    if (skippedText) process.stderr.write(`${pointsFile}: ${skippedText}\n`);
    if (caseObject && typeof caseObject === 'object') {
      delete caseObject.measured;
      caseObject.measuredPoints = points;
    }
  } catch (e) {
    process.stderr.write(`${pointsFile}: ${e.message}\n`);
    process.exit(1);
  }
  text = JSON.stringify(caseObject);
}
try {
  const hobsharp = await loadHobSharp();
  const caseText = caseWithMeasuredX3p(hobsharp, text, x3p);
  const json = hobsharp.evaluateToJson(caseText);
  if (pointsOut) {
    const c = JSON.parse(json).correction;
    // Points at the grid's positions are the grid (docs/measured-points.md): the result stands,
    // and there are no points of their own to write.
    if (!c || !c.pointMeasured) {
      const points = Array.isArray(JSON.parse(caseText).measuredPoints);
      const why = !c ? 'the case has no measured face' : points ? 'the points lie on the grid, and the result is the grid\'s'
        : 'the measurement is a grid, not points';
      process.stderr.write(`--points-out: nothing written: ${why}.\n`);
    } else {
      writeFileSync(`${pointsOut}-measured.csv`, pointsToCsv(c.pointMeasured));
      writeFileSync(`${pointsOut}-predicted.csv`, pointsToCsv(c.pointResidual));
    }
  }
  writeResultX3p(JSON.parse(json), caseText, x3p, hobsharp.resultFields()).forEach((f) => process.stderr.write(`wrote ${f}\n`));
  if (nc) {
    // The program of the axes the page shows under "Axes to run" (wasm/lib/axes-to-run.js).
    const limits = hobsharp.limits();
    setModuleLimits(limits);
    const program = programFor(JSON.parse(json), JSON.parse(caseText), nc, { digits: limits.correction.coefficientDigits });
    process.stdout.write(program.text);
  } else {
    process.stdout.write(json + '\n');
  }
} catch (e) {
  process.stderr.write(x3p.measured && e.message.startsWith(`${x3p.measured}:`) ? `${e.message}\n` : `${pointsFile || file}: ${e.message}\n`);
  process.exit(1);
}

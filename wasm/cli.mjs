#!/usr/bin/env node
// node wasm/cli.mjs case.json  - evaluates a hobsharp-case/1 file and prints the result as JSON,
// exactly as the C++ writer wrote it (core/result_model.h). On bad input it prints the message on
// stderr and exits with 1 (2 for a usage error). The X3P options (wasm/cli-x3p.mjs) read the
// measured grid from an .x3p and write the result's topographies as .x3p files.
import { readFileSync } from 'node:fs';
import { loadHobSharp } from './hobsharp.mjs';
import { X3P_USAGE, caseWithMeasuredX3p, takeX3pOptions, writeResultX3p } from './cli-x3p.mjs';

const usage = (why = '') => {
  process.stderr.write(`${why}usage: node wasm/cli.mjs case.json ${X3P_USAGE}\n`);
  process.exit(2);
};
let x3p = {};
try {
  x3p = takeX3pOptions(process.argv);
} catch (e) {
  usage(`${e.message}\n`);
}
const file = process.argv[2];
if (!file || process.argv.length > 3) usage();
let text;
try {
  text = readFileSync(file, 'utf8');
} catch (e) {
  process.stderr.write(`${file}: ${e.code === 'ENOENT' ? 'no such file' : e.message}\n`);
  process.exit(1);
}
try {
  const hobsharp = await loadHobSharp();
  const caseText = caseWithMeasuredX3p(hobsharp, text, x3p);
  const out = hobsharp.evaluateToJson(caseText);
  writeResultX3p(JSON.parse(out), caseText, x3p).forEach((f) => process.stderr.write(`wrote ${f}\n`));
  process.stdout.write(out + '\n');
} catch (e) {
  process.stderr.write(x3p.measured && e.message.startsWith(`${x3p.measured}:`) ? `${e.message}\n` : `${file}: ${e.message}\n`);
  process.exit(1);
}

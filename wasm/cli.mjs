#!/usr/bin/env node
// node wasm/cli.mjs case.json  - evaluates a hobsharp-case/1 file and prints the result as JSON.
// On bad input it prints the message on stderr and exits with 1 (2 for a usage error).
import { readFileSync } from 'node:fs';
import { loadHobSharp } from './hobsharp.mjs';

const file = process.argv[2];
if (!file || process.argv.length > 3) {
  process.stderr.write('usage: node wasm/cli.mjs case.json\n');
  process.exit(2);
}
let caseObject;
try {
  caseObject = JSON.parse(readFileSync(file, 'utf8'));
} catch (e) {
  process.stderr.write(`${file}: ${e.code === 'ENOENT' ? 'no such file' : 'not valid JSON: ' + e.message}\n`);
  process.exit(1);
}
try {
  const hobsharp = await loadHobSharp();
  process.stdout.write(JSON.stringify(hobsharp.evaluate(caseObject), null, 1) + '\n');
} catch (e) {
  process.stderr.write(`${file}: ${e.message}\n`);
  process.exit(1);
}

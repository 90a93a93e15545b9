#!/usr/bin/env node
// node wasm/cli.mjs case.json  - evaluates a hobsharp-case/1 file and prints the result as JSON,
// exactly as the C++ writer wrote it (core/result_model.h). On bad input it prints the message on
// stderr and exits with 1 (2 for a usage error).
import { readFileSync } from 'node:fs';
import { loadHobSharp } from './hobsharp.mjs';

const file = process.argv[2];
if (!file || process.argv.length > 3) {
  process.stderr.write('usage: node wasm/cli.mjs case.json\n');
  process.exit(2);
}
let text;
try {
  text = readFileSync(file, 'utf8');
} catch (e) {
  process.stderr.write(`${file}: ${e.code === 'ENOENT' ? 'no such file' : e.message}\n`);
  process.exit(1);
}
try {
  const hobsharp = await loadHobSharp();
  process.stdout.write(hobsharp.evaluateToJson(text) + '\n');
} catch (e) {
  process.stderr.write(`${file}: ${e.message}\n`);
  process.exit(1);
}

// For the Node tests that hold the module against the native build: the repository's root, the
// paper's case, and a case evaluated by the native build's command (tests/native_eval.cpp).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const paperFile = path.join(root, 'tests', 'data', 'tab1.json');
export const paper = () => JSON.parse(readFileSync(paperFile, 'utf8'));
export const nativeEval = process.env.HOBSHARP_NATIVE_EVAL || path.join(root, 'build', 'native', 'tests', 'hobsharp_native_eval');

// The native build's result for a case, as JSON.
export function native(caseObject) {
  const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-'));
  const file = path.join(dir, 'case.json');
  writeFileSync(file, JSON.stringify(caseObject));
  return JSON.parse(execFileSync(nativeEval, [file], { encoding: 'utf8' }));
}

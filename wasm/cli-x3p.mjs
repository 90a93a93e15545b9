// The command line's X3P options (wasm/cli.mjs; the container is wasm/lib/x3p.js):
//   --measured-x3p FILE   the measured grid read from an ISO 5436-2 .x3p into the case (it takes
//                         the place of the case's `measured`), checked against the case's grid;
//   --x3p-out PREFIX      the result's topographies written as PREFIX-measured.x3p and
//                         PREFIX-predicted.x3p (with a measurement), or PREFIX-simulated.x3p.
import { readFileSync, writeFileSync } from 'node:fs';
import { readX3p, writeX3p, x3pOnGrid, x3pTopographies } from './lib/x3p.js';

export const X3P_USAGE = '[--measured-x3p file.x3p] [--x3p-out prefix]';

// Takes the X3P options (each with its value) out of argv; throws on one without a value.
export function takeX3pOptions(argv) {
  const options = {};
  for (const [flag, key] of [['--measured-x3p', 'measured'], ['--x3p-out', 'out']]) {
    const k = argv.indexOf(flag);
    if (k < 0) continue;
    if (k + 1 >= argv.length || argv[k + 1].startsWith('--')) throw new Error(`${flag} needs a value`);
    options[key] = argv[k + 1];
    argv.splice(k, 2);
  }
  return options;
}

// The case text with the measured grid of options.measured; throws an Error whose message starts
// with the file that is wrong (the .x3p, or the case when it cannot be evaluated).
export function caseWithMeasuredX3p(hobsharp, caseText, options) {
  if (!options.measured) return caseText;
  let bytes;
  try {
    bytes = readFileSync(options.measured);
  } catch (e) {
    throw new Error(`${options.measured}: ${e.code === 'ENOENT' ? 'no such file' : e.message}`);
  }
  const c = JSON.parse(caseText);
  const plain = { ...c };
  delete plain.measured;
  const { topography } = hobsharp.evaluate(plain);
  try {
    c.measured = x3pOnGrid(readX3p(bytes), topography);
  } catch (e) {
    throw new Error(`${options.measured}: ${e.message}`);
  }
  return JSON.stringify(c);
}

// Writes the result's topographies; returns the files written.
// fields: the module's resultFields(), whose units the files' notes use.
export function writeResultX3p(result, caseText, options, fields = [], date = new Date()) {
  if (!options.out) return [];
  const { r, x } = result.topography;
  const unitOf = (path) => (fields.find((f) => f.path === path) || {}).unit || '';
  return x3pTopographies(result, JSON.parse(caseText), unitOf).map(({ kind, values, note }) => {
    const file = `${options.out}-${kind}.x3p`;
    writeFileSync(file, writeX3p({ r, x, values, kind, date, note }));
    return file;
  });
}

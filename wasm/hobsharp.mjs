// The HobSharp module for Node: the same WebAssembly build and the same evaluate(case) as the page.
//   import { loadHobSharp } from './wasm/hobsharp.mjs';
//   const hobsharp = await loadHobSharp();
//   const result = hobsharp.evaluate(caseObject);   // throws an Error naming the field on bad input
import { createRequire } from 'node:module';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const here = path.dirname(fileURLToPath(import.meta.url));

// Where the build puts the module; HOBSHARP_MODULE overrides it.
export function modulePath() {
  return process.env.HOBSHARP_MODULE || path.join(here, '..', 'build', 'wasm', 'site', 'hobsharp.js');
}

export async function loadHobSharp(file = modulePath()) {
  if (!existsSync(file)) {
    throw new Error(`The HobSharp module is not built (${file}); run ./hobsharp.sh test or ./hobsharp.sh serve first.`);
  }
  const factory = createRequire(import.meta.url)(file);
  // The .wasm is embedded in the .js (SINGLE_FILE), so Node needs no fetch or wasmBinary.
  return factory();
}

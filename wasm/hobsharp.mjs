// The HobSharp module for Node: the same WebAssembly build and the same JS API as the page.
//   import { loadHobSharp, HobSharpError } from './wasm/hobsharp.mjs';
//   const hobsharp = await loadHobSharp();
//   const result = hobsharp.evaluate(caseObject);   // throws a HobSharpError naming the field
// HobSharpError is the module's class (Module.HobSharpError), set once a module has loaded;
// `instanceof HobSharpError` holds for an error from any instance.
import { createRequire } from 'node:module';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const here = path.dirname(fileURLToPath(import.meta.url));

export let HobSharpError;

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
  const module = await factory();
  HobSharpError = HobSharpError || module.HobSharpError;
  return module;
}

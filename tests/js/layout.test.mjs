// The layout holds (issue 23, item 2): the file formats the page and the CLI share are wasm/lib,
// and nothing under wasm/ imports from web/ (the page can be reorganised without breaking the
// command line). The import specifiers are read by esbuild's parser (every static import,
// export ... from, import() and require() with a literal specifier), not by a regex.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import * as esbuild from 'esbuild';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const WEB = path.join(ROOT, 'web');
const LIB = path.join(ROOT, 'wasm', 'lib');

// The .js and .mjs files under `dir`, recursively.
function sources(dir) {
  return readdirSync(dir, { withFileTypes: true, recursive: true })
    .filter((e) => e.isFile() && /\.m?js$/.test(e.name))
    .map((e) => path.join(e.parentPath ?? e.path, e.name));
}

// file -> [{specifier, kind}]: what each file imports, as esbuild parses it (nothing followed).
export async function importsOf(files) {
  const out = new Map(files.map((f) => [f, []]));
  await esbuild.build({
    entryPoints: files, bundle: true, write: false, format: 'esm', platform: 'neutral', outdir: tmpdir(),
    logLevel: 'silent',
    plugins: [{
      name: 'record-imports',
      setup(build) {
        build.onResolve({ filter: /.*/ }, (args) => {
          if (args.kind === 'entry-point') return undefined;
          out.get(args.importer)?.push({ specifier: args.path, kind: args.kind });
          return { path: args.path, external: true };
        });
      },
    }],
  });
  return out;
}

// A relative specifier as the file it names; null for a package or a node: builtin.
const target = (file, specifier) => (specifier.startsWith('.') ? path.resolve(path.dirname(file), specifier) : null);
const inside = (file, dir) => !path.relative(dir, file).startsWith('..');
const rel = (file) => path.relative(ROOT, file);

test('the import reader sees every form of import (a check that could fail)', async () => {
  const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-layout-'));
  const file = path.join(dir, 'probe.mjs');
  writeFileSync(file, [
    "import { a } from './a.js';",
    "import './b.js';",
    "export * from './c.js';",
    "export { d } from './d.js';",
    "const e = await import('./e.js');",
    "// import { f } from './comment.js';",
    "const s = \"import { g } from './string.js'\";",
  ].join('\n'));
  const found = (await importsOf([file])).get(file).map((i) => i.specifier).sort();
  assert.deepEqual(found, ['./a.js', './b.js', './c.js', './d.js', './e.js']);
});

test('no file under wasm/ imports from web/', async () => {
  const files = sources(path.join(ROOT, 'wasm'));
  assert.ok(files.some((f) => f.endsWith(path.join('wasm', 'cli.mjs'))), 'the CLI is among the files read');
  const imports = await importsOf(files);
  const intoWeb = [];
  for (const [file, list] of imports) {
    for (const { specifier } of list) {
      const t = target(file, specifier);
      if ((t && inside(t, WEB)) || /(^|\/)web\//.test(specifier)) intoWeb.push(`${rel(file)} imports ${specifier}`);
    }
  }
  assert.deepEqual(intoWeb, []);
});

test('wasm/lib is pure and self-contained: it imports only itself and the npm dependencies, never web/', async () => {
  const files = sources(LIB);
  assert.ok(files.length >= 10, `wasm/lib holds the shared formats; found ${files.length} files`);
  const { dependencies } = JSON.parse(readFileSync(path.join(ROOT, 'package.json'), 'utf8'));
  const packageOf = (s) => (s.startsWith('@') ? s.split('/').slice(0, 2).join('/') : s.split('/')[0]);
  const imports = await importsOf(files);
  const intoWeb = [], outside = [];
  for (const [file, list] of imports) {
    for (const { specifier } of list) {
      const t = target(file, specifier);
      if ((t && inside(t, WEB)) || /(^|\/)web\//.test(specifier)) intoWeb.push(`${rel(file)} imports ${specifier}`);
      else if (t ? !inside(t, LIB) : !Object.hasOwn(dependencies, packageOf(specifier))) outside.push(`${rel(file)} imports ${specifier}`);
    }
  }
  assert.deepEqual(intoWeb, [], 'no file under wasm/lib imports from web/');
  assert.deepEqual(outside, [], 'wasm/lib imports only wasm/lib and the npm dependencies (no node: builtin: the page runs it too)');
  // Pure: no page object is touched (the page's views keep what is about the page).
  const dom = files.filter((f) => /\b(document|window)\.\w|\blocalStorage\b|\bnavigator\./.test(readFileSync(f, 'utf8')));
  assert.deepEqual(dom.map(rel), [], 'wasm/lib uses no DOM');
});

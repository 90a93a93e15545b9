// The module as a guest in a Node process: loading it leaves Node's own error handling alone
// (Emscripten's default handlers rethrew every unrelated error from inside the 735 kB one-line
// module, so Node printed that whole line), and a case nested a million deep is refused every
// time without eating the module's memory (it once leaked ~48 MB a call until the module died).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const loader = new URL('../../wasm/hobsharp.mjs', import.meta.url).href;
const paper = () => JSON.parse(readFileSync(path.join(here, '..', 'data', 'tab1.json'), 'utf8'));

// A child Node that loads the module and then runs `then`; its exit status and stderr.
function childLoadingTheModule(then) {
  const script = `import { loadHobSharp } from ${JSON.stringify(loader)};\n` +
                 `const m = await loadHobSharp();\n` +
                 `if (typeof m.evaluate !== 'function') process.exit(3);\n${then}\n`;
  return spawnSync(process.execPath, ['--input-type=module', '-e', script],
                   { encoding: 'utf8', env: process.env, timeout: 60_000 });
}

test('an unrelated uncaught error after loading: Node reports it, briefly, with its own exit code', () => {
  const r = childLoadingTheModule("setTimeout(() => { throw new Error('unrelated failure 4711'); }, 0);");
  assert.match(r.stderr, /Error: unrelated failure 4711/);
  assert.ok(r.stderr.length < 2000, `stderr holds ${r.stderr.length} bytes:\n${r.stderr.slice(0, 500)}`);
  assert.equal(r.status, 1, 'Node exits with 1 on an uncaught error (7 means a handler threw it again)');
});

test('an unrelated unhandled rejection after loading: Node reports it, briefly', () => {
  const r = childLoadingTheModule("Promise.reject(new Error('unrelated rejection 4712'));");
  assert.match(r.stderr, /unrelated rejection 4712/);
  assert.ok(r.stderr.length < 2000, `stderr holds ${r.stderr.length} bytes:\n${r.stderr.slice(0, 500)}`);
  assert.equal(r.status, 1);
});

test('loading the module adds no process-wide error handlers', async () => {
  const events = ['uncaughtException', 'unhandledRejection', 'exit'];
  const before = events.map((e) => process.listenerCount(e));
  await loadHobSharp();
  assert.deepEqual(events.map((e) => process.listenerCount(e)), before);
});

test('a case nested a million deep is refused each time, naming the field, and the heap stays', async () => {
  const hobsharp = await loadHobSharp();
  const deep = '{"format": ' + '['.repeat(1e6) + ']'.repeat(1e6) + '}';
  const heap = () => hobsharp.HEAP8.buffer.byteLength;
  hobsharp.evaluateJson(deep);  // the first call may grow the heap once, for the 2 MB text
  const before = heap();
  for (let i = 0; i < 30; i++) {
    const r = hobsharp.evaluateJson(deep);
    assert.equal(r.ok, false);
    assert.equal(r.field, 'format');
    assert.match(r.message, /^format: .*nested more than 64 deep/);
    assert.ok(r.message.length < 200, r.message);
  }
  const grown = heap() - before;
  assert.ok(grown < 16 * 2 ** 20, `the heap grew by ${(grown / 2 ** 20).toFixed(0)} MB over 30 calls`);
  // And through the JS API: still answering, still naming fields.
  assert.ok(hobsharp.evaluate(paper()).axes.X.length === 5);
  const lone = paper();
  lone.hob.hand = '\ud800';
  assert.throws(() => hobsharp.evaluate(lone), (e) => e.field === 'hob.hand' && /^hob\.hand: .*surrogate/.test(e.message));
});

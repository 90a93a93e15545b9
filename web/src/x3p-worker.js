// The X3P reader's worker (bundled by esbuild as x3p-worker.js beside app.js): an .x3p is read
// here, off the page's thread, so that a large or hostile file never freezes the page
// (x3p-reader.js starts one per file). Posts {ok, notes, values} or {ok: false, message}.
import { readX3p, x3pOnGrid } from '../../wasm/lib/x3p.js';

self.onmessage = ({ data: { bytes, grid } }) => {
  try {
    const read = readX3p(bytes);
    self.postMessage({ ok: true, notes: read.notes, values: x3pOnGrid(read, grid) });
  } catch (e) {
    self.postMessage({ ok: false, message: (e && e.message) || String(e) });
  }
};

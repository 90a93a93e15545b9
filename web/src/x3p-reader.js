// An .x3p read off the page's thread (x3p-worker.js), checked against the face grid: resolves to
// {notes, values} (wasm/lib/x3p.js readX3p and x3pOnGrid), rejects with the reader's Error. Each file
// gets a worker of its own, ended when it answers. A page opened from disk may not start a worker
// from a file, and reads there (the reader stops a runaway file at its declared size).
import { readX3p, x3pOnGrid } from '../../wasm/lib/x3p.js';

export function readX3pOffPage(bytes, grid) {
  if (location.protocol === 'file:') {
    return new Promise((resolve) => setTimeout(resolve, 0)).then(() => {
      const read = readX3p(bytes);
      return { notes: read.notes, values: x3pOnGrid(read, grid) };
    });
  }
  return new Promise((resolve, reject) => {
    const worker = new Worker('x3p-worker.js');
    worker.onmessage = ({ data }) => {
      worker.terminate();
      if (data.ok) resolve({ notes: data.notes, values: data.values });
      else reject(new Error(data.message));
    };
    worker.onerror = (event) => {
      worker.terminate();
      reject(new Error(`The X3P reader stopped: ${event.message || 'its worker did not start'}.`));
    };
    worker.postMessage({ bytes, grid: { r: grid.r, x: grid.x } }, [bytes.buffer]);
  });
}

// Hostile files for the tests, generated (nothing huge is committed): an X3P whose points entry
// declares its true size but whose deflate stream runs on (a "zip bomb" that the declared size
// hides), wheel and grid CSVs with far more values than the calculator takes.
import { deflateRawSync } from 'node:zlib';
import { zipSync } from 'fflate';

// Offsets of the fields a zip's local header (PK 3 4) and central directory entry (PK 1 2) hold.
const LOCAL = { signature: 0x04034b50, method: 8, compressed: 18, size: 22, nameLength: 26, name: 30 };
const CENTRAL = { signature: 0x02014b50, method: 10, compressed: 20, size: 24, nameLength: 28, name: 46 };

function headersOf(zip, name) {
  const view = new DataView(zip.buffer, zip.byteOffset, zip.byteLength);
  const found = [];
  for (let k = 0; k + 46 < zip.length; k += 1) {
    for (const h of [LOCAL, CENTRAL]) {
      if (view.getUint32(k, true) !== h.signature) continue;
      const n = view.getUint16(k + h.nameLength, true);
      if (new TextDecoder().decode(zip.subarray(k + h.name, k + h.name + n)) === name) found.push({ k, h });
    }
  }
  return { view, found };
}

// entries: {name: bytes} as zipSync takes them; `name`'s bytes are stored as the raw deflate
// stream `stream`, its header declaring `declared` bytes inflated. The stream takes the place of a
// stored placeholder of the same length, so every offset in the zip holds.
export function zipWithStream(entries, name, stream, declared) {
  const zip = zipSync({ ...entries, [name]: [new Uint8Array(stream.length), { level: 0 }] });
  const { view, found } = headersOf(zip, name);
  if (found.length !== 2) throw new Error(`zipWithStream: ${name} not found once in each directory`);
  for (const { k, h } of found) {
    view.setUint16(k + h.method, 8, true);
    view.setUint32(k + h.size, declared, true);
    if (h === LOCAL) zip.set(stream, k + h.name + view.getUint16(k + h.nameLength, true) + view.getUint16(k + 28, true));
  }
  return zip;
}

// The zip bomb: `data` then `extraBytes` zeros, deflated, in place of `name`, which declares
// data.length bytes (so the first data.length bytes inflated are the true ones).
export function runOnX3p(entries, name, extraBytes) {
  const data = entries[name];
  const stream = deflateRawSync(Buffer.concat([Buffer.from(data), Buffer.alloc(extraBytes)]), { level: 9 });
  return zipWithStream(entries, name, new Uint8Array(stream.buffer, stream.byteOffset, stream.length), data.length);
}

// A wheel CSV of n points (R rising from 30 mm in steps of 0.1 µm, an offset of 0 to 4 µm):
// 150,000 points are 1.5 MB.
export function wheelCsv(n) {
  const lines = ['R (mm),offset (µm)'];
  for (let k = 0; k < n; k += 1) lines.push(`${((300000 + k) / 10000).toFixed(4)},${k % 5}`);
  return `${lines.join('\n')}\n`;
}

// A grid CSV of `rows` lines of one digit each: 990,000 rows are 1.9 MB.
export const longGridCsv = (rows) => `${Array.from({ length: rows }, (_, k) => k % 10).join("\n")}\n`;

// A small map of a grid on a canvas, with a two-line title: the sensitivity gallery's thumbnails
// (25 of them, drawn in a few milliseconds).
import { colourOf } from './colours.js';
import { sized } from './canvas.js';

let scratch = null;  // one grid point per pixel, scaled up into each thumbnail

// z: rows root to tip (drawn bottom to top) of values along the gash (left to right).
export function drawThumbnail(el, { z, range, title }) {
  let canvas = el.querySelector('canvas');
  if (!canvas) {
    canvas = document.createElement('canvas');
    el.replaceChildren(canvas);
  }
  const width = el.clientWidth || 190, height = el.clientHeight || 150;
  const g = sized(canvas, width, height);
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', title.join(', '));
  g.fillStyle = '#fff';
  g.fillRect(0, 0, width, height);
  g.fillStyle = '#2a3340';
  g.font = '11px system-ui, sans-serif';
  g.textAlign = 'center';
  g.textBaseline = 'top';
  title.forEach((line, k) => g.fillText(line, width / 2, 3 + 13 * k));
  // One pixel per grid point, scaled up: as fast for 201 x 201 as for 9 x 5.
  const rows = z.length, cols = z[0].length;
  const image = new ImageData(cols, rows);
  for (let i = 0; i < rows; i++) {
    for (let j = 0; j < cols; j++) {
      const c = colourOf(z[i][j], range), at = ((rows - 1 - i) * cols + j) * 4;
      image.data[at] = c[0];
      image.data[at + 1] = c[1];
      image.data[at + 2] = c[2];
      image.data[at + 3] = 255;
    }
  }
  scratch = scratch || document.createElement('canvas');
  [scratch.width, scratch.height] = [cols, rows];
  scratch.getContext('2d').putImageData(image, 0, 0);
  g.imageSmoothingEnabled = false;
  g.drawImage(scratch, 6, 32, width - 12, height - 38);
}

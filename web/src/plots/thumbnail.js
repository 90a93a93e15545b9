// A small map of a grid on a canvas, with a two-line title: the sensitivity gallery's thumbnails
// (25 of them, drawn in a few milliseconds).
import { colourOf, css } from './colours.js';
import { sized } from './canvas.js';

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
  const top = 32, left = 6, w = width - 12, h = height - top - 6;
  const rows = z.length, cols = z[0].length;
  for (let i = 0; i < rows; i++) {
    const y0 = top + h - ((i + 1) * h) / rows;
    for (let j = 0; j < cols; j++) {
      g.fillStyle = css(colourOf(z[i][j], range));
      g.fillRect(left + (j * w) / cols, y0, w / cols + 0.5, h / rows + 0.5);
    }
  }
}

// Drawing on a canvas: sizing for the screen's pixel ratio, a colour bar, a tooltip.
import { colourOf, css, ticks, tickText } from './colours.js';

export const FONT = '12px system-ui, sans-serif';

// The canvas at width x height CSS pixels, sharp on the screen; its backing store is made anew
// only when the size changed (that is the costly part).
export function sized(canvas, width, height) {
  const dpr = window.devicePixelRatio || 1;
  const [w, h] = [Math.round(width * dpr), Math.round(height * dpr)];
  if (canvas.width !== w || canvas.height !== h) {
    canvas.width = w;
    canvas.height = h;
    canvas.style.width = `${width}px`;
    canvas.style.height = `${height}px`;
  }
  const g = canvas.getContext('2d');
  g.setTransform(1, 0, 0, 1, 0, 0);
  g.clearRect(0, 0, w, h);
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  return g;
}

// A vertical colour bar from +range (top) to -range, with ticks and a title above it.
export function colourBar(g, left, top, h, range, title) {
  for (let k = 0; k < h; k++) {
    g.fillStyle = css(colourOf(range * (1 - (2 * k) / h), range));
    g.fillRect(left, top + k, 14, 1.5);
  }
  g.font = FONT;
  g.fillStyle = '#2a3340';
  g.textAlign = 'left';
  g.textBaseline = 'middle';
  for (const v of ticks(-range, range)) g.fillText(tickText(v), left + 19, top + ((range - v) / (2 * range)) * h);
  g.textAlign = 'center';
  g.fillText(title, left + 7, top - 12);
}

// The grid point nearest the pointer (within 15 px) marked, with its values in a box.
export function hover(overlay, points, px, py, spec) {
  const g = overlay.getContext('2d');
  g.clearRect(0, 0, overlay.width, overlay.height);
  let best = null, bestD = 15 * 15;
  for (const p of points) {
    const d = (p.s[0] - px) ** 2 + (p.s[1] - py) ** 2;
    if (d < bestD) { best = p; bestD = d; }
  }
  const lines = best && spec ? spec.hover(best.i, best.j) : [];
  overlay.dataset.hover = lines.join('; ');
  if (!lines.length) return;
  const [sx, sy] = best.s;
  g.font = FONT;
  const w = Math.max(...lines.map((t) => g.measureText(t).width)) + 12;
  const bx = Math.min(sx + 10, overlay.clientWidth - w - 2), by = Math.max(2, sy - 12 - 16 * lines.length);
  g.fillStyle = '#1a202c';
  g.beginPath();
  g.arc(sx, sy, 3.5, 0, 2 * Math.PI);
  g.fill();
  g.fillStyle = 'rgba(255,255,255,0.94)';
  g.strokeStyle = '#5a6472';
  g.fillRect(bx, by, w, 16 * lines.length + 6);
  g.strokeRect(bx, by, w, 16 * lines.length + 6);
  g.fillStyle = '#1a202c';
  g.textAlign = 'left';
  g.textBaseline = 'top';
  lines.forEach((t, k) => g.fillText(t, bx + 6, by + 4 + 16 * k));
}

// The sensitivity gallery: one Plotly figure of small heatmaps, one per coefficient, each with its
// own colour range (one newPlot for all of them is many times faster than a figure each). The
// two-line titles are HTML above each map (#gallery-titles), not Plotly annotations: measuring 50
// lines of SVG text took longer than drawing the 25 maps. As many columns as fit, up to 5.
// el: the figure's element; labels: the element over it that holds the titles.
import { reactPlot } from './config.js';
import { DEVIATION_SCALE } from './colours.js';
import { escapeHtml } from '../format.js';

const ROW = 150, TITLE = 32, GAP = 8;  // px: a thumbnail's row, its title above it, the gap below

// items: [{z (rows root to tip of values along the gash), range, title: [line, line]}]
export function drawGallery(Plotly, el, labels, x, y, items) {
  const columns = Math.max(2, Math.min(5, Math.floor((el.clientWidth || 950) / 190)));
  const rows = Math.ceil(items.length / columns);
  const height = rows * ROW;
  const layout = { height, margin: { t: 0, r: 0, b: 0, l: 0 }, showlegend: false };
  const titles = [];
  const traces = items.map(({ z, range, title }, k) => {
    const row = Math.floor(k / columns), col = k % columns, n = k + 1;
    const xd = [col / columns + 0.01, (col + 1) / columns - 0.01];
    const yd = [1 - ((row + 1) * ROW - GAP) / height, 1 - (row * ROW + TITLE) / height];
    layout[`xaxis${n}`] = { domain: xd, anchor: `y${n}`, visible: false, fixedrange: true };
    layout[`yaxis${n}`] = { domain: yd, anchor: `x${n}`, visible: false, fixedrange: true };
    titles.push(`<div style="left:${(100 * col) / columns}%;width:${100 / columns}%;top:${row * ROW}px">` +
      `${title.map(escapeHtml).join('<br>')}</div>`);
    return {
      type: 'heatmap', x, y, z, xaxis: `x${n}`, yaxis: `y${n}`, zmin: -range, zmax: range,
      colorscale: DEVIATION_SCALE, showscale: false, name: title[0],
    };
  });
  labels.style.height = `${height}px`;
  labels.innerHTML = titles.join('');
  return reactPlot(Plotly, el, traces, layout, { staticPlot: true, responsive: true });
}

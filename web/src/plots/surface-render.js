// Drawing a 3D surface on a 2D canvas: an orthographic view of the box (aspect 1.6 : 1 : 0.6),
// the walls behind it with grid lines at the ticks, the grid's quads far ones first, each coloured
// by its mean value and shaded by its slope, then ticks, titles and the colour bar.
import { colourOf, css, ticks, tickText } from './colours.js';
import { FONT, colourBar, sized } from './canvas.js';

const RAD = Math.PI / 180;
const HALF = { x: 0.8, y: 0.5, z: 0.3 };
const MESH = 100;

// Orthographic view: turned by az about the vertical, then tilted by el towards the viewer.
function projector(view, width, height) {
  const [ca, sa, ce, se] = [Math.cos(view.az * RAD), Math.sin(view.az * RAD), Math.cos(view.el * RAD), Math.sin(view.el * RAD)];
  const raw = (x, y, z) => {
    const x1 = x * ca - y * sa, y1 = x * sa + y * ca;
    return [x1, z * ce + y1 * se, y1 * ce - z * se];  // screen right, screen up, depth (far is larger)
  };
  let [u0, u1, v0, v1] = [Infinity, -Infinity, Infinity, -Infinity];
  for (const x of [-HALF.x, HALF.x]) for (const y of [-HALF.y, HALF.y]) for (const z of [-HALF.z, HALF.z]) {
    const [u, v] = raw(x, y, z);
    [u0, u1, v0, v1] = [Math.min(u0, u), Math.max(u1, u), Math.min(v0, v), Math.max(v1, v)];
  }
  const area = { left: 70, right: width - 130, top: 52, bottom: height - 45 };
  const scale = Math.min((area.right - area.left) / (u1 - u0), (area.bottom - area.top) / (v1 - v0));
  const cx = (area.left + area.right) / 2 - ((u0 + u1) / 2) * scale, cy = (area.top + area.bottom) / 2 + ((v0 + v1) / 2) * scale;
  return (x, y, z) => {
    const [u, v, d] = raw(x, y, z);
    return [cx + u * scale, cy - v * scale, d];
  };
}

// Returns the grid points with their screen positions, for the tooltip.
export function renderSurface(base, overlay, width, spec, view) {
  const height = spec.height;
  const g = sized(base, width, height);
  sized(overlay, width, height);
  g.fillStyle = '#fff';
  g.fillRect(0, 0, width, height);
  const P = projector(view, width, height);
  const { x, y, z, range } = spec;
  const [x0, x1, y0, y1] = [x[0], x[x.length - 1], y[0], y[y.length - 1]];
  const nx = (v) => ((v - x0) / (x1 - x0 || 1) - 0.5) * 2 * HALF.x;
  const ny = (v) => ((v - y0) / (y1 - y0 || 1) - 0.5) * 2 * HALF.y;
  const nz = (v) => (v / range) * HALF.z;
  const far = (px, py, pz) => P(px, py, pz)[2];
  // The walls behind the surface and the edges the ticks stand on.
  const bx = far(HALF.x, 0, 0) > far(-HALF.x, 0, 0) ? HALF.x : -HALF.x;
  const by = far(0, HALF.y, 0) > far(0, -HALF.y, 0) ? HALF.y : -HALF.y;
  const floor = view.el >= 0 ? -HALF.z : HALF.z;
  const [zx, zy] = [[-HALF.x, -HALF.y], [HALF.x, -HALF.y], [HALF.x, HALF.y], [-HALF.x, HALF.y]]
    .reduce((a, b) => (P(b[0], b[1], 0)[0] < P(a[0], a[1], 0)[0] ? b : a));
  const axes = [
    { title: spec.axes.x, values: ticks(x0, x1), at: (v) => [nx(v), -by, floor], wall: (v) => [[nx(v), -by, floor], [nx(v), by, floor], [nx(v), by, -floor]] },
    { title: spec.axes.y, values: ticks(y0, y1), at: (v) => [-bx, ny(v), floor], wall: (v) => [[-bx, ny(v), floor], [bx, ny(v), floor], [bx, ny(v), -floor]] },
    { title: spec.axes.z, values: ticks(-range, range), at: (v) => [zx, zy, nz(v)], top: true, wall: (v) => [[-bx, by, nz(v)], [bx, by, nz(v)], [bx, -by, nz(v)]] },
  ];
  const line = (pts, colour) => {
    g.strokeStyle = colour;
    g.beginPath();
    pts.map((p) => P(...p)).forEach(([sx, sy], k) => (k ? g.lineTo(sx, sy) : g.moveTo(sx, sy)));
    g.stroke();
  };
  g.lineWidth = 1;
  for (const a of axes) for (const v of a.values) line(a.wall(v), '#e2e5ea');
  line([[-bx, -by, floor], [bx, -by, floor], [bx, by, floor], [-bx, by, floor], [-bx, -by, floor]], '#b8bec8');

  // The surface, far quads first, each shaded by its slope towards the viewer.
  // At most MESH lines each way are drawn (every grid point up to that; beyond, every k-th line,
  // the last always): finer than a few pixels does not show, and the map beside shows them all.
  const lines = (n) => { const k = Math.ceil((n - 1) / MESH); const out = []; for (let i = 0; i < n - 1; i += k) out.push(i); out.push(n - 1); return out; };
  const [xi, yi] = [lines(x.length), lines(y.length)];
  const pt = yi.map((i) => xi.map((j) => P(nx(x[j]), ny(y[i]), nz(z[i][j]))));
  const quads = [];
  for (let a = 0; a + 1 < yi.length; a++) {
    for (let b = 0; b + 1 < xi.length; b++) {
      const [i, i1, j, j1] = [yi[a], yi[a + 1], xi[b], xi[b + 1]];
      const c = [pt[a][b], pt[a][b + 1], pt[a + 1][b + 1], pt[a + 1][b]];
      const mean = (z[i][j] + z[i][j1] + z[i1][j1] + z[i1][j]) / 4;
      const ux = nx(x[j1]) - nx(x[j]), uy = ny(y[i1]) - ny(y[i]);
      const dzx = nz((z[i][j1] + z[i1][j1] - z[i][j] - z[i1][j]) / 2), dzy = nz((z[i1][j] + z[i1][j1] - z[i][j] - z[i][j1]) / 2);
      const slope = Math.hypot(dzx / ux, dzy / uy);
      quads.push({ c, depth: (c[0][2] + c[1][2] + c[2][2] + c[3][2]) / 4, rgb: colourOf(mean, range, 1 - 0.25 * Math.min(1, slope)) });
    }
  }
  quads.sort((p, q) => q.depth - p.depth);
  const edges = xi.length <= 41 && yi.length <= 41;
  for (const q of quads) {
    g.beginPath();
    q.c.forEach(([sx, sy], k) => (k ? g.lineTo(sx, sy) : g.moveTo(sx, sy)));
    g.closePath();
    g.fillStyle = css(q.rgb);
    g.fill();
    g.strokeStyle = edges ? 'rgba(40,40,40,0.35)' : g.fillStyle;
    g.stroke();
  }

  // Ticks and titles beside their edges, on the side away from the box's centre.
  const [mx, my] = P(0, 0, 0);
  g.fillStyle = '#2a3340';
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  for (const a of axes) {
    const ends = [a.at(a.values[0]), a.at(a.values[a.values.length - 1])].map((p) => P(...p));
    let [nx0, ny0] = [ends[0][1] - ends[1][1], ends[1][0] - ends[0][0]];
    const d = Math.hypot(nx0, ny0) || 1;
    [nx0, ny0] = [nx0 / d, ny0 / d];
    if (nx0 * (ends[0][0] - mx) + ny0 * (ends[0][1] - my) < 0) [nx0, ny0] = [-nx0, -ny0];
    const label = (text, [sx, sy], push) => {
      const w = g.measureText(text).width;
      const k = push + (Math.abs(nx0) * w) / 2 + Math.abs(ny0) * 7;
      g.fillText(text, sx + nx0 * k, sy + ny0 * k);
    };
    g.font = FONT;
    const widest = Math.max(...a.values.map((v) => g.measureText(tickText(v)).width));
    for (const v of a.values) label(tickText(v), P(...a.at(v)), 6);
    g.font = `600 ${FONT}`;
    if (a.top) {
      // Above the box, over its vertical edge, clear of the surface.
      const top = Math.min(...[[-1, -1], [1, -1], [1, 1], [-1, 1]].map(([u, v]) => P(u * HALF.x, v * HALF.y, HALF.z)[1]));
      g.fillText(a.title, Math.max(P(zx, zy, HALF.z)[0], g.measureText(a.title).width / 2 + 4), top - 14);
    } else {
      const mid = P(...a.at((a.values[0] + a.values[a.values.length - 1]) / 2));
      label(a.title, mid, 14 + Math.abs(nx0) * widest + Math.abs(ny0) * 14);
    }
  }
  g.font = `600 14px system-ui, sans-serif`;
  g.textAlign = 'center';
  g.fillText(spec.title, width / 2, 16);
  colourBar(g, width - 70, 40, height - 85, range, spec.colourTitle || 'µm');
  return yi.flatMap((i, a) => xi.map((j, b) => ({ i, j, s: pt[a][b] })));
}


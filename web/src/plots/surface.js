// A deviation topography as a 3D surface, drawn on a 2D canvas (WebGL in software rendering took
// seconds per surface). Drag or the arrow keys turn it, a double click resets the view, and the
// pointer shows the nearest grid point's values.
import { hover } from './canvas.js';
import { renderSurface } from './surface-render.js';

const VIEW = { az: -35, el: 28 };

// spec: {x, y, z (rows along y of values along x), range, height, title,
//        axes: {x, y, z} titles, hover: (i, j) => text}
export function drawSurface(el, spec) {
  if (!el.hobsharpSurface) el.hobsharpSurface = mount(el);
  el.hobsharpSurface.show(spec);
}

export function clearSurface(el) {
  if (el.hobsharpSurface) el.hobsharpSurface.clear();
}

function mount(el) {
  el.replaceChildren();
  el.classList.add('surface');
  const base = document.createElement('canvas');
  const overlay = document.createElement('canvas');
  overlay.tabIndex = 0;
  overlay.setAttribute('role', 'img');
  el.append(base, overlay);
  const view = { ...VIEW };
  let spec = null, frame = null, points = [];

  const draw = () => {
    frame = null;
    if (!spec) return;
    points = renderSurface(base, overlay, el.clientWidth || 600, spec, view);
  };
  const redraw = () => { if (!frame) frame = requestAnimationFrame(draw); };
  const turn = (daz, del) => {
    view.az += daz;
    view.el = Math.min(90, Math.max(-10, view.el + del));
    redraw();
  };
  let drag = null;
  overlay.addEventListener('pointerdown', (e) => { drag = { x: e.clientX, y: e.clientY }; overlay.setPointerCapture(e.pointerId); });
  overlay.addEventListener('pointerup', () => { drag = null; });
  overlay.addEventListener('pointermove', (e) => {
    if (drag) {
      turn((e.clientX - drag.x) * 0.5, (e.clientY - drag.y) * 0.5);
      drag = { x: e.clientX, y: e.clientY };
    } else if (spec) {
      const r = overlay.getBoundingClientRect();
      hover(overlay, points, e.clientX - r.left, e.clientY - r.top, spec);
    }
  });
  overlay.addEventListener('pointerleave', () => hover(overlay, [], 0, 0, spec));
  overlay.addEventListener('dblclick', () => { Object.assign(view, VIEW); redraw(); });
  overlay.addEventListener('keydown', (e) => {
    const step = { ArrowLeft: [-5, 0], ArrowRight: [5, 0], ArrowUp: [0, -5], ArrowDown: [0, 5] }[e.key];
    if (step) { e.preventDefault(); turn(...step); }
  });
  new ResizeObserver(redraw).observe(el);
  return {
    show(next) { spec = next; el.hidden = false; overlay.setAttribute('aria-label', `${next.title}: 3D surface; arrow keys turn it`); draw(); },
    clear() { spec = null; points = []; el.hidden = true; for (const c of [base, overlay]) c.getContext('2d').clearRect(0, 0, c.width, c.height); },
  };
}

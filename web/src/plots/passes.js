// When the plots are drawn. After every result (or a switch of view), once the numbers are on
// screen and the plotting library (plotly.min.js: Plotly's core with the heatmap and bar traces;
// the surface trace is registered when the first surface is drawn), which loads in parallel with the calculator, is there: first the quick plots (axis
// motions, wheel, maps, singular values), then, after the browser has shown them, the slow ones
// (the 3D surfaces when they are open, the sensitivity gallery). A newer result stops a pass
// under way; 'plots' is emitted when a pass has drawn every plot. A plot kept on demand (in a
// closed <details>: the wheel, the axis motions, the sensitivities) is drawn when it is opened, or
// when print opens it ('print', views/report.js: drawn at once, before the report sizes the plots).
import { loadScript } from '../client.js';
import { keepToolbarsUntabbed } from './config.js';

let loading = null;
export function loadPlotly() {
  if (!loading) loading = self.Plotly ? Promise.resolve(self.Plotly) : loadScript('plotly.min.js').then(() => self.Plotly);
  return loading;
}

const nextFrame = () => new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));

// Whether a drawer's plots wait until they are opened: each inside a closed <details>.
const onDemand = (d) => d.el && d.el.every((s) => Boolean(document.querySelector(s)?.closest('details:not([open])')));

export function mountPlots(store) {
  keepToolbarsUntabbed();
  const drawers = [];
  let generation = 0;
  let inFlight = 0;  // passes started and not yet ended (drawn, stopped by a newer one, or failed)

  async function pass() {
    inFlight += 1;
    try { await drawAll(); } finally { inFlight -= 1; }
  }

  async function drawAll() {
    const mine = ++generation;
    const current = () => mine === generation;
    await nextFrame();
    try {
      const Plotly = await loadPlotly();
      for (const later of [false, true]) {
        if (later) await nextFrame();
        for (const d of drawers.filter((x) => x.later === later)) {
          if (!current() || !store.state.result) return;
          d.pending = onDemand(d);
          if (!d.pending) await d.draw({ Plotly, result: store.state.result, state: store.state, current });
        }
      }
    } catch (e) {
      if (current()) store.setStatus(`The plots cannot be drawn: ${e.message}. The numbers above stand.`, 'error');
      return;
    }
    if (current()) store.emit('plots', { at: performance.now() });
  }

  // The drawers that waited while their plots were on demand and are no longer: taken to be drawn.
  function takeWaiting() {
    const waiting = drawers.filter((d) => d.pending && !onDemand(d));
    for (const d of waiting) d.pending = false;
    return waiting;
  }

  // A <details> opened: the plots in it that waited are drawn, those drawn while it was closed are
  // laid out again at their width (drawn hidden, Plotly took its default size).
  async function opened(details) {
    const mine = generation;
    const Plotly = await loadPlotly().catch(() => null);
    if (!Plotly || !store.state.result) return;
    for (const el of details.querySelectorAll('.js-plotly-plot')) Plotly.Plots.resize(el);
    const waiting = takeWaiting();
    for (const d of waiting) {
      if (mine !== generation) return;  // a newer pass draws them
      await d.draw({ Plotly, result: store.state.result, state: store.state, current: () => mine === generation });
    }
    if (waiting.length && mine === generation) store.emit('plots', { at: performance.now() });
  }
  document.addEventListener('toggle', (e) => { if (e.target.open) opened(e.target); }, true);
  // Print opened the parts it prints: their plots are drawn now, not after the toggle events (a
  // cartesian plot of Plotly's is drawn within the call), so that the report can size them.
  store.on('print', () => {
    if (!self.Plotly || !store.state.result) return;
    for (const d of takeWaiting()) {
      Promise.resolve(d.draw({ Plotly: self.Plotly, result: store.state.result, state: store.state, current: () => true })).catch(() => {});
    }
  });

  store.on('result', pass);
  store.on('view', pass);
  // The window made wider or narrower (a tablet turned, a desktop window resized): a pass draws
  // every plot again, so that what a plot lays out by its width when drawn (the gallery's columns,
  // the pass history's panels, the surfaces' camera, titles broken on a phone) fits the new width.
  // Plotly's own resize only stretches the layout drawn. A change of height alone (a phone's
  // toolbar sliding away) changes nothing drawn.
  // While print media apply the plots are at the paper's width (views/report.js), whatever the
  // window's: a width pass then would draw them at the window's, past the paper's edge. It waits
  // until print is over.
  let width = window.innerWidth, widthTimer = 0, widthWaiting = false;
  const printMedia = window.matchMedia('print');
  const widthPass = () => {
    widthWaiting = false;
    if (window.innerWidth === width || printMedia.matches) return;
    width = window.innerWidth;
    store.emit('width');  // the views that draw on their own (the pass history) draw again
    if (store.state.result) pass();
  };
  window.addEventListener('resize', () => {
    clearTimeout(widthTimer);
    widthWaiting = window.innerWidth !== width && !printMedia.matches;
    widthTimer = setTimeout(widthPass, 200);
  });
  printMedia.addEventListener('change', () => { if (!printMedia.matches) widthPass(); });
  return {
    // draw({Plotly, result, state, current}) draws one view's plots; those added with
    // {later: true} are drawn after the others have shown. current() turns false once a newer
    // pass has started. el: the selectors of the elements it draws in; given, the drawing waits
    // while they are all on demand (see onDemand).
    add(draw, { later = false, el = null } = {}) { drawers.push({ draw, later, el }); },
    // A view that shows a plot it did not show before (the 3D surfaces) asks for a pass.
    redraw() { if (store.state.result) pass(); },
    // Whether a pass is under way (the tests' hobsharpTest.settled() waits until none is).
    busy: () => inFlight > 0 || widthWaiting,
  };
}

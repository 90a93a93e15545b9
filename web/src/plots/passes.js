// When the plots are drawn. After every result (or a switch of view), once the numbers are on
// screen and the plotting library (plotly.min.js: Plotly's core with the heatmap and bar traces;
// the surface trace is registered when the first surface is drawn), which loads in parallel with the calculator, is there: first the quick plots (axis
// motions, wheel, maps, singular values), then, after the browser has shown them, the slow ones
// (the 3D surfaces when they are open, the sensitivity gallery). A newer result stops a pass
// under way; 'plots' is emitted when a pass has drawn every plot.
import { loadScript } from '../client.js';

let loading = null;
export function loadPlotly() {
  if (!loading) loading = self.Plotly ? Promise.resolve(self.Plotly) : loadScript('plotly.min.js').then(() => self.Plotly);
  return loading;
}

const nextFrame = () => new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));

export function mountPlots(store) {
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
          await d.draw({ Plotly, result: store.state.result, state: store.state, current });
        }
      }
    } catch (e) {
      if (current()) store.setStatus(`The plots cannot be drawn: ${e.message}. The numbers above stand.`, 'error');
      return;
    }
    if (current()) store.emit('plots', { at: performance.now() });
  }

  store.on('result', pass);
  store.on('view', pass);
  return {
    // draw({Plotly, result, state, current}) draws one view's plots; those added with
    // {later: true} are drawn after the others have shown. current() turns false once a newer
    // pass has started.
    add(draw, { later = false } = {}) { drawers.push({ draw, later }); },
    // A view that shows a plot it did not show before (the 3D surfaces) asks for a pass.
    redraw() { if (store.state.result) pass(); },
    // Whether a pass is under way (the tests' hobsharpTest.settled() waits until none is).
    busy: () => inFlight > 0,
  };
}

// When the plots are drawn. After every result (or a switch of view), once the numbers are on
// screen: first the plots drawn on a canvas of our own, then the Plotly ones, once the plotting
// library (plotly.min.js: Plotly's core with the heatmap and bar traces), which loads in parallel
// with the calculator, is there. A newer result stops a pass under way; 'plots' is emitted when a
// pass has drawn every plot.
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

  async function pass() {
    const mine = ++generation;
    const current = () => mine === generation;
    await nextFrame();
    try {
      for (const plotly of [false, true]) {
        const Plotly = plotly ? await loadPlotly() : null;
        for (const d of drawers.filter((x) => x.plotly === plotly)) {
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
    // draw({Plotly, result, state, current}) draws one view's plots (Plotly is there only for
    // those added with {plotly: true}); current() turns false once a newer pass has started.
    add(draw, { plotly }) { drawers.push({ draw, plotly }); },
  };
}

// The plotting library as the page loads it (plotly.min.js, bundled by the site target): Plotly's
// core, which brings the scatter trace, the heatmap and bar traces, and the surface (3D) trace.
// The surface trace (and the WebGL code under it) is in the file but evaluated only when
// plotlySurface() is first called: evaluating it takes longer than the rest of Plotly together,
// and the 3D surfaces are drawn only on demand.
const Plotly = require('plotly.js/lib/core');

Plotly.register([require('plotly.js/lib/heatmap'), require('plotly.js/lib/bar')]);
let surface = false;
self.plotlySurface = () => {
  if (!surface) Plotly.register([require('plotly.js/lib/surface')]);
  surface = true;
  return Plotly;
};
self.Plotly = Plotly;

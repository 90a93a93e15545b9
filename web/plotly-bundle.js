// The plotting library as the page loads it (plotly.min.js, bundled by the site target): Plotly's
// core, which brings the scatter trace, and the heatmap and bar traces. The 3D surfaces and the
// sensitivity thumbnails are drawn on canvases by the page itself (web/src/plots/).
import Plotly from 'plotly.js/lib/core';
import bar from 'plotly.js/lib/bar';
import heatmap from 'plotly.js/lib/heatmap';

Plotly.register([heatmap, bar]);
self.Plotly = Plotly;

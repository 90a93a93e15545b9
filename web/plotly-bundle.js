// The plotting library as the page loads it (plotly.min.js, bundled by the site target): Plotly's
// core, which brings the scatter trace, and the surface (3D), heatmap and bar traces; nothing else.
import Plotly from 'plotly.js/lib/core';
import bar from 'plotly.js/lib/bar';
import heatmap from 'plotly.js/lib/heatmap';
import surface from 'plotly.js/lib/surface';

Plotly.register([surface, heatmap, bar]);
self.Plotly = Plotly;

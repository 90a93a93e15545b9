// How every plot of the page is configured: Plotly's toolbar (the modebar) shows only while the
// pointer is over its plot (style.css hides it on a phone, where it would cover the title), and
// its buttons are never a tab stop (keepToolbarsUntabbed).
export const PLOT_CONFIG = Object.freeze({ responsive: true, displaylogo: false, displayModeBar: 'hover' });

// A plot's element: `el` itself, or the element of that id.
const plotElement = (el) => (typeof el === 'string' && typeof document !== 'undefined' ? document.getElementById(el) : el);

// A plot narrower than this (px) is on a phone: its long titles and legend entries break onto two
// lines, and a 3D surface's colour bar lies under the scene.
export const NARROW_PLOT = 560;
// The width a plot is drawn at, px (0 without an element).
export const plotWidth = (el) => {
  const node = plotElement(el);
  return (node && node.clientWidth) || 0;
};
export const isNarrowPlot = (el) => (plotWidth(el) || 1000) < NARROW_PLOT;

// Draws (or redraws) a plot: Plotly.react, with the plot's container held at the layout's height.
// On a window's resize (a phone's toolbar sliding away, a tablet turned) Plotly's responsive mode
// drops a layout's height unless it also gives a width, and sizes the plot to its container: a
// container left to its content then shrank the plot to the page's smallest (200 px), cutting the
// maps' axes, colour bars and legends.
export function reactPlot(Plotly, el, traces, layout, config = PLOT_CONFIG) {
  const node = plotElement(el);
  if (layout.height && node && node.style) node.style.height = `${layout.height}px`;
  return Plotly.react(node, traces, layout, config);
}

// Empties a plot (Plotly.purge) and lets its container fall back to the page's own height, which
// reactPlot had held at the plot's.
export function purgePlot(Plotly, el) {
  const node = plotElement(el);
  if (node && node.style) node.style.height = '';
  return Plotly.purge(node);
}

// Takes the toolbars' buttons out of the tab order (Plotly makes them <button>s), each as Plotly
// adds it, whichever view drew its plot.
export function keepToolbarsUntabbed(root = document.body) {
  const untab = (node) => {
    if (node.nodeType !== 1) return;
    if (node.classList.contains('modebar-btn')) node.tabIndex = -1;
    for (const b of node.querySelectorAll('.modebar-btn')) b.tabIndex = -1;
  };
  untab(root);
  new MutationObserver((records) => { for (const r of records) r.addedNodes.forEach(untab); })
    .observe(root, { childList: true, subtree: true });
}

// How every plot of the page is configured: Plotly's toolbar (the modebar) shows only while the
// pointer is over its plot (style.css hides it on a phone, where it would cover the title), and
// its buttons are never a tab stop (keepToolbarsUntabbed).
export const PLOT_CONFIG = Object.freeze({ responsive: true, displaylogo: false, displayModeBar: 'hover' });

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

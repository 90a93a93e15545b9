// How every plot of the page is configured: Plotly's toolbar (the modebar) shows only while the
// pointer is over its plot (style.css hides it on a phone, where it would cover the title), and
// its buttons are out of the keyboard's tab order (untabbable, after each drawing).
export const PLOT_CONFIG = Object.freeze({ responsive: true, displaylogo: false, displayModeBar: 'hover' });

// Takes the toolbars' buttons under `root` out of the tab order: Plotly makes them <button>s.
export function untabToolbars(root = document) {
  for (const b of root.querySelectorAll('.modebar-btn')) b.tabIndex = -1;
}

// The warning in the answer when the top band of the face lies past the edge of the wheel's
// envelope (docs/method.md, "The edge of the wheel's envelope"): the module's own sentence
// (wheelProfile.edge), hidden when the conjugate wheel's profile reaches the tip.
export function wheelEdgeText(result) {
  return (result && result.wheelProfile && result.wheelProfile.edge) || '';
}

export function mountWheelEdge(store) {
  const note = document.querySelector('#wheel-edge');
  store.on('result', ({ result }) => {
    const edge = wheelEdgeText(result);
    note.hidden = !edge;
    note.textContent = edge;
  });
}

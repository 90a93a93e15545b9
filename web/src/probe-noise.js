// The probe noise the correction assumes (correction.probeNoise, σ in µm). A grid the page grinds
// from a what-if is noise-free, and the page declares it so (1e-4 µm, docs/case-format.md): the
// correction then fits all of it. A grid pasted or uploaded is measured: the case's own σ, or the
// calculator's default (0.5 µm), so that the correction never fits the probe's noise.
export const SIMULATED_NOISE = 1e-4;

// The correction's options (state.tuning) for a grid that is simulated or measured.
export function tuningFor(tuning, simulated) {
  const { probeNoise, ...rest } = tuning;
  if (simulated) return { ...rest, probeNoise: SIMULATED_NOISE };
  return probeNoise === SIMULATED_NOISE ? rest : { ...tuning };
}

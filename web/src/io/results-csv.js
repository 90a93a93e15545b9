// The results as CSV: the axis polynomials (nominal and corrected) with their units, and the
// topography grids; the wheel profile's points for a dresser.
import { AXES, coefficientUnit } from '../limits.js';
import { motionUnit } from '../format.js';

export function resultsCsv(r) {
  const lines = ['# HobSharp results (hobsharp-case/1)', '# axis polynomials', 'coefficient,unit,nominal,corrected'];
  const per = motionUnit(r);
  for (const a of AXES) {
    r.axes[a].forEach((v, k) => {
      const c = r.correction ? r.correction.axes[a][k] : '';
      lines.push(`${a} a${k},${coefficientUnit(a, k, per)},${v},${c}`);
    });
  }
  const grid = (title, z) => {
    lines.push('', `# ${title}; rows r (mm) root to tip, columns x (mm) along the gash`);
    lines.push(['r \\ x', ...r.topography.x].join(','));
    z.forEach((row, i) => lines.push([r.topography.r[i], ...row].join(',')));
  };
  grid('simulated normal deviation (µm) for the axes run', r.topography.normal);
  grid('simulated circular deviation (µm at the mean radius)', r.topography.circular);
  if (r.correction) grid('predicted normal deviation after correction (µm)', r.correction.residual);
  lines.push('', `# thickness error at the mean point (µm),${r.topography.thickness}`);
  return lines.join('\n') + '\n';
}

export function profileCsv(r) {
  const p = r.wheelProfile;
  const rows = ['# wheel axial profile: tooth-face radius r, wheel radius R, axial position Z (mm)', 'r_mm,R_mm,Z_mm'];
  p.r.forEach((radius, i) => rows.push(`${radius},${p.R[i]},${p.Z[i]}`));
  return rows.join('\n') + '\n';
}

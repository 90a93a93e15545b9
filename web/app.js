// HobSharp's page: the inputs of Tab. 1, a worker that runs the WebAssembly module, and the plots.
// Nothing here computes geometry; every number shown comes from the module's evaluate(case).
'use strict';

const AXES = ['X', 'Y', 'Z', 'A', 'B'];
const ROTARY = new Set(['A', 'B']);
const AXIS_NAMES = {
  X: 'C<sub>x</sub> horizontal stroke', Y: 'C<sub>y</sub> radial infeed', Z: 'C<sub>z</sub> wheel axial',
  A: 'ψ<sub>a</sub> hob rotation', B: 'ψ<sub>b</sub> wheel swivel',
};
const SUPERSCRIPT = ['', '', '²', '³', '⁴', '⁵', '⁶'];
const MAX_CSV_BYTES = 2 * 1024 * 1024;
const DEBOUNCE_MS = 250;

const $ = (selector) => document.querySelector(selector);
const $$ = (selector) => Array.from(document.querySelectorAll(selector));

// ---------------------------------------------------------------------------------------------
// Formatting: every number on the page goes through these; nothing that is not finite is shown.

function fmt(v, significant = 7) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return '—';
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a < 1e-4 || a >= 1e7) return v.toExponential(Math.max(0, significant - 3));
  return String(Number(v.toPrecision(significant)));
}
function fixed(v, digits) {
  return typeof v === 'number' && Number.isFinite(v) ? v.toFixed(digits) : '—';
}
function signed(v, digits) {
  return typeof v === 'number' && Number.isFinite(v) ? (v > 0 ? '+' : '') + v.toFixed(digits) : '—';
}
function motionUnit(result) { return result && result.setup.motionUnit === 'mm' ? 'mm' : 'rad'; }
function motionSymbol(result) { return motionUnit(result) === 'mm' ? 's' : 'φ₁'; }
function coefficientUnit(axis, k, per) {
  const base = ROTARY.has(axis) ? 'rad' : 'mm';
  return k === 0 ? base : `${base}/${per}${SUPERSCRIPT[k]}`;
}
function polynomialText(coefficients, symbol) {
  const terms = [];
  coefficients.forEach((c, k) => {
    if (c === 0 && !(k === 0 && coefficients.every((x) => x === 0))) return;
    const value = fmt(Math.abs(c), 7);
    const sign = c < 0 ? '−' : '+';
    const power = k === 0 ? '' : k === 1 ? ` ${symbol}` : ` ${symbol}${SUPERSCRIPT[k]}`;
    terms.push({ sign, text: `${value}${power}`, k });
  });
  return terms.map((t, i) => (i === 0 ? (t.sign === '−' ? '−' : '') : ` ${t.sign} `) + t.text).join('');
}

// ---------------------------------------------------------------------------------------------
// The worker: built from the module's factory and hobsharpWorkerMain, as a blob of our own code.

// The worker: from worker.js when served; from a file opened on disk (where a page may not start
// a worker from a file URL), from a blob of the module's factory and hobsharpWorkerMain, both
// loaded into the page for that purpose.
function loadScript(src) {
  return new Promise((resolve, reject) => {
    const el = document.createElement('script');
    el.src = src;
    el.onload = resolve;
    el.onerror = () => reject(new Error(`${src} did not load`));
    document.head.append(el);
  });
}

async function startWorker() {
  if (location.protocol !== 'file:') return new Worker('worker.js');
  await loadScript('hobsharp.js');
  await loadScript('worker-main.js');
  const source = `var _scriptDir;\nvar HobSharpModule = ${HobSharpModule.toString()};\n` +
    `(${hobsharpWorkerMain.toString()})(self, HobSharpModule);\n`;
  return new Worker(URL.createObjectURL(new Blob([source], { type: 'text/javascript' })));
}

const worker = (() => {
  const started = startWorker();
  const pending = new Map();
  let nextId = 1;
  const onmessage = (event) => {
    const { id, ok, result, error, ms } = event.data;
    const p = pending.get(id);
    if (!p) return;
    pending.delete(id);
    if (ok) p.resolve({ result, ms });
    else {
      const e = new Error(error.message);
      e.field = error.field;
      p.reject(e);
    }
  };
  const onerror = (event) => {
    for (const p of pending.values()) p.reject(new Error(`The calculator stopped: ${event.message || 'the worker failed to start'}`));
    pending.clear();
  };
  started.then((w) => { w.onmessage = onmessage; w.onerror = onerror; }, onerror);
  return {
    evaluate(caseObject) {
      const id = nextId++;
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject });
        started.then((w) => w.postMessage({ id, caseObject }), reject);
      });
    },
  };
})();

// ---------------------------------------------------------------------------------------------
// State: the case in the form, the measured grid, the what-if offsets and the locks.

const state = {
  measured: null,          // rows root to tip of values along the gash, µm
  offsets: {},             // axis -> offsets per coefficient
  locked: new Set(),       // 'X a0' ...
  lockedAxes: new Set(),   // 'X' ...
  result: null,            // the last good result
  resultCase: null,        // the case it came from
  view: 'normal',
  latest: 0,               // the newest recompute; older answers are dropped
  galleryGeneration: 0,    // the newest run of sensitivity thumbnails
};

function setPath(object, path, value) {
  const keys = path.split('.');
  let o = object;
  for (const k of keys.slice(0, -1)) o = o[k] = o[k] || {};
  o[keys[keys.length - 1]] = value;
}
function getPath(object, path) {
  return path.split('.').reduce((o, k) => (o == null ? undefined : o[k]), object);
}

function readForm() {
  const c = { format: 'hobsharp-case/1', hob: {}, wheel: {}, setup: {}, machine: {} };
  for (const el of $$('#inputs [data-field]')) {
    const field = el.dataset.field;
    if (el.tagName === 'SELECT') { setPath(c, field, el.value); continue; }
    if (el.value.trim() === '') {
      if (el.validity && el.validity.badInput) setPath(c, field, el.value); // lets the module name it
      continue;
    }
    setPath(c, field, Number(el.value));
  }
  if (c.hob.gash === 'straight') { delete c.hob.gashLead; delete c.hob.gashHelixAngle; delete c.hob.hand; }
  else if ($('#gash-by').value === 'lead') delete c.hob.gashHelixAngle;
  else delete c.hob.gashLead;
  return c;
}

function writeForm(c) {
  for (const el of $$('#inputs [data-field]')) {
    const v = getPath(c, el.dataset.field);
    if (el.tagName === 'SELECT') el.value = v === undefined ? el.options[0].value : v;
    else el.value = v === undefined || v === null ? '' : String(v);
  }
  $('#gash-by').value = c.hob && c.hob.gashLead === undefined && c.hob.gashHelixAngle !== undefined ? 'angle' : 'lead';
  showGashFields();
}

function showGashFields() {
  const helical = $('[data-field="hob.gash"]').value !== 'straight';
  const byLead = $('#gash-by').value === 'lead';
  for (const el of $$('.helical-only')) el.hidden = !helical;
  for (const el of $$('.by-lead')) el.hidden = !helical || !byLead;
  for (const el of $$('.by-angle')) el.hidden = !helical || byLead;
}

// The case as sent to the module: the form, plus the measured grid and the locks.
function currentCase() {
  const c = readForm();
  if (state.measured) {
    c.measured = state.measured;
    c.correction = { lockedAxes: [...state.lockedAxes], locked: [...state.locked] };
  }
  return c;
}

function loadCase(c) {
  writeForm(c);
  state.measured = Array.isArray(c.measured) ? c.measured : null;
  state.locked = new Set((c.correction && c.correction.locked) || []);
  state.lockedAxes = new Set((c.correction && c.correction.lockedAxes) || []);
  $('#measured-csv').value = state.measured ? state.measured.map((row) => row.join(', ')).join('\n') : '';
  recompute(0);
}

// ---------------------------------------------------------------------------------------------
// Errors: at the field, with the previous results left on screen.

function clearErrors() {
  for (const el of $$('.invalid')) el.classList.remove('invalid');
  for (const el of $$('.field-message')) el.remove();
  $('#form-error').hidden = true;
  $('#measured-error').hidden = true;
}

function showError(error) {
  const field = error.field || '';
  const input = field && $(`#inputs [data-field="${field}"]`);
  if (input) {
    input.classList.add('invalid');
    const note = document.createElement('span');
    note.className = 'field-message';
    note.textContent = error.message;
    input.closest('label').append(note);
  } else if (field.startsWith('measured') || field.startsWith('correction')) {
    $('#measured-error').textContent = error.message;
    $('#measured-error').hidden = false;
  } else {
    $('#form-error').textContent = error.message;
    $('#form-error').hidden = false;
  }
  setStatus(`Not computed: ${error.message}${state.result ? ' The results below are from the last good input.' : ''}`, 'error');
}

function setStatus(text, kind = '') {
  const s = $('#status');
  s.textContent = text;
  s.className = kind;
}

// ---------------------------------------------------------------------------------------------
// Recompute on change, debounced; the newest request wins.

let timer = null;
function recompute(delay = DEBOUNCE_MS) {
  clearTimeout(timer);
  timer = setTimeout(run, delay);
}

async function run() {
  const caseObject = currentCase();
  const id = ++state.latest;
  setStatus('Computing…', 'busy');
  try {
    const { result, ms } = await worker.evaluate(caseObject);
    if (id !== state.latest) return;
    clearErrors();
    state.result = result;
    state.resultCase = caseObject;
    render(result);
    saveToUrl(caseObject);
    setStatus(`Computed in ${ms.toFixed(1)} ms in a WebAssembly worker.`, 'ok');
    if (!window.hobsharpTimings.firstResult) window.hobsharpTimings.firstResult = performance.now();
    window.hobsharpTimings.results += 1;
  } catch (e) {
    if (id !== state.latest) return;
    clearErrors();
    showError(e);
    window.hobsharpTimings.errors += 1;
  }
}

// ---------------------------------------------------------------------------------------------
// Rendering.

// The numbers first (they need nothing but the result), then the plots once the plotting library,
// which loads asynchronously, is there.
function render(r) {
  renderDerived(r);
  renderTab2(r);
  renderFigures(r);
  renderWhatIf(r);
  renderCorrectionText(r);
  $('#grid-shape').textContent = `${r.topography.r.length} rows × ${r.topography.x.length} values`;
  schedulePlots();
}

let plotsScheduled = false;
function schedulePlots() {
  if (plotsScheduled) return;
  plotsScheduled = true;
  const draw = () => {
    plotsScheduled = false;
    if (!state.result) return;
    const r = state.result;
    renderAxisPlot(r);
    renderWheel(r);
    renderTopography(r);
    renderSensitivities(r);
    window.hobsharpTimings.plotted = window.hobsharpTimings.plotted || performance.now();
  };
  plotly().then(() => requestAnimationFrame(() => setTimeout(draw, 0)),
                 (e) => setStatus(`The plots cannot be drawn: ${e.message}. The numbers above stand.`, 'error'));
}

// The plotting library (4.8 MB) is loaded after the first numbers are on screen, so that it does not
// compete with the module for the machine while the page opens.
let plotlyLoading = null;
function plotly() {
  if (!plotlyLoading) plotlyLoading = window.Plotly ? Promise.resolve() : loadScript('plotly.min.js');
  return plotlyLoading;
}

function renderDerived(r) {
  const s = r.setup;
  const out = (name, text) => { $(`[data-derived="${name}"]`).textContent = text; };
  out('rakeAngle', `rake angle γc = ${fixed(s.rakeAngle, 4)}°`);
  out('gashHelixAngle', s.gashHelixAngle !== undefined ? `helix angle βc = ${fixed(s.gashHelixAngle, 4)}°` : '');
  out('gashLead', s.gashLead !== undefined ? `lead Lc = ${fixed(s.gashLead, 3)} mm` : '');
  out('settingAngle', s.settingAngleDerived ? `auto: ${fixed(s.settingAngle, 4)}° (gash helix angle, by hand)` : `used: ${fmt(s.settingAngle)}°`);
  out('centerDistance', s.centerDistanceDerived ? `auto: ${fixed(s.centerDistance, 6)} mm (wheel rim at the gash root)` : `used: ${fmt(s.centerDistance)} mm`);
  out('screwParameter', s.motionUnit === 'mm' ? 's (mm): straight gash, the hob travels along its axis'
    : `${fixed(s.screwParameter, 4)} φ₁ mm (P_t = L_c / 2π = ${fixed(s.screwParameter, 4)} mm/rad)`);
  $('.motion-symbol').textContent = s.motionUnit === 'mm' ? 's in mm (straight gash)' : 'φ₁ in rad';
}

function renderTab2(r) {
  const symbol = motionSymbol(r);
  const corrected = r.correction && r.correction.axes;
  const unit = (a) => (ROTARY.has(a) ? 'rad' : 'mm');
  $('#tab2 tbody').innerHTML = AXES.map((a) => `<tr>
      <th>${AXIS_NAMES[a]} <span class="unit">(${unit(a)})</span></th>
      <td data-set="nominal" data-axis="${a}">${polynomialText(r.axes[a], symbol)}</td>
      <td data-set="corrected" data-axis="${a}">${corrected ? polynomialText(corrected[a], symbol) : '—'}</td>
    </tr>`).join('');
  const degree = r.axes.X.length - 1;
  const per = motionUnit(r);
  $('#coefficients thead').innerHTML = '<tr><th>coefficient</th><th>unit</th><th>nominal</th><th>corrected</th><th>change</th></tr>';
  const rows = [];
  for (const a of AXES) {
    for (let k = 0; k <= degree; k++) {
      const n = r.axes[a][k], c = corrected ? corrected[a][k] : undefined;
      rows.push(`<tr><td>${a} a${k}</td><td>${coefficientUnit(a, k, per)}</td>
        <td class="num" data-coef="nominal ${a} ${k}">${fmt(n, 9)}</td>
        <td class="num" data-coef="corrected ${a} ${k}">${corrected ? fmt(c, 9) : '—'}</td>
        <td class="num">${corrected ? fmt(c - n, 6) : '—'}</td></tr>`);
    }
  }
  $('#coefficients tbody').innerHTML = rows.join('');
}

function polyAt(c, t) { return c.reduceRight((acc, a) => acc * t + a, 0); }

function renderAxisPlot(r) {
  const n = 121, lo = r.motion.min, hi = r.motion.max;
  const t = Array.from({ length: n }, (_, i) => lo + ((hi - lo) * i) / (n - 1));
  const traces = [];
  const add = (axes, dash, label) => {
    for (const a of AXES) {
      traces.push({
        x: t, y: t.map((v) => polyAt(axes[a], v)), name: `${a} ${label}`, mode: 'lines',
        yaxis: ROTARY.has(a) ? 'y2' : 'y', line: { dash },
      });
    }
  };
  add(r.axes, 'solid', '(nominal)');
  if (r.correction) add(r.correction.axes, 'dot', '(corrected)');
  const u = motionUnit(r);
  Plotly.react('plot-axes', traces, {
    title: { text: 'Axis motions over the motion range' }, margin: { t: 40, r: 60, b: 50, l: 60 }, height: 320,
    xaxis: { title: { text: `${motionSymbol(r)} (${u})` } },
    yaxis: { title: { text: 'X, Y, Z (mm)' } },
    yaxis2: { title: { text: 'A, B (rad)' }, overlaying: 'y', side: 'right' },
    legend: { orientation: 'h', y: -0.25 },
  }, { responsive: true, displaylogo: false });
}

function renderWheel(r) {
  const p = r.wheelProfile;
  Plotly.react('plot-wheel', [{
    x: p.Z, y: p.R, mode: 'lines+markers', marker: { size: 4 }, name: 'axial profile',
    text: p.r.map((v) => `tooth-face radius r = ${fixed(v, 3)} mm`),
    hovertemplate: 'Z = %{x:.4f} mm<br>R = %{y:.4f} mm<br>%{text}<extra></extra>',
  }], {
    title: { text: 'Wheel axial profile (R against Z)' }, height: 360, margin: { t: 40, r: 20, b: 50, l: 60 },
    xaxis: { title: { text: 'Z, along the wheel axis (mm)' } },
    yaxis: { title: { text: 'R, wheel radius (mm)' }, scaleanchor: 'x', scaleratio: 1 },
  }, { responsive: true, displaylogo: false });
}

function colourRange(z) {
  let m = 0;
  for (const row of z) for (const v of row) m = Math.max(m, Math.abs(v));
  return Math.max(m, 0.1);
}

function topographyPlots(prefix, grid, z, title) {
  const range = colourRange(z);
  const colour = { colorscale: 'RdBu', reversescale: true, cmin: -range, cmax: range, zmin: -range, zmax: range };
  const axisX = 'x, along the gash (mm)', axisR = 'r, root → tip (mm)';
  Plotly.react(`plot-${prefix}-3d`, [{
    type: 'surface', x: grid.x, y: grid.r, z, ...colour,
    colorbar: { title: { text: 'µm' } },
  }], {
    title: { text: `${title} (3D)` }, height: 380, margin: { t: 40, r: 10, b: 10, l: 10 },
    scene: { xaxis: { title: { text: axisX } }, yaxis: { title: { text: axisR } },
             zaxis: { title: { text: 'deviation (µm)' }, range: [-range, range] }, aspectmode: 'manual', aspectratio: { x: 1.6, y: 1, z: 0.6 } },
  }, { responsive: true, displaylogo: false });
  Plotly.react(`plot-${prefix}-2d`, [{
    type: 'heatmap', x: grid.x, y: grid.r, z, ...colour, colorbar: { title: { text: 'µm' } },
    hovertemplate: 'x = %{x:.2f} mm<br>r = %{y:.2f} mm<br>%{z:.3f} µm<extra></extra>',
  }], {
    title: { text: `${title} (map)` }, height: 300, margin: { t: 40, r: 10, b: 50, l: 60 },
    xaxis: { title: { text: axisX } }, yaxis: { title: { text: axisR } },
  }, { responsive: true, displaylogo: false });
}

function figuresText(sse, max, thickness) {
  return `Sum of squares ${fmt(sse, 6)} µm² · largest |deviation| ${fixed(max, 3)} µm · thickness error ${signed(thickness, 3)} µm`;
}

function topographyViews(r) {
  const circular = state.view === 'circular';
  const viewName = circular ? 'circular deviation' : 'normal deviation';
  if (r.correction) {
    const c = r.correction;
    return {
      beforeTitle: 'Measured', viewName,
      before: circular ? c.measuredCircular : state.resultCase.measured, beforeName: `Measured ${viewName}`,
      beforeFigures: figuresText(c.sseBefore, c.maxBefore, c.thicknessBefore),
      after: circular ? c.residualCircular : c.residual, afterName: `After correction, ${viewName}`,
      afterFigures: figuresText(c.sseAfter, c.maxAfter, c.thicknessAfter),
    };
  }
  const t = r.topography;
  return {
    beforeTitle: 'Ground face (simulated for the axes run)', viewName,
    before: circular ? t.circular : t.normal, beforeName: `Simulated ${viewName}`,
    beforeFigures: figuresText(t.sse, t.max, t.thickness),
    after: null, afterFigures: 'No correction yet: give a measured topography below.',
  };
}

function renderFigures(r) {
  const v = topographyViews(r);
  $('#before-title').textContent = v.beforeTitle;
  $('#figures-before').textContent = v.beforeFigures;
  $('#figures-after').textContent = v.afterFigures;
}

function renderTopography(r) {
  const grid = { x: r.topography.x, r: r.topography.r };
  const v = topographyViews(r);
  topographyPlots('before', grid, v.before, v.beforeName);
  if (v.after) topographyPlots('after', grid, v.after, v.afterName);
  else for (const id of ['plot-after-3d', 'plot-after-2d']) Plotly.purge(id);
}

function renderWhatIf(r) {
  const degree = r.axes.X.length - 1;
  const per = motionUnit(r);
  const head = ['<tr><th>axis</th><th>lock</th>'];
  for (let k = 0; k <= degree; k++) head.push(`<th>a${k}</th>`);
  $('#what-if thead').innerHTML = head.join('') + '</tr>';
  $('#what-if tbody').innerHTML = AXES.map((a) => {
    const offsets = state.offsets[a] || [];
    const cells = [];
    for (let k = 0; k <= degree; k++) {
      const name = `${a} a${k}`;
      cells.push(`<td><input type="number" step="any" data-offset="${a} ${k}" value="${offsets[k] || ''}" placeholder="0"
        title="offset of ${name}, ${coefficientUnit(a, k, per)}"><span class="unit">${coefficientUnit(a, k, per)}</span>
        <label class="lock"><input type="checkbox" data-lock="${name}" ${state.locked.has(name) ? 'checked' : ''}> lock</label></td>`);
    }
    return `<tr><th>${a}</th><td><input type="checkbox" data-lock-axis="${a}" ${state.lockedAxes.has(a) ? 'checked' : ''} title="lock every coefficient of ${a}"></td>${cells.join('')}</tr>`;
  }).join('');
}

function renderSensitivities(r) {
  const s = r.sensitivities;
  const range = Math.max(Math.abs(r.motion.min), Math.abs(r.motion.max)) || 1;
  const per = motionUnit(r);
  const gallery = $('#gallery');
  if (gallery.childElementCount !== s.coefficients.length) {
    gallery.innerHTML = s.coefficients.map((_, j) => `<div class="thumb" id="sens-${j}"></div>`).join('');
  }
  // One thumbnail per task, so that the page answers between them; a newer result stops the run.
  const generation = ++state.galleryGeneration;
  const drawThumb = (j) => {
    if (generation !== state.galleryGeneration) return;
    if (j >= s.coefficients.length) { window.hobsharpTimings.draws += 1; return; }  // every plot is drawn
    const name = s.coefficients[j];
    const [axis, ak] = name.split(' ');
    const k = Number(ak.slice(1));
    const step = (ROTARY.has(axis) ? 0.01 : 0.1) / Math.pow(range, k);
    const z = s.normal[j].map((row) => row.map((v) => v * step));
    const m = colourRange(z);
    Plotly.react(`sens-${j}`, [{
      type: 'heatmap', x: r.topography.x, y: r.topography.r, z, colorscale: 'RdBu', reversescale: true,
      zmin: -m, zmax: m, showscale: false,
    }], {
      title: { text: `${name} + ${fmt(step, 3)} ${coefficientUnit(axis, k, per)}<br>±${fixed(m, 2)} µm`, font: { size: 11 } },
      width: 190, height: 150, margin: { t: 38, r: 4, b: 16, l: 22 },
      xaxis: { showticklabels: false }, yaxis: { showticklabels: false },
    }, { staticPlot: true });
    setTimeout(() => drawThumb(j + 1), 0);
  };
  drawThumb(0);
  if (r.correction) {
    const sv = r.correction.singularValues;
    const kept = r.correction.rank;
    Plotly.react('plot-singular', [{
      type: 'bar', x: sv.map((_, i) => i + 1), y: sv.map((v) => Math.max(v, 1e-18)),
      marker: { color: sv.map((_, i) => (i < kept ? '#2b6cb0' : '#c53030')) },
      hovertemplate: 'σ%{x} = %{y:.3e}<extra></extra>',
    }], {
      title: { text: `Singular values of the scaled sensitivity matrix (${kept} used)` }, height: 300,
      margin: { t: 40, r: 10, b: 40, l: 60 }, yaxis: { type: 'log', title: { text: 'σ (unit columns)' } },
      xaxis: { title: { text: 'index' } },
    }, { responsive: true, displaylogo: false });
    $('#unobservable').innerHTML = r.correction.unobservable.length
      ? r.correction.unobservable.map((u) => `<li>${u}</li>`).join('')
      : '<li>None: every coefficient combination is seen on the grid.</li>';
  } else {
    Plotly.purge('plot-singular');
    $('#unobservable').innerHTML = '<li>Computed with the correction: give a measured topography.</li>';
  }
}

function renderCorrectionText(r) {
  const v = $('#verdict');
  if (!r.correction) { v.textContent = ''; delete v.dataset.sseBefore; delete v.dataset.sseAfter; return; }
  const c = r.correction;
  v.dataset.sseBefore = c.sseBefore;
  v.dataset.sseAfter = c.sseAfter;
  v.textContent = `${c.verdict} Sum of squares ${fmt(c.sseBefore, 6)} → ${fmt(c.sseAfter, 4)} µm²; ` +
    `thickness ${signed(c.thicknessBefore, 3)} → ${signed(c.thicknessAfter, 3)} µm; ` +
    `${c.rank} singular directions used${c.amplifyingDropped ? `, ${c.amplifyingDropped} left out as amplifying` : ''}.`;
}

// ---------------------------------------------------------------------------------------------
// Measured data: CSV paste or upload, checked against the grid.

function parseMeasuredCsv(text, rows, cols) {
  const lines = text.split(/\r?\n/).map((l) => l.trim()).filter((l) => l !== '' && !l.startsWith('#'));
  if (lines.length === 0) throw new Error('The measured grid is empty.');
  const grid = lines.map((line, i) => {
    const cells = line.split(/[,;\t ]+/).filter((c) => c !== '');
    return cells.map((cell, j) => {
      const v = Number(cell);
      if (!Number.isFinite(v)) throw new Error(`Row ${i + 1}, column ${j + 1}: "${cell.slice(0, 20)}" is not a number (µm).`);
      return v;
    });
  });
  if (grid.length !== rows) {
    throw new Error(`The grid has ${rows} radial lines (root to tip), but the CSV has ${grid.length} rows.`);
  }
  grid.forEach((row, i) => {
    if (row.length !== cols) throw new Error(`Row ${i + 1} has ${row.length} values; the grid has ${cols} axial lines.`);
  });
  return grid;
}

function measuredError(message) {
  window.hobsharpTimings.errors += 1;
  $('#measured-error').textContent = message;
  $('#measured-error').hidden = false;
  setStatus(`Measured grid not used: ${message}${state.result ? ' The results below are from the last good input.' : ''}`, 'error');
}

function useMeasuredText(text) {
  if (!state.result) { measuredError('Compute a setup first, so that the grid is known.'); return; }
  try {
    const grid = parseMeasuredCsv(text, state.result.topography.r.length, state.result.topography.x.length);
    $('#measured-error').hidden = true;
    state.measured = grid;
    recompute(0);
  } catch (e) {
    measuredError(e.message);
  }
}

// ---------------------------------------------------------------------------------------------
// Files and links.

function download(name, text, type) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

function saveToUrl(caseObject) {
  const c = { ...caseObject };
  if (c.measured && c.measured.length * c.measured[0].length > 2500) delete c.measured;  // keeps links short
  history.replaceState(null, '', `#case=${encodeURIComponent(JSON.stringify(c))}`);
}

function caseFromUrl() {
  const m = /^#case=(.*)$/.exec(location.hash);
  if (!m) return null;
  try {
    return JSON.parse(decodeURIComponent(m[1]));
  } catch (e) {
    setStatus('The link holds no readable case; the paper example is loaded instead.', 'error');
    return null;
  }
}

function resultsCsv(r) {
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

// ---------------------------------------------------------------------------------------------
// Wiring.

// For the browser tests and for anyone curious: when the page opened, showed its first result,
// drew its plots, and how many results and refusals it has had.
window.hobsharpTimings = { opened: performance.now(), results: 0, errors: 0, draws: 0 };

$('#inputs').addEventListener('input', (e) => {
  if (e.target.matches('[data-field="hob.gash"], #gash-by')) showGashFields();
  recompute();
});
$('#inputs').addEventListener('change', () => recompute());
$('#preset-paper').addEventListener('click', () => {
  state.offsets = {};
  loadCase(structuredClone(HOBSHARP_PAPER_CASE));
});
$('#save-case').addEventListener('click', () => download('hobsharp-case.json', JSON.stringify(currentCase(), null, 2) + '\n', 'application/json'));
$('#load-case').addEventListener('change', async (e) => {
  const file = e.target.files[0];
  e.target.value = '';
  if (!file) return;
  if (file.size > 20 * MAX_CSV_BYTES) { setStatus(`${file.name} is ${(file.size / 1048576).toFixed(1)} MB: too large for a case file.`, 'error'); return; }
  let c;
  try { c = JSON.parse(await file.text()); } catch (err) {
    setStatus(`${file.name} is not a case file: ${err.message}. Nothing was changed.`, 'error');
    return;
  }
  if (!c || c.format !== 'hobsharp-case/1') {
    setStatus(`${file.name}: format must be "hobsharp-case/1". Nothing was changed.`, 'error');
    return;
  }
  loadCase(c);
});
$('#copy-link').addEventListener('click', async () => {
  try {
    await navigator.clipboard.writeText(location.href);
    setStatus('The link to this job is on the clipboard.', 'ok');
  } catch (e) {
    setStatus(`Copy this link: ${location.href}`, 'ok');
  }
});
$('#download-results').addEventListener('click', () => {
  if (state.result) download('hobsharp-results.csv', resultsCsv(state.result), 'text/csv');
});
$('#download-profile').addEventListener('click', () => {
  if (!state.result) return;
  const p = state.result.wheelProfile;
  const rows = ['# wheel axial profile: tooth-face radius r, wheel radius R, axial position Z (mm)', 'r_mm,R_mm,Z_mm'];
  p.r.forEach((r, i) => rows.push(`${r},${p.R[i]},${p.Z[i]}`));
  download('hobsharp-wheel-profile.csv', rows.join('\n') + '\n', 'text/csv');
});
for (const input of $$('input[name="view"]')) {
  input.addEventListener('change', () => {
    state.view = input.value;
    if (state.result) { renderFigures(state.result); schedulePlots(); }
  });
}
$('#use-measured').addEventListener('click', () => useMeasuredText($('#measured-csv').value));
$('#clear-measured').addEventListener('click', () => {
  state.measured = null;
  $('#measured-csv').value = '';
  $('#measured-error').hidden = true;
  recompute(0);
});
$('#measured-file').addEventListener('change', async (e) => {
  const file = e.target.files[0];
  e.target.value = '';
  if (!file) return;
  if (file.size === 0) { measuredError(`${file.name} is empty.`); return; }
  if (file.size > MAX_CSV_BYTES) {
    measuredError(`${file.name} is ${(file.size / 1048576).toFixed(1)} MB; a measured grid of at most 201 × 201 values is a few hundred kB. Is this the right file?`);
    return;
  }
  const text = await file.text();
  $('#measured-csv').value = text;
  useMeasuredText(text);
});
$('#what-if').addEventListener('change', (e) => {
  const t = e.target;
  if (t.dataset.offset) {
    const [a, k] = t.dataset.offset.split(' ');
    (state.offsets[a] = state.offsets[a] || [])[Number(k)] = t.value === '' ? 0 : Number(t.value);
  } else if (t.dataset.lock) {
    if (t.checked) state.locked.add(t.dataset.lock); else state.locked.delete(t.dataset.lock);
    if (state.measured) recompute(0);
  } else if (t.dataset.lockAxis) {
    if (t.checked) state.lockedAxes.add(t.dataset.lockAxis); else state.lockedAxes.delete(t.dataset.lockAxis);
    if (state.measured) recompute(0);
  }
});
$('#reset-error').addEventListener('click', () => { state.offsets = {}; if (state.result) renderWhatIf(state.result); });
$('#generate-error').addEventListener('click', async () => {
  if (!state.result) return;
  const base = readForm();
  const axes = {};
  for (const a of AXES) axes[a] = state.result.axes[a].map((v, k) => v + ((state.offsets[a] || [])[k] || 0));
  setStatus('Grinding the face with the machine error…', 'busy');
  try {
    const { result } = await worker.evaluate({ ...base, axes });
    state.measured = result.topography.normal;
    $('#measured-csv').value = state.measured.map((row) => row.map((v) => v.toFixed(4)).join(', ')).join('\n');
    $('#measured-error').hidden = true;
    recompute(0);
  } catch (e) {
    measuredError(`The machine error cannot be ground: ${e.message}`);
  }
});

loadCase(caseFromUrl() || structuredClone(HOBSHARP_PAPER_CASE));

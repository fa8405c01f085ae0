// The job view's friction and load-step parts (docs/web.md): the shear and stick/slip plot of
// a frictional result, and for load steps the step selector with the chosen step's tractions,
// the load path (tangential against normal force) and the table of steps.
import { fmt } from './format.js';
import { resultUnits } from './mesh_fields.js';
import {
  STATE_COLOURS, commonCoefficient, forceAxes, hasFriction, loadStepColumns, loadStepRows, stickZoneText,
} from './friction.js';

const $ = (id) => document.getElementById(id);

/** The legend of the state band: a swatch and a word per state, and how many edges have it. */
function stateLegend(contact) {
  const counts = { stick: 0, slip: 0, open: 0 };
  for (const s of contact.state ?? []) if (s in counts) counts[s]++;
  return Object.entries(counts).map(([state, n]) => {
    const item = document.createElement('span');
    item.className = 'state-key';
    item.dataset.state = state;
    const swatch = Object.assign(document.createElement('span'), { className: 'swatch' });
    swatch.style.background = STATE_COLOURS[state];
    item.append(swatch, `${state} (${n})`);
    return item;
  });
}

/** Draws `contact`'s friction plot into `box` with its legend; returns the chart. */
function drawFrictionInto(box, legend, contact, view, plots) {
  box.innerHTML = '';
  legend.replaceChildren(...stateLegend(contact));
  return plots.frictionPlot(box, contact, {
    abscissa: $('pressure-abscissa').value,
    coefficient: commonCoefficient(view.result.friction),
    units: resultUnits(view.result),
  });
}

// A frictional result: shear and pressure over the stick / slip / open band.
export function drawFriction(view, plots) {
  const contact = view.result.contact;
  const shown = hasFriction(contact);
  $('friction-figure').hidden = !shown;
  if (!shown) return;
  view.charts.push(drawFrictionInto($('friction-plot'), $('friction-legend'), contact, view, plots));
  const coefficient = commonCoefficient(view.result.friction);
  $('friction-note').textContent = `Shear traction σ_nt (t = (−n_y, n_x), counter-clockwise around the body) and ` +
    `pressure p per contact edge; the band under the curves colours each edge by its state.` +
    (coefficient !== null ? ` Dashed: the slip bounds ±${fmt(coefficient)} p; slipping edges lie on one.` : '') +
    ` Stick zone: ${stickZoneText(contact.stick_zone)}.`;
}

/** Fills the step selector (keeping the chosen step) and returns the chosen row's index. */
function chooseStep(view, rows) {
  const select = $('load-step-select');
  const wanted = view.loadStep ?? rows.length - 1;  // the last step first: the result's own numbers
  select.replaceChildren(...rows.map((r, k) => new Option(`${r.step}: ${r.changes}`, String(k))));
  const chosen = Math.min(Math.max(0, wanted), rows.length - 1);
  select.value = String(chosen);
  return chosen;
}

/** Fills the table: one row per step, the chosen one marked. */
function renderLoadStepTable(table, rows, columns, chosen) {
  const head = table.tHead.rows[0] ?? table.tHead.insertRow();
  // The changes are text: left-aligned, heading and cells alike (the numbers align right).
  const align = (title) => (title === 'changes' ? 'changes' : '');
  head.replaceChildren(...columns.map(([title]) => Object.assign(document.createElement('th'), { scope: 'col', textContent: title, className: align(title) })));
  table.tBodies[0].replaceChildren(...rows.map((r, k) => {
    const tr = document.createElement('tr');
    if (!r.converged) tr.className = 'not-converged';
    if (k === chosen) tr.setAttribute('aria-current', 'true');
    for (const [title, text] of columns) {
      tr.append(Object.assign(document.createElement('td'), { textContent: text(r), className: align(title) }));
    }
    return tr;
  }));
}

/** The chosen step's tractions: the friction plot, or pressure and gap without friction. */
function drawStep(view, plots, row) {
  const box = $('load-step-plot');
  const legend = $('load-step-legend');
  box.innerHTML = '';
  legend.replaceChildren();
  if (!row.contact?.x?.length) {
    box.textContent = 'This step has no contact boundary.';
    return;
  }
  if (hasFriction(row.contact)) view.charts.push(drawFrictionInto(box, legend, row.contact, view, plots));
  else view.charts.push(plots.boundaryPlot(box, row.contact, { abscissa: $('pressure-abscissa').value, units: resultUnits(view.result) }));
  box.dataset.step = String(row.step);
}

// Load steps: the chosen step's tractions, the load path and the steps' table.
export function drawLoadSteps(view, plots) {
  const loadSteps = view.result.load_steps;
  $('load-steps-section').hidden = !loadSteps?.steps?.length;
  if (!loadSteps?.steps?.length) return;
  const axes = forceAxes(view.result.contact?.plane_normal);
  const rows = loadStepRows(loadSteps, axes);
  const chosen = chooseStep(view, rows);
  drawStep(view, plots, rows[chosen]);
  const forceBox = $('load-force-plot');
  forceBox.innerHTML = '';
  const coefficient = commonCoefficient(view.result.friction);
  view.charts.push(plots.stepForcePlot(forceBox, rows, { axes, coefficient }));
  renderLoadStepTable($('load-step-table'), rows, loadStepColumns(axes), chosen);
  $('load-force-note').textContent = (axes.byPlane
    ? `${axes.normalLabel} = F·ν and ${axes.tangentialLabel} = F·t along the plane obstacle (ν = (${view.result.contact.plane_normal.map((v) => fmt(v)).join(', ')}) ` +
      'from the obstacle into the body, t = (ν_y, −ν_x))'
    : 'The obstacle is not one plane: F_x against F_y') +
    `, the force of the obstacle on the body per unit thickness; numbers beside the points are the steps.` +
    (coefficient !== null ? ` Dashed red: Coulomb's limit |${axes.tangentialLabel}| = ${fmt(coefficient)} ${axes.normalLabel}, where the whole contact slides.` : '');
}

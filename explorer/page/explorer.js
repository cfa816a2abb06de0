// The corlab e(v) explorer's page logic: reads the inputs, asks corlab's C++ (the WebAssembly
// module CorlabExplorer, explorer/src/explorer_api.hpp) and shows what it answers (plot.js).
// Every number shown comes from the C++: this file holds no formula of a model, only the speed
// grid, the material spec text (units.js), the link (link.js) and the layout.
// window.corlabExplorer is what the browser tests read (python/tests/test_browser*.py).
// SPDX-License-Identifier: BSD-3-Clause
"use strict";

const FIELDS = [  // the keys of a material spec (src/materials/material_database.cpp)
  {key: "E", label: "E", units: "GPa"},
  {key: "nu", label: "nu [-]"},
  {key: "rho", label: "rho [kg/m^3]"},
  {key: "sy", label: "sigma_y", json: "sigma_y", optional: true, units: "MPa"},
  {key: "H", label: "H", units: "MPa"},
];
const CUSTOM = "custom";
// What the page shows, for the tests; the module itself stays private.
const state = {ready: false, catalog: null, request: null, result: null, dem: null, error: null,
  stale: false, csv: null, feCommand: null, updates: 0};
window.corlabExplorer = state;
let corlab = null;  // the WebAssembly module
let lastResult = null;  // the last valid answer, greyed while the inputs are invalid

const $ = (id) => document.getElementById(id);
const fmt = (x, digits = 4) => (x === null || x === undefined ? "" : Number(x).toPrecision(digits));

function el(tag, text, attrs = {}) {
  const node = document.createElement(tag);
  if (text !== undefined && text !== null) node.textContent = text;
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  return node;
}

// The material pickers: the library grouped by category plus "custom", the five fields (moduli
// with a unit each) and the chosen entry's source.
function buildMaterialInputs(body, defaultName) {
  const select = $(`${body}-name`);
  const groups = new Map();
  for (const m of state.catalog.materials) {
    const name = m.category || "other";
    if (!groups.has(name)) groups.set(name, el("optgroup", null, {label: name}));
    groups.get(name).append(el("option", m.name, {value: m.name, title: m.source}));
  }
  for (const g of groups.values()) select.append(g);
  select.append(el("option", "custom (fields below)", {value: CUSTOM}));
  select.value = defaultName;
  const box = document.querySelector(`.fields[data-body="${body}"]`);
  for (const f of FIELDS) {
    const label = el("label", `${f.label} `);
    const input = el("input", null, {id: `${body}-${f.key}`, type: "text", inputmode: "decimal",
      placeholder: f.optional ? "none (elastic)" : ""});
    input.addEventListener("change", () => {
      select.value = CUSTOM;
      fillFields(body);  // the source line says "custom values"; the typed values stay
      update();
    });
    label.append(input);
    if (f.units) {
      const unit = el("select", null, {id: `${body}-${f.key}-unit`, "aria-label": `${f.label} unit`});
      for (const u of Object.keys(UNIT_EXPONENT)) unit.append(el("option", u, {value: u}));
      unit.value = f.units;
      unit.dataset.unit = f.units;
      unit.addEventListener("change", () => {  // the same value in the new unit
        input.value = convertText(input.value, unit.dataset.unit, unit.value);
        unit.dataset.unit = unit.value;
        update();
      });
      label.append(unit);
    } else {
      label.append(el("span", "", {class: "unit"}));
    }
    box.append(label);
  }
  select.addEventListener("change", () => { fillFields(body); update(); });
  fillFields(body);
}

function fillFields(body) {
  const name = $(`${body}-name`).value;
  const m = state.catalog.materials.find((x) => x.name === name);
  $(`${body}-source`).textContent = m ? `${m.name}: ${m.source}` : "custom values";
  if (!m) return;  // custom: keep what is typed
  for (const f of FIELDS) {
    const v = m[f.json || f.key];
    const unit = f.units ? $(`${body}-${f.key}-unit`).value : "Pa";
    $(`${body}-${f.key}`).value = v === null || v === undefined ? "" : unitText(v, unit);
  }
}

// The spec `corlab predict --sphere/--substrate` takes: a database name, or key=value pairs [SI].
function materialSpec(body) {
  const name = $(`${body}-name`).value;
  if (name !== CUSTOM) return name;
  const parts = [];
  for (const f of FIELDS) {
    const text = $(`${body}-${f.key}`).value.trim();
    if (text === "" && f.optional) continue;
    parts.push(`${f.key}=${f.units ? specText(text, $(`${body}-${f.key}-unit`).value) : text}`);
  }
  return parts.join(",");
}

// The speeds: START..STOP in N points, log or lin spacing, the grid of `corlab predict --velocity
// START:STOP:N --spacing S` (src: apps/corlab/cmd_predict.cpp, parse_velocities).
function velocityGrid() {
  const start = Number($("v-min").value);
  const stop = Number($("v-max").value);
  const n = Math.round(Number($("v-count").value));
  const log = $("v-spacing").value === "log";
  if (!(start > 0) || !(stop >= start) || !(n >= 1) || n > 2000) {
    throw new Error(`invalid velocity range ${$("v-min").value}:${$("v-max").value}:` +
      `${$("v-count").value}: must be 0 < v min <= v max and 1 <= points <= 2000 [m/s]`);
  }
  const v = [];
  for (let i = 0; i < n; i++) {
    const t = n === 1 ? 0 : i / (n - 1);
    v.push(log ? start * Math.pow(stop / start, t) : start + (stop - start) * t);
  }
  if (n > 1) v[n - 1] = stop;
  return v;
}

// The radius ratio R1/R2 as typed (0: a flat); the C++ checks it.
function radiusRatio() {
  const text = $("radius-ratio").value.trim();
  return text === "" ? 0 : Number(text);
}

const logX = () => $("v-spacing").value === "log";

// Bad input: the message, the last curves greyed, and nothing to copy or download that belongs
// to other inputs (tables marked stale, DEM fragments, FE command and CSV cleared).
function showError(message) {
  state.error = message;
  $("error").textContent = message ? `error: ${message}` : "";
  state.stale = Boolean(message);
  document.body.classList.toggle("stale", state.stale);
  if (!message) return;
  state.result = null;
  state.dem = null;
  state.csv = null;
  state.feCommand = null;
  $("dem").replaceChildren();
  $("fe-command").textContent = "";
  $("fe-note").textContent = "";
  $("download-csv").disabled = true;
  if (lastResult) drawStale(lastResult, logX());
}

function update() {
  let request;
  try {
    request = {sphere: materialSpec("sphere"), substrate: materialSpec("substrate"),
      velocity: velocityGrid(), radius_ratio: radiusRatio(), nearest: 12};
  } catch (err) {
    state.updates += 1;
    showError(err.message);
    writeLink();
    return;
  }
  const result = JSON.parse(corlab.evaluate(JSON.stringify(request)));
  state.request = request;
  state.updates += 1;
  writeLink();
  if (result.error) {
    showError(result.error.message);
    return;
  }
  showError("");
  state.result = result;
  lastResult = result;
  draw(result, logX());
  tables(result);
  feSection(request, result);
  state.csv = csvText(result);
  $("download-csv").disabled = false;
  demSection(request, result);
}

// Where a model is outside its accurate range, in words (the flags are the C++'s).
function rangeText(m) {
  const n = m.accuracy.outside.filter(Boolean).length;
  if (n === 0) return m.calibration || m.accuracy.reasons.length ? "inside" : "no numeric range";
  const where = n === m.e.length ? "every speed" : `${n} of ${m.e.length} speeds`;
  return `outside at ${where}: ${m.accuracy.reasons.join("; ")}`;
}

function cell(row, text, cls) {
  const td = el("td", text);
  if (cls) td.className = cls;
  row.append(td);
}

function tables(r) {
  const pair = r.radius_ratio > 0 ? `, a free sphere R1/R2 = ${r.radius_ratio} (rho* = ` +
    `${fmt(r.effective_density)} kg/m^3)` : ", a flat";
  $("pair-summary").textContent = `E* = ${fmt(r.effective_modulus)} Pa, k2 = sigma_y/E* = ` +
    `${fmt(r.k2)}, first yield at ${fmt(r.first_yield_velocity)} m/s in the ` +
    `${r.sphere_yields_first ? "sphere" : "substrate"}; substrate${pair}.`;
  const body = document.querySelector("#models tbody");
  body.replaceChildren();
  const warnings = $("warnings");
  warnings.replaceChildren();
  for (const m of r.models) {
    const row = el("tr", null, {"data-model": m.model});
    cell(row, m.model);
    cell(row, m.status, m.status.startsWith("verified") ? "" : "outside");
    cell(row, fmt(m.v_y));
    cell(row, fmt(m.e[0], 6));
    cell(row, fmt(m.e[m.e.length - 1], 6));
    const text = rangeText(m);
    cell(row, text, text.startsWith("outside") ? "outside text" : "text");
    const info = state.catalog.models.find((x) => x.name === m.model);
    cell(row, info.validity, "text");
    row.title = `${info.title}. ${info.citation}. ${info.status_note}`;
    body.append(row);
    for (const w of m.warnings) warnings.append(el("li", w));
  }
  const nearest = document.querySelector("#nearest tbody");
  nearest.replaceChildren();
  for (const n of r.nearest) {
    const row = el("tr");
    for (const x of [n.design_index, fmt(n.distance, 3), fmt(n.velocity_pair), fmt(n.e, 5),
      fmt(n.e_error, 2), fmt(n.k2, 3), fmt(n.modulus_ratio, 3),
      n.sphere_yield_ratio === null ? "elastic" : fmt(n.sphere_yield_ratio, 3),
      fmt(n.nu_sphere, 3), fmt(n.nu_substrate, 3), fmt(n.hardening_ratio_sphere, 3),
      fmt(n.hardening_ratio_substrate, 3)]) cell(row, String(x));
    nearest.append(row);
  }
  if (!r.nearest.length) {
    const row = el("tr");
    cell(row, "no run of the dataset maps into this speed range");
    row.firstChild.setAttribute("colspan", "12");
    nearest.append(row);
  }
}

// The model `corlab predict --model auto` trusts (corlab2026p) and the FE command for the speeds
// where it is outside its accurate range (all of them when it is inside everywhere: a check).
const AUTO_MODEL = "corlab2026p";
const FE_POINTS = 8;

// A speed [m/s] to 3 significant digits, rounded by `round` (Math.floor or Math.ceil).
function roundSpeed(v, round) {
  const unit = Math.pow(10, Math.floor(Math.log10(v)) - 2);
  return Number((round(v / unit) * unit).toPrecision(3));
}

function feSection(request, r) {
  const m = r.models.find((x) => x.model === AUTO_MODEL);
  const v = r.velocity;
  const out = m ? v.filter((_, i) => m.accuracy.outside[i]) : v;
  const span = out.length ? out : v;
  const lo = roundSpeed(Math.min(...span), Math.floor);  // 3 digits, still covering the span
  const hi = roundSpeed(Math.max(...span), Math.ceil);
  const n = lo === hi ? 1 : Math.min(FE_POINTS, span.length);
  const words = ["corlab", "predict", "--model", "fe", "--sphere", request.sphere, "--substrate",
    request.substrate, "--velocity", n === 1 ? String(lo) : `${lo}:${hi}:${n}`];
  if (n > 1) words.push("--spacing", $("v-spacing").value);
  if (request.radius_ratio > 0) words.push("--radius-ratio", String(request.radius_ratio));
  state.feCommand = words.map(shellWord).join(" ");
  $("fe-command").textContent = state.feCommand;
  $("fe-note").textContent = out.length ?
    `${AUTO_MODEL} is outside its accurate range at ${out.length} of ${v.length} speeds ` +
    `(${fmt(lo, 3)} to ${fmt(hi, 3)} m/s: ${m ? m.accuracy.reasons.join("; ") : ""}). ` +
    "corlab's FE solver answers there, each e with its error bar (seconds per speed):" :
    `${AUTO_MODEL} is inside its accurate range at every speed; the FE solver checks it:`;
}

// The curves as CSV: one row per model and speed, the columns of `corlab predict --format csv`
// and whether the speed is outside the model's accurate range; numbers round-trip exactly.
function csvText(r) {
  const lines = ["model,velocity,e,k1,k2,v_y,status,outside_accurate_range"];
  for (const m of r.models) {
    r.velocity.forEach((v, i) => lines.push([m.model, v, m.e[i], r.k1[i], r.k2, m.v_y, m.status,
      m.accuracy.outside[i]].map(String).join(",")));
  }
  return `${lines.join("\n")}\n`;
}

function downloadCsv() {
  if (!state.csv) return;
  const name = `corlab_e_v_${state.request.sphere}_on_${state.request.substrate}.csv`
    .replace(/[^A-Za-z0-9_.=-]+/g, "_");
  const url = URL.createObjectURL(new Blob([state.csv], {type: "text/csv"}));
  const a = el("a", null, {href: url, download: name});
  document.body.append(a);
  a.click();
  a.remove();
  // Revoked late: a busy browser may start reading the blob seconds after the click.
  setTimeout(() => URL.revokeObjectURL(url), 60000);
}

function copyButton(pre, label = "copy") {
  const button = el("button", label, {type: "button"});
  button.addEventListener("click", () => {
    const range = document.createRange();
    range.selectNodeContents(pre);
    const sel = window.getSelection();
    sel.removeAllRanges();
    sel.addRange(range);
    document.execCommand("copy");
  });
  return button;
}

function demSection(request, r) {
  const dem = $("dem");
  dem.replaceChildren();
  const answer = JSON.parse(corlab.demExport(JSON.stringify({
    sphere: request.sphere, substrate: request.substrate, radius: Number($("radius").value),
    model: $("dem-model").value, v_min: r.velocity[0], v_max: r.velocity[r.velocity.length - 1],
    radius_ratio: request.radius_ratio})));
  state.dem = answer;
  if (answer.error) {
    dem.append(el("p", `error: ${answer.error.message}`, {class: "error"}));
    return;
  }
  const list = el("ul", null, {class: "note", id: "dem-routes"});
  for (const p of answer.pairs) {
    for (const route of p.routes) {
      list.append(el("li", `${route.code}: ${route.route}, max |e - target| ` +
        `${fmt(route.max_abs_error, 2)} over the range, time step ${fmt(route.time_step, 3)} s ` +
        `(${p.target})`, {"data-code": route.code}));
    }
  }
  dem.append(list);
  const fragments = {"corlab command": answer.command, ...answer.fragments};
  for (const [name, text] of Object.entries(fragments)) {
    const head = el("h3", name);
    const pre = el("pre", text, {id: `dem-${name.replace(/ /g, "-")}`});
    head.append(" ", copyButton(pre));
    dem.append(head, pre);
  }
}

async function start() {
  try {
    corlab = await CorlabExplorer();
    state.catalog = JSON.parse(corlab.catalog());
    if (state.catalog.error) throw new Error(state.catalog.error.message);
    const loaded = JSON.parse(corlab.loadDataset($("corlab-dataset").textContent));
    if (loaded.error) throw new Error(loaded.error.message);
    $("version").textContent = state.catalog.version;
    $("dataset-size").textContent = String(loaded.runs);
    $("pi-text").textContent =
      `95 % of its training runs lie within +-${(100 * state.catalog.prediction_interval_95)
        .toFixed(1)} % of e`;
    buildMaterialInputs("sphere", "alumina_ma2023");
    buildMaterialInputs("substrate", "aluminium_ma2023");
    const demModel = $("dem-model");
    for (const m of state.catalog.models) demModel.append(el("option", m.name, {value: m.name}));
    demModel.value = "corlab2026";
    readLink();
    fillFields("sphere");
    fillFields("substrate");
    for (const id of ["v-min", "v-max", "v-count", "v-spacing", "radius", "radius-ratio",
      "dem-model"]) {
      $(id).addEventListener("change", update);
    }
    $("download-csv").addEventListener("click", downloadCsv);
    $("fe-copy").replaceWith(copyButton($("fe-command")));
    $("copy-link").addEventListener("click", () => {
      $("link").textContent = location.href;
      navigator.clipboard?.writeText(location.href).catch(() => {});
    });
    update();
    state.ready = true;
  } catch (err) {
    showError(`the explorer did not start: ${err.message}`);
    console.error(err);
  }
}

start();

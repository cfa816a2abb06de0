// The corlab e(v) explorer's page logic: reads the inputs, asks corlab's C++ (the WebAssembly
// module CorlabExplorer, explorer/src/explorer_api.hpp) and draws what it answers with plotly.js.
// Every number shown comes from the C++: this file holds no formula of a model, only the speed
// grid, the material spec text and the layout. window.corlabExplorer is what the browser tests
// read (python/tests/test_browser.py).
// SPDX-License-Identifier: BSD-3-Clause
"use strict";

const FIELDS = [  // the keys of a material spec (src/materials/material_database.cpp)
  {key: "E", label: "E [Pa]"},
  {key: "nu", label: "nu [-]"},
  {key: "rho", label: "rho [kg/m^3]"},
  {key: "sy", label: "sigma_y [Pa]", json: "sigma_y", optional: true},
  {key: "H", label: "H [Pa]"},
];
const CUSTOM = "custom";
// What the page shows, for the tests; the module itself stays private.
const state = {ready: false, catalog: null, request: null, result: null, dem: null, error: null,
  updates: 0};
window.corlabExplorer = state;
let corlab = null;  // the WebAssembly module

const $ = (id) => document.getElementById(id);
const fmt = (x, digits = 4) => (x === null || x === undefined ? "" : Number(x).toPrecision(digits));

function el(tag, text, attrs = {}) {
  const node = document.createElement(tag);
  if (text !== undefined && text !== null) node.textContent = text;
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  return node;
}

// The material pickers: one select of the built-in materials plus "custom", and the five fields.
function buildMaterialInputs(body, defaultName) {
  const select = $(`${body}-name`);
  for (const m of state.catalog.materials) select.append(el("option", m.name, {value: m.name}));
  select.append(el("option", "custom (fields below)", {value: CUSTOM}));
  select.value = defaultName;
  const box = document.querySelector(`.fields[data-body="${body}"]`);
  for (const f of FIELDS) {
    const label = el("label", `${f.label} `);
    const input = el("input", null, {id: `${body}-${f.key}`, type: "text", inputmode: "decimal",
      placeholder: f.optional ? "none (elastic)" : ""});
    input.addEventListener("change", () => { select.value = CUSTOM; update(); });
    label.append(input);
    box.append(label);
  }
  select.addEventListener("change", () => { fillFields(body); update(); });
  fillFields(body);
}

function fillFields(body) {
  const name = $(`${body}-name`).value;
  const m = state.catalog.materials.find((x) => x.name === name);
  if (!m) return;  // custom: keep what is typed
  for (const f of FIELDS) {
    const v = m[f.json || f.key];
    $(`${body}-${f.key}`).value = v === null || v === undefined ? "" : String(v);
  }
}

// The spec `corlab predict --sphere/--substrate` takes: a database name, or key=value pairs.
function materialSpec(body) {
  const name = $(`${body}-name`).value;
  if (name !== CUSTOM) return name;
  const parts = [];
  for (const f of FIELDS) {
    const text = $(`${body}-${f.key}`).value.trim();
    if (text === "" && f.optional) continue;
    parts.push(`${f.key}=${text}`);
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

function showError(message) {
  state.error = message;
  $("error").textContent = message ? `error: ${message}` : "";
}

function update() {
  let request;
  try {
    request = {sphere: materialSpec("sphere"), substrate: materialSpec("substrate"),
      velocity: velocityGrid(), nearest: 12};
  } catch (err) {
    showError(err.message);
    return;
  }
  const result = JSON.parse(corlab.evaluate(JSON.stringify(request)));
  state.request = request;
  state.updates += 1;
  if (result.error) {
    state.result = null;
    showError(result.error.message);
    return;
  }
  showError("");
  state.result = result;
  draw(result);
  tables(result);
  demSection(request, result);
}

// Splits a model's curve into the part inside its calibration box (solid) and outside (dotted);
// neighbouring points join the two so the curve stays continuous.
function splitByBox(v, e, outside) {
  const inside = e.map((x, i) => (outside[i] ? null : x));
  const out = e.map((x, i) => (outside[i] || outside[i - 1] || outside[i + 1] ? x : null));
  return [inside, out];
}

// Distinct colours, one per model (12 registered now; a 13th model repeats a colour with
// another dash).
const COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2",
  "#17becf", "#7f7f7f", "#bcbd22", "#000000", "#aec7e8", "#98df8a", "#ffbb78"];

function draw(r) {
  const traces = [];
  const pi = r.prediction_interval;
  if (pi) {
    traces.push({x: r.velocity, y: pi.low, mode: "lines", line: {width: 0}, hoverinfo: "skip",
      showlegend: false, legendgroup: pi.model});
    traces.push({x: r.velocity, y: pi.high, mode: "lines", line: {width: 0}, fill: "tonexty",
      fillcolor: "rgba(23,190,207,0.18)", name: `${pi.model} 95 % prediction interval`,
      legendgroup: pi.model, hoverinfo: "skip"});
  }
  r.models.forEach((m, k) => {
    const colour = COLOURS[k % COLOURS.length];
    const cal = m.calibration;
    const outside = r.velocity.map((_, i) => Boolean(cal && (cal.k2_outside || cal.k1_outside[i])));
    const [inside, out] = splitByBox(r.velocity, m.e, outside);
    const dash = k < COLOURS.length ? "solid" : "dashdot";
    traces.push({x: r.velocity, y: inside, mode: "lines", name: m.model, legendgroup: m.model,
      line: {color: colour, width: 2, dash}, connectgaps: false});
    if (outside.some(Boolean)) {
      traces.push({x: r.velocity, y: out, mode: "lines", name: `${m.model} (outside its box)`,
        legendgroup: m.model, showlegend: false, line: {color: colour, width: 2, dash: "dot"},
        connectgaps: false});
    }
  });
  if (r.nearest.length) {
    traces.push({x: r.nearest.map((n) => n.velocity_pair), y: r.nearest.map((n) => n.e),
      mode: "markers", name: "FE dataset, nearest runs", marker: {color: "#000", symbol: "diamond",
        size: 8}, error_y: {type: "data", array: r.nearest.map((n) => n.e_error ?? 0),
        visible: true, color: "#000"},
      text: r.nearest.map((n) => `design ${n.design_index}, distance ${fmt(n.distance, 3)}`)});
  }
  const layout = {
    margin: {t: 30, r: 20, b: 55, l: 60}, height: 520,
    xaxis: {title: "impact speed v [m/s]", type: $("v-spacing").value === "log" ? "log" : "linear"},
    yaxis: {title: "coefficient of restitution e [-]",
      range: [0, Math.max(1.05, ...r.models.flatMap((m) => m.e.filter(Number.isFinite)))]},
    legend: {orientation: "v"},
  };
  Plotly.react("plot", traces, layout, {displaylogo: false, responsive: true});
}

function cell(row, text, cls) {
  const td = el("td", text);
  if (cls) td.className = cls;
  row.append(td);
}

// Where a model is outside its box, in words (the flags are the C++'s, validity.hpp).
function boxText(m, v) {
  const cal = m.calibration;
  if (!cal) return "no numeric box";
  const out = v.filter((_, i) => cal.k1_outside[i]);
  const parts = [];
  if (cal.k2_outside) parts.push("k2 outside: every speed");
  if (out.length === v.length) parts.push("k1 outside at every speed");
  else if (out.length) parts.push(`k1 outside at ${out.length} of ${v.length} speeds`);
  return parts.length ? parts.join("; ") : "inside";
}

function tables(r) {
  $("pair-summary").textContent = `E* = ${fmt(r.effective_modulus)} Pa, k2 = sigma_y/E* = ` +
    `${fmt(r.k2)}, first yield at ${fmt(r.first_yield_velocity)} m/s in the ` +
    `${r.sphere_yields_first ? "sphere" : "substrate"}.`;
  const body = document.querySelector("#models tbody");
  body.replaceChildren();
  const warnings = $("warnings");
  warnings.replaceChildren();
  for (const m of r.models) {
    const row = el("tr", null, {"data-model": m.model});
    cell(row, m.model);
    cell(row, m.status);
    cell(row, fmt(m.v_y));
    cell(row, fmt(m.e[0], 6));
    cell(row, fmt(m.e[m.e.length - 1], 6));
    const text = boxText(m, r.velocity);
    cell(row, text, text === "inside" || text === "no numeric box" ? "" : "outside");
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

function copyButton(pre) {
  const button = el("button", "copy", {type: "button"});
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
    model: $("dem-model").value, v_min: r.velocity[0],
    v_max: r.velocity[r.velocity.length - 1]})));
  state.dem = answer;
  if (answer.error) {
    dem.append(el("p", `error: ${answer.error.message}`, {class: "error"}));
    return;
  }
  const fits = answer.pairs.map((p) => `${p.target}: LAMMPS viscoelastic eta = ` +
    `${fmt(p.lammps_viscoelastic_eta, 6)} (max |de| ${fmt(p.viscoelastic_max_abs_error, 3)}), ` +
    `LIGGGHTS yield ratio = ${fmt(p.liggghts_yield_ratio, 6)} (max |de| ` +
    `${fmt(p.liggghts_max_abs_error, 3)})`);
  dem.append(el("p", fits.join("; "), {class: "note"}));
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
    for (const id of ["v-min", "v-max", "v-count", "v-spacing", "radius", "dem-model"]) {
      $(id).addEventListener("change", update);
    }
    update();
    state.ready = true;
  } catch (err) {
    showError(`the explorer did not start: ${err.message}`);
    console.error(err);
  }
}

start();

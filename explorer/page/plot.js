// The explorer's plot (explorer.js): e(v) of every model with plotly.js. The y-axis is fitted to
// the verified models and corlab2026's band; an unverified model is dashed and clipped by that
// axis, as are dataset runs far from the pair (faded with their distance). A model is dotted where it is outside its accurate range (the C++'s
// flags). After bad input the last curves stay, greyed, under a note (drawStale).
// SPDX-License-Identifier: BSD-3-Clause
"use strict";

// Colours by model: corlab's own models dark and thick (black and blue, far from the band's
// orange), the others distinct hues (Okabe-Ito, then tab10's remaining ones).
const MODEL_COLOURS = {corlab2026: "#000000", corlab2026p: "#0072b2"};
const OTHER_COLOURS = ["#d55e00", "#009e73", "#cc79a7", "#56b4e9", "#8c564b", "#7f7f7f",
  "#bcbd22", "#9467bd", "#e6194b", "#17becf", "#3cb44b", "#911eb4", "#f58231"];
const BAND_COLOUR = "rgba(230,159,0,0.28)";  // corlab2026's 95 % band: orange
const STALE_COLOUR = "#c8c8c8";

function modelColour(name, k) {
  return MODEL_COLOURS[name] || OTHER_COLOURS[k % OTHER_COLOURS.length];
}

const isVerified = (m) => m.status.startsWith("verified");

// A curve split into the part inside the model's accurate range and the part outside it; the
// neighbours of an outside point join the two so the curve stays continuous.
function splitByRange(e, outside) {
  const inside = e.map((x, i) => (outside[i] ? null : x));
  const out = e.map((x, i) => (outside[i] || outside[i - 1] || outside[i + 1] ? x : null));
  return [inside, out];
}

// [low, high] of the e-axis: the verified models' e and the band, padded 5 %.
function yRange(r) {
  const values = r.models.filter(isVerified).flatMap((m) => m.e);
  if (r.prediction_interval) values.push(...r.prediction_interval.low, ...r.prediction_interval.high);
  const finite = values.filter(Number.isFinite);
  if (!finite.length) return [0, 1.05];
  const lo = Math.min(...finite);
  const hi = Math.max(...finite);
  const pad = Math.max(0.05 * (hi - lo), 0.01);
  return [Math.max(0, lo - pad), hi + pad];
}

// A dataset run's marker fades with its distance from the pair: 1 - 2 distance, at least 0.15
// (a run of other materials is a guide, not the pair's result).
const runOpacity = (distance) => Math.min(1, Math.max(0.15, 1 - 2 * distance));

function traces(r) {
  const list = [];
  const pi = r.prediction_interval;
  if (pi) {
    list.push({x: r.velocity, y: pi.low, mode: "lines", line: {width: 0}, hoverinfo: "skip",
      showlegend: false, legendgroup: "band"});
    list.push({x: r.velocity, y: pi.high, mode: "lines", line: {width: 0}, fill: "tonexty",
      fillcolor: BAND_COLOUR, name: `${pi.model} 95 % prediction interval`,
      legendgroup: "band", hoverinfo: "skip"});
  }
  let other = 0;
  for (const m of r.models) {
    const own = m.model in MODEL_COLOURS;
    const colour = modelColour(m.model, own ? 0 : other++);
    const verified = isVerified(m);
    const [inside, outside] = splitByRange(m.e, m.accuracy.outside);
    const width = own ? 3 : 2;
    const label = verified ? m.model : `${m.model} (unverified)`;
    list.push({x: r.velocity, y: inside, mode: "lines", name: label, legendgroup: m.model,
      line: {color: colour, width, dash: verified ? "solid" : "dash"}, connectgaps: false,
      opacity: verified ? 1 : 0.75, meta: {model: m.model, part: "inside", verified}});
    if (m.accuracy.outside.some(Boolean)) {
      list.push({x: r.velocity, y: outside, mode: "lines", name: `${m.model} (outside its range)`,
        legendgroup: m.model, showlegend: false, connectgaps: false,
        opacity: verified ? 1 : 0.75, line: {color: colour, width, dash: "dot"},
        meta: {model: m.model, part: "outside", verified}});
    }
  }
  if (r.nearest.length) {
    list.push({x: r.nearest.map((n) => n.velocity_pair), y: r.nearest.map((n) => n.e),
      mode: "markers", name: "FE dataset, nearest runs", marker: {color: "#444", symbol: "diamond",
        size: 8, opacity: r.nearest.map((n) => runOpacity(n.distance))}, error_y: {type: "data", array: r.nearest.map((n) => n.e_error ?? 0),
        visible: true, color: "#444"},
      text: r.nearest.map((n) => `design ${n.design_index}, distance ${fmt(n.distance, 3)}`)});
  }
  return list;
}

function layout(r, logX, note) {
  const l = {
    margin: {t: 30, r: 20, b: 55, l: 60}, height: 520,
    xaxis: {title: "impact speed v [m/s]", type: logX ? "log" : "linear"},
    yaxis: {title: "coefficient of restitution e [-]", range: yRange(r)},
    legend: {orientation: "v"},
  };
  if (note) {
    l.annotations = [{text: note, xref: "paper", yref: "paper", x: 0.5, y: 1.04,
      showarrow: false, font: {color: "#b00"}}];
  }
  return l;
}

function draw(r, logX) {
  Plotly.react("plot", traces(r), layout(r, logX), {displaylogo: false, responsive: true});
}

// The last valid curves, every trace grey, under a note that they are not the inputs' answer.
function drawStale(r, logX) {
  const grey = traces(r).map((t) => {
    const g = {...t};
    if (t.line) g.line = {...t.line, color: STALE_COLOUR};
    if (t.marker) g.marker = {...t.marker, color: STALE_COLOUR};
    if (t.error_y) g.error_y = {...t.error_y, color: STALE_COLOUR};
    if (t.fillcolor) g.fillcolor = "rgba(200,200,200,0.25)";
    return g;
  });
  Plotly.react("plot", grey, layout(r, logX, "stale: the inputs are invalid (see the error above)"),
    {displaylogo: false, responsive: true});
}

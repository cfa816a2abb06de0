// The explorer's state in the page's URL (explorer.js): every input as a query string in the
// fragment (#sphere-name=...&v-max=...), rewritten after each change and read once on load, so a
// copied link opens the same pair, speeds, units and DEM model. A file:// page keeps its fragment.
// SPDX-License-Identifier: BSD-3-Clause
"use strict";

// The ids of the inputs the link holds, in the order they are restored (a material's name before
// its fields, a field's unit before its text).
function linkIds() {
  const ids = [];
  for (const body of ["sphere", "substrate"]) {
    ids.push(`${body}-name`);
    for (const f of FIELDS) {
      if (f.units) ids.push(`${body}-${f.key}-unit`);
      ids.push(`${body}-${f.key}`);
    }
  }
  return ids.concat(["v-min", "v-max", "v-count", "v-spacing", "radius", "radius-ratio",
    "dem-model"]);
}

// The fragment of the current inputs (a built-in material's fields are implied by its name).
function linkFragment() {
  const params = new URLSearchParams();
  for (const id of linkIds()) {
    const body = id.split("-")[0];
    const isField = FIELDS.some((f) => id === `${body}-${f.key}`);
    if (isField && document.getElementById(`${body}-name`).value !== CUSTOM) continue;
    params.set(id, document.getElementById(id).value);
  }
  return params.toString();
}

function writeLink() {
  history.replaceState(null, "", `#${linkFragment()}`);
}

// Sets the inputs named in the URL's fragment (unknown names and options ignored); true when the
// fragment named any. The caller then shows a built-in material's values in the units read.
function readLink() {
  const params = new URLSearchParams(location.hash.replace(/^#/, ""));
  let any = false;
  for (const id of linkIds()) {
    const node = document.getElementById(id);
    if (!params.has(id) || !node) continue;
    const value = params.get(id);
    if (node.tagName === "SELECT" && ![...node.options].some((o) => o.value === value)) continue;
    node.value = value;
    if (id.endsWith("-unit")) node.dataset.unit = value;  // the unit its field shows
    any = true;
  }
  return any;
}

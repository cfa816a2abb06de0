// The explorer's text helpers (explorer.js): moduli typed in Pa, MPa or GPa turned into the
// exact decimal text of a `corlab predict` material spec, and a built-in value shown in a unit.
// Only decimal exponents are shifted: "370" GPa is "370e9", never 370 * 1e9 rounded.
// SPDX-License-Identifier: BSD-3-Clause
"use strict";

const UNIT_EXPONENT = {Pa: 0, MPa: 6, GPa: 9};  // the units a modulus or stress field offers
const DECIMAL = /^([+-]?)(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$/;

// text (a decimal number) as {sign, digits, exponent}: value = sign digits * 10^exponent with
// digits an integer without leading zeros ("" for zero); null for anything else.
function parseDecimal(text) {
  const m = DECIMAL.exec(text.trim());
  if (!m || (m[2] === "" && (m[3] === undefined || m[3] === ""))) return null;
  const frac = m[3] || "";
  const digits = (m[2] + frac).replace(/^0+/, "");
  return {sign: m[1] === "-" ? "-" : "", digits, exponent: Number(m[4] || 0) - frac.length};
}

// The shortest plain text of sign digits * 10^exponent ("0" for zero; an exponent beyond the
// plain range of numbers people type stays in e-notation).
function decimalText({sign, digits, exponent}) {
  if (digits === "") return "0";
  let d = digits;
  let e = exponent;
  while (d.length > 1 && d.endsWith("0")) {
    d = d.slice(0, -1);
    e += 1;
  }
  if (e >= 0 && d.length + e <= 15) return sign + d + "0".repeat(e);
  const point = d.length + e;
  if (e < 0 && point > 0) return `${sign}${d.slice(0, point)}.${d.slice(point)}`;
  if (e < 0 && point > -6) return `${sign}0.${"0".repeat(-point)}${d}`;
  return `${sign}${d}e${e}`;
}

// A field's text in `unit` as the spec's text in Pa: "370" GPa -> "370e9", "2.75e2" MPa ->
// "2.75e8"; text that is no decimal number goes through unchanged (the C++ names it).
function specText(text, unit) {
  const k = UNIT_EXPONENT[unit] || 0;
  const trimmed = text.trim();
  const m = DECIMAL.exec(trimmed);
  if (k === 0 || !parseDecimal(trimmed)) return trimmed;
  const mantissa = trimmed.replace(/[eE][+-]?\d+$/, "");
  if (Number(mantissa) === 0) return mantissa;
  return `${mantissa}e${Number(m[4] || 0) + k}`;
}

// A value [Pa] as text in `unit`, exact: 380e6 in MPa -> "380".
function unitText(value, unit) {
  const d = parseDecimal(String(value).replace("e+", "e"));
  if (!d) return String(value);
  return decimalText({...d, exponent: d.exponent - (UNIT_EXPONENT[unit] || 0)});
}

// A field's text moved from one unit to another, exact ("0.38" GPa -> "380" MPa); text that is no
// number stays as it is.
function convertText(text, from, to) {
  const d = parseDecimal(text);
  if (!d) return text;
  return decimalText({...d, exponent: d.exponent + UNIT_EXPONENT[from] - UNIT_EXPONENT[to]});
}

// A word of a shell command line, quoted when it holds anything but safe characters.
function shellWord(text) {
  return /^[A-Za-z0-9_.,=+:\/-]+$/.test(text) ? text : `'${text.replace(/'/g, "'\\''")}'`;
}

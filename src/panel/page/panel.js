// testrig front panel: draws the state streamed on /api/stream, sends commands to
// /api/command (docs/api.md).
"use strict";

const $ = (id) => document.getElementById(id);
let state = null;
let info = null;
let marker = null; // index of the marked spectrum line
// Bound beyond loopback, the panel's URL carries a token every API request must repeat.
const TOKEN = new URLSearchParams(location.search).get("token");
const api = (path) => (TOKEN ? `${path}?token=${encodeURIComponent(TOKEN)}` : path);

async function send(command) {
  const response = await fetch(api("/api/command"), {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(command),
  });
  const reply = await response.json();
  if (!reply.ok) echoed = {};
  $("error").textContent = reply.ok
    ? `${command.cmd} at t = ${reply.at_s.toFixed(3)} s`
    : `${command.cmd}: ${reply.error}`;
  $("error").style.color = reply.ok ? "#bfe3bf" : "#ff8080";
  return reply;
}

// A box's number; an empty or non-numeric box refuses the command, never sends 0.
class Refused extends Error {}
const number = (id) => {
  const text = $(id).value.trim();
  const value = Number(text);
  if (text === "" || !Number.isFinite(value)) {
    const label = document.querySelector(`label[for="${id}"]`);
    throw new Refused(`${label ? label.textContent : id}: give a number (nothing was sent)`);
  }
  return value;
};
const on = (id, make) => $(id).addEventListener("click", () => {
  let command;
  try {
    command = make();
  } catch (e) {
    if (!(e instanceof Refused)) throw e;
    $("error").textContent = e.message;
    $("error").style.color = "#ff8080";
    return;
  }
  send(command);
});

on("set-speed", () => ({ cmd: "set_speed", rpm: number("speed") }));
on("set-load", () => ({ cmd: "set_load", nm: number("load") }));
on("set-osc", () => ({ cmd: "set_oscillating_load", nm: number("osc-nm"), hz: number("osc-hz") }));
on("osc-off", () => ({ cmd: "set_oscillating_load", nm: 0, hz: 0 }));
on("set-gain", () => ({ cmd: "set_amplifier_gain", gain: number("gain") }));
on("set-filter", () => ({ cmd: "set_filter", kind: $("filter-kind").value, cutoff_hz: number("cutoff") }));
on("set-range", () => ({ cmd: "set_adc_range", range_v: number("range") }));
on("set-analyser", () => ({
  cmd: "set_analyser", fmax_hz: number("fmax"), block: number("block"),
  window: $("window").value, averages: number("averages-set"), overlap_pct: number("overlap"),
}));
on("start-average", () => ({ cmd: "start_average" }));
on("hold-average", () => ({ cmd: "hold_average" }));
on("set-scope", () => ({
  cmd: "set_scope", volts_per_div: number("vdiv"), seconds_per_div: number("sdiv") / 1000,
  trigger_v: number("trigger"), mode: $("scope-mode").value,
}));
on("arm-scope", () => ({ cmd: "arm_scope" }));
on("record", () => ({ cmd: "record", on: !(state && state.recording) }));
on("save", () => ({ cmd: "save_displays" }));
on("quit", () => ({ cmd: "quit" }));

// ---- scope: ten by eight divisions ----
function drawScope() {
  const c = $("scope"), g = c.getContext("2d"), w = c.width, h = c.height;
  g.fillStyle = "#0d1410"; g.fillRect(0, 0, w, h);
  g.strokeStyle = "#2c4a34"; g.lineWidth = 1;
  for (let i = 0; i <= 10; i++) { g.beginPath(); g.moveTo(i * w / 10, 0); g.lineTo(i * w / 10, h); g.stroke(); }
  for (let j = 0; j <= 8; j++) { g.beginPath(); g.moveTo(0, j * h / 8); g.lineTo(w, j * h / 8); g.stroke(); }
  const t = state && state.trace;
  g.fillStyle = "#9fd9a8"; g.font = "12px monospace";
  if (!t) { g.fillText("scope: waiting for a trigger", 8, 16); return; }
  g.strokeStyle = "#7CFC8A"; g.lineWidth = 1.5; g.beginPath();
  const span = 10 * t.seconds_per_div;
  t.time_s.forEach((ts, k) => {
    const x = ts / span * w, y = h / 2 - t.divisions[k] * h / 8;
    if (k === 0) g.moveTo(x, y); else g.lineTo(x, y);
  });
  g.stroke();
  g.fillStyle = "rgba(13, 20, 16, 0.8)"; g.fillRect(4, 3, 430, 18);
  g.fillStyle = "#9fd9a8";
  g.fillText(`${t.signal}  ${t.volts_per_div} ${t.unit}/div  ${(t.seconds_per_div * 1e3).toPrecision(3)} ms/div  ` +
    `trig ${t.trigger_v} ${t.unit}  ${t.mode}`, 8, 16);
}

// ---- spectrum: dB against linear frequency, orders and aliases marked ----
const db = (p) => 10 * Math.log10(Math.max(p, 1e-30));
let plotArea = null;

function drawSpectrum() {
  const c = $("spectrum"), g = c.getContext("2d"), w = c.width, h = c.height;
  g.fillStyle = "#0d1410"; g.fillRect(0, 0, w, h);
  const s = state && state.spectrum;
  g.font = "12px monospace"; g.fillStyle = "#9fd9a8";
  if (!s || s.frequency_hz.length === 0) { g.fillText("analyser: no average yet", 8, 16); return; }
  const left = 50, right = w - 10, top = 24, bottom = h - 28;
  const fmax = s.frequency_hz[s.frequency_hz.length - 1] || 1;
  const levels = s.power_v2.map(db);
  const hi = Math.ceil(Math.max(...levels) / 10) * 10, lo = hi - 100;
  const x = (f) => left + (right - left) * f / fmax;
  const y = (d) => top + (bottom - top) * (hi - Math.max(d, lo)) / (hi - lo);
  plotArea = { left, right, fmax };
  g.strokeStyle = "#2c4a34";
  for (let d = lo; d <= hi; d += 20) {
    g.beginPath(); g.moveTo(left, y(d)); g.lineTo(right, y(d)); g.stroke();
    g.fillText(`${d}`, 8, y(d) + 4);
  }
  g.fillText(`dB re 1 ${s.unit}²`, 8, 14);
  g.fillText(`${s.signal}: ${s.averages}/${s.averages_set} averages, ${s.window}` +
    (s.complete ? " (held)" : ""), left + 80, 14);
  for (let k = 0; k <= 4; k++) g.fillText(`${(fmax * k / 4).toFixed(0)} Hz`, x(fmax * k / 4) - 14, h - 8);
  // Orders of the running speed: ½, 1, 3/2, 2 … Every order gets its dashed line; a
  // label only where it clears the label before it and the legend (top right).
  if (s.running_hz > 0) {
    g.strokeStyle = "#55608a"; g.setLineDash([3, 4]);
    const legendLeft = right - 175;
    let labelEnd = -Infinity;
    for (let k = 1; k * s.running_hz / 2 <= fmax; k++) {
      const f = k * s.running_hz / 2;
      g.beginPath(); g.moveTo(x(f), top); g.lineTo(x(f), bottom); g.stroke();
      const label = k % 2 ? `${k}/2` : `${k / 2}`;
      const at = x(f) + 2, end = at + g.measureText(label).width;
      if (at > labelEnd + 6 && end < legendLeft) { g.fillText(label, at, top + 10); labelEnd = end; }
    }
    g.setLineDash([]);
  }
  s.frequency_hz.forEach((f, i) => {
    g.strokeStyle = s.alias_of_hz[i] != null ? "#ff4040" : "#7CFC8A";
    g.beginPath(); g.moveTo(x(f), bottom); g.lineTo(x(f), y(levels[i])); g.stroke();
  });
  g.fillStyle = "#7CFC8A"; g.fillRect(right - 170, top + 4, 10, 3);
  g.fillStyle = "#e8e8e8"; g.fillText("line", right - 155, top + 9);
  g.fillStyle = "#ff4040"; g.fillRect(right - 110, top + 4, 10, 3);
  g.fillStyle = "#e8e8e8"; g.fillText("alias (truth)", right - 95, top + 9);
  if (marker != null && marker < s.frequency_hz.length) {
    g.strokeStyle = "#ffd36b"; g.beginPath();
    g.moveTo(x(s.frequency_hz[marker]), top); g.lineTo(x(s.frequency_hz[marker]), bottom); g.stroke();
  }
  readMarker();
}

function readMarker() {
  const s = state && state.spectrum;
  if (!s || marker == null || marker >= s.frequency_hz.length) return;
  const f = s.frequency_hz[marker], level = db(s.power_v2[marker]);
  const order = s.running_hz > 0 ? (f / s.running_hz).toFixed(2) : "–";
  const alias = s.alias_of_hz[marker];
  $("marker-readout").textContent = `${f.toFixed(2)} Hz  ${level.toFixed(1)} dB  order ${order}  ` +
    (alias != null ? `alias of ${alias.toFixed(1)} Hz` : "not an alias");
}

// The strongest line within two lines of order k.
function markOrder(k) {
  const s = state && state.spectrum;
  if (!s || s.running_hz <= 0 || s.frequency_hz.length < 2) return;
  const df = s.frequency_hz[1] - s.frequency_hz[0];
  const centre = Math.round(k * s.running_hz / df);
  let best = centre;
  for (let i = Math.max(0, centre - 2); i <= Math.min(s.power_v2.length - 1, centre + 2); i++)
    if (s.power_v2[i] > (s.power_v2[best] ?? -1)) best = i;
  marker = best; drawSpectrum();
}
$("marker-half").addEventListener("click", () => markOrder(0.5));
$("marker-one").addEventListener("click", () => markOrder(1));
$("marker-two").addEventListener("click", () => markOrder(2));
$("spectrum").addEventListener("click", (e) => {
  const s = state && state.spectrum;
  if (!s || !plotArea) return;
  const rect = e.target.getBoundingClientRect();
  const px = (e.clientX - rect.left) * e.target.width / rect.width;
  const f = (px - plotArea.left) / (plotArea.right - plotArea.left) * plotArea.fmax;
  const df = s.frequency_hz[1] - s.frequency_hz[0];
  marker = Math.max(0, Math.min(s.frequency_hz.length - 1, Math.round(f / df)));
  drawSpectrum();
});

let previous = null; // the state of about a second ago, for rates
let impactRate = 0;

// The controls echo what the rig applies: a box takes the applied value when it changes
// (not while the user edits the box), and after a refusal every box returns to what is
// applied, so a refused or clamped setting shows.
let echoed = {};
function echo(id, value) {
  const box = $(id);
  if (value === undefined || value === null || document.activeElement === box) return;
  const text = String(value);
  if (echoed[id] === text) return;
  echoed[id] = text;
  box.value = text;
}

function echoSettings() {
  echo("speed", state.speed_set_rpm);
  echo("load", state.load_set_nm);
  echo("osc-nm", state.oscillating_load_nm);
  if (state.oscillating_load_nm > 0) echo("osc-hz", state.oscillating_load_hz);
  echo("gain", state.chain.amplifier_gain);
  const filter = state.chain.filter;
  if (filter) {
    echo("filter-kind", filter.kind);
    if (filter.kind !== "none") echo("cutoff", filter.cutoff_hz);
  }
  const sp = state.spectrum;
  if (sp) {
    echo("fmax", sp.fmax_hz);
    echo("block", sp.block);
    echo("window", sp.window);
    echo("averages-set", sp.averages_set);
    echo("overlap", sp.overlap_pct);
    echo("range", sp.adc_range_v);
    $("range-label").textContent = `ADC ± ${sp.unit}`;
  }
  const tr = state.trace;
  if (tr) {
    echo("vdiv", tr.volts_per_div);
    echo("sdiv", tr.seconds_per_div * 1000);
    echo("trigger", tr.trigger_v);
    echo("scope-mode", tr.mode);
    $("vdiv-label").textContent = `${tr.unit}/div`;
    $("trigger-label").textContent = `trigger ${tr.unit}`;
  }
}

function show() {
  if (!state) return;
  echoSettings();
  if (!previous || state.simulated_s < previous.simulated_s) previous = state;
  const span = state.simulated_s - previous.simulated_s;
  if (span >= 1) {
    impactRate = (state.impacts - previous.impacts) / span;
    previous = state;
  }
  $("dvm").textContent = state.dvm_v.toFixed(2);
  $("dvm-rpm").textContent = `(${state.dvm_rpm.toFixed(0)} rev/min)`;
  $("meter").textContent = state.meter_v.toFixed(4);
  $("averages").textContent = `${state.averages[0]}/${state.averages[1]}`;
  $("record").classList.toggle("on", state.recording);
  $("record").textContent = state.recording ? "Stop recording" : "Record";
  $("status").textContent =
    `t ${state.simulated_s.toFixed(1)} s | set ${+state.speed_set_rpm.toPrecision(6)} rev/min ${+state.load_set_nm.toPrecision(6)} N m | ` +
    `late ${state.lateness_ms.toFixed(2)} ms | overruns ${state.overruns} | ADC overloads ${state.adc_overloads} | ` +
    `pace ${info ? info.pace : "–"} | impacts ${impactRate.toFixed(0)}/s | ${motionText(state)}`;
  drawScope();
  drawSpectrum();
}

async function connect() {
  info = await (await fetch(api("/api/info"))).json();
  $("scenario").textContent = info.scenario;
  // The rig's own limits, one source of truth: the boxes allow what the rig accepts.
  $("speed").min = 0;
  $("speed").max = info.max_speed_rpm;
  $("load").min = 0;
  // A rig file's motor without a torque limit holds any load: the info says null.
  if (info.max_load_nm !== null) $("load").max = info.max_load_nm;
  $("osc-hz").max = info.max_oscillating_load_hz;
  const ws = new WebSocket(`ws://${location.host}${api("/api/stream")}`);
  ws.onmessage = (m) => { state = JSON.parse(m.data); show(); };
  ws.onclose = () => { $("status").textContent = "disconnected: the session has ended"; };
}
connect();

// The judged motion for the status line: "settling" until the rig has settled after a
// change of set points, then the verdict on the last 10 s with the old regime beside it.
function motionText(state) {
  if (state.motion == null || state.motion === "settling") {
    return "motion settling (judged over 10 s once settled)";
  }
  return `motion ${state.motion} (last 10 s; regime ${state.regime ?? "–"})`;
}

// The explorer page: a progressive view of the scene (a quarter-resolution frame at once, or a
// smaller one where that is slow, then finer ones while the view is still), orbit and zoom with
// the mouse, the Mandelbrot map that picks c, presets, and the exports. Every request names this
// tab's client id, so the server cancels the tab's stale render as soon as a newer view is asked
// for. The timeline (timeline.js) keys, plays and copies films of the view.
import { buildControls, markInvalid, sameValue, tomlValue } from './controls.js';
import { createTimeline } from './timeline.js';

const clientId = 'tab-' + Math.random().toString(36).slice(2, 12);
const view = document.getElementById('view');
const viewport = document.getElementById('viewport');
const statusLine = document.getElementById('status');
const controls = document.getElementById('controls');
const copied = document.getElementById('copied');
const certifyBox = document.getElementById('certify');

// ?size=WxH fixes the final image size (benchmarks, tests); otherwise it fits the window.
const fixedSize = /^(\d+)x(\d+)$/.exec(new URLSearchParams(location.search).get('size') || '');
const STILL_MS = 120;  // the view counts as still after this long without a change

let table = [];
const start = {};  // name -> the starting scene's value
const state = {};  // name -> current value
let refreshControls = () => {};

// ---- Requests ---------------------------------------------------------------------------------

// The query for the current view: every key whose value differs from the starting scene.
function viewQuery(extra = {}) {
  const query = new URLSearchParams({ client: clientId });
  for (const { name } of table)
    if (!sameValue(state[name], start[name])) query.set(name, tomlValue(state[name]));
  for (const [name, value] of Object.entries(extra)) query.set(name, tomlValue(value));
  return query.toString();
}

function finalSize() {
  if (fixedSize) return [+fixedSize[1], +fixedSize[2]];
  const scale = Math.min(1, 1920 / viewport.clientWidth, 1080 / viewport.clientHeight);
  return [Math.max(16, Math.round(viewport.clientWidth * scale)),
          Math.max(16, Math.round(viewport.clientHeight * scale))];
}

// The preview (the first level, and the frames shown while dragging) is the final size divided
// by previewDivisor: 4, a quarter, where that frame renders within the budget; more where it
// does not (coquaternions, biquaternions, bicomplex functions: seconds at a quarter of full HD),
// so that a drag still shows 5 frames a second. Each preview's server time moves the divisor by
// the square root of its ratio to the budget (the time goes about as the pixels), with some
// slack either way so that it settles; at most 64 (30x17 of full HD). ?previewBudget=MS sets
// the budget (the browser test makes every preview too slow with 0.01).
const PREVIEW_BUDGET_MS = +(new URLSearchParams(location.search).get('previewBudget') || 120);
let previewDivisor = 4;
function adaptPreview(renderMs) {
  if (!(renderMs > 0)) return;
  const ratio = renderMs / PREVIEW_BUDGET_MS;
  if (ratio > 1.3 || (ratio < 0.5 && previewDivisor > 4))
    previewDivisor = Math.min(64, Math.max(4, previewDivisor * Math.sqrt(ratio)));
}

// Refinement levels: the preview with one sample, then halving the divisor from the largest
// power of two below it (a half and full after a quarter), then the samples the scene asks for.
function levels() {
  const [width, height] = finalSize();
  const size = (d) => ({ 'render.width': Math.max(1, Math.round(width / d)),
                         'render.height': Math.max(1, Math.round(height / d)) });
  const list = [{ ...size(previewDivisor), 'render.samples': 1 }];
  for (let d = 2 ** Math.floor(Math.log2(previewDivisor / 1.5)); d >= 1; d /= 2)
    list.push({ ...size(d), 'render.samples': 1 });
  if (state['render.samples'] > 1) list.push({ ...size(1), 'render.samples': state['render.samples'] });
  return list;
}

async function errorText(response) {
  try {
    const body = await response.json();
    markInvalid(controls, body.key);
    return `${body.key ? body.key + ': ' : ''}${body.error}`;
  } catch {
    return `HTTP ${response.status}`;
  }
}

// ---- Progressive view -------------------------------------------------------------------------

let generation = 0;       // bumped by every change of the view
let lastChange = 0;
let inflight = null;      // { controller, level } of the running request
let framePending = false;
const timing = { started: performance.now(), firstFrameMs: null, firstRenderMs: null, frames: [],
                 frameInfo: [] };
window.exploreTiming = timing;

// While the mouse moves, a quarter-resolution request in flight is let finish (it takes a few
// tens of milliseconds) and its completion asks for the newest view, so frames keep coming;
// a refinement in flight is stale at once and is aborted (the server cancels it when the next
// request of this tab arrives).
function viewChanged() {
  timeline.stop();  // the live view takes the image back
  ++generation;
  lastChange = performance.now();
  document.body.dataset.state = 'rendering';
  if (inflight && inflight.level === 0) return;
  // At most one new request per animation frame, however fast the mouse moves.
  if (framePending) return;
  framePending = true;
  requestAnimationFrame(() => {
    framePending = false;
    if (!(inflight && inflight.level === 0)) requestLevel(0);
  });
}

async function requestLevel(level) {
  const myGeneration = generation;
  const list = levels();
  if (inflight) inflight.controller.abort();
  const request = (inflight = { controller: new AbortController(), level });
  // The certificate is asked for with the final frame alone: it costs more than the render.
  const certify = certifyBox.checked && level + 1 === list.length;
  let response, blob;
  try {
    response = await fetch('/api/render?' + viewQuery(certify ? { ...list[level], certify }
                                                              : list[level]),
                           { signal: request.controller.signal });
    if (response.status === 200) blob = await response.blob();
  } catch {
    return;  // aborted by a newer view
  }
  if (inflight === request) inflight = null;
  const stale = myGeneration !== generation;
  if (stale && level > 0) return;
  if (response.status === 204 || response.status === 429) {
    // Cancelled on the server by a newer request, or too many: ask again for the newest view.
    setTimeout(() => !inflight && requestLevel(0), response.status === 429 ? 200 : 0);
    return;
  }
  if (!response.ok) {
    statusLine.textContent = await errorText(response);
    statusLine.className = 'error';
    document.body.dataset.state = 'error';
    return;
  }
  markInvalid(controls, null);
  if (level === 0) adaptPreview(+response.headers.get('X-Render-Ms'));
  await show(blob, list[level], response.headers.get('X-Render-Ms'), certify && response.headers);
  if (stale) {  // a frame of a view just left: shown, now the newest view
    if (!inflight) requestLevel(0);
    return;
  }
  view.dataset.level = level;
  if (!table.length) return;  // main() refines once it knows the scene's samples
  const last = level + 1 === list.length;
  document.body.dataset.state = last ? 'final' : 'refining';
  if (last) return;
  const wait = Math.max(0, lastChange + STILL_MS - performance.now());
  setTimeout(() => myGeneration === generation && requestLevel(level + 1), wait);
}

// The certificate's part of the status line, from the answer's headers: the undecided
// fraction, or why the scene cannot be certified (an error, though the picture is shown).
function certifyStatus(headers) {
  const refusal = headers.get('X-Certify-Error');
  if (refusal) {
    document.body.dataset.certify = 'refused';
    return { text: `not certified: ${headers.get('X-Certify-Key')}: ${refusal}`, error: true };
  }
  const undecided = +headers.get('X-Certify-Undecided');
  document.body.dataset.certify = String(undecided);
  return { text: `certified in ${Math.round(+headers.get('X-Certify-Ms'))} ms, ` +
                 `${(100 * undecided).toFixed(2)}% undecided (magenta)`, error: false };
}

async function show(blob, level, renderMs, certifyHeaders) {
  const url = URL.createObjectURL(blob);
  const previous = view.src;
  view.src = url;
  await view.decode().catch(() => {});
  if (previous.startsWith('blob:')) URL.revokeObjectURL(previous);
  const now = performance.now();
  if (timing.firstFrameMs === null) {
    timing.firstFrameMs = now - timing.started;  // from this script's start
    timing.firstFrameSinceNavigationMs = now;   // performance.now() counts from navigation
    timing.firstRenderMs = +renderMs;            // the server's render time of that frame
    loadMap();  // after the first frame, so that the two do not share the cores
  }
  timing.frames.push(now);
  timing.frameInfo.push({ size: `${level['render.width']}x${level['render.height']}`,
                          renderMs: +renderMs });
  view.dataset.frames = timing.frames.length;
  statusLine.className = '';
  statusLine.textContent = `${level['render.width']}x${level['render.height']}, ` +
    `${level['render.samples']} spp, ${Math.round(+renderMs)} ms`;
  if (!certifyHeaders) {
    delete document.body.dataset.certify;
    return;
  }
  const { text, error } = certifyStatus(certifyHeaders);
  statusLine.textContent += '; ' + text;
  if (error) statusLine.className = 'error';
}

// ---- Orbit and zoom ---------------------------------------------------------------------------

function orbit(dYaw, dPitch, zoom) {
  const at = state['camera.look_at'];
  const offset = state['camera.position'].map((p, i) => p - at[i]);
  let radius = Math.hypot(...offset);
  let yaw = Math.atan2(offset[0], offset[2]);
  let pitch = Math.asin(offset[1] / radius);
  yaw += dYaw;
  pitch = Math.max(-1.45, Math.min(1.45, pitch + dPitch));  // never along camera.up
  radius = Math.max(0.3, Math.min(1000, radius * zoom));
  const round = (v) => +v.toFixed(6);
  state['camera.position'] = [at[0] + radius * Math.cos(pitch) * Math.sin(yaw),
                              at[1] + radius * Math.sin(pitch),
                              at[2] + radius * Math.cos(pitch) * Math.cos(yaw)].map(round);
  refreshControls();
  viewChanged();
}

let drag = null;
viewport.addEventListener('pointerdown', (e) => {
  drag = { x: e.clientX, y: e.clientY };
  viewport.setPointerCapture(e.pointerId);
  viewport.classList.add('dragging');
});
viewport.addEventListener('pointermove', (e) => {
  if (!drag) return;
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  drag = { x: e.clientX, y: e.clientY };
  orbit(-dx * 0.008, dy * 0.008, 1);
});
const endDrag = () => { drag = null; viewport.classList.remove('dragging'); };
viewport.addEventListener('pointerup', endDrag);
viewport.addEventListener('pointercancel', endDrag);
viewport.addEventListener('wheel', (e) => {
  e.preventDefault();
  orbit(0, 0, Math.exp(e.deltaY * 0.001));
}, { passive: false });
window.addEventListener('resize', () => fixedSize || viewChanged());
// Ticking or clearing the box asks for the final frame again, with or without the tint.
certifyBox.addEventListener('change', () => {
  delete document.body.dataset.certify;
  document.body.dataset.state = 'rendering';
  ++generation;
  requestLevel(levels().length - 1);
});

// ---- Mandelbrot map ---------------------------------------------------------------------------

const map = document.getElementById('map');
const MAP_VIEW = { center: [-0.6, 0], width: 3.2 };
let mapImage = null, mapFormula = null;

function mapPoint(x, y) {  // canvas pixels -> c = re + im i, as plane_view.h maps them
  const scale = MAP_VIEW.width / map.width;
  return [MAP_VIEW.center[0] + (x - map.width / 2) * scale,
          MAP_VIEW.center[1] + (map.height / 2 - y) * scale];
}

async function loadMap() {
  if (!table.length) return;  // the formula is not known yet: main() loads the map
  mapFormula = state['fractal.formula'];
  const query = new URLSearchParams({ client: clientId });
  const settings = { 'fractal.formula': mapFormula, 'render.width': map.width,
    'render.height': map.height, 'render.samples': 2, 'plane.center': MAP_VIEW.center,
    'plane.width': MAP_VIEW.width, 'plane.max_iterations': 200 };
  for (const [name, value] of Object.entries(settings)) query.set(name, tomlValue(value));
  const response = await fetch('/api/mandelbrot?' + query);
  if (response.status !== 200) return;
  mapImage = await createImageBitmap(await response.blob());
  drawMap();
  document.body.dataset.map = 'ready';
}

function drawMap() {
  const context = map.getContext('2d');
  if (mapImage) context.drawImage(mapImage, 0, 0);
  const c = state['fractal.c'];
  const scale = MAP_VIEW.width / map.width;
  const x = map.width / 2 + (c[0] - MAP_VIEW.center[0]) / scale;
  const y = map.height / 2 - (c[1] - MAP_VIEW.center[1]) / scale;
  context.strokeStyle = '#fff';
  context.beginPath();
  context.arc(x, y, 4, 0, 2 * Math.PI);
  context.stroke();
  const text = c.map((v) => +v.toFixed(6));
  document.getElementById('c-value').textContent =
    `c = ${text[0]} + ${text[1]}i + ${text[2]}j + ${text[3]}k` +
    (text.length > 4 ? ` + (${text.slice(4).join(', ')})` : '');
  document.body.dataset.c = JSON.stringify(c);
}

map.addEventListener('click', (e) => {
  const rect = map.getBoundingClientRect();
  const [re, im] = mapPoint((e.clientX - rect.left) * map.width / rect.width,
                            (e.clientY - rect.top) * map.height / rect.height);
  // The other components (2 or 6, as the algebra has 4 or 8) go to 0.
  state['fractal.c'] = [+re.toFixed(6), +im.toFixed(6)].concat(
    new Array(state['fractal.c'].length - 2).fill(0));
  changed('fractal.c');
});

// ---- Presets and exports ----------------------------------------------------------------------

// The presets come from the server (GET /api/presets, the library's list that --preset reads);
// Start goes back to the starting scene's values of every key a preset sets.
function buildPresets(presets) {
  const container = document.getElementById('presets');
  const keys = new Set(presets.flatMap((preset) => Object.keys(preset.values)));
  const startValues = Object.fromEntries([...keys].map((name) => [name, start[name]]));
  const buttons = [{ name: 'Start', description: 'The scene the explorer started with',
                     values: startValues }, ...presets];
  for (const { name, description, values } of buttons) {
    const button = Object.assign(document.createElement('button'),
      { type: 'button', textContent: name, title: description });
    button.dataset.preset = name;
    button.addEventListener('click', () => {
      Object.assign(state, structuredClone(values));
      changed('fractal.formula');
    });
    container.append(button);
  }
}

// The exact final view: the size and samples the page refines to.
function exactQuery() {
  return viewQuery(levels().at(-1));
}

async function copyText(route, attribute) {
  // The scene file carries the film; a still's command does not need it.
  const query = route === 'scene' ? timeline.query(levels().at(-1)) : exactQuery();
  const response = await fetch(`/api/${route}?` + query);
  const text = response.ok ? (await response.text()).trim() : await errorText(response);
  copied.value = text;
  document.body.dataset[attribute] = text;
  try { await navigator.clipboard.writeText(text); } catch { /* no clipboard: the box has it */ }
}

function downloadFrom(url) {
  const link = Object.assign(document.createElement('a'), { href: url, download: '' });
  document.body.append(link);
  link.click();
  link.remove();
}

document.getElementById('copy-scene').addEventListener('click', () => copyText('scene', 'scene'));
document.getElementById('copy-cli').addEventListener('click', () => copyText('command', 'cli'));
// The full-size picture, tinted where undecided when the Certify box is ticked.
document.getElementById('download').addEventListener('click', () => downloadFrom('/api/download?' +
  viewQuery({ 'render.width': start['render.width'], 'render.height': start['render.height'],
              'render.samples': state['render.samples'],
              ...(certifyBox.checked ? { certify: true } : {}) })));
document.getElementById('export-mesh').addEventListener('click', () => downloadFrom('/api/mesh?' +
  viewQuery({ 'mesh.resolution': Math.min(256, state['mesh.resolution']) })));

// ---- Timeline ---------------------------------------------------------------------------------

const timeline = createTimeline({
  state, start, viewQuery, timing, changed, errorText, resumeLive: () => viewChanged(),
  // Frames at the first level's size, the live view's preview (a quarter, or less where slow).
  previewSize: () => {
    const { 'render.width': width, 'render.height': height } = levels()[0];
    return { 'render.width': width, 'render.height': height };
  },
  // Playing owns the image: the live view's request is dropped and refines no further.
  pauseLive: () => {
    ++generation;
    if (inflight) inflight.controller.abort();
    inflight = null;
    document.body.dataset.state = 'film';
  },
  showFrame: async (blob, text) => {
    const url = URL.createObjectURL(blob);
    const previous = view.src;
    view.src = url;
    await view.decode().catch(() => {});
    if (previous.startsWith('blob:')) URL.revokeObjectURL(previous);
    statusLine.className = '';
    statusLine.textContent = text;
  },
});

// ---- Start ------------------------------------------------------------------------------------

function changed(name) {
  refreshControls();
  if (name === 'fractal.formula' && state['fractal.formula'] !== mapFormula) loadMap();
  else drawMap();
  viewChanged();
}

async function main() {
  // The starting view needs no table (it changes no key): its first frame is asked for at once,
  // alongside the table.
  lastChange = performance.now();
  requestLevel(0);
  const presets = fetch('/api/presets').then((response) => response.json());
  table = await (await fetch('/api/parameters')).json();
  for (const parameter of table) {
    start[parameter.name] = parameter.value;
    state[parameter.name] = structuredClone(parameter.value);
  }
  refreshControls = buildControls(controls, table, state, changed);
  buildPresets(await presets);
  drawMap();  // c, before the map's image arrives
  // A first frame that came before the table could not load the map.
  if (timing.firstFrameMs !== null && mapFormula === null) loadMap();
  if (!inflight && view.dataset.level !== undefined) requestLevel(+view.dataset.level + 1);
  timeline.load(table);  // the starting scene's keys, if it has any
}
main();

// The timeline: the keys of a film on a strip (a time cursor; markers to select, drag in time
// and delete), each key's interpolation, fps and duration, and play / stop. A key stores the
// whole view (every numeric parameter of fractal, slice, camera and shading) at its time, and
// the film shows it exactly there; what no key changes comes from the current view. Frames
// come from the server (GET /api/frame, the library's sceneAtFrame) and are never interpolated
// here, so that the page plays what `quaternia animate` renders.
import { sameValue, tomlValue } from './controls.js';

const ANIMATED_SECTIONS = new Set([
  'fractal', 'slice', 'camera', 'shading', 'light1', 'light2', 'light3', 'light4', 'light5', 'light6',
  'light7', 'material', 'ground', 'environment',
]);
const NUMERIC_TYPES =
  new Set(['real', 'integer', 'vector2', 'vector3', 'vector4', 'vector6', 'components']);
const MAX_KEYS = 64;  // ExploreLimits::maxAnimationKeys

// The parameters a key stores: numbers of the view (not the image size, which is the page's).
export function animatedNames(table) {
  return table.filter((p) => ANIMATED_SECTIONS.has(p.section) && NUMERIC_TYPES.has(p.type))
    .map((p) => p.name);
}

// The keys as animation.keys' inline TOML array. Each names every parameter that some key holds
// at another value than `current` (the view the rest of the scene comes from), so that at a
// key's time the film shows that key's values exactly; the others are current's all along.
export function keysToml(keys, names, current) {
  const moving = names.filter((name) =>
    keys.some((key) => !sameValue(key.view[name], current[name])));
  if (!moving.length) return '[]';
  return '[' + keys.map((key) => {
    const parts = [`time = ${key.time}`];
    if (key.interpolation) parts.push(`interpolation = "${key.interpolation}"`);
    if (key.shortest) parts.push('shortest = true');
    for (const name of moving) parts.push(`"${name}" = ${tomlValue(key.view[name])}`);
    return '{' + parts.join(', ') + '}';
  }).join(', ') + ']';
}

// FNV-1a of the bytes: lets tests see that frames differ without keeping them.
function hashBytes(buffer) {
  let hash = 0x811c9dc5;
  for (const byte of new Uint8Array(buffer)) hash = Math.imul(hash ^ byte, 0x01000193) >>> 0;
  return hash;
}

// `page`: { state, start, viewQuery(extra), previewSize(), pauseLive(), resumeLive(),
// showFrame(blob, text), changed(name), errorText(response), timing }.
export function createTimeline(page) {
  const $ = (id) => document.getElementById(id);
  const track = $('track'), cursorLine = $('cursor'), timeBox = $('timeline-time');
  const fpsBox = $('timeline-fps'), durationBox = $('timeline-duration');
  const interpolationMenu = $('key-interpolation'), info = $('film-info');
  const { state } = page;
  let names = [];
  let keys = [];        // { time, interpolation, shortest, view }, in time order
  let selected = null;  // a key of `keys`
  let cursor = 0;       // seconds
  let playback = null;  // { controller } while playing

  const fps = () => state['animation.fps'];
  const snap = (t) => Math.max(0, Math.round(t * fps()) / fps());
  const span = () => state['animation.duration'] > 0 ? state['animation.duration']
    : Math.max(4, Math.ceil((keys.at(-1)?.time ?? 0) + 1), Math.ceil(cursor));
  const say = (text, error = false) => {
    info.textContent = text;
    info.classList.toggle('error', error);
  };

  function draw() {
    for (const marker of track.querySelectorAll('.key')) marker.remove();
    const total = span();
    keys.forEach((key, index) => {
      const marker = document.createElement('div');
      marker.className = 'key' + (key === selected ? ' selected' : '');
      marker.style.left = (100 * Math.min(1, key.time / total)) + '%';
      marker.dataset.index = index;
      marker.title = `key at ${+key.time.toFixed(3)} s`;
      track.append(marker);
    });
    cursorLine.style.left = (100 * Math.min(1, cursor / total)) + '%';
    $('track-end').textContent = `${+total.toFixed(2)} s`;
    timeBox.value = +cursor.toFixed(4);
    interpolationMenu.disabled = $('delete-key').disabled = !selected;
    interpolationMenu.value = selected ? selected.interpolation : '';
    document.body.dataset.keys = JSON.stringify(keys.map((k) => k.time));
  }

  function setCursor(seconds) {
    cursor = snap(seconds);
    draw();
  }

  // Selecting a key shows its view.
  function select(key) {
    selected = key;
    if (key) {
      cursor = key.time;
      const changed = names.filter((n) => !sameValue(key.view[n], state[n]));
      for (const name of changed) state[name] = structuredClone(key.view[name]);
      if (changed.length) page.changed(null);
    }
    draw();
  }

  function addKey() {
    const view = Object.fromEntries(names.map((n) => [n, structuredClone(state[n])]));
    const existing = keys.find((k) => k.time === cursor);
    if (existing) {
      existing.view = view;  // a key at the cursor's time is replaced
      selected = existing;
    } else if (keys.length >= MAX_KEYS) {
      return say(`at most ${MAX_KEYS} keys`, true);
    } else {
      selected = { time: cursor, interpolation: '', shortest: false, view };
      keys.push(selected);
      keys.sort((a, b) => a.time - b.time);
    }
    say(`${keys.length} key${keys.length === 1 ? '' : 's'}`);
    draw();
  }

  function deleteKey() {
    if (!selected) return;
    keys = keys.filter((k) => k !== selected);
    selected = null;
    say(`${keys.length} key${keys.length === 1 ? '' : 's'}`);
    draw();
  }

  const timeAt = (clientX) => {
    const rect = track.getBoundingClientRect();
    return snap(Math.min(1, Math.max(0, (clientX - rect.left) / rect.width)) * span());
  };

  // Drag a marker to move its key; a drop on another key's time is refused (times stay
  // strictly increasing). A click on the strip moves the cursor.
  let drag = null;
  track.addEventListener('pointerdown', (e) => {
    track.focus();
    const marker = e.target.closest('.key');
    if (!marker) return setCursor(timeAt(e.clientX));
    const key = keys[+marker.dataset.index];
    if (key !== selected) select(key);
    drag = { key, marker, time: key.time };
    track.setPointerCapture(e.pointerId);
  });
  track.addEventListener('pointermove', (e) => {
    if (!drag) return;
    drag.time = timeAt(e.clientX);
    drag.marker.style.left = (100 * drag.time / span()) + '%';
  });
  track.addEventListener('pointerup', () => {
    if (!drag) return;
    const { key, time } = drag;
    drag = null;
    if (keys.some((k) => k !== key && k.time === time)) {
      say(`a key is already at ${+time.toFixed(3)} s`, true);
    } else {
      key.time = cursor = time;
      keys.sort((a, b) => a.time - b.time);
    }
    draw();
  });
  track.addEventListener('keydown', (e) => {
    if (e.key === 'Delete' || e.key === 'Backspace') deleteKey();
  });

  timeBox.addEventListener('change', () => {
    if (Number.isFinite(+timeBox.value)) setCursor(+timeBox.value);
  });
  $('add-key').addEventListener('click', addKey);
  $('delete-key').addEventListener('click', deleteKey);
  interpolationMenu.addEventListener('change', () => {
    if (selected) selected.interpolation = interpolationMenu.value;
  });
  fpsBox.addEventListener('change', () => {
    if (+fpsBox.value > 0) state['animation.fps'] = +fpsBox.value;
    fpsBox.value = fps();
  });
  durationBox.addEventListener('change', () => {
    if (+durationBox.value >= 0) state['animation.duration'] = +durationBox.value;
    durationBox.value = state['animation.duration'];
    draw();
  });

  // The query of the view with its film.
  function query(extra = {}) {
    return page.viewQuery(extra) + '&' +
      new URLSearchParams({ 'animation.keys': keysToml(keys, names, state) });
  }

  async function filmError(response) {
    say(response.status === 414 ? 'the keys are too long for one request (8 KiB)'
      : await page.errorText(response), true);
    document.body.dataset.play = 'error';
  }

  // Frames in order at the preview size, each shown at its time (or as soon as it comes).
  async function play() {
    stop();
    const request = (playback = { controller: new AbortController() });
    const { signal } = request.controller;
    const playing = () => playback === request;
    const response = await fetch('/api/film?' + query());
    if (!response.ok) return filmError(response);
    const film = await response.json();
    if (!film.frames) {
      say('nothing moves: add keys with different values', true);
      document.body.dataset.play = 'error';
      return;
    }
    page.pauseLive();
    document.body.dataset.play = 'playing';
    $('stop').disabled = false;
    page.timing.playFrames = [];
    const frameQuery = query({ ...page.previewSize(), 'render.samples': 1 });
    const fetchFrame = async (n) => {
      for (;;) {
        const r = await fetch(`/api/frame?${frameQuery}&frame=${n}`, { signal });
        if (r.status !== 429) return r;
        await new Promise((resolve) => setTimeout(resolve, 200));
      }
    };
    const begin = performance.now();
    try {
      let next = fetchFrame(1);
      for (let n = 1; n <= film.frames && playing(); ++n) {
        const frame = await next;
        if (!frame.ok) return filmError(frame);
        const buffer = await frame.arrayBuffer();
        if (n < film.frames) next = fetchFrame(n + 1);
        const due = begin + 1000 * (n - 1) / film.fps;
        await new Promise((resolve) => setTimeout(resolve, Math.max(0, due - performance.now())));
        if (!playing()) return;
        cursor = (n - 1) / film.fps;
        draw();
        page.timing.playFrames.push({ frame: n, bytes: buffer.byteLength,
                                      hash: hashBytes(buffer) });
        await page.showFrame(new Blob([buffer], { type: 'image/png' }),
          `frame ${n} of ${film.frames}, ${+cursor.toFixed(3)} s`);
      }
    } catch {
      return;  // stopped
    }
    if (playing()) {
      playback = null;
      $('stop').disabled = true;
      document.body.dataset.play = 'done';
      say(`${film.frames} frames at ${film.fps} fps`);
    }
  }

  // Stops playing; the last frame stays until the view changes.
  function stop() {
    if (!playback) return false;
    playback.controller.abort();
    playback = null;
    $('stop').disabled = true;
    document.body.dataset.play = 'stopped';
    return true;
  }

  $('play').addEventListener('click', play);
  $('stop').addEventListener('click', () => stop() && page.resumeLive());

  // The starting scene's keys (GET /api/film without keys): each key's view is the starting
  // view with the values the film has at that key's time.
  async function load(table) {
    names = animatedNames(table);
    fpsBox.value = fps();
    durationBox.value = state['animation.duration'];
    const response = await fetch('/api/film');
    if (response.ok) {
      for (const key of (await response.json()).keys) {
        const view = Object.fromEntries(names.map((n) => [n, structuredClone(page.start[n])]));
        Object.assign(view, key.values);
        keys.push({ time: key.time, interpolation: key.interpolation || '', shortest: key.shortest,
                    view });
      }
    }
    draw();
  }

  return { load, query, stop };
}

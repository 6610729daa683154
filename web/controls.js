// The controls, generated from the server's parameter table (GET /api/parameters): a slider
// and a number box per real, integer or vector component, a menu per choice, a text box per
// text; components (fractal.c, slice.origin, slice.axes) a menu of their allowed lengths and a
// slider per component of the length chosen. Ranges and help come from the table; where a table
// range is far wider than is useful to drag through (camera position: +-10000), the slider gets
// a narrower one and the number box still takes anything the table allows.

// Sections and keys the page sets itself (image size, output format; [animation] belongs to the
// timeline) or that belong to other commands (plane images, meshes, orbits and cycles).
const HIDDEN_SECTIONS = new Set(['plane', 'mesh', 'orbit', 'cycles', 'animation']);
const HIDDEN_KEYS = new Set(['render.width', 'render.height', 'render.bit_depth', 'camera.up']);

const SLIDER_RANGES = {
  'fractal.c': [-1.5, 1.5], 'fractal.max_iterations': [1, 64], 'fractal.bailout': [0, 16],
  'slice.normal': [-1, 1], 'slice.distance': [-1.5, 1.5], 'slice.left': [-1, 1],
  'slice.right': [-1, 1], 'slice.angles': [-180, 180], 'camera.position': [-10, 10],
  'camera.look_at': [-2, 2], 'camera.fov': [5, 120], 'render.samples': [1, 16],
  'render.step': [0.0005, 0.02], 'render.epsilon': [0.05, 2], 'render.max_steps': [100, 20000],
  'shading.light_direction': [-1, 1], 'shading.fill_direction': [-1, 1],
  'shading.shadow_softness': [1, 64], 'shading.specular': [0, 2], 'shading.shininess': [1, 200],
  'shading.gamma': [0.5, 4], 'shading.exposure': [0, 4],
};
const COMPONENT_NAMES = {
  'fractal.c': ['1', 'i', 'j', 'k'], 'slice.left': ['1', 'i', 'j', 'k'],
  'slice.right': ['1', 'i', 'j', 'k'], 'slice.normal': ['x', 'y', 'z', 'w'],
  'slice.angles': ['1i', '1j', '1k', 'ij', 'ik', 'jk'],
};
const VECTOR_LENGTHS = { vector2: 2, vector3: 3, vector4: 4, vector6: 6 };
// How many components fractal.c has in each algebra (fractal.algebra).
const ALGEBRA_DIMENSIONS = { biquaternion: 8, octonion: 8 };

// A value in TOML syntax, as the server reads query parameters.
export function tomlValue(value) {
  if (Array.isArray(value)) return '[' + value.map(String).join(', ') + ']';
  if (typeof value === 'string') return JSON.stringify(value);
  return String(value);
}

export function sameValue(a, b) {
  return JSON.stringify(a) === JSON.stringify(b);
}

// An id usable in CSS selectors: "fractal.c", 0 -> "ctl-fractal_c-0".
export function controlId(name, component = 0) {
  return 'ctl-' + name.replace('.', '_') + '-' + component;
}

function sliderRange(parameter) {
  const range = SLIDER_RANGES[parameter.name];
  if (range) return range;
  if (parameter.name.endsWith('_color') || parameter.name.startsWith('shading.background'))
    return [0, 1];
  return [parameter.minimum, parameter.maximum];
}

function componentNames(parameter, count) {
  if (parameter.type === 'components') {
    // e0 .. e7 of the algebra; grouped values (slice.axes) as axis:component.
    const group = parameter.groups ? count / parameter.groups : count;
    const named = COMPONENT_NAMES[parameter.name] || [];
    return Array.from({ length: count }, (_, i) => named[i] ??
      (count > group ? `${Math.floor(i / group) + 1}:` : '') + 'e' + (i % group));
  }
  if (COMPONENT_NAMES[parameter.name]) return COMPONENT_NAMES[parameter.name];
  if (parameter.name.includes('color') || parameter.name.includes('background'))
    return ['r', 'g', 'b'];
  return ['x', 'y', 'z', 'w', 'u', 'v'].slice(0, count);
}

// One slider + number pair; `onValue(number)` on every change.
function numberWidget(parameter, id, label, initial, onValue) {
  const row = document.createElement('div');
  row.className = 'component';
  const [low, high] = sliderRange(parameter);
  const integer = parameter.type === 'integer';
  const step = integer ? 1 : (high - low) / 1000;
  const slider = Object.assign(document.createElement('input'),
    { type: 'range', min: low, max: high, step, value: initial, id, title: parameter.help });
  const box = Object.assign(document.createElement('input'),
    { type: 'number', min: parameter.minimum, max: parameter.maximum, step: integer ? 1 : 'any',
      value: initial, title: parameter.help });
  box.id = id + '-number';
  const tag = document.createElement('span');
  tag.textContent = label;
  // Slider steps are (high - low) / 1000; rounding to 6 decimals keeps CLI commands short.
  slider.addEventListener('input', () => {
    const v = integer ? Math.round(+slider.value) : +(+slider.value).toFixed(6);
    box.value = v;
    onValue(v);
  });
  box.addEventListener('change', () => {
    if (box.value === '' || !Number.isFinite(+box.value)) return;
    slider.value = box.value;
    onValue(+box.value);
  });
  row.append(tag, slider, box);
  const update = (v) => { slider.value = v; box.value = v; };
  return { row, update, tag };
}

// Builds every control into `container`. `state` maps names to values and is changed in place;
// `onChange(name)` follows each change. Returns refresh(), which shows the state's values again
// (after a drag, a map click or a preset changed them).
export function buildControls(container, table, state, onChange) {
  const updaters = [];
  let details = null, section = '';
  for (const parameter of table) {
    const name = parameter.name;
    if (HIDDEN_SECTIONS.has(parameter.section) || HIDDEN_KEYS.has(name)) continue;
    if (parameter.section !== section) {
      section = parameter.section;
      details = document.createElement('details');
      details.open = section === 'fractal' || section === 'slice';
      details.innerHTML = `<summary>${section}</summary>`;
      container.append(details);
    }
    const control = document.createElement('div');
    control.className = 'control';
    control.dataset.name = name;
    const label = document.createElement('label');
    label.textContent = parameter.key.replaceAll('_', ' ');
    label.title = parameter.help;
    control.append(label);
    const count = VECTOR_LENGTHS[parameter.type];
    if (parameter.type === 'components') {
      buildComponents(control, parameter, state, onChange, updaters);
    } else if (count) {
      const names = componentNames(parameter, count);
      for (let i = 0; i < count; ++i) {
        const widget = numberWidget(parameter, controlId(name, i), names[i], state[name][i], (v) => {
          state[name] = state[name].slice();
          state[name][i] = v;
          onChange(name);
        });
        control.append(widget.row);
        updaters.push(() => widget.update(state[name][i]));
      }
    } else if (parameter.type === 'real' || parameter.type === 'integer') {
      const widget = numberWidget(parameter, controlId(name), '', state[name], (v) => {
        state[name] = v;
        onChange(name);
      });
      control.append(widget.row);
      updaters.push(() => widget.update(state[name]));
    } else if (parameter.type === 'choice') {
      const select = Object.assign(document.createElement('select'),
        { id: controlId(name), title: parameter.help });
      for (const choice of parameter.choices) select.add(new Option(choice, choice));
      select.value = state[name];
      select.addEventListener('change', () => {
        state[name] = select.value;
        // c takes as many components as the algebra has (the server checks it).
        const c = state['fractal.c'];
        if (name === 'fractal.algebra' && Array.isArray(c))
          state['fractal.c'] = resized(c, ALGEBRA_DIMENSIONS[select.value] || 4);
        onChange(name);
      });
      control.append(select);
      updaters.push(() => { select.value = state[name]; });
    } else if (parameter.type === 'boolean') {
      const box = Object.assign(document.createElement('input'),
        { type: 'checkbox', id: controlId(name), checked: state[name], title: parameter.help });
      box.addEventListener('change', () => { state[name] = box.checked; onChange(name); });
      control.append(box);
      updaters.push(() => { box.checked = state[name]; });
    } else {
      const input = Object.assign(document.createElement('input'),
        { type: 'text', id: controlId(name), value: state[name], title: parameter.help });
      input.addEventListener('change', () => { state[name] = input.value; onChange(name); });
      control.append(input);
      updaters.push(() => { input.value = state[name]; });
    }
    details.append(control);
  }
  return () => updaters.forEach((update) => update());
}

// `v` padded with zeros or cut to `length` numbers.
function resized(v, length) {
  return Array.from({ length }, (_, i) => (i < v.length ? v[i] : 0));
}

// A components parameter: a menu of the allowed lengths (where there are several) and a slider
// per component, those past the value's length hidden. An empty array (slice.origin and
// slice.axes: not given) shows no sliders. Choosing a length pads with zeros, or cuts.
function buildComponents(control, parameter, state, onChange, updaters) {
  const name = parameter.name;
  const most = Math.max(...parameter.lengths);
  let menu = null;
  if (parameter.lengths.length > 1) {
    menu = Object.assign(document.createElement('select'),
      { id: controlId(name) + '-length', title: parameter.help });
    for (const length of parameter.lengths)
      menu.add(new Option(length ? `${length} components` : 'not given', length));
    menu.value = state[name].length;
    menu.addEventListener('change', () => {
      const groups = parameter.groups, length = +menu.value;
      const group = groups ? length / groups : 0;
      // Axes given anew start as e0, e1, e2 (the default slice), not as zeros; grouped values
      // keep each group's leading components.
      const axis = (_, i) => (i % group === Math.floor(i / group) ? 1 : 0);
      const old = state[name], oldGroup = groups ? old.length / groups : 0;
      state[name] = group && !old.length ? Array.from({ length }, axis)
        : group && length ? Array.from({ length }, (_, i) =>
          (i % group < oldGroup ? old[Math.floor(i / group) * oldGroup + (i % group)] : 0))
          : resized(old, length);
      onChange(name);
    });
    control.append(menu);
  }
  const names = componentNames(parameter, most);
  const rows = [];
  for (let i = 0; i < most; ++i) {
    const widget = numberWidget(parameter, controlId(name, i), names[i], state[name][i] ?? 0,
      (v) => {
        state[name] = state[name].slice();
        state[name][i] = v;
        onChange(name);
      });
    control.append(widget.row);
    rows.push(widget);
  }
  const update = () => {
    if (menu) menu.value = state[name].length;
    // Grouped values name their components by the length given (slice.axes: 3 axes of 4 or 8).
    const shown = parameter.groups && state[name].length
      ? componentNames(parameter, state[name].length) : names;
    rows.forEach((widget, i) => {
      widget.row.hidden = i >= state[name].length;
      if (i < state[name].length) {
        widget.update(state[name][i]);
        widget.tag.textContent = shown[i];
      }
    });
  };
  update();
  updaters.push(update);
}

// Marks the control of `name` (or none) as the one the server refused.
export function markInvalid(container, name) {
  for (const control of container.querySelectorAll('.control'))
    control.classList.toggle('invalid', control.dataset.name === name);
}

// K-ICNP knowledge editor: shared state, the API client and DOM helpers.
// An ES module loaded by index.html; no build step, nothing from the network.
export const $ = (id) => document.getElementById(id);
export const TYPES = ['TYPE_INSTANCE', 'TYPE_STR', 'TYPE_INT', 'TYPE_FLOAT', 'TYPE_BOOL', 'TYPE_FRAME', 'TYPE_LIST'];
export const RELATIONS = ['SYNCHRONIZATION', 'SUCCESSION', 'RESTRICTION'];
export const state = {
  frames: [], byName: new Map(), session: { loggedIn: false }, version: 0,
  selected: null, frame: null, draft: null, dirty: false, collapsed: new Set(), details: new Set(),
  problems: [], socket: null
};

// ---- API ----

export class ApiError extends Error {
  constructor(status, message, problems) {
    super(message);
    this.status = status;
    this.problems = problems || [];
  }
}

export async function api(method, path, body) {
  const options = { method, credentials: 'same-origin', headers: { Accept: 'application/json' } };
  if (body !== undefined) {
    options.headers['Content-Type'] = 'application/json';
    options.body = JSON.stringify(body);
  }
  let response;
  try {
    response = await fetch(path, options);
  } catch (e) {
    throw new ApiError(0, 'The editor server cannot be reached: ' + e.message);
  }
  const text = await response.text();
  let data = null;
  try {
    data = text ? JSON.parse(text) : null;
  } catch (e) {
    data = { error: text };
  }
  if (!response.ok) {
    // The login ended (logged out in another tab, expired, the server restarted): the page reads its session again.
    if (response.status === 401 && path !== '/api/login') window.dispatchEvent(new Event('kicnp-session-lost'));
    throw new ApiError(response.status, (data && data.error) || response.statusText, data && data.problems);
  }
  return data;
}

export const enc = (name) => encodeURIComponent(name);

// ---- addresses ----
// A frame's address is #frame/NAME, the World panel's #world. A frame name cannot hold '/', so the two never clash,
// even for a frame named "world". An old address #NAME still opens the frame NAME (unless NAME is "world").

/** The address (location hash) of frame `name`. */
export const frameAddress = (name) => '#frame/' + enc(name);
export const WORLD_ADDRESS = '#world';

/** What an address opens: {frame: NAME}, {world: true} or {} for none. */
export function readAddress(hash) {
  const h = hash.startsWith('#') ? hash.slice(1) : hash;
  if (h === 'world') return { world: true };
  const name = decodeURIComponent(h.startsWith('frame/') ? h.slice('frame/'.length) : h);
  return name ? { frame: name } : {};
}

// ---- small DOM helpers ----

export function el(tag, props, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(props || {})) {
    if (v === undefined || v === null || v === false) continue;
    if (k === 'class') node.className = v;
    else if (k === 'text') node.textContent = v;
    else if (k.startsWith('on')) node.addEventListener(k.slice(2), v);
    else if (k === 'dataset') Object.assign(node.dataset, v);
    else if (k in node && typeof v !== 'string') node[k] = v;
    else node.setAttribute(k, v === true ? '' : v);
  }
  for (const c of children.flat()) {
    if (c !== null && c !== undefined && c !== false) node.append(c);
  }
  return node;
}

export function show(id, visible) {
  $(id).hidden = !visible;
}

export function showErrors(containerId, error) {
  const box = $(containerId);
  box.replaceChildren();
  if (!error) {
    box.hidden = true;
    return;
  }
  box.append(el('p', { text: error.message }));
  const list = (error.problems || []).filter((p) => p.message !== error.message || p.line || error.problems.length > 1);
  if (list.length) {
    box.append(el('ul', {}, list.map((p) => el('li', {
      text: (p.line ? 'line ' + p.line + ', column ' + p.column + ': ' : '') + p.message
    }))));
  }
  box.hidden = false;
}

const PANELS = ['welcome', 'import-panel', 'create-panel', 'frame-panel', 'inference-panel', 'world-panel'];

export function showMain(id) {
  for (const p of PANELS) show(p, p === id);
}

export function notice(text) {
  const n = $('frame-notice');
  n.textContent = text;
  n.hidden = !text;
}

// K-ICNP knowledge editor: the IS-A hierarchy as clickable buttons.
// An ES module loaded by index.html; no build step, nothing from the network.
import { $, api, el, state } from './base.js';
import { openFrame } from './frame.js';
import { drawLinks } from './links.js';

// ---- hierarchy ----

export async function loadFrames() {
  const rows = await api('GET', '/api/frames');
  state.frames = rows;
  state.byName = new Map(rows.map((r) => [r.name, r]));
  renderTree();
  renderNameLists();
}

function renderStats() {
  const count = (p) => String(state.frames.filter(p).length);
  const stat = (label, value) => el('div', {}, el('dt', { text: label }), el('dd', { text: value }));
  $('stats').replaceChildren(
    stat('Frames', String(state.frames.length)),
    stat('Classes', count((f) => f.kind === 'CLASS')),
    stat('Instances', count((f) => f.kind === 'INSTANCE')),
    stat('Learned', count((f) => f.learned)));
}

export function renderNameLists() {
  renderStats();
  $('class-names').replaceChildren(...state.frames.filter((f) => f.kind === 'CLASS')
    .map((f) => el('option', { value: f.name })));
  $('frame-names').replaceChildren(...state.frames.map((f) => el('option', { value: f.name })));
}

export function renderTree() {
  const focused = document.activeElement && document.activeElement.dataset
    ? document.activeElement.dataset.frame : undefined;
  const query = $('search').value.trim().toLowerCase();
  const children = new Map();
  const roots = [];
  for (const f of state.frames) {
    if (f.parent && state.byName.has(f.parent)) {
      if (!children.has(f.parent)) children.set(f.parent, []);
      children.get(f.parent).push(f);
    } else {
      roots.push(f);
    }
  }
  let visible = null;
  if (query) {
    visible = new Set();
    for (const f of state.frames) {
      if (f.name.toLowerCase().includes(query)) {
        for (let n = f; n && !visible.has(n.name); n = state.byName.get(n.parent)) visible.add(n.name);
      }
    }
  }
  const ctx = { children, visible, query };
  const tree = $('tree');
  tree.replaceChildren(list(roots, ctx));
  if (visible && visible.size === 0) tree.append(el('p', { class: 'muted small-text', text: 'No frame matches.' }));
  if (focused) {
    const again = tree.querySelector('[data-frame="' + CSS.escape(focused) + '"]');
    if (again) again.focus();
  }
  drawLinks();
}

function item(f, ctx) {
  const kids = ctx.children.get(f.name) || [];
  const query = ctx.query;
  const open = query || !state.collapsed.has(f.name);
  const twisty = el('button', {
    type: 'button', class: 'twisty' + (kids.length ? '' : ' leaf'), tabindex: '-1',
    'aria-label': (open ? 'Collapse ' : 'Expand ') + f.name, text: kids.length ? (open ? '▾' : '▸') : '',
    onclick: () => {
      if (state.collapsed.has(f.name)) state.collapsed.delete(f.name); else state.collapsed.add(f.name);
      renderTree();
    }
  });
  const label = f.name + (f.kind === 'INSTANCE' ? ' (instance' : ' (class') + (f.learned ? ', learned)' : ')');
  const button = el('button', {
    type: 'button', dataset: { frame: f.name },
    class: 'frame-button ' + f.kind.toLowerCase() + (f.name === state.selected ? ' selected' : '')
      + (query && f.name.toLowerCase().includes(query) ? ' match' : ''),
    'aria-label': label, 'aria-current': f.name === state.selected ? 'true' : null,
    'aria-expanded': kids.length ? String(!!open) : null,
    onclick: () => openFrame(f.name),
    onkeydown: (e) => {
      if ((e.key === 'ArrowRight' || e.key === 'ArrowLeft') && kids.length && !query) {
        e.preventDefault();
        if (e.key === 'ArrowLeft') state.collapsed.add(f.name); else state.collapsed.delete(f.name);
        renderTree();
      }
    }
  },
  el('i', { class: 'kind-icon ' + f.kind.toLowerCase() }),
  el('span', { text: f.name }),
  f.learned ? el('i', { class: 'learned-mark', title: 'learned', text: 'L' }) : null,
  f.hasLinks ? el('i', { class: 'link-mark', title: 'has semantic links', text: '⇄' }) : null,
  kids.length && !open ? el('span', { class: 'count', text: String(kids.length) }) : null);
  return el('li', {}, el('div', { class: 'node' }, twisty, button), kids.length && open ? list(kids, ctx) : null);
}

// A class with thousands of runtime instances shows the first ones; the search box finds the others.
const MAX_CHILDREN_SHOWN = 200;

function list(frames, ctx) {
  const shown = frames.filter((f) => !ctx.visible || ctx.visible.has(f.name));
  const ul = el('ul', {}, shown.slice(0, MAX_CHILDREN_SHOWN).map((f) => item(f, ctx)));
  if (shown.length > MAX_CHILDREN_SHOWN) {
    ul.append(el('li', { class: 'muted small-text more', text: '… ' + (shown.length - MAX_CHILDREN_SHOWN)
      + ' more; use the search box' }));
  }
  return ul;
}

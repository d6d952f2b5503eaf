// K-ICNP knowledge editor: the semantic links of the hierarchy drawn as arrows over the tree.
// An ES module loaded by index.html; no build step, nothing from the network.
//
// Every row of GET /api/frames carries the links its frame declares as arrows {relation, from, to}. They are drawn
// in one SVG laid over the tree's scrolled content, each as a bracket on the right of the frame buttons: out of
// the right edge of the "from" button, along a lane right of every label in between, into the "to" button with an
// arrowhead. A link whose end is folded away or filtered out is drawn to that frame's nearest visible ancestor
// (dashed lighter, and said so in its tooltip); a link with no visible end at all is listed under the tree. The
// same links are listed as buttons below the tree, so they can be read and followed with the keyboard.
import { $, el, state } from './base.js';
import { openFrame } from './frame.js';

const SVG = 'http://www.w3.org/2000/svg';
const KINDS = ['SUCCESSION', 'SYNCHRONIZATION', 'RESTRICTION'];
// More arrows than this would only be ink; the list below the tree still names them all.
const MAX_ARROWS = 400;

/** The CSS class of a relation: one of the three coordination relations, or "named" for a relation of your own. */
export function relationKind(relation) {
  return KINDS.includes(relation) ? relation.toLowerCase() : 'named';
}

function svg(tag, attrs, ...children) {
  const node = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs || {})) if (v !== undefined && v !== null) node.setAttribute(k, String(v));
  for (const c of children) if (c) node.append(c);
  return node;
}

const key = (l) => l.relation + '\u0000' + l.from + '\u0000' + l.to;

/** Every declared link once, as {relation, from, to}, whichever end declared it (or both). */
export function allLinks() {
  const seen = new Map();
  for (const f of state.frames) {
    for (const l of f.links || []) {
      if (!seen.has(key(l))) seen.set(key(l), l);
    }
  }
  return [...seen.values()];
}

function markers() {
  return svg('defs', {}, ...[...KINDS.map((k) => k.toLowerCase()), 'named'].map((k) => svg('marker', {
    id: 'arrowhead-' + k, class: 'arrowhead ' + k, viewBox: '0 0 8 8', refX: 7, refY: 4,
    markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse', markerUnits: 'userSpaceOnUse'
  }, svg('path', { d: 'M0,0.5 L8,4 L0,7.5 z' }))));
}

// The button drawn for a frame: its own, or its nearest ancestor's when it is folded away or filtered out.
function drawnButton(name, buttons) {
  const seen = new Set();
  for (let n = name; n && !seen.has(n); n = state.byName.get(n) && state.byName.get(n).parent) {
    seen.add(n);
    if (buttons.has(n)) return { name: n, button: buttons.get(n) };
  }
  return null;
}

/** A short sample of the line an arrow of this kind is drawn with, for the legend and the list. */
export function swatch(kind) {
  return svg('svg', { class: 'link-swatch', width: 22, height: 8, viewBox: '0 0 22 8', 'aria-hidden': 'true' },
    svg('line', { class: 'link-arrow ' + kind, x1: 1, y1: 4, x2: 21, y2: 4 }));
}

function label(l) {
  return l.relation.toLowerCase() + ': ' + l.from + ' → ' + l.to;
}

/** Redraws the arrows and the list of links; called after every render of the tree and on resize. */
export function drawLinks() {
  const tree = $('tree');
  const old = tree.querySelector('svg.link-layer');
  if (old) old.remove();
  const links = allLinks();
  const drawnKeys = new Set();
  if (links.length && $('show-links').checked) drawArrows(tree, links, drawnKeys);
  renderList(links, drawnKeys);
}

function drawArrows(tree, links, drawnKeys) {
  const buttons = new Map();
  for (const b of tree.querySelectorAll('.frame-button[data-frame]')) buttons.set(b.dataset.frame, b);
  const box = tree.getBoundingClientRect();
  const ox = tree.scrollLeft - box.left;
  const oy = tree.scrollTop - box.top;
  const rects = new Map();
  const rect = (b) => {
    if (!rects.has(b)) {
      const r = b.getBoundingClientRect();
      rects.set(b, { left: r.left + ox, right: r.right + ox, top: r.top + oy, bottom: r.bottom + oy, mid: (r.top + r.bottom) / 2 + oy });
    }
    return rects.get(b);
  };
  const rows = [...buttons.values()].map(rect).sort((a, b) => a.top - b.top);
  const width = tree.clientWidth;
  const layer = svg('svg', {
    class: 'link-layer', width, height: tree.scrollHeight, 'aria-hidden': 'true', 'data-count': 0
  }, markers());
  const lanes = [];
  let drawn = 0;
  for (const l of links) {
    if (drawn >= MAX_ARROWS) break;
    const from = drawnButton(l.from, buttons);
    const to = drawnButton(l.to, buttons);
    if (!from || !to || from.name === to.name) continue;
    const a = rect(from.button);
    const b = rect(to.button);
    const y1 = a.mid - 3;
    const y2 = b.mid + 3;
    const top = Math.min(y1, y2);
    const bottom = Math.max(y1, y2);
    // The lane runs right of every label between the two ends, and right of the lanes it would cross.
    let lane = Math.max(a.right, b.right);
    for (const r of rows) if (r.bottom >= top && r.top <= bottom) lane = Math.max(lane, r.right);
    lane += 10;
    for (const other of lanes) if (other.top <= bottom && other.bottom >= top && other.x >= lane - 4) lane = other.x + 6;
    lane = Math.min(lane, width - 3);
    lanes.push({ top, bottom, x: lane });
    const x1 = a.right + 2;
    const x2 = b.right + 3;
    const r = Math.max(0, Math.min(6, (bottom - top) / 2, lane - Math.max(x1, x2)));
    const down = y2 > y1 ? 1 : -1;
    const d = ['M', x1, y1, 'H', lane - r, 'Q', lane, y1, lane, y1 + down * r,
      'V', y2 - down * r, 'Q', lane, y2, lane - r, y2, 'H', x2].join(' ');
    const via = from.name !== l.from || to.name !== l.to;
    const kind = relationKind(l.relation);
    const path = svg('path', {
      d, class: 'link-arrow ' + kind + (via ? ' via' : ''), 'marker-end': 'url(#arrowhead-' + kind + ')',
      'data-relation': l.relation, 'data-from': l.from, 'data-to': l.to,
      'data-drawn-from': from.name, 'data-drawn-to': to.name
    }, svg('title', {}, document.createTextNode(label(l) + (via ? ' (drawn to ' + from.name + ' → ' + to.name
      + ', the nearest frames shown)' : ''))));
    if (state.selected && (l.from === state.selected || l.to === state.selected)) path.classList.add('hot');
    layer.append(path);
    drawnKeys.add(key(l));
    drawn++;
  }
  layer.setAttribute('data-count', drawn);
  tree.prepend(layer);
}

// Below the tree: every link as a button that opens its "from" frame; focus or hover lights its arrow up.
function renderList(links, drawnKeys) {
  const box = $('link-list');
  box.hidden = links.length === 0;
  $('link-count').textContent = String(links.length);
  const items = links.map((l) => {
    const kind = relationKind(l.relation);
    const light = (on) => {
      for (const p of $('tree').querySelectorAll('path.link-arrow')) {
        if (p.dataset.from === l.from && p.dataset.to === l.to && p.dataset.relation === l.relation) p.classList.toggle('lit', on);
      }
    };
    const shown = drawnKeys.has(key(l));
    return el('li', { class: shown ? null : 'not-drawn' },
      el('button', {
        type: 'button', class: 'link-item', dataset: { from: l.from, to: l.to, relation: l.relation },
        title: label(l) + ' (Enter opens ' + l.from + ')', 'aria-label': label(l), onclick: () => openFrame(l.from),
        onfocus: () => light(true), onblur: () => light(false),
        onmouseenter: () => light(true), onmouseleave: () => light(false)
      },
      swatch(kind),
      el('span', { text: l.from }), el('span', { class: 'arrow-sign', text: '→' }), el('span', { text: l.to }),
      shown ? null : el('span', { class: 'muted small-text', text: '(not shown)' })));
  });
  const focused = document.activeElement && document.activeElement.classList.contains('link-item')
    ? document.activeElement.dataset : null;
  $('link-items').replaceChildren(...items);
  if (focused) {
    const again = [...$('link-items').querySelectorAll('button.link-item')].find((b) => b.dataset.from === focused.from
      && b.dataset.to === focused.to && b.dataset.relation === focused.relation);
    if (again) again.focus();
  }
}

let pending = false;

/** Redraws once on the next animation frame, however many times it is asked for before that. */
export function scheduleDrawLinks() {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    drawLinks();
  });
}

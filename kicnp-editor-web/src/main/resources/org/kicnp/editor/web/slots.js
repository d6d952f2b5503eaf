// K-ICNP knowledge editor: the slot editing table, one row per slot, every Table 2 facet a column.
// An ES module loaded by index.html; no build step, nothing from the network.
import { $, TYPES, api, el, state } from './base.js';
import { markDirty, renderFrame } from './frame.js';
import { editor as codeEditor } from './highlight.js';

// The paper's procedural slots, the only string slots the platform runs as scripts (kicnp-core's FrameScripts), so the
// only ones edited as code and syntax-checked: any other string slot, even one named on… (onTable), holds data.
const PROCEDURAL = ['onInstantiate', 'onDestroy'];
export const isScript = (s) => s.type === 'TYPE_STR' && PROCEDURAL.includes(s.name);
// A list item holding a comma or a quote (or a space at either end) is shown as a quoted string, so that the text
// splits back into the same items (splitItems).
const itemText = (t) => (/[,"]|^\s|\s$/.test(t) ? JSON.stringify(t) : t);
export const listText = (v) => (Array.isArray(v) ? v.map((t) => itemText(String(t))).join(', ')
  : (v === null || v === undefined ? '' : String(v)));
export const splitList = (text) => text.split(',').map((t) => t.trim()).filter((t) => t);

/** The items of a list value as typed: comma-separated, an item in double quotes may hold commas ("Hello, Ken"). */
export function splitItems(text) {
  const items = [];
  let i = 0;
  while (i < text.length) {
    while (i < text.length && /\s/.test(text[i])) i++;
    let item = null;
    const quoted = text[i] === '"' ? /^"(?:[^"\\]|\\.)*"/.exec(text.slice(i)) : null;
    if (quoted) {
      try {
        item = JSON.parse(quoted[0]);
        i += quoted[0].length;
      } catch (e) {
        item = null;
      }
    }
    const comma = text.indexOf(',', i);
    const stop = comma < 0 ? text.length : comma;
    if (item === null) item = text.slice(i, stop).trim();
    if (item !== '') items.push(item);
    i = stop + 1;
  }
  return items;
}

export function renderSlots(editable) {
  const body = $('slot-rows');
  body.replaceChildren();
  const d = state.draft;
  const problemsBySlot = new Map();
  for (const p of state.problems) {
    if (p.slot) {
      if (!problemsBySlot.has(p.slot)) problemsBySlot.set(p.slot, []);
      problemsBySlot.get(p.slot).push(p.message);
    }
  }
  d.slots.forEach((s, i) => {
    const problems = problemsBySlot.get(s.name) || [];
    body.append(ownRow(s, i, editable, problems.length > 0));
    if (state.details.has(i) || (isScript(s) && problems.length)) body.append(detailsRow(s, i, editable));
    for (const m of problems) {
      body.append(el('tr', { class: 'problem-row' }, el('td', { colspan: '14', text: m })));
    }
  });
  const own = new Set(d.slots.map((s) => s.name));
  for (const e of state.frame.effectiveSlots) {
    if (e.inherited && !own.has(e.slot.name)) body.append(inheritedRow(e, editable));
  }
  if (!body.children.length) {
    body.append(el('tr', {}, el('td', { colspan: '14', class: 'muted', text: 'This frame has no slots.' })));
  }
}

function ownRow(s, i, editable, invalid) {
  const label = (facet) => s.name + ' ' + facet;
  const text = (facet, key, opts) => el('td', {}, el('input', Object.assign({
    type: 'text', value: listText(s[key]), 'aria-label': label(facet), disabled: !editable,
    dataset: { slot: String(i), facet: key },
    oninput: (e) => {
      const v = e.target.value;
      if (key === 'frameListRelated') s[key] = splitList(v);
      else if (s.type === 'TYPE_LIST' && (key === 'value' || key === 'defaultValue')) {
        s[key] = v.trim() === '' ? null : splitItems(v);
      } else s[key] = v === '' ? null : v;
      markDirty();
    }
  }, opts || {})));
  const check = (facet, key) => el('td', { class: 'check' }, el('input', {
    type: 'checkbox', checked: !!s[key], 'aria-label': label(facet), disabled: !editable,
    onchange: (e) => { s[key] = e.target.checked; markDirty(); }
  }));
  const type = el('select', {
    'aria-label': label('data type'), disabled: !editable,
    onchange: (e) => { s.type = e.target.value; markDirty(); renderFrame(); }
  }, TYPES.map((t) => el('option', { value: t, text: t.replace('TYPE_', '') })));
  type.value = s.type;
  const lines = s.value ? String(s.value).split('\n').length : 0;
  const valueCell = isScript(s)
    ? el('td', {}, el('button', {
      type: 'button', class: 'small ghost', 'aria-label': 'Edit script ' + s.name,
      text: lines ? 'Script (' + lines + ' line' + (lines > 1 ? 's' : '') + ')' : 'Script…',
      onclick: () => toggleDetails(i)
    }))
    : text('value', 'value');
  return el('tr', { class: 'own' + (invalid ? ' invalid' : ''), dataset: { slotName: s.name } },
    el('td', {}, el('input', {
      type: 'text', value: s.name, 'aria-label': 'Slot name ' + (i + 1), disabled: !editable,
      oninput: (e) => { s.name = e.target.value.trim(); markDirty(); }
    })),
    text('role', 'role'), text('from', 'from'), el('td', {}, type), valueCell,
    text('default', 'defaultValue'), text('condition', 'condition', { placeholder: 'COND_ANY' }),
    text('argument', 'argument', { list: 'class-names' }),
    check('required', 'required'), check('shared', 'shared'), check('unique', 'unique'),
    text('frame-related', 'frameRelated', { list: 'frame-names' }), text('frame-list-related', 'frameListRelated'),
    el('td', {}, el('div', { class: 'row-actions' },
      el('button', {
        type: 'button', class: 'icon', text: '⋯', 'aria-expanded': String(state.details.has(i)),
        'aria-label': 'Scripts and demons of ' + s.name, title: 'Scripts and demons', onclick: () => toggleDetails(i)
      }),
      editable ? el('button', {
        type: 'button', class: 'icon', text: '✕', 'aria-label': 'Remove slot ' + s.name, title: 'Remove slot',
        onclick: () => { state.draft.slots.splice(i, 1); state.details.clear(); markDirty(); renderFrame(); }
      }) : null)));
}

function toggleDetails(i) {
  if (state.details.has(i)) state.details.delete(i); else state.details.add(i);
  renderFrame();
}

function detailsRow(s, i, editable) {
  const editors = [];
  const add = (key, label) => {
    const ed = codeEditor('script-' + i + '-' + key, label, s[key], (v) => {
      s[key] = v === '' ? null : v;
      markDirty();
    });
    ed.textarea.disabled = !editable;
    ed.textarea.rows = key === 'value' ? 4 : 2;
    editors.push(el('div', { class: key === 'value' ? 'wide' : null }, ed.element,
      el('div', { class: 'script-result', id: 'script-' + i + '-' + key + '-result' })));
  };
  if (isScript(s)) add('value', s.name + ' (JavaScript value)');
  add('onNeeded', 'onNeeded demon');
  add('onAdded', 'onAdded demon');
  add('onRemoved', 'onRemoved demon');
  const reactive = el('label', {},
    el('input', {
      type: 'checkbox', checked: s.reactive !== false, disabled: !editable,
      onchange: (e) => { s.reactive = e.target.checked; markDirty(); }
    }), ' Reactive (writes re-trigger matching)');
  return el('tr', { class: 'details' }, el('td', { colspan: '14' },
    el('div', { class: 'details-grid' }, editors, el('div', { class: 'wide' }, reactive))));
}

function inheritedRow(e) {
  const s = e.slot;
  const cell = (v) => el('td', {}, el('span', { class: 'cell-text', title: listText(v), text: listText(v) }));
  const mark = (b) => el('td', { class: 'check', text: b ? '✓' : '–' });
  return el('tr', { class: 'inherited', dataset: { slotName: s.name } },
    el('td', {}, el('span', { class: 'slot-name', text: s.name }),
      el('span', { class: 'from', text: 'from ' + e.declaredBy })),
    cell(s.role), cell(s.from), cell(s.type.replace('TYPE_', '')),
    cell(isScript(s) && s.value ? 'script' : s.value), cell(s.defaultValue), cell(s.condition), cell(s.argument),
    mark(s.required), mark(s.shared), mark(s.unique), cell(s.frameRelated), cell(s.frameListRelated),
    el('td', {}, state.session.loggedIn ? el('button', {
      type: 'button', class: 'small ghost', text: 'Override', 'aria-label': 'Override ' + s.name + ' here',
      onclick: () => {
        const copy = JSON.parse(JSON.stringify(s));
        state.draft.slots.push(copy);
        markDirty();
        renderFrame();
      }
    }) : null));
}

// ---- saving ----

export async function checkScripts() {
  if (!state.session.scripts) return [];
  const problems = [];
  for (const [i, s] of state.draft.slots.entries()) {
    const sources = [];
    if (isScript(s) && s.value) sources.push(['value', s.value]);
    for (const k of ['onNeeded', 'onAdded', 'onRemoved']) if (s[k]) sources.push([k, s[k]]);
    if (s.condition && /^js:/.test(s.condition.trim())) sources.push(['condition', s.condition.trim().slice(3)]);
    for (const [key, source] of sources) {
      const r = await api('POST', '/api/scripts/check', { source, name: state.frame.name + '.' + s.name + '.' + key });
      const out = $('script-' + i + '-' + key + '-result');
      if (!r.ok) {
        problems.push({ frame: state.frame.name, slot: s.name, message: 'Script ' + key + ' of slot \'' + s.name
          + '\' has a syntax error at line ' + r.line + ', column ' + r.column + ': ' + r.message });
        state.details.add(i);
      } else if (out) {
        out.textContent = '✓ syntax ok';
        out.className = 'script-result good';
      }
    }
  }
  return problems;
}

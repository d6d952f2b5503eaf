// K-ICNP knowledge editor: one frame: its Table 1 items, saving, create, rename and delete.
// An ES module loaded by index.html; no build step, nothing from the network.
import { $, ApiError, api, el, enc, frameAddress, notice, show, showErrors, showMain, state } from './base.js';
import { loadFrames, renderTree } from './tree.js';
import { checkScripts, renderSlots, splitList } from './slots.js';

// ---- one frame ----

/** Whether the unsaved edits, if any, may go: asks before they are discarded. */
export function mayDiscardEdits() {
  return !state.dirty || window.confirm('Discard the unsaved changes to ' + state.selected + '?');
}

export async function openFrame(name, keepNotice) {
  if (name !== state.selected && !mayDiscardEdits()) {
    return;
  }
  try {
    const frame = await api('GET', '/api/frames/' + enc(name));
    state.selected = name;
    setFrame(frame);
    if (!keepNotice) notice('');
    showErrors('frame-errors', null);
    showMain('frame-panel');
    renderTree();
    history.replaceState(null, '', frameAddress(name));
  } catch (e) {
    showMain('welcome');
    showErrors('frame-errors', e);
  }
}

export function setFrame(frame) {
  state.frame = frame;
  state.draft = JSON.parse(JSON.stringify({
    kind: frame.kind, parent: frame.parent, priority: frame.priority, provenance: frame.provenance,
    parts: frame.parts, linksTo: frame.linksTo, linksFrom: frame.linksFrom, slots: frame.slots
  }));
  state.dirty = false;
  state.problems = [];
  show('stale-note', false);
  show('rename-form', false);
  show('delete-confirm', false);
  renderFrame();
}

export function markDirty() {
  state.dirty = true;
  $('save-button').disabled = !state.session.loggedIn;
  $('revert-button').disabled = false;
}

export function renderFrame() {
  const f = state.frame;
  const editable = !!state.session.loggedIn;
  $('frame-title').textContent = f.name;
  const crumbs = $('frame-crumbs');
  crumbs.replaceChildren();
  f.ancestors.slice().reverse().forEach((a) => {
    crumbs.append(el('button', { type: 'button', text: a, onclick: () => openFrame(a) }), ' › ');
  });
  $('frame-meta').replaceChildren(...[
    el('span', { class: 'pill ' + f.kind.toLowerCase(), text: f.kind === 'CLASS' ? 'Class' : 'Instance' }),
    f.learned ? el('span', { class: 'pill learned', text: 'Learned' }) : null,
    el('span', { text: f.provenance.toLowerCase() + ' · revision ' + f.revision })
  ].filter((n) => n));
  for (const id of ['save-button', 'rename-button', 'delete-button', 'new-child-button', 'add-slot-button']) {
    $(id).disabled = !editable;
  }
  $('new-child-button').disabled = !editable || f.kind !== 'CLASS';
  // A behavior frame (a class with a required instance slot, its own or inherited) can be asked why it has not fired.
  $('why-not-frame-button').hidden = !state.session.inference || f.kind !== 'CLASS'
    || !f.effectiveSlots.some((e) => e.slot.required && e.slot.type === 'TYPE_INSTANCE');
  $('save-button').disabled = !editable || !state.dirty;
  $('revert-button').disabled = !state.dirty;
  renderItems(editable);
  renderSlots(editable);
}

function renderItems(editable) {
  const f = state.frame;
  const d = state.draft;
  const box = $('frame-items');
  const field = (id, label, control) => [el('label', { for: id, text: label }), control];
  const kind = el('select', {
    id: 'item-kind', disabled: !editable,
    onchange: (e) => { d.kind = e.target.value; markDirty(); }
  }, el('option', { value: 'CLASS', text: 'Class' }), el('option', { value: 'INSTANCE', text: 'Instance' }));
  kind.value = d.kind;
  const parent = el('input', {
    id: 'item-parent', type: 'text', list: 'class-names', value: d.parent || '', placeholder: '(root)',
    disabled: !editable, oninput: (e) => { d.parent = e.target.value.trim() || null; markDirty(); }
  });
  const parts = el('input', {
    id: 'item-parts', type: 'text', value: d.parts.join(', '), placeholder: 'frame, frame…', disabled: !editable,
    oninput: (e) => { d.parts = splitList(e.target.value); markDirty(); }
  });
  const priority = el('input', {
    id: 'item-priority', type: 'number', value: String(d.priority), disabled: !editable,
    oninput: (e) => { d.priority = parseInt(e.target.value, 10) || 0; markDirty(); }
  });
  const chips = (names) => names.length
    ? el('div', { class: 'chips' }, names.map((n) => el('button', {
      type: 'button', class: 'chip', text: n, onclick: () => openFrame(n)
    })))
    : el('span', { class: 'muted', text: 'NULL' });
  const linkChips = (links, arrow) => links.length
    ? el('div', { class: 'chips' }, links.map((l) => el('button', {
      type: 'button', class: 'chip', text: l.relation + ' ' + arrow + ' ' + l.frame, onclick: () => openFrame(l.frame)
    })))
    : el('span', { class: 'muted', text: 'NULL' });
  const links = f.linksIn.length || f.linksOut.length
    ? el('div', { class: 'chips' }, f.linksIn.length ? linkChips(f.linksIn, '←') : null,
      f.linksOut.length ? linkChips(f.linksOut, '→') : null)
    : el('span', { class: 'muted', text: 'NULL' });
  box.replaceChildren(
    el('span', { class: 'item-label', text: 'Frame name' }), el('strong', { text: f.name }),
    ...field('item-kind', 'Frame type', kind),
    ...field('item-parent', 'A-kind-of', parent),
    ...field('item-priority', 'Priority', priority),
    ...field('item-parts', 'Has-part', parts),
    el('span', { class: 'item-label', text: 'Descendants' }), chips(f.children.map((c) => c.name)),
    el('span', { class: 'item-label', text: 'Semantic-link-to' }), linkEditor('to', d.linksTo, editable),
    el('span', { class: 'item-label', text: 'Semantic-link-from' }), linkEditor('from', d.linksFrom, editable),
    el('span', { class: 'item-label', text: 'Links, both ends' }), el('div', { class: 'span3' }, links)
  );
}

function linkEditor(which, links, editable) {
  const box = el('div');
  links.forEach((l, i) => {
    const id = 'link-' + which + '-' + i;
    box.append(el('div', { class: 'link-row' },
      el('label', { for: id + '-rel', class: 'sr-only', text: 'Relation of link ' + (i + 1) }),
      el('input', {
        id: id + '-rel', type: 'text', list: 'relations', value: l.relation, disabled: !editable,
        oninput: (e) => { l.relation = e.target.value.trim(); markDirty(); }
      }),
      el('label', { for: id + '-frame', class: 'sr-only', text: 'Frame of link ' + (i + 1) }),
      el('input', {
        id: id + '-frame', type: 'text', list: 'frame-names', value: l.frame, disabled: !editable,
        oninput: (e) => { l.frame = e.target.value.trim(); markDirty(); }
      }),
      editable ? el('button', {
        type: 'button', class: 'icon', 'aria-label': 'Remove link ' + (i + 1), text: '✕',
        onclick: () => { links.splice(i, 1); markDirty(); renderFrame(); }
      }) : null));
  });
  if (!links.length) box.append(el('span', { class: 'muted', text: 'NULL ' }));
  if (editable) {
    box.append(el('button', {
      type: 'button', class: 'small ghost', text: 'Add link',
      onclick: () => { links.push({ relation: 'SUCCESSION', frame: '' }); markDirty(); renderFrame(); }
    }));
  }
  return box;
}

export async function save() {
  const f = state.frame;
  const d = state.draft;
  try {
    const scriptProblems = await checkScripts();
    if (scriptProblems.length) {
      state.problems = scriptProblems;
      renderFrame();
      showErrors('frame-errors', new ApiError(422, 'Fix the scripts before saving; nothing was saved.', scriptProblems));
      return;
    }
    const body = Object.assign({ name: f.name, expectedRevision: f.revision }, d);
    const sent = JSON.stringify(d); // what this save holds: edits typed after it are not in it
    const saved = await api('PUT', '/api/frames/' + enc(f.name), body);
    state.details.clear();
    if (state.frame !== f) {
      notice('Saved ' + f.name + ' (revision ' + saved.frame.revision + ').'); // another frame is open now
    } else if (state.draft === d && JSON.stringify(d) !== sent) {
      keepLaterEdits(saved.frame);
      notice('Saved ' + f.name + ' (revision ' + saved.frame.revision + '); the edits made since are not saved yet.');
    } else {
      setFrame(saved.frame);
      showErrors('frame-errors', null);
      notice('Saved ' + f.name + ' (revision ' + saved.frame.revision + ').');
    }
  } catch (e) {
    if (e.status === 409) {
      const stale = $('stale-note');
      stale.replaceChildren(e.message + ' ', el('button', {
        type: 'button', class: 'small', text: 'Reload frame',
        onclick: () => { state.dirty = false; openFrame(f.name); }
      }));
      stale.hidden = false;
    }
    state.problems = e.problems || [];
    renderFrame();
    showErrors('frame-errors', e);
    notice('');
  }
}

/**
 * The answer to a save came back after more edits were typed: the frame moves to the saved revision (so the next save
 * is not refused as stale) and the draft, which holds the later edits, stays as it is, unsaved. The form is not
 * rebuilt, so the field being typed in keeps its focus.
 */
function keepLaterEdits(saved) {
  state.frame = saved;
  state.problems = [];
  state.dirty = true;
  const row = state.byName.get(saved.name);
  // The change event of this very save may have arrived first and been taken for someone else's change.
  if (!(row && row.revision > saved.revision)) show('stale-note', false);
  $('frame-meta').lastElementChild.textContent = saved.provenance.toLowerCase() + ' · revision ' + saved.revision;
  $('save-button').disabled = !state.session.loggedIn;
  $('revert-button').disabled = false;
  showErrors('frame-errors', null);
}

// ---- create, rename, delete ----

export function startCreate(parent) {
  if (!mayDiscardEdits()) return; // creating opens the new frame, which drops the edits
  showMain('create-panel');
  showErrors('create-errors', null);
  $('create-name').value = '';
  $('create-parent').value = parent || '';
  $('create-kind').value = 'CLASS';
  $('create-name').focus();
}

export async function create(event) {
  event.preventDefault();
  const body = { name: $('create-name').value.trim(), kind: $('create-kind').value,
    parent: $('create-parent').value.trim() || null, slots: [] };
  try {
    const saved = await api('POST', '/api/frames', body);
    await loadFrames();
    state.dirty = false;
    await openFrame(saved.frame.name);
    notice('Created ' + saved.frame.name + '.');
  } catch (e) {
    showErrors('create-errors', e);
  }
}

export async function rename(event) {
  event.preventDefault();
  const from = state.frame.name;
  try {
    const saved = await api('POST', '/api/frames/' + enc(from) + '/rename', { newName: $('rename-input').value.trim() });
    await loadFrames();
    state.dirty = false;
    await openFrame(saved.frame.name);
    notice('Renamed ' + from + ' to ' + saved.frame.name + '; references in other frames were updated.');
  } catch (e) {
    showErrors('frame-errors', e);
  }
}

export async function remove() {
  const name = state.frame.name;
  try {
    const result = await api('DELETE', '/api/frames/' + enc(name));
    state.dirty = false;
    state.selected = null;
    state.frame = null;
    showMain('welcome');
    const withIt = ((result && result.removed) || []).filter(n => n !== name);
    $('welcome-text').textContent = 'Deleted ' + name
      + (withIt.length ? ', and with it what rested on it: ' + withIt.join(', ') : '') + '.';
    await loadFrames();
  } catch (e) {
    show('delete-confirm', false);
    showErrors('frame-errors', e);
  }
}

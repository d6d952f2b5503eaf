// K-ICNP knowledge editor page. Plain JavaScript, no build step; it uses only the documented JSON API
// (docs/editor-openapi.yaml) and the /api/events WebSocket.
(function () {
  'use strict';

  const $ = (id) => document.getElementById(id);
  const TYPES = ['TYPE_INSTANCE', 'TYPE_STR', 'TYPE_INT', 'TYPE_FLOAT', 'TYPE_BOOL', 'TYPE_FRAME', 'TYPE_LIST'];
  const RELATIONS = ['SYNCHRONIZATION', 'SUCCESSION', 'RESTRICTION'];
  const state = {
    frames: [], byName: new Map(), session: { loggedIn: false }, version: 0,
    selected: null, frame: null, draft: null, dirty: false, collapsed: new Set(), details: new Set(),
    problems: [], socket: null
  };

  // ---- API ----

  class ApiError extends Error {
    constructor(status, message, problems) {
      super(message);
      this.status = status;
      this.problems = problems || [];
    }
  }

  async function api(method, path, body) {
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
      throw new ApiError(response.status, (data && data.error) || response.statusText, data && data.problems);
    }
    return data;
  }

  const enc = (name) => encodeURIComponent(name);

  // ---- small DOM helpers ----

  function el(tag, props, ...children) {
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

  function show(id, visible) {
    $(id).hidden = !visible;
  }

  function showErrors(containerId, error) {
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

  const PANELS = ['welcome', 'import-panel', 'create-panel', 'frame-panel', 'inference-panel'];

  function showMain(id) {
    for (const p of PANELS) show(p, p === id);
  }

  function notice(text) {
    const n = $('frame-notice');
    n.textContent = text;
    n.hidden = !text;
  }

  // ---- session ----

  async function loadSession() {
    state.session = await api('GET', '/api/session');
    const s = state.session;
    show('login-form', !s.loggedIn && s.editingPossible);
    show('session-info', s.loggedIn);
    const note = $('readonly-note');
    if (!s.editingPossible) {
      note.textContent = 'Read-only: no editor password is configured on the server (editor.password).';
    } else if (!s.loggedIn) {
      note.textContent = 'Read-only until you log in.';
    }
    note.hidden = s.loggedIn;
    $('import-button').disabled = !s.loggedIn || !s.xml;
    $('import-button').title = !s.xml ? 'XML import is not available in this build' : 'Import frames from XML';
    $('export-button').disabled = !s.xml;
    $('export-button').title = !s.xml ? 'XML export is not available in this build' : 'Download every frame as XML';
    $('new-frame-button').disabled = !s.loggedIn;
    $('inference-button').hidden = !s.inference;
    $('run-button').disabled = !s.loggedIn;
    document.body.classList.toggle('readonly', !s.loggedIn);
    if (state.frame) renderFrame();
  }

  async function login(event) {
    event.preventDefault();
    const input = $('login-password');
    try {
      await api('POST', '/api/login', { password: input.value });
      input.value = '';
      $('login-error').hidden = true;
      await loadSession();
    } catch (e) {
      $('login-error').textContent = e.message;
      $('login-error').hidden = false;
      input.select();
    }
  }

  async function logout() {
    await api('POST', '/api/logout', {});
    await loadSession();
  }

  // ---- hierarchy ----

  async function loadFrames() {
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

  function renderNameLists() {
    renderStats();
    $('class-names').replaceChildren(...state.frames.filter((f) => f.kind === 'CLASS')
      .map((f) => el('option', { value: f.name })));
    $('frame-names').replaceChildren(...state.frames.map((f) => el('option', { value: f.name })));
  }

  function renderTree() {
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

  // ---- one frame ----

  async function openFrame(name, keepNotice) {
    if (state.dirty && name !== state.selected
        && !window.confirm('Discard the unsaved changes to ' + state.selected + '?')) {
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
      history.replaceState(null, '', '#' + enc(name));
    } catch (e) {
      showMain('welcome');
      showErrors('frame-errors', e);
    }
  }

  function setFrame(frame) {
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

  function markDirty() {
    state.dirty = true;
    $('save-button').disabled = !state.session.loggedIn;
    $('revert-button').disabled = false;
  }

  function renderFrame() {
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

  const isScript = (s) => s.type === 'TYPE_STR' && /^on[A-Z]/.test(s.name);
  const listText = (v) => (Array.isArray(v) ? v.join(', ') : (v === null || v === undefined ? '' : String(v)));
  const splitList = (text) => text.split(',').map((t) => t.trim()).filter((t) => t);

  function renderSlots(editable) {
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
        else s[key] = v === '' ? null : v;
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
    const valueCell = isScript(s)
      ? el('td', {}, el('button', {
        type: 'button', class: 'small ghost', 'aria-label': 'Edit script ' + s.name,
        text: s.value ? 'Script (' + String(s.value).split('\n').length + ' line' + (String(s.value).split('\n').length > 1 ? 's' : '') + ')' : 'Script…',
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
      const ed = window.KicnpHighlight.editor('script-' + i + '-' + key, label, s[key], (v) => {
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

  async function checkScripts() {
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

  async function save() {
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
      const saved = await api('PUT', '/api/frames/' + enc(f.name), body);
      state.details.clear();
      setFrame(saved.frame);
      showErrors('frame-errors', null);
      notice('Saved ' + f.name + ' (revision ' + saved.frame.revision + ').');
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

  // ---- create, rename, delete ----

  function startCreate(parent) {
    showMain('create-panel');
    showErrors('create-errors', null);
    $('create-name').value = '';
    $('create-parent').value = parent || '';
    $('create-kind').value = 'CLASS';
    $('create-name').focus();
  }

  async function create(event) {
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

  async function rename(event) {
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

  async function remove() {
    const name = state.frame.name;
    try {
      await api('DELETE', '/api/frames/' + enc(name));
      state.dirty = false;
      state.selected = null;
      state.frame = null;
      showMain('welcome');
      await loadFrames();
    } catch (e) {
      show('delete-confirm', false);
      showErrors('frame-errors', e);
    }
  }

  // ---- import / export ----

  function startImport() {
    showMain('import-panel');
    showErrors('import-errors', null);
    $('import-text').focus();
  }

  async function applyImport() {
    try {
      const r = await api('POST', '/api/import', { xml: $('import-text').value });
      await loadFrames();
      showMain('welcome');
      $('welcome-text').textContent = 'Imported ' + r.count + ' frame(s); ' + r.changed + ' were new or changed.';
    } catch (e) {
      showErrors('import-errors', e);
    }
  }

  // ---- inference ----

  let inferenceTimer = null;

  function scheduleInferenceReload() {
    clearTimeout(inferenceTimer);
    inferenceTimer = setTimeout(() => loadInference().catch(() => {}), 300);
  }

  async function openInference() {
    if (state.dirty && !window.confirm('Discard the unsaved changes to ' + state.selected + '?')) return;
    state.dirty = false;
    showMain('inference-panel');
    await loadInference();
  }

  async function loadInference() {
    try {
      const s = await api('GET', '/api/inference');
      $('inference-meta').textContent = 'agenda ' + s.agenda + ' · ' + s.instances.length
        + ' instance(s) in working memory · ' + s.actions + ' action(s) issued';
      $('wm-rows').replaceChildren(...(s.instances.length ? s.instances.map((i) => el('tr', {},
        el('td', {}, el('button', { type: 'button', class: 'chip', text: i.name, onclick: () => openFrame(i.name) })),
        el('td', { text: i.className }),
        el('td', { text: i.derived ? 'derived' : 'asserted' }),
        el('td', {}, el('button', {
          type: 'button', class: 'small ghost', text: 'Why?', 'aria-label': 'Why does ' + i.name + ' exist?',
          onclick: () => why(i.name)
        }))))
        : [el('tr', {}, el('td', { colspan: '4', class: 'muted', text: 'Working memory is empty.' }))]));
      showErrors('inference-errors', null);
    } catch (e) {
      showErrors('inference-errors', e);
    }
  }

  async function runInference() {
    try {
      const r = await api('POST', '/api/inference/run', {});
      await loadInference();
      $('inference-meta').textContent += ' · last run: ' + r.firings + ' firing(s)';
    } catch (e) {
      showErrors('inference-errors', e);
    }
  }

  async function why(instance) {
    try {
      const e = await api('GET', '/api/inference/why/' + enc(instance));
      $('why-tree').replaceChildren(el('ul', {}, explanationItem(e)));
    } catch (err) {
      showErrors('inference-errors', err);
    }
  }

  function explanationItem(e) {
    if (e.type === 'asserted') {
      return el('li', {}, el('span', { class: 'what', text: e.instance }),
        el('span', { class: 'how', text: ' asserted as ' + e.className }));
    }
    const d = e.derivation;
    const binding = Object.entries(d.binding).map(([k, v]) => k + '=' + v).join(', ');
    return el('li', {}, el('span', { class: 'what', text: e.instance }),
      el('span', { class: 'how', text: ' made by ' + d.frame + ' (firing #' + d.firing + '; ' + binding + ')' }),
      e.supports.length ? el('ul', {}, e.supports.map(explanationItem)) : null);
  }

  async function askInference(event) {
    event.preventDefault();
    try {
      const answers = await api('GET', '/api/inference/ask?class=' + enc($('ask-class').value.trim()));
      $('ask-answers').replaceChildren(...(answers.length ? answers.map((a) => el('li', {
        text: (a.instance || '(new ' + a.className + ')') + (a.derivable ? ' — derivable' : ' — exists')
          + (Object.keys(a.slots).length ? ': ' + Object.entries(a.slots).map(([k, v]) => k + '=' + v).join(', ') : '')
      })) : [el('li', { class: 'muted', text: 'No instance exists or could be derived.' })]));
    } catch (e) {
      showErrors('inference-errors', e);
    }
  }

  function addTrace(event) {
    const log = $('trace-log');
    log.append(el('li', { class: event.event }, el('span', { class: 'ev', text: event.event }), ' ', event.text));
    while (log.children.length > 300) log.firstChild.remove();
    log.scrollTop = log.scrollHeight;
  }

  // ---- live updates ----

  function connect() {
    const url = (location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host + '/api/events';
    const socket = new WebSocket(url);
    state.socket = socket;
    socket.onopen = () => {
      $('live').textContent = 'live';
      $('live').classList.remove('off');
    };
    socket.onclose = () => {
      $('live').textContent = 'offline';
      $('live').classList.add('off');
      setTimeout(connect, 2000);
    };
    socket.onmessage = (m) => {
      const event = JSON.parse(m.data);
      if (event.type === 'hello') {
        setVersion(event.version);
        loadFrames().catch(() => {});
      } else if (event.type === 'change') {
        setVersion(event.version);
        applyChanges(event.events);
        if (!$('inference-panel').hidden) scheduleInferenceReload();
      } else if (event.type === 'trace') {
        addTrace(event);
      }
    };
  }

  function setVersion(v) {
    state.version = v;
    $('kb-version').textContent = 'knowledge base version ' + v;
  }

  let treeRenderPending = false;

  // Bursts of changes (an inference run, an import) re-render the tree once per animation frame, not per event.
  function scheduleTreeRender() {
    if (treeRenderPending) return;
    treeRenderPending = true;
    requestAnimationFrame(() => {
      treeRenderPending = false;
      renderTree();
      renderNameLists();
    });
  }

  function applyChanges(events) {
    let touchedSelected = false;
    for (const e of events) {
      if (e.kind === 'removed') {
        state.byName.delete(e.name);
      } else if (e.frame) {
        state.byName.set(e.name, e.frame);
      }
      if (e.name === state.selected) touchedSelected = e;
    }
    const order = state.frames.map((f) => f.name);
    for (const n of state.byName.keys()) if (!order.includes(n)) order.push(n);
    state.frames = order.filter((n) => state.byName.has(n)).map((n) => state.byName.get(n));
    scheduleTreeRender();
    if (touchedSelected && state.frame) {
      if (touchedSelected.kind === 'removed') {
        const stale = $('stale-note');
        stale.textContent = 'Frame ' + state.selected + ' was removed.';
        stale.hidden = false;
      } else if (touchedSelected.frame.revision !== state.frame.revision) {
        if (state.dirty) {
          const stale = $('stale-note');
          stale.textContent = 'Someone else changed ' + state.selected + ' (revision ' + touchedSelected.frame.revision
            + '). Saving your edit will be refused; reload to see theirs.';
          stale.hidden = false;
        } else {
          openFrame(state.selected, true);
        }
      }
    }
  }

  // ---- wiring ----

  function wire() {
    $('login-form').addEventListener('submit', login);
    $('logout-button').addEventListener('click', logout);
    $('search').addEventListener('input', renderTree);
    $('new-frame-button').addEventListener('click', () => startCreate(''));
    $('new-child-button').addEventListener('click', () => startCreate(state.frame.name));
    $('create-form').addEventListener('submit', create);
    $('create-cancel').addEventListener('click', () => showMain(state.frame ? 'frame-panel' : 'welcome'));
    $('save-button').addEventListener('click', save);
    $('revert-button').addEventListener('click', () => { setFrame(state.frame); showErrors('frame-errors', null); });
    $('add-slot-button').addEventListener('click', () => {
      state.draft.slots.push({ name: 'newSlot' + (state.draft.slots.length + 1), type: 'TYPE_STR', value: null,
        defaultValue: null, condition: 'COND_ANY', argument: null, required: false, shared: true, unique: false,
        frameRelated: null, frameListRelated: [], role: null, from: null, reactive: true });
      markDirty();
      renderFrame();
      const inputs = $('slot-rows').querySelectorAll('tr.own td:first-child input');
      inputs[inputs.length - 1].select();
    });
    $('rename-button').addEventListener('click', () => {
      show('rename-form', true);
      $('rename-input').value = state.frame.name;
      $('rename-input').select();
    });
    $('rename-form').addEventListener('submit', rename);
    $('rename-cancel').addEventListener('click', () => show('rename-form', false));
    $('delete-button').addEventListener('click', () => {
      $('delete-question').textContent = 'Delete frame ' + state.frame.name + '? This cannot be undone.';
      show('delete-confirm', true);
      $('delete-cancel').focus();
    });
    $('delete-apply').addEventListener('click', remove);
    $('delete-cancel').addEventListener('click', () => show('delete-confirm', false));
    $('export-button').addEventListener('click', () => { window.location.assign('/api/export?download=true'); });
    $('import-button').addEventListener('click', startImport);
    $('import-cancel').addEventListener('click', () => showMain(state.frame ? 'frame-panel' : 'welcome'));
    $('inference-button').addEventListener('click', openInference);
    $('inference-refresh').addEventListener('click', loadInference);
    $('run-button').addEventListener('click', runInference);
    $('ask-form').addEventListener('submit', askInference);
    $('import-apply').addEventListener('click', applyImport);
    $('import-file').addEventListener('change', async (e) => {
      const file = e.target.files[0];
      if (file) $('import-text').value = await file.text();
    });
    document.body.append(el('datalist', { id: 'relations' }, RELATIONS.map((r) => el('option', { value: r }))));
  }

  async function init() {
    wire();
    try {
      await loadSession();
      await loadFrames();
      const wanted = decodeURIComponent(location.hash.slice(1));
      if (wanted && state.byName.has(wanted)) await openFrame(wanted);
    } catch (e) {
      $('login-error').textContent = e.message;
      $('login-error').hidden = false;
    }
    connect();
  }

  document.addEventListener('DOMContentLoaded', init);
})();

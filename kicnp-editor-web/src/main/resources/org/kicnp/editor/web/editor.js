// K-ICNP knowledge editor: start-up, session, import/export, live updates and wiring.
// An ES module loaded by index.html; no build step, nothing from the network.
import { $, RELATIONS, api, el, readAddress, show, showErrors, showMain, state } from './base.js';
import { loadFrames, renderNameLists, renderTree } from './tree.js';
import { drawLinks, scheduleDrawLinks, swatch } from './links.js';
import { create, markDirty, mayDiscardEdits, openFrame, remove, rename, renderFrame, save, setFrame, startCreate } from './frame.js';
import { addTrace, askInference, loadInference, openInference, proveInference, runInference, scheduleInferenceReload, whyNotInference } from './inference.js';
import { openWorld, renderWorldSession, worldEvent, worldVisible } from './world.js';
import { cancelWrong, chatLine, feedbackEvent, markWrong, renderActions, renderArgs, say, sendCommand } from './operate.js';

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
  renderWorldSession();
  if (worldVisible()) openWorld();
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
      const again = helloSeen;
      helloSeen = true;
      (again ? reconnected() : loadFrames()).catch(() => {});
    } else if (event.type === 'change') {
      setVersion(event.version);
      applyChanges(event.events);
      if (!$('inference-panel').hidden) scheduleInferenceReload();
    } else if (event.type === 'trace') {
      addTrace(event);
    } else if (event.type === 'world') {
      worldEvent(event);
    } else if (event.type === 'chat') {
      chatLine(event);
    } else if (event.type === 'feedback') {
      feedbackEvent(event);
    }
  };
}

let helloSeen = false;

// Back after the connection dropped: the server may have restarted (its sessions gone) and the changes made in
// between were never pushed, so the session, the tree and the open frame are read again.
async function reconnected() {
  await loadSession();
  await loadFrames();
  if (state.frame) selectedChanged(state.byName.get(state.selected) || null);
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
  if (touchedSelected && state.frame) selectedChanged(touchedSelected.kind === 'removed' ? null : touchedSelected.frame);
}

// The open frame's row as the server now lists it (null: gone): reload it, or say why the edit will be refused.
function selectedChanged(row) {
  if (!row) {
    const stale = $('stale-note');
    stale.textContent = 'Frame ' + state.selected + ' was removed.';
    stale.hidden = false;
  } else if (row.revision !== state.frame.revision) {
    if (state.dirty) {
      const stale = $('stale-note');
      stale.textContent = 'Someone else changed ' + state.selected + ' (revision ' + row.revision
        + '). Saving your edit will be refused; reload to see theirs.';
      stale.hidden = false;
    } else {
      openFrame(state.selected, true);
    }
  }
}

// ---- wiring ----

function wire() {
  $('login-form').addEventListener('submit', login);
  $('logout-button').addEventListener('click', logout);
  window.addEventListener('kicnp-session-lost', () => { loadSession().catch(() => {}); });
  $('search').addEventListener('input', renderTree);
  $('new-frame-button').addEventListener('click', () => startCreate(''));
  $('new-child-button').addEventListener('click', () => startCreate(state.frame.name));
  $('create-form').addEventListener('submit', create);
  $('create-cancel').addEventListener('click', () => showMain(state.frame ? 'frame-panel' : 'welcome'));
  $('save-button').addEventListener('click', save);
  $('revert-button').addEventListener('click', () => {
    setFrame(state.frame);
    showErrors('frame-errors', null);
    // Someone else saved it meanwhile: revert to what is there now, not to the revision read before theirs.
    const row = state.byName.get(state.selected);
    if (row && row.revision !== state.frame.revision) openFrame(state.selected, true);
  });
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
    if (!mayDiscardEdits()) return; // renaming reopens the frame as saved
    show('rename-form', true);
    $('rename-input').value = state.frame.name;
    $('rename-input').select();
  });
  $('rename-form').addEventListener('submit', rename);
  $('rename-cancel').addEventListener('click', () => show('rename-form', false));
  $('delete-button').addEventListener('click', () => {
    // With an inference engine, an instance goes through it: what was derived from it goes too.
    const derivedGoToo = state.frame.kind === 'INSTANCE' && state.session.inference;
    $('delete-question').textContent = 'Delete frame ' + state.frame.name + '?'
      + (derivedGoToo ? ' The instances derived from it go with it.' : '') + ' This cannot be undone.';
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
  $('prove-button').addEventListener('click', proveInference);
  $('why-not-button').addEventListener('click', whyNotInference);
  $('why-not-frame-button').addEventListener('click', async () => {
    const frame = state.frame.name;
    await openInference();
    if ($('inference-panel').hidden) return; // the unsaved changes were kept
    $('ask-class').value = frame;
    await whyNotInference();
  });
  $('import-apply').addEventListener('click', applyImport);
  $('world-button').addEventListener('click', openWorld);
  $('world-refresh').addEventListener('click', openWorld);
  $('chat-form').addEventListener('submit', say);
  $('teleop-robot').addEventListener('change', renderActions);
  $('teleop-action').addEventListener('change', renderArgs);
  $('teleop-form').addEventListener('submit', sendCommand);
  $('wrong-form').addEventListener('submit', markWrong);
  $('wrong-cancel').addEventListener('click', cancelWrong);
  window.addEventListener('resize', () => { if (worldVisible()) renderWorldSession(); });
  // The arrows follow the tree's boxes: redrawn when the tree is re-rendered (tree.js), resized or re-wrapped.
  $('link-legend').replaceChildren(...[['succession', 'succession'], ['synchronization', 'sync'],
    ['restriction', 'restriction'], ['named', 'named']].map(([kind, text]) => el('span', {}, swatch(kind), text)));
  $('show-links').addEventListener('change', drawLinks);
  new ResizeObserver(scheduleDrawLinks).observe($('tree'));
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
    const wanted = readAddress(location.hash);
    if (wanted.world) await openWorld();
    else if (wanted.frame && state.byName.has(wanted.frame)) await openFrame(wanted.frame);
  } catch (e) {
    $('login-error').textContent = e.message;
    $('login-error').hidden = false;
  }
  connect();
}

init();

// K-ICNP knowledge editor: the inference view: working memory, run, why, ask, trace.
// An ES module loaded by index.html; no build step, nothing from the network.
import { $, api, el, enc, showErrors, showMain, state } from './base.js';
import { openFrame } from './frame.js';

// ---- inference ----

let inferenceTimer = null;

// The errors shown come from the view's status (its reload: on opening, on refresh, on live events) or from a
// question (ask, prove, why-not, why, run). A question's error stays until the next question is answered, whatever
// reloads the status meanwhile — the reload that opening the view starts could come back after a question asked at
// once and hide its error — and a question answered after a later one was asked does not overwrite that one's outcome.
let errorsOf = null;
let asked = 0;
let shownFor = 0;

function statusOutcome(error) {
  if (error) {
    errorsOf = 'status';
    showErrors('inference-errors', error);
  } else if (errorsOf === 'status') {
    errorsOf = null;
    showErrors('inference-errors', null);
  }
}

/** Shows the outcome of question number `ticket` (its error, or none); false when a later question's is shown already. */
function questionOutcome(ticket, error) {
  if (ticket < shownFor) return false;
  shownFor = ticket;
  errorsOf = error ? 'question' : null;
  showErrors('inference-errors', error || null);
  return true;
}

export function scheduleInferenceReload() {
  clearTimeout(inferenceTimer);
  inferenceTimer = setTimeout(() => loadInference().catch(() => {}), 300);
}

export async function openInference() {
  if (state.dirty && !window.confirm('Discard the unsaved changes to ' + state.selected + '?')) return;
  state.dirty = false;
  showMain('inference-panel');
  await loadInference();
}

export async function loadInference() {
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
    const activations = s.activations || [];
    $('agenda-rows').replaceChildren(...(activations.length ? activations.map((a) => el('tr', {},
      el('td', {}, el('button', { type: 'button', class: 'chip', text: a.frame, onclick: () => openFrame(a.frame) })),
      el('td', { text: Object.entries(a.binding).map(([slot, inst]) => slot + ' = ' + inst).join(', ') }),
      el('td', { text: String(a.priority) }),
      el('td', { text: String(a.depth) }),
      el('td', { text: String(a.recency) })))
      : [el('tr', {}, el('td', { colspan: '5', class: 'muted', text: 'The agenda is empty.' }))]));
    statusOutcome(null);
  } catch (e) {
    statusOutcome(e);
  }
}

export async function runInference() {
  const ticket = ++asked;
  try {
    const r = await api('POST', '/api/inference/run', {});
    questionOutcome(ticket, null);
    await loadInference();
    $('inference-meta').textContent += ' · last run: ' + r.firings + ' firing(s)';
  } catch (e) {
    questionOutcome(ticket, e);
  }
}

async function why(instance) {
  const ticket = ++asked;
  try {
    const e = await api('GET', '/api/inference/why/' + enc(instance));
    if (questionOutcome(ticket, null)) $('why-tree').replaceChildren(el('ul', {}, explanationItem(e)));
  } catch (err) {
    if (questionOutcome(ticket, err)) $('why-tree').replaceChildren();
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

export async function askInference(event) {
  event.preventDefault();
  const ticket = ++asked;
  try {
    const answers = await api('GET', '/api/inference/ask?class=' + enc($('ask-class').value.trim()));
    if (!questionOutcome(ticket, null)) return;
    $('ask-answers').replaceChildren(...(answers.length ? answers.map((a) => el('li', {
      text: (a.instance || '(new ' + a.className + ')') + (a.derivable ? ' — derivable' : ' — exists')
        + (Object.keys(a.slots).length ? ': ' + Object.entries(a.slots).map(([k, v]) => k + '=' + v).join(', ') : '')
    })) : [el('li', { class: 'muted', text: 'No instance exists or could be derived.' })]));
  } catch (e) {
    refused(ticket, e);
  }
}

export async function proveInference() {
  const cls = $('ask-class').value.trim();
  if (!cls) return;
  const ticket = ++asked;
  try {
    const proofs = await api('GET', '/api/inference/prove?class=' + enc(cls));
    if (!questionOutcome(ticket, null)) return;
    $('ask-answers').replaceChildren(...(proofs.length ? proofs.map(proofItem)
      : [el('li', { class: 'muted', text: 'Nothing to prove: no instance exists or could be derived.' })]));
  } catch (e) {
    refused(ticket, e);
  }
}

/** Why the behavior frame named in the box has not fired: its slots' candidates, then each binding's outcome. */
export async function whyNotInference() {
  const frame = $('ask-class').value.trim();
  if (!frame) return;
  const ticket = ++asked;
  try {
    const w = await api('GET', '/api/inference/why-not?frame=' + enc(frame));
    if (!questionOutcome(ticket, null)) return;
    const slots = w.slots.map((s) => el('li', {},
      el('span', { class: 'what', text: s.slot }),
      el('span', { class: 'how', text: ' (' + s.argument + ', ' + s.condition + '): '
        + (s.candidates.length ? s.candidates.join(', ') : 'no candidate')
        + (s.candidateCount > s.candidates.length ? ' … and ' + (s.candidateCount - s.candidates.length) + ' more' : '') }),
      s.rejected.length ? el('ul', {}, s.rejected.map((r) => el('li', { class: 'muted', text: 'turned away: ' + r }))) : null));
    const bindings = w.bindings.map((b) => el('li', { class: 'why-not-' + b.outcome },
      el('span', { class: 'what', text: Object.entries(b.binding).map(([k, v]) => k + '=' + v).join(', ') }),
      el('span', { class: 'how', text: ' — ' + b.reason })));
    $('ask-answers').replaceChildren(el('li', { class: 'why-not-summary', text: w.summary }), ...slots, ...bindings);
  } catch (e) {
    refused(ticket, e);
  }
}

// A refused question: its error replaces the answers to the last one, which would read as answers to this one.
function refused(ticket, error) {
  if (questionOutcome(ticket, error)) $('ask-answers').replaceChildren();
}

function proofItem(p) {
  if (p.kind === 'exists') {
    return el('li', {}, el('span', { class: 'what', text: p.instance }),
      el('span', { class: 'how', text: ' exists (' + p.className + ')' }));
  }
  const slots = Object.entries(p.slots).map(([slot, sub]) => {
    const item = proofItem(sub);
    item.prepend(el('span', { class: 'how', text: slot + ': ' }));
    return item;
  });
  const assumed = p.assumptions.length ? ' assuming ' + p.assumptions.join('; ') : '';
  return el('li', {}, el('span', { class: 'what', text: '(new ' + p.className + ')' }),
    el('span', { class: 'how', text: ' derivable by ' + p.className + assumed }),
    slots.length ? el('ul', {}, slots) : null);
}

export function addTrace(event) {
  const log = $('trace-log');
  log.append(el('li', { class: event.event }, el('span', { class: 'ev', text: event.event }), ' ', event.text));
  while (log.children.length > 300) log.firstChild.remove();
  log.scrollTop = log.scrollHeight;
}

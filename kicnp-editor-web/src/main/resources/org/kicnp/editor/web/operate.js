// K-ICNP knowledge editor: the World panel's controls: the chat (a person speaking as User A to the robots, the
// parser's verdict, the robots' replies), tele-operation (a command by hand, its feedback), stopping a command under
// way and "this action was wrong". An ES module loaded by index.html; no build step, nothing from the network.
import { $, api, el, enc, showErrors, state } from './base.js';

let robots = [];
const commands = new Map();
let wrongTarget = null;

// ---- chat ----

export async function loadChat() {
  const r = await api('GET', '/api/chat');
  $('chat-log').replaceChildren();
  r.lines.forEach(chatLine);
}

const KIND_LABEL = { understood: 'understood', not_understood: 'say it again', system: 'platform' };

export function chatLine(line) {
  const log = $('chat-log');
  const item = el('li', { class: 'chat-' + line.kind },
    KIND_LABEL[line.kind] ? el('span', { class: 'verdict', text: KIND_LABEL[line.kind] + ': ' })
      : el('span', { class: 'who', text: line.speaker }),
    el('span', { class: 'said', text: line.text }));
  log.append(item);
  while (log.children.length > 200) log.firstChild.remove();
  log.scrollTop = log.scrollHeight;
}

export async function say(event) {
  event.preventDefault();
  const input = $('chat-text');
  const text = input.value.trim();
  if (!text) return;
  try {
    await api('POST', '/api/chat', { speaker: 'User A', text });
    input.value = '';
    showErrors('chat-errors', null);
  } catch (e) {
    showErrors('chat-errors', e);
  }
  input.focus();
}

// ---- tele-operation ----

export async function loadRobots() {
  robots = await api('GET', '/api/robots');
  const select = $('teleop-robot');
  const before = select.value;
  select.replaceChildren(...robots.map((r) => el('option', { value: r.name, text: r.name + (r.kind ? ' (' + r.kind + ')' : '') })));
  if (robots.some((r) => r.name === before)) select.value = before;
  renderActions();
}

export function renderActions() {
  const robot = robots.find((r) => r.name === $('teleop-robot').value);
  const select = $('teleop-action');
  const before = select.value;
  select.replaceChildren(...(robot ? robot.actions : []).map((a) => el('option', { value: a.name, text: a.name })));
  if (robot && robot.actions.some((a) => a.name === before)) select.value = before;
  renderArgs();
}

export function renderArgs() {
  const robot = robots.find((r) => r.name === $('teleop-robot').value);
  const action = robot && robot.actions.find((a) => a.name === $('teleop-action').value);
  $('teleop-doc').textContent = action ? action.doc : '';
  $('teleop-args').replaceChildren(...(action ? action.args : []).map((a) => el('div', { class: 'arg' },
    el('label', { for: 'arg-' + a.name, text: a.name + (a.required ? ' *' : '') }),
    el('input', { id: 'arg-' + a.name, dataset: { arg: a.name }, required: a.required,
      placeholder: a.type, inputmode: a.type === 'number' ? 'decimal' : undefined }))));
}

export async function sendCommand(event) {
  event.preventDefault();
  const robot = $('teleop-robot').value;
  const args = {};
  for (const input of $('teleop-args').querySelectorAll('input[data-arg]')) {
    if (input.value.trim()) args[input.dataset.arg] = input.value.trim();
  }
  try {
    const row = await api('POST', '/api/robots/' + enc(robot) + '/commands', { action: $('teleop-action').value, args });
    feedbackEvent(row);
    showErrors('teleop-errors', null);
  } catch (e) {
    showErrors('teleop-errors', e);
  }
}

// ---- recent commands, their feedback, "stop", "wrong" ----

export async function loadCommands() {
  const rows = await api('GET', '/api/commands');
  commands.clear();
  rows.reverse().forEach((r) => commands.set(r.id, r));
  renderCommands();
}

/** A `feedback` event (or the answer to a send): the command's row as it now is. */
export function feedbackEvent(row) {
  const known = commands.get(row.id);
  // An answer (to a send, a stop, a "wrong") can be overtaken by the command's feedback, or the other way round:
  // keep the copy the server changed last (its rev), so a row never goes back.
  if (known && known.rev > row.rev) return;
  commands.delete(row.id);
  commands.set(row.id, { ...known, ...row });
  while (commands.size > 50) commands.delete(commands.keys().next().value);
  renderCommands();
}

function renderCommands() {
  const rows = [...commands.values()].reverse();
  const canJudge = state.session.loggedIn;
  $('command-rows').replaceChildren(...(rows.length ? rows.map((c) => el('tr', { dataset: { command: c.id } },
    el('td', {}, el('span', { class: 'cmd-robot', text: c.robot }), ' ', el('span', { class: 'cmd-action', text: c.action }),
      Object.keys(c.args || {}).length ? el('span', { class: 'muted small-text', text: ' ' + Object.entries(c.args)
        .map(([k, v]) => k + '=' + v).join(' ') }) : null,
      el('div', { class: 'muted small-text', text: c.id })),
    el('td', {}, el('span', { class: 'cmd-status status-' + c.status, text: c.status }),
      c.detail ? el('div', { class: 'small-text detail', text: c.detail }) : null,
      c.stop ? el('div', { class: 'small-text stop-note', text: 'stop asked: ' + c.stop }) : null,
      c.wrong ? el('div', { class: 'small-text wrong-note', text: 'marked wrong: ' + c.wrong }) : null),
    el('td', {}, canJudge && !c.stop && (c.status === 'sent' || c.status === 'started')
      ? el('button', { type: 'button', class: 'small danger', text: 'Stop',
        'aria-label': 'Stop command ' + c.id + ' (' + c.action + ' of ' + c.robot + ')',
        onclick: () => stopCommand(c.id) }) : null,
    canJudge && !c.wrong ? el('button', { type: 'button', class: 'small ghost danger', text: 'Wrong',
      'aria-label': 'Mark command ' + c.id + ' (' + c.action + ' of ' + c.robot + ') as wrong',
      onclick: () => startWrong(c.id, c.action + ' of ' + c.robot) }) : null)))
    : [el('tr', {}, el('td', { colspan: '3', class: 'muted', text: 'No commands yet.' }))]));
}

/** Stops a command under way at once (no question asked, as an emergency stop); its feedback follows. */
export async function stopCommand(id) {
  try {
    feedbackEvent(await api('POST', '/api/actions/' + enc(id) + '/stop', {}));
    showErrors('teleop-errors', null);
  } catch (e) {
    showErrors('teleop-errors', e);
  }
}

export function startWrong(id, what) {
  wrongTarget = id;
  $('wrong-question').textContent = 'Why was ' + what + ' (' + id + ') wrong?';
  $('wrong-form').hidden = false;
  $('wrong-reason').value = '';
  showErrors('wrong-errors', null);
  $('wrong-reason').focus();
}

export async function markWrong(event) {
  event.preventDefault();
  try {
    const row = await api('POST', '/api/actions/' + enc(wrongTarget) + '/wrong', { reason: $('wrong-reason').value.trim() });
    feedbackEvent(row);
    $('wrong-form').hidden = true;
  } catch (e) {
    showErrors('wrong-errors', e);
  }
}

export function cancelWrong() {
  $('wrong-form').hidden = true;
}

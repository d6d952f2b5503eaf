// K-ICNP knowledge editor: the World panel's room view: the simulated room drawn live on a canvas, and the
// robot list (each robot's state and current actions). Snapshots come from GET /api/world and `world` events.
// An ES module loaded by index.html; no build step, nothing from the network.
import { $, WORLD_ADDRESS, api, el, showErrors, showMain, state } from './base.js';
import { loadCommands, loadChat, loadRobots, startWrong, stopCommand } from './operate.js';

const COLORS = { humanoid: '#1f5fbf', mobile: '#0e9384', quadruped: '#b54708' };
const RADIUS = { humanoid: 0.3, mobile: 0.2, quadruped: 0.22 };
let latest = null;
let drawPending = false;

export function worldVisible() {
  return !$('world-panel').hidden;
}

export async function openWorld() {
  if (state.dirty && !window.confirm('Discard the unsaved changes to ' + state.selected + '?')) return;
  state.dirty = false;
  showMain('world-panel');
  history.replaceState(null, '', WORLD_ADDRESS);
  renderWorldSession();
  const s = state.session;
  try {
    if (s.world) {
      const snapshot = await api('GET', '/api/world');
      if (snapshot) latest = snapshot;
      scheduleDraw();
    }
    await Promise.all([s.chat ? loadChat() : null, s.teleOperation ? loadRobots() : null,
      s.teleOperation ? loadCommands() : null]);
    showErrors('world-errors', null);
  } catch (e) {
    showErrors('world-errors', e);
  }
}

// Which parts of the panel work: a port the platform did not give shows "not connected" instead.
export function renderWorldSession() {
  const s = state.session;
  const parts = [['world', 'world-view', s.world], ['chat', 'chat-box', s.chat],
    ['teleop', 'teleop-box', s.teleOperation]];
  for (const [name, box, on] of parts) {
    $(box).hidden = !on;
    $(name + '-off').hidden = !!on;
  }
  $('world-meta').textContent = s.world || s.chat || s.teleOperation
    ? 'Connected to the platform.' : 'This editor is not connected to a platform.';
  const canAct = s.loggedIn;
  $('chat-text').disabled = !canAct;
  $('chat-send').disabled = !canAct;
  $('teleop-send').disabled = !canAct;
  $('chat-login').hidden = canAct;
  $('teleop-login').hidden = canAct;
  if (latest) scheduleDraw();
}

/** A `world` event: keep the snapshot, draw it on the next animation frame when the panel is shown. */
export function worldEvent(event) {
  latest = event.snapshot;
  if (worldVisible()) scheduleDraw();
}

function scheduleDraw() {
  if (drawPending) return;
  drawPending = true;
  requestAnimationFrame(() => {
    drawPending = false;
    draw();
    renderRobots();
  });
}

function draw() {
  const canvas = $('world-canvas');
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth;
  const height = canvas.clientHeight;
  if (!width || !height) return;
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  const g = canvas.getContext('2d');
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  g.clearRect(0, 0, width, height);
  if (!latest) {
    g.fillStyle = '#667085';
    g.font = '14px system-ui, sans-serif';
    g.textAlign = 'center';
    g.fillText('Waiting for the first picture of the room…', width / 2, height / 2);
    $('world-time').textContent = '';
    return;
  }
  const room = latest.room;
  const margin = 28;
  const scale = Math.min((width - 2 * margin) / room.width, (height - 2 * margin) / room.height);
  const ox = (width - room.width * scale) / 2;
  const oy = (height - room.height * scale) / 2;
  const X = (x) => ox + x * scale;
  const Y = (y) => oy + (room.height - y) * scale;

  // floor and a one-metre grid
  g.fillStyle = '#fbfcfd';
  g.fillRect(X(0), Y(room.height), room.width * scale, room.height * scale);
  g.strokeStyle = '#edf0f4';
  g.lineWidth = 1;
  g.fillStyle = '#98a2b3';
  g.font = '10px system-ui, sans-serif';
  for (let x = 1; x < room.width; x++) line(g, X(x), Y(0), X(x), Y(room.height));
  for (let y = 1; y < room.height; y++) line(g, X(0), Y(y), X(room.width), Y(y));
  g.textAlign = 'center';
  for (let x = 0; x <= room.width; x += 2) {
    if (room.door.y > 0.01 || Math.abs(x - room.door.x) > 0.8) g.fillText(x + ' m', X(x), Y(0) + 14);
  }

  // walls with the door gap (on whichever wall the door is), the counter, obstacles
  drawWalls(g, room, X, Y);
  const c = room.counter;
  g.fillStyle = '#f2e6d3';
  g.strokeStyle = '#b08a5a';
  g.lineWidth = 1.5;
  g.fillRect(X(c.x0), Y(c.y1), (c.x1 - c.x0) * scale, (c.y1 - c.y0) * scale);
  g.strokeRect(X(c.x0), Y(c.y1), (c.x1 - c.x0) * scale, (c.y1 - c.y0) * scale);
  g.save();
  g.translate(X((c.x0 + c.x1) / 2) + 14, Y((c.y0 + c.y1) / 2));
  g.rotate(-Math.PI / 2);
  g.fillStyle = '#7a5a32';
  g.fillText('counter', 0, 0);
  g.restore();
  for (const o of latest.obstacles) {
    g.fillStyle = '#d0d5dd';
    g.fillRect(X(o.x - o.w / 2), Y(o.y + o.h / 2), o.w * scale, o.h * scale);
  }

  // cups, users, robots
  for (const cup of latest.cups) {
    circle(g, X(cup.x), Y(cup.y), Math.max(4, 0.07 * scale), cup.kind === 'coffee' ? '#7a4b2a' : '#12b76a', '#fff');
  }
  for (const u of latest.users) {
    circle(g, X(u.x), Y(u.y), 0.25 * scale, '#f79009', '#fff');
    heading(g, X(u.x), Y(u.y), 0.25 * scale, u.headingDeg, '#fff');
    label(g, u.name, X(u.x), Y(u.y) + 0.25 * scale + 13, '#93370d');
  }
  for (const r of latest.robots) {
    const radius = (RADIUS[r.kind] || 0.25) * scale;
    const color = COLORS[r.kind] || '#475467';
    if (r.actions.length) circle(g, X(r.x), Y(r.y), radius + 4, 'rgba(31,95,191,0.15)', null);
    circle(g, X(r.x), Y(r.y), radius, color, '#fff');
    heading(g, X(r.x), Y(r.y), radius, r.headingDeg, '#fff');
    label(g, r.name, X(r.x), Y(r.y) - radius - 6, '#1d2430', 'bold 12px system-ui, sans-serif');
    if (r.actions.length) {
      pill(g, r.actions.map((a) => a.action).join(', '), X(r.x), Y(r.y) + radius + 13);
    }
  }
  $('world-time').textContent = 't = ' + latest.time.toFixed(1) + ' s';
}

function drawWalls(g, room, X, Y) {
  const w = room.width;
  const h = room.height;
  const d = room.door;
  const half = 0.45;
  const walls = { S: [[0, 0], [w, 0]], E: [[w, 0], [w, h]], N: [[w, h], [0, h]], W: [[0, h], [0, 0]] };
  const doorWall = d.y <= 0.01 ? 'S' : d.y >= h - 0.01 ? 'N' : d.x <= 0.01 ? 'W' : 'E';
  g.strokeStyle = '#344054';
  g.lineWidth = 4;
  g.lineCap = 'square';
  for (const [name, [a, b]] of Object.entries(walls)) {
    if (name !== doorWall) {
      line(g, X(a[0]), Y(a[1]), X(b[0]), Y(b[1]));
      continue;
    }
    const along = name === 'S' || name === 'N' ? 0 : 1;
    const at = along === 0 ? d.x : d.y;
    const lo = a[along] < b[along] ? a : b;
    const hi = a[along] < b[along] ? b : a;
    const gapLo = [...lo];
    const gapHi = [...hi];
    gapLo[along] = at - half;
    gapHi[along] = at + half;
    line(g, X(lo[0]), Y(lo[1]), X(gapLo[0]), Y(gapLo[1]));
    line(g, X(gapHi[0]), Y(gapHi[1]), X(hi[0]), Y(hi[1]));
  }
  g.lineCap = 'butt';
  const offset = { S: [0, 14], N: [0, -8], W: [-16, 4], E: [16, 4] }[doorWall];
  g.fillStyle = '#667085';
  g.font = '11px system-ui, sans-serif';
  g.textAlign = 'center';
  g.fillText('door', X(d.x) + offset[0], Y(d.y) + offset[1]);
}

function line(g, x0, y0, x1, y1) {
  g.beginPath();
  g.moveTo(x0, y0);
  g.lineTo(x1, y1);
  g.stroke();
}

function circle(g, x, y, r, fill, stroke) {
  g.beginPath();
  g.arc(x, y, r, 0, 2 * Math.PI);
  g.fillStyle = fill;
  g.fill();
  if (stroke) {
    g.strokeStyle = stroke;
    g.lineWidth = 1.5;
    g.stroke();
  }
}

function heading(g, x, y, r, deg, color) {
  const a = -deg * Math.PI / 180;
  g.strokeStyle = color;
  g.lineWidth = 2.5;
  line(g, x, y, x + Math.cos(a) * r, y + Math.sin(a) * r);
}

function label(g, text, x, y, color, font) {
  g.font = font || '11px system-ui, sans-serif';
  g.textAlign = 'center';
  g.lineWidth = 3;
  g.strokeStyle = 'rgba(255,255,255,0.9)';
  g.strokeText(text, x, y);
  g.fillStyle = color;
  g.fillText(text, x, y);
}

function pill(g, text, x, y) {
  g.font = '11px system-ui, sans-serif';
  const w = g.measureText(text).width + 10;
  g.fillStyle = '#1f5fbf';
  g.beginPath();
  g.roundRect(x - w / 2, y - 10, w, 15, 7);
  g.fill();
  g.fillStyle = '#fff';
  g.textAlign = 'center';
  g.fillText(text, x, y + 1);
}

let robotsShown = '';

// Rebuilt only when something in it changed, so a focused "Stop" or "Wrong" button keeps its focus while the robots
// move.
function renderRobots() {
  if (!latest) return;
  const canJudge = state.session.loggedIn && state.session.teleOperation;
  const shown = JSON.stringify([canJudge, latest.robots.map((r) => [r.name, r.kind, r.actions, r.state]),
    latest.users.map((u) => u.name), latest.cups.map((c) => c.holder)]);
  if (shown === robotsShown) return;
  robotsShown = shown;
  $('robot-rows').replaceChildren(...latest.robots.map((r) => el('tr', { dataset: { robot: r.name } },
    el('th', { scope: 'row' }, el('i', { class: 'swatch kind-' + (COLORS[r.kind] ? r.kind : 'other') }),
      r.name),
    el('td', { text: r.kind }),
    el('td', {}, r.actions.length ? r.actions.map((a) => el('span', { class: 'action-chip' }, a.action,
      el('span', { class: 'muted', text: ' ' + a.part + ' · ' + a.id }),
      canJudge ? el('button', { type: 'button', class: 'small danger', text: 'Stop',
        'aria-label': 'Stop action ' + a.id + ' (' + a.action + ' of ' + r.name + ')',
        onclick: () => stopCommand(a.id) }) : null,
      canJudge ? el('button', { type: 'button', class: 'small ghost danger', text: 'Wrong',
        'aria-label': 'Mark action ' + a.id + ' (' + a.action + ' of ' + r.name + ') as wrong',
        onclick: () => startWrong(a.id, a.action + ' of ' + r.name) }) : null))
      : el('span', { class: 'muted', text: 'idle' })),
    el('td', { class: 'small-text', text: r.state || '—' }))));
  const people = latest.users.map((u) => u.name).join(', ');
  const held = latest.cups.filter((c) => c.holder).map((c) => c.name + ' (' + c.holder + ')').join(', ');
  $('world-legend-text').textContent = (people ? 'People: ' + people + '. ' : 'Nobody in the room. ')
    + (held ? 'Cups held: ' + held + '.' : 'All cups on the counter.');
}

// The panels beside the drawing: counters, the last decisions, the device table and the fabric's tables (the nodes'
// in nodes.js).
// Each is rebuilt only when its part of the model changed; the device table shows the devices in trouble first
// and at most ROWS of them, so that a fleet of a thousand robots costs the page no more than a few dozen rows.
import { value } from './model.js';
import { renderNodes } from './nodes.js';

const ROWS = 60;
const COUNTERS = {
  cartsDelivered: 'carts delivered', cartsLifted: 'carts lifted', doorOpenings: 'door openings',
  robotInFront: 'robot in front detected', robotInFrontResolved: 'robot in front resolved',
  doorInFront: 'closed door in front', commandsSent: 'commands sent', commandsRefused: 'commands refused',
  missionsFinished: 'missions finished', missionsFailed: 'missions failed',
  unreachableEvents: 'devices lost', behavioursInstalled: 'behaviours installed (BMS)',
};
const TROUBLE = { UNREACHABLE: 0, STALE: 1, OK: 2 };

export function renderPanels(model) {
  counters(model.counters);
  decisions(model.decisions);
  fabric(model.fabric);
}

function counters(values) {
  const dl = document.getElementById('counters');
  for (const [key, label] of Object.entries(COUNTERS)) {
    let dd = dl.querySelector(`dd[data-counter="${key}"]`);
    if (!dd) {
      const dt = document.createElement('dt');
      dt.textContent = label;
      dd = document.createElement('dd');
      dd.dataset.counter = key;
      dd.id = `counter-${key}`;
      dl.append(dt, dd);
    }
    const text = String(values[key] ?? 0);
    if (dd.textContent !== text) dd.textContent = text;
  }
}

function decisions(list) {
  rows('decisions', [...list].reverse().slice(0, 15), d => {
    const tr = row([`${d.command || '?'}${params(d.params)}`, d.deviceId || '', d.outcome
      + (d.reason ? `: ${d.reason}` : '')]);
    tr.dataset.commandId = d.commandId;
    tr.dataset.outcome = d.outcome;
    if (d.outcome === 'refused') tr.className = 'refused';
    return tr;
  });
}

function params(p) {
  if (!p || !Object.keys(p).length) return '';
  return ` (${Object.entries(p).map(([k, v]) => `${k}=${v}`).join(', ')})`;
}

export function renderDevices(model) {
  // the model keeps devices in id order (the snapshot's, then new ones): no sort, only those in trouble first
  const trouble = [], ok = [];
  for (const d of model.devices.values()) {
    if (d.kind !== 'robot' && d.kind !== 'door') continue;
    (d.status === 'OK' ? ok : trouble).push(d);
  }
  trouble.sort((a, b) => TROUBLE[a.status] - TROUBLE[b.status]);
  const all = trouble.length + ok.length;
  document.getElementById('device-summary').textContent =
    `${all} devices, ${trouble.length} stale or unreachable` + (all > ROWS ? `; ${ROWS} shown, in trouble first` : '');
  const shown = trouble.concat(ok.slice(0, Math.max(0, ROWS - trouble.length))).slice(0, ROWS);
  const body = document.querySelector('#devices tbody');
  while (body.rows.length > shown.length) body.deleteRow(-1);
  shown.forEach((d, i) => {
    const tr = body.rows[i] || body.insertRow();
    const x = value(d, 'position', 'x'), y = value(d, 'position', 'y');
    const mission = value(d, 'mission', 'type');
    fill(tr, [d.id, d.status === 'OK' ? 'ok' : `${d.status.toLowerCase()}${d.reason ? `: ${d.reason}` : ''}`,
      `(${x}, ${y})`, value(d, 'position', 'heading') || '',
      value(d, 'state', 'state') || value(d, 'door', 'state') || '', value(d, 'state', 'obstacle') || '',
      value(d, 'cart', 'cart') || '', mission ? `${mission} ${value(d, 'mission', 'state')}` : '']);
    const data = { device: d.id, kind: d.kind, status: d.status, x: String(x), y: String(y) };
    for (const k in data) if (tr.dataset[k] !== data[k]) tr.dataset[k] = data[k];
  });
}

/** Sets a row's cells in place, touching only the text that changed (a rebuilt row costs layout). */
function fill(tr, cells) {
  while (tr.cells.length < cells.length) tr.insertCell();
  cells.forEach((c, i) => {
    const text = c == null ? '' : String(c);
    if (tr.cells[i].textContent !== text) tr.cells[i].textContent = text;
  });
}

function fabric(f) {
  renderNodes(f.nodes);
  rows('behaviours', f.behaviours || [], b => row([b.symbolicName, b.version, b.state,
    new Date(b.installedAt).toLocaleTimeString(), b.reason || '']));
  rows('bms-history', [...(f.bmsHistory || [])].reverse(), h => row([new Date(h.time).toLocaleTimeString(), h.kind,
    h.behaviour || '', (h.eventTypes || []).map(short).join(', '), h.durationMs]));
  const types = [...(f.eventTypes || [])].sort((a, b) => b.published - a.published).slice(0, 25);
  rows('event-types', types, t => {
    const tr = row([short(t.eventType), t.published, t.delivered, t.failed, t.unhandled, t.held]);
    tr.title = t.eventType;
    tr.dataset.eventType = t.eventType;
    return tr;
  });
}

function short(type) {
  return type ? type.substring(type.lastIndexOf('.') + 1) : '';
}

function row(cells) {
  const tr = document.createElement('tr');
  for (const c of cells) {
    const td = document.createElement('td');
    td.textContent = c == null ? '' : String(c);
    if (typeof c === 'number') td.className = 'num';
    tr.append(td);
  }
  return tr;
}

const EMPTY = { decisions: 'no command yet', behaviours: 'none installed (or no installer on this node)',
  'bms-history': 'nothing yet', 'event-types': 'no event yet' };

function rows(tableId, items, make) {
  const body = document.querySelector(`#${tableId} tbody`);
  if (!items.length && EMPTY[tableId]) {
    const tr = row([EMPTY[tableId]]);
    tr.className = 'empty';
    tr.cells[0].colSpan = 8;
    body.replaceChildren(tr);
    return;
  }
  body.replaceChildren(...items.map(make));
}

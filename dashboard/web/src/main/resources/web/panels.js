// The panels beside the drawing: counters, the last decisions, the device table and the fabric's tables.
// Each is rebuilt only when its part of the model changed; the device table shows the devices in trouble first
// and at most ROWS of them, so that a fleet of a thousand robots costs the page no more than a few dozen rows.
import { value } from './model.js';

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
  const all = [...model.devices.values()].filter(d => d.kind === 'robot' || d.kind === 'door');
  const trouble = all.filter(d => d.status !== 'OK').length;
  document.getElementById('device-summary').textContent =
    `${all.length} devices, ${trouble} stale or unreachable` + (all.length > ROWS ? `; ${ROWS} shown, in trouble first` : '');
  all.sort((a, b) => (TROUBLE[a.status] - TROUBLE[b.status]) || a.id.localeCompare(b.id, 'en', { numeric: true }));
  rows('devices', all.slice(0, ROWS), d => {
    const x = value(d, 'position', 'x'), y = value(d, 'position', 'y');
    const mission = value(d, 'mission', 'type');
    const tr = row([d.id, d.status === 'OK' ? 'ok' : `${d.status.toLowerCase()}${d.reason ? `: ${d.reason}` : ''}`,
      `(${x}, ${y})`, value(d, 'position', 'heading') || '',
      value(d, 'state', 'state') || value(d, 'door', 'state') || '', value(d, 'state', 'obstacle') || '',
      value(d, 'cart', 'cart') || '', mission ? `${mission} ${value(d, 'mission', 'state')}` : '']);
    Object.assign(tr.dataset, { device: d.id, kind: d.kind, status: d.status, x, y });
    return tr;
  });
}

function fabric(f) {
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

function rows(tableId, items, make) {
  const body = document.querySelector(`#${tableId} tbody`);
  body.replaceChildren(...items.map(make));
}

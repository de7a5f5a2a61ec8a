// The "Nodes" panel: this node and every other node of its fabric (the federation's FabricMonitor, under
// fabric.nodes), with presence and counters. Names and event types come from other nodes over the network: they
// are only ever set as text (textContent, title), never as markup. A node without a fabric has no such panel.

const COLUMNS = ['node', 'status', 'since', 'behaviours', 'consumes', 'sent', 'resent', 'acked', 'backlog',
  'received', 'duplicates', 'refused', 'installed'];
const TYPES_SHOWN = 6;
const NUMERIC = new Set(['behaviours', 'sent', 'resent', 'acked', 'backlog', 'received', 'duplicates', 'refused',
  'installed']);

export function renderNodes(status) {
  const panel = document.getElementById('nodes-panel');
  if (!status) {
    panel.hidden = true;
    return;
  }
  panel.hidden = false;
  const table = document.getElementById('nodes');
  if (!table.tHead.rows.length) header(table);
  const remotes = status.remotes || [];
  const online = remotes.filter(r => r.status === 'online').length;
  document.getElementById('nodes-summary').textContent = `fabric ${status.fabric}, broker ${status.brokerUri}; `
    + `${online} of ${remotes.length} other node${remotes.length === 1 ? '' : 's'} online`
    + (status.problem ? `; this node does not join: ${status.problem}` : '');
  const rows = [self(status), ...remotes.map(remote)];
  const body = table.tBodies[0];
  while (body.rows.length > rows.length) body.deleteRow(-1);
  rows.forEach((r, i) => {
    const tr = body.rows[i] || body.insertRow();
    while (tr.cells.length < COLUMNS.length) {
      const td = tr.insertCell();
      if (NUMERIC.has(COLUMNS[tr.cells.length - 1])) td.className = 'num';
    }
    COLUMNS.forEach((c, k) => {
      const text = r.cells[c] == null ? '' : String(r.cells[c]);
      if (tr.cells[k].textContent !== text) tr.cells[k].textContent = text;
    });
    tr.cells[COLUMNS.indexOf('consumes')].title = r.types.join('\n');
    const data = { node: r.name, status: r.status, self: String(r.self) };
    for (const k in data) if (tr.dataset[k] !== data[k]) tr.dataset[k] = data[k];
  });
}

function header(table) {
  const tr = table.tHead.insertRow();
  for (const c of COLUMNS) {
    const th = document.createElement('th');
    th.textContent = c;
    if (NUMERIC.has(c)) th.className = 'num';
    tr.append(th);
  }
}

function self(s) {
  return { name: s.node, status: s.state, self: true, types: s.eventTypes || [], cells: {
    node: `${s.node} (this node)`, status: s.state, since: time(s.since), behaviours: s.interestEntries,
    consumes: types(s.eventTypes), installed: s.installedBehaviours } };
}

function remote(r) {
  return { name: r.name, status: r.status, self: false, types: r.eventTypes || [], cells: {
    node: r.name, status: r.status, since: time(r.since), behaviours: r.interestEntries, consumes: types(r.eventTypes),
    sent: r.sent, resent: r.resent, acked: r.acknowledged, backlog: r.backlog, received: r.received,
    duplicates: r.duplicates, refused: r.refused, installed: r.installedBehaviours } };
}

function time(ms) {
  return ms ? new Date(ms).toLocaleTimeString() : '';
}

/**
 * At most TYPES_SHOWN short names (after the last dot), sorted, and how many more: a node's dashboard alone consumes
 * twenty types. Every full name is in the cell's title.
 */
function types(list) {
  const short = (list || []).map(t => t.substring(t.lastIndexOf('.') + 1)).sort();
  const more = short.length - TYPES_SHOWN;
  return short.slice(0, TYPES_SHOWN).join(', ') + (more > 0 ? ` (+${more} more)` : '');
}

// The live dashboard: loads a snapshot, then follows the node's event stream (no polling). When the stream
// breaks (the node stopped, a network hiccup), it reconnects by itself with the id of the last event it applied:
// the node replays what was missed or, when it cannot (it restarted), sends a fresh snapshot first.
import { Model } from './model.js';
import { Drawing } from './draw.js';
import { renderPanels, renderDevices } from './panels.js';

const model = new Model();
const drawing = new Drawing(document.getElementById('map'));
const connection = document.getElementById('connection');
const eventIdLabel = document.getElementById('event-id');
let source = null;
let retryMs = 500;
let frameRequested = false;

// Work per second of the page, for the benchmark: the time spent applying events and drawing them.
const perf = { seconds: [], current: null, events: 0, rasterise: false };
function account(kind, ms) {
  const second = Math.floor(performance.now() / 1000);
  if (!perf.current || perf.current.second !== second) {
    if (perf.current) perf.seconds.push(perf.current);
    if (perf.seconds.length > 600) perf.seconds.shift();
    perf.current = { second, applyMs: 0, drawMs: 0, canvasMs: 0, tableMs: 0, panelsMs: 0, events: 0, devices: 0,
      frames: 0 };
  }
  perf.current[kind] += ms;
}

function setConnection(state, text) {
  connection.dataset.state = state;
  connection.textContent = text;
}

function render() {
  frameRequested = false;
  const t0 = performance.now();
  if (model.devicesChanged) {
    drawing.draw(model);
    if (perf.rasterise) drawing.rasterise(); // the benchmark counts the canvas's painting too, not only its commands
    const t1 = performance.now();
    account('canvasMs', t1 - t0);
    renderDevices(model);
    account('tableMs', performance.now() - t1);
    model.devicesChanged = false;
  }
  if (model.panelsChanged) {
    const t2 = performance.now();
    renderPanels(model);
    account('panelsMs', performance.now() - t2);
    model.panelsChanged = false;
  }
  eventIdLabel.textContent = model.eventId ? `event ${model.eventId}` : '';
  account('drawMs', performance.now() - t0);
  perf.current.frames++;
}

function changed() {
  if (!frameRequested) {
    frameRequested = true;
    requestAnimationFrame(render);
  }
}

function onSnapshot(e) {
  const t0 = performance.now();
  model.load(JSON.parse(e.data));
  account('applyMs', performance.now() - t0);
  changed();
}

function onDelta(e) {
  const t0 = performance.now();
  const delta = JSON.parse(e.data);
  model.apply(delta, e.lastEventId);
  account('applyMs', performance.now() - t0);
  perf.current.events++;
  perf.current.devices += delta.devices.length;
  perf.events++;
  changed();
}

// When the node is exposed beyond loopback its API answers 401 until this browser has a session: a form takes the
// token and POSTs it (as a bearer token, with a JSON body, as the node's gate demands of every POST) to the node's
// session endpoint, which answers with an HttpOnly cookie that the page's requests and its stream then carry.
const login = document.getElementById('login');
const loginToken = document.getElementById('login-token');
const loginError = document.getElementById('login-error');

function showLogin(message) {
  if (source) { source.close(); source = null; }
  setConnection('login', 'log in');
  loginError.textContent = message || '';
  login.hidden = false;
  loginToken.focus();
}

login.addEventListener('submit', async (e) => {
  e.preventDefault();
  loginError.textContent = '';
  try {
    const answer = await fetch('/sensinact/session', {
      method: 'POST', cache: 'no-store', credentials: 'same-origin',
      headers: { 'Authorization': `Bearer ${loginToken.value.trim()}`, 'Content-Type': 'application/json' },
      body: '{}',
    });
    if (!answer.ok) {
      const error = await answer.json().catch(() => ({}));
      showLogin(answer.status === 401 ? 'wrong token' : (error.error || `the node answered ${answer.status}`));
      return;
    }
    loginToken.value = '';
    login.hidden = true;
    start();
  } catch (err) {
    showLogin(`the node did not answer (${err.message})`);
  }
});

function connect() {
  const url = 'api/stream' + (model.eventId ? `?lastEventId=${encodeURIComponent(model.eventId)}` : '');
  source = new EventSource(url);
  source.addEventListener('snapshot', onSnapshot);
  source.addEventListener('delta', onDelta);
  source.onopen = () => { retryMs = 500; setConnection('live', 'live'); };
  source.onerror = () => {
    // CONNECTING: the browser retries by itself, sending Last-Event-ID. CLOSED: it gave up (the node answered
    // with an error while starting, say): start again ourselves, with the last id we applied.
    if (source.readyState === EventSource.CLOSED) {
      setConnection('reconnecting', `reconnecting in ${Math.round(retryMs / 100) / 10} s…`);
      source.close();
      setTimeout(reconnect, retryMs);
      retryMs = Math.min(retryMs * 2, 5000);
    } else {
      setConnection('reconnecting', 'reconnecting…');
    }
  };
}

// An EventSource hides its error's status: ask once whether the session ended (the node restarted, or it expired).
async function reconnect() {
  try {
    const answer = await fetch('api/snapshot', { method: 'HEAD', cache: 'no-store' });
    if (answer.status === 401) { showLogin('the session ended: log in again'); return; }
  } catch (e) {
    // the node is down: the stream's retry below says so
  }
  connect();
}

async function start() {
  try {
    const answer = await fetch('api/snapshot', { cache: 'no-store' });
    if (answer.status === 401) { showLogin(); return; }
    if (answer.ok) onSnapshot({ data: await answer.text() });
  } catch (e) {
    // the stream sends a snapshot too: go on
  }
  connect();
}

// For tests and the benchmark: what the page holds and drew, read with executeScript.
window.dashboard = {
  model,
  scene: () => drawing.scene,
  connection: () => connection.dataset.state,
  perf,
};

start();

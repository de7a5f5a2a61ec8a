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
      setTimeout(connect, retryMs);
      retryMs = Math.min(retryMs * 2, 5000);
    } else {
      setConnection('reconnecting', 'reconnecting…');
    }
  };
}

async function start() {
  try {
    const answer = await fetch('api/snapshot', { cache: 'no-store' });
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

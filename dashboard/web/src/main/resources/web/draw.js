// Draws the warehouse on a canvas: the map (walls and areas, once the edge has it as a provider of kind
// "warehouse"; until then a grid as large as the devices need), each door, each cart, each robot with its heading.
// The static part is drawn once into an off-screen canvas; a frame copies it and draws the devices.
import { value } from './model.js';

const AREA_COLOURS = { '#': '#37474f', 'd': '#e3f2fd', 'R': '#e3f2fd', 's': '#e8f5e9', 'u': '#fff8e1', 'C': '#fff8e1',
  '.': '#ffffff', 'D': '#ffffff' };
const DOOR_COLOURS = { open: '#66bb6a', opening: '#ffb300', closing: '#ffb300', closed: '#c62828' };
const STATUS_COLOURS = { STALE: '#c0a000', UNREACHABLE: '#b00020' };
const HEADINGS = { N: [0, -1], E: [1, 0], S: [0, 1], W: [-1, 0] };
const MAX_CANVAS = 1400;

export class Drawing {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d', { alpha: false });
    this.background = null;
    this.backgroundKey = null;
    this.scene = { cell: 0, width: 0, height: 0, robots: [], doors: [], carts: [], map: false };
  }

  /** Draws the model; returns (and keeps, for tests) what was drawn where. */
  draw(model) {
    const map = mapOf(model);
    // without a map, the grid only grows: a robot that comes back from a far corner must not make the drawing jump
    const [width, height] = map ? [map.width, map.height] : this.grow(extent(model));
    const cell = Math.max(2, Math.min(32, Math.floor(MAX_CANVAS / Math.max(width, height * 2))));
    this.resize(width * cell, height * cell);
    const key = `${width}x${height}@${cell}:${map ? map.rows.join('') : ''}`;
    if (key !== this.backgroundKey) {
      this.background = background(width, height, cell, map);
      this.backgroundKey = key;
    }
    const ctx = this.ctx;
    ctx.drawImage(this.background, 0, 0);
    const scene = { cell, width, height, map: !!map, robots: [], doors: [], carts: [] };
    for (const d of model.ofKind('door')) scene.doors.push(drawDoor(ctx, d, cell));
    for (const c of model.ofKind('cart')) {
      const drawn = drawCart(ctx, c, cell);
      if (drawn) scene.carts.push(drawn);
    }
    drawRobots(ctx, model.ofKind('robot'), cell, scene.robots);
    this.scene = scene;
    return scene;
  }

  grow([w, h]) {
    this.extent = [Math.max(w, this.extent ? this.extent[0] : 0), Math.max(h, this.extent ? this.extent[1] : 0)];
    return this.extent;
  }

  /** Makes the canvas paint what it was told now (reading a pixel waits for it), for honest timing. */
  rasterise() {
    this.ctx.getImageData(0, 0, 1, 1);
  }

  resize(w, h) {
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
  }
}

/** The map of the warehouse provider, or null: {width, height, rows}. */
function mapOf(model) {
  for (const w of model.ofKind('warehouse')) {
    let rows = value(w, 'map', 'rows');
    if (typeof rows === 'string') rows = rows.split('\n');
    if (Array.isArray(rows) && rows.length) {
      return { width: Math.max(...rows.map(r => r.length)), height: rows.length, rows };
    }
  }
  return null;
}

/** Without a map: a grid that holds every device, with a margin of one cell. */
function extent(model) {
  let w = 4, h = 4;
  for (const d of model.devices.values()) {
    const x = value(d, 'position', 'x'), y = value(d, 'position', 'y');
    if (typeof x === 'number') w = Math.max(w, x + 2);
    if (typeof y === 'number') h = Math.max(h, y + 2);
  }
  return [w, h];
}

function background(width, height, cell, map) {
  const c = document.createElement('canvas');
  c.width = width * cell;
  c.height = height * cell;
  const ctx = c.getContext('2d', { alpha: false });
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(0, 0, c.width, c.height);
  if (map) {
    for (let y = 0; y < map.rows.length; y++) {
      const row = map.rows[y];
      for (let x = 0; x < row.length; x++) {
        ctx.fillStyle = AREA_COLOURS[row[x]] || '#ffffff';
        ctx.fillRect(x * cell, y * cell, cell, cell);
      }
    }
  }
  if (cell >= 6) {
    ctx.strokeStyle = 'rgba(0,0,0,0.07)';
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (let x = 0; x <= width; x++) { ctx.moveTo(x * cell + 0.5, 0); ctx.lineTo(x * cell + 0.5, c.height); }
    for (let y = 0; y <= height; y++) { ctx.moveTo(0, y * cell + 0.5); ctx.lineTo(c.width, y * cell + 0.5); }
    ctx.stroke();
  }
  return c;
}

function drawDoor(ctx, d, cell) {
  const x = value(d, 'position', 'x'), y = value(d, 'position', 'y'), state = value(d, 'door', 'state');
  ctx.fillStyle = d.status === 'OK' ? (DOOR_COLOURS[state] || '#9e9e9e') : STATUS_COLOURS[d.status];
  const inset = Math.max(1, cell / 8);
  ctx.fillRect(x * cell + inset, y * cell + inset, cell - 2 * inset, cell - 2 * inset);
  return { id: d.id, x, y, state, status: d.status };
}

function drawCart(ctx, c, cell) {
  const x = value(c, 'position', 'x'), y = value(c, 'position', 'y');
  if (typeof x !== 'number' || value(c, 'cart', 'carriedBy')) return null; // a carried cart is drawn on its robot
  ctx.fillStyle = '#8d6e63';
  const inset = Math.max(1, cell / 4);
  ctx.fillRect(x * cell + inset, y * cell + inset, cell - 2 * inset, cell - 2 * inset);
  return { id: c.id, x, y };
}

/**
 * Robots are drawn in batches, one path per colour (and one for every heading mark), not one path per robot: with a
 * thousand robots on a software-rendered canvas, the number of fill and stroke calls is what costs.
 */
function drawRobots(ctx, robots, cell, drawn) {
  const byColour = new Map();
  const carts = [], unreachable = [];
  for (const r of robots) {
    const x = value(r, 'position', 'x'), y = value(r, 'position', 'y'), heading = value(r, 'position', 'heading');
    const state = value(r, 'state', 'state'), detect = value(r, 'state', 'detect'), cart = value(r, 'cart', 'cart');
    if (typeof x !== 'number' || typeof y !== 'number') continue;
    let colour = state === 'running' ? '#2e7d32' : '#546e7a';
    if (detect) colour = '#ef6c00';
    if (r.status !== 'OK') colour = STATUS_COLOURS[r.status];
    const robot = { id: r.id, x, y, heading, state, detect, cart, status: r.status };
    drawn.push(robot);
    if (!byColour.has(colour)) byColour.set(colour, []);
    byColour.get(colour).push(robot);
    if (cart) carts.push(robot);
    if (r.status === 'UNREACHABLE') unreachable.push(robot);
  }
  ctx.fillStyle = '#8d6e63'; // the cart a robot carries, under it
  for (const r of carts) ctx.fillRect(r.x * cell + 1, r.y * cell + 1, cell - 2, cell - 2);
  const radius = cell * 0.4;
  for (const [colour, list] of byColour) {
    ctx.fillStyle = colour;
    if (cell < 6) {
      for (const r of list) ctx.fillRect(r.x * cell, r.y * cell, cell, cell);
      continue;
    }
    ctx.beginPath();
    for (const r of list) {
      const cx = (r.x + 0.5) * cell, cy = (r.y + 0.5) * cell;
      ctx.moveTo(cx + radius, cy);
      ctx.arc(cx, cy, radius, 0, Math.PI * 2);
    }
    ctx.fill();
  }
  if (cell < 6) return;
  ctx.strokeStyle = '#ffffff';
  ctx.lineWidth = Math.max(1, cell / 10);
  ctx.beginPath();
  for (const r of drawn) {
    const [dx, dy] = HEADINGS[r.heading] || [0, 0];
    const cx = (r.x + 0.5) * cell, cy = (r.y + 0.5) * cell;
    ctx.moveTo(cx, cy);
    ctx.lineTo(cx + dx * radius, cy + dy * radius);
  }
  ctx.stroke();
  if (unreachable.length) { // a cross: not where it is, only where it was last seen
    ctx.strokeStyle = '#b00020';
    ctx.beginPath();
    for (const r of unreachable) {
      ctx.moveTo(r.x * cell, r.y * cell); ctx.lineTo((r.x + 1) * cell, (r.y + 1) * cell);
      ctx.moveTo((r.x + 1) * cell, r.y * cell); ctx.lineTo(r.x * cell, (r.y + 1) * cell);
    }
    ctx.stroke();
  }
  if (cell >= 16) {
    ctx.fillStyle = '#1d2330';
    ctx.font = `${Math.floor(cell / 2.5)}px system-ui, sans-serif`;
    for (const r of drawn) ctx.fillText(r.id.replace(/^robot/, ''), r.x * cell + 1, r.y * cell + cell / 2.5);
  }
}

// The page's copy of the dashboard's state: applied from the snapshot and the stream's events, read by the
// drawing and the panels. Plain data; no DOM here.

const DECISIONS = 30;

export class Model {
  constructor() {
    this.devices = new Map();      // id -> {id, kind, status, reason, values: {service: {resource: value}}}
    this.counters = {};
    this.decisions = [];           // oldest first, one per commandId
    this.fabric = {};
    this.eventId = null;           // the id of the last event applied (what a reconnection asks to resume after)
    this.devicesChanged = true;    // the device list must be drawn again
    this.panelsChanged = true;
  }

  /** Replaces everything (a snapshot: first load, or a reconnection that could not be replayed). */
  load(snapshot) {
    this.devices.clear();
    for (const d of snapshot.devices) this.devices.set(d.id, d);
    this.counters = snapshot.counters || {};
    this.decisions = snapshot.decisions || [];
    this.fabric = snapshot.fabric || {};
    this.eventId = snapshot.eventId;
    this.devicesChanged = this.panelsChanged = true;
  }

  /** Applies one delta event; {@code id} is its event id. */
  apply(delta, id) {
    for (const d of delta.devices) {
      const known = this.devices.get(d.id);
      if (d.full || !known) {
        this.devices.set(d.id, d);
      } else { // only what changed: merge it
        known.status = d.status;
        for (const service in d.values) {
          known.values[service] = Object.assign(known.values[service] || {}, d.values[service]);
        }
      }
    }
    for (const gone of delta.removed) this.devices.delete(gone);
    if (delta.devices.length || delta.removed.length) this.devicesChanged = true;
    if (delta.counters) this.counters = delta.counters;
    if (delta.decisions) {
      for (const entry of delta.decisions) {
        const at = this.decisions.findIndex(d => d.commandId === entry.commandId);
        if (at >= 0) this.decisions.splice(at, 1);
        this.decisions.push(entry);
      }
      if (this.decisions.length > DECISIONS) this.decisions.splice(0, this.decisions.length - DECISIONS);
    }
    if (delta.fabric) this.fabric = delta.fabric;
    this.eventId = id;
    this.panelsChanged = true;
  }

  /** Providers of one kind (robot, door, cart, warehouse). */
  *ofKind(kind) {
    for (const d of this.devices.values()) if (d.kind === kind) yield d;
  }
}

/** A resource's value, or undefined. */
export function value(device, service, resource) {
  const s = device.values && device.values[service];
  return s ? s[resource] : undefined;
}

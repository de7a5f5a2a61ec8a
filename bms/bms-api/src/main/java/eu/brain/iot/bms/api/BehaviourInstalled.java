package eu.brain.iot.bms.api;

import java.util.List;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** A behaviour that the BMS asked for is installed and registered with the bus; the held events went to it. */
public class BehaviourInstalled extends BrainIoTEvent {
    /**
     * The event types that waited for it (usually one); empty when the BMS brought back a behaviour whose bundle
     * stopped or was uninstalled outside the installer, and no event waited for it.
     */
    public List<String> eventTypes;
    /** The behaviour bundle's symbolic name. */
    public String behaviour;
    /** Its version. */
    public String version;
    /** The index it came from. */
    public String repository;
    /** Milliseconds from the first unhandled event (or from its bundle going away) to the installer's answer. */
    public long durationMs;
    /** Which attempt succeeded, from 1. */
    public int attempt;
}

package eu.brain.iot.bms.api;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * An install that the BMS asked for failed. Unless {@link #finalFailure}, the BMS keeps the type's events held and
 * tries again at {@link #nextRetry}.
 */
public class BehaviourInstallFailed extends BrainIoTEvent {
    /**
     * The event type whose first event asked for the install; {@code null} when no event did: the BMS was bringing
     * back a behaviour whose bundle stopped or was uninstalled outside the installer.
     */
    public String eventType;
    /** The behaviour bundle's symbolic name and version, e.g. {@code eu.brain.iot.behaviours.door 0.1.0}. */
    public String behaviour;
    /** The installer's kind of failure ({@code eu.brain.iot.bis.api.InstallException.Problem} name). */
    public String problem;
    /** What was wrong and what to do, as the installer said it. */
    public String reason;
    /** Which attempt failed, from 1. */
    public int attempt;
    /** When the next attempt is made (milliseconds since the epoch); 0 when there is none. */
    public long nextRetry;
    /** {@code true} when the BMS gives up: its held events are discarded (counted) and no retry follows. */
    public boolean finalFailure;
    /** How many events of the type are held now. */
    public int heldEvents;
}

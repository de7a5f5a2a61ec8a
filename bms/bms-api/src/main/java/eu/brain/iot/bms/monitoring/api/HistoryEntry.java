package eu.brain.iot.bms.monitoring.api;

import java.util.List;

import org.osgi.dto.DTO;

/** Something the BMS did. */
public class HistoryEntry extends DTO {
    /** When it ended (milliseconds since the epoch). */
    public long time;
    /**
     * {@code INSTALLED}, {@code RESTARTED} (it was installed but not active), {@code REINSTALLED} (its bundle had been
     * uninstalled outside the installer), {@code INSTALL_FAILED}, {@code NOT_FOUND}, {@code GAVE_UP},
     * {@code REMOVED_BY_OPERATOR}, {@code NOT_TAKEN}.
     */
    public String kind;
    /** The event types concerned; empty when no event was: a behaviour brought back after its bundle went away. */
    public List<String> eventTypes;
    /** The behaviour (symbolic name and version), if one was chosen. */
    public String behaviour;
    /**
     * Milliseconds from the first unhandled event (or from the behaviour's bundle going away, or from the attempt's
     * start) to this outcome.
     */
    public long durationMs;
    /** The attempt, from 1 (0 when no install was tried). */
    public int attempt;
    /**
     * Held events given up on at that moment ({@code NOT_FOUND}, {@code GAVE_UP}, {@code REMOVED_BY_OPERATOR},
     * {@code NOT_TAKEN}), or held at a failed attempt ({@code INSTALL_FAILED}); 0 for {@code INSTALLED}: the bus handed
     * the held events to the behaviour as it registered it.
     */
    public int heldEvents;
    /** The reason of a failure, why events were given up on, or why a behaviour was started or installed again. */
    public String reason;
}

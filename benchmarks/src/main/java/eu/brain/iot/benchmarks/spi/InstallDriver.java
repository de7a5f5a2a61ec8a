package eu.brain.iot.benchmarks.spi;

/**
 * What the install benchmark asks of a node with the BMS and the BIS; implemented by the install driver bundle inside
 * the embedded framework (with the real bus, BMS and BIS APIs), seen by the launcher through the system bundle.
 */
public interface InstallDriver {

    /** The probe behaviour's symbolic name, as in the index. */
    String BEHAVIOUR = "eu.brain.iot.benchmarks.behaviour.probe";

    /**
     * Write an R5 index of the probe behaviour bundle (bnd's repository support) beside it, then configure the BIS
     * with {@code indexUrl} (which serves that directory) and wait until the BMS is up and the index offers it.
     */
    void configure(String bundleFile, String indexUrl, String journalDir) throws Exception;

    /** Publish one event of the probe behaviour's type, stamped with {@code System.nanoTime()}. */
    void publish(String publisher, int seq);

    /** Uninstall the probe behaviour (not as an operator: the BMS may install it again) and wait until it is gone. */
    void uninstall() throws Exception;

    /** @return the BMS's and the bus's view, for the report: installs, held events, unhandled events */
    String counters();
}

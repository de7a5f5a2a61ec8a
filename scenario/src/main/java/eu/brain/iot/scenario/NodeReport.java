package eu.brain.iot.scenario;

import java.util.List;
import java.util.Map;

/**
 * One node of a fabric run as the report and the summary show it: its last reading (at the run's end, or just
 * before it was killed). A null field is a figure unknown (the node ended before it could be read).
 *
 * @param name                 the node's name
 * @param killedAtWarehouseMs  warehouse time (from the run's start) at which the runner killed it, or null
 * @param restartedAtWarehouseMs warehouse time at which the runner started it again after the kill, or null
 * @param devicesOwned         the robots and doors its edge owned, sorted
 * @param behavioursInstalled  the symbolic names of its active behaviour bundles ({@code eu.brain.iot.behaviours.*})
 * @param eventsSentTo         events it published to each other node ({@code fabric:stats}, over its lives)
 * @param eventsReceivedFrom   events from each other node handed to its bus
 * @param cpuMs                its JVM's CPU time from the run's start until its end (or last reading)
 * @param wallMs               the wall time from the run's start until the node's end or the run's
 */
record NodeReport(String name, Long killedAtWarehouseMs, Long restartedAtWarehouseMs, List<String> devicesOwned,
                  List<String> behavioursInstalled,
                  Map<String, Long> eventsSentTo, Map<String, Long> eventsReceivedFrom, Long cpuMs, long wallMs) {

    /** CPU time over the wall time the node ran during the run, in percent of one core; null when unknown. */
    Double cpuPercentOfOneCore() {
        return cpuMs == null || wallMs <= 0 ? null : 100.0 * cpuMs / wallMs;
    }
}

package eu.brain.iot.node.logging;

import java.io.PrintStream;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Enumeration;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.LogEntry;
import org.osgi.service.log.LogLevel;
import org.osgi.service.log.LogListener;
import org.osgi.service.log.LogReaderService;

/**
 * Writes what the bundles log through the OSGi log service (Felix log) to the node's console, one line per entry
 * on standard error: {@code 12:04:31.207 WARN eu.brain.iot.edge.impl.EdgeComponent - robot robot2 is unreachable ...}.
 * That is the layout slf4j-simple gives Jetty's lines (the node's bndrun configures it so), so every log line of the
 * node looks the same, whoever wrote it. The Felix log service keeps entries in memory only: without this component
 * the edge's warnings were seen only by typing {@code log warn} in the shell, and not at all with {@code --no-shell}.
 * <p>
 * Which entries exist at all is the log service's decision, by level, as the OSGi Log Service 1.4 specifies it: the
 * framework property {@code org.osgi.service.log.admin.loglevel} (the node's bndrun: {@code INFO}) for every logger,
 * and per logger name (a component's class, or a package prefix of it) the Config Admin configuration
 * {@code org.osgi.service.log.admin}, e.g. a file {@code node/config/org.osgi.service.log.admin.cfg} holding
 * {@code eu.brain.iot.edge=DEBUG}. This component prints each entry once, as it is recorded; it leaves out only the
 * framework's own bookkeeping below WARN (the log service records every bundle and service event at INFO or DEBUG
 * under the logger names {@code Events.*}: hundreds of lines at each start, still there for {@code log info}).
 * <p>
 * Ownership: the log service calls {@link #logged} on its own listener thread; the constructor runs on SCR's. Both
 * print under {@link #lock}, which also guards {@link #printedAtStart}, so that an entry of the history read at
 * activation is not printed again by the listener, and lines never interleave. The listener may get entries out of
 * their sequence (two threads logging at once), so an entry is recognised by its own sequence number, not compared
 * with the last one printed.
 */
@Component
public final class ConsoleLog {

    /** The logger names under which the log service records framework, bundle and service events. */
    private static final String FRAMEWORK_EVENTS = "Events.";
    /**
     * What a {@code LogService.log} call (the pre-1.4 API) is recorded under, and what a bundle's own logger without
     * a name is: the bundle's name says more.
     */
    private static final Set<String> UNNAMED = Set.of("LogService", "ROOT");
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS")
            .withZone(ZoneId.systemDefault());

    private final LogReaderService reader;
    private final PrintStream out;
    private final Object lock = new Object();
    /** Not a service (SCR would register it as one, and make the component wait for a user): a listener only. */
    private final LogListener listener = this::logged;
    /** Sequence numbers of the history entries printed at activation that the listener has not delivered yet. */
    private final Set<Long> printedAtStart = new HashSet<>();

    @Activate
    public ConsoleLog(@Reference LogReaderService reader) {
        this(reader, System.err);
    }

    ConsoleLog(LogReaderService reader, PrintStream out) {
        this.reader = reader;
        this.out = out;
        synchronized (lock) {
            reader.addLogListener(listener);
            // what was logged before this component started (the log keeps it, newest first), oldest first
            List<LogEntry> history = new ArrayList<>();
            for (Enumeration<LogEntry> e = reader.getLog(); e.hasMoreElements();) {
                history.add(e.nextElement());
            }
            Collections.reverse(history);
            for (LogEntry entry : history) {
                printedAtStart.add(entry.getSequence());
                print(entry);
            }
        }
    }

    @Deactivate
    void deactivate() {
        reader.removeLogListener(listener);
    }

    private void logged(LogEntry entry) {
        synchronized (lock) {
            if (!printedAtStart.remove(entry.getSequence())) {
                print(entry);
            }
        }
    }

    /** Called under {@link #lock}. */
    private void print(LogEntry entry) {
        String line = format(entry);
        if (line != null) {
            out.println(line);
        }
    }

    /** The console line for an entry, or {@code null} for the framework's own events below WARN. */
    static String format(LogEntry entry) {
        LogLevel level = entry.getLogLevel();
        String logger = entry.getLoggerName();
        if (logger != null && logger.startsWith(FRAMEWORK_EVENTS) && !LogLevel.WARN.implies(level)) {
            return null;
        }
        if (logger == null || UNNAMED.contains(logger)) {
            logger = entry.getBundle() == null ? "?" : entry.getBundle().getSymbolicName();
        }
        StringBuilder line = new StringBuilder(TIME.format(Instant.ofEpochMilli(entry.getTime()))).append(' ')
                .append(level == LogLevel.AUDIT ? "AUDIT" : level.name()).append(' ').append(logger).append(" - ")
                .append(entry.getMessage());
        Throwable exception = entry.getException();
        if (exception != null) {
            // the cause in one line; the whole trace stays in the log service ('log error' in the shell)
            line.append(" (").append(exception).append(')');
        }
        return line.toString();
    }
}

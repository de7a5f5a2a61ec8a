package eu.brain.iot.node.logging;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.lang.reflect.Proxy;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.service.log.LogEntry;
import org.osgi.service.log.LogLevel;
import org.osgi.service.log.LogListener;
import org.osgi.service.log.LogReaderService;

/** The console line of a log entry: one line, the layout slf4j-simple gives Jetty's, framework events left out. */
class ConsoleLogTest {

    @Test
    void aComponentsWarningIsOneLineNamingItsLogger() {
        assertThat(ConsoleLog.format(entry(LogLevel.WARN, "eu.brain.iot.edge.impl.EdgeComponent", "robot2 unreachable",
                null))).matches("\\d\\d:\\d\\d:\\d\\d\\.\\d{3} WARN eu\\.brain\\.iot\\.edge\\.impl\\.EdgeComponent - "
                        + "robot2 unreachable");
    }

    @Test
    void anExceptionIsSummedUpInTheSameLine() {
        assertThat(ConsoleLog.format(entry(LogLevel.ERROR, "x.Y", "failed", new IllegalStateException("no port"))))
                .endsWith(" ERROR x.Y - failed (java.lang.IllegalStateException: no port)").doesNotContain("\n");
    }

    @Test
    void unnamedLoggersAreNamedAfterTheirBundle() {
        assertThat(ConsoleLog.format(entry(LogLevel.INFO, "LogService", "hello", null))).contains(" INFO b.sn - hello");
        assertThat(ConsoleLog.format(entry(LogLevel.INFO, "ROOT", "hello", null))).contains(" INFO b.sn - hello");
    }

    @Test
    void frameworkEventsBelowWarnAreLeftOut() {
        assertThat(ConsoleLog.format(entry(LogLevel.INFO, "Events.Bundle.b.sn", "BundleEvent STARTED", null))).isNull();
        assertThat(ConsoleLog.format(entry(LogLevel.DEBUG, "Events.Service.b.sn", "ServiceEvent MODIFIED", null)))
                .isNull();
        assertThat(ConsoleLog.format(entry(LogLevel.ERROR, "Events.Framework.b.sn", "FrameworkEvent ERROR", null)))
                .contains(" ERROR Events.Framework.b.sn - FrameworkEvent ERROR");
        assertThat(ConsoleLog.format(entry(LogLevel.WARN, "Events.Framework.b.sn", "FrameworkEvent WARNING", null)))
                .isNotNull();
    }

    @Test
    void everyEntryIsPrintedOnceEvenWhenTheListenerGetsThemOutOfSequence() {
        List<LogEntry> history = List.of(entry(2, "second"), entry(1, "first")); // the log's order: newest first
        List<LogListener> listeners = new ArrayList<>();
        LogReaderService reader = (LogReaderService) Proxy.newProxyInstance(LogReaderService.class.getClassLoader(),
                new Class<?>[] { LogReaderService.class }, (proxy, method, args) -> switch (method.getName()) {
                case "addLogListener" -> listeners.add((LogListener) args[0]);
                case "getLog" -> Collections.enumeration(history);
                default -> null;
                });
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        new ConsoleLog(reader, new PrintStream(out, true, StandardCharsets.UTF_8));
        LogListener listener = listeners.get(0);
        listener.logged(entry(2, "second")); // logged while the history was read: printed already
        listener.logged(entry(4, "fourth")); // two threads logging at once: 4 comes before 3
        listener.logged(entry(3, "third"));
        assertThat(out.toString(StandardCharsets.UTF_8).lines().map(l -> l.substring(l.lastIndexOf(' ') + 1)))
                .containsExactly("first", "second", "fourth", "third");
    }

    private static LogEntry entry(long sequence, String message) {
        return (LogEntry) Proxy.newProxyInstance(LogEntry.class.getClassLoader(), new Class<?>[] { LogEntry.class },
                (proxy, method, args) -> switch (method.getName()) {
                case "getLogLevel" -> LogLevel.INFO;
                case "getLoggerName" -> "x.Y";
                case "getMessage" -> message;
                case "getTime" -> 1_700_000_000_000L;
                case "getSequence" -> sequence;
                default -> null;
                });
    }

    private static LogEntry entry(LogLevel level, String logger, String message, Throwable exception) {
        Bundle bundle = (Bundle) Proxy.newProxyInstance(Bundle.class.getClassLoader(), new Class<?>[] { Bundle.class },
                (proxy, method, args) -> method.getName().equals("getSymbolicName") ? "b.sn" : null);
        return (LogEntry) Proxy.newProxyInstance(LogEntry.class.getClassLoader(), new Class<?>[] { LogEntry.class },
                (proxy, method, args) -> switch (method.getName()) {
                case "getLogLevel" -> level;
                case "getLoggerName" -> logger;
                case "getMessage" -> message;
                case "getException" -> exception;
                case "getBundle" -> bundle;
                case "getTime" -> 1_700_000_000_000L;
                case "getSequence" -> 1L;
                default -> null;
                });
    }
}

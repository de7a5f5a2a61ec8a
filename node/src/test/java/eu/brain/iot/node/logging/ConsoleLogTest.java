package eu.brain.iot.node.logging;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Proxy;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.service.log.LogEntry;
import org.osgi.service.log.LogLevel;

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

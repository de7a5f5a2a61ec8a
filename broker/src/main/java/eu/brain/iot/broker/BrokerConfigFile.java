package eu.brain.iot.broker;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Writes HiveMQ's {@code config.xml} for the given options: one TCP listener, the persistence mode, the offline
 * queue's size, and anonymous usage statistics off (HiveMQ sends them to its makers by default; a fabric's broker
 * makes no call home). Beside it a {@code logback.xml}: one line per event on standard output, in the nodes' form
 * ({@code <time> <LEVEL> <logger> - <message>}).
 */
final class BrokerConfigFile {
    static final String FILE_NAME = "config.xml";
    static final String LOGBACK_FILE_NAME = "logback.xml";

    private static final String LOGBACK = """
            <configuration scan="false">
                <!-- Written by the fabric's broker launcher (broker/) at every start. -->
                <appender name="CONSOLE" class="ch.qos.logback.core.ConsoleAppender">
                    <encoder><pattern>%d{HH:mm:ss.SSS} %-5level broker - %msg%n%ex</pattern></encoder>
                </appender>
                <root level="INFO"><appender-ref ref="CONSOLE"/></root>
                <logger name="migrations" level="WARN"/>
                <logger name="jetbrains.exodus" level="WARN"/>
                <logger name="org.eclipse.jetty" level="ERROR"/>
                <logger name="com.google.common.util.concurrent.Futures.CombinedFuture" level="OFF"/>
                <logger name="oshi" level="ERROR"/>
            </configuration>
            """;

    private BrokerConfigFile() {
    }

    /** The XML for these options. */
    static String xml(BrokerOptions options) {
        return """
                <?xml version="1.0"?>
                <!-- Written by the fabric's broker launcher (broker/) at every start from its command line. -->
                <hivemq>
                    <listeners>
                        <tcp-listener>
                            <port>%d</port>
                            <bind-address>%s</bind-address>
                        </tcp-listener>
                    </listeners>
                    <mqtt>
                        <queued-messages>
                            <max-queue-size>%d</max-queue-size>
                            <strategy>discard</strategy>
                        </queued-messages>
                    </mqtt>
                    <persistence>
                        <mode>%s</mode>
                    </persistence>
                    <anonymous-usage-statistics>
                        <enabled>false</enabled>
                    </anonymous-usage-statistics>
                </hivemq>
                """.formatted(options.port(), escape(options.bind()), options.maxQueued(),
                options.persistence().hivemqName());
    }

    /** Writes {@code config.xml} and {@code logback.xml} into the folder (created if missing) and returns the folder. */
    static Path write(Path configDir, BrokerOptions options) throws IOException {
        Files.createDirectories(configDir);
        Files.writeString(configDir.resolve(FILE_NAME), xml(options), StandardCharsets.UTF_8);
        Files.writeString(configDir.resolve(LOGBACK_FILE_NAME), LOGBACK, StandardCharsets.UTF_8);
        return configDir;
    }

    private static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}

package eu.brain.iot.edge.rest.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.osgi.service.log.LogEntry;
import org.osgi.service.log.LogLevel;
import org.osgi.service.log.LogReaderService;
import org.osgi.test.common.annotation.InjectService;

/**
 * A stream client that never reads is disconnected once the connection has taken nothing for
 * {@code sse.write.timeout.ms}, and logged once at warn with its address; a reading client is not disturbed.
 * Changes flowing at a modest rate find it within seconds too: the connection's send buffer is bounded
 * ({@code send.buffer.bytes}), where the kernel would grow it to megabytes before the write timeout could start.
 */
class SlowSseClientIntegrationTest extends RestTestBase {

    @InjectService(timeout = 10_000)
    static LogReaderService logs;

    @Test
    void aClientThatNeverReadsIsDisconnectedAndLoggedOnce() throws Exception {
        // a queue large enough that the write timeout, not the queue, finds the client
        configure(Map.of("sse.write.timeout.ms", 500L, "sse.queue.capacity", 200_000));
        String x = "x".repeat(2_000);
        try (Socket stalled = stalledSubscriber()) {
            String who = "SSE client 127.0.0.1:" + stalled.getLocalPort() + " ";
            List<String> received = new CopyOnWriteArrayList<>();
            HttpResponse<Stream<String>> reader = reading("door1", received);

            // megabytes for the stalled client: more than the socket buffers on both sides hold
            for (int i = 0; i < 8_000 && !logged(who); i++) {
                model.emit(ScriptedModel.value("robot1", "position", "x", x + i));
            }
            await("the stalled client is found").atMost(DEADLINE).until(() -> logged(who));
            await().atMost(DEADLINE).until(() -> model.subscribers() == 1);
            model.emit(ScriptedModel.value("door1", "door", "state", "open"));
            await("the reading client still gets changes").atMost(DEADLINE)
                    .until(() -> received.stream().anyMatch(l -> l.contains("\"open\"")));
            assertThat(entries(who)).hasSize(1).allSatisfy(e -> {
                assertThat(e.getLogLevel()).isEqualTo(LogLevel.WARN);
                assertThat(e.getMessage()).contains("not reading", "sse.write.timeout.ms");
            });
            reader.body().close();
        }
    }

    @Test
    void aClientThatNeverReadsIsFoundWithinSecondsAtAModestRate() throws Exception {
        configure(Map.of("sse.write.timeout.ms", 500L, "sse.queue.capacity", 200_000));
        String x = "x".repeat(500);
        ScheduledExecutorService changes = Executors.newSingleThreadScheduledExecutor();
        try (Socket stalled = stalledSubscriber()) {
            String who = "SSE client 127.0.0.1:" + stalled.getLocalPort() + " ";
            List<String> received = new CopyOnWriteArrayList<>();
            HttpResponse<Stream<String>> reader = reading("robot1", received);

            // about 50 KB/s: the kernel's self-grown buffers (up to 4 MB on Linux) would take over a minute to fill
            AtomicInteger sent = new AtomicInteger();
            changes.scheduleAtFixedRate(() -> model.emit(ScriptedModel.value("robot1", "position", "x",
                    x + sent.incrementAndGet())), 0, 10, TimeUnit.MILLISECONDS);
            await("the stalled client is found within seconds").atMost(Duration.ofSeconds(15))
                    .until(() -> logged(who));
            int before = sent.get();
            await("the reading client still gets changes").atMost(DEADLINE)
                    .until(() -> received.stream().anyMatch(l -> l.contains(x + (before + 1) + "\"")));
            assertThat(entries(who)).hasSize(1).allSatisfy(e -> {
                assertThat(e.getLogLevel()).isEqualTo(LogLevel.WARN);
                assertThat(e.getMessage()).contains("not reading", "sse.write.timeout.ms");
            });
            reader.body().close();
        } finally {
            changes.shutdownNow();
        }
    }

    /** A subscriber to robot1 with a 4 KB receive buffer that never reads. */
    private static Socket stalledSubscriber() throws Exception {
        Socket stalled = new Socket();
        stalled.setReceiveBufferSize(4_096); // before connecting: the window it offers stays small
        stalled.connect(new InetSocketAddress(base.getHost(), base.getPort()), 5_000);
        stalled.getOutputStream().write(("GET /sensinact/subscribe?provider=robot1 HTTP/1.1\r\n"
                + RawHttp.host(base) + "\r\n\r\n").getBytes(StandardCharsets.UTF_8));
        return stalled;
    }

    /** A second subscriber, to that provider, whose lines a daemon thread adds to {@code received}; both subscribed. */
    private static HttpResponse<Stream<String>> reading(String provider, List<String> received) throws Exception {
        HttpResponse<Stream<String>> reader = HTTP.send(HttpRequest.newBuilder(uri("/sensinact/subscribe?provider="
                + provider)).timeout(Duration.ofSeconds(30)).build(), HttpResponse.BodyHandlers.ofLines());
        Thread t = new Thread(() -> {
            try {
                reader.body().forEach(received::add);
            } catch (java.io.UncheckedIOException e) {
                // the test closed the stream: the end of this reader
            }
        }, "sse-test-reader");
        t.setDaemon(true);
        t.start();
        await().atMost(DEADLINE).until(() -> model.subscribers() == 2);
        return reader;
    }

    private static boolean logged(String who) {
        return !entries(who).isEmpty();
    }

    private static List<LogEntry> entries(String who) {
        return Collections.list(logs.getLog()).stream().filter(e -> e.getMessage().contains(who)
                && e.getMessage().contains("disconnected")).toList();
    }
}

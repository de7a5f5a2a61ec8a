package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.net.URI;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;

import org.junit.jupiter.api.Test;

class FleetHttpClientTest {

    /**
     * A poll that starts while the edge stops (its component restarting) gets a failed answer, not one that never
     * comes (Netty rejected the pool's listener and logged an ERROR with a stack trace on the node's console).
     */
    @Test
    void aRequestAfterCloseFailsAtOnce() {
        FleetHttpClient client = new FleetHttpClient(1, 4, 1_000);
        client.close();
        await().atMost(Duration.ofSeconds(10)).until(client::terminated);
        CompletableFuture<HttpAnswer> answer = client.get(URI.create("http://127.0.0.1:9/robot1"));
        assertThat(answer).failsWithin(Duration.ofSeconds(5)).withThrowableThat()
                .havingRootCause().isInstanceOf(DeviceIOException.class).withMessageContaining("closed");
    }
}

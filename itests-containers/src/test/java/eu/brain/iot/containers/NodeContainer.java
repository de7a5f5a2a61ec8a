package eu.brain.iot.containers;

import java.io.IOException;
import org.testcontainers.containers.GenericContainer;

/**
 * A fabric node in its container, with the API token it was given, and a client for its REST API. A request
 * names the node's own address ({@code Host: 127.0.0.1:8181}), which the REST API accepts, rather than the port
 * Docker maps it to on this machine, which it would refuse (421).
 *
 * <p>Threads: used by the test thread only.
 */
record NodeContainer(String name, String token, GenericContainer<?> container) {
    /** GET {@code path} with the token, or without it when {@code withToken} is false. */
    PlainHttp.Answer get(String path, boolean withToken) throws IOException {
        return PlainHttp.get(container.getHost(), container.getMappedPort(FabricContainers.HTTP_PORT),
                "127.0.0.1:" + FabricContainers.HTTP_PORT, path, withToken ? token : null);
    }

    /** The container's output so far. */
    String logs() {
        return container.getLogs();
    }
}

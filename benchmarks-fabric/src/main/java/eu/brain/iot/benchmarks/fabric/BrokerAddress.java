package eu.brain.iot.benchmarks.fabric;

import java.net.URI;

/** A broker's {@code tcp://host:port}, checked. */
record BrokerAddress(String host, int port) {

    static BrokerAddress parse(String uri) {
        URI u = URI.create(uri.strip());
        if (!"tcp".equals(u.getScheme()) || u.getHost() == null || u.getPort() < 1) {
            throw new IllegalArgumentException("a broker URI is tcp://HOST:PORT, found '" + uri + "'");
        }
        return new BrokerAddress(u.getHost(), u.getPort());
    }

    String uri() {
        return "tcp://" + host + ":" + port;
    }
}

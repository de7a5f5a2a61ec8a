package eu.brain.iot.edge.impl;

import java.net.URI;
import java.net.URISyntaxException;
import java.util.List;

/**
 * The edge's configuration, checked: every problem is reported with the property's name and what to write.
 *
 * @param baseUrl          the fleet's REST base, ending in '/'
 * @param robots           robot ids to poll (with {@code doors}, empty means: ask the fleet)
 * @param doors            door ids to poll
 * @param periodMillis     time between two polls of one device
 * @param timeoutMillis    how long to wait for an answer
 * @param maxConnections   keep-alive connections per host
 * @param ioThreads        HTTP client threads
 * @param unreachableAfter failed polls in a row before a device is reported unreachable
 * @param backoffMaxMillis longest time between polls of an unreachable device
 * @param worldPeriodMillis time between two reads of the fleet's world ({@code GET /world}: carts and map), 0: never
 * @param share            this node's share of the fleet's devices (what it polls and commands, unless ownership
 *                         changes at run time)
 */
record FleetSettings(URI baseUrl, List<String> robots, List<String> doors, long periodMillis, long timeoutMillis,
        int maxConnections, int ioThreads, int unreachableAfter, long backoffMaxMillis, long worldPeriodMillis,
        Share share) {

    FleetSettings {
        robots = List.copyOf(robots);
        doors = List.copyOf(doors);
    }

    boolean discover() {
        return robots.isEmpty() && doors.isEmpty();
    }

    /** Settings that need a new HTTP client when they change. */
    boolean sameConnection(FleetSettings other) {
        return other != null && timeoutMillis == other.timeoutMillis && maxConnections == other.maxConnections
                && ioThreads == other.ioThreads;
    }

    static FleetSettings from(EdgeConfig c) {
        return from(c, c.fleet_url());
    }

    /** The configuration with {@code url} as the fleet's URL (see {@code EdgeComponent.fleetUrl}). */
    static FleetSettings from(EdgeConfig c, String url) {
        FleetSettings s = of(url, List.of(c.robots()), List.of(c.doors()), c.poll_period_ms(), c.request_timeout_ms(),
                c.max_connections(), c.io_threads(), c.unreachable_after_failures(), c.backoff_max_ms());
        return s.withWorldPeriod(c.world_period_ms()).withShare(Share.parse(c.share(), c.doors_owner()).withLeased(c.share_leased()));
    }

    /** The same settings with this share of the fleet. */
    FleetSettings withShare(Share next) {
        return new FleetSettings(baseUrl, robots, doors, periodMillis, timeoutMillis, maxConnections, ioThreads,
                unreachableAfter, backoffMaxMillis, worldPeriodMillis, next);
    }

    /**
     * The same settings reading the fleet's world every {@code millis} (0: never).
     *
     * @throws IllegalArgumentException when it is negative
     */
    FleetSettings withWorldPeriod(long millis) {
        if (millis < 0) {
            throw new IllegalArgumentException("world.period.ms must be 0 (never) or positive, found " + millis);
        }
        return new FleetSettings(baseUrl, robots, doors, periodMillis, timeoutMillis, maxConnections, ioThreads,
                unreachableAfter, backoffMaxMillis, millis, share);
    }

    /** @throws IllegalArgumentException naming the configuration property at fault */
    static FleetSettings of(String url, List<String> robots, List<String> doors, long periodMillis,
            long timeoutMillis, int maxConnections, int ioThreads, int unreachableAfter, long backoffMaxMillis) {
        URI base = baseUrl(url);
        positive("poll.period.ms", periodMillis);
        positive("request.timeout.ms", timeoutMillis);
        positive("max.connections", maxConnections);
        positive("io.threads", ioThreads);
        positive("unreachable.after.failures", unreachableAfter);
        if (backoffMaxMillis < periodMillis) {
            throw new IllegalArgumentException("backoff.max.ms (" + backoffMaxMillis
                    + ") must be at least poll.period.ms (" + periodMillis + ")");
        }
        return new FleetSettings(base, ids("robots", robots), ids("doors", doors), periodMillis, timeoutMillis,
                maxConnections, ioThreads, unreachableAfter, backoffMaxMillis, 0, Share.EVERY_DEVICE);
    }

    private static URI baseUrl(String url) {
        try {
            URI uri = new URI(url == null ? "" : url.strip());
            if (!"http".equalsIgnoreCase(uri.getScheme()) || uri.getHost() == null) {
                throw new IllegalArgumentException("fleet.url must be an http URL such as http://127.0.0.1:8090/, "
                        + "found '" + url + "'");
            }
            return uri.getPath().endsWith("/") ? uri : new URI(uri + "/");
        } catch (URISyntaxException e) {
            throw new IllegalArgumentException("fleet.url is not a URL: " + e.getMessage());
        }
    }

    private static List<String> ids(String property, List<String> ids) {
        for (String id : ids) {
            if (id == null || !id.matches("[A-Za-z0-9_.-]+")) {
                throw new IllegalArgumentException(property + " holds '" + id
                        + "': a device id is letters, digits, '_', '.' or '-'");
            }
        }
        return ids;
    }

    private static void positive(String property, long value) {
        if (value <= 0) {
            throw new IllegalArgumentException(property + " must be positive, found " + value);
        }
    }
}

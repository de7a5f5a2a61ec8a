package eu.brain.iot.edge.rest;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;
import org.osgi.service.log.Logger;

/** Refusals under attack cost the log one short line per client address and period, not one per request. */
class RefusalLogTest {

    private final List<String> warnings = new ArrayList<>();
    private final AtomicLong nanos = new AtomicLong(1_000);
    private final RefusalLog refusals = new RefusalLog(recording(), 60_000, nanos::get);

    @Test
    void twoHundredRefusalsFromOneAddressAreOneLineAPeriod() {
        for (int i = 0; i < 200; i++) {
            refusals.refused("127.0.0.2", "408, too slow");
        }
        assertThat(warnings).containsExactly("client 127.0.0.2: 408, too slow; at most one such line per address "
                + "every 60 s");

        nanos.addAndGet(60_000_000_000L);
        refusals.refused("127.0.0.2", "408, too slow");
        assertThat(warnings).hasSize(2).last().asString().contains("127.0.0.2", "and 199 more");
    }

    @Test
    void eachAddressHasItsOwnLine() {
        refusals.refused("127.0.0.2", "408");
        refusals.refused("127.0.0.3", "408");
        refusals.refused("127.0.0.2", "408");
        assertThat(warnings).hasSize(2).anySatisfy(w -> assertThat(w).startsWith("client 127.0.0.3:"));
    }

    @Test
    void theAddressesRememberedAreBounded() {
        for (int i = 0; i <= RefusalLog.MAX_ADDRESSES; i++) {
            refusals.refused("10.0." + i / 256 + "." + i % 256, "408");
        }
        refusals.refused("10.0.0.0", "408"); // forgotten as the oldest: logged again
        assertThat(warnings).hasSize(RefusalLog.MAX_ADDRESSES + 2);
    }

    /** A Logger that records its warn(String) lines (the only call RefusalLog makes). */
    private Logger recording() {
        return (Logger) Proxy.newProxyInstance(Logger.class.getClassLoader(), new Class<?>[] { Logger.class },
                (proxy, method, args) -> {
                    if (method.getName().equals("warn") && args.length == 1) {
                        warnings.add((String) args[0]);
                        return null;
                    }
                    throw new UnsupportedOperationException(method.toString());
                });
    }
}

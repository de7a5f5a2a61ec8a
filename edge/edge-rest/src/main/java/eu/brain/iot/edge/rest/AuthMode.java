package eu.brain.iot.edge.rest;

import java.util.Arrays;
import java.util.Locale;

import org.osgi.service.log.Logger;

/**
 * The policy of the {@code auth} setting: when the API requires its token. An unknown value does not take the API
 * down: it is refused by name in the log, and the safe default ({@link #AUTO}) applies. There is no value that turns
 * authentication off.
 */
enum AuthMode {
    /** The token when the API is bound to anything but loopback. */
    AUTO,
    /** The token always. */
    TOKEN;

    static AuthMode of(String value, Logger log) {
        String name = value == null ? "" : value.strip().toLowerCase(Locale.ROOT);
        for (AuthMode m : values()) {
            if (m.setting().equals(name)) {
                return m;
            }
        }
        log.error("configuration " + RestConfig.PID + ": auth='" + value + "' is not a value of this setting ("
                + Arrays.stream(values()).map(AuthMode::setting).toList() + ": 'auto' requires the API token when the "
                + "API is bound to anything but loopback, 'token' always); the API uses 'auto', the safe default. "
                + "Authentication cannot be turned off");
        return AUTO;
    }

    String setting() {
        return name().toLowerCase(Locale.ROOT);
    }

    boolean tokenRequired(boolean loopbackOnly) {
        return this == TOKEN || !loopbackOnly;
    }
}

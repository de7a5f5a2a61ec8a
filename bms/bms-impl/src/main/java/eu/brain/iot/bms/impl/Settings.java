package eu.brain.iot.bms.impl;

import java.util.List;

/**
 * The BMS's configuration, checked. A bad value is refused with the property's name, what it was and what it must
 * be, so that the previous settings stay in force.
 */
record Settings(int maxHeldEvents, long negativeCacheMs, long retryInitialMs, long retryMaxMs,
        long installDeadlineMs, long handoverGraceMs, long sweepIntervalMs, List<String> ignoredTypes,
        int historySize, long restartGraceMs) {

    static final Settings DEFAULTS = new Settings(65_536, 60_000, 500, 30_000, 120_000, 0, 1_000, List.of(),
            256, 1_000);

    Settings {
        atLeast("max.held.events", maxHeldEvents, 1);
        atLeast("negative.cache.ms", negativeCacheMs, 0);
        atLeast("retry.initial.ms", retryInitialMs, 1);
        atLeast("retry.max.ms", retryMaxMs, 1);
        atLeast("install.deadline.ms", installDeadlineMs, 1);
        atLeast("handover.grace.ms", handoverGraceMs, 0);
        atLeast("sweep.interval.ms", sweepIntervalMs, 1);
        atLeast("history.size", historySize, 1);
        atLeast("restart.grace.ms", restartGraceMs, 0);
        if (retryMaxMs < retryInitialMs) {
            throw new IllegalArgumentException("retry.max.ms (" + retryMaxMs + ") is below retry.initial.ms ("
                    + retryInitialMs + ") in configuration PID " + BehaviourManagerComponent.PID
                    + ": make it at least as large");
        }
        ignoredTypes = List.copyOf(ignoredTypes);
    }

    static Settings from(BmsConfig config) {
        return new Settings(config.max_held_events(), config.negative_cache_ms(), config.retry_initial_ms(),
                config.retry_max_ms(), config.install_deadline_ms(), config.handover_grace_ms(),
                config.sweep_interval_ms(), config.ignored_types() == null ? List.of()
                        : List.of(config.ignored_types()), config.history_size(), config.restart_grace_ms());
    }

    /** The delay before attempt {@code attempt + 1}, after {@code attempt} failures: doubling, capped. */
    long backoff(int attempt) {
        long delay = retryInitialMs;
        for (int i = 1; i < attempt && delay < retryMaxMs; i++) {
            delay *= 2;
        }
        return Math.min(delay, retryMaxMs);
    }

    /** Whether the type is one never searched for ({@code ignored.types}). */
    boolean ignored(String eventType) {
        for (String pattern : ignoredTypes) {
            if (pattern.endsWith("*") ? eventType.startsWith(pattern.substring(0, pattern.length() - 1))
                    : eventType.equals(pattern)) {
                return true;
            }
        }
        return false;
    }

    private static void atLeast(String property, long value, long least) {
        if (value < least) {
            throw new IllegalArgumentException(property + " must be at least " + least + ", was " + value
                    + " (configuration PID " + BehaviourManagerComponent.PID + ")");
        }
    }
}

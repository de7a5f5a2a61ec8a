package eu.brain.iot.bis.impl.install;

/**
 * An installed behaviour found not active was started again: when (ms since the epoch), why, and how often since
 * the installer started. Immutable.
 */
public record Restart(long at, String why, int count) {
}

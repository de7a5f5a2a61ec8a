package eu.brain.iot.bis.impl.repo;

/**
 * One index as {@code bis:repos} shows it. Immutable snapshot.
 *
 * @param readAt when its content in use was read (ms since the epoch), 0 if never
 * @param checkedAt when it was last checked for changes, 0 if never
 * @param signature "valid (key ...)", "not checked (no trusted.keys)", "REFUSED: ...", or "-" before a first read
 * @param failures consecutive failed reads
 * @param lastError the last read's problem, or null
 */
public record IndexStatus(String url, int resources, int behaviours, long readAt, long checkedAt, String signature,
        int failures, String lastError) {
}

package eu.brain.iot.bis.impl.journal;

/**
 * One bundle the installer put into the framework, as the journal keeps it.
 *
 * @param location the location it was installed under (its URL in the index): how the installer finds it again
 */
public record BundleFact(String symbolicName, String version, String sha256, String location) {
}

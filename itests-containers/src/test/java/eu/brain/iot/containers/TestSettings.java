package eu.brain.iot.containers;

import java.nio.file.Path;

/**
 * What the build passes to the container tests (system properties set in this module's pom).
 *
 * @param root   the checkout's root folder, where the jars the images hold were built
 * @param work   this module's scratch folder (the jlinked runtime, the tests' files)
 * @param prefix prefix of every image, container and network name these tests make
 */
record TestSettings(Path root, Path work, String prefix) {
    /** The label on every container and network these tests make; its value is the prefix. */
    static final String LABEL = "eu.brain.iot.containers.test";

    static TestSettings fromSystemProperties() {
        return new TestSettings(Path.of(System.getProperty("fabric.root", "..")).toAbsolutePath().normalize(),
                Path.of(System.getProperty("containers.work", "target/containers")).toAbsolutePath(),
                System.getProperty("containers.prefix", "brain-iot-test-"));
    }
}

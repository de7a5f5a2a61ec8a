package eu.brain.iot.bis.integration;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyPair;
import java.util.List;
import java.util.function.Predicate;
import java.util.stream.Stream;

import org.osgi.framework.namespace.IdentityNamespace;
import org.osgi.resource.Resource;

import aQute.bnd.osgi.repository.XMLResourceGenerator;
import aQute.bnd.osgi.repository.XMLResourceParser;
import eu.brain.iot.bis.sign.IndexSigning;

/**
 * A copy of the real test index (target/test-repository: the real behaviour bundles and the index bnd's indexer
 * wrote at build time) in a directory of its own, which a test may sign, tamper with or re-index.
 */
final class TestRepository {

    static final String DOOR = "eu.brain.iot.behaviours.door";
    static final String ROBOT = "eu.brain.iot.behaviours.robot";
    static final String ORCHESTRATOR = "eu.brain.iot.behaviours.orchestrator";
    static final String EVENTS = "eu.brain.iot.behaviours.events";
    /** The warehouse helpers the robot, door and orchestrator behaviours share. */
    static final String WAREHOUSE = "eu.brain.iot.behaviours.warehouse";
    /** The edge's API bundles, which the behaviours import (they drive the fleet through the edge). */
    static final String EDGE_API = "eu.brain.iot.edge.api";
    static final String EDGE_MODEL_API = "eu.brain.iot.edge.model.api";
    static final String DOOR_CLOSED = "eu.brain.iot.behaviours.events.DoorBehaviorClosed";
    static final String ROBOT_UNLOAD = "eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation";
    static final String ROBOT_COLLISION = "eu.brain.iot.behaviours.events.ConnectorResolveCollision";

    final Path dir;
    final Path index;

    private TestRepository(Path dir) {
        this.dir = dir;
        this.index = dir.resolve("index.xml");
    }

    /** @param source the framework property bis.test.repository */
    static TestRepository copy(String source, Path target) throws IOException {
        Files.createDirectories(target);
        try (Stream<Path> files = Files.list(Path.of(source))) {
            for (Path f : files.toList()) {
                Files.copy(f, target.resolve(f.getFileName()));
            }
        }
        return new TestRepository(target);
    }

    void sign(KeyPair keys) throws Exception {
        sign(keys, index);
    }

    static void sign(KeyPair keys, Path file) throws Exception {
        Files.writeString(file.resolveSibling(file.getFileName() + IndexSigning.SUFFIX),
                IndexSigning.sign(keys.getPrivate(), Files.readAllBytes(file)), StandardCharsets.US_ASCII);
    }

    Path publicKey(KeyPair keys, String name) throws IOException {
        Path file = dir.resolveSibling(name + ".pub");
        Files.writeString(file, IndexSigning.publicKeyPem(keys.getPublic()), StandardCharsets.US_ASCII);
        return file;
    }

    /** Rewrites the index (with bnd's generator) without the resources that match. */
    void drop(Predicate<String> symbolicName) throws Exception {
        List<Resource> kept = XMLResourceParser.getResources(index.toUri()).stream()
                .filter(r -> !symbolicName.test(identity(r))).toList();
        XMLResourceGenerator generator = new XMLResourceGenerator().resources(kept).name("test").base(dir.toUri());
        try (OutputStream out = Files.newOutputStream(index)) {
            generator.save(out);
        }
    }

    /** The bundle file of a resource. */
    Path jar(String artifactPrefix) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(f -> f.getFileName().toString().startsWith(artifactPrefix)).findFirst().orElseThrow();
        }
    }

    private static String identity(Resource r) {
        return String.valueOf(r.getCapabilities(IdentityNamespace.IDENTITY_NAMESPACE).get(0).getAttributes()
                .get(IdentityNamespace.IDENTITY_NAMESPACE));
    }
}

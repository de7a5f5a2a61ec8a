package eu.brain.iot.containers;

import com.github.dockerjava.api.DockerClient;
import com.github.dockerjava.api.exception.DockerException;
import com.github.dockerjava.api.exception.NotFoundException;
import com.github.dockerjava.api.model.Image;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.testcontainers.DockerClientFactory;
import org.testcontainers.images.builder.ImageFromDockerfile;

/**
 * The images of the container tests, built from this checkout's own artifacts (no registry is involved):
 * <ul>
 * <li>{@code <prefix>jre}: {@code FROM scratch}, the jlinked Java runtime and its libraries ({@link JavaRuntimeRootfs});
 * <li>{@code <prefix>node}: the runtime and {@code node/target/fabric-node.jar}, with what its Bundle Installer reads
 * (the behaviour repository's index and bundles, its public key, {@code node/config/eu.brain.iot.bis.cfg}) under
 * {@code /app} laid out as in the checkout ({@code -Dfabric.node.root=/app});
 * <li>{@code <prefix>broker}: the runtime and {@code broker/target/broker.jar} with its {@code lib/};
 * <li>{@code <prefix>robot-sim}: the runtime and {@code robot-sim/target/robot-sim.jar}.
 * </ul>
 * Each is tagged with a digest of what went into it (names, sizes, modification times), built only when no image
 * has that tag, and older tags of the same name are removed.
 *
 * <p>Threads: {@link #build} is synchronized; one test thread builds, Testcontainers' build runs on its threads.
 */
final class FabricImages {
    /** The image names, each with its tag. */
    record Names(String node, String broker, String robotSim) {
    }

    private static Names built;

    private FabricImages() {
    }

    static synchronized Names build(TestSettings settings) {
        if (built != null) {
            return built;
        }
        Path root = settings.root();
        Path rootfs = JavaRuntimeRootfs.build(settings.work());
        String jre = image(settings, "jre", """
                FROM scratch
                COPY rootfs/ /
                ENV JAVA_HOME=%s PATH=%s/bin
                WORKDIR /app
                ENTRYPOINT ["%s/bin/java"]
                """.formatted(JavaRuntimeRootfs.JAVA_HOME, JavaRuntimeRootfs.JAVA_HOME, JavaRuntimeRootfs.JAVA_HOME),
                Map.of("rootfs", rootfs));

        Map<String, Path> node = new LinkedHashMap<>();
        node.put("app/fabric-node.jar", required(root, "node/target/fabric-node.jar", "mvn -pl node -am package"));
        node.put("app/repository/target/repository", required(root, "repository/target/repository",
                "mvn -pl repository -am package"));
        node.put("app/repository/target/index-signing.pub", required(root, "repository/target/index-signing.pub",
                "mvn -pl repository -am package"));
        node.put("app/node/config/eu.brain.iot.bis.cfg", required(root, "node/config/eu.brain.iot.bis.cfg", "git"));
        String nodeImage = image(settings, "node", from(jre) + "COPY app/ /app/\n", node);

        Path brokerLib = required(root, "broker/target/lib", "mvn -pl broker package");
        String broker = image(settings, "broker", from(jre) + "COPY app/ /app/\nCOPY natives/ /\n", Map.of(
                "app/broker.jar", required(root, "broker/target/broker.jar", "mvn -pl broker package"),
                "app/lib", brokerLib,
                "natives", nativesRootfs(settings.work().resolve("broker-natives"), brokerLib, rootfs)));
        String robotSim = image(settings, "robot-sim", from(jre) + "COPY app/ /app/\n", Map.of(
                "app/robot-sim.jar", required(root, "robot-sim/target/robot-sim.jar", "mvn -pl robot-sim package")));
        built = new Names(nodeImage, broker, robotSim);
        return built;
    }

    /**
     * A folder of the system libraries the jars' native code needs beyond what the runtime's root file system
     * holds, under their absolute paths (RocksDB's {@code libpthread.so.0} for the broker).
     */
    private static Path nativesRootfs(Path dir, Path jarFolder, Path runtimeRootfs) {
        try {
            JavaRuntimeRootfs.deleteTree(dir);
            Path rootfs = Files.createDirectories(dir.resolve("rootfs"));
            List<Path> jars;
            try (Stream<Path> files = Files.list(jarFolder)) {
                jars = files.filter(p -> p.toString().endsWith(".jar")).sorted().toList();
            }
            java.util.Set<String> missing = new java.util.TreeSet<>();
            for (String lib : JarNativeLibraries.neededBy(jars, dir.resolve("unpacked"))) {
                if (!Files.exists(runtimeRootfs.resolve(lib.substring(1)))) {
                    missing.add(lib);
                }
            }
            JavaRuntimeRootfs.copyLibraries(missing, rootfs);
            JavaRuntimeRootfs.deleteTree(dir.resolve("unpacked"));
            return rootfs;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot gather the native libraries of " + jarFolder, e);
        }
    }

    private static String from(String base) {
        return "FROM " + base + "\n";
    }

    private static Path required(Path root, String relative, String howToMake) {
        Path p = root.resolve(relative);
        if (!Files.exists(p)) {
            throw new IllegalStateException("the container images need " + p + ", which does not exist: build it ("
                    + howToMake + ") before these tests");
        }
        return p;
    }

    /** The image {@code <prefix><role>:<digest>}, built from the Dockerfile and the files when missing. */
    private static String image(TestSettings settings, String role, String dockerfile, Map<String, Path> files) {
        String repository = settings.prefix() + role;
        String name = repository + ":" + digest(dockerfile, files);
        DockerClient docker = DockerClientFactory.instance().client();
        try {
            docker.inspectImageCmd(name).exec();
            return name;
        } catch (NotFoundException e) {
            // built below
        }
        long started = System.nanoTime();
        ImageFromDockerfile build = new ImageFromDockerfile(name, false).withFileFromString("Dockerfile", dockerfile);
        files.forEach(build::withFileFromPath);
        build.get();
        System.out.printf("container tests: built image %s in %d ms%n", name, (System.nanoTime() - started) / 1_000_000);
        removeOtherTags(docker, repository, name);
        return name;
    }

    private static void removeOtherTags(DockerClient docker, String repository, String keep) {
        List<Image> images = docker.listImagesCmd().withImageNameFilter(repository).exec();
        for (Image image : images) {
            String[] tags = image.getRepoTags();
            if (tags == null || List.of(tags).contains(keep)) {
                continue;
            }
            for (String tag : tags) {
                if (tag.startsWith(repository + ":")) {
                    try {
                        docker.removeImageCmd(tag).exec();
                    } catch (DockerException e) {
                        System.out.println("container tests: could not remove the older image " + tag + ": "
                                + e.getMessage());
                    }
                }
            }
        }
    }

    /** Twelve hex digits over the Dockerfile and every file's path, size and modification time. */
    private static String digest(String dockerfile, Map<String, Path> files) {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            sha.update(dockerfile.getBytes(StandardCharsets.UTF_8));
            for (Map.Entry<String, Path> e : new java.util.TreeMap<>(files).entrySet()) {
                try (Stream<Path> walk = Files.walk(e.getValue())) {
                    for (Path p : walk.filter(Files::isRegularFile).sorted().toList()) {
                        String line = e.getKey() + "/" + e.getValue().relativize(p) + " " + Files.size(p) + " "
                                + Files.getLastModifiedTime(p).toMillis() + "\n";
                        sha.update(line.getBytes(StandardCharsets.UTF_8));
                    }
                }
            }
            return HexFormat.of().formatHex(sha.digest()).substring(0, 12);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}

package eu.brain.iot.containers;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The root file system of the images' base: a Java 17 runtime made by {@code jlink} from the JDK that runs the
 * tests, the shared libraries it links to (found by {@code ldd}, copied from this machine under the same paths),
 * {@code /etc/passwd} and {@code /etc/group} with root (the JVM takes {@code user.home} from there), {@code /root}
 * and {@code /tmp}. No package manager, no shell: an image {@code FROM scratch} with this is enough for the fabric's
 * jars. Made once in the work folder and reused while the module list is the same.
 *
 * <p>Threads: {@link #build} is synchronized (one test thread makes it).
 */
final class JavaRuntimeRootfs {
    /** Where the runtime lies in the image. */
    static final String JAVA_HOME = "/opt/java";
    /**
     * Every standard module (java.se), so that no bundle's import of a JDK package goes unresolved (Felix HTTP's
     * Jetty bundle imports java.awt and java.rmi, for nothing a headless node runs), and: jdk.unsupported
     * (sun.misc.Unsafe for Netty and HiveMQ), jdk.crypto.ec (TLS to a broker), jdk.zipfs, jdk.management, jdk.net.
     */
    static final List<String> MODULES = List.of("java.se", "jdk.unsupported", "jdk.crypto.ec", "jdk.zipfs",
            "jdk.management", "jdk.net");
    /** AWT's window-system, sound, font and image libraries: a headless JVM never loads them, nor their X11 libraries. */
    private static final Set<String> UNUSED_NATIVE = Set.of("libawt_xawt.so", "libsplashscreen.so", "libjsound.so",
            "libfontmanager.so", "liblcms.so", "libjavajpeg.so", "libjawt.so", "libmlib_image.so");
    private static final Pattern LDD_PATH = Pattern.compile("(/\\S+) \\(0x[0-9a-f]+\\)");
    private static final String MARKER = ".modules";

    private JavaRuntimeRootfs() {
    }

    /** The root file system under {@code work/jre-rootfs}, made when missing or made for other modules. */
    static synchronized Path build(Path work) {
        Path rootfs = work.resolve("jre-rootfs");
        String wanted = String.join(",", MODULES) + " " + System.getProperty("java.version");
        try {
            Path marker = rootfs.resolve(MARKER);
            if (Files.exists(marker) && Files.readString(marker).equals(wanted)) {
                return rootfs;
            }
            deleteTree(rootfs);
            Path javaHome = rootfs.resolve(JAVA_HOME.substring(1));
            Files.createDirectories(javaHome.getParent());
            run(List.of(jlink().toString(), "--add-modules", String.join(",", MODULES), "--strip-debug",
                    "--no-man-pages", "--no-header-files", "--compress=2", "--output", javaHome.toString()));
            copyLibraries(sharedLibraries(javaHome), rootfs);
            Files.createDirectories(rootfs.resolve("etc"));
            Files.writeString(rootfs.resolve("etc/passwd"), "root:x:0:0:root:/root:/nonexistent\n");
            Files.writeString(rootfs.resolve("etc/group"), "root:x:0:\n");
            Files.createDirectories(rootfs.resolve("root"));
            Files.createDirectories(rootfs.resolve("tmp"));
            Files.writeString(marker, wanted, StandardCharsets.UTF_8);
            return rootfs;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot make the images' Java runtime under " + rootfs, e);
        }
    }

    /** Copies each library (an absolute path on this machine) to the same path under {@code rootfs}. */
    static void copyLibraries(Set<String> libraries, Path rootfs) throws IOException {
        for (String library : libraries) {
            Path target = rootfs.resolve(library.substring(1));
            if (!Files.exists(target)) {
                Files.createDirectories(target.getParent());
                Files.copy(Path.of(library).toRealPath(), target, java.nio.file.StandardCopyOption.COPY_ATTRIBUTES);
            }
        }
    }

    /** The absolute paths {@code ldd} names for one binary (those it cannot find left out). */
    static Set<String> linkedLibraries(Path binary) throws IOException {
        Set<String> libraries = new TreeSet<>();
        Matcher m = LDD_PATH.matcher(run(List.of("ldd", binary.toString())));
        while (m.find()) {
            libraries.add(m.group(1));
        }
        return libraries;
    }

    private static Path jlink() {
        Path jlink = Path.of(System.getProperty("java.home"), "bin", "jlink");
        if (!Files.isExecutable(jlink)) {
            throw new IllegalStateException("no jlink at " + jlink + ": the container tests need a JDK (Debian: "
                    + "openjdk-17-jdk-headless), not only a JRE, to make their images' Java runtime");
        }
        return jlink;
    }

    /** Every library outside the runtime that its launcher and native libraries link to, by absolute path. */
    private static Set<String> sharedLibraries(Path javaHome) throws IOException {
        List<Path> binaries;
        try (Stream<Path> files = Files.walk(javaHome)) {
            binaries = files.filter(Files::isRegularFile)
                    .filter(p -> p.getParent().getFileName().toString().equals("bin")
                            || p.getFileName().toString().endsWith(".so"))
                    .filter(p -> !UNUSED_NATIVE.contains(p.getFileName().toString()))
                    .toList();
        }
        Set<String> libraries = new TreeSet<>();
        for (Path binary : binaries) {
            linkedLibraries(binary).stream().filter(l -> !l.startsWith(javaHome.toString())).forEach(libraries::add);
        }
        return libraries;
    }

    private static String run(List<String> command) throws IOException {
        Process p = new ProcessBuilder(new ArrayList<>(command)).redirectErrorStream(true).start();
        try {
            byte[] out = p.getInputStream().readAllBytes();
            if (!p.waitFor(5, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                throw new IOException(command.get(0) + " did not end within 5 minutes");
            }
            String text = new String(out, StandardCharsets.UTF_8);
            if (p.exitValue() != 0 && !command.get(0).equals("ldd")) {
                throw new IOException(String.join(" ", command) + " failed (exit code " + p.exitValue() + "): " + text);
            }
            return text;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while running " + command.get(0), e);
        }
    }

    static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) {
            return;
        }
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path p : files.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }
}

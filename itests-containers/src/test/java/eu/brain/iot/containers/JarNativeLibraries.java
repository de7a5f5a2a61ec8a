package eu.brain.iot.containers;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Enumeration;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

/**
 * The system libraries that native code packed inside jars links to (RocksDB's in HiveMQ, JNA's in OSHI): such code
 * is unpacked at run time, so {@code ldd} on the Java runtime does not see what it needs (RocksDB needs
 * {@code libpthread.so.0}, which the JVM itself does not). Only libraries built for this machine's architecture
 * and C library are looked at; the others (macOS, Windows, musl, other CPUs) are never loaded here.
 */
final class JarNativeLibraries {
    /** ELF header: e_machine of x86-64. */
    private static final int EM_X86_64 = 62;
    private static final int EM_AARCH64 = 183;

    private JarNativeLibraries() {
    }

    /** Absolute paths of the libraries the jars' native code links to, for {@link JavaRuntimeRootfs#copyLibraries}. */
    static Set<String> neededBy(List<Path> jars, Path scratch) {
        Set<String> libraries = new TreeSet<>();
        try {
            Files.createDirectories(scratch);
            for (Path jar : jars) {
                try (ZipFile zip = new ZipFile(jar.toFile())) {
                    Enumeration<? extends ZipEntry> entries = zip.entries();
                    while (entries.hasMoreElements()) {
                        ZipEntry e = entries.nextElement();
                        String name = e.getName();
                        if (!name.endsWith(".so") || name.contains("musl")) {
                            continue;
                        }
                        Path so = scratch.resolve(name.replace('/', '_'));
                        try (InputStream in = zip.getInputStream(e)) {
                            Files.copy(in, so, StandardCopyOption.REPLACE_EXISTING);
                        }
                        if (forThisMachine(so)) {
                            libraries.addAll(JavaRuntimeRootfs.linkedLibraries(so));
                        }
                    }
                }
            }
            return libraries;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the native libraries in " + jars, e);
        }
    }

    /** Whether the file is a 64-bit little-endian ELF object for this JVM's architecture. */
    private static boolean forThisMachine(Path so) throws IOException {
        byte[] header = new byte[20];
        try (InputStream in = Files.newInputStream(so)) {
            if (in.readNBytes(header, 0, header.length) < header.length) {
                return false;
            }
        }
        boolean elf64le = header[0] == 0x7f && header[1] == 'E' && header[2] == 'L' && header[3] == 'F'
                && header[4] == 2 && header[5] == 1;
        int machine = (header[18] & 0xff) | (header[19] & 0xff) << 8;
        String arch = System.getProperty("os.arch");
        int wanted = arch.equals("aarch64") ? EM_AARCH64 : EM_X86_64;
        return elf64le && machine == wanted;
    }
}

package eu.brain.iot.bms.integration;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;

import aQute.bnd.osgi.repository.XMLResourceGenerator;
import aQute.bnd.osgi.resource.ResourceBuilder;

/**
 * A real R5 repository made by the test: a behaviour bundle built from classes of this test bundle (so it has its
 * own copies of them), with the {@code eu.brain.iot.behaviour} capability bnd would generate, and an index of it
 * written by bnd's repository support (identity, packages, SHA-256 content with a URL relative to the index).
 */
final class TestRepository {

    final Path dir;
    final Path index;
    final Path jar;

    private TestRepository(Path dir, Path jar) {
        this.dir = dir;
        this.index = dir.resolve("index.xml");
        this.jar = jar;
    }

    /** Writes {@code <symbolicName>.jar} (consuming {@code consumed}) and index.xml into {@code dir}. */
    static TestRepository create(Path dir, String symbolicName, Class<?> activator, String[] consumed,
            Class<?>... classes) throws Exception {
        Files.createDirectories(dir);
        Path jar = dir.resolve(symbolicName + ".jar");
        Manifest manifest = new Manifest();
        Attributes main = manifest.getMainAttributes();
        main.put(Attributes.Name.MANIFEST_VERSION, "1.0");
        main.putValue("Bundle-ManifestVersion", "2");
        main.putValue("Bundle-SymbolicName", symbolicName);
        main.putValue("Bundle-Version", "1.0.0");
        main.putValue("Bundle-Activator", activator.getName());
        main.putValue("Import-Package", "org.osgi.framework;version=\"[1.8,2)\", eu.brain.iot.eventing.api");
        main.putValue("Provide-Capability", "eu.brain.iot.behaviour;consumed:List<String>=\""
                + String.join(",", consumed) + "\"");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar), manifest)) {
            add(out, activator);
            for (Class<?> c : classes) {
                add(out, c);
            }
        }
        TestRepository repository = new TestRepository(dir, jar);
        repository.reindex();
        return repository;
    }

    /** (Re)writes the index from the jar as it is now. */
    void reindex() throws Exception {
        ResourceBuilder resource = new ResourceBuilder();
        resource.addFile(jar.toFile(), jar.toUri());
        XMLResourceGenerator generator = new XMLResourceGenerator().resource(resource.build()).name("bms itests")
                .base(dir.toUri());
        try (OutputStream out = Files.newOutputStream(index)) {
            generator.save(out);
        }
    }

    /** Changes the bundle's bytes after indexing: its SHA-256 no longer matches the index. */
    void tamper() throws IOException {
        byte[] bytes = Files.readAllBytes(jar);
        bytes[bytes.length / 2] ^= 0x5A;
        Files.write(jar, bytes);
    }

    private static void add(JarOutputStream jar, Class<?> type) throws IOException {
        String path = type.getName().replace('.', '/') + ".class";
        jar.putNextEntry(new JarEntry(path));
        try (InputStream in = type.getClassLoader().getResourceAsStream(path)) {
            in.transferTo(jar);
        }
        jar.closeEntry();
    }
}

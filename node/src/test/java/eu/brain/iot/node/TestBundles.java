package eu.brain.iot.node;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;

/**
 * Bundles for tests: a jar with nothing but a manifest, which is all a bundle needs to be installed and started.
 * <p>
 * Kept, not replaced by osgi-test's {@code @InjectInstalledBundle}: these tests are not in-framework tests. They
 * launch a framework of their own ({@code BundleHealthTest}, which needs bundles with broken or unresolvable
 * headers written per test) or a whole node process ({@code FabricNodeSmokeTest}, which drops a jar file into the
 * node's configuration folder), and osgi-test installs bundles only into the framework the test itself runs in.
 */
public final class TestBundles {

    private TestBundles() {
    }

    /** Writes bundle {@code symbolicName} 1.0.0 with the extra headers given as name, value, name, value... */
    public static Path write(Path jar, String symbolicName, String... headers) throws IOException {
        Manifest manifest = new Manifest();
        Attributes main = manifest.getMainAttributes();
        main.put(Attributes.Name.MANIFEST_VERSION, "1.0");
        main.putValue("Bundle-ManifestVersion", "2");
        main.putValue("Bundle-SymbolicName", symbolicName);
        main.putValue("Bundle-Version", "1.0.0");
        for (int i = 0; i < headers.length; i += 2) {
            main.putValue(headers[i], headers[i + 1]);
        }
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream ignored = new JarOutputStream(out, manifest)) {
            return jar;
        }
    }
}

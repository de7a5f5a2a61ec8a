package eu.brain.iot.bip.generate;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/** Compiles generated sources with the JDK's compiler, against the eventing API and the OSGi annotations. */
final class InMemoryCompiler {

    private InMemoryCompiler() {
    }

    /** @return a class loader over the compiled classes; fails the test with javac's messages on errors */
    static ClassLoader compile(List<JavaFile> files, Path out) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        List<JavaFileObject> sources = new ArrayList<>();
        for (JavaFile f : files) {
            sources.add(new SimpleJavaFileObject(java.net.URI.create("string:///" + f.relativePath()),
                    JavaFileObject.Kind.SOURCE) {
                @Override
                public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                    return f.source();
                }
            });
        }
        String classpath = String.join(java.io.File.pathSeparator, location(eu.brain.iot.eventing.api.BrainIoTEvent.class),
                location(org.osgi.service.component.annotations.Component.class),
                location(org.osgi.annotation.bundle.Capability.class), location(org.osgi.dto.DTO.class));
        try (StandardJavaFileManager fm = javac.getStandardFileManager(diagnostics, Locale.ROOT, null)) {
            Files.createDirectories(out);
            boolean ok = javac.getTask(null, fm, diagnostics, List.of("-d", out.toString(), "-cp", classpath,
                    "-Xlint:all", "-Werror", "-proc:none"), null, sources).call();
            if (!ok) {
                StringBuilder message = new StringBuilder("generated code does not compile:\n");
                for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
                    message.append(d).append('\n');
                }
                throw new AssertionError(message);
            }
            return new URLClassLoader(new URL[] {out.toUri().toURL()}, InMemoryCompiler.class.getClassLoader());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String location(Class<?> type) {
        try {
            return Path.of(type.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}

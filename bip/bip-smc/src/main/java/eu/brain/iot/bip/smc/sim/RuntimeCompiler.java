package eu.brain.iot.bip.smc.sim;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.FileObject;
import javax.tools.ForwardingJavaFileManager;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileManager;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import eu.brain.iot.bip.generate.JavaFile;
import eu.brain.iot.bip.smc.runtime.SimulatedSystem;

/**
 * Compiles generated sources in memory with the JDK's compiler (javax.tools) and loads them in a fresh class loader
 * whose parent is the model checker's, so the classes of one model never meet another's. The loader defines every class it
 * compiled itself (child first): the deployed classes of the same names (a behaviour jar on the class path of a test
 * or of the Maven goal) are never used in their place, so the code compiled from the model is the code that runs.
 */
final class RuntimeCompiler {

    /** The compiler is missing (a JRE without jdk.compiler) or the generated code does not compile. */
    static final class CompileException extends Exception {
        private static final long serialVersionUID = 1L;

        CompileException(String message) {
            super(message);
        }
    }

    private RuntimeCompiler() {
    }

    static ClassLoader compile(List<JavaFile> files, List<Path> classpath) throws CompileException {
        return compile(files, classpath, RuntimeCompiler.class.getClassLoader());
    }

    /** @param parent where every class that was not compiled here comes from (the model checker's runtime, the JDK) */
    static ClassLoader compile(List<JavaFile> files, List<Path> classpath, ClassLoader parent)
            throws CompileException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new CompileException("no Java compiler in this runtime (run on a JDK, not a JRE)");
        }
        List<JavaFileObject> sources = new ArrayList<>();
        for (JavaFile f : files) {
            sources.add(new SimpleJavaFileObject(URI.create("string:///" + f.relativePath().toString()
                    .replace(File.separatorChar, '/')), JavaFileObject.Kind.SOURCE) {
                @Override
                public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                    return f.source();
                }
            });
        }
        List<String> cp = new ArrayList<>();
        cp.add(location(SimulatedSystem.class));
        classpath.forEach(p -> cp.add(p.toString()));
        Map<String, byte[]> classes = new HashMap<>();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager standard = javac.getStandardFileManager(diagnostics, Locale.ROOT, null);
                JavaFileManager fm = new ForwardingJavaFileManager<>(standard) {
                    @Override
                    public JavaFileObject getJavaFileForOutput(Location location, String className,
                            JavaFileObject.Kind kind, FileObject sibling) {
                        return new SimpleJavaFileObject(URI.create("mem:///" + className.replace('.', '/') + ".class"),
                                kind) {
                            @Override
                            public OutputStream openOutputStream() {
                                return new ByteArrayOutputStream() {
                                    @Override
                                    public void close() {
                                        classes.put(className, toByteArray());
                                    }
                                };
                            }
                        };
                    }
                }) {
            boolean ok = javac.getTask(null, fm, diagnostics, List.of("-classpath", String.join(File.pathSeparator, cp),
                    "-proc:none", "-nowarn", "-g:none", "--release", "17"), null, sources).call();
            if (!ok) {
                StringBuilder message = new StringBuilder("the Java generated for simulation does not compile "
                        + "(please report it with the model):");
                for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
                    if (d.getKind() == Diagnostic.Kind.ERROR) {
                        message.append('\n').append(d);
                    }
                }
                throw new CompileException(message.toString());
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return new GeneratedClassLoader(classes, parent);
    }

    /**
     * Child first for the classes it holds: a class compiled here is defined here even when the parent knows a class
     * of that name (the deployed one: same name, another runtime package, so the generated bridge could not reach
     * its package-private fields); every other class comes from the parent. Classes are defined under the lock
     * {@link ClassLoader#getClassLoadingLock} gives (the loader is parallel capable, sampling threads share it).
     */
    static final class GeneratedClassLoader extends ClassLoader {
        static {
            registerAsParallelCapable();
        }

        private final Map<String, byte[]> classes;

        GeneratedClassLoader(Map<String, byte[]> classes, ClassLoader parent) {
            super("bip-smc-generated", parent);
            this.classes = Map.copyOf(classes);
        }

        @Override
        protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
            byte[] bytes = classes.get(name);
            if (bytes == null) {
                return super.loadClass(name, resolve);
            }
            synchronized (getClassLoadingLock(name)) {
                Class<?> c = findLoadedClass(name);
                if (c == null) {
                    c = defineClass(name, bytes, 0, bytes.length);
                }
                if (resolve) {
                    resolveClass(c);
                }
                return c;
            }
        }

        @Override
        protected Class<?> findClass(String name) throws ClassNotFoundException {
            throw new ClassNotFoundException(name);
        }
    }

    private static String location(Class<?> type) {
        try {
            return Path.of(type.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (URISyntaxException | NullPointerException e) {
            return System.getProperty("java.class.path");
        }
    }
}

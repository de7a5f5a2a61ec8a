package eu.brain.iot.bip.maven;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.apache.maven.project.MavenProject;

import eu.brain.iot.bip.generate.Toolchain;

/**
 * {@code bip:generate}: checks the module's BIP models and writes their Java into
 * {@code target/generated-sources/bip}, which becomes a compile source root. Atom classes and extern interfaces
 * for every atom type of the module; a smart behaviour for each of them the root compound instantiates; the event
 * types when the root compound is one of the module's.
 */
@Mojo(name = "generate", defaultPhase = LifecyclePhase.GENERATE_SOURCES, threadSafe = true)
public class GenerateMojo extends AbstractBipMojo {

    @Parameter(property = "bip.outputDirectory", defaultValue = "${project.build.directory}/generated-sources/bip")
    private File outputDirectory;

    /**
     * Whether a root compound that cannot be realised on the event bus (a hierarchical connector, a connector with
     * neither trigger nor coordinator) fails the build; when false, only atom classes and extern interfaces are
     * generated and the reasons are logged as warnings.
     */
    @Parameter(property = "bip.strict", defaultValue = "true")
    private boolean strict;

    @Parameter(defaultValue = "${project}", readonly = true, required = true)
    private MavenProject project;

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        if (skip) {
            getLog().info("bip:generate skipped");
            return;
        }
        Toolchain tool = loadAndCheck();
        Path out = outputDirectory.toPath();
        clean(out);
        int written = tool.generate(out, root, strict);
        report(tool.diagnostics());
        project.addCompileSourceRoot(outputDirectory.getAbsolutePath());
        getLog().info("BIP: wrote " + written + " Java file(s) to " + out + ":");
        tool.summary().forEach(line -> getLog().info("  " + line));
    }

    /** Removes Java left from an earlier run, so a renamed atom leaves no stale class behind. */
    private static void clean(Path out) throws MojoExecutionException {
        if (!Files.isDirectory(out)) {
            return;
        }
        try (Stream<Path> walk = Files.walk(out)) {
            for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        } catch (IOException e) {
            throw new MojoExecutionException("cannot clean " + out + ": " + e.getMessage(), e);
        }
    }
}

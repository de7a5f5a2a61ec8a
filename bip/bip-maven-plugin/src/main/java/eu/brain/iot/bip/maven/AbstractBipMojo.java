package eu.brain.iot.bip.maven;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.Parameter;

import eu.brain.iot.bip.diag.Diagnostic;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.generate.Toolchain;

/** What both goals share: finding the model files, loading and checking them, reporting problems. */
abstract class AbstractBipMojo extends AbstractMojo {

    /** The directory of this module's models; every {@code *.bip} under it is checked. */
    @Parameter(property = "bip.sourceDirectory", defaultValue = "${project.basedir}/src/main/bip")
    protected File sourceDirectory;

    /** Directories where packages named by {@code use} are found (as {@code <Package>.bip}), like bipc -I. */
    @Parameter
    protected List<File> modelPath = new ArrayList<>();

    /** The root compound type of the system (default: the only one, or the last one of this module). */
    @Parameter(property = "bip.root")
    protected String root;

    /** Skips the goal. */
    @Parameter(property = "bip.skip", defaultValue = "false")
    protected boolean skip;

    /** Loads and checks the models; fails the build on errors, logging every problem as file:line:col. */
    protected Toolchain loadAndCheck() throws MojoExecutionException, MojoFailureException {
        List<Path> files = modelFiles();
        List<Path> path = new ArrayList<>();
        path.add(sourceDirectory.toPath());
        modelPath.forEach(f -> path.add(f.toPath()));
        Diagnostics diagnostics = new Diagnostics();
        Toolchain tool = Toolchain.load(files, path, diagnostics, root);
        tool.check();
        report(diagnostics);
        return tool;
    }

    protected List<Path> modelFiles() throws MojoExecutionException {
        if (!sourceDirectory.isDirectory()) {
            return List.of();
        }
        try (Stream<Path> walk = Files.walk(sourceDirectory.toPath())) {
            return walk.filter(p -> p.toString().endsWith(".bip")).sorted().toList();
        } catch (IOException e) {
            throw new MojoExecutionException("cannot list the models in " + sourceDirectory + ": " + e.getMessage(), e);
        }
    }

    protected void report(Diagnostics diagnostics) throws MojoFailureException {
        for (Diagnostic d : diagnostics.sorted()) {
            if (d.isError()) {
                getLog().error(d.toString());
            } else {
                getLog().warn(d.toString());
            }
        }
        if (diagnostics.hasErrors()) {
            throw new MojoFailureException("BIP models have " + diagnostics.errorCount() + " error(s); see above"
                    + (diagnostics.hiddenCount() == 0 ? "" : " (and " + diagnostics.hiddenCount() + " unknown name(s) "
                            + "in packages that use a package not found, not shown)"));
        }
    }
}

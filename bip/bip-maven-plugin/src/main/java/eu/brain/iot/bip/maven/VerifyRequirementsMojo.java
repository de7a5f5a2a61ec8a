package eu.brain.iot.bip.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.apache.maven.plugins.annotations.ResolutionScope;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.smc.RequirementsCheck;
import eu.brain.iot.bip.smc.engine.PointResult;

/**
 * {@code bip:verify-requirements} (phase {@code verify}): checks the module's requirements file (PBLTL queries with
 * thresholds, bip/README "Requirements file") on its model by statistical model checking, writes the report under
 * {@code target/smc}, and fails the build naming each refuted requirement with its estimate and confidence.
 */
@Mojo(name = "verify-requirements", defaultPhase = LifecyclePhase.VERIFY, threadSafe = true,
        requiresDependencyResolution = ResolutionScope.TEST)
public class VerifyRequirementsMojo extends AbstractBipMojo {

    /** The requirements file; when it does not exist the goal does nothing. */
    @Parameter(property = "bip.smc.requirements", defaultValue = "${project.basedir}/src/main/bip/requirements.smc")
    protected File requirements;

    /** Where report.txt, report.csv and the sweep plots are written. */
    @Parameter(property = "bip.smc.reportDirectory", defaultValue = "${project.build.directory}/smc")
    protected File reportDirectory;

    /** Sampling threads (default: every core). */
    @Parameter(property = "bip.smc.threads")
    protected Integer threads;

    /** Overrides the requirements file's seed. */
    @Parameter(property = "bip.smc.seed")
    protected Long seed;

    /** Skips this goal only. */
    @Parameter(property = "bip.smc.skip", defaultValue = "false")
    protected boolean smcSkip;

    /** Where the class named by the file's {@code set externs} is found (the module's test class path). */
    @Parameter(defaultValue = "${project.testClasspathElements}", readonly = true)
    protected List<String> classpathElements = new ArrayList<>();

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        if (skip || smcSkip) {
            getLog().info("bip:verify-requirements skipped");
            return;
        }
        if (requirements == null || !requirements.isFile()) {
            getLog().info("bip:verify-requirements: no requirements file " + requirements + ", nothing to verify");
            return;
        }
        List<Path> path = new ArrayList<>();
        path.add(sourceDirectory.toPath());
        modelPath.forEach(f -> path.add(f.toPath()));
        Map<String, String> overrides = new LinkedHashMap<>();
        if (threads != null) {
            overrides.put("threads", threads.toString());
        }
        if (seed != null) {
            overrides.put("seed", seed.toString());
        }
        List<Path> classpath = classpathElements.stream().map(Path::of).toList();
        Diagnostics diagnostics = new Diagnostics();
        Optional<RequirementsCheck.Outcome> outcome;
        try {
            outcome = RequirementsCheck.run(new RequirementsCheck.Request(modelFiles(), path, root,
                    requirements.toPath(), reportDirectory.toPath(), overrides, classpath), diagnostics, null);
        } catch (RequirementsCheck.Failure e) {
            throw new MojoFailureException("statistical model checking failed: " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new MojoExecutionException("interrupted", e);
        }
        report(diagnostics);
        if (outcome.isEmpty()) {
            throw new MojoFailureException("the requirements could not be checked; see above");
        }
        outcome.get().report().lines().forEach(getLog()::info);
        List<PointResult> refuted = outcome.get().refuted();
        if (!refuted.isEmpty()) {
            StringBuilder message = new StringBuilder(refuted.size() + " requirement(s) refuted (report: "
                    + reportDirectory.toPath().resolve("report.txt") + "):");
            for (PointResult r : refuted) {
                message.append('\n').append(RequirementsCheck.refutation(r).strip());
            }
            throw new MojoFailureException(message.toString());
        }
        getLog().info("BIP: " + outcome.get().results().size() + " requirement result(s), none refuted; report in "
                + reportDirectory);
    }
}

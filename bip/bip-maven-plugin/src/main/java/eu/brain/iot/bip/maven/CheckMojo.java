package eu.brain.iot.bip.maven;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;

/** {@code bip:check}: parses and checks the module's BIP models and fails the build on any error. */
@Mojo(name = "check", defaultPhase = LifecyclePhase.VALIDATE, threadSafe = true)
public class CheckMojo extends AbstractBipMojo {

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        if (skip) {
            getLog().info("bip:check skipped");
            return;
        }
        int files = modelFiles().size();
        loadAndCheck();
        getLog().info("BIP: " + files + " model file(s) checked, no errors");
    }
}

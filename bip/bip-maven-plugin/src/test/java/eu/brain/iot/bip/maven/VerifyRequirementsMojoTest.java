package eu.brain.iot.bip.maven;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;

import org.apache.maven.plugin.MojoFailureException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The gate: a refuted requirement fails the build with its name, estimate and confidence; one that holds does not. */
class VerifyRequirementsMojoTest {

    private static final String COIN = """
            package Coin
              port type E()
              atom type Coin()
                port E heads(), tails()
                place S, H, T
                initial to S
                on heads from S to H
                on tails from S to T
              end
              compound type Flip()
                component Coin c()
              end
            end
            """;

    private static VerifyRequirementsMojo mojo(Path dir, String requirements) throws Exception {
        Path src = Files.createDirectories(dir.resolve("src/main/bip"));
        Files.writeString(src.resolve("Coin.bip"), COIN);
        Files.writeString(src.resolve("requirements.smc"), requirements);
        VerifyRequirementsMojo mojo = new VerifyRequirementsMojo();
        mojo.sourceDirectory = src.toFile();
        mojo.requirements = src.resolve("requirements.smc").toFile();
        mojo.reportDirectory = dir.resolve("target/smc").toFile();
        mojo.threads = 2;
        return mojo;
    }

    @Test
    void aRefutedRequirementFailsTheBuildNamingItsEstimateAndConfidence(@TempDir Path dir) throws Exception {
        VerifyRequirementsMojo mojo = mojo(dir, """
                # a fair coin: heads in about half of the flips, so 0.9 cannot hold
                REQ-heads: P>=0.9 [ F<=1 c at H ]
                """);
        assertThatThrownBy(mojo::execute).isInstanceOf(MojoFailureException.class)
                .hasMessageContaining("1 requirement(s) refuted")
                .hasMessageContaining("requirements.smc:2:12: requirement REQ-heads REFUTED")
                .hasMessageContaining("estimate 0.")
                .hasMessageContaining("99% interval")
                .hasMessageContaining("justification: a fair coin");
        String report = Files.readString(dir.resolve("target/smc/report.txt"));
        assertThat(report).contains("REQ-heads").contains("REFUTED");
        assertThat(dir.resolve("target/smc/report.csv")).exists();
    }

    @Test
    void requirementsThatHoldPassAndSweepsArePlotted(@TempDir Path dir) throws Exception {
        VerifyRequirementsMojo mojo = mojo(dir, """
                set root = Coin.Flip
                set epsilon = 0.05
                set seed = 7
                REQ-heads: P>=0.3 [ F<=1 c at H ]
                REQ-never: P<=0.01 [ F<=5 c at S && c at H ]
                phi: P=? [ F<=k c at H ] for k = 0:2:1
                """);
        mojo.root = "Deployed.System"; // a plugin-level <root> for bip:generate: the file's own root wins
        mojo.execute();
        assertThat(Files.readString(dir.resolve("target/smc/report.txt"))).contains("holds").doesNotContain("REFUTED");
        assertThat(Files.readString(dir.resolve("target/smc/phi.svg"))).startsWith("<svg").contains("polyline");
    }

    @Test
    void aQueryNamingAnUnknownComponentFailsWithItsPosition(@TempDir Path dir) throws Exception {
        VerifyRequirementsMojo mojo = mojo(dir, "REQ: P>=0.5 [ F<=1 d at H ]\n");
        assertThatThrownBy(mojo::execute).isInstanceOf(MojoFailureException.class);
    }

    @Test
    void noRequirementsFileIsNothingToDo(@TempDir Path dir) throws Exception {
        VerifyRequirementsMojo mojo = mojo(dir, "");
        mojo.requirements = new File(dir.toFile(), "missing.smc");
        mojo.execute();
        assertThat(dir.resolve("target/smc")).doesNotExist();
    }
}

package eu.brain.iot.bip.smc.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.smc.SmcSession;
import eu.brain.iot.bip.smc.engine.PointResult;
import eu.brain.iot.bip.smc.query.Query;

/** The plot's x axis: nice ticks (1-2-5 steps, whole numbers for whole sweeps) printed shortly. */
class SvgPlotTest {

    @Test
    void ticksAreOneTwoOrFiveTimesAPowerOfTen() {
        assertThat(SvgPlot.ticks(0, 3, true)).containsExactly(0.0, 1.0, 2.0, 3.0);
        assertThat(SvgPlot.ticks(0, 3, false)).containsExactly(0.0, 1.0, 2.0, 3.0);
        assertThat(SvgPlot.ticks(0, 1, true)).containsExactly(0.0, 1.0);
        assertThat(SvgPlot.ticks(0, 1, false)).containsExactly(0.0, 0.2, 0.4, 0.6, 0.8, 1.0);
        assertThat(SvgPlot.ticks(0, 100, true)).containsExactly(0.0, 20.0, 40.0, 60.0, 80.0, 100.0);
        assertThat(SvgPlot.ticks(1, 12, true)).containsExactly(2.0, 4.0, 6.0, 8.0, 10.0, 12.0);
        assertThat(SvgPlot.ticks(-0.35, 0.35, false)).containsExactly(-0.2, 0.0, 0.2);
        assertThat(SvgPlot.ticks(0.001, 0.004, false)).containsExactly(0.001, 0.002, 0.003, 0.004);
        assertThat(SvgPlot.ticks(0, 1000, true)).containsExactly(0.0, 200.0, 400.0, 600.0, 800.0, 1000.0);
        assertThat(SvgPlot.ticks(2, 2.5, false)).containsExactly(2.0, 2.1, 2.2, 2.3, 2.4, 2.5);
        assertThat(SvgPlot.ticks(1000, 3000, true)).containsExactly(1000.0, 1500.0, 2000.0, 2500.0, 3000.0);
    }

    @Test
    void numbersPrintShortly() {
        assertThat(Reports.number(0.6)).isEqualTo("0.6");
        assertThat(Reports.number(1.2)).isEqualTo("1.2");
        assertThat(Reports.number(0.1 + 0.2)).isEqualTo("0.3");
        assertThat(Reports.number(3)).isEqualTo("3");
        assertThat(Reports.number(-0.0015)).isEqualTo("-0.0015");
        assertThat(Reports.number(1.0 / 3)).isEqualTo("0.333333");
    }

    @Test
    void aWholeSweepFrom0To3IsLabelledWithItsWholeNumbers() throws Exception {
        Diagnostics d = new Diagnostics();
        SmcSession s = SmcSession.load(List.of(Path.of("src/test/resources/smc/RandomWalk.bip")), List.of(), null, d)
                .orElseThrow(() -> new AssertionError(d.toString()));
        Query q = s.parse("P=? [ F<=10 w.x == x ] for x = 0:3:1");
        List<PointResult> points = new ArrayList<>();
        for (int x = 0; x <= 3; x++) {
            points.add(new PointResult(q, new double[] {x}, "Okamoto/Clopper-Pearson", 100, 50, 0.5, 0.4, 0.6, 0.99,
                    null, 0, 1000, 1));
        }
        String svg = SvgPlot.plot("sweep", points);
        List<String> labels = new ArrayList<>();
        Matcher m = Pattern.compile("<text x=\"[\\d.]+\" y=\"368\" text-anchor=\"middle\">([^<]*)</text>").matcher(svg);
        while (m.find()) {
            labels.add(m.group(1));
        }
        assertThat(labels).containsExactly("0", "1", "2", "3");
        assertThat(svg).doesNotContain("0.600000").doesNotContain("1.20000");
    }
}

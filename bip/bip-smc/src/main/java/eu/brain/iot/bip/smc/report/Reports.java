package eu.brain.iot.bip.smc.report;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import eu.brain.iot.bip.smc.engine.PointResult;
import eu.brain.iot.bip.smc.query.Query;

/** The results as a text table and as CSV. */
public final class Reports {

    private Reports() {
    }

    /** @return the swept parameters of a point, {@code x=4 y=1} */
    public static String params(PointResult r) {
        List<String> parts = new ArrayList<>();
        for (int i = 0; i < r.query().sweeps().size(); i++) {
            parts.add(r.query().sweeps().get(i).name() + "=" + number(r.params()[i]));
        }
        return String.join(" ", parts);
    }

    /**
     * @return a parameter value, short: whole numbers without a fraction, others to 6 significant digits without
     *         trailing zeros ({@code 0.6}, not {@code 0.600000}; a sweep's {@code 0.1 + 0.2} prints {@code 0.3})
     */
    public static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        return new BigDecimal(v).round(new MathContext(6)).stripTrailingZeros().toPlainString();
    }

    /** @return the verdict column: "holds", "REFUTED", or "" for an estimate */
    public static String verdict(PointResult r) {
        return r.verdict() == null ? "" : r.verdict() ? "holds" : "REFUTED";
    }

    public static String table(List<PointResult> results) {
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"query", "parameters", "estimate", "interval", "confidence", "samples", "verdict",
            "method", "time"});
        for (PointResult r : results) {
            rows.add(new String[] {r.query().name(), params(r), String.format(Locale.ROOT, "%.4f", r.estimate()),
                String.format(Locale.ROOT, "[%.4f, %.4f]", r.lower(), r.upper()),
                String.format(Locale.ROOT, "%.2f%%", 100 * r.confidence()), Long.toString(r.samples()), verdict(r),
                r.method() + (r.undecided() > 0 ? " (" + r.undecided() + " traces cut at max-steps)" : ""),
                String.format(Locale.ROOT, "%.2f s", r.samplingNanos() / 1e9)});
        }
        int[] width = new int[rows.get(0).length];
        for (String[] row : rows) {
            for (int i = 0; i < row.length; i++) {
                width[i] = Math.max(width[i], row[i].length());
            }
        }
        StringBuilder s = new StringBuilder();
        for (String[] row : rows) {
            StringBuilder line = new StringBuilder();
            for (int i = 0; i < row.length; i++) {
                line.append(String.format("%-" + width[i] + "s", row[i])).append(i + 1 < row.length ? "  " : "");
            }
            s.append(line.toString().stripTrailing()).append('\n');
        }
        return s.toString();
    }

    public static String csv(List<PointResult> results) {
        StringBuilder s = new StringBuilder("query,formula,parameters,estimate,lower,upper,confidence,samples,"
                + "successes,verdict,method,undecided,steps,seconds\n");
        for (PointResult r : results) {
            Query q = r.query();
            s.append(String.join(",", quote(q.name()), quote(q.text()), quote(params(r)),
                    String.format(Locale.ROOT, "%.6f,%.6f,%.6f,%.4f", r.estimate(), r.lower(), r.upper(),
                            r.confidence()),
                    Long.toString(r.samples()), Long.toString(r.successes()), verdict(r), quote(r.method()),
                    Long.toString(r.undecided()), Long.toString(r.steps()),
                    String.format(Locale.ROOT, "%.3f", r.samplingNanos() / 1e9))).append('\n');
        }
        return s.toString();
    }

    private static String quote(String s) {
        return "\"" + s.replace("\"", "\"\"") + "\"";
    }
}

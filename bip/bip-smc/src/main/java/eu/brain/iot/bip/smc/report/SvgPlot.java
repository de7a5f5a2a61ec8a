package eu.brain.iot.bip.smc.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import eu.brain.iot.bip.smc.engine.PointResult;

/**
 * A plot of swept results, written by hand as SVG: probability (0 to 1) against the first swept parameter, one line
 * per query (and per value of further swept parameters), with the confidence interval as error bars, like the
 * paper's Figs. 14 and 15.
 */
public final class SvgPlot {

    private static final String[] COLOURS = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
        "#e377c2", "#17becf"};
    private static final int W = 640;
    private static final int H = 400;
    private static final int LEFT = 60;
    private static final int RIGHT = 180;
    private static final int TOP = 30;
    private static final int BOTTOM = 50;

    private SvgPlot() {
    }

    /** @param results swept results (the first sweep of each query is the x axis); others are ignored */
    public static String plot(String title, List<PointResult> results) {
        Map<String, List<PointResult>> lines = new LinkedHashMap<>();
        String axis = null;
        for (PointResult r : results) {
            if (r.query().sweeps().isEmpty()) {
                continue;
            }
            axis = axis == null ? r.query().sweeps().get(0).name() : axis;
            List<String> rest = new ArrayList<>();
            for (int i = 1; i < r.query().sweeps().size(); i++) {
                rest.add(r.query().sweeps().get(i).name() + "=" + Reports.number(r.params()[i]));
            }
            String key = r.query().name() + (rest.isEmpty() ? "" : " (" + String.join(", ", rest) + ")");
            lines.computeIfAbsent(key, k -> new ArrayList<>()).add(r);
        }
        double xmin = Double.POSITIVE_INFINITY;
        double xmax = Double.NEGATIVE_INFINITY;
        boolean integers = true;
        for (List<PointResult> l : lines.values()) {
            for (PointResult r : l) {
                xmin = Math.min(xmin, r.params()[0]);
                xmax = Math.max(xmax, r.params()[0]);
                integers &= r.params()[0] == Math.rint(r.params()[0]);
            }
        }
        if (lines.isEmpty()) {
            xmin = 0;
            xmax = 1;
        } else if (xmax <= xmin) {
            xmax = xmin + 1;
        }
        StringBuilder s = new StringBuilder();
        s.append(String.format(Locale.ROOT, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                + "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">%n", W, H, W, H));
        s.append(String.format(Locale.ROOT, "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>%n", W, H));
        s.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"18\" font-size=\"14\">%s</text>%n", LEFT,
                escape(title)));
        int pw = W - LEFT - RIGHT;
        int ph = H - TOP - BOTTOM;
        for (int i = 0; i <= 10; i += 2) {
            double y = TOP + ph - ph * i / 10.0;
            s.append(String.format(Locale.ROOT, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/>"
                    + "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%.1f</text>%n", LEFT, y, LEFT + pw, y, LEFT - 6,
                    y + 4, i / 10.0));
        }
        for (double xv : ticks(xmin, xmax, integers)) {
            double x = LEFT + pw * (xv - xmin) / (xmax - xmin);
            s.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"black\"/>"
                    + "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>%n", x, TOP + ph, x, TOP + ph + 5, x,
                    TOP + ph + 18, Reports.number(xv)));
        }
        s.append(String.format(Locale.ROOT, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" "
                + "stroke=\"black\"/>%n", LEFT, TOP, pw, ph));
        s.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">%s</text>%n",
                LEFT + pw / 2, H - 10, escape(axis == null ? "" : axis)));
        s.append(String.format(Locale.ROOT, "<text transform=\"translate(16,%d) rotate(-90)\" "
                + "text-anchor=\"middle\">probability</text>%n", TOP + ph / 2));
        int n = 0;
        for (Map.Entry<String, List<PointResult>> line : lines.entrySet()) {
            String colour = COLOURS[n % COLOURS.length];
            StringBuilder points = new StringBuilder();
            for (PointResult r : line.getValue()) {
                double x = LEFT + pw * (r.params()[0] - xmin) / (xmax - xmin);
                points.append(String.format(Locale.ROOT, "%.1f,%.1f ", x, TOP + ph * (1 - r.estimate())));
                s.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" "
                        + "stroke=\"%s\"/><circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>%n", x,
                        TOP + ph * (1 - r.lower()), x, TOP + ph * (1 - r.upper()), colour, x,
                        TOP + ph * (1 - r.estimate()), colour));
            }
            s.append(String.format(Locale.ROOT, "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" "
                    + "stroke-width=\"2\"/>%n", points.toString().trim(), colour));
            int ly = TOP + 10 + 18 * n;
            s.append(String.format(Locale.ROOT, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"%s\" "
                    + "stroke-width=\"2\"/><text x=\"%d\" y=\"%d\">%s</text>%n", LEFT + pw + 10, ly, LEFT + pw + 30,
                    ly, colour, LEFT + pw + 35, ly + 4, escape(line.getKey())));
            n++;
        }
        s.append("</svg>\n");
        return s.toString();
    }

    /**
     * Ticks for an axis from {@code min} to {@code max}: the smallest step of 1, 2 or 5 times a power of ten (at
     * least 1 when the values are whole numbers) that puts at most 6 ticks, at its multiples, within the range.
     */
    static List<Double> ticks(double min, double max, boolean integers) {
        double base = Math.pow(10, Math.floor(Math.log10((max - min) / 6)));
        double step = base;
        // 1, 2, 5, 10, 20, 50, ... times base
        for (int k = 1; integers && step < 1 || count(min, max, step) > 6; k++) {
            step = new double[] {1, 2, 5}[k % 3] * base * Math.pow(10, k / 3);
        }
        // tick i is i * step, rounded to the step's decimals, so 3 * 0.2 is 0.6
        int decimals = Math.max(0, (int) -Math.floor(Math.log10(step) + 1e-9));
        double scale = Math.pow(10, decimals);
        List<Double> ticks = new ArrayList<>();
        for (long i = first(min, step); i * step <= max + step * 1e-9; i++) {
            ticks.add(Math.round(i * step * scale) / scale);
        }
        return ticks;
    }

    private static long first(double min, double step) {
        return (long) Math.ceil(min / step - 1e-9);
    }

    private static long count(double min, double max, double step) {
        return (long) Math.floor(max / step + 1e-9) - first(min, step) + 1;
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}

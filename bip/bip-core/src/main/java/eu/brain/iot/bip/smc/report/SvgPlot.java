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
        for (List<PointResult> l : lines.values()) {
            for (PointResult r : l) {
                xmin = Math.min(xmin, r.params()[0]);
                xmax = Math.max(xmax, r.params()[0]);
            }
        }
        if (xmax <= xmin) {
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
        for (int i = 0; i <= 5; i++) {
            double xv = xmin + (xmax - xmin) * i / 5;
            double x = LEFT + pw * i / 5.0;
            s.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>%n", x,
                    TOP + ph + 18, Reports.number(Math.round(xv * 1000) / 1000.0)));
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

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}

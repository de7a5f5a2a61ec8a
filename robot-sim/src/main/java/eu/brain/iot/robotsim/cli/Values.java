package eu.brain.iot.robotsim.cli;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/**
 * Checked conversions of option values, for picocli option setters: a value out of range or not a number is a
 * {@link ParameterException} whose message names the option, the range and what was found.
 */
public final class Values {
    private Values() {
    }

    /** A whole number in {@code min..max}; the range is left out of the message when it is all of {@code long}. */
    public static long whole(CommandSpec spec, String option, String text, long min, long max) {
        try {
            long n = Long.parseLong(text.strip());
            if (n >= min && n <= max) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        String range = min == Long.MIN_VALUE && max == Long.MAX_VALUE ? "" : " " + min + ".." + max;
        throw new ParameterException(spec.commandLine(),
                option + " must be a whole number" + range + ", found '" + text + "'");
    }

    public static int wholeInt(CommandSpec spec, String option, String text, int min, int max) {
        return (int) whole(spec, option, text, min, max);
    }

    /** A number {@code > minExclusive} and {@code <= max}. */
    public static double above(CommandSpec spec, String option, String text, double minExclusive, double max) {
        try {
            double d = Double.parseDouble(text.strip());
            if (d > minExclusive && d <= max) {
                return d;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new ParameterException(spec.commandLine(), option + " must be a number > " + minExclusive
                + " and <= " + max + ", found '" + text + "'");
    }
}

package eu.brain.iot.bip.diag;

import eu.brain.iot.bip.model.Pos;

/** One problem found in a model, printed as {@code file:line:col: error: message}. */
public record Diagnostic(Severity severity, Pos pos, String message) {

    public enum Severity {
        ERROR, WARNING;

        @Override
        public String toString() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    public boolean isError() {
        return severity == Severity.ERROR;
    }

    @Override
    public String toString() {
        return pos + ": " + severity + ": " + message;
    }
}

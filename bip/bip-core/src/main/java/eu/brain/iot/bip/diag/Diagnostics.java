package eu.brain.iot.bip.diag;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import eu.brain.iot.bip.model.Pos;

/**
 * Collects the problems of one run (parser, checker and generator share one). Not thread-safe: owned by the thread
 * that runs the tool.
 */
public final class Diagnostics {

    private final List<Diagnostic> all = new ArrayList<>();

    public void error(Pos pos, String message) {
        all.add(new Diagnostic(Diagnostic.Severity.ERROR, pos, message));
    }

    public void warning(Pos pos, String message) {
        all.add(new Diagnostic(Diagnostic.Severity.WARNING, pos, message));
    }

    public boolean hasErrors() {
        return all.stream().anyMatch(Diagnostic::isError);
    }

    public long errorCount() {
        return all.stream().filter(Diagnostic::isError).count();
    }

    public long warningCount() {
        return all.size() - errorCount();
    }

    /** @return every diagnostic, sorted by file, line and column (stable for the same position) */
    public List<Diagnostic> sorted() {
        List<Diagnostic> copy = new ArrayList<>(all);
        copy.sort(Comparator.comparing((Diagnostic d) -> d.pos().file()).thenComparingInt(d -> d.pos().line())
                .thenComparingInt(d -> d.pos().column()));
        return copy;
    }

    public List<Diagnostic> errors() {
        return sorted().stream().filter(Diagnostic::isError).toList();
    }

    public List<Diagnostic> all() {
        return List.copyOf(all);
    }

    @Override
    public String toString() {
        StringBuilder out = new StringBuilder();
        for (Diagnostic d : sorted()) {
            out.append(d).append('\n');
        }
        return out.toString();
    }
}

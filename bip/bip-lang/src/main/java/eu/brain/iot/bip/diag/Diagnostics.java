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
    /** Errors that follow from another one (e.g. names of a package that was not found): counted, not shown. */
    private final List<Diagnostic> hidden = new ArrayList<>();

    public void error(Pos pos, String message) {
        all.add(new Diagnostic(Diagnostic.Severity.ERROR, pos, message));
    }

    public void warning(Pos pos, String message) {
        all.add(new Diagnostic(Diagnostic.Severity.WARNING, pos, message));
    }

    public boolean hasErrors() {
        return !hidden.isEmpty() || all.stream().anyMatch(Diagnostic::isError);
    }

    /** @return the errors shown (not those hidden as consequences of another) */
    public long errorCount() {
        return all.stream().filter(Diagnostic::isError).count();
    }

    /**
     * Hides the errors that follow from another error already reported (they still make the run fail).
     *
     * @return how many were hidden
     */
    public int hideConsequences(java.util.function.Predicate<Diagnostic> followsFromAnother) {
        List<Diagnostic> consequences = all.stream().filter(d -> d.isError() && followsFromAnother.test(d)).toList();
        all.removeAll(consequences);
        hidden.addAll(consequences);
        return consequences.size();
    }

    /** @return how many errors were hidden as consequences of others */
    public int hiddenCount() {
        return hidden.size();
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

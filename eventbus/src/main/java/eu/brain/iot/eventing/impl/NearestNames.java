package eu.brain.iot.eventing.impl;

import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * The policy for suggesting event type names to a person who typed one that no bundle knows: the same name in
 * another case first, then the known names of the same simple class name (the package left out or mistyped), then
 * those within a few edits (Levenshtein distance) of the typed name or of its simple name. Stateless.
 */
final class NearestNames {

    /** Suggestions shown at most. */
    static final int MAX_SUGGESTIONS = 3;
    /** Edits (insertions, deletions, substitutions) at most between a typed name and a suggestion. */
    static final int MAX_EDITS = 3;

    private NearestNames() {
    }

    /** @return up to {@link #MAX_SUGGESTIONS} known names nearest to {@code typed}, nearest first; empty if none */
    static List<String> nearest(String typed, Collection<String> known) {
        record Scored(String name, int score) {
        }
        return known.stream().filter(Objects::nonNull).distinct().map(name -> new Scored(name, score(typed, name)))
                .filter(s -> s.score() <= MAX_EDITS + 2)
                .sorted(Comparator.comparingInt(Scored::score).thenComparing(Scored::name))
                .limit(MAX_SUGGESTIONS).map(Scored::name).toList();
    }

    /** 0: same name but for case; 1: same simple name; then 2 + edits; {@code Integer.MAX_VALUE}: not near. */
    private static int score(String typed, String name) {
        if (typed.equalsIgnoreCase(name)) {
            return 0;
        }
        String typedSimple = simple(typed).toLowerCase(Locale.ROOT);
        String nameSimple = simple(name).toLowerCase(Locale.ROOT);
        if (typedSimple.equals(nameSimple)) {
            return 1;
        }
        int edits = Math.min(distance(typed.toLowerCase(Locale.ROOT), name.toLowerCase(Locale.ROOT), MAX_EDITS),
                distance(typedSimple, nameSimple, MAX_EDITS));
        return edits <= MAX_EDITS ? 2 + edits : Integer.MAX_VALUE;
    }

    private static String simple(String name) {
        return name.substring(name.lastIndexOf('.') + 1);
    }

    /** Levenshtein distance, or {@code limit + 1} once it is certain to exceed {@code limit}. */
    static int distance(String a, String b, int limit) {
        if (Math.abs(a.length() - b.length()) > limit) {
            return limit + 1;
        }
        int[] previous = new int[b.length() + 1];
        int[] current = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            current[0] = i;
            int rowMin = current[0];
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                current[j] = Math.min(Math.min(current[j - 1] + 1, previous[j] + 1), previous[j - 1] + cost);
                rowMin = Math.min(rowMin, current[j]);
            }
            if (rowMin > limit) {
                return limit + 1;
            }
            int[] swap = previous;
            previous = current;
            current = swap;
        }
        return previous[b.length()];
    }
}

package eu.brain.iot.bip;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

/** Mutated models for robustness tests: tokens and characters deleted, duplicated, swapped or replaced. */
public final class Mutants {

    private static final String[] INSERTS = {"(", ")", "{", "}", "'", ";", ",", ".", "end", "on", "from", "to",
            "provided", "do", "if", "then", "else", "fi", "define", "export", "port", "data", "atom type",
            "connector type", "compound type", "component", "connector", "priority", "*:*", "<", "=", "==", "&&",
            "\"", "/*", "//", "@java(", "0x", "1e", "9999999999999", "x", "p1", "START", "int", "float", "string",
            "const", "resume", "invariant", "extern port", "remember", "-", "*", "/ 0", "+ \"s\""};

    private Mutants() {
    }

    /** The models mutants are made from: every golden model, a synthetic system and Listing 7. */
    public static List<String> seeds() {
        List<String> seeds = new ArrayList<>();
        for (String name : List.of("package", "atom", "connector", "compound", "expressions", "bip2")) {
            seeds.add(Models.resource("golden/" + name + ".bip"));
        }
        seeds.add(SyntheticModel.of(80, 11));
        seeds.add(Models.resource("listings/listing7.bip"));
        return seeds;
    }

    public static String mutate(String seed, Random random) {
        StringBuilder s = new StringBuilder(seed);
        int mutations = 1 + random.nextInt(4);
        for (int m = 0; m < mutations && s.length() > 1; m++) {
            int at = random.nextInt(s.length());
            int len = Math.min(s.length() - at, 1 + random.nextInt(12));
            switch (random.nextInt(5)) {
                case 0 -> s.delete(at, at + len);
                case 1 -> s.insert(at, INSERTS[random.nextInt(INSERTS.length)]);
                case 2 -> s.insert(at, s.substring(at, at + len));
                case 3 -> s.setCharAt(at, (char) (32 + random.nextInt(95)));
                default -> {
                    int other = random.nextInt(s.length());
                    char c = s.charAt(at);
                    s.setCharAt(at, s.charAt(other));
                    s.setCharAt(other, c);
                }
            }
        }
        return s.toString();
    }
}

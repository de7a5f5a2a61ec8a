package eu.brain.iot.bip;

import java.util.Random;

/**
 * Writes large, valid BIP models (for the benchmark, round trips and as fuzzing seeds): atom types with data,
 * guards, actions, if/else and extern calls, connector types of each shape, and a compound instantiating them.
 */
public final class SyntheticModel {

    private SyntheticModel() {
    }

    private static int lineCount(CharSequence s) {
        int n = 0;
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) == '\n') {
                n++;
            }
        }
        return n;
    }

    /** @return a model of about {@code lines} lines, deterministic for a seed */
    public static String of(int lines, long seed) {
        Random random = new Random(seed);
        StringBuilder b = new StringBuilder();
        b.append("package Synthetic\n");
        b.append("  const data int LIMIT = 100\n  const data float RATE = 0.5\n");
        b.append("  extern function int sense(int)\n  extern function report(string, int)\n");
        b.append("  port type Data(int v)\n  port type Silent()\n");
        b.append("  connector type Pair(Data a, Data b)\n    define a b\n    on a b provided (a.v >= 0) down { b.v = a.v; }\n  end\n");
        b.append("  connector type Fan(Silent s, Silent r1, Silent r2)\n    define s' r1 r2\n  end\n");
        int atoms = 0;
        StringBuilder compound = new StringBuilder("  compound type Top()\n");
        while (lineCount(b) + lineCount(compound) < lines - 2) {
            String name = "Worker" + atoms;
            int places = 4 + random.nextInt(4);
            b.append("  atom type ").append(name).append("(int id)\n");
            b.append("    data int x = 0\n    data int y\n    data float level = 1.5\n    data bool busy = false\n");
            b.append("    data string label = \"w\"\n");
            b.append("    export port Data out(x)\n    export port Data in(y)\n    export port Silent tick()\n");
            b.append("    export port Silent hear1()\n    export port Silent hear2()\n    port Silent work()\n");
            b.append("    place ");
            for (int p = 0; p < places; p++) {
                b.append(p == 0 ? "" : ", ").append("P").append(p);
            }
            b.append("\n    initial to P0 do { x = id; y = sense(id); label = \"worker \" + id; }\n");
            for (int p = 0; p < places; p++) {
                int next = (p + 1) % places;
                String port = switch (random.nextInt(6)) {
                    case 0 -> "out";
                    case 1 -> "in";
                    case 2 -> "tick";
                    case 3 -> "hear1";
                    case 4 -> "hear2";
                    default -> "work";
                };
                b.append("    on ").append(port).append(" from P").append(p).append(" to P").append(next)
                        .append(" provided (x < LIMIT && !busy || level > RATE)")
                        .append(" do { x = x + ").append(1 + random.nextInt(9))
                        .append("; if (x > 50) then level = level * RATE; busy = !busy; else y = y + x % 7; fi")
                        .append(" report(label + \":\" + x, y); }\n");
            }
            b.append("    internal from P").append(places - 1).append(" to P0 provided (x > LIMIT) do { x = 0; }\n");
            b.append("    priority low work < tick provided (y > 0)\n");
            b.append("  end\n");
            compound.append("    component ").append(name).append(" w").append(atoms).append("a(").append(atoms)
                    .append("), w").append(atoms).append("b(").append(atoms + 1).append(")\n");
            compound.append("    connector Pair c").append(atoms).append("(w").append(atoms).append("a.out, w")
                    .append(atoms).append("b.in)\n");
            atoms++;
        }
        b.append(compound).append("  end\nend\n");
        return b.toString();
    }
}

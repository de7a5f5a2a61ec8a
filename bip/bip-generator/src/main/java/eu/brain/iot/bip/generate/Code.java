package eu.brain.iot.bip.generate;

/** An indenting Java source builder. */
final class Code {

    private final StringBuilder out = new StringBuilder();
    private int indent;

    Code line(String text) {
        if (text.isEmpty()) {
            out.append('\n');
        } else {
            out.append("    ".repeat(indent)).append(text).append('\n');
        }
        return this;
    }

    Code open(String text) {
        line(text + " {");
        indent++;
        return this;
    }

    Code close() {
        return close("}");
    }

    Code close(String text) {
        indent--;
        return line(text);
    }

    /** Closes a block and opens the next one on the same line, as in {@code } else {}. */
    Code middle(String text) {
        indent--;
        line(text);
        indent++;
        return this;
    }

    /** Appends text (already indented lines) as it is. */
    Code raw(String text) {
        out.append(text);
        return this;
    }

    Code blank() {
        return line("");
    }

    @Override
    public String toString() {
        return out.toString();
    }
}

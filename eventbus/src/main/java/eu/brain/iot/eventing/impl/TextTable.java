package eu.brain.iot.eventing.impl;

import java.util.ArrayList;
import java.util.List;

/**
 * A plain-text table for the shell: each column as wide as its widest cell, up to the column's maximum; a longer cell
 * is cut and ends with {@value #ELLIPSIS}, so that the rows stay aligned however long a bundle or behaviour name is.
 * Numbers are right-aligned under right-aligned headers. The last column is never cut (it runs to the line's end).
 * Not thread-safe: built and printed by one command call.
 */
final class TextTable {

    /** Marks a cut cell; plain ASCII, since a shell's console may not print other characters. */
    static final String ELLIPSIS = "...";

    /** One column: its header, its widest width, and whether its cells are right-aligned (numbers). */
    record Column(String header, int maxWidth, boolean right) {
        static Column text(String header, int maxWidth) {
            return new Column(header, maxWidth, false);
        }

        static Column number(String header) {
            return new Column(header, Integer.MAX_VALUE, true);
        }
    }

    private final List<Column> columns;
    private final List<String[]> rows = new ArrayList<>();

    TextTable(Column... columns) {
        this.columns = List.of(columns);
    }

    TextTable row(Object... cells) {
        String[] row = new String[columns.size()];
        for (int i = 0; i < row.length; i++) {
            row[i] = String.valueOf(cells[i]);
        }
        rows.add(row);
        return this;
    }

    @Override
    public String toString() {
        int[] widths = new int[columns.size()];
        for (int i = 0; i < widths.length; i++) {
            int w = columns.get(i).header().length();
            for (String[] row : rows) {
                w = Math.max(w, row[i].length());
            }
            widths[i] = Math.min(w, Math.max(columns.get(i).maxWidth(), columns.get(i).header().length()));
        }
        StringBuilder out = new StringBuilder();
        String[] headers = columns.stream().map(Column::header).toArray(String[]::new);
        line(out, headers, widths);
        for (String[] row : rows) {
            line(out, row, widths);
        }
        return out.toString();
    }

    private void line(StringBuilder out, String[] cells, int[] widths) {
        StringBuilder line = new StringBuilder();
        int last = cells.length - 1;
        for (int i = 0; i <= last; i++) {
            if (i > 0) {
                line.append("  ");
            }
            if (i == last && !columns.get(i).right()) {
                line.append(cells[i]);
                break;
            }
            String cell = cut(cells[i], widths[i]);
            String pad = " ".repeat(widths[i] - cell.length());
            line.append(columns.get(i).right() ? pad + cell : cell + pad);
        }
        out.append(line.toString().stripTrailing()).append(System.lineSeparator());
    }

    static String cut(String cell, int width) {
        if (cell.length() <= width) {
            return cell;
        }
        return width <= ELLIPSIS.length() ? cell.substring(0, width)
                : cell.substring(0, width - ELLIPSIS.length()) + ELLIPSIS;
    }
}

package eu.brain.iot.bip.smc;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Pos;

/**
 * A requirements file (bip/README, "Requirements file"): {@code set KEY = VALUE} lines, and one query per line,
 * {@code NAME: P>=θ [ φ ] [for x = a:b:c]}, with the {@code #} comment lines just above as its justification.
 * Read without the model; the queries are resolved later against the system.
 */
public record RequirementsFile(Path file, Map<String, Setting> settings, List<Entry> entries) {

    /** A {@code set} line. */
    public record Setting(String value, Pos pos) {
    }

    /** A query line: {@code textPos} is where the query text starts. */
    public record Entry(String name, String text, Pos textPos, String justification) {
    }

    private static final Pattern SET = Pattern.compile("set\\s+([\\w-]+)\\s*=\\s*(.*)");
    private static final Pattern NAMED = Pattern.compile("([A-Za-z_][\\w.-]*)\\s*:\\s*(P.*)");

    /** Reads the file, reporting malformed lines in {@code diagnostics}. */
    public static RequirementsFile read(Path file, Diagnostics diagnostics) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            diagnostics.error(new Pos(file.toString(), 1, 1), "cannot read the requirements file: " + e.getMessage());
            return new RequirementsFile(file, Map.of(), List.of());
        }
        return parse(file.toString(), lines, diagnostics, file);
    }

    static RequirementsFile parse(String name, List<String> lines, Diagnostics diagnostics, Path file) {
        Map<String, Setting> settings = new LinkedHashMap<>();
        List<Entry> entries = new ArrayList<>();
        StringBuilder comment = new StringBuilder();
        for (int i = 0; i < lines.size(); i++) {
            String raw = lines.get(i);
            String line = raw.strip();
            int indent = raw.indexOf(line.isEmpty() ? " " : line.substring(0, 1));
            if (line.isEmpty()) {
                comment.setLength(0);
                continue;
            }
            if (line.startsWith("#")) {
                comment.append(comment.length() == 0 ? "" : " ").append(line.substring(1).strip());
                continue;
            }
            int hash = line.indexOf('#');
            String content = (hash >= 0 ? line.substring(0, hash) : line).strip();
            Matcher set = SET.matcher(content);
            Matcher named = NAMED.matcher(content);
            if (set.matches()) {
                settings.put(set.group(1), new Setting(set.group(2).strip(), new Pos(name, i + 1, indent + 1)));
            } else if (named.matches()) {
                entries.add(new Entry(named.group(1), named.group(2), new Pos(name, i + 1, indent + 1
                        + named.start(2)), comment.toString()));
            } else if (content.startsWith("P")) {
                entries.add(new Entry(null, content, new Pos(name, i + 1, indent + 1), comment.toString()));
            } else {
                diagnostics.error(new Pos(name, i + 1, indent + 1), "expected 'set KEY = VALUE', 'NAME: P... [ φ ]' "
                        + "or a '#' comment, found '" + content + "'");
            }
            comment.setLength(0);
        }
        return new RequirementsFile(file, settings, entries);
    }
}

package eu.brain.iot.bip.generate;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Pos;

/** One generated Java source file. */
public record JavaFile(String packageName, String className, String source) {

    public String qualifiedName() {
        return packageName.isEmpty() ? className : packageName + "." + className;
    }

    public Path relativePath() {
        return Path.of(packageName.replace('.', '/'), className + ".java");
    }

    /** Writes the file under {@code root}, reporting (not throwing) a failure. */
    public void writeUnder(Path root, Diagnostics diagnostics) {
        Path file = root.resolve(relativePath());
        try {
            Files.createDirectories(file.getParent());
            Files.writeString(file, source, StandardCharsets.UTF_8);
        } catch (IOException e) {
            diagnostics.error(new Pos(file.toString(), 1, 1), "cannot write generated file: " + e.getMessage());
        }
    }
}

package eu.brain.iot.node.logging;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;

import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;

/**
 * Sets the levels of java.util.logging loggers from the framework property {@value #LEVELS}, a comma-separated
 * list of {@code <logger name>=<level>} (a {@link Level} name such as {@code WARNING}). JUL takes per-logger
 * levels only from a configuration file otherwise, and some bundles log through it with no option of their own:
 * Aries SPI Fly 1.3.7, for one, logs every provider it registers at INFO on the console.
 * <p>
 * This component starts with the node's core (start level 1), so the levels are in place before the bundles of
 * the higher levels start. It holds the loggers it configured (JUL keeps loggers only weakly, and a level set on a
 * logger that is collected is lost) and gives them back their previous levels when it is deactivated.
 */
@Component
public final class JulLevels {

    /** Framework (or system) property, e.g. {@code org.apache.aries.spifly=WARNING}. */
    public static final String LEVELS = "fabric.node.jul.levels";

    private final List<Logger> loggers = new ArrayList<>();
    private final List<Level> previous = new ArrayList<>();

    @Activate
    public JulLevels(BundleContext context) {
        String levels = context.getProperty(LEVELS);
        if (levels == null) {
            return;
        }
        for (String entry : levels.split(",")) {
            int equals = entry.indexOf('=');
            if (entry.isBlank()) {
                continue;
            }
            if (equals < 0) {
                System.err.printf("fabric node: %s: '%s' is not <logger>=<level>, ignored%n", LEVELS, entry.trim());
                continue;
            }
            String name = entry.substring(0, equals).trim();
            Level level;
            try {
                level = Level.parse(entry.substring(equals + 1).trim());
            } catch (IllegalArgumentException e) {
                System.err.printf("fabric node: %s: '%s' is not a java.util.logging level, ignored%n", LEVELS,
                        entry.substring(equals + 1).trim());
                continue;
            }
            Logger logger = Logger.getLogger(name);
            loggers.add(logger);
            previous.add(logger.getLevel());
            logger.setLevel(level);
        }
    }

    @Deactivate
    void deactivate() {
        for (int i = 0; i < loggers.size(); i++) {
            loggers.get(i).setLevel(previous.get(i));
        }
    }
}

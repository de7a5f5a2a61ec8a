package eu.brain.iot.edge.impl;

/**
 * Where the edge's core writes its log: the OSGi log in a framework, standard error in a benchmark. Kept this
 * small so that the core (client, poller, model) runs without a framework.
 */
interface EdgeLog {
    void warn(String message);

    void info(String message);

    void debug(String message);

    static EdgeLog of(org.osgi.service.log.Logger logger) {
        return new EdgeLog() {
            @Override
            public void warn(String message) {
                logger.warn(message);
            }

            @Override
            public void info(String message) {
                logger.info(message);
            }

            @Override
            public void debug(String message) {
                logger.debug(message);
            }
        };
    }

    /** Warnings and information to standard error, debug dropped. */
    static EdgeLog stderr() {
        return new EdgeLog() {
            @Override
            public void warn(String message) {
                System.err.println("edge WARN: " + message);
            }

            @Override
            public void info(String message) {
                System.err.println("edge: " + message);
            }

            @Override
            public void debug(String message) {
                // dropped
            }
        };
    }
}

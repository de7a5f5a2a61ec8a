package eu.brain.iot.node.logging;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.slf4j.LoggerFactory;

/**
 * Makes slf4j find its provider (slf4j-simple, on the framework's class path: see the node's bndrun) at start level 1,
 * on the one thread that starts the node's bundle, before the bundles that log through slf4j start. slf4j binds its
 * provider at the first call; when two threads log during that first call (Jetty's start and another thread's, at
 * level 2) it records their lines and prints three {@code SLF4J(W): A number (6) of logging calls during the
 * initialization phase have been intercepted} warnings at every start.
 */
@Component
public final class Slf4jStart {

    @Activate
    public Slf4jStart() {
        LoggerFactory.getILoggerFactory();
    }
}

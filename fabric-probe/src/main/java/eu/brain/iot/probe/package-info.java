/**
 * The probe bundle of the container tests, dropped into a node's configuration folder (Apache Felix File Install
 * installs it): {@link eu.brain.iot.probe.ProbePublisher} publishes numbered events on one node,
 * {@link eu.brain.iot.probe.ProbeCounter} counts them inside its {@code notify()} on another, and both
 * print what they did on standard output, which the tests read from the container's log. Each is a component that
 * runs only with its configuration.
 */
package eu.brain.iot.probe;

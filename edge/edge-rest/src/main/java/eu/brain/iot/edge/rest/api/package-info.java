/**
 * The node's HTTP access gate, for other web parts the node serves beside the edge's {@code /sensinact} API (the
 * dashboard): the same {@code Host} and {@code Origin} checks and, when the node is exposed beyond loopback, the same
 * authentication (the API token as a bearer token, or the browser session cookie from {@code POST
 * /sensinact/session}), so that one login covers every part of the node.
 */
@Export
@Version("1.0.0")
package eu.brain.iot.edge.rest.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;

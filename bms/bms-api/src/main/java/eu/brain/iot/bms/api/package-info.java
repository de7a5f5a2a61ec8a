/**
 * The alert events of the Behaviour Management Service (BMS), published on the event bus: a behaviour, a dashboard
 * or a consumer of last resort may consume them like any other event. The BMS never searches a repository for these
 * types itself: an alert nobody consumes goes to the consumers of last resort, else it is counted as unhandled.
 */
@Export
@Version("1.0.0")
package eu.brain.iot.bms.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;

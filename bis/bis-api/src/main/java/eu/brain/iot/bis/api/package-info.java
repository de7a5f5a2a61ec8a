/**
 * The Bundle Installer Service (BIS) API: install a behaviour from the configured repositories (by identity or by
 * the event types it consumes), list what was installed, when and why, and uninstall it. A Behaviour Management
 * Service depends on this API only, so that a remote installer on another node can take the local one's place.
 * Since 1.3, {@code find} may be given the event that no behaviour takes, so that such an installer can choose the
 * node by the event's fields.
 */
@Export
@Version("1.3.0")
package eu.brain.iot.bis.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;

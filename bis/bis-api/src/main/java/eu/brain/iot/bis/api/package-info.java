/**
 * The Bundle Installer Service (BIS) API: install a behaviour from the configured repositories (by identity or by
 * the event types it consumes), list what was installed, when and why, and uninstall it. A Behaviour Management
 * Service depends on this API only, so that a remote installer on another node can take the local one's place.
 */
@Export
@Version("1.2.0")
package eu.brain.iot.bis.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;

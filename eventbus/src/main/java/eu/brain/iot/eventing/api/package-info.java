/**
 * The BRAIN-IoT eventing API: the types every smart behaviour compiles against. Source compatible with the
 * original BRAIN-IoT fabric's {@code eu.brain.iot.eventing.api}. Since 1.1, {@code BrainIoTEvent} extends
 * {@code org.osgi.dto.DTO}, as it does there. Since 1.2, {@code EventBus} has {@code tryDeliver}, which never waits
 * for room (an addition to a provider type: behaviours and other consumers of the API are not affected).
 */
@Export
@Version("1.2.0")
package eu.brain.iot.eventing.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;

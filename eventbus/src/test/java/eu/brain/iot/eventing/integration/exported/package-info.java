/** Events of an exported package, for {@code bus:publish} of a subtype (PublishCommandIntegrationTest). */
package eu.brain.iot.eventing.integration.exported;

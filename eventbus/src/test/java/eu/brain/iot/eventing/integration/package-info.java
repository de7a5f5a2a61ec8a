/** In-framework tests of the event bus: the real bundle in a real Felix, behaviours registered as services. */
package eu.brain.iot.eventing.integration;

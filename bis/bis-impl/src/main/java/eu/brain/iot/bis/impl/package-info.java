/**
 * The Bundle Installer Service's implementation (private): the DS component, its configuration and Gogo commands.
 */
package eu.brain.iot.bis.impl;

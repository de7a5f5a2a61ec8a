package eu.brain.iot.edge.impl;

import java.util.regex.Pattern;

/** The name of the node the edge runs on: framework property {@value #PROPERTY}, checked. */
final class EdgeNode {

    /** The framework property that names the node (the launcher sets it; the BIS and the REST API read it too). */
    static final String PROPERTY = "fabric.node.name";
    /** The name of a node that was given none. */
    static final String DEFAULT_NAME = "node";

    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9_.-]{1,64}");

    private EdgeNode() {
    }

    /**
     * @param property the framework property's value, or null
     * @return the node's name: the property, or {@value #DEFAULT_NAME} when it is unset or blank
     * @throws IllegalArgumentException when it is no node name
     */
    static String name(String property) {
        if (property == null || property.isBlank()) {
            return DEFAULT_NAME;
        }
        String name = property.strip();
        if (!NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("framework property " + PROPERTY + " must be 1 to 64 letters, digits, "
                    + "'_', '.' or '-' (it names the node on every command the edge sends), found '" + property + "'");
        }
        return name;
    }
}

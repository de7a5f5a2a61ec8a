package eu.brain.iot.bip.parser;

import java.lang.reflect.RecordComponent;
import java.util.List;

import eu.brain.iot.bip.model.Pos;

/** A readable, stable dump of a model tree (records, lists, positions), for golden files. */
final class ModelDump {

    private ModelDump() {
    }

    static String dump(Object node) {
        StringBuilder out = new StringBuilder();
        write(out, node, 0);
        return out.toString();
    }

    private static void write(StringBuilder out, Object node, int indent) {
        if (node == null) {
            out.append("null\n");
        } else if (node instanceof Pos p) {
            out.append('@').append(p.line()).append(':').append(p.column()).append('\n');
        } else if (node instanceof String s) {
            out.append('"').append(s.replace("\\", "\\\\").replace("\n", "\\n").replace("\"", "\\\"")).append("\"\n");
        } else if (node instanceof List<?> list) {
            if (list.isEmpty()) {
                out.append("[]\n");
                return;
            }
            out.append('\n');
            for (Object item : list) {
                out.append("  ".repeat(indent + 1)).append("- ");
                write(out, item, indent + 2);
            }
        } else if (node.getClass().isRecord()) {
            RecordComponent[] components = node.getClass().getRecordComponents();
            out.append(node.getClass().getName().replaceFirst("^.*\\.", "")).append('\n');
            for (RecordComponent c : components) {
                out.append("  ".repeat(indent + 1)).append(c.getName()).append(": ");
                try {
                    write(out, c.getAccessor().invoke(node), indent + 1);
                } catch (ReflectiveOperationException e) {
                    throw new IllegalStateException(e);
                }
            }
        } else {
            out.append(node).append('\n');
        }
    }
}

package eu.brain.iot.bis.impl.repo;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.util.List;
import java.util.zip.GZIPInputStream;

import javax.xml.stream.Location;
import javax.xml.stream.XMLStreamException;

import org.osgi.resource.Resource;

import aQute.bnd.osgi.repository.XMLResourceParser;

/**
 * Parses an R5 repository index (plain or gzipped XML) with bnd's {@link XMLResourceParser}; relative {@code url}
 * attributes of {@code osgi.content} are resolved against the index's own URL. Stateless.
 */
public final class IndexParser {

    private IndexParser() {
    }

    public static List<Resource> parse(byte[] bytes, URI location) throws IndexException {
        try (InputStream in = open(bytes); XMLResourceParser parser = new XMLResourceParser(in, location.toString(),
                location)) {
            List<Resource> resources = parser.parse();
            if (!parser.isOk()) {
                throw new IndexException(location + " is not a valid R5 index: " + String.join("; ", parser.getErrors())
                        + " (regenerate it with bnd's indexer, see repository/README.md)");
            }
            return resources;
        } catch (IndexException e) {
            throw e;
        } catch (XMLStreamException e) {
            Location where = e.getLocation();
            String at = where == null ? "" : ":" + where.getLineNumber() + ":" + where.getColumnNumber();
            throw new IndexException(location + at + " is not a valid R5 index: " + firstLine(e.getMessage())
                    + " (regenerate it with bnd's indexer, see repository/README.md)");
        } catch (Exception e) {
            Throwable cause = e.getCause() instanceof XMLStreamException x ? x : e;
            throw new IndexException(location + " is not a valid R5 index: " + firstLine(String.valueOf(cause))
                    + " (regenerate it with bnd's indexer, see repository/README.md)");
        }
    }

    private static InputStream open(byte[] bytes) throws IOException {
        InputStream in = new ByteArrayInputStream(bytes);
        boolean gzip = bytes.length > 2 && (bytes[0] & 0xff) == 0x1f && (bytes[1] & 0xff) == 0x8b;
        return gzip ? new GZIPInputStream(in) : in;
    }

    private static String firstLine(String message) {
        if (message == null) {
            return "unknown error";
        }
        int newline = message.indexOf('\n');
        return newline < 0 ? message : message.substring(0, newline);
    }
}

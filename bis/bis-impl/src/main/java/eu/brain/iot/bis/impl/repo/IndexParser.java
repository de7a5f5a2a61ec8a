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

    /** Parses an index of any size (tests, the signing command); a node's reads go through the bounded form. */
    public static List<Resource> parse(byte[] bytes, URI location) throws IndexException {
        return parse(bytes, location, Long.MAX_VALUE);
    }

    /** @param maxBytes the most a gzipped index may inflate to: a larger one is refused, not parsed */
    public static List<Resource> parse(byte[] bytes, URI location, long maxBytes) throws IndexException {
        try (InputStream in = open(bytes, location, maxBytes); XMLResourceParser parser = new XMLResourceParser(in, location.toString(),
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

    private static InputStream open(byte[] bytes, URI location, long maxBytes) throws IOException {
        InputStream in = new ByteArrayInputStream(bytes);
        boolean gzip = bytes.length > 2 && (bytes[0] & 0xff) == 0x1f && (bytes[1] & 0xff) == 0x8b;
        return gzip ? new Bounded(new GZIPInputStream(in), location, maxBytes) : in;
    }

    /** An inflating stream that fails once more than {@code max} bytes came out of it. Not thread-safe. */
    private static final class Bounded extends java.io.FilterInputStream {
        private final URI location;
        private final long max;
        private long count;

        Bounded(InputStream in, URI location, long max) {
            super(in);
            this.location = location;
            this.max = max;
        }

        @Override
        public int read() throws IOException {
            int b = super.read();
            if (b >= 0) {
                counted(1);
            }
            return b;
        }

        @Override
        public int read(byte[] buffer, int offset, int length) throws IOException {
            int n = super.read(buffer, offset, length);
            if (n > 0) {
                counted(n);
            }
            return n;
        }

        private void counted(int n) throws IOException {
            count += n;
            if (count > max) {
                throw new IOException(location + " inflates to more than the " + max + " bytes allowed"
                        + " (index.max.bytes); refused");
            }
        }
    }

    private static String firstLine(String message) {
        if (message == null) {
            return "unknown error";
        }
        int newline = message.indexOf('\n');
        return newline < 0 ? message : message.substring(0, newline);
    }
}

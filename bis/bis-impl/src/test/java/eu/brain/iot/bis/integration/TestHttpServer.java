package eu.brain.iot.bis.integration;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

/**
 * A tiny real HTTP/1.1 server on 127.0.0.1 for the installer's tests: serves the files of a folder, except the paths
 * a test makes misbehave: a body that never ends, one that trickles a byte at a time, an answer that never comes.
 * Each connection is answered on a thread of its own and closed after one answer.
 * <p>
 * Threads: the accepting thread and one per connection; {@link #behaviours} and {@link #requests} are concurrent.
 */
final class TestHttpServer implements AutoCloseable {

    /** How a path misbehaves. */
    enum Behaviour {
        /** 200 with no length, then bytes for ever (until the client goes away). */
        ENDLESS,
        /** 200 with the file's length, then one byte every 200 ms. */
        TRICKLE,
        /** Reads the request and never answers. */
        SILENT
    }

    private static final long TRICKLE_PAUSE_MS = 200;

    private final Path root;
    private final ServerSocket socket;
    private final ExecutorService threads = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "test-http-server");
        t.setDaemon(true);
        return t;
    });
    private final Map<String, Behaviour> behaviours = new ConcurrentHashMap<>();
    final List<String> requests = new CopyOnWriteArrayList<>();

    TestHttpServer(Path root) throws IOException {
        this.root = root;
        this.socket = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        threads.execute(this::accept);
    }

    /** @param path e.g. {@code /index.xml} */
    TestHttpServer misbehave(String path, Behaviour behaviour) {
        behaviours.put(path, behaviour);
        return this;
    }

    String url(String path) {
        return "http://127.0.0.1:" + socket.getLocalPort() + path;
    }

    @Override
    public void close() throws IOException {
        socket.close();
        threads.shutdownNow();
        try {
            threads.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void accept() {
        while (!socket.isClosed()) {
            try {
                Socket client = socket.accept();
                threads.execute(() -> answer(client));
            } catch (IOException e) {
                return; // closed
            }
        }
    }

    private void answer(Socket client) {
        try (client; OutputStream out = client.getOutputStream()) {
            BufferedReader in = new BufferedReader(new InputStreamReader(client.getInputStream(),
                    StandardCharsets.ISO_8859_1));
            String requestLine = in.readLine();
            for (String header = in.readLine(); header != null && !header.isEmpty(); header = in.readLine()) {
                // headers are not looked at
            }
            if (requestLine == null) {
                return;
            }
            String path = requestLine.split(" ")[1];
            requests.add(path);
            Behaviour behaviour = behaviours.get(path);
            Path file = root.resolve(path.substring(1));
            if (behaviour == Behaviour.SILENT) {
                Thread.sleep(Long.MAX_VALUE); // until the server closes (interrupt) or the client leaves
            } else if (behaviour == Behaviour.ENDLESS) {
                out.write(head(200, -1));
                byte[] chunk = new byte[64 * 1024];
                Arrays.fill(chunk, (byte) ' ');
                while (!Thread.currentThread().isInterrupted()) {
                    out.write(chunk);
                }
            } else if (!Files.isRegularFile(file)) {
                out.write(head(404, 0));
            } else if (behaviour == Behaviour.TRICKLE) {
                byte[] bytes = Files.readAllBytes(file);
                out.write(head(200, bytes.length));
                for (byte b : bytes) {
                    out.write(b);
                    out.flush();
                    Thread.sleep(TRICKLE_PAUSE_MS);
                }
            } else {
                byte[] bytes = Files.readAllBytes(file);
                out.write(head(200, bytes.length));
                out.write(bytes);
            }
        } catch (IOException e) {
            // the client went away (the installer abandoned the read): what these tests provoke
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static byte[] head(int status, long length) {
        return ("HTTP/1.1 " + status + (status == 200 ? " OK" : " Not Found") + "\r\nConnection: close\r\n"
                + (length >= 0 ? "Content-Length: " + length + "\r\n" : "") + "\r\n")
                .getBytes(StandardCharsets.ISO_8859_1);
    }
}

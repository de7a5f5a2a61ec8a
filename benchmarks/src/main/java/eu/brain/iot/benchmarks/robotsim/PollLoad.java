package eu.brain.iot.benchmarks.robotsim;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.cli.CliErrors;
import eu.brain.iot.robotsim.cli.Values;
import eu.brain.iot.robotsim.view.Json;
import io.netty.bootstrap.Bootstrap;
import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.channel.nio.NioEventLoopGroup;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioSocketChannel;
import io.netty.handler.codec.http.DefaultFullHttpRequest;
import io.netty.handler.codec.http.FullHttpResponse;
import io.netty.handler.codec.http.HttpClientCodec;
import io.netty.handler.codec.http.HttpHeaderNames;
import io.netty.handler.codec.http.HttpMethod;
import io.netty.handler.codec.http.HttpObjectAggregator;
import io.netty.handler.codec.http.HttpVersion;
import io.netty.util.concurrent.DefaultThreadFactory;
import java.io.IOException;
import java.io.PrintStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * The poll load: many keep-alive HTTP/1.1 connections (an asynchronous Netty client), each polling
 * {@code GET /{robot}/robot_local_control/state} round-robin over every robot of a running robot-sim as fast as
 * answers come. Runs for a warm-up and a measured period, then stops by itself and prints polls/s, errors and latency.
 * The counters are shared by the Netty I/O threads (adders, atomics); each {@link Poller} is confined to its
 * channel's event loop; {@code running} is written by the main thread.
 */
public final class PollLoad {
    private final List<String> paths;
    private final String hostHeader;
    private final AtomicInteger nextRobot = new AtomicInteger();
    private final LongAdder ok = new LongAdder();
    private final LongAdder errors = new LongAdder();
    private final LongAdder badBodies = new LongAdder();
    private final LatencyHistogram latency = new LatencyHistogram();
    private final int checkEvery;
    private volatile boolean running = true;

    private PollLoad(List<String> paths, String hostHeader, int checkEvery) {
        this.paths = paths;
        this.hostHeader = hostHeader;
        this.checkEvery = checkEvery;
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /** Returns the exit code: 0 fine, 1 errors seen or the simulator not reachable, 2 bad command line. */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CliErrors.install(new CommandLine(new Options(out)), "poll-load", false, out, err).execute(args);
    }

    /** The command line. */
    @Command(name = "poll-load", sortOptions = false, usageHelpWidth = 120,
            customSynopsis = "java -cp benchmarks/target/benchmarks.jar eu.brain.iot.benchmarks.robotsim.PollLoad "
                    + "[options]    (start the simulator first)",
            footer = "The robot list comes from GET / of the simulator. Exit code 1 when an error was seen.")
    static final class Options implements Callable<Integer> {
        @Spec
        private CommandSpec spec;
        private final PrintStream out;
        private URI base = URI.create("http://127.0.0.1:8090/");
        private int connections = 128;
        private int threads = 1;
        private int warmup = 5;
        private int duration = 20;
        private int checkEvery = 1000;

        @Option(names = {"--help", "-h"}, usageHelp = true, order = 7, description = "show this help")
        private boolean help;

        Options(PrintStream out) {
            this.out = out;
        }

        @Option(names = "--url", paramLabel = "URL", order = 1,
                description = "simulator base URL (default http://127.0.0.1:8090/)")
        void url(String v) {
            try {
                base = URI.create(withSlash(v));
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), "--url: " + e.getMessage());
            }
            if (base.getHost() == null || base.getPort() < 0) {
                throw new ParameterException(spec.commandLine(),
                        "--url must be http://HOST:PORT/, found '" + v + "'");
            }
        }

        @Option(names = "--connections", paramLabel = "N", order = 2, description = "keep-alive connections (default 128)")
        void connections(String v) {
            connections = Values.wholeInt(spec, "--connections", v, 1, 10_000);
        }

        @Option(names = "--threads", paramLabel = "N", order = 3, description = "client I/O threads (default 1)")
        void threads(String v) {
            threads = Values.wholeInt(spec, "--threads", v, 1, 64);
        }

        @Option(names = "--warmup", paramLabel = "S", order = 4, description = "seconds polled before measuring (default 5)")
        void warmup(String v) {
            warmup = Values.wholeInt(spec, "--warmup", v, 0, 3600);
        }

        @Option(names = "--duration", paramLabel = "S", order = 5, description = "seconds measured (default 20)")
        void duration(String v) {
            duration = Values.wholeInt(spec, "--duration", v, 1, 3600);
        }

        @Option(names = "--check-every", paramLabel = "N", order = 6,
                description = "parse and check one answer in N as JSON (default 1000)")
        void checkEvery(String v) {
            checkEvery = Values.wholeInt(spec, "--check-every", v, 1, Integer.MAX_VALUE);
        }

        @Override
        public Integer call() throws IOException, InterruptedException {
            List<String> robots = robots(base);
            List<String> paths = new ArrayList<>(robots.size());
            for (String id : robots) {
                paths.add(base.getPath() + id + "/robot_local_control/state");
            }
            PollLoad load = new PollLoad(paths, base.getHost() + ":" + base.getPort(), checkEvery);
            return load.drive(base, connections, threads, warmup, duration, out);
        }
    }

    private static String withSlash(String url) {
        return url.endsWith("/") ? url : url + "/";
    }

    private static List<String> robots(URI base) throws IOException, InterruptedException {
        HttpClient client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        HttpResponse<String> index;
        try {
            index = client.send(HttpRequest.newBuilder(base).timeout(Duration.ofSeconds(30)).build(),
                    HttpResponse.BodyHandlers.ofString());
        } catch (IOException e) {
            throw new IOException("cannot reach the simulator at " + base + " (is it running?): " + e, e);
        }
        if (index.statusCode() != 200) {
            throw new IOException("GET " + base + " answered " + index.statusCode());
        }
        List<String> ids = new ArrayList<>();
        for (JsonNode id : Json.MAPPER.readTree(index.body()).path("robots")) {
            ids.add(id.asText());
        }
        if (ids.isEmpty()) {
            throw new IOException("the simulator at " + base + " has no robots");
        }
        return ids;
    }

    private int drive(URI base, int connections, int threads, int warmup, int duration, PrintStream out)
            throws InterruptedException {
        EventLoopGroup group = new NioEventLoopGroup(threads, new DefaultThreadFactory("poll-load", true));
        try {
            Bootstrap bootstrap = new Bootstrap().group(group).channel(NioSocketChannel.class)
                    .option(ChannelOption.TCP_NODELAY, true)
                    .option(ChannelOption.CONNECT_TIMEOUT_MILLIS, 10_000)
                    .handler(new ChannelInitializer<SocketChannel>() {
                        @Override
                        protected void initChannel(SocketChannel ch) {
                            ch.pipeline().addLast(new HttpClientCodec(), new HttpObjectAggregator(1 << 20),
                                    new Poller());
                        }
                    });
            List<Channel> channels = new ArrayList<>();
            for (int i = 0; i < connections; i++) {
                channels.add(bootstrap.connect(base.getHost(), base.getPort()).sync().channel());
            }
            out.printf("poll-load: %d robots at %s, %d connections, %d client thread(s); warm-up %d s, measuring %d s%n",
                    paths.size(), base, connections, threads, warmup, duration);
            TimeUnit.SECONDS.sleep(warmup);
            ok.reset();
            errors.reset();
            badBodies.reset();
            latency.reset();
            long start = System.nanoTime();
            TimeUnit.SECONDS.sleep(duration);
            long polls = ok.sum();
            long errs = errors.sum();
            long bad = badBodies.sum();
            double seconds = (System.nanoTime() - start) / 1e9;
            running = false;
            for (Channel c : channels) {
                c.close();
            }
            out.printf("polls %d in %.1f s = %.0f polls/s; errors %d; bad bodies %d; latency p50 %.2f ms, "
                            + "p99 %.2f ms, p99.9 %.2f ms%n", polls, seconds, polls / seconds, errs, bad,
                    latency.percentileMillis(0.50), latency.percentileMillis(0.99),
                    latency.percentileMillis(0.999));
            return errs == 0 && bad == 0 && polls > 0 ? 0 : 1;
        } finally {
            running = false;
            group.shutdownGracefully(0, 1, TimeUnit.SECONDS).sync();
        }
    }

    /** One connection: sends the next poll when the previous answer arrives. */
    private final class Poller extends SimpleChannelInboundHandler<FullHttpResponse> {
        private long sentAt;
        private String expected;
        private int sinceCheck;

        @Override
        public void channelActive(ChannelHandlerContext ctx) {
            send(ctx);
        }

        private void send(ChannelHandlerContext ctx) {
            if (!running) {
                return;
            }
            int i = Math.floorMod(nextRobot.getAndIncrement(), paths.size());
            String path = paths.get(i);
            expected = path;
            DefaultFullHttpRequest req = new DefaultFullHttpRequest(HttpVersion.HTTP_1_1, HttpMethod.GET, path);
            req.headers().set(HttpHeaderNames.HOST, hostHeader);
            sentAt = System.nanoTime();
            ctx.writeAndFlush(req, ctx.voidPromise());
        }

        @Override
        protected void channelRead0(ChannelHandlerContext ctx, FullHttpResponse response) {
            latency.record(System.nanoTime() - sentAt);
            if (response.status().code() == 200) {
                ok.increment();
                if (++sinceCheck >= checkEvery) {
                    sinceCheck = 0;
                    check(response.content());
                }
            } else {
                errors.increment();
            }
            send(ctx);
        }

        private void check(ByteBuf content) {
            try {
                JsonNode state = Json.MAPPER.readTree(content.toString(StandardCharsets.UTF_8));
                String id = state.path("id").asText();
                if (!expected.contains("/" + id + "/") || !state.has("x") || !state.has("detect")) {
                    badBodies.increment();
                }
            } catch (IOException e) {
                badBodies.increment();
            }
        }

        @Override
        public void channelInactive(ChannelHandlerContext ctx) {
            if (running) {
                errors.increment();
            }
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            if (running) {
                errors.increment();
            }
            ctx.close();
        }
    }
}

package eu.brain.iot.robotsim.http;

import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.WorldThread;
import eu.brain.iot.robotsim.fault.FaultTable;
import eu.brain.iot.robotsim.view.ViewPublisher;
import io.netty.bootstrap.ServerBootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.nio.NioEventLoopGroup;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.handler.codec.http.HttpServerCodec;
import io.netty.handler.flow.FlowControlHandler;
import io.netty.util.concurrent.DefaultThreadFactory;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.ToIntFunction;

/**
 * The simulator's HTTP/1.1 server (Netty, keep-alive, one port for the whole fleet). I/O threads answer state polls
 * from pre-serialized views and hand orders to the world thread. Each connection answers its requests one after the
 * other, in order ({@link Connection}); a request must pass the {@link RequestGate} first.
 */
public final class HttpServer implements AutoCloseable {
    static final int MAX_BODY = 64 * 1024;
    static final int MAX_LINE = 4096;
    static final int MAX_HEADERS = 8192;

    private final EventLoopGroup boss;
    private final EventLoopGroup workers;
    private final Channel channel;

    /** What the server serves; ids map to indices of the world's robots and doors. */
    public record Wiring(WorldThread world, ViewPublisher views, FaultTable faults, Map<String, Integer> robots,
                         Map<String, Integer> doors, List<String> robotIds, Map<String, Object> index,
                         long stepMillis, CommandCounter commands, CommandOriginLog origins) {
    }

    /**
     * What the server accepts.
     *
     * @param allowedHosts         host names accepted in {@code Host} and {@code Origin} besides 127.0.0.1,
     *                             localhost, [::1] and the bind address
     * @param requestTimeoutMillis time a request may take to arrive whole once its first bytes came
     */
    public record Limits(Set<String> allowedHosts, long requestTimeoutMillis) {
    }

    private HttpServer(EventLoopGroup boss, EventLoopGroup workers, Channel channel) {
        this.boss = boss;
        this.workers = workers;
        this.channel = channel;
    }

    /**
     * Binds and starts serving.
     *
     * @param ioThreads I/O threads, 0 for one per core
     * @throws IOException when the address cannot be bound (for example the port is taken)
     */
    public static HttpServer start(String bindAddress, int port, int ioThreads, Limits limits, Wiring w)
            throws IOException {
        ToIntFunction<String> robotIndex = id -> w.robots().getOrDefault(id, -1);
        Router router = new Router(w.robots(), w.doors(), new RobotApi(w.world(), w.views(), w.faults(), w.commands(), w.origins()),
                new DoorApi(w.world(), w.views(), w.commands()), new AdminApi(w.world(), w.faults(), w.robotIds(), robotIndex),
                new WorldApi(w.world(), w.index(), w.stepMillis(), w.commands(), w.origins()));
        Set<String> hosts = new HashSet<>(limits.allowedHosts());
        hosts.addAll(List.of("127.0.0.1", "localhost", "[::1]", SimConfig.hostName(bindAddress)));
        RequestGate gate = new RequestGate(hosts);
        int threads = ioThreads > 0 ? ioThreads : Runtime.getRuntime().availableProcessors();
        EventLoopGroup boss = new NioEventLoopGroup(1, new DefaultThreadFactory("robot-sim-accept", true));
        EventLoopGroup workers = new NioEventLoopGroup(threads, new DefaultThreadFactory("robot-sim-io", true));
        ServerBootstrap bootstrap = new ServerBootstrap()
                .group(boss, workers)
                .channel(NioServerSocketChannel.class)
                .option(ChannelOption.SO_BACKLOG, 4096)
                .childOption(ChannelOption.TCP_NODELAY, true)
                .childOption(ChannelOption.AUTO_READ, false) // a connection reads its next request when it answered
                .childHandler(new ChannelInitializer<SocketChannel>() {
                    @Override
                    protected void initChannel(SocketChannel ch) {
                        Connection connection = new Connection(router, gate, MAX_BODY, limits.requestTimeoutMillis());
                        ch.pipeline()
                                .addLast(connection.bytesWatch())
                                .addLast(new HttpServerCodec(MAX_LINE, MAX_HEADERS, 8192))
                                .addLast(new FlowControlHandler())
                                .addLast(connection);
                    }
                });
        try {
            Channel channel = bootstrap.bind(new InetSocketAddress(bindAddress, port)).sync().channel();
            return new HttpServer(boss, workers, channel);
        } catch (Exception e) {
            boss.shutdownGracefully(0, 1, TimeUnit.SECONDS);
            workers.shutdownGracefully(0, 1, TimeUnit.SECONDS);
            throw new IOException("cannot listen on " + bindAddress + ":" + port + ": " + e.getMessage(), e);
        }
    }

    /** The port actually bound (useful when 0 was asked). */
    public int port() {
        return ((InetSocketAddress) channel.localAddress()).getPort();
    }

    @Override
    public void close() {
        channel.close().syncUninterruptibly();
        boss.shutdownGracefully(0, 2, TimeUnit.SECONDS).syncUninterruptibly();
        workers.shutdownGracefully(0, 2, TimeUnit.SECONDS).syncUninterruptibly();
    }
}

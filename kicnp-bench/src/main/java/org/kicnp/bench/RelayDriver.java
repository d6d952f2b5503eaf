package org.kicnp.bench;

import io.netty.bootstrap.Bootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFuture;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoop;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.socket.SocketChannel;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.HdrHistogram.Histogram;
import org.kicnp.gateway.Transport;

/**
 * Connects a number of benchmark agents to a hub through one {@link RelayClient} and runs the two measurements:
 * {@link #throughput} (closed loop, a bounded window of messages outstanding per sender) and {@link #latency}
 * (open loop at a fixed total rate, latency against the intended send time). Agents {@code 2k} and {@code 2k+1}
 * are peers, each sending to the other, and share one client event loop.
 */
final class RelayDriver implements AutoCloseable {
    private static final Duration DRAIN = Duration.ofSeconds(5);

    private final EventLoopGroup group;
    private final List<RelayLoop> loops = new ArrayList<>();
    private final List<RelayAgent> agents = new ArrayList<>();

    private RelayDriver(EventLoopGroup group) {
        this.group = group;
    }

    /**
     * Connects {@code count} agents (an even number) and waits until every one can send and receive.
     *
     * @param threads client event loops
     * @param transport their socket transport
     */
    static RelayDriver connect(RelayClient client, InetSocketAddress hub, int count, int threads, Transport transport,
            Duration timeout)
            throws InterruptedException {
        if (count < 2 || count % 2 != 0) {
            throw new IllegalArgumentException("Agents come in pairs: " + count + " is not an even number of 2 or more.");
        }
        RelayDriver d = new RelayDriver(new MultiThreadIoEventLoopGroup(threads, transport.ioHandlerFactory()));
        try {
            for (io.netty.util.concurrent.EventExecutor e : d.group) {
                d.loops.add(new RelayLoop((EventLoop) e));
            }
            for (int k = 0; k < count; k++) {
                RelayLoop loop = d.loops.get((k / 2) % d.loops.size());
                String name = RelayAgent.nameOf(k);
                RelayAgent a = new RelayAgent(k, name, loop, client.encoderFor(name, RelayAgent.nameOf(k ^ 1)));
                d.agents.add(a);
                loop.agents.add(a);
            }
            for (int k = 0; k < count; k++) {
                d.agents.get(k).peer = d.agents.get(k ^ 1);
            }
            d.connectAll(client, hub, transport, timeout);
            return d;
        } catch (RuntimeException | InterruptedException e) {
            d.close();
            throw e;
        }
    }

    private void connectAll(RelayClient client, InetSocketAddress hub, Transport transport, Duration timeout)
            throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        int batch = 100; // handshakes in flight at once, so the listen backlog never overflows
        for (int from = 0; from < agents.size(); from += batch) {
            List<CompletableFuture<Void>> ready = new ArrayList<>();
            for (RelayAgent a : agents.subList(from, Math.min(agents.size(), from + batch))) {
                CompletableFuture<Void> f = new CompletableFuture<>();
                ready.add(f);
                Channel ch = new Bootstrap().group(a.loop.executor).channel(transport.socketChannel())
                        .option(ChannelOption.TCP_NODELAY, true)
                        .handler(new ChannelInitializer<SocketChannel>() {
                            @Override protected void initChannel(SocketChannel c) {
                                client.initPipeline(c.pipeline(), a, f);
                            }
                        })
                        .connect(hub).channel();
                a.channel = ch;
                ch.closeFuture().addListener(x -> f.completeExceptionally(
                        new IllegalStateException("Agent " + a + " could not connect to " + hub + ".")));
            }
            try {
                CompletableFuture.allOf(ready.toArray(CompletableFuture[]::new))
                        .get(Math.max(1, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (ExecutionException e) {
                throw new IllegalStateException("Connecting the bench agents to " + hub + " failed: "
                        + e.getCause().getMessage(), e.getCause());
            } catch (TimeoutException e) {
                throw new IllegalStateException("Connecting " + agents.size() + " bench agents to " + hub
                        + " took longer than " + timeout + ".", e);
            }
        }
    }

    /**
     * Closed loop: each agent keeps {@code window} messages outstanding to its peer; after {@code warmup}, counts
     * deliveries for {@code measure}. Returns delivered (relayed) messages per second.
     */
    Throughput throughput(int window, Duration warmup, Duration measure, java.util.function.LongUnaryOperator hubCpu)
            throws InterruptedException {
        onLoops(loop -> {
            loop.startClosed(window);
            return null;
        });
        Thread.sleep(warmup.toMillis());
        CpuMark cpu0 = mark(hubCpu);
        long before = delivered();
        long t0 = System.nanoTime();
        Thread.sleep(measure.toMillis());
        long after = delivered();
        long t1 = System.nanoTime();
        CpuMark cpu1 = mark(hubCpu);
        onLoops(loop -> {
            loop.stopClosed();
            return null;
        });
        long deadline = System.nanoTime() + DRAIN.toNanos();
        while (onLoops(RelayLoop::inFlight).stream().mapToInt(Integer::intValue).sum() > 0
                && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        long n = Math.max(1, after - before);
        return new Throughput((after - before) * 1e9 / (t1 - t0), (cpu1.hub() - cpu0.hub()) / 1e3 / n,
                (cpu1.clients() - cpu0.clients()) / 1e3 / n);
    }

    /**
     * The closed-loop result: delivered messages per second, and the CPU time the hub and the clients spent per
     * delivered message (on a shared machine the CPU cost is steadier than the rate, which depends on the share).
     */
    record Throughput(double msgsPerSecond, double hubCpuMicrosPerMsg, double clientCpuMicrosPerMsg) {
    }

    /** CPU time so far of the client event loops and of the hub (in nanoseconds), and the machine's idle time. */
    private record CpuMark(long clients, long hub, ProcessCpu.MachineIdle machine) {
    }

    private CpuMark mark(java.util.function.LongUnaryOperator hubCpu) throws InterruptedException {
        long clients = clientCpuNanos();
        return new CpuMark(clients, hubCpu.applyAsLong(clients), ProcessCpu.MachineIdle.now());
    }

    /** CPU time of the client event loops so far, in nanoseconds. */
    long clientCpuNanos() throws InterruptedException {
        return onLoops(loop -> java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime())
                .stream().mapToLong(Long::longValue).sum();
    }

    /**
     * Open loop: {@code rate} messages per second in total, spread evenly over the agents; after {@code warmup},
     * records the latency of every message intended to be sent within {@code measure}, and the CPU time the hub
     * ({@code hubCpu}, given the client loops' time) and the client loops spent over that window.
     */
    LatencyFigures latency(int rate, Duration warmup, Duration measure, java.util.function.LongUnaryOperator hubCpu)
            throws InterruptedException {
        long period = Math.round(agents.size() * 1e9 / rate);
        long start = RelayLoop.now() + TimeUnit.MILLISECONDS.toNanos(20);
        long recordFrom = start + warmup.toNanos();
        long recordUntil = recordFrom + measure.toNanos();
        onLoops(loop -> {
            loop.startOpen(start, period, agents.size(), recordFrom, recordUntil);
            return null;
        });
        Ticker ticker = Ticker.start(() -> {
            for (RelayLoop loop : loops) {
                loop.executor.execute(loop.tickTask);
            }
        }, start, recordUntil);
        CpuMark cpu0;
        CpuMark cpu1;
        try {
            TimeUnit.NANOSECONDS.sleep(recordFrom - RelayLoop.now());
            cpu0 = mark(hubCpu);
            ticker.awaitEnd(); // every tick up to the window's end has been handed to the loops
            cpu1 = mark(hubCpu);
        } finally {
            ticker.stop();
        }
        long deadline = System.nanoTime() + DRAIN.toNanos();
        Histogram all = new Histogram(3);
        long expected;
        while (true) {
            List<Histogram> parts = onLoops(loop -> loop.latencies.copy());
            expected = onLoops(RelayLoop::scheduledInWindow).stream().mapToLong(Long::longValue).sum();
            all = new Histogram(3);
            parts.forEach(all::add);
            if (all.getTotalCount() >= expected || System.nanoTime() > deadline) {
                break;
            }
            Thread.sleep(20);
        }
        onLoops(loop -> {
            loop.stopOpen();
            return null;
        });
        return LatencyFigures.of(rate, all, expected, measure, cpu1.hub() - cpu0.hub(),
                cpu1.clients() - cpu0.clients(), cpu1.machine().busyPercentSince(cpu0.machine()),
                cpu1.machine().stealPercentSince(cpu0.machine()));
    }

    private long delivered() throws InterruptedException {
        return onLoops(loop -> loop.delivered).stream().mapToLong(Long::longValue).sum();
    }

    private <T> List<T> onLoops(java.util.function.Function<RelayLoop, T> task) throws InterruptedException {
        List<io.netty.util.concurrent.Future<T>> futures = new ArrayList<>();
        for (RelayLoop loop : loops) {
            futures.add(loop.executor.submit((Callable<T>) () -> task.apply(loop)));
        }
        List<T> results = new ArrayList<>();
        for (io.netty.util.concurrent.Future<T> f : futures) {
            f.await();
            if (!f.isSuccess()) {
                throw new IllegalStateException("A bench loop failed: " + f.cause(), f.cause());
            }
            results.add(f.getNow());
        }
        return results;
    }

    int agentCount() {
        return agents.size();
    }

    @Override public void close() {
        loops.forEach(l -> l.closing = true);
        List<ChannelFuture> closed = new ArrayList<>();
        for (RelayAgent a : agents) {
            if (a.channel != null) {
                a.channel.eventLoop().execute(a::discard);
                closed.add(a.channel.close());
            }
        }
        // Closing is asynchronous on io_uring (the kernel completes the close); the loops stay up until every channel
        // has closed, else a channel's last tasks meet a terminated loop.
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        for (ChannelFuture f : closed) {
            f.awaitUninterruptibly(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
        }
        group.shutdownGracefully(0, 1, TimeUnit.SECONDS).syncUninterruptibly();
    }
}

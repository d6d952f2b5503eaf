package org.kicnp.gateway;

import io.netty.channel.IoHandlerFactory;
import io.netty.channel.ServerChannel;
import io.netty.channel.epoll.Epoll;
import io.netty.channel.epoll.EpollIoHandler;
import io.netty.channel.epoll.EpollServerSocketChannel;
import io.netty.channel.epoll.EpollSocketChannel;
import io.netty.channel.nio.NioIoHandler;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.channel.socket.nio.NioSocketChannel;
import io.netty.channel.uring.IoUring;
import io.netty.channel.uring.IoUringIoHandler;
import io.netty.channel.uring.IoUringServerSocketChannel;
import io.netty.channel.uring.IoUringSocketChannel;
import java.util.Arrays;
import java.util.Locale;
import java.util.Optional;
import java.util.stream.Collectors;

/**
 * The socket transport under the gateway's event loops (and any Netty client that wants the same):
 * <ul>
 *   <li>{@link #IO_URING}: Linux io_uring (Netty's native transport): the reads and writes of many connections are
 *       submitted and reaped with one system call per loop turn, instead of one per read and one per write;</li>
 *   <li>{@link #EPOLL}: Linux epoll (Netty's native transport): a system call per read and per write, but no
 *       selector bookkeeping per ready connection;</li>
 *   <li>{@link #NIO}: Java NIO, everywhere.</li>
 * </ul>
 * {@link #best()} is the first of these that works here: the native ones need Linux on x86-64 and, for io_uring, a
 * kernel that allows it (container runtimes often forbid io_uring by their seccomp profile; it is then skipped).
 * Measured on the 2-core benchmark machine (docs/benchmarks.md, gateway round 5): io_uring relayed ~15 % more
 * messages per second than NIO at 1,000 agents, for ~15 % less CPU per message.
 */
public enum Transport {
    IO_URING("io_uring"), EPOLL("epoll"), NIO("nio");

    private final String label;

    Transport(String label) {
        this.label = label;
    }

    /** The name used on the command line and in reports: {@code io_uring}, {@code epoll}, {@code nio}. */
    public String label() {
        return label;
    }

    /** The first transport that works here, in the order io_uring, epoll, NIO. */
    public static Transport best() {
        for (Transport t : values()) {
            if (t.isAvailable()) {
                return t;
            }
        }
        return NIO;
    }

    /**
     * The transport named {@code name} ({@code auto} = {@link #best()}), or an {@link IllegalArgumentException} that
     * lists the names. Whether it works here is a separate question: {@link #isAvailable()}.
     */
    public static Transport parse(String name) {
        String n = name.strip().toLowerCase(Locale.ROOT);
        if (n.equals("auto")) {
            return best();
        }
        for (Transport t : values()) {
            if (t.label.equals(n)) {
                return t;
            }
        }
        throw new IllegalArgumentException("No transport '" + name + "': choose auto, "
                + Arrays.stream(values()).map(Transport::label).collect(Collectors.joining(", ")) + ".");
    }

    /** Whether this transport works in this JVM on this machine. */
    public boolean isAvailable() {
        return unavailabilityCause().isEmpty();
    }

    /** This transport, or an {@link IllegalArgumentException} that says why it does not work here. */
    public Transport requireAvailable() {
        unavailabilityCause().ifPresent(why -> {
            throw new IllegalArgumentException("The " + label + " transport does not work here: " + why
                    + " (choose another, or auto for the best one that does).");
        });
        return this;
    }

    /**
     * Why this transport does not work here (its native library did not load, the kernel refused, the library does not
     * match the Java classes that bind to it), if it does not.
     */
    public Optional<String> unavailabilityCause() {
        Throwable cause = switch (this) {
            case IO_URING -> IoUring.isAvailable() ? nativeBindingProblem() : IoUring.unavailabilityCause();
            case EPOLL -> Epoll.isAvailable() ? nativeBindingProblem() : Epoll.unavailabilityCause();
            case NIO -> null;
        };
        return cause == null ? Optional.empty()
                : Optional.of(cause.getClass().getSimpleName() + ": " + cause.getMessage());
    }

    /**
     * A native transport's library loads before its shared part ({@code unix-common}) binds its own native methods,
     * which happens on the first error a connection meets: a library built for another Netty version than those
     * classes would then fail inside the event loop. Binding them here turns that into "not available".
     */
    private static Throwable nativeBindingProblem() {
        try {
            Class.forName("io.netty.channel.unix.Errors", true, Transport.class.getClassLoader());
            return null;
        } catch (ClassNotFoundException | LinkageError e) {
            return e instanceof ExceptionInInitializerError && e.getCause() != null ? e.getCause() : e;
        }
    }

    public IoHandlerFactory ioHandlerFactory() {
        return switch (this) {
            case IO_URING -> IoUringIoHandler.newFactory();
            case EPOLL -> EpollIoHandler.newFactory();
            case NIO -> NioIoHandler.newFactory();
        };
    }

    public Class<? extends ServerChannel> serverChannel() {
        return switch (this) {
            case IO_URING -> IoUringServerSocketChannel.class;
            case EPOLL -> EpollServerSocketChannel.class;
            case NIO -> NioServerSocketChannel.class;
        };
    }

    public Class<? extends SocketChannel> socketChannel() {
        return switch (this) {
            case IO_URING -> IoUringSocketChannel.class;
            case EPOLL -> EpollSocketChannel.class;
            case NIO -> NioSocketChannel.class;
        };
    }
}

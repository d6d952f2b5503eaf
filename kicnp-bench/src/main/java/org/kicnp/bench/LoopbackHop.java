package org.kicnp.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;

/**
 * The kernel's share of a relayed message, measured on this machine: the CPU time of one loopback TCP hop of a
 * message's bytes, one {@code write} of the message on one end of a connection and one {@code read} of it on the
 * other, in one thread, so no wake-up and no event loop are counted, only what the operating system does for the
 * bytes (the TCP send path, the loopback device, the receive path, the copy out). A message relayed through a hub
 * takes two such hops (agent to hub, hub to agent) whatever the hub does, so twice this figure is the least CPU any
 * hub and any client can spend per relayed message on this machine; the bench prints it beside the measured costs.
 * Blocking NIO channels with direct buffers, Nagle off, as the clients send.
 */
final class LoopbackHop {
    private LoopbackHop() {
    }

    /**
     * Thread CPU microseconds per hop of {@code bytes}, over {@code hops} hops after as many untimed ones.
     *
     * @throws IOException when loopback TCP does not work, or a read returns other bytes than were written
     */
    static double cpuMicros(int bytes, int hops) throws IOException {
        if (bytes < 1 || hops < 1) {
            throw new IllegalArgumentException("Need at least one byte and one hop, not " + bytes + " and " + hops + ".");
        }
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        try (ServerSocketChannel server = ServerSocketChannel.open()
                .bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
             SocketChannel sender = SocketChannel.open(server.getLocalAddress());
             SocketChannel receiver = server.accept()) {
            sender.setOption(StandardSocketOptions.TCP_NODELAY, true);
            ByteBuffer out = ByteBuffer.allocateDirect(bytes);
            ByteBuffer in = ByteBuffer.allocateDirect(bytes);
            for (int i = 0; i < bytes; i++) {
                out.put(i, (byte) i);
            }
            hops(sender, receiver, out, in, hops);
            long before = threads.getCurrentThreadCpuTime();
            hops(sender, receiver, out, in, hops);
            return (threads.getCurrentThreadCpuTime() - before) / 1_000.0 / hops;
        }
    }

    private static void hops(SocketChannel sender, SocketChannel receiver, ByteBuffer out, ByteBuffer in, int hops)
            throws IOException {
        for (int h = 0; h < hops; h++) {
            out.clear();
            while (out.hasRemaining()) {
                sender.write(out);
            }
            in.clear();
            while (in.hasRemaining()) {
                if (receiver.read(in) < 0) {
                    throw new IOException("The loopback connection closed after " + h + " hops.");
                }
            }
            if (in.flip().compareTo(out.flip()) != 0) {
                throw new IOException("Hop " + h + " read other bytes than were written.");
            }
        }
    }
}

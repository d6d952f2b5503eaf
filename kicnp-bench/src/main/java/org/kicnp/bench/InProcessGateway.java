package org.kicnp.bench;

import java.lang.management.ManagementFactory;
import java.net.InetSocketAddress;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.gateway.Transport;

/**
 * The gateway inside the bench's own JVM, beside the clients ({@code --gateway-in-process}): the clients' garbage
 * collections and compilations stall it too. Kept to compare with {@link GatewayProcess}.
 */
final class InProcessGateway implements KicnpHub {
    private final GatewayServer server;

    private InProcessGateway(GatewayServer server) {
        this.server = server;
    }

    /** Starts the gateway on an ephemeral loopback port, authenticating the bench's {@code agents}. */
    static InProcessGateway start(int agents, int ioThreads, Transport transport) {
        GatewayConfig config = GatewayConfig.defaults().withPort(0).withTransport(transport);
        if (ioThreads > 0) {
            config = config.withIoThreads(ioThreads);
        }
        return new InProcessGateway(GatewayServer.start(config, GatewayMain.directory(agents), KnowledgeBase.create(),
                FeedbackListener.NONE));
    }

    @Override public InetSocketAddress address() {
        return server.address();
    }

    @Override public long shed() {
        return server.metrics().shed();
    }

    /** This process's CPU time minus the clients'. */
    @Override public long cpuNanos(long clientCpuNanos) {
        var os = ManagementFactory.getOperatingSystemMXBean();
        long process = os instanceof com.sun.management.OperatingSystemMXBean sun ? sun.getProcessCpuTime() : 0;
        return process - clientCpuNanos;
    }

    @Override public String metrics() {
        return server.metrics().toString();
    }

    @Override public String describe() {
        return "in the bench's JVM, beside the clients";
    }

    @Override public void close() {
        server.close();
    }
}

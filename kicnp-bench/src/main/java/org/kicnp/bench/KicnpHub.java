package org.kicnp.bench;

import java.net.InetSocketAddress;

/**
 * The K-ICNP gateway a {@code bench gateway} run measures: either its own process ({@link GatewayProcess}, the
 * default, as Mosquitto is its own process) or inside the bench's JVM beside the clients ({@link InProcessGateway}).
 */
sealed interface KicnpHub extends AutoCloseable permits GatewayProcess, InProcessGateway {
    /** Where the clients connect (loopback). */
    InetSocketAddress address();

    /** Messages the gateway has shed so far (to connections above their write-buffer mark). */
    long shed();

    /**
     * The gateway's CPU time so far, in nanoseconds.
     *
     * @param clientCpuNanos the clients' CPU time so far, subtracted when the gateway shares the clients' process
     */
    long cpuNanos(long clientCpuNanos);

    /** The gateway's counters, for people watching the run. */
    String metrics();

    /** Where the gateway runs and with which JVM options, for the report's preamble. */
    String describe();

    @Override void close();
}

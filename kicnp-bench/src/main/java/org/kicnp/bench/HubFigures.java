package org.kicnp.bench;

/**
 * One hub's figures at one agent count: closed-loop throughput in relayed (delivered) messages per second, and
 * the open-loop latency at the fixed offered load.
 *
 * @param hubCpuMicrosPerMsg CPU time the hub spent per delivered message in the throughput run (for K-ICNP the
 *     whole process's CPU time minus the client loops', so JIT and GC are charged to the gateway)
 * @param clientCpuMicrosPerMsg CPU time the client event loops spent per delivered message
 * @param shed messages the hub dropped (K-ICNP's slow-consumer shedding; 0 for Mosquitto, which does not say)
 */
record HubFigures(double msgsPerSecond, LatencyFigures latency, long shed, double hubCpuMicrosPerMsg,
                  double clientCpuMicrosPerMsg) {
}

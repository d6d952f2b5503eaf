package org.kicnp.bench;

/**
 * One hub's figures at one agent count: closed-loop throughput in relayed (delivered) messages per second, and
 * the open-loop latency at the fixed offered load.
 *
 * @param shed messages the hub dropped (K-ICNP's slow-consumer shedding; 0 for Mosquitto, which does not say)
 */
record HubFigures(double msgsPerSecond, LatencyFigures latency, long shed) {
}

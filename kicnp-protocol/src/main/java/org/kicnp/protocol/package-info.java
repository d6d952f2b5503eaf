/**
 * The K-ICNP wire protocol: the closed set of {@link org.kicnp.protocol.Message}s exchanged between the gateway
 * (the paper's server agent) and robot, user, service and peer agents, and their length-prefixed JSON encoding.
 * The contract for agents in other languages is {@code docs/protocol.md} with its JSON Schemas.
 */
package org.kicnp.protocol;

/**
 * The network gateway: the paper's "daemon program allowing networked software agents to access knowledge stored
 * in K-ICNP", and its server agent, "a message-switching hub" between user and robot agents. Netty, one class per
 * role: {@link org.kicnp.gateway.GatewayServer} (bootstrap), {@code GatewayInitializer} (pipeline),
 * {@code FrameDecoder} (frames; plain relays forwarded from the read buffer), {@code MessageDecoder}/
 * {@code MessageEncoder} (codec), {@code GatewayHandler} (one per connection), and behind
 * it the server agent's parts: {@code ServerAgent} (authentication, registration, relay), {@code Commands}
 * (the platform's {@link org.kicnp.gateway.ActionSink} and feedback), {@code KnowledgeAccess} (queries,
 * subscriptions, knowledge between platforms) and {@code RuntimeFrames} (presence, sensor and feedback frames).
 */
package org.kicnp.gateway;

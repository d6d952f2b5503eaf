package org.kicnp.bench;

import io.netty.channel.ChannelPipeline;
import java.util.concurrent.CompletableFuture;

/**
 * One side of the comparison: how a benchmark agent speaks to its hub. Both clients run on the same Netty event
 * loops with the same batching (one flush per batch of reads), so the clients cost the two hubs alike.
 */
sealed interface RelayClient permits KicnpRelayClient, MqttRelayClient {
    /** A short description for the report. */
    String describe();

    /** The encoder of the messages {@code name} sends to {@code peer}. */
    RelayAgent.Encoder encoderFor(String name, String peer);

    /**
     * Installs the client's handlers; they complete {@code ready} once the agent can send and receive, and from
     * then on report each delivery to the agent's {@link RelayLoop}.
     */
    void initPipeline(ChannelPipeline pipeline, RelayAgent agent, CompletableFuture<Void> ready);
}

package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.channel.embedded.EmbeddedChannel;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/**
 * Relays between connections of one event loop are written when the sender's batch of reads ends, not after a
 * whole round of reads; and a batch whose end is never signalled is still drained by the loop's tasks.
 */
class ReadBatchTest {
    private final KnowledgeBase kb = KnowledgeBase.create();
    private final GatewayMetrics metrics = new GatewayMetrics();
    private final GatewayConfig config = GatewayConfig.defaults();
    private final ServerAgent[] server = new ServerAgent[1];
    private final EmbeddedChannel alice = Wire.channel(config,
            AgentDirectory.empty().with("alice", "a", AgentKind.USER).with("bob", "b", AgentKind.USER), kb,
            FeedbackListener.NONE, metrics, server);
    private final EmbeddedChannel bob = Wire.channel(config, server[0], metrics);

    @AfterEach
    void close() {
        alice.finishAndReleaseAll();
        bob.finishAndReleaseAll();
    }

    private static void join(EmbeddedChannel ch, String name, String token) {
        ch.writeInbound(Wire.frame(new Message.Hello("h", name, AgentKind.USER, token)));
        ch.writeInbound(Wire.frame(new Message.Register("r", List.of())));
        assertThat(Wire.written(ch)).containsExactly(new Message.AuthResult("h", true, "kicnp", Optional.empty()),
                new Message.Ack("r"));
    }

    @Test
    void relay_isWrittenToItsReceiver_whenTheSendersReadBatchEnds() {
        join(alice, "alice", "a");
        join(bob, "bob", "b");
        Message.Relay hi = Message.Relay.toAgent("", "alice", "bob", "say", "hi");

        alice.pipeline().fireChannelRead(Wire.frame(hi));
        assertThat((Object) bob.readOutbound()).as("nothing written while alice's reads go on").isNull();

        alice.pipeline().fireChannelReadComplete();
        assertThat((Object) bob.readOutbound()).as("written without waiting for a task").isNotNull()
                .satisfies(b -> ((io.netty.buffer.ByteBuf) b).release());
    }

    @Test
    void relaysOfOneBatch_toOneReceiver_areWrittenInOrderAsOneBuffer() {
        join(alice, "alice", "a");
        join(bob, "bob", "b");
        Message.Relay one = Message.Relay.toAgent("", "alice", "bob", "say", "one");
        Message.Relay two = Message.Relay.toAgent("", "alice", "bob", "say", "two");

        alice.pipeline().fireChannelRead(Wire.frame(one));
        alice.pipeline().fireChannelRead(Wire.frame(two));
        alice.pipeline().fireChannelReadComplete();

        assertThat(bob.outboundMessages()).hasSize(1);
        assertThat(Wire.written(bob)).containsExactly(one, two);
    }

    @Test
    void batchWhoseEndIsNeverSignalled_isDrainedByTheLoopsTasks() {
        join(alice, "alice", "a");
        join(bob, "bob", "b");
        Message.Relay hi = Message.Relay.toAgent("", "alice", "bob", "say", "hi");

        alice.pipeline().fireChannelRead(Wire.frame(hi));
        assertThat((Object) bob.readOutbound()).isNull();

        assertThat(Wire.written(bob)).as("the receiver's loop ran its tasks").containsExactly(hi);
    }
}

package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
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
 * whole round of reads; and a batch whose end is never signalled is still drained by the loop's tasks. The frame
 * decoder's fast path for plain relays ({@link FrameDecoder}): a relay that names its sender is copied from the
 * sender's read buffer into the receiver's next write, keeping no reference to that buffer; and relays so copied keep
 * their order with messages that wait in the receiver's outbox.
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
                .satisfies(b -> ((ByteBuf) b).release());
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

    @Test
    void plainRelay_isCopiedOutOfTheSendersReadBuffer_beforeTheReceiverIsWritten() {
        join(alice, "alice", "a");
        join(bob, "bob", "b");
        Message.Relay hi = Message.Relay.toAgent("", "alice", "bob", "say", "hi");
        ByteBuf read = Wire.frame(hi);

        alice.pipeline().fireChannelRead(read);

        assertThat((Object) bob.readOutbound()).as("written when alice's batch of reads ends").isNull();
        assertThat(read.refCnt()).as("no slice of alice's read buffer waits for bob's write").isZero();
        alice.pipeline().fireChannelReadComplete();
        assertThat(Wire.written(bob)).containsExactly(hi);
        assertThat(metrics.received.sum()).as("hello, register, hello, register, relay").isEqualTo(5);
    }

    @Test
    void relaysCopiedAtOnce_andMessagesQueuedMeanwhile_reachTheReceiverInTheOrderTheHubTookThem() {
        join(alice, "alice", "a");
        join(bob, "bob", "b");
        Message.Relay one = Message.Relay.toAgent("", "alice", "bob", "say", "one");
        // Names another sender: decoded in full and queued in bob's outbox as a message, not copied.
        Message.Relay two = Message.Relay.toAgent("", "carol", "bob", "say", "two");
        Message.Relay three = Message.Relay.toAgent("", "alice", "bob", "say", "three");

        alice.pipeline().fireChannelRead(Wire.frame(one));
        alice.pipeline().fireChannelRead(Wire.frame(two));
        alice.pipeline().fireChannelRead(Wire.frame(three));
        alice.pipeline().fireChannelReadComplete();

        assertThat(Wire.written(bob)).containsExactly(one, Message.Relay.toAgent("", "alice", "bob", "say", "two"),
                three);
    }

    @Test
    void severalFramesInOneRead_areTakenInOrder_aroundAMessageThatIsNotARelay() {
        join(alice, "alice", "a");
        join(bob, "bob", "b");
        Message.Relay one = Message.Relay.toAgent("", "alice", "bob", "say", "one");
        Message.Relay three = Message.Relay.toAgent("7", "alice", "bob", "say", "three");
        ByteBuf read = alice.alloc().buffer();
        for (Message m : List.of(one, new Message.Heartbeat(1), three)) {
            ByteBuf f = Wire.frame(m);
            read.writeBytes(f);
            f.release();
        }

        alice.pipeline().fireChannelRead(read);
        alice.pipeline().fireChannelReadComplete();

        assertThat(Wire.written(bob)).containsExactly(one, three);
        assertThat(Wire.written(alice)).containsExactly(new Message.Ack("7"));
    }
}

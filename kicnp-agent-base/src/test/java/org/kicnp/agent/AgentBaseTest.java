package org.kicnp.agent;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;

/** The SDK's connection life cycle against a minimal scripted server on loopback (the gateway is tested elsewhere). */
class AgentBaseTest {
    private static final MessageCodec CODEC = new MessageCodec();

    @Test
    void awaitConnected_withNoServer_timesOutWithAddress() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        try (UserAgent a = new UserAgent(AgentOptions.of("127.0.0.1", port, "alice", AgentKind.USER, "t")
                .withBackoff(Duration.ofMillis(10), Duration.ofMillis(50)))) {
            a.start();
            assertThatThrownBy(() -> a.awaitConnected(Duration.ofMillis(300))).isInstanceOf(AgentTimeoutException.class)
                    .hasMessageStartingWith("Agent 'alice' was not registered with 127.0.0.1:" + port + " within 300 ms; "
                            + "the last attempt failed: ")
                    .hasMessageContaining("Connection refused");
            assertThatThrownBy(() -> a.query("Cup")).isInstanceOf(NotConnectedException.class);
        }
    }

    @Test
    void agent_retriesUntilServerAccepts_thenRegisters() throws Exception {
        AtomicInteger connections = new AtomicInteger();
        try (ServerSocket server = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
             UserAgent a = new UserAgent(AgentOptions.of("127.0.0.1", server.getLocalPort(), "alice", AgentKind.USER, "t")
                     .withBackoff(Duration.ofMillis(10), Duration.ofMillis(50)))) {
            Thread.ofVirtual().start(() -> {
                try {
                    server.accept().close(); // first attempt: dropped at once
                    connections.incrementAndGet();
                    Socket s = server.accept();
                    connections.incrementAndGet();
                    DataInputStream in = new DataInputStream(s.getInputStream());
                    DataOutputStream out = new DataOutputStream(s.getOutputStream());
                    Message.Hello hello = (Message.Hello) CODEC.decode(Framing.read(in, 1 << 20));
                    Framing.write(out, CODEC.encode(new Message.AuthResult(hello.id(), true, "fake", Optional.empty())));
                    Message.Register reg = (Message.Register) CODEC.decode(Framing.read(in, 1 << 20));
                    Framing.write(out, CODEC.encode(new Message.Ack(reg.id())));
                    Thread.sleep(5_000);
                } catch (Exception ignored) {
                    // the test ends by closing the server socket
                }
            });
            a.startAndAwait(Duration.ofSeconds(10));
            assertThat(a.isConnected()).isTrue();
            assertThat(connections.get()).isEqualTo(2);
        }
    }

    @Test
    void refusedHello_stopsTheAgentWithAuthenticationException() throws Exception {
        try (ServerSocket server = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
             UserAgent a = new UserAgent(AgentOptions.of("127.0.0.1", server.getLocalPort(), "alice", AgentKind.USER, "t"))) {
            Thread.ofVirtual().start(() -> {
                try (Socket s = server.accept()) {
                    DataInputStream in = new DataInputStream(s.getInputStream());
                    Message.Hello hello = (Message.Hello) CODEC.decode(Framing.read(in, 1 << 20));
                    Framing.write(new DataOutputStream(s.getOutputStream()), CODEC.encode(
                            new Message.AuthResult(hello.id(), false, "fake", Optional.of("Wrong token"))));
                } catch (Exception ignored) {
                    // nothing to clean up
                }
            });
            assertThatThrownBy(() -> a.startAndAwait(Duration.ofSeconds(10))).isInstanceOf(AuthenticationException.class)
                    .hasMessage("Server refused agent 'alice': Wrong token.");
        }
    }

    /**
     * An error without id while the agent says hello or registers is about that connection (a timeout, a failure in
     * the server), not a refusal of the agent: it is logged and the agent connects again.
     */
    @Test
    void errorWithoutId_whileRegistering_doesNotStopTheAgent_itConnectsAgain() throws Exception {
        try (FakeGateway server = new FakeGateway(
                peer -> {
                    peer.authenticate();
                    peer.readSkippingHeartbeats(); // the register
                    peer.send(Message.ErrorReply.of(ErrorCode.INTERNAL, "The server failed on this connection: boom."));
                },
                peer -> {
                    peer.readSkippingHeartbeats(); // the hello
                    peer.send(Message.ErrorReply.of(ErrorCode.HEARTBEAT_TIMEOUT,
                            "Nothing was heard from this connection within the heartbeat timeout."));
                },
                peer -> {
                    peer.register();
                    peer.drain();
                });
             UserAgent a = new UserAgent(alice(server))) {
            a.startAndAwait(Duration.ofSeconds(10));
            assertThat(a.isConnected()).isTrue();
            assertThat(a.stopped()).isEmpty();
            assertThat(server.connections()).isEqualTo(3);
        }
    }

    /** An agent replaced by a newer connection under its name stops, and is seen disconnected once it is seen stopped. */
    @Test
    void agentReplacedByANewerConnection_stops_andIsNotConnectedOnceStopped() throws Exception {
        try (FakeGateway server = new FakeGateway(peer -> {
            peer.register();
            peer.send(Message.ErrorReply.of(ErrorCode.SUPERSEDED, "Agent 'alice' was replaced by a newer connection."));
            peer.drain();
        });
             UserAgent a = new UserAgent(alice(server))) {
            a.start();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (a.stopped().isEmpty() && System.nanoTime() < deadline) {
                Thread.onSpinWait();
            }
            assertThat(a.isConnected()).as("connected when first seen stopped").isFalse();
            assertThat(a.stopped()).get().extracting(Throwable::getMessage)
                    .isEqualTo("Agent 'alice' stops: Agent 'alice' was replaced by a newer connection.");
            assertThat(server.connections()).isEqualTo(1);
        }
    }

    /**
     * A request longer than the server's frame limit is refused as soon as its length is read, and the server closes
     * after saying so, while the agent may still be writing it. The caller hears the server's reason, not that the
     * socket closed under the write: here the server reads nothing more, so the write is still stuck when the agent
     * reads the refusal and the end of the stream and closes its socket.
     */
    @Test
    void requestRefusedForItsLength_whileStillBeingWritten_failsWithTheServersReason() throws Exception {
        int tooLong = 32 << 20; // more than loopback's socket buffers hold: the write waits for a reader
        CountDownLatch over = new CountDownLatch(1);
        try (FakeGateway server = new FakeGateway(peer -> {
            peer.register();
            int length = peer.readLengthOfAFrameOfAtLeast(tooLong);
            peer.send(Message.ErrorReply.of(ErrorCode.FRAME_TOO_LARGE,
                    "A frame of " + length + " bytes is longer than this server accepts (1048576 bytes at most)."));
            peer.shutdownOutput();
            over.await(30, TimeUnit.SECONDS); // open, unread: the agent's write cannot finish
        });
             UserAgent a = new UserAgent(alice(server).withMaxFrameBytes(64 << 20))) {
            a.startAndAwait(Duration.ofSeconds(10));

            assertThatThrownBy(() -> a.relayTo("bob", "note", "x".repeat(tooLong)))
                    .isInstanceOfSatisfying(RequestRefusedException.class,
                            e -> assertThat(e.code()).isEqualTo(ErrorCode.FRAME_TOO_LARGE))
                    .hasMessageContaining("longer than this server accepts (1048576 bytes at most)");
        } finally {
            over.countDown();
        }
    }

    /** An id-less {@code not_authenticated} answering the hello is a refusal: the agent stops, saying so. */
    @Test
    void notAuthenticatedWithoutId_answeringTheHello_stopsTheAgentWithAuthenticationException() throws Exception {
        try (FakeGateway server = new FakeGateway(peer -> {
            peer.readSkippingHeartbeats();
            peer.send(Message.ErrorReply.of(ErrorCode.NOT_AUTHENTICATED, "Send 'hello' first."));
        });
             UserAgent a = new UserAgent(alice(server))) {
            assertThatThrownBy(() -> a.startAndAwait(Duration.ofSeconds(10))).isInstanceOf(AuthenticationException.class)
                    .hasMessage("Server refused agent 'alice': Send 'hello' first.");
            assertThat(server.connections()).isEqualTo(1);
        }
    }

    /**
     * A snapshot is the query's frames with the server's clock when it read them; from a server that does not send
     * that clock (before 'frames' had 'time'), the frames alone, the clock empty. {@code query} gives the frames either way.
     */
    @Test
    void snapshot_carriesTheServersClock_whenItSaysIt_andIsEmptyWhenItDoesNot() throws Exception {
        String cup = "<FRAME><NAME>cup1</NAME><ISA>Cup</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>";
        try (FakeGateway server = new FakeGateway(peer -> {
            peer.register();
            Message.Query q = (Message.Query) peer.readSkippingHeartbeats();
            peer.send(new Message.Frames(q.id(), List.of(cup), Optional.of(1_234_567_890_123L)));
            q = (Message.Query) peer.readSkippingHeartbeats();
            peer.send(new Message.Frames(q.id(), List.of(cup), Optional.empty()));
            q = (Message.Query) peer.readSkippingHeartbeats();
            peer.send(new Message.Frames(q.id(), List.of(cup), Optional.empty()));
            peer.drain();
        });
             UserAgent a = new UserAgent(alice(server))) {
            a.startAndAwait(Duration.ofSeconds(10));

            AgentBase.Snapshot told = a.snapshot("Cup");
            AgentBase.Snapshot untold = a.snapshot("Cup");
            List<Frame> queried = a.query("Cup");

            assertThat(told.serverTime()).contains(1_234_567_890_123L);
            assertThat(told.frames()).extracting(Frame::name).containsExactly("cup1");
            assertThat(untold.serverTime()).isEmpty();
            assertThat(untold.frames()).extracting(Frame::name).containsExactly("cup1");
            assertThat(queried).extracting(Frame::name).containsExactly("cup1");
        }
    }

    /**
     * A server of this protocol answers a register before it sends the agent anything else; one that did not (an
     * older gateway could queue a command a behavior frame issued the moment the robot's presence appeared ahead of
     * the answer) no longer has that command passed by while the agent waits for the answer: it runs once registered.
     */
    @Test
    void commandSentBeforeTheAnswerToTheRegister_isCarriedOut_notPassedBy() throws Exception {
        BlockingQueue<Message> heard = new LinkedBlockingQueue<>();
        try (FakeGateway server = new FakeGateway(peer -> {
            peer.authenticate();
            Message.Register reg = (Message.Register) peer.readSkippingHeartbeats();
            peer.send(new Message.Command("c1", "bot", "wave", java.util.Map.of()));
            peer.send(new Message.Ack(reg.id()));
            while (true) {
                heard.add(peer.readSkippingHeartbeats());
            }
        });
             AgentBase bot = new AgentBase(AgentOptions.of("127.0.0.1", server.port(), "bot", AgentKind.ROBOT, "t")) {
                 @Override protected void onCommand(Message.Command command, ActionHandle handle) {
                     handle.started();
                     handle.ended("waved");
                 }
             }) {
            bot.startAndAwait(Duration.ofSeconds(10));

            Message first = heard.poll(10, TimeUnit.SECONDS);
            Message second = heard.poll(10, TimeUnit.SECONDS);
            assertThat(List.of(first, second)).extracting(m -> ((Message.Feedback) m).stage().name())
                    .containsExactly("STARTED", "ENDED");
            assertThat(((Message.Feedback) second).detail()).isEqualTo("waved");
        }
    }

    /** A subscription the server refuses to renew after a reconnect is reported to the agent, and has ended. */
    @Test
    void resubscription_refusedAfterAReconnect_isReportedThroughOnSubscriptionRefused() throws Exception {
        try (FakeGateway server = new FakeGateway(
                peer -> {
                    peer.register();
                    Message.Subscribe sub = (Message.Subscribe) peer.readSkippingHeartbeats();
                    peer.send(new Message.Ack(sub.id()));
                }, // then the connection drops
                peer -> {
                    peer.register();
                    Message.Subscribe again = (Message.Subscribe) peer.readSkippingHeartbeats();
                    peer.send(Message.ErrorReply.to(again.id(), ErrorCode.UNKNOWN_FRAME, "No frame 'Cup' exists."));
                    peer.drain();
                });
             Subscriber a = new Subscriber(alice(server))) {
            a.startAndAwait(Duration.ofSeconds(10));
            a.subscribe("Cup");
            RequestRefusedException refusal = a.refused.poll(10, TimeUnit.SECONDS);
            assertThat(refusal).isNotNull();
            assertThat(refusal.code()).isEqualTo(ErrorCode.UNKNOWN_FRAME);
            assertThat(refusal).hasMessage("No frame 'Cup' exists.");
            assertThat(a.refusedClasses).containsExactly("Cup");
            assertThat(server.connections()).isEqualTo(2);
        }
    }

    /** Records the subscriptions the server refused to renew. */
    private static final class Subscriber extends UserAgent {
        final BlockingQueue<RequestRefusedException> refused = new LinkedBlockingQueue<>();
        final List<String> refusedClasses = new CopyOnWriteArrayList<>();

        Subscriber(AgentOptions options) {
            super(options);
        }

        @Override protected void onSubscriptionRefused(String ofClass, RequestRefusedException reason) {
            refusedClasses.add(ofClass);
            refused.add(reason);
        }
    }

    /** A request the server never answers times out with a sentence people read ("300 ms", not "PT0.3S"). */
    @Test
    void request_thatTheServerNeverAnswers_timesOutSayingWhichAndHowLong() throws Exception {
        try (ServerSocket server = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            AgentOptions o = AgentOptions.of("127.0.0.1", server.getLocalPort(), "alice", AgentKind.USER, "t")
                    .withRequestTimeout(Duration.ofMillis(300));
            Thread.ofVirtual().start(() -> {
                try (Socket s = server.accept()) {
                    DataInputStream in = new DataInputStream(s.getInputStream());
                    DataOutputStream out = new DataOutputStream(s.getOutputStream());
                    Message.Hello hello = (Message.Hello) CODEC.decode(Framing.read(in, 1 << 20));
                    Framing.write(out, CODEC.encode(new Message.AuthResult(hello.id(), true, "fake", Optional.empty())));
                    Message.Register reg = (Message.Register) CODEC.decode(Framing.read(in, 1 << 20));
                    Framing.write(out, CODEC.encode(new Message.Ack(reg.id())));
                    while (true) {
                        Framing.read(in, 1 << 20); // reads everything, answers nothing
                    }
                } catch (Exception ignored) {
                    // the test ends by closing the agent
                }
            });
            try (UserAgent a = new UserAgent(o)) {
                a.startAndAwait(Duration.ofSeconds(10));
                assertThatThrownBy(() -> a.query("Cup")).isInstanceOf(AgentTimeoutException.class)
                        .hasMessageMatching("The server did not answer Query '\\d+' within 300 ms\\.");
                assertThat(a.isConnected()).isTrue();
            }
        }
    }

    /**
     * A command id is the agent's name, the time and a counter; for a name near the limit it keeps only the name's
     * beginning, so the id stays within the limit every request id is held to and the command is sent.
     */
    @Test
    void command_ofAnAgentWithTheLongestName_hasAnIdWithinTheLimit() throws Exception {
        String id = sentCommandId("n".repeat(Message.MAX_NAME_LENGTH));

        assertThat(id).hasSize(Message.MAX_NAME_LENGTH).matches("n+-[0-9a-z]+-[0-9]+");
    }

    /** A name of letters beyond the basic plane (two UTF-16 units each) is never cut between the two. */
    @Test
    void command_ofAnAgentWithTheLongestNameOfTwoUnitLetters_keepsWholeLetters() throws Exception {
        String letter = "\uD835\uDC9C"; // MATHEMATICAL SCRIPT CAPITAL A
        String id = sentCommandId(letter.repeat(Message.MAX_NAME_LENGTH / 2));

        assertThat(id.length()).isLessThanOrEqualTo(Message.MAX_NAME_LENGTH);
        assertThat(id.substring(0, id.indexOf('-'))).matches("(" + letter + ")+");
    }

    /** The id of the command an agent called {@code name} sends, as the server received it and the ticket holds it. */
    private static String sentCommandId(String name) throws Exception {
        BlockingQueue<Message.Command> sent = new LinkedBlockingQueue<>();
        try (FakeGateway gateway = new FakeGateway(peer -> {
            peer.register();
            Message.Command c = (Message.Command) peer.readSkippingHeartbeats();
            sent.add(c);
            peer.send(new Message.Ack(c.id()));
            peer.drain();
        }); UserAgent a = new UserAgent(AgentOptions.of("127.0.0.1", gateway.port(), name, AgentKind.USER, "t"))) {
            a.startAndAwait(Duration.ofSeconds(10));

            CommandTicket ticket = a.command("scout", "fetch", java.util.Map.of());

            Message.Command c = sent.poll(10, TimeUnit.SECONDS);
            assertThat(c).as("the command the server received").isNotNull();
            assertThat(c.id()).isEqualTo(ticket.command().id());
            return c.id();
        }
    }

    /** User agent alice of the fake gateway, retrying quickly. */
    private static AgentOptions alice(FakeGateway server) {
        return AgentOptions.of("127.0.0.1", server.port(), "alice", AgentKind.USER, "t")
                .withBackoff(Duration.ofMillis(10), Duration.ofMillis(50));
    }
}

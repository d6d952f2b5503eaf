package org.kicnp.gateway;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.core.Change;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;

/**
 * Knowledge between platforms (section 3.2: the XML "can be also transmitted over the network to a remote
 * K-ICNP"): this server connects to another as a {@code peer} agent and pushes a subtree or its whole knowledge
 * base there, or pulls frames from it. The remote side stores a push all or none; {@link #pullInto} does the same
 * here.
 */
public final class PlatformLink implements AutoCloseable {
    private static final class Peer extends AgentBase {
        Peer(AgentOptions options) {
            super(options);
        }
    }

    private final Peer peer;

    private PlatformLink(Peer peer) {
        this.peer = peer;
    }

    /**
     * Connects to another K-ICNP server as a peer agent and waits until it is registered.
     *
     * @throws org.kicnp.agent.AgentException when the remote server refuses or cannot be reached in time
     */
    public static PlatformLink connect(AgentOptions options, Duration timeout) {
        if (options.kind() != AgentKind.PEER) {
            throw new IllegalArgumentException("A platform link connects as a peer agent, not as " + options.kind() + ".");
        }
        Peer p = new Peer(options);
        try {
            p.startAndAwait(timeout);
        } catch (RuntimeException e) {
            p.close();
            throw e;
        }
        return new PlatformLink(p);
    }

    /**
     * Pushes the durable frames of a subtree of {@code from} (or all of them, without a root) to the remote server.
     *
     * @return the number of frames sent
     * @throws org.kicnp.agent.RequestRefusedException listing the problems when the remote server refused them
     */
    public int push(KnowledgeBase from, Optional<String> root) {
        requireNonNull(from, "from");
        root.ifPresent(from::require);
        List<Frame> frames = Subtree.of(from, root);
        peer.push(frames);
        return frames.size();
    }

    /** The remote server's durable frames of a subtree (or all of them), parents first. */
    public List<Frame> pull(Optional<String> root) {
        return peer.pull(root);
    }

    /**
     * Pulls from the remote server and stores the frames in {@code into} as one batch of upserts, all or none.
     *
     * @throws org.kicnp.core.BatchRejectedException listing every problem, when the frames do not fit here
     */
    public ChangeSet pullInto(KnowledgeBase into, Optional<String> root) {
        return into.apply(pull(root).stream().map(Change.Put::new).toList());
    }

    @Override public void close() {
        peer.close();
    }
}

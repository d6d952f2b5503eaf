package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import java.util.Optional;

/**
 * The live platform the editor's World panel talks to: each port is optional. Without a port its panel says
 * "not connected to a platform" and its API answers 503 with a sentence. {@code ./kicnp serve} fills them in;
 * {@link #none()} is an editor on a knowledge base alone.
 */
public final class PlatformPorts {
    private static final PlatformPorts NONE = new PlatformPorts(null, null, null);

    private final WorldView world;
    private final ChatPort chat;
    private final TeleOperation teleOperation;

    private PlatformPorts(WorldView world, ChatPort chat, TeleOperation teleOperation) {
        this.world = world;
        this.chat = chat;
        this.teleOperation = teleOperation;
    }

    /** No platform: the editor edits knowledge only. */
    public static PlatformPorts none() {
        return NONE;
    }

    /** These ports with the world view set. */
    public PlatformPorts withWorld(WorldView view) {
        return new PlatformPorts(requireNonNull(view, "view"), chat, teleOperation);
    }

    /** These ports with the chat set. */
    public PlatformPorts withChat(ChatPort port) {
        return new PlatformPorts(world, requireNonNull(port, "port"), teleOperation);
    }

    /** These ports with tele-operation set. */
    public PlatformPorts withTeleOperation(TeleOperation port) {
        return new PlatformPorts(world, chat, requireNonNull(port, "port"));
    }

    public Optional<WorldView> world() {
        return Optional.ofNullable(world);
    }

    public Optional<ChatPort> chat() {
        return Optional.ofNullable(chat);
    }

    public Optional<TeleOperation> teleOperation() {
        return Optional.ofNullable(teleOperation);
    }
}

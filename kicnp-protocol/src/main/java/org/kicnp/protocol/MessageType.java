package org.kicnp.protocol;

import java.util.Arrays;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.stream.Collectors;

/** The {@code "type"} discriminator of each {@link Message} record: the one place wire names are spelled. */
public enum MessageType {
    HELLO(Message.Hello.class),
    AUTH_RESULT(Message.AuthResult.class),
    REGISTER(Message.Register.class),
    ACK(Message.Ack.class),
    HEARTBEAT(Message.Heartbeat.class),
    RELAY(Message.Relay.class),
    COMMAND(Message.Command.class),
    FEEDBACK(Message.Feedback.class),
    CANCEL(Message.Cancel.class),
    SENSOR(Message.SensorSignal.class),
    QUERY(Message.Query.class),
    FRAMES(Message.Frames.class),
    ASK(Message.Ask.class),
    ANSWER(Message.Answer.class),
    ASSERT(Message.Assert.class),
    DESTROY(Message.Destroy.class),
    SUBSCRIBE(Message.Subscribe.class),
    UNSUBSCRIBE(Message.Unsubscribe.class),
    CHANGED(Message.Changed.class),
    PUSH(Message.Push.class),
    PULL(Message.Pull.class),
    PROVE(Message.Prove.class),
    PROOFS(Message.Proofs.class),
    WHY(Message.Why.class),
    EXPLAINED(Message.Explained.class),
    WHY_NOT(Message.WhyNot.class),
    NOT_FIRED(Message.NotFired.class),
    ERROR(Message.ErrorReply.class);

    private static final Map<String, MessageType> BY_WIRE_NAME =
            Arrays.stream(values()).collect(Collectors.toUnmodifiableMap(MessageType::wireName, Function.identity()));
    private static final Map<Class<?>, MessageType> BY_CLASS =
            Arrays.stream(values()).collect(Collectors.toUnmodifiableMap(t -> t.recordClass, Function.identity()));

    private final Class<? extends Message> recordClass;

    MessageType(Class<? extends Message> recordClass) {
        this.recordClass = recordClass;
    }

    /** The record this type decodes into. */
    public Class<? extends Message> recordClass() {
        return recordClass;
    }

    /** The value of {@code "type"} on the wire, such as {@code auth_result}. */
    public String wireName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The type with this wire name, if it is one. */
    public static Optional<MessageType> fromWireName(String wireName) {
        return Optional.ofNullable(BY_WIRE_NAME.get(wireName));
    }

    /** The type of a message. */
    public static MessageType of(Message message) {
        return BY_CLASS.get(message.getClass());
    }
}

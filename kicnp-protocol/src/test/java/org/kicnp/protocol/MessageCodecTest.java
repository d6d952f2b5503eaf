package org.kicnp.protocol;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import org.kicnp.core.Value;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class MessageCodecTest {
    private final MessageCodec codec = new MessageCodec();

    static java.util.stream.Stream<Message> samples() {
        return Samples.all().stream();
    }

    @ParameterizedTest
    @MethodSource("samples")
    void decode_ofEncoded_returnsEqualMessage(Message message) {
        assertThat(codec.decode(codec.encode(message))).isEqualTo(message);
    }

    @Test
    void samples_coverEveryMessageType() {
        Set<MessageType> covered = Samples.all().stream().map(MessageType::of).collect(Collectors.toSet());
        assertThat(covered).containsExactlyInAnyOrderElementsOf(EnumSet.allOf(MessageType.class));
        long records = Arrays.stream(Message.class.getPermittedSubclasses())
                .flatMap(c -> c.isRecord() ? java.util.stream.Stream.of(c) : Arrays.stream(c.getPermittedSubclasses()))
                .distinct().count();
        assertThat(records).isEqualTo(MessageType.values().length);
    }

    @Test
    void encode_writesEnvelopeFirstAndLowerCaseEnums() {
        String json = new String(codec.encode(new Message.Hello("1", "scout", AgentKind.ROBOT, "t")), UTF_8);
        assertThat(json).isEqualTo(
                "{\"v\":1,\"type\":\"hello\",\"id\":\"1\",\"agent\":\"scout\",\"kind\":\"robot\",\"token\":\"t\"}");
    }

    @Test
    void encode_leavesOutAbsentOptionalMembers() {
        String json = new String(codec.encode(new Message.Pull("1", java.util.Optional.empty())), UTF_8);
        assertThat(json).isEqualTo("{\"v\":1,\"type\":\"pull\",\"id\":\"1\"}");
    }

    @Test
    void decode_ignoresUnknownMembers() {
        assertThat(decode("{\"v\":1,\"type\":\"ack\",\"id\":\"7\",\"later\":true}")).isEqualTo(new Message.Ack("7"));
    }

    @Test
    void decode_whenNotJson_reportsBadJson() {
        assertCode("GET / HTTP/1.1", ErrorCode.BAD_JSON, "not valid JSON");
        assertCode("[1,2]", ErrorCode.BAD_JSON, "one JSON object");
        assertCode("{\"v\":1,\"type\":\"ack\",\"id\":\"7\"} trailing", ErrorCode.BAD_JSON, "not valid JSON");
    }

    @Test
    void decode_whenVersionMissingOrOther_reportsUnsupportedVersion() {
        assertCode("{\"type\":\"ack\",\"id\":\"7\"}", ErrorCode.UNSUPPORTED_VERSION, "version (missing)");
        assertCode("{\"v\":2,\"type\":\"ack\",\"id\":\"7\"}", ErrorCode.UNSUPPORTED_VERSION, "version 2 is not supported");
    }

    @Test
    void decode_whenTypeUnknown_reportsUnknownTypeQuotingIt() {
        assertCode("{\"v\":1,\"type\":\"launch_missiles\"}", ErrorCode.UNKNOWN_TYPE, "Unknown message type 'launch_missiles'.");
    }

    @Test
    void decode_whenRequiredMemberMissing_reportsBadMessageNamingIt() {
        assertCode("{\"v\":1,\"type\":\"heartbeat\"}", ErrorCode.BAD_MESSAGE, "needs the member 'time'");
        assertCode("{\"v\":1,\"type\":\"hello\",\"id\":\"1\",\"agent\":\"a\",\"kind\":\"robot\"}",
                ErrorCode.BAD_MESSAGE, "needs the member 'token'");
    }

    @Test
    void decode_whenABindingOrArgumentIsNull_saysSoInWords() {
        assertCode("{\"v\":1,\"type\":\"prove\",\"id\":\"1\",\"ofClass\":\"C\",\"bindings\":{\"mUser\":null}}",
                ErrorCode.BAD_MESSAGE, "Bad 'prove' message: a value is null where the protocol wants one.");
        assertCode("{\"v\":1,\"type\":\"command\",\"id\":\"1\",\"robot\":\"scout\",\"action\":\"go\","
                + "\"args\":{\"to\":null}}", ErrorCode.BAD_MESSAGE,
                "Bad 'command' message: a value is null where the protocol wants one.");
    }

    @Test
    void decode_whenANumberOrBooleanStandsForAString_reportsBadMessage() {
        assertCode("{\"v\":1,\"type\":\"cancel\",\"id\":9,\"robot\":\"scout\",\"command\":\"c-1\",\"reason\":\"r\"}",
                ErrorCode.BAD_MESSAGE, "Bad 'cancel' message");
        assertCode("{\"v\":1,\"type\":\"destroy\",\"id\":\"1\",\"frame\":true}", ErrorCode.BAD_MESSAGE,
                "Bad 'destroy' message");
        assertCode("{\"v\":1,\"type\":\"prove\",\"id\":\"1\",\"ofClass\":\"C\",\"bindings\":{\"s\":5}}",
                ErrorCode.BAD_MESSAGE, "Bad 'prove' message");
        assertCode("{\"v\":1,\"type\":\"why\",\"id\":\"1\",\"instance\":1.5}", ErrorCode.BAD_MESSAGE,
                "Bad 'why' message");
        assertCode("{\"v\":1,\"type\":\"command\",\"id\":\"1\",\"robot\":\"scout\",\"action\":\"go\","
                + "\"args\":{\"speed\":2}}", ErrorCode.BAD_MESSAGE, "Bad 'command' message");
    }

    @Test
    void decode_whenMemberHasWrongTypeOrValue_reportsBadMessage() {
        assertCode("{\"v\":1,\"type\":\"heartbeat\",\"time\":\"noon\"}", ErrorCode.BAD_MESSAGE, "Bad 'heartbeat' message");
        assertCode("{\"v\":1,\"type\":\"hello\",\"id\":\"1\",\"agent\":\"a\",\"kind\":\"toaster\",\"token\":\"t\"}",
                ErrorCode.BAD_MESSAGE, "Bad 'hello' message");
        assertCode("{\"v\":1,\"type\":\"hello\",\"id\":\"1\",\"agent\":\"no spaces\",\"kind\":\"user\",\"token\":\"t\"}",
                ErrorCode.BAD_MESSAGE, "'no spaces' is not a valid agent name");
        assertCode("{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"subject\":\"s\",\"body\":\"b\"}",
                ErrorCode.BAD_MESSAGE, "exactly one of toAgent and toKind");
    }

    @Test
    void sensor_timeToLive_isAWholeNumberOfMillisecondsFromOneToADay() {
        String head = "{\"v\":1,\"type\":\"sensor\",\"source\":\"a\",\"sensor\":\"sonar\",\"values\":[1.5]";
        assertThat(decode(head + ",\"ttlMs\":250}")).isEqualTo(
                new Message.SensorSignal("a", "sonar", List.of(Value.of(1.5)), Optional.of(250L)));
        assertThat(decode(head + "}")).isEqualTo(new Message.SensorSignal("a", "sonar", List.of(Value.of(1.5))));
        assertThat(new String(codec.encode(new Message.SensorSignal("a", "sonar", List.of(), Optional.of(86_400_000L))),
                UTF_8)).contains("\"ttlMs\":86400000");
        assertCode(head + ",\"ttlMs\":0}", ErrorCode.BAD_MESSAGE,
                "The time to live of sensor 'sonar' must be 1 to 86400000 ms, not 0.");
        assertCode(head + ",\"ttlMs\":-5}", ErrorCode.BAD_MESSAGE, "not -5");
        assertCode(head + ",\"ttlMs\":86400001}", ErrorCode.BAD_MESSAGE, "not 86400001");
        assertCode(head + ",\"ttlMs\":\"250\"}", ErrorCode.BAD_MESSAGE, "Bad 'sensor' message");
        assertCode(head + ",\"ttlMs\":2.5}", ErrorCode.BAD_MESSAGE, "Bad 'sensor' message");
    }

    @Test
    void decode_relay_readsEveryFormTheGeneralPathAccepts_andRefusesTheRest() {
        assertThat(decode("{\"type\":\"relay\",\"body\":\"b\",\"v\":1,\"id\":\"1\",\"from\":\"a\",\"toKind\":\"ROBOT\","
                + "\"toAgent\":null,\"subject\":\"s\",\"extra\":{\"x\":[1,{}]}}"))
                .isEqualTo(Message.Relay.toKind("1", "a", AgentKind.ROBOT, "s", "b"));
        assertCode("{\"v\":1,\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"b\"}",
                ErrorCode.UNKNOWN_TYPE, "Unknown message type");
        assertCode("{\"v\":2,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"b\"}",
                ErrorCode.UNSUPPORTED_VERSION, "version 2");
        assertCode("{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":7}",
                ErrorCode.BAD_MESSAGE, "'body' must be a string");
        assertCode("{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"toKind\":\"user\","
                + "\"subject\":\"s\",\"body\":\"b\"}", ErrorCode.BAD_MESSAGE, "exactly one of toAgent and toKind");
        assertCode("{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toKind\":\"toaster\",\"subject\":\"s\","
                + "\"body\":\"b\"}", ErrorCode.BAD_MESSAGE, "Bad 'relay' message");
        assertCode("{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\"}",
                ErrorCode.BAD_MESSAGE, "needs the member 'body'");
        assertCode("{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"b\"}}",
                ErrorCode.BAD_JSON, "not valid JSON");
    }

    /** An agent learns which member was wrong, not a Java type name alone. */
    @Test
    void decode_whenAMemberHasTheWrongJsonType_namesTheMember() {
        assertCode("{\"v\":1,\"type\":\"query\",\"id\":{\"a\":1},\"ofClass\":\"Cup\"}", ErrorCode.BAD_MESSAGE,
                "Bad 'query' message: the member 'id': ");
        assertCode("{\"v\":1,\"type\":\"register\",\"id\":\"1\",\"capabilities\":\"<FRAME/>\"}",
                ErrorCode.BAD_MESSAGE, "Bad 'register' message: the member 'capabilities': ");
        assertCode("{\"v\":1,\"type\":\"sensor\",\"source\":\"a\",\"sensor\":\"sonar\",\"values\":[1],\"ttlMs\":\"250\"}",
                ErrorCode.BAD_MESSAGE, "Bad 'sensor' message: the member 'ttlMs': ");
        assertCode("{\"v\":1,\"type\":\"command\",\"id\":\"1\",\"robot\":\"scout\",\"action\":\"go\","
                + "\"args\":{\"speed\":2}}", ErrorCode.BAD_MESSAGE, "Bad 'command' message: the member 'args.speed': ");
        assertCode("{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toKind\":\"toaster\",\"subject\":\"s\","
                + "\"body\":\"b\"}", ErrorCode.BAD_MESSAGE,
                "Bad 'relay' message: the member 'toKind' must be robot, user, service or peer, not 'toaster'.");
    }

    /** A number is not one of the lower-case names of an enumerated member; Jackson would take it as an index. */
    @Test
    void decode_whenAnEnumeratedMemberIsANumber_reportsBadMessageNamingIt() {
        assertCode("{\"v\":1,\"type\":\"hello\",\"id\":\"1\",\"agent\":\"a\",\"kind\":0,\"token\":\"t\"}",
                ErrorCode.BAD_MESSAGE, "Bad 'hello' message: the member 'kind': ");
        assertCode("{\"v\":1,\"type\":\"feedback\",\"id\":\"c1\",\"robot\":\"a\",\"stage\":3,\"detail\":\"\"}",
                ErrorCode.BAD_MESSAGE, "Bad 'feedback' message: the member 'stage': ");
        assertCode("{\"v\":1,\"type\":\"error\",\"code\":5,\"message\":\"m\"}", ErrorCode.BAD_MESSAGE,
                "Bad 'error' message: the member 'code': ");
    }

    /** A version too large for a long is not version 1 (its low 64 bits would be). */
    @Test
    void decode_whenVersionIsAHugeNumber_reportsUnsupportedVersion() {
        assertCode("{\"v\":18446744073709551617,\"type\":\"ack\",\"id\":\"7\"}", ErrorCode.UNSUPPORTED_VERSION,
                "Protocol version 18446744073709551617 is not supported");
    }

    /** Progress is the fraction done: "NaN" (which Jackson reads for a number), 1e400 (Infinity) or 7 are not one. */
    @Test
    void feedback_progress_isAFractionFromZeroToOne() {
        String head = "{\"v\":1,\"type\":\"feedback\",\"id\":\"c1\",\"robot\":\"scout\",\"stage\":\"progress\",\"detail\":\"\"";
        assertThat(decode(head + ",\"progress\":0.5}")).isEqualTo(new Message.Feedback("c1", "scout",
                FeedbackStage.PROGRESS, Optional.of(0.5), ""));
        assertThat(decode(head + ",\"progress\":1}")).isEqualTo(new Message.Feedback("c1", "scout",
                FeedbackStage.PROGRESS, Optional.of(1.0), ""));
        assertCode(head + ",\"progress\":\"NaN\"}", ErrorCode.BAD_MESSAGE,
                "The progress of command 'c1' must be a fraction from 0.0 to 1.0, not NaN.");
        assertCode(head + ",\"progress\":1e400}", ErrorCode.BAD_MESSAGE, "not Infinity.");
        assertCode(head + ",\"progress\":7}", ErrorCode.BAD_MESSAGE, "not 7.0.");
        assertCode(head + ",\"progress\":-0.5}", ErrorCode.BAD_MESSAGE, "not -0.5.");
        assertThatThrownBy(() -> new Message.Feedback("c1", "scout", FeedbackStage.PROGRESS, Optional.of(50.0), ""))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("not 50.0.");
    }

    /**
     * A float JSON has no number for (a script's 0/0 in a slot, say) travels as {"float": "NaN"}, "Infinity" or
     * "-Infinity" and arrives a float again, at any depth of lists; another text there is not a value.
     */
    @Test
    void answer_floatsThatAreNotFinite_travelTagged_andArriveFloats() {
        Message.Answer a = new Message.Answer("q1", Optional.of(new Value.Lst(List.of(Value.of(Double.NaN),
                Value.of(Double.POSITIVE_INFINITY), new Value.Lst(List.of(Value.of(1.5),
                        Value.of(Double.NEGATIVE_INFINITY)))))));

        String json = new String(codec.encode(a), UTF_8);

        assertThat(json).contains("[{\"float\":\"NaN\"},{\"float\":\"Infinity\"},[1.5,{\"float\":\"-Infinity\"}]]");
        Message back = decode(json);
        assertThat(back).isEqualTo(a); // Value.Real compares floats as Double.compare does: NaN equals NaN
        Value first = ((Value.Lst) ((Message.Answer) back).value().orElseThrow()).items().getFirst();
        assertThat(first).isInstanceOf(Value.Real.class);
        assertThat(((Value.Real) first).value()).isNaN();
        assertCode("{\"v\":1,\"type\":\"answer\",\"id\":\"q1\",\"value\":{\"float\":\"nan\"}}",
                ErrorCode.BAD_MESSAGE, "{\"float\": \"NaN\"} (or \"Infinity\", \"-Infinity\")");
    }

    /**
     * JSON has no NaN or Infinity: 1e400 would become a float Infinity in the knowledge base, and a robot's NaN or
     * Infinity reading (a range sensor with no return) would be written as the string "NaN", a TYPE_STR. A reading
     * in the tagged form of a float ({"float": "NaN"}) is refused as well: a sensor reports numbers.
     */
    @Test
    void sensor_valuesThatAreNotFiniteNumbers_areRefused() {
        String head = "{\"v\":1,\"type\":\"sensor\",\"source\":\"a\",\"sensor\":\"range\",\"values\":";
        assertCode(head + "[0.5,1e400]}", ErrorCode.BAD_MESSAGE, "Sensor 'range' value #2 is Infinity");
        assertCode(head + "[[1.0,-1e400]]}", ErrorCode.BAD_MESSAGE, "Sensor 'range' value #1 is -Infinity");
        assertCode(head + "[{\"float\":\"NaN\"}]}", ErrorCode.BAD_MESSAGE, "Sensor 'range' value #1 is NaN");
        assertThat(decode(head + "[\"NaN\",1e300]}")).isEqualTo(new Message.SensorSignal("a", "range",
                List.of(Value.of("NaN"), Value.of(1e300))));
        assertThatThrownBy(() -> new Message.SensorSignal("a", "range", List.of(Value.of(Double.NaN))))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("Sensor 'range' value #1 is NaN");
    }

    private Message decode(String json) {
        return codec.decode(json.getBytes(UTF_8));
    }

    private void assertCode(String json, ErrorCode code, String messagePart) {
        assertThatThrownBy(() -> decode(json))
                .isInstanceOfSatisfying(ProtocolException.class, e -> assertThat(e.code()).isEqualTo(code))
                .hasMessageContaining(messagePart);
    }
}

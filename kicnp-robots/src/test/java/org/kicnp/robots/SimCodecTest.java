package org.kicnp.robots;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;
import java.util.Optional;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

/** The JSON-lines mapping, line by line, with the examples of robots-sim/PROTOCOL.md. */
class SimCodecTest {
    private final SimCodec codec = new SimCodec();

    @Test
    void encode_aCommand_carriesIdTypeArgsAndOptionalMembers() {
        String line = codec.encode("c1", new SimRequest.Command("scout", "go_to", Map.of("x", 6.2), Optional.of(30.0),
                Optional.empty()));

        assertThat(line).isEqualTo("{\"id\":\"c1\",\"type\":\"command\",\"robot\":\"scout\",\"action\":\"go_to\","
                + "\"args\":{\"x\":6.2},\"timeout_s\":30.0}");
    }

    @Test
    void encode_aSpawnWithAFace_writesTheFaceAsANumberArray() {
        String line = codec.encode("u", new SimRequest.SpawnUser("bob", 4, 2, 90, Optional.of(List.of(1.0, 0.0))));

        assertThat(line).isEqualTo("{\"id\":\"u\",\"type\":\"spawn_user\",\"name\":\"bob\",\"x\":4.0,\"y\":2.0,"
                + "\"heading_deg\":90.0,\"face\":[1.0,0.0]}");
    }

    @Test
    void command_withAnArgumentThatIsNotJson_isRefusedNamingIt() {
        assertThatThrownBy(() -> SimRequest.Command.of("scout", "go_to", Map.of("x", new Object())))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("Argument 'x' of scout.go_to is a Object, not a string, number, boolean or list.");
    }

    @Test
    void decode_actionFailed_keepsTheReason() {
        SimEvent e = codec.decode("{\"type\":\"action_failed\",\"t\":3.2833,\"id\":\"c3\",\"robot\":\"scout\","
                + "\"action\":\"go_to\",\"reason\":\"blocked: bumper 0\"}");

        assertThat(e).isEqualTo(new SimEvent.ActionFailed(3.2833, "c3", "scout", "go_to", "blocked: bumper 0"));
    }

    @Test
    void decode_anErrorWithoutId_hasNeitherIdNorField() {
        SimEvent e = codec.decode("{\"type\":\"error\",\"t\":0.0,\"id\":null,\"field\":null,"
                + "\"message\":\"request: malformed JSON\"}");

        assertThat(e).isEqualTo(new SimEvent.Error(0.0, Optional.empty(), Optional.empty(), "request: malformed JSON"));
    }

    @Test
    void decode_sensors_becomeTheirRecords() {
        assertThat(codec.decode("{\"type\":\"sensor\",\"t\":3.2833,\"robot\":\"scout\",\"sensor\":\"bumper\",\"bumper\":0,"
                + "\"pressed\":true,\"contact\":\"box\"}"))
                .isEqualTo(new SimEvent.Bumper(3.2833, "scout", 0, true, Optional.of("box")));
        assertThat(codec.decode("{\"type\":\"sensor\",\"t\":3.88,\"robot\":\"scout\",\"sensor\":\"arrival\",\"x\":6.2,"
                + "\"y\":3.6,\"heading_deg\":90.0,\"user\":\"alice\",\"gap_m\":0.549}"))
                .isEqualTo(new SimEvent.Arrival(3.88, "scout", 6.2, 3.6, 90.0, Optional.of("alice")));
        assertThat(codec.decode("{\"type\":\"sensor\",\"t\":1.0,\"robot\":\"robovie\",\"sensor\":\"face_lost\","
                + "\"bearing_deg\":0.0,\"distance_m\":1.2,\"face\":[0.5,-0.5],\"track\":\"face-1\",\"truth_user\":\"alice\"}"))
                .isEqualTo(new SimEvent.Face(1.0, "robovie", false, "face-1", 0.0, 1.2, List.of(0.5, -0.5),
                        Optional.of("alice")));
    }

    @Test
    void decode_aLineThatIsNotJson_failsQuotingIt() {
        assertThatThrownBy(() -> codec.decode("Traceback (most recent call last):"))
                .isInstanceOf(SimProtocolException.class)
                .hasMessageStartingWith("Simulator line 'Traceback (most recent call last):' is not a valid event: "
                        + "it is not JSON");
    }

    @Test
    void decode_aMissingMember_failsNamingIt() {
        assertThatThrownBy(() -> codec.decode("{\"type\":\"action_ended\",\"t\":1.0,\"id\":\"c1\",\"robot\":\"aibo\"}"))
                .isInstanceOf(SimProtocolException.class)
                .hasMessageEndingWith("is not a valid event: member 'action' is missing.");
    }

    @Test
    void decode_anUnknownType_failsNamingIt() {
        assertThatThrownBy(() -> codec.decode("{\"type\":\"teleport\",\"t\":1.0}"))
                .isInstanceOf(SimProtocolException.class)
                .hasMessageEndingWith("is not a valid event: its type 'teleport' is unknown.");
    }

    @Test
    void encode_aRequestLongerThanTheProtocolsLineLimit_isRefusedNamingItsLengthAndTheLimit() {
        SimRequest.Command say = SimRequest.Command.of("robovie", "say", Map.of("text", "x".repeat(10_000_000)));

        assertThatThrownBy(() -> codec.encode("c9", say))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageMatching("The simulator request 'c9' \\(robovie\\.say\\) would be a line of 100000\\d\\d "
                        + "characters, longer than the protocol's limit of 10000000 characters; it was not sent\\.");
    }

    @Test
    void decode_aLineLongerThanTheProtocolsLimit_failsNamingItsLengthTheLimitAndWhatHappensNext() {
        String line = "{\"type\":\"utterance\",\"t\":1.0,\"robot\":\"robovie\",\"id\":\"c1\",\"text\":\""
                + "x".repeat(10_000_000) + "\",\"duration_s\":1.0}";

        assertThatThrownBy(() -> codec.decode(line))
                .isInstanceOf(SimProtocolException.class)
                .hasMessageStartingWith("Simulator line '{\"type\":\"utterance\",\"t\":1.0,")
                .hasMessageEndingWith("' is not a valid event: it is " + line.length() + " characters long, longer "
                        + "than the protocol's limit of 10000000 characters; it is skipped, and a request it answers "
                        + "fails when it times out.");
    }
}

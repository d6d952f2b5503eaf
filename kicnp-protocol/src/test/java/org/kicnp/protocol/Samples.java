package org.kicnp.protocol;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.kicnp.core.Value;

/** One message of every type, with optional members both present and absent, for round-trip tests. */
final class Samples {
    private Samples() {
    }

    static final String FRAME = "<FRAME><NAME>Fetch</NAME><ISA>Action</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>";

    static List<Message> all() {
        return List.of(
                new Message.Hello("1", "scout", AgentKind.ROBOT, "s3cret"),
                new Message.AuthResult("1", true, "kicnp", Optional.empty()),
                new Message.AuthResult("1", false, "kicnp", Optional.of("Wrong token for agent 'scout'.")),
                new Message.Register("2", List.of(FRAME)),
                new Message.Ack("2"),
                new Message.Heartbeat(1_700_000_000_000L),
                Message.Relay.toAgent("3", "alice", "scout", "say", "hello"),
                Message.Relay.toKind("4", "alice", AgentKind.ROBOT, "say", "hello all"),
                new Message.Command("c-9", "scout", "fetch", Map.of("item", "tea")),
                new Message.Feedback("c-9", "scout", FeedbackStage.PROGRESS, Optional.of(0.5), "halfway"),
                new Message.Feedback("c-9", "scout", FeedbackStage.ENDED, Optional.empty(), "cup delivered"),
                new Message.Cancel("c-10", "scout", "c-9", "the user changed her mind"),
                new Message.SensorSignal("scout", "sonar", List.of(Value.of(1.25), Value.of(3L), Value.of(true),
                        Value.of("near"), Value.ref("user1"), new Value.Lst(List.of(Value.of(1L))))),
                new Message.SensorSignal("robovie", "face_seen", List.of(Value.of("Ken")), Optional.of(1500L)),
                new Message.Query("5", "Robot"),
                new Message.Frames("5", List.of(FRAME), Optional.of(1_780_000_000_000L)),
                new Message.Ask("6", "scout", "speed"),
                new Message.Answer("6", Optional.of(Value.of(2L))),
                new Message.Answer("6", Optional.empty()),
                new Message.Assert("7", FRAME),
                new Message.Destroy("8", "cup1"),
                new Message.Subscribe("9", "SensorSignal"),
                new Message.Unsubscribe("10", "SensorSignal"),
                new Message.Changed("SensorSignal", ChangeKind.ADDED, "signal_scout_sonar", Optional.of(FRAME)),
                new Message.Changed("SensorSignal", ChangeKind.REPLACED, "signal_scout_sonar", Optional.of(FRAME),
                        Optional.of(List.of(Value.of(0.5), Value.of(2L), Value.of("2"), Value.of(false), Value.ref("ken"),
                                new Value.Lst(List.of(Value.of(1.0), Value.of("x")))))),
                new Message.Changed("SensorSignal", ChangeKind.REMOVED, "signal_scout_sonar", Optional.empty()),
                new Message.Push("11", List.of(FRAME)),
                new Message.Pull("12", Optional.of("Robot")),
                new Message.Pull("12", Optional.empty()),
                new Message.Prove("13", "AskUserName", Map.of("mUser", "userA")),
                new Message.Proofs("13", List.of(new Message.ProofNode("AskUserName", Optional.empty(), Map.of(
                        "mUser", new Message.ProofNode("NewUser", Optional.of("userA"), Map.of(), List.of()),
                        "mMouth", new Message.ProofNode("Mouth", Optional.of("mouth1"), Map.of(), List.of())),
                        List.of("mMouth: js: s.mMouth.open")))),
                new Message.Proofs("13", List.of()),
                new Message.Why("14", "AskUserName-1"),
                new Message.Explained("14", new Message.Reason("AskUserName-1", "AskUserName", true,
                        Map.of("mUser", "userA"), List.of("mUser: Any = userA"), List.of(new Message.Reason("userA",
                        "NewUser", false, Map.of(), List.of(), List.of())))),
                new Message.WhyNot("15", "Greeting", Map.of("mMouth", "mouth1")),
                new Message.WhyNot("16", "Greeting", Map.of()),
                new Message.NotFired("15", "Greeting", "'Greeting' has 1 binding: 1 blocked.", List.of(
                        new Message.SlotCandidates("mUser", "KnownUser", "COND_ANY", List.of("taro"), List.of(), 1, 0),
                        new Message.SlotCandidates("mMouth", "Mouth", "COND_ANY", List.of("mouth1"),
                                List.of("mouth2: .open == true is false ('mouth2'.open is false)"), 1, 1)),
                        List.of(new Message.BindingOutcome(Map.of("mUser", "taro"), "blocked",
                                "refraction: this binding has already fired")), false),
                Message.ErrorReply.to("3", ErrorCode.UNKNOWN_AGENT, "No agent 'pino' is connected."),
                Message.ErrorReply.of(ErrorCode.BAD_JSON, "The frame is not valid JSON."));
    }
}

package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.tuple;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.core.Relation;

class ActionCoordinationTest {

    /** Two behavior frames A and B on a Go stimulus; each commands its robot. */
    private static Fixture twoFrames(Relation relation) {
        Fixture f = new Fixture();
        f.cls("Go", null);
        f.kb.add(Frame.classFrame("A").priority(1).slot(Fixture.inst("mGo", "Go"))
                .slot(Fixture.str("onInstantiate", "cmd-a")).build());
        Frame.Builder b = Frame.classFrame("B").slot(Fixture.inst("mGo", "Go")).slot(Fixture.str("onInstantiate", "cmd-b"));
        if (relation != null) {
            b.linkFrom(relation, "A");
        }
        f.kb.add(b.build());
        f.scripts.define("cmd-a", g -> Fixture.call(g, "command", "PINO", "walk", "2m"));
        f.scripts.define("cmd-b", g -> Fixture.call(g, "command", "AIBO", "lie_down"));
        return f;
    }

    @Test
    void withoutRelation_bothActionsAreSentAtOnce() {
        Fixture f = twoFrames(null);
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        assertThat(f.sent).extracting(Action::robot).containsExactly("PINO", "AIBO");
    }

    @Test
    void succession_holdsTheFollowerUntilThePredecessorEnds() {
        Fixture f = twoFrames(Relation.Coordination.SUCCESSION);
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        assertThat(f.sent).extracting(Action::robot).containsExactly("PINO");
        String walk = f.sent.getFirst().id();
        e.actionStarted(walk);
        e.runToQuiescence();
        assertThat(f.sent).hasSize(1);
        e.actionEnded(walk, "arrived");
        e.runToQuiescence();
        assertThat(f.sent).extracting(Action::robot).containsExactly("PINO", "AIBO");
        assertThat(e.actionStatus(walk)).contains(Action.Status.ENDED);
    }

    @Test
    void succession_whenPredecessorFails_failsTheFollowerWithTheReason() {
        Fixture f = twoFrames(Relation.Coordination.SUCCESSION);
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        String walk = f.sent.getFirst().id();
        String follower = e.actions().get(1).id();
        e.actionFailed(walk, "fell over");
        e.runToQuiescence();
        assertThat(f.sent).hasSize(1);
        assertThat(e.actionStatus(follower)).contains(Action.Status.FAILED);
        assertThat(f.traced(TraceEvent.ActionChanged.class)).anySatisfy(c -> {
            assertThat(c.actionId()).isEqualTo(follower);
            assertThat(c.detail()).isEqualTo("predecessor action '" + walk + "' of frame 'A' failed: fell over");
        });
    }

    @Test
    void succession_whenFollowerIsRetractedWhileHeld_itsActionIsFailedNotSent() {
        Fixture f = twoFrames(Relation.Coordination.SUCCESSION);
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        String follower = e.actions().get(1).id();
        e.destroy(e.actions().get(1).instance());
        e.actionEnded(f.sent.getFirst().id(), "ok");
        e.runToQuiescence();
        assertThat(f.sent).hasSize(1);
        assertThat(e.actionStatus(follower)).contains(Action.Status.FAILED);
    }

    @Test
    void timeout_whenNoEndIsReported_timesOutAndFailsTheFollower() {
        Fixture f = twoFrames(Relation.Coordination.SUCCESSION);
        InferenceEngine e = f.engine(EngineOptions.defaults().withActionTimeout(Duration.ofSeconds(5)));
        f.assertFact("go", "Go");
        e.runToQuiescence();
        String walk = f.sent.getFirst().id();
        f.now += 4_000;
        e.runToQuiescence();
        assertThat(e.actionStatus(walk)).contains(Action.Status.SENT);
        f.now += 2_000;
        e.runToQuiescence();
        assertThat(e.actionStatus(walk)).contains(Action.Status.TIMED_OUT);
        assertThat(e.actionStatus(e.actions().get(1).id())).contains(Action.Status.FAILED);
    }

    @Test
    void timeout_asksTheRobotToStopWhatThePlatformGaveUpOn() {
        Fixture f = twoFrames(null);
        InferenceEngine e = f.engine(EngineOptions.defaults().withActionTimeout(Duration.ofSeconds(5)));
        f.assertFact("go", "Go");
        e.runToQuiescence();
        String walk = f.sent.getFirst().id();
        e.actionEnded(f.sent.get(1).id(), "lay down");
        f.now += 6_000;
        e.runToQuiescence();

        assertThat(e.actionStatus(walk)).contains(Action.Status.TIMED_OUT);
        assertThat(f.cancelled).containsExactly(walk + ": timed out: no end reported within 5000 ms");
    }

    @Test
    void cancelAction_failsItAndWhatWaitsOnIt_andAsksTheRobotToStop() {
        Fixture f = twoFrames(Relation.Coordination.SUCCESSION);
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        String walk = f.sent.getFirst().id();
        String follower = e.actions().get(1).id();

        assertThat(e.cancelAction(walk, "the user left")).isTrue();

        assertThat(e.actionStatus(walk)).contains(Action.Status.FAILED);
        assertThat(e.actionStatus(follower)).contains(Action.Status.FAILED);
        assertThat(f.sent).hasSize(1);
        assertThat(f.cancelled).containsExactly(walk + ": the user left");
        assertThat(f.traced(TraceEvent.ActionChanged.class)).anySatisfy(c -> {
            assertThat(c.actionId()).isEqualTo(walk);
            assertThat(c.detail()).isEqualTo("cancelled: the user left");
        });
        assertThat(e.cancelAction(walk, "again")).as("finished already").isFalse();
        // A late answer from the robot changes nothing.
        e.actionEnded(walk, "walked anyway");
        assertThat(e.actionStatus(walk)).contains(Action.Status.FAILED);
    }

    @Test
    void aScriptsCancel_ofARobot_cancelsItsUnfinishedActions() {
        Fixture f = twoFrames(null);
        f.cls("Stop", null);
        f.kb.add(Frame.classFrame("Halt").slot(Fixture.inst("mStop", "Stop"))
                .slot(Fixture.str("onInstantiate", "halt")).build());
        f.scripts.define("halt", g -> Fixture.call(g, "cancel", "PINO", "stop requested"));
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        String walk = f.sent.getFirst().id();
        String lie = f.sent.get(1).id();

        f.assertFact("stop", "Stop");
        e.runToQuiescence();

        assertThat(e.actionStatus(walk)).contains(Action.Status.FAILED);
        assertThat(e.actionStatus(lie)).as("AIBO's action is not PINO's").contains(Action.Status.SENT);
        assertThat(f.cancelled).containsExactly(walk + ": stop requested");
    }

    @Test
    @SuppressWarnings("unchecked")
    void aScriptsActions_listTheUnfinishedActions_soItCanCancelOneKind() {
        Fixture f = twoFrames(Relation.Coordination.SUCCESSION);
        f.cls("Stop", null);
        f.kb.add(Frame.classFrame("Halt").slot(Fixture.inst("mStop", "Stop"))
                .slot(Fixture.str("onInstantiate", "halt-walks")).build());
        List<List<Map<String, Object>>> seen = new ArrayList<>();
        f.scripts.define("halt-walks", g -> {
            seen.add((List<Map<String, Object>>) Fixture.call(g, "actions"));
            List<Map<String, Object>> pino = (List<Map<String, Object>>) Fixture.call(g, "actions", "PINO");
            seen.add(pino);
            pino.stream().filter(a -> a.get("name").equals("walk"))
                    .forEach(a -> Fixture.call(g, "cancel", a.get("id"), "walk no more"));
            return null;
        });
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        String walk = f.sent.getFirst().id();

        f.assertFact("stop", "Stop");
        e.runToQuiescence();

        assertThat(seen.getFirst()).extracting(a -> a.get("robot"), a -> a.get("name"), a -> a.get("status"),
                a -> a.get("frame")).containsExactly(tuple("PINO", "walk", "sent", "A"),
                tuple("AIBO", "lie_down", "held", "B"));
        assertThat(seen.get(1)).singleElement().satisfies(a -> {
            assertThat(a).containsEntry("id", walk).containsEntry("args", List.of("2m"))
                    .containsEntry("target", "PINO");
            assertThat((String) a.get("instance")).startsWith("A-");
        });
        assertThat(e.actionStatus(walk)).contains(Action.Status.FAILED);
        assertThat(f.cancelled).containsExactly(walk + ": walk no more");
        assertThat(e.actions()).filteredOn(a -> a.name().equals("lie_down")).singleElement()
                .satisfies(a -> assertThat(e.actionStatus(a.id())).as("it waited on the walk by succession")
                        .contains(Action.Status.FAILED));
    }

    @Test
    void timeoutSlot_onBehaviorFrame_overridesTheDefaultTimeout() {
        Fixture f = twoFrames(null);
        f.kb.replace(f.kb.require("A").withSlot(Fixture.num("timeout", 1_000)));
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        f.now += 1_500;
        e.runToQuiescence();
        assertThat(e.actionStatus(f.sent.get(0).id())).contains(Action.Status.TIMED_OUT);
        assertThat(e.actionStatus(f.sent.get(1).id())).contains(Action.Status.SENT);
        assertThat(f.traced(TraceEvent.ActionChanged.class)).anySatisfy(c ->
                assertThat(c.detail()).isEqualTo("no end reported within 1000 ms"));
    }

    @Test
    void sendmsgToAPart_isPerformedByTheRobotItsRobotSlotNames() {
        Fixture f = twoFrames(null);
        f.cls("Mouth", null);
        f.assertFact("robovie", "Go");
        f.assertFact("mouth1", "Mouth", "robot", "Robovie");
        f.scripts.define("cmd-a", g -> Fixture.call(g, "sendmsg", "mouth1", "hello"));
        InferenceEngine e = f.engine();
        e.runToQuiescence();
        assertThat(f.sent).filteredOn(a -> a.name().equals("say")).isNotEmpty().allSatisfy(a -> {
            assertThat(a.robot()).isEqualTo("Robovie");
            assertThat(a.target()).isEqualTo("mouth1");
        });
    }

    @Test
    void synchronization_releasesLinkedActionsTogetherWithOneStartTime() {
        Fixture f = twoFrames(Relation.Coordination.SYNCHRONIZATION);
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        assertThat(f.sent).hasSize(2);
        assertThat(f.sent).extracting(Action::startAt).containsOnly(f.now);
        assertThat(f.traced(TraceEvent.ActionChanged.class)).extracting(TraceEvent.ActionChanged::status)
                .containsSubsequence(Action.Status.HELD, Action.Status.HELD, Action.Status.SENT, Action.Status.SENT);
    }

    @Test
    void synchronization_whenAScriptCancelsAHeldActionBeforeQuiescence_itIsNeverSent() {
        Fixture f = twoFrames(Relation.Coordination.SYNCHRONIZATION);
        f.cls("Stop", null);
        f.kb.add(Frame.classFrame("Halt").slot(Fixture.inst("mStop", "Stop"))
                .slot(Fixture.str("onInstantiate", "halt")).build());
        f.scripts.define("halt", g -> Fixture.call(g, "cancel", "PINO", "stop requested"));
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        f.assertFact("stop", "Stop");

        e.runToQuiescence(); // A (priority 1) issues the walk, held for its group; Halt (newer fact) cancels it; B last

        String walk = e.actions().stream().filter(a -> a.robot().equals("PINO")).findFirst().orElseThrow().id();
        assertThat(e.actionStatus(walk)).contains(Action.Status.FAILED);
        assertThat(f.sent).as("a cancelled held action is never sent").extracting(Action::robot).containsExactly("AIBO");
        assertThat(f.cancelled).as("the robot never had it").isEmpty();
    }

    @Test
    void restriction_whileRestrictedActionRuns_otherRobotsWaitInOrder() {
        Fixture f = twoFrames(null);
        f.kb.replace(f.kb.require("A").toBuilder().linkTo(Relation.Coordination.RESTRICTION, "B").build());
        f.kb.add(Frame.classFrame("C").slot(Fixture.inst("mGo", "Go")).slot(Fixture.str("onInstantiate", "cmd-c"))
                .build());
        f.scripts.define("cmd-c", g -> Fixture.call(g, "command", "Scout", "bring", "tea"));
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        assertThat(f.sent).extracting(Action::robot).containsExactly("PINO");
        e.actionEnded(f.sent.getFirst().id(), "ok");
        e.runToQuiescence();
        assertThat(f.sent).extracting(Action::robot).containsExactlyInAnyOrder("PINO", "AIBO", "Scout");
    }

    @Test
    void feedback_whenActionEnds_isAnInstanceThatSlotConditionsCanMatch() {
        Fixture f = twoFrames(null);
        f.kb.add(InferenceEngine.feedbackClass());
        f.kb.add(Frame.classFrame("AfterWalk").slot(Fixture.inst("mFb", InferenceEngine.FEEDBACK_CLASS,
                ".status == \"ended\"")).slot(Fixture.str("onInstantiate", "cmd-b")).build());
        InferenceEngine e = f.engine();
        f.assertFact("go", "Go");
        e.runToQuiescence();
        e.actionFailed(f.sent.get(1).id(), "battery");
        e.runToQuiescence();
        assertThat(f.instancesOf("AfterWalk")).isEmpty();
        e.actionEnded(f.sent.getFirst().id(), "arrived");
        e.runToQuiescence();
        assertThat(f.instancesOf("AfterWalk")).hasSize(1);
        assertThat(f.kb.value(InferenceEngine.FEEDBACK_CLASS + "-" + f.sent.getFirst().id(), "result"))
                .map(v -> v.text()).contains("arrived");
    }

    /** An engine over the fixture whose action sink throws for robot PINO and records the other robots' actions. */
    private static InferenceEngine withSinkFailingFor(Fixture f, String robot) {
        InferenceEngine e = InferenceEngine.builder(f.kb).scripts(f.scripts).clock(() -> f.now).actionSink(new ActionSink() {
            @Override public void send(Action action) {
                if (action.robot().equals(robot)) {
                    throw new IllegalStateException(robot + " is not connected");
                }
                f.sent.add(action);
            }

            @Override public void cancel(Action action, String reason) {
                throw new IllegalStateException("cannot reach " + action.robot());
            }
        }).build();
        e.addTraceListener(f.trace::add);
        return e;
    }

    @Test
    void sinkThatThrows_failsOnlyThatAction_andTheFiringIsAppliedWhole_andTheEngineGoesOn() {
        Fixture f = twoFrames(Relation.Coordination.SUCCESSION);
        f.cls("Note", null);
        f.scripts.define("cmd-a", g -> {
            Fixture.call(g, "command", "PINO", "walk", "2m");
            Fixture.call(g, "command", "Scout", "wave");
            return Fixture.call(g, "create", "Note", Map.of());
        });
        InferenceEngine e = withSinkFailingFor(f, "PINO");
        f.assertFact("go", "Go");

        assertThat(e.runToQuiescence()).as("A and B fire; nothing escapes the run").isEqualTo(2);

        String a = f.instancesOf("A").getFirst();
        assertThat(e.why(a)).isInstanceOf(Explanation.Derived.class);
        assertThat(f.instancesOf("Note")).as("the effect after the failed send is applied").hasSize(1);
        Action walk = e.actions().getFirst();
        String why = "the action sink failed to send it: PINO is not connected";
        assertThat(e.actionStatus(walk.id())).contains(Action.Status.FAILED);
        assertThat(f.traced(TraceEvent.ActionChanged.class)).filteredOn(c -> c.actionId().equals(walk.id()))
                .extracting(TraceEvent.ActionChanged::status, TraceEvent.ActionChanged::detail)
                .containsExactly(tuple(Action.Status.SENT, ""), tuple(Action.Status.FAILED, why));
        assertThat(f.kb.value(InferenceEngine.FEEDBACK_CLASS + "-" + walk.id(), "status")).map(v -> v.text())
                .contains("failed");
        assertThat(f.sent).extracting(Action::robot).as("Scout's wave is sent, B's lie_down waits on it")
                .containsExactly("Scout");

        e.actionEnded(f.sent.getFirst().id(), "waved"); // coordination goes on: B's action follows the wave
        e.actionEnded(walk.id(), "walked anyway"); // a late report changes nothing
        e.runToQuiescence();
        assertThat(f.sent).extracting(Action::robot).containsExactly("Scout", "AIBO");
        f.assertFact("go2", "Go");
        assertThat(e.runToQuiescence()).isEqualTo(2);
        assertThat(e.actionStatus(walk.id())).contains(Action.Status.FAILED);
        assertThat(f.instancesOf("A")).hasSize(2);
        assertThat(f.instancesOf("Note")).hasSize(2);
    }

    @Test
    void sinkThatThrowsOnCancel_stillFailsTheAction_andTheEngineGoesOn() {
        Fixture f = twoFrames(null);
        InferenceEngine e = withSinkFailingFor(f, "nobody");
        f.assertFact("go", "Go");
        e.runToQuiescence();
        String walk = f.sent.getFirst().id();

        assertThat(e.cancelAction(walk, "the user left")).isTrue();

        assertThat(e.actionStatus(walk)).contains(Action.Status.FAILED);
        f.assertFact("go2", "Go");
        assertThat(e.runToQuiescence()).isEqualTo(2);
    }

    @Test
    void feedback_forUnknownAction_isRefusedWithItsId() {
        Fixture f = twoFrames(null);
        InferenceEngine e = f.engine();
        e.actionEnded("a99", "ok");
        assertThatThrownBy(e::runToQuiescence).isInstanceOf(InferenceException.class)
                .hasMessage("Action 'a99' is not known to this engine.");
    }
}

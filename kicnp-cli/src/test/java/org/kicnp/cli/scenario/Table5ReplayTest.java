package org.kicnp.cli.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.cli.platform.PlatformEvent;
import org.kicnp.cli.scenario.RunRecord.Step;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.robots.SimRequest;

/**
 * The headless replay of Table 5 with real processes on loopback: the platform in-process, the simulator
 * subprocess at accelerated time, the four robot agents and a scripted User A.
 */
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class Table5ReplayTest {
    static final double TIME_SCALE = 8;
    static final long SKEW_MS = 250;

    @TempDir
    Path tmp;

    private Table5Run start(Path kb, String name) {
        return Table5Run.headless(kb, Optional.of(Path.of("target/replay-events/" + name + ".jsonl")), 2004, TIME_SCALE,
                Optional.of(new PrintStream(System.out, true)));
    }

    private static String holding(Table5Run run) {
        return run.world().sim().query().at("/users/userA/holding/0").asText();
    }

    private Path kb() throws Exception {
        return ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
    }

    @Test
    void table5_rowsHappenInOrder_withFeedback_succession_synchronization_andRestriction() throws Exception {
        try (Table5Run run = Table5Run.headless(kb(), Optional.of(Path.of("target/replay-events/first-visit.jsonl")), 2004, TIME_SCALE, Optional.of(new PrintStream(System.out, true)))) {
            run.playFirstVisit("Taro", "Tea, please.");
            run.awaitEnd();
            RunRecord r = run.record();
            System.out.println(r.latencySummary());
            assertThat(Table5Checks.problems(r, "Taro")).isEmpty();

            assertThat(r.lines()).containsSubsequence(
                    "How are you! I have never seen you before. What is your name?",
                    "Hi, Taro. Nice to meet you. Welcome you to visit my room.",
                    "This is my friend, PINO.",
                    "What do you want to drink?",
                    "This is a robot dog AIBO. Please enjoy yourself with it.");
            List<String> frames = r.steps().stream().map(Step::frame).toList();
            assertThat(frames).containsSubsequence("FirstMeet", "AskUserName", "Welcome", "ShakeBothHands",
                    "PinoGreetsUser", "AskDrink", "ScoutToKitchen", "ScoutToCup", "ScoutTakesCup", "ScoutBring",
                    "ScoutServesCup", "IntroduceAibo", "AIBOAction1", "AIBOAction2");
            assertThat(r.steps()).allSatisfy(s -> assertThat(s.outcome()).as(s.frame() + " " + s.detail()).isEqualTo("ended"));
            // succession: each starts after the one before has ended
            String[] chain = {"Welcome", "ShakeBothHands", "ScoutToKitchen", "ScoutToCup", "ScoutTakesCup", "ScoutBring",
                    "ScoutServesCup", "IntroduceAibo", "AIBOAction1", "AIBOAction2"};
            for (int i = 1; i < chain.length; i++) {
                Step before = r.stepsOf(chain[i - 1]).getFirst();
                Step after = r.stepsOf(chain[i]).getFirst();
                assertThat(after.sent()).as(chain[i] + " after " + chain[i - 1]).isGreaterThanOrEqualTo(before.finished());
            }
            // synchronization: Robovie's "This is my friend, PINO." and PINO's walk start together
            Step intro = r.stepsOf("IntroducePino").getFirst();
            Step walk = r.stepsOf("PinoWalk").getFirst();
            assertThat(Math.abs(intro.sent() - walk.sent()) / 1_000_000).isLessThanOrEqualTo(SKEW_MS);
            // restriction: nothing else is sent while Scout hands over the cup
            Step hand = r.stepsOf("ScoutServesCup").getFirst();
            assertThat(r.steps()).filteredOn(s -> s != hand && s.sent() > hand.sent() && s.sent() < hand.finished())
                    .isEmpty();
            assertThat(run.world().sim().query().at("/users/userA/holding/0").asText()).startsWith("tea");
            assertThat(run.platform().kb().contains("Taro")).isTrue();
        }
    }

    @Test
    void secondVisit_isGreetedByName_withoutBeingAsked_alsoAfterARestart() throws Exception {
        Path kb = kb();
        try (Table5Run run = start(kb, "second-visit")) {
            run.playFirstVisit("Taro", "Tea, please.");
            run.awaitEnd();
            int before = run.record().lines().size();
            run.playSecondVisit("Taro");
            List<String> second = run.record().lines().subList(before, run.record().lines().size());
            assertThat(second).contains("Hi! Nice to meet you. Welcome to visit my room!")
                    .noneMatch(l -> l.contains("What is your name?"));
            assertThat(run.record().stepsOf("WelcomeBack")).as("the greeting by name is said to its end")
                    .singleElement().satisfies(s -> assertThat(s.outcome()).isEqualTo("ended"));
        }
        assertThat(Files.readString(kb.resolve("learned.xml"))).contains("<NAME>Taro</NAME>");
        try (Table5Run again = start(kb, "after-restart")) {
            again.playReturn("Taro");
            assertThat(again.record().lines()).noneMatch(l -> l.contains("What is your name?"));
        }
    }

    @Test
    void aNameWithAnAccentAnApostropheAndTwoWords_isSaidAsGiven_andRemembered_alsoAfterARestart() throws Exception {
        String name = "José O'Brien";
        Path kb = kb();
        try (Table5Run run = start(kb, "name-as-said")) {
            run.playFirstVisit(name, "Tea, please.");
            run.awaitEnd();
            assertThat(Table5Checks.problems(run.record(), name)).isEmpty();
            run.playSecondVisit(name);
        }
        try (Table5Run again = start(kb, "name-as-said-after-restart")) {
            again.playReturn(name);
        }
    }

    @Test
    void aNameInJapanese_evenWithALetterBeyondU_FFFF_isLearned_andTheVisitGoesOn() throws Exception {
        String name = "\uD842\uDFB7野太郎"; // 𠮷 (U+20BB7), which a frame name cannot hold
        try (Table5Run run = start(kb(), "name-japanese")) {
            run.playUntilAskedForADrink(name);
            assertThat(run.record().lines()).contains("Hi, " + name + ". Nice to meet you. Welcome you to visit my room.");
        }
    }

    @Test
    void aNameThatIsTheNameOfAFrame_isLearnedAndRemembered_andTheFrameIsNotReplaced() throws Exception {
        Path kb = kb();
        try (Table5Run run = start(kb, "name-of-a-frame")) {
            run.playFirstVisit("Welcome", "Tea, please.");
            run.awaitEnd();
            assertThat(Table5Checks.problems(run.record(), "Welcome")).isEmpty();
            run.playSecondVisit("Welcome");
            KnowledgeBase k = run.platform().kb();
            assertThat(k.frame("Welcome").orElseThrow().learned()).as("the declared row is still the declared one").isFalse();
            assertThat(k.isA("Welcome", "Speech")).isTrue();
            assertThat(learnedUsersNamed(k, "Welcome")).hasSize(1);
        }
        try (Table5Run again = start(kb, "name-of-a-frame-after-restart")) {
            again.playReturn("Welcome");
            assertThat(again.record().lines()).noneMatch(l -> l.contains("What is your name?"));
        }
    }

    @Test
    void twoPeopleWithOneName_areBothRemembered_eachWithTheirOwnFace_alsoAfterARestart() throws Exception {
        Path kb = kb();
        try (Table5Run run = start(kb, "two-kens")) {
            run.playFirstVisit("Ken", "Tea, please.");
            run.awaitEnd();
            leave(run, run.user());
            try (UserA other = UserA.connect(run.platform(), run.world().sim(), "user")) {
                long mark = System.nanoTime();
                other.appear();
                awaitLineAfter(run, mark, "What is your name?");
                awaitAfter(run, mark, e -> e.kind().equals("feedback") && !e.text("stage").equals("started")
                        && run.record().step(e.text("id")).map(s -> s.frame().equals("AskUserName")).orElse(false),
                        "the end of AskUserName");
                other.say("My name is Ken.");
                awaitLineAfter(run, mark, "Hi, Ken. Nice to meet you. Welcome you to visit my room.");
                awaitLineAfter(run, mark, "What do you want to drink?");
            }
            assertThat(learnedUsersNamed(run.platform().kb(), "Ken")).as("one learned class for each Ken").hasSize(2)
                    .extracting(f -> f.ownSlot("faceText").flatMap(Slot::value).orElseThrow()).doesNotHaveDuplicates();
        }
        try (Table5Run again = start(kb, "two-kens-after-restart")) {
            again.playReturn("Ken");
            leave(again, again.user());
            try (UserA other = UserA.connect(again.platform(), again.world().sim(), "user")) {
                long mark = System.nanoTime();
                other.appear();
                awaitLineAfter(again, mark, "Hi, Ken. Good to see you again.");
            }
            assertThat(again.record().lines()).noneMatch(l -> l.contains("What is your name?"));
        }
    }

    /** The LEARNED sub-frames of KnownUser whose {@code name} slot is {@code name}. */
    private static List<Frame> learnedUsersNamed(KnowledgeBase kb, String name) {
        return kb.frames().stream().filter(f -> f.learned() && kb.isA(f.name(), "KnownUser"))
                .filter(f -> f.ownSlot("name").flatMap(Slot::value).map(Value::text).equals(Optional.of(name))).toList();
    }

    /** Waits for a line Robovie begins to say after {@code mark} ({@link System#nanoTime()}). */
    private static void awaitLineAfter(Table5Run run, long mark, String text) throws Exception {
        awaitAfter(run, mark, e -> e.kind().equals("utterance") && RunRecord.firstValue(e).contains(text),
                "the line '" + text + "'");
    }

    private static void awaitAfter(Table5Run run, long mark, Predicate<PlatformEvent> match, String what) throws Exception {
        run.record().await(e -> e.nanos() > mark && match.test(e), Table5Run.STEP.multipliedBy(2), what);
    }

    /** The person leaves, and FaceLost ends the visit (the face signal is retracted). */
    private static void leave(Table5Run run, UserA person) throws Exception {
        long mark = System.nanoTime();
        person.leave();
        awaitAfter(run, mark, e -> e.kind().equals("retracted") && e.text("instance").equals("signal_robovie_face_seen"),
                "the end of the visit (FaceLost)");
    }

    @Test
    void bareAnswers_aNameAlone_andADrinkAlone_answerRoboviesQuestions() throws Exception {
        try (Table5Run run = start(kb(), "bare-answers")) {
            run.user().appear();
            run.record().awaitLine("What is your name?", Table5Run.STEP);
            run.record().awaitFinished("AskUserName", Table5Run.STEP);
            run.user().say("Ken.");
            run.record().awaitLine("Hi, Ken. Nice to meet you. Welcome you to visit my room.", Table5Run.STEP);
            run.record().awaitLine("What do you want to drink?", Table5Run.STEP.multipliedBy(2));
            run.record().awaitFinished("AskDrink", Table5Run.STEP);
            run.user().say("Lemonade.");
            run.record().awaitLine("I am sorry, we have no lemonade. We have tea and coffee.", Table5Run.STEP);
            assertThat(run.user().sayAgainReplies()).isEmpty();
        }
    }

    @Test
    void coffee_scoutBringsCoffee() throws Exception {
        try (Table5Run run = start(kb(), "coffee")) {
            run.playFirstVisit("Hanako", "I'd like a coffee.");
            run.awaitEnd();
            assertThat(holding(run)).startsWith("coffee");
            assertThat(run.record().stepsOf("ScoutTakesCup").getFirst().args()).contains("cup=coffee");
        }
    }

    @Test
    void unknownDrink_robovieSaysItHasNone_andScoutStays() throws Exception {
        try (Table5Run run = start(kb(), "unknown-drink")) {
            run.playFirstVisit("Jiro", "I'd like a beer, please.");
            run.awaitEnd();
            assertThat(run.record().lines()).contains("I am sorry, we have no beer. We have tea and coffee.",
                    "This is a robot dog AIBO. Please enjoy yourself with it.");
            assertThat(run.record().steps()).noneMatch(s -> s.robot().equals("scout"));
        }
    }

    @Test
    void changeOfMind_whileScoutIsOnItsWay_scoutHalts_andTheTaskChangesToCoffee() throws Exception {
        try (Table5Run run = start(kb(), "change-of-mind")) {
            run.playFirstVisit("Saburo", "Tea, please.");
            run.record().await(e -> e.kind().equals("feedback") && e.text("stage").equals("started")
                    && e.text("robot").equals("scout"), Table5Run.STEP, "Scout setting off");
            run.user().say("No, coffee please.");
            run.awaitEnd();
            Step trip = run.record().stepsOf("ScoutToKitchen").getFirst();
            assertThat(trip.outcome()).as("the move under way is cancelled").isEqualTo("failed");
            assertThat(trip.detail()).contains("cancelled: the order changed");
            // The platform sends the cancel and then the new move at once (the engine fails the cancelled action
            // itself); the robot starts the new move only once the old one has halted and been reported.
            assertThat(run.record().stepsOf("ScoutBackToKitchen").getFirst().started())
                    .as("back to the kitchen once the move was stopped").isGreaterThanOrEqualTo(trip.finished());
            assertThat(holding(run)).startsWith("coffee");
            assertThat(run.record().steps()).filteredOn(s -> s.frame().equals("ScoutTakesCup") && s.ended())
                    .extracting(Step::args).containsExactly("{cup=coffee}");
            assertThat(run.record().lines()).noneMatch(l -> l.contains("Scout could not"));
        }
    }

    @Test
    void changeOfMind_whileScoutBringsTheTea_scoutTurnsBack_putsItDownAndBringsCoffee() throws Exception {
        try (Table5Run run = start(kb(), "late-change-of-mind")) {
            run.playFirstVisit("Shiro", "Tea, please.");
            run.record().await(e -> e.kind().equals("feedback") && e.text("stage").equals("started")
                    && e.text("robot").equals("scout") && e.text("action").equals("approach_user"),
                    Table5Run.STEP, "Scout bringing the tea back");
            assertThat(run.world().sim().query().at("/robots/scout/carrying").asText()).startsWith("tea");
            run.user().say("No, coffee please.");
            run.awaitEnd();
            RunRecord r = run.record();

            assertThat(r.lines()).contains("All right, Scout will bring you coffee instead.")
                    .noneMatch(l -> l.contains("Scout could not"));
            Step oldBring = r.stepsOf("ScoutBring").getFirst();
            assertThat(oldBring.args()).contains("user=userA");
            assertThat(oldBring.outcome()).as("the approach under way is cancelled").isEqualTo("failed");
            assertThat(oldBring.detail()).contains("cancelled: the order changed");
            Step back = r.stepsOf("ScoutBackToKitchen").getFirst();
            // As above: the new move may be sent before the robot reports the old one stopped, not started.
            assertThat(back.started()).as("back to the kitchen once the approach was stopped")
                    .isGreaterThanOrEqualTo(oldBring.finished());
            Step putDown = r.stepsOf("ScoutPutsCupDown").getFirst();
            assertThat(putDown.outcome()).isEqualTo("ended");
            assertThat(putDown.detail()).contains("\"kind\":\"tea\"");
            assertThat(r.steps()).filteredOn(st -> st.frame().equals("ScoutTakesCup") && st.ended())
                    .extracting(Step::args).containsExactly("{cup=tea}", "{cup=coffee}");
            assertThat(r.stepsOf("ScoutServesCup")).filteredOn(Step::ended).singleElement()
                    .satisfies(st -> assertThat(st.sent()).isGreaterThan(putDown.finished()));
            assertThat(run.world().sim().query().at("/users/userA/holding")).singleElement()
                    .satisfies(cup -> assertThat(cup.asText()).startsWith("coffee"));
            assertThat(run.world().sim().query().at("/robots/scout/carrying").isNull()).isTrue();
        }
    }

    @Test
    void aiboDisconnected_theFailureIsReported_andTheOthersCarryOn() throws Exception {
        try (Table5Run run = start(kb(), "aibo-disconnected")) {
            run.playUntilAskedForADrink("Shiro");
            run.world().agent("aibo").orElseThrow().close();
            run.user().say("Tea, please.");
            run.awaitEnd();
            assertThat(holding(run)).startsWith("tea");
            assertThat(run.record().stepsOf("AIBOAction1").getFirst().outcome()).isEqualTo("failed");
            assertThat(run.record().lines()).contains("I am sorry, AIBO cannot come to you now.");
        }
    }

    @Test
    void scoutBlocked_reportsFailure_andRobovieApologises() throws Exception {
        try (Table5Run run = start(kb(), "scout-blocked")) {
            run.world().sim().call(new SimRequest.AddObstacle("box", 6.3, 3.0, 1.0, 0.2));
            run.playFirstVisit("Goro", "Tea, please.");
            run.awaitEnd();
            Step trip = run.record().stepsOf("ScoutToKitchen").getFirst();
            assertThat(trip.outcome()).isEqualTo("failed");
            assertThat(trip.detail()).contains("blocked");
            assertThat(run.record().lines()).containsSubsequence("I am sorry, Scout could not bring your drink.",
                    "This is a robot dog AIBO. Please enjoy yourself with it.");
        }
    }
}

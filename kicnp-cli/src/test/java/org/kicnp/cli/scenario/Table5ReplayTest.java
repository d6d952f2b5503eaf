package org.kicnp.cli.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.cli.scenario.RunRecord.Step;

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
}

package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

class ForwardChainingTest {

    @Test
    void askUserName_whenNewUserAndMouthAreSetUp_createsInstanceAndRunsOnInstantiateOnce() {
        Fixture f = Fixture.paper();
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        assertThat(e.runToQuiescence()).isZero();
        f.assertFact("userA", "NewUser");
        assertThat(e.runToQuiescence()).isEqualTo(1);
        assertThat(e.runToQuiescence()).isZero();

        assertThat(f.instancesOf("AskUserName")).hasSize(1);
        Frame made = f.kb.require(f.instancesOf("AskUserName").getFirst());
        assertThat(made.provenance()).isEqualTo(Provenance.RUNTIME);
        assertThat(f.kb.value(made.name(), "mUser")).contains(Value.ref("userA"));
        assertThat(f.kb.value(made.name(), "mMouth")).contains(Value.ref("mouth1"));
        assertThat(f.scripts.calls("ask-name")).isEqualTo(1);
        assertThat(f.sent).singleElement().satisfies(a -> {
            assertThat(a.robot()).isEqualTo("mouth1");
            assertThat(a.args()).containsExactly("What is your name?");
            assertThat(a.frame()).isEqualTo("AskUserName");
            assertThat(a.instance()).isEqualTo(made.name());
        });
    }

    @Test
    void greeting_whenUserIsInstanceOfLearnedSubclassOfKnownUser_greetsAndDoesNotAskName() {
        Fixture f = Fixture.paper();
        f.kb.add(Frame.classFrame("Taro").parent("KnownUser").provenance(Provenance.LEARNED).build());
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("face7", "Taro");
        e.runToQuiescence();
        assertThat(f.instancesOf("Greeting")).hasSize(1);
        assertThat(f.instancesOf("AskUserName")).isEmpty();
        assertThat(f.sent).extracting(a -> a.args().getFirst())
                .containsExactly("Hi! Nice to meet you. Welcome to visit my room!");
    }

    @Test
    void chaining_whenDerivedInstancesFeedFurtherFrames_goesThreeDeep() {
        Fixture f = chain3();
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        assertThat(e.runToQuiescence()).isEqualTo(3);
        assertThat(f.instancesOf("Step1")).hasSize(1);
        assertThat(f.instancesOf("Step2")).hasSize(1);
        assertThat(f.instancesOf("Step3")).hasSize(1);
    }

    static Fixture chain3() {
        Fixture f = new Fixture();
        f.cls("Stimulus", null);
        f.kb.add(Frame.classFrame("Step1").slot(Fixture.inst("mIn", "Stimulus")).build());
        f.kb.add(Frame.classFrame("Step2").slot(Fixture.inst("mIn", "Step1")).build());
        f.kb.add(Frame.classFrame("Step3").slot(Fixture.inst("mIn", "Step2")).build());
        return f;
    }

    @Test
    void sharedSlot_whenOneMouthServesTwoUsers_firesForEach_butUnsharedSlotConsumesIt() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Cup", null);
        f.kb.add(Frame.classFrame("Chat").slot(Fixture.inst("mUser", "User")).slot(Fixture.inst("mCup", "Cup")).build());
        f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mCup", DataType.INSTANCE).argument("Cup").required(true).shared(false).build())
                .build());
        InferenceEngine e = f.engine();
        f.assertFact("cup", "Cup");
        f.assertFact("u1", "User");
        f.assertFact("u2", "User");
        e.runToQuiescence();
        assertThat(f.instancesOf("Chat")).hasSize(2);
        assertThat(f.instancesOf("Serve")).hasSize(1);
        assertThat(f.traced(TraceEvent.Blocked.class)).anySatisfy(b ->
                assertThat(b.reason()).contains("unshared slot 'mCup' already holds 'cup'"));
    }

    @Test
    void unsharedSlot_whenConsumerIsDestroyed_isFreedForTheWaitingBinding() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Cup", null);
        f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mCup", DataType.INSTANCE).argument("Cup").required(true).shared(false).build())
                .build());
        InferenceEngine e = f.engine();
        f.assertFact("cup", "Cup");
        f.assertFact("u1", "User");
        f.assertFact("u2", "User");
        e.runToQuiescence();
        String first = f.instancesOf("Serve").getFirst();
        e.destroy(first);
        assertThat(f.instancesOf("Serve")).hasSize(1).doesNotContain(first);
    }

    @Test
    void uniqueSlots_formOneKey_whileNonUniqueSlotMayRepeat() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Mouth", null);
        f.kb.add(Frame.classFrame("Both").slot(Fixture.inst("mUser", "User")).slot(Fixture.inst("mMouth", "Mouth"))
                .build());
        f.kb.add(Frame.classFrame("OncePerUser").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mMouth", DataType.INSTANCE).argument("Mouth").required(true).build()).build());
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        f.assertFact("m1", "Mouth");
        f.assertFact("m2", "Mouth");
        e.runToQuiescence();
        assertThat(f.instancesOf("Both")).hasSize(2);
        assertThat(f.instancesOf("OncePerUser")).hasSize(1);
        assertThat(f.traced(TraceEvent.Blocked.class)).anySatisfy(b ->
                assertThat(b.reason()).contains("unique slots [mUser]"));
    }

    @Test
    void optionalSlot_isBoundWhenSomethingFits_andLeftEmptyOtherwise() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Camera", null);
        f.kb.add(Frame.classFrame("Watch").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mCam", DataType.INSTANCE).argument("Camera").build()).build());
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        e.runToQuiescence();
        f.assertFact("cam", "Camera");
        f.assertFact("u2", "User");
        e.runToQuiescence();
        var made = f.instancesOf("Watch");
        assertThat(made).hasSize(2);
        assertThat(f.kb.value(made.get(0), "mCam")).isEmpty();
        assertThat(f.kb.value(made.get(1), "mCam")).contains(Value.ref("cam"));
    }

    @Test
    void optionalUniqueSlot_neverHoldsTheSameInstanceInTwoInstances_andIsFreedByRetraction() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Camera", null);
        f.kb.add(Frame.classFrame("Watch").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mCam", DataType.INSTANCE).argument("Camera").unique(true).build()).build());
        InferenceEngine e = f.engine();
        f.assertFact("cam", "Camera");
        f.assertFact("u1", "User");
        f.assertFact("u2", "User");
        e.runToQuiescence();
        var made = f.instancesOf("Watch");
        assertThat(made).hasSize(2);
        assertThat(made.stream().filter(w -> f.kb.value(w, "mCam").isPresent()).toList())
                .as("only one Watch may hold the unique camera").hasSize(1);
        String holder = made.stream().filter(w -> f.kb.value(w, "mCam").isPresent()).findFirst().orElseThrow();
        e.destroy(holder);
        f.assertFact("u3", "User");
        e.runToQuiescence();
        assertThat(f.instancesOf("Watch").stream().filter(w -> f.kb.value(w, "mCam").isPresent()).toList())
                .as("the camera is free again once its holder is gone").hasSize(1);
    }

    @Test
    void refraction_whenFactIsChangedWithoutEffect_doesNotFireTheSameBindingTwice() {
        Fixture f = Fixture.paper();
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("userA", "NewUser", "age", "3");
        e.runToQuiescence();
        f.kb.replace(f.kb.require("userA").withSlot(Fixture.str("age", "4")));
        assertThat(e.runToQuiescence()).isZero();
        assertThat(f.instancesOf("AskUserName")).hasSize(1);
        assertThat(f.traced(TraceEvent.Blocked.class)).anySatisfy(b -> assertThat(b.reason()).startsWith("refraction"));
    }

    @Test
    void constantCondition_isTestedOnTheCandidate() {
        Fixture f = new Fixture();
        f.cls("Order", null);
        f.kb.add(Frame.classFrame("ServeTea").slot(Fixture.inst("mOrder", "Order", ".drink == \"tea\"")).build());
        InferenceEngine e = f.engine();
        f.assertFact("o1", "Order", "drink", "coffee");
        f.assertFact("o2", "Order", "drink", "tea");
        e.runToQuiescence();
        assertThat(f.instancesOf("ServeTea")).singleElement()
                .satisfies(n -> assertThat(f.kb.value(n, "mOrder")).contains(Value.ref("o2")));
    }

    @Test
    void joinCondition_bindsOnlyPartnersWithEqualValues() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Order2").parent("Order").build());
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".user == mUser")).build());
        f.kb.add(Frame.classFrame("ByName").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".who == mUser.name")).build());
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User", "name", "Ann");
        f.assertFact("u2", "User", "name", "Bob");
        f.assertFact("o1", "Order", "user", "@u2", "who", "Bob");
        f.assertFact("o2", "Order2", "user", "@u1", "who", "Ann");
        f.assertFact("o3", "Order", "user", "@u1", "who", "Nobody");
        e.runToQuiescence();
        assertThat(f.instancesOf("Deliver").stream().map(n -> f.kb.value(n, "mUser").orElseThrow().text() + "/"
                + f.kb.value(n, "mOrder").orElseThrow().text())).containsExactlyInAnyOrder("u2/o1", "u1/o2", "u1/o3");
        assertThat(f.instancesOf("ByName").stream().map(n -> f.kb.value(n, "mUser").orElseThrow().text() + "/"
                + f.kb.value(n, "mOrder").orElseThrow().text())).containsExactlyInAnyOrder("u2/o1", "u1/o2");
    }

    @Test
    void cycleLimit_whenFrameFeedsItself_stopsWithErrorNamingTheFrame() {
        Fixture f = new Fixture();
        f.cls("Thing", null);
        f.kb.add(Frame.classFrame("Echo").parent("Thing").slot(Fixture.inst("mIn", "Thing")).build());
        InferenceEngine e = f.engine(EngineOptions.defaults().withMaxFirings(50));
        f.assertFact("t0", "Thing");
        assertThatThrownBy(e::runToQuiescence).isInstanceOf(InferenceLimitException.class)
                .hasMessage("Inference stopped after 50 firings without reaching quiescence; the frames firing most were "
                        + "'Echo'.")
                .satisfies(x -> assertThat(((InferenceLimitException) x).topFrames()).containsExactly("Echo"));
        assertThat(f.traced(TraceEvent.LimitReached.class)).hasSize(1);
    }

    @Test
    void cycleLimit_namesTheFramesFiringMostAmongTheLast4096Firings_theLoopNotWhatFiredBeforeIt() {
        Fixture f = new Fixture();
        f.cls("Thing", null).cls("Visitor", null);
        f.kb.add(Frame.classFrame("Echo").parent("Thing").priority(1).slot(Fixture.inst("mIn", "Thing")).build());
        f.kb.add(Frame.classFrame("Greet").priority(5).slot(Fixture.inst("mVisitor", "Visitor")).build());
        InferenceEngine e = f.engine(EngineOptions.defaults().withMaxFirings(8_000));
        f.assertFact("t0", "Thing");
        for (int i = 0; i < 5_000; i++) {
            f.assertFact("v" + i, "Visitor");
        }
        // 5,000 Greets first (higher priority), then Echo feeds itself: 3,001 Echos when the limit stops it. In the
        // whole run Greet fired more; among the last 4,096 firings Echo did (3,001 to 1,095).
        assertThatThrownBy(e::runToQuiescence).isInstanceOf(InferenceLimitException.class)
                .satisfies(x -> assertThat(((InferenceLimitException) x).topFrames()).containsExactly("Echo", "Greet"));
        assertThat(f.instancesOf("Greet")).hasSize(5_000);
    }

    /** Runs {@code change} on another thread, as a sensor's agent would, and waits until it is committed. */
    private static void fromAnotherThread(ExecutorService outside, Runnable change) {
        try {
            outside.submit(change).get(10, TimeUnit.SECONDS);
        } catch (Exception x) {
            throw new AssertionError("the change from outside did not complete: " + x, x);
        }
    }

    @Test
    void cycleLimit_countsFiringsInARow_aStreamOfStimuliFromOutsideTheRunIsNoRunaway() throws Exception {
        Fixture f = new Fixture();
        f.cls("Ping", null);
        f.kb.add(Frame.classFrame("Respond").slot(Fixture.inst("mPing", "Ping"))
                .slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of("next-ping"))).build());
        ExecutorService outside = Executors.newSingleThreadExecutor();
        AtomicInteger sent = new AtomicInteger(1);
        // Each response brings the next stimulus from another thread while the run still fires: it is queued before
        // the run next looks at its agenda, so the agenda never empties until the 60th, three times the limit.
        f.scripts.define("next-ping", g -> {
            int i = sent.getAndIncrement();
            if (i < 60) {
                fromAnotherThread(outside, () -> f.assertFact("p" + i, "Ping"));
            }
            return null;
        });
        InferenceEngine e = f.engine(EngineOptions.defaults().withMaxFirings(20));
        f.assertFact("p0", "Ping");
        try {
            assertThat(e.runToQuiescence()).as("one run, all sixty").isEqualTo(60);
        } finally {
            outside.shutdownNow();
        }
        assertThat(f.instancesOf("Respond")).hasSize(60);
        assertThat(f.traced(TraceEvent.LimitReached.class)).isEmpty();
    }

    @Test
    void cycleLimit_stopsARunawayAfterMaxFiringsInARow_countingAgainFromTheLastChangeFromOutside() throws Exception {
        Fixture f = new Fixture();
        f.cls("Thing", null).cls("Note", null);
        f.kb.add(Frame.classFrame("Echo").parent("Thing").slot(Fixture.inst("mIn", "Thing"))
                .slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of("note-at-30"))).build());
        ExecutorService outside = Executors.newSingleThreadExecutor();
        AtomicInteger echoes = new AtomicInteger();
        f.scripts.define("note-at-30", g -> {
            if (echoes.incrementAndGet() == 30) {
                fromAnotherThread(outside, () -> f.assertFact("n1", "Note"));
            }
            return null;
        });
        InferenceEngine e = f.engine(EngineOptions.defaults().withMaxFirings(50));
        f.assertFact("t0", "Thing");
        try {
            assertThatThrownBy(e::runToQuiescence).isInstanceOf(InferenceLimitException.class)
                    .satisfies(x -> assertThat(((InferenceLimitException) x).topFrames()).containsExactly("Echo"));
        } finally {
            outside.shutdownNow();
        }
        // 30 firings, the note from outside, then 50 more in a row: the 81st is the one refused
        assertThat(f.instancesOf("Echo")).hasSize(80);
    }

    @Test
    void derivationDepthLimit_stopsARunawayThatChangesFromOutsideKeepFromFiringMaxFiringsInARow() throws Exception {
        Fixture f = new Fixture();
        f.cls("Thing", null).cls("Note", null);
        f.kb.add(Frame.classFrame("Echo").parent("Thing").slot(Fixture.inst("mIn", "Thing"))
                .slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of("note-every-20"))).build());
        ExecutorService outside = Executors.newSingleThreadExecutor();
        AtomicInteger echoes = new AtomicInteger();
        f.scripts.define("note-every-20", g -> {
            int n = echoes.incrementAndGet();
            if (n % 20 == 0 && n <= 2_000) { // a sensor's reading, from another thread, every 20 firings
                fromAnotherThread(outside, () -> f.assertFact("n" + n, "Note"));
            }
            return null;
        });
        InferenceEngine e = f.engine(EngineOptions.defaults().withMaxFirings(50).withMaxDerivationDepth(300));
        f.assertFact("t0", "Thing");
        try {
            assertThatThrownBy(e::runToQuiescence).isInstanceOf(InferenceLimitException.class)
                    .hasMessage("Inference stopped: 'Echo' would derive an instance resting on 300 derived instances, "
                            + "each made from the one before, so the knowledge base feeds itself; the frames firing "
                            + "most were 'Echo'.");
        } finally {
            outside.shutdownNow();
        }
        assertThat(f.instancesOf("Echo")).as("never 50 in a row: the depth stopped it, at the 301st").hasSize(300);
        assertThat(f.traced(TraceEvent.LimitReached.class)).singleElement()
                .satisfies(l -> assertThat(l.limit()).isEqualTo(300));
        String deepest = f.instancesOf("Echo").stream().max(java.util.Comparator.comparingInt(
                i -> e.derivation(i).orElseThrow().depth())).orElseThrow();
        assertThat(e.derivation(deepest).orElseThrow().depth()).isEqualTo(300);
    }

    @Test
    void derivationDepth_isOneMoreThanTheDeepestBoundInstance_andCountsAScriptsCreationsToo() {
        Fixture f = ForwardChainingTest.chain3();
        f.cls("Made", null);
        f.kb.add(Frame.classFrame("Maker").slot(Fixture.inst("mIn", "Step2"))
                .slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of("make"))).build());
        f.scripts.define("make", g -> Fixture.call(g, "create", "Made", Map.of()));
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();

        assertThat(Map.of("Step1", 1, "Step2", 2, "Step3", 3, "Maker", 3, "Made", 4)).allSatisfy((cls, depth) ->
                assertThat(e.derivation(f.instancesOf(cls).getFirst()).orElseThrow().depth()).as(cls).isEqualTo(depth));
    }

    @Test
    void cycleLimit_countsFirings_notActivationsBlockedWhenTheirTurnCame() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Cup", null);
        f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mCup", DataType.INSTANCE).argument("Cup").required(true).shared(false).build())
                .build());
        InferenceEngine e = f.engine(EngineOptions.defaults().withMaxFirings(2));
        f.assertFact("cup", "Cup");
        for (String u : List.of("u1", "u2", "u3", "u4")) {
            f.assertFact(u, "User");
        }
        assertThat(e.agendaSize()).as("all four wait: nothing holds the cup yet").isEqualTo(4);

        assertThat(e.runToQuiescence()).as("one firing; the other three find the cup taken").isEqualTo(1);
        assertThat(f.instancesOf("Serve")).hasSize(1);
        assertThat(f.traced(TraceEvent.LimitReached.class)).isEmpty();
    }

    @Test
    void onNeeded_whenTheDemonReturnsAValueNotOfTheSlotsType_readsNothingAndTracesTheFailureNamingFrameAndSlot() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("User").slot(Slot.builder("age", DataType.INTEGER).onNeeded("guess-age").build())
                .build());
        f.scripts.define("guess-age", g -> {
            Fixture.call(g, "command", "PINO", "ask_age");
            return "about ten";
        });
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");

        assertThat(e.read("u1", "age")).isEmpty();

        assertThat(f.traced(TraceEvent.ScriptFailed.class)).singleElement().satisfies(x -> {
            assertThat(x.frame()).isEqualTo("User");
            assertThat(x.slot()).isEqualTo("onNeeded");
            assertThat(x.message()).isEqualTo("The onNeeded demon of slot 'age' of frame 'User' returned a value that "
                    + "slot cannot hold: 'about ten' is not an integer.");
        });
        assertThat(f.sent).as("a failed demon's effects are discarded").isEmpty();
    }

    @Test
    void agenda_ordersByPriorityThenDepthThenConditionsThenRecency() {
        Fixture f = new Fixture();
        f.cls("Thing", null).cls("Base", null);
        f.kb.add(Frame.classFrame("Low").slot(Fixture.inst("mX", "Thing")).build());
        f.kb.add(Frame.classFrame("High").priority(5).slot(Fixture.inst("mX", "Thing")).build());
        f.kb.add(Frame.classFrame("Deep").parent("Base").slot(Fixture.inst("mX", "Thing")).build());
        f.kb.add(Frame.classFrame("Picky").slot(Fixture.inst("mX", "Thing", ".size >= 0")).build());
        InferenceEngine e = f.engine();
        f.assertFact("old", "Thing", "size", 1);
        f.assertFact("new", "Thing", "size", 2);
        e.runToQuiescence();
        List<String> order = f.traced(TraceEvent.Fired.class).stream()
                .map(x -> x.frame() + ":" + x.binding().get("mX")).toList();
        assertThat(order).containsExactly("High:new", "High:old", "Deep:new", "Deep:old", "Picky:new", "Picky:old",
                "Low:new", "Low:old");
    }

    @Test
    void engineStartedLate_matchesInstancesAlreadyThere() {
        Fixture f = Fixture.paper();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("userA", "NewUser");
        InferenceEngine e = f.engine();
        assertThat(e.runToQuiescence()).isEqualTo(1);
    }
}

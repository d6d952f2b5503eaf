package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.core.Frames.cls;
import static org.kicnp.core.Frames.figure1;
import static org.kicnp.core.Frames.instanceSlot;
import static org.kicnp.core.Frames.str;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class KnowledgeBaseTest {

    @Test
    void add_whenParentUnknown_rejectsNamingBothFrames() {
        KnowledgeBase kb = figure1();
        assertThatThrownBy(() -> kb.add(cls("Greeting", "Speach")))
                .isInstanceOf(BatchRejectedException.class)
                .hasMessage("Frame 'Greeting' is a kind of 'Speach', which is not defined.");
    }

    @Test
    void problems_listsWhatApplyWouldRefuse_andChangesNothing() {
        KnowledgeBase kb = figure1();
        long version = kb.version();
        int size = kb.size();

        List<Problem> problems = kb.problems(List.of(new Change.Add(cls("Greeting", "Speach")),
                new Change.Add(cls("Speech", "System")), new Change.Add(cls("Farewell", "Speech"))));
        List<Problem> ok = kb.problems(List.of(new Change.Add(cls("Farewell", "Speech"))));
        List<Problem> bad = kb.problems(List.of(new Change.Add(cls("Greeting", "Speach"))));

        assertThat(problems).extracting(Problem::message).containsExactly("A frame named 'Speech' already exists.");
        assertThat(ok).isEmpty();
        assertThat(bad).extracting(Problem::message)
                .containsExactly("Frame 'Greeting' is a kind of 'Speach', which is not defined.");
        assertThat(kb.version()).isEqualTo(version);
        assertThat(kb.size()).isEqualTo(size);
        assertThat(kb.contains("Farewell")).isFalse();
    }

    @Test
    void add_whenNameTaken_rejectsDuplicate() {
        KnowledgeBase kb = figure1();
        assertThatThrownBy(() -> kb.add(cls("Speech", "System")))
                .hasMessage("A frame named 'Speech' already exists.");
    }

    @Test
    void add_whenParentIsInstance_rejects() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.instance("ken", "KnownUser").build());
        assertThatThrownBy(() -> kb.add(cls("Sub", "ken")))
                .hasMessageContaining("which is an instance; only classes can have sub-frames");
    }

    @Test
    void replace_whenParentMakesCycle_rejectsAndShowsTheCycle() {
        KnowledgeBase kb = figure1();
        assertThatThrownBy(() -> kb.replace(cls("User", "KnownUser")))
                .hasMessage("Frame 'User' is a kind of 'KnownUser', which makes an IS-A cycle: "
                        + "User -> KnownUser -> User.");
    }

    @Test
    void remove_whenClassHasInstances_rejectsAndListsThem() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.instance("ken", "KnownUser").build());
        assertThatThrownBy(() -> kb.remove("KnownUser"))
                .hasMessage("Frame 'KnownUser' cannot be removed: it still has instances 'ken'.");
    }

    @Test
    void remove_whenClassHasSubclasses_rejects() {
        KnowledgeBase kb = figure1();
        assertThatThrownBy(() -> kb.remove("User"))
                .hasMessageContaining("cannot be removed: it still has subclasses or instances 'KnownUser', 'NewUser'");
    }

    @Test
    void remove_whenReferredToBySlotArgument_rejectsNamingTheReferrer() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.classFrame("Greeting").parent("Speech").slot(instanceSlot("mMouth", "Mouth")).build());
        assertThatThrownBy(() -> kb.remove("Mouth"))
                .hasMessage("Frame 'Mouth' cannot be removed: frame 'Greeting' refers to it.");
    }

    @Test
    void remove_whenReferrerRemovedInSameBatch_succeeds() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.classFrame("Greeting").parent("Speech").slot(instanceSlot("mMouth", "Mouth")).build());
        kb.apply(List.of(new Change.Remove("Greeting"), new Change.Remove("Mouth")));
        assertThat(kb.contains("Mouth")).isFalse();
        assertThat(kb.contains("Greeting")).isFalse();
    }

    @Test
    void add_whenArgumentClassUnknown_rejectsNamingSlot() {
        KnowledgeBase kb = figure1();
        BatchRejectedException e = org.junit.jupiter.api.Assertions.assertThrows(BatchRejectedException.class,
                () -> kb.add(Frame.classFrame("Greeting").parent("Speech")
                        .slot(instanceSlot("mUser", "KnownUsr")).build()));
        assertThat(e.problems()).singleElement().satisfies(p -> {
            assertThat(p.frame()).isEqualTo("Greeting");
            assertThat(p.slot()).contains("mUser");
            assertThat(p.message()).isEqualTo("Slot 'mUser' of frame 'Greeting' names class 'KnownUsr' as its "
                    + "ARGUMENT, which is not defined.");
        });
    }

    @Test
    void add_whenInstanceSlotHasNoArgument_rejects() {
        KnowledgeBase kb = figure1();
        assertThatThrownBy(() -> kb.add(Frame.classFrame("Greeting").parent("Speech")
                .slot(Slot.builder("mUser", DataType.INSTANCE).build()).build()))
                .hasMessageContaining("has no ARGUMENT naming the class it must hold");
    }

    @Test
    void add_whenValueIsNotAnInstanceOfTheArgumentClass_rejects() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.classFrame("Greeting").parent("Speech").slot(instanceSlot("mUser", "KnownUser")).build());
        kb.add(Frame.instance("bob", "NewUser").build());
        assertThatThrownBy(() -> kb.add(Frame.instance("g1", "Greeting")
                .slot(Slot.ofValue("mUser", DataType.INSTANCE, Value.ref("bob"))).build()))
                .hasMessage("Slot 'mUser' of frame 'g1' must hold an instance of 'KnownUser', but 'bob' is not one.");
    }

    @Test
    void apply_whenArgumentIsDeclaredTwoClassesUp_checksValuesAgainstItAndTypesAgainstTheNearest() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.instance("bob", "NewUser").build());
        List<Change> batch = List.of(
                new Change.Add(Frame.classFrame("Talk").parent("Speech").slot(instanceSlot("mUser", "KnownUser"))
                        .build()),
                new Change.Add(Frame.classFrame("Chat").parent("Talk")
                        .slot(Slot.builder("mUser", DataType.INSTANCE).required(true).build()).build()),
                new Change.Add(Frame.classFrame("Banter").parent("Chat").build()),
                new Change.Add(Frame.instance("c1", "Banter")
                        .slot(Slot.ofValue("mUser", DataType.INSTANCE, Value.ref("bob"))).build()),
                new Change.Add(Frame.instance("c2", "Chat")
                        .slot(Slot.ofValue("mUser", DataType.STRING, Value.of("bob"))).build()));

        assertThatThrownBy(() -> kb.apply(batch)).isInstanceOfSatisfying(BatchRejectedException.class, e ->
                assertThat(e.problems()).extracting(Problem::message).containsExactlyInAnyOrder(
                        "Slot 'mUser' of frame 'c1' must hold an instance of 'KnownUser', but 'bob' is not one.",
                        "Slot 'mUser' of frame 'c2' is TYPE_STR but 'Chat' declares it TYPE_INSTANCE."));
    }

    @Test
    void add_whenSlotTypeDiffersFromInheritedDeclaration_rejects() {
        KnowledgeBase kb = figure1();
        assertThatThrownBy(() -> kb.add(Frame.instance("ken", "KnownUser")
                .slot(Slot.ofValue("name", DataType.INTEGER, Value.of(3))).build()))
                .hasMessage("Slot 'name' of frame 'ken' is TYPE_INT but 'User' declares it TYPE_STR.");
    }

    @Test
    void add_whenAConditionCanNeverHoldBecauseOfTypes_rejectsNamingFrameAndSlot() {
        KnowledgeBase kb = figure1();
        Frame bad = Frame.classFrame("Odd").parent("Speech")
                .slot(Slot.builder("count", DataType.INTEGER).condition(ConditionParser.parse("== \"3\"")).build())
                .slot(Slot.builder("size", DataType.FLOAT).condition(ConditionParser.parse("between 5 and 1")).build())
                .slot(Slot.builder("word", DataType.STRING).condition(ConditionParser.parse(".length > 3")).build())
                .slot(Slot.builder("mUser", DataType.INSTANCE).argument("User")
                        .condition(ConditionParser.parse(".name == 7")).build())
                .build();

        assertThatThrownBy(() -> kb.add(bad)).isInstanceOfSatisfying(BatchRejectedException.class, e ->
                assertThat(e.problems()).extracting(Problem::message).containsExactlyInAnyOrder(
                        "Slot 'count' of frame 'Odd' has the condition '== \"3\"', which compares a TYPE_INT value "
                                + "with \"3\": they never compare, so it can never hold.",
                        "Slot 'size' of frame 'Odd' has the condition 'between 5 and 1', whose low end is above its "
                                + "high end, so it can never hold.",
                        "Slot 'word' of frame 'Odd' has the condition '.length > 3' on '.length', but the slot holds "
                                + "TYPE_STR, not an instance: the path leads nowhere.",
                        "Slot 'mUser' of frame 'Odd' has the condition '.name == 7', which compares a TYPE_STR value "
                                + "with 7: they never compare, so it can never hold."));
        assertThat(kb.contains("Odd")).isFalse();
    }

    @Test
    void add_whenConditionsFitTheirTypes_acceptsThem() {
        KnowledgeBase kb = figure1();

        kb.add(Frame.classFrame("Fine").parent("Speech")
                .slot(Slot.builder("count", DataType.INTEGER).condition(ConditionParser.parse(">= 2.5")).build())
                .slot(Slot.builder("size", DataType.FLOAT).condition(ConditionParser.parse("between 1 and 5")).build())
                .slot(Slot.builder("mUser", DataType.INSTANCE).argument("User")
                        .condition(ConditionParser.parse(".name in (\"taro\", \"hanako\")")).build())
                .build());

        assertThat(kb.contains("Fine")).isTrue();
    }

    @Test
    void add_whenConditionPathNamesUnknownSlot_rejects() {
        KnowledgeBase kb = figure1();
        Slot s = Slot.builder("mUser", DataType.INSTANCE).argument("User")
                .condition(ConditionParser.parse(".name == mSpeaker.name")).build();
        assertThatThrownBy(() -> kb.add(Frame.classFrame("Echo").parent("Speech").slot(s).build()))
                .hasMessageContaining("has a condition on 'mSpeaker.name', but frame 'Echo' has no slot 'mSpeaker'");
    }

    @Test
    void apply_whenOneChangeIsBad_appliesNothingAndReportsEveryProblem() {
        KnowledgeBase kb = figure1();
        long before = kb.version();
        List<Frame> framesBefore = kb.frames();
        BatchRejectedException e = org.junit.jupiter.api.Assertions.assertThrows(BatchRejectedException.class,
                () -> kb.apply(List.of(
                        new Change.Add(cls("Gesture", "HumanRobotInteraction")),
                        new Change.Add(cls("Wave", "Gestur")),
                        new Change.Add(cls("Nod", "Gestr")))));
        assertThat(e.problems()).extracting(Problem::frame).containsExactly("Wave", "Nod");
        assertThat(kb.version()).isEqualTo(before);
        assertThat(kb.frames()).isEqualTo(framesBefore);
        assertThat(kb.contains("Gesture")).isFalse();
    }

    @Test
    void apply_addsParentAndChildInOneBatchInAnyOrder() {
        KnowledgeBase kb = figure1();
        kb.apply(List.of(new Change.Add(Frame.instance("wave1", "Wave").build()),
                new Change.Add(cls("Wave", "Gesture")),
                new Change.Add(cls("Gesture", "HumanRobotInteraction"))));
        assertThat(kb.instancesOf("HumanRobotInteraction")).extracting(Frame::name).containsExactly("wave1");
        assertThat(kb.isA("wave1", "System")).isTrue();
    }

    @Test
    void instancesOf_includesDescendantsInstancesAndFollowsReparenting() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.instance("ken", "KnownUser").build());
        kb.add(Frame.instance("bob", "NewUser").build());
        kb.add(Frame.instance("mouth1", "Mouth").build());
        assertThat(kb.instancesOf("User")).extracting(Frame::name).containsExactly("ken", "bob");
        assertThat(kb.instancesOf("System")).extracting(Frame::name).containsExactly("ken", "bob", "mouth1");
        assertThat(kb.instancesOf("KnownUser")).extracting(Frame::name).containsExactly("ken");

        kb.replace(cls("KnownUser", "HumanRobotInteraction"));
        assertThat(kb.instancesOf("User")).extracting(Frame::name).containsExactly("bob");
        assertThat(kb.instancesOf("HumanRobotInteraction")).extracting(Frame::name)
                .containsExactlyInAnyOrder("ken", "mouth1");
        assertThat(kb.countInstancesOf("System")).isEqualTo(3);

        kb.remove("ken");
        assertThat(kb.instancesOf("HumanRobotInteraction")).extracting(Frame::name).containsExactly("mouth1");
        assertThat(kb.children("KnownUser")).isEmpty();
    }

    @Test
    void instancesOf_whenInstanceMovesToAnotherClass_updatesBothChains() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.instance("ana", "NewUser").build());
        kb.replace(Frame.instance("ana", "KnownUser").build());
        assertThat(kb.instancesOf("NewUser")).isEmpty();
        assertThat(kb.instancesOf("KnownUser")).extracting(Frame::name).containsExactly("ana");
        assertThat(kb.instancesOf("User")).extracting(Frame::name).containsExactly("ana");
    }

    @Test
    void isA_anInstanceIsAnInstanceOfItsClassAndEveryAncestor() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.instance("ken", "KnownUser").build());
        assertThat(kb.isA("ken", "KnownUser")).isTrue();
        assertThat(kb.isA("ken", "User")).isTrue();
        assertThat(kb.isA("ken", "System")).isTrue();
        assertThat(kb.isA("ken", "NewUser")).isFalse();
        assertThat(kb.ancestors("ken")).containsExactly("KnownUser", "User", "System");
    }

    @Test
    void children_isDerivedFromAkindOfAndNeverStored() {
        KnowledgeBase kb = figure1();
        assertThat(kb.children("User")).extracting(Frame::name).containsExactly("KnownUser", "NewUser");
        kb.remove("NewUser");
        assertThat(kb.children("User")).extracting(Frame::name).containsExactly("KnownUser");
        assertThat(kb.roots()).extracting(Frame::name).containsExactly("System");
    }

    @Test
    void replace_withStaleRevision_isRefusedWithAClearMessage() {
        KnowledgeBase kb = figure1();
        long read = kb.revision("Speech");
        kb.replace(Frame.classFrame("Speech").parent("HumanRobotInteraction").slot(str("text", "hi")).build());
        assertThatThrownBy(() -> kb.apply(List.of(new Change.Replace(
                Frame.classFrame("Speech").parent("HumanRobotInteraction").slot(str("text", "bye")).build(), read))))
                .isInstanceOf(StaleRevisionException.class)
                .hasMessageContaining("Frame 'Speech' was changed by someone else");
        assertThat(kb.value("Speech", "text")).contains(Value.of("hi"));
    }

    @Test
    void remove_withStaleRevision_isRefusedAndKeepsTheNewerFrame_withTheRevisionReadItGoes() {
        KnowledgeBase kb = figure1();
        long read = kb.revision("Speech");
        kb.replace(Frame.classFrame("Speech").parent("HumanRobotInteraction").slot(str("text", "hi")).build());
        assertThatThrownBy(() -> kb.apply(List.of(new Change.Remove("Speech", read))))
                .isInstanceOf(StaleRevisionException.class)
                .hasMessageContaining("Frame 'Speech' was changed by someone else");
        assertThat(kb.value("Speech", "text")).contains(Value.of("hi"));
        kb.apply(List.of(new Change.Remove("Speech", kb.revision("Speech"))));
        assertThat(kb.contains("Speech")).isFalse();
    }

    @Test
    void put_thatChangesNothing_makesNoEventAndNoVersion() {
        KnowledgeBase kb = figure1();
        long v = kb.version();
        ChangeSet cs = kb.put(kb.require("Speech"));
        assertThat(cs.events()).isEmpty();
        assertThat(kb.version()).isEqualTo(v);
    }

    @Test
    void apply_ofAnEmptyBatch_makesNoVersionAndTellsNoListener() {
        KnowledgeBase kb = figure1();
        long v = kb.version();
        List<ChangeSet> heard = new ArrayList<>();
        kb.addListener(heard::add);
        assertThat(kb.apply(List.of()).events()).isEmpty();
        assertThat(kb.version()).isEqualTo(v);
        kb.add(Frame.instance("ken", "KnownUser").provenance(Provenance.RUNTIME).build());
        assertThat(heard).extracting(ChangeSet::version).containsExactly(v + 1);
    }

    @Test
    void listeners_hearBatchesInCommitOrder_includingChangesMadeByAListener() {
        KnowledgeBase kb = figure1();
        List<String> heard = new ArrayList<>();
        kb.addListener(cs -> {
            cs.events().forEach(e -> heard.add(e.getClass().getSimpleName() + ":" + e.name()));
            if (cs.events().stream().anyMatch(e -> e.name().equals("ken"))) {
                kb.add(Frame.instance("greeting1", "Speech").provenance(Provenance.RUNTIME).build());
                heard.add("after nested add");
            }
        });
        kb.add(Frame.instance("ken", "KnownUser").build());
        assertThat(heard).containsExactly("Added:ken", "after nested add", "Added:greeting1");
    }

    @Test
    void commitLog_seesOnlyDurableFrames_andAFailingLogLeavesTheBaseUnchanged() {
        List<String> logged = new ArrayList<>();
        boolean[] fail = {false};
        KnowledgeBase kb = KnowledgeBase.create((version, events) -> {
            if (fail[0]) {
                throw new IllegalStateException("disk full");
            }
            events.forEach(e -> logged.add(e.name()));
        });
        kb.add(Frames.root("System"));
        kb.add(Frame.instance("stimulus1", "System").provenance(Provenance.RUNTIME).build());
        kb.add(Frame.instance("ken", "System").provenance(Provenance.LEARNED).build());
        assertThat(logged).containsExactly("System", "ken");

        fail[0] = true;
        assertThatThrownBy(() -> kb.add(Frame.instance("ana", "System").provenance(Provenance.LEARNED).build()))
                .hasMessageContaining("could not be made durable").hasMessageContaining("disk full");
        assertThat(kb.contains("ana")).isFalse();
        assertThat(kb.version()).isEqualTo(3);
    }

    @Test
    void semanticLinks_areSeenFromBothEnds() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.classFrame("Greeting").parent("Speech").build());
        kb.add(Frame.classFrame("AskDrink").parent("Speech")
                .linkFrom(Relation.Coordination.SUCCESSION, "Greeting").build());
        assertThat(kb.linksOutOf("Greeting"))
                .containsExactly(new SemanticLink(Relation.Coordination.SUCCESSION, "AskDrink"));
        assertThat(kb.linksInto("AskDrink"))
                .containsExactly(new SemanticLink(Relation.Coordination.SUCCESSION, "Greeting"));
    }

    @Test
    void learnedFrames_areMarked() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.classFrame("Ken").parent("KnownUser").provenance(Provenance.LEARNED).build());
        assertThat(kb.require("Ken").learned()).isTrue();
        assertThat(kb.require("KnownUser").learned()).isFalse();
    }

    @Test
    void concurrentReadersAndWriters_keepTheIndexesConsistent() throws Exception {
        KnowledgeBase kb = figure1();
        int perThread = 500;
        List<Thread> threads = new ArrayList<>();
        for (int t = 0; t < 4; t++) {
            int id = t;
            threads.add(Thread.ofPlatform().start(() -> {
                for (int i = 0; i < perThread; i++) {
                    kb.add(Frame.instance("u" + id + "_" + i, i % 2 == 0 ? "KnownUser" : "NewUser")
                            .provenance(Provenance.RUNTIME).build());
                    kb.instancesOf("User");
                }
            }));
        }
        for (Thread t : threads) {
            t.join();
        }
        assertThat(kb.countInstancesOf("User")).isEqualTo(4 * perThread);
        assertThat(kb.countInstancesOf("KnownUser") + kb.countInstancesOf("NewUser")).isEqualTo(4 * perThread);
    }

    @Test
    void listeners_hearEveryVersionOnceInCommitOrder_oneAtATime_whileThreadsCommitAtOnce() throws Exception {
        KnowledgeBase kb = figure1();
        DeliveryProbe probe = DeliveryProbe.on(kb);
        int perThread = 3_000;
        DeliveryProbe.together(4, id -> {
            for (int i = 0; i < perThread; i++) {
                // plain instances (the short cut) and class frames (the general path), interleaved
                kb.add(i % 5 == 0 ? cls("C" + id + "_" + i, "Speech")
                        : Frame.instance("u" + id + "_" + i, "NewUser").provenance(Provenance.RUNTIME).build());
            }
        });
        probe.assertHeardInOrder(4 * perThread);
    }

    @Test
    void add_whenDurableFrameRefersToRuntimeFrame_rejectsBecauseItCouldNotReload() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.classFrame("Greeting").parent("Speech").slot(instanceSlot("mUser", "User")).build());
        kb.add(Frame.instance("face7", "NewUser").provenance(Provenance.RUNTIME).build());
        assertThatThrownBy(() -> kb.add(Frame.instance("g1", "Greeting").provenance(Provenance.LEARNED)
                .slot(Slot.ofValue("mUser", DataType.INSTANCE, Value.ref("face7"))).build()))
                .hasMessage("Frame 'g1' is kept on disk but refers to 'face7', which exists only at run time; "
                        + "copy the values it needs instead.");
        kb.add(Frame.instance("g2", "Greeting").provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("mUser", DataType.INSTANCE, Value.ref("face7"))).build());
        assertThat(kb.contains("g2")).isTrue();
    }
}

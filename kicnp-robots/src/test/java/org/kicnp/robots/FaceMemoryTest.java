package org.kicnp.robots;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.kicnp.robots.SimWorldTest.waitUntil;

/** Faces kept with KnownUser frames, and Robovie recognising a live face from the simulator's eye cameras. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class FaceMemoryTest {
    private SimWorld world;

    /** Figure 1's users, with the face slot as the Table 5 hierarchy declares it. */
    static KnowledgeBase users() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("User").root()
                .slot(Slot.builder("name", DataType.STRING).build())
                .slot(Slot.builder("face", DataType.LIST).argument("TYPE_FLOAT").build())
                .build());
        kb.add(Frame.classFrame("KnownUser").parent("User").build());
        kb.add(Frame.classFrame("NewUser").parent("User").build());
        return kb;
    }

    @AfterEach
    void stop() {
        if (world != null) {
            world.close();
        }
    }

    @Test
    void attach_enrolsTheKnownUsersAlreadyThereAndLaterOnesButNotNewUsers() {
        KnowledgeBase kb = users();
        FaceMemory.remember(kb, "alice", FaceVector.of(1, 0, 0));
        kb.add(Frame.instance("someone", "NewUser")
                .slot(Slot.ofValue("face", DataType.LIST, new Value.Lst(List.of(Value.of(0.0), Value.of(1.0), Value.of(0.0)))))
                .build());
        FaceRecognizer recognizer = FaceRecognizer.create(0.3);
        FaceMemory.attach(kb, recognizer);
        assertThat(recognizer.names()).containsExactly("alice");

        FaceMemory.remember(kb, "bob", FaceVector.of(0, 0, 1));

        assertThat(recognizer.names()).containsExactlyInAnyOrder("alice", "bob");
        assertThat(recognizer.recognize(FaceVector.of(0.05, 0, 0.98))).map(FaceRecognizer.Match::name).contains("bob");
        assertThat(kb.require("bob").learned()).isTrue();
    }

    @Test
    void removingAKnownUser_forgetsTheirFace() {
        KnowledgeBase kb = users();
        FaceRecognizer recognizer = FaceRecognizer.create(0.3);
        FaceMemory.attach(kb, recognizer);
        FaceMemory.remember(kb, "alice", FaceVector.of(1, 0, 0));

        kb.remove("alice");

        assertThat(recognizer.names()).isEmpty();
        assertThat(recognizer.recognize(FaceVector.of(1, 0, 0))).isEmpty();
    }

    @Test
    void robovie_seesAStrangerAsUnknown_learnsTheFace_thenRecognisesTheUserOnTheNextVisit() throws Exception {
        KnowledgeBase kb = users();
        FaceRecognizer recognizer = FaceRecognizer.create();
        FaceMemory.attach(kb, recognizer);
        List<SensorSignal> signals = new CopyOnWriteArrayList<>();
        world = SimWorld.start(SimWorldTest.manual().withSeed(11));
        RobotDriver robovie = RobotDriver.attach(world, RobotModels.robovie(), recognizer, signals::add);

        visit("alice");
        waitUntil(() -> faceSeen(signals).size() == 1);
        assertThat(faceSeen(signals).getFirst().first()).isEqualTo(Value.of(RobotDriver.UNKNOWN));
        assertThat(faceSeen(signals).getFirst().values().get(1)).isInstanceOfSatisfying(Value.Lst.class,
                l -> assertThat(l.items()).hasSize(16));
        FaceMemory.remember(kb, "alice", robovie.lastFace().orElseThrow()); // what GotNewName does with the name heard
        leave("alice");
        waitUntil(() -> signals.stream().anyMatch(s -> s.sensor().equals("face_lost")));

        visit("alice");
        visit("carol");
        waitUntil(() -> faceSeen(signals).size() >= 2);
        assertThat(faceSeen(signals).get(1).first()).isEqualTo(Value.of("alice"));
        leave("alice");
        waitUntil(() -> faceSeen(signals).size() == 3);
        assertThat(faceSeen(signals).get(2).first()).isEqualTo(Value.of(RobotDriver.UNKNOWN));
    }

    private void visit(String user) {
        world.call(new SimRequest.SpawnUser(user, 4.0, 1.4, 90, Optional.empty()));
        world.step(0.5, false);
    }

    private void leave(String user) {
        world.call(new SimRequest.RemoveUser(user));
        world.step(0.5, false);
    }

    private static List<SensorSignal> faceSeen(List<SensorSignal> signals) {
        return signals.stream().filter(s -> s.sensor().equals("face_seen")).toList();
    }
}

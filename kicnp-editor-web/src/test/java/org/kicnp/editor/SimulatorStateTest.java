package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.kicnp.editor.WorldSnapshot.Room;

/** The simulator's {@code hello} and {@code state} events (robots-sim/PROTOCOL.md) as world snapshots. */
class SimulatorStateTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String HELLO = """
            {"type":"hello","t":0.0,"room":{"width":9.0,"height":6.0,"door":{"x":4.0,"y":0.0,"entry":{"x":4.0,"y":0.6}},
            "counter":{"x0":7.2,"y0":3.4,"x1":7.95,"y1":5.6}}}""";
    private static final String STATE = """
            {"type":"state","t":4.45,"robots":{
            "robovie":{"kind":"humanoid","x":4.0,"y":3.2,"heading_deg":-90.0,"v_mps":0.0,"actions":{},
              "arms":{"left":"up","right":"wave"}},
            "scout":{"kind":"mobile","x":6.2,"y":3.554,"heading_deg":90.14,"v_mps":0.3,
              "actions":{"base":{"id":"c9","action":"go_to"}},"carrying":"tea-1"},
            "aibo":{"kind":"quadruped","x":2.5,"y":2.0,"heading_deg":0.0,"actions":{},"posture":"sit"}},
            "users":{"alice":{"x":6.2,"y":4.6,"heading_deg":-90.0,"walking":false,"holding":[]}},
            "cups":{"tea-1":{"kind":"tea","x":6.2,"y":3.5,"holder":"robot:scout"},
              "coffee-1":{"kind":"coffee","x":7.3,"y":4.6,"holder":null}},
            "obstacles":{"box":{"x":6.2,"y":3.6,"w":1.0,"h":0.2}}}""";

    @Test void room_fromHello_readsSizeDoorAndCounter() throws Exception {
        Room room = SimulatorState.room(JSON.readTree(HELLO));
        assertThat(room.width()).isEqualTo(9.0);
        assertThat(room.door().x()).isEqualTo(4.0);
        assertThat(room.counter().x1()).isEqualTo(7.95);
    }

    @Test void snapshot_fromState_mapsEveryThingOneToOne() throws Exception {
        WorldSnapshot s = SimulatorState.snapshot(JSON.readTree(STATE), Room.SIMULATOR);

        assertThat(s.time()).isEqualTo(4.45);
        assertThat(s.robots()).extracting(WorldSnapshot.Robot::name).containsExactly("robovie", "scout", "aibo");
        assertThat(s.robots().get(0).state()).isEqualTo("arms up/wave");
        assertThat(s.robots().get(0).headingDeg()).isEqualTo(-90.0);
        assertThat(s.robots().get(1).actions()).containsExactly(new WorldSnapshot.RunningAction("base", "c9", "go_to"));
        assertThat(s.robots().get(1).state()).isEqualTo("carrying tea-1, moving 0.30 m/s");
        assertThat(s.robots().get(2).state()).isEqualTo("posture sit");
        assertThat(s.users()).containsExactly(new WorldSnapshot.User("alice", 6.2, 4.6, -90.0));
        assertThat(s.cups()).containsExactly(new WorldSnapshot.Cup("tea-1", "tea", 6.2, 3.5, "robot:scout"),
                new WorldSnapshot.Cup("coffee-1", "coffee", 7.3, 4.6, ""));
        assertThat(s.obstacles()).containsExactly(new WorldSnapshot.Obstacle("box", 6.2, 3.6, 1.0, 0.2));
    }

    @Test void snapshot_fromAnotherEvent_isRefusedInWords() {
        assertThatThrownBy(() -> SimulatorState.snapshot(JSON.readTree(HELLO), Room.SIMULATOR))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("A world snapshot is made from a 'state' event, not from 'hello'.");
    }
}

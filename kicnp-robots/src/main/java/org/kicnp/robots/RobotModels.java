package org.kicnp.robots;

import java.util.ArrayList;
import java.util.List;

import static org.kicnp.core.DataType.FLOAT;
import static org.kicnp.core.DataType.LIST;
import static org.kicnp.core.DataType.STRING;
import static org.kicnp.robots.ArgSpec.optional;
import static org.kicnp.robots.ArgSpec.required;

/**
 * The four robots of the paper (section 4.1) as the simulator offers them (robots-sim/PROTOCOL.md, "Actions per
 * robot"): each action's capability frame is the robot's prefix followed by the action in camel case
 * ({@code go_to} of Scout is {@code ScoutGoTo}).
 */
public final class RobotModels {
    private RobotModels() {
    }

    public static RobotModel robovie() {
        List<ActionSpec> a = motion("Robovie");
        a.add(moveArms("Robovie"));
        a.add(spec("Robovie", "head", "Turns the head (and the eye cameras with it).",
                optional("pan_deg", FLOAT), optional("tilt_deg", FLOAT)));
        a.add(spec("Robovie", "shake_hands", "Shakes hands with a user within 0.6 m, with both arms.",
                required("user", STRING)));
        a.add(spec("Robovie", "say", "Speaks a sentence through the speaker.", required("text", STRING)));
        return new RobotModel("robovie", "humanoid upper torso on a wheeled base: eye cameras with face recognition, "
                + "arms, head, speech; leads the interaction", a);
    }

    public static RobotModel pino() {
        List<ActionSpec> a = motion("Pino");
        a.add(moveArms("Pino"));
        a.add(spec("Pino", "shake_hands", "Shakes hands with a user within 0.6 m.", required("user", STRING)));
        a.add(spec("Pino", "stand_up", "Gets up after a fall."));
        return new RobotModel("pino", "biped humanoid with 26 degrees of freedom: walks, moves its arms, shakes hands", a);
    }

    public static RobotModel scout() {
        List<ActionSpec> a = motion("Scout");
        a.add(spec("Scout", "drive", "Drives the wheels at given speeds for a time.",
                required("left_mps", FLOAT), required("right_mps", FLOAT), required("duration_s", FLOAT)));
        a.add(spec("Scout", "pick_up", "Picks up a cup (tea, coffee or a cup id) from the counter within 0.4 m.",
                required("cup", STRING)));
        a.add(spec("Scout", "hand_over", "Hands the carried cup to a user within 0.6 m.", required("user", STRING)));
        a.add(spec("Scout", "put_down", "Puts the carried cup down on the counter in front of it (within 0.4 m); "
                + "carrying none, it ends at once."));
        return new RobotModel("scout", "differential-drive mobile robot: 16 sonars, 6 bumpers, carries a cup", a);
    }

    public static RobotModel aibo() {
        List<ActionSpec> a = motion("Aibo");
        a.add(spec("Aibo", "set_posture", "Stands, sits or lies down.", required("posture", STRING)));
        a.add(spec("Aibo", "lie_down", "Lies down."));
        a.add(spec("Aibo", "set_lights", "Sets the 19 lights: all to one colour, or a comma-separated list of 19.",
                optional("all", STRING), optional("lights", LIST)));
        return new RobotModel("aibo", "four-legged entertainment robot: walks, sits, lies down, 19 lights", a);
    }

    /** The four robots, Robovie first. */
    public static List<RobotModel> all() {
        return List.of(robovie(), pino(), scout(), aibo());
    }

    private static List<ActionSpec> motion(String prefix) {
        List<ActionSpec> a = new ArrayList<>();
        a.add(spec(prefix, "go_to", "Goes to (x, y) in metres, then turns to heading_deg if given.",
                required("x", FLOAT), required("y", FLOAT), optional("heading_deg", FLOAT),
                optional("tolerance_m", FLOAT), optional("stall_s", FLOAT)));
        a.add(spec(prefix, "turn_to", "Turns in place to heading_deg (0 = east, counter-clockwise).",
                required("heading_deg", FLOAT), optional("stall_s", FLOAT)));
        a.add(spec(prefix, "approach_user", "Goes up to a user, distance_m from them, and faces them.",
                required("user", STRING), optional("distance_m", FLOAT), optional("tolerance_m", FLOAT),
                optional("stall_s", FLOAT)));
        return a;
    }

    private static ActionSpec moveArms(String prefix) {
        return spec(prefix, "move_arms", "Moves the arms: pose for both, or left/right (down, up, wave, shake).",
                optional("pose", STRING), optional("left", STRING), optional("right", STRING));
    }

    private static ActionSpec spec(String prefix, String simAction, String doc, ArgSpec... args) {
        return new ActionSpec(prefix + camel(simAction), simAction, List.of(args), doc);
    }

    static String camel(String snake) {
        StringBuilder sb = new StringBuilder();
        for (String part : snake.split("_")) {
            sb.append(Character.toUpperCase(part.charAt(0))).append(part.substring(1));
        }
        return sb.toString();
    }
}

package org.kicnp.robots;

import org.kicnp.core.Frame;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * What one simulated robot is to the platform: its name (the agent's and the simulator's), a line about it, and
 * the actions it offers. The four robots of the paper are in {@link RobotModels}.
 */
public record RobotModel(String name, String description, List<ActionSpec> actions) {
    public RobotModel {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(description, "description");
        actions = List.copyOf(actions);
    }

    /** The action a platform command names, by its frame name ({@code ScoutGoTo}) or its simulator name ({@code go_to}). */
    public Optional<ActionSpec> action(String commandAction) {
        return actions.stream()
                .filter(a -> a.frameName().equals(commandAction) || a.simAction().equals(commandAction))
                .findFirst();
    }

    /** The frames to register: the common root {@code RobotAction}, then one class per action. */
    public List<Frame> capabilityFrames() {
        List<Frame> frames = new ArrayList<>();
        frames.add(ActionSpec.rootFrame());
        for (ActionSpec a : actions) {
            frames.add(a.toFrame(name));
        }
        return List.copyOf(frames);
    }
}

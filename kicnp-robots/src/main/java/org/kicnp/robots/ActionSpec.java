package org.kicnp.robots;

import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * One thing a robot can do: the name of its capability frame on the platform ({@code ScoutGoTo}), the simulator
 * action it becomes ({@code go_to}), and its arguments. {@link #toFrame} is the frame the agent registers;
 * {@link #toArgs} is the paper's "instruction converted to the command of the local control program".
 */
public record ActionSpec(String frameName, String simAction, List<ArgSpec> args, String doc) {
    /** The root class of every capability frame; each action frame says which robot and simulator action it is. */
    public static final String ROOT = "RobotAction";

    public ActionSpec {
        Objects.requireNonNull(frameName, "frameName");
        Objects.requireNonNull(simAction, "simAction");
        args = List.copyOf(args);
        Objects.requireNonNull(doc, "doc");
    }

    /** The root class frame of all capability frames: the slots {@code robot} and {@code command}. */
    public static Frame rootFrame() {
        return Frame.classFrame(ROOT).root()
                .slot(Slot.builder("robot", DataType.STRING).role("the robot that performs the action").build())
                .slot(Slot.builder("command", DataType.STRING).role("the simulator action it becomes").build())
                .slot(Slot.builder("doc", DataType.STRING).role("what the action does").build())
                .build();
    }

    /** The capability frame: a class below {@link #ROOT} with one slot per argument, required ones marked. */
    public Frame toFrame(String robot) {
        Frame.Builder b = Frame.classFrame(frameName).parent(ROOT)
                .slot(Slot.ofValue("robot", DataType.STRING, Value.of(robot)))
                .slot(Slot.ofValue("command", DataType.STRING, Value.of(simAction)))
                .slot(Slot.ofValue("doc", DataType.STRING, Value.of(doc)));
        for (ArgSpec a : args) {
            Slot.Builder s = Slot.builder(a.name(), a.type()).required(a.required()).role("argument");
            if (a.type() == DataType.LIST) {
                s.argument(DataType.STRING.xmlName());
            }
            b.slot(s.build());
        }
        return b.build();
    }

    /** Converts a platform command's text arguments, refusing unknown and missing ones with a full sentence. */
    public Map<String, Object> toArgs(Map<String, String> given) {
        Map<String, Object> out = new LinkedHashMap<>();
        for (String name : given.keySet()) {
            if (args.stream().noneMatch(a -> a.name().equals(name))) {
                throw new IllegalArgumentException("Action " + frameName + " has no argument '" + name + "'; it takes "
                        + args.stream().map(ArgSpec::name).toList() + ".");
            }
        }
        for (ArgSpec a : args) {
            String text = given.get(a.name());
            if (text == null) {
                if (a.required()) {
                    throw new IllegalArgumentException("Action " + frameName + " needs the argument '" + a.name() + "'.");
                }
                continue;
            }
            out.put(a.name(), a.parse(frameName, text));
        }
        return out;
    }
}

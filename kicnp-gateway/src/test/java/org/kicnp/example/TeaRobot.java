package org.kicnp.example;

import java.util.List;
import org.kicnp.agent.ActionHandle;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message.Command;

/** A complete K-ICNP robot agent: Scout, who brings a cup of tea (the scenario of the paper's Table 5). */
public final class TeaRobot extends AgentBase {

    public TeaRobot(AgentOptions options) {
        super(options);
    }

    /** What Scout can do, told to the platform as frames each time it registers. */
    @Override protected List<Frame> capabilities() {
        return List.of(Frame.classFrame("BringTea")
                .slot(Slot.builder("item", DataType.STRING).defaultValue(Value.of("tea")).build())
                .build());
    }

    /** One command from the platform or a user agent; report how it goes through the handle. */
    @Override protected void onCommand(Command command, ActionHandle action) {
        if (!command.action().equals("bring")) {
            action.failed("Scout cannot '" + command.action() + "'.");
            return;
        }
        String item = command.args().getOrDefault("item", "tea");
        action.started();
        for (int leg = 1; leg <= 3; leg++) {
            driveLeg(leg);
            action.progress(leg / 3.0, "leg " + leg + " of 3");
            sensor("sonar", Value.of(1.5 / leg)); // distance to the user in metres, for slot conditions
        }
        action.ended("brought a cup of " + item);
    }

    private void driveLeg(int leg) {
        // Scout's local control program moves the robot here (section 3.3).
    }

    /** Runs Scout against a gateway on this machine until the process is stopped. */
    public static void main(String[] args) throws InterruptedException {
        String token = System.getenv().getOrDefault("KICNP_TOKEN", "");
        try (TeaRobot scout = new TeaRobot(AgentOptions.of("127.0.0.1", 7777, "scout", AgentKind.ROBOT, token))) {
            scout.start(); // connects, registers, and reconnects by itself whenever the gateway restarts
            Thread.currentThread().join();
        }
    }
}

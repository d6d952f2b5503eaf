package org.kicnp.robots;

import org.kicnp.agent.AgentOptions;

/**
 * The agent of the simulated Scout (the mobile robot that carries cups): {@link RobotModels#scout()} over the gateway, nothing
 * more.
 */
public final class ScoutAgent extends RobotAgent {
    public ScoutAgent(AgentOptions options, SimWorld world) {
        super(options, signals -> RobotDriver.attach(world, RobotModels.scout(), signals));
    }
}

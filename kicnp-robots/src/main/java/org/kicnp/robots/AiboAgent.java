package org.kicnp.robots;

import org.kicnp.agent.AgentOptions;

/**
 * The agent of the simulated AIBO (the robot dog): {@link RobotModels#aibo()} over the gateway, nothing
 * more.
 */
public final class AiboAgent extends RobotAgent {
    public AiboAgent(AgentOptions options, SimWorld world) {
        super(options, signals -> RobotDriver.attach(world, RobotModels.aibo(), signals));
    }
}

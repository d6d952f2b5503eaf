package org.kicnp.robots;

import org.kicnp.agent.AgentOptions;

/**
 * The agent of the simulated PINO (the biped humanoid): {@link RobotModels#pino()} over the gateway, nothing
 * more.
 */
public final class PinoAgent extends RobotAgent {
    public PinoAgent(AgentOptions options, SimWorld world) {
        super(options, signals -> RobotDriver.attach(world, RobotModels.pino(), signals));
    }
}

/**
 * Playing the paper's Table 5 on the running platform: the simulated world and the four robot agents
 * ({@link org.kicnp.cli.scenario.RobotWorld}), User A played by a script or by a person
 * ({@link org.kicnp.cli.scenario.UserA}), the console that prints what the robots say and do
 * ({@link org.kicnp.cli.scenario.Narrator}) and the checks of a finished run ({@link org.kicnp.cli.scenario.RunRecord}).
 * The scenario itself lives in {@code scenarios/table5/*.xml}: nothing here decides what a robot does.
 */
package org.kicnp.cli.scenario;

/**
 * The simulated robots of the K-ICNP scenario: {@link org.kicnp.robots.SimWorld} runs the Python simulator
 * ({@code robots-sim/}) as a subprocess and speaks its JSON-lines protocol; {@link org.kicnp.robots.RobotDriver}
 * turns platform commands into simulator commands and simulator events into feedback and sensor signals for one
 * robot; {@link org.kicnp.robots.FaceRecognizer} is Robovie's eigenface recogniser over the faces stored with the
 * {@code KnownUser} frames.
 */
package org.kicnp.robots;

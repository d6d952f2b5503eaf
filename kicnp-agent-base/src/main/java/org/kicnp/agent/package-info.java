/**
 * The agent SDK, the paper's "Agent Base Classes": a robot developer subclasses {@link org.kicnp.agent.AgentBase}
 * to connect to a K-ICNP gateway, authenticate, register the robot's capabilities as frames, take commands through
 * {@link org.kicnp.agent.ActionHandle}s, report sensor signals, use the knowledge base, relay and subscribe. It
 * reconnects by itself after a server restart. Blocking socket I/O on virtual threads; see {@code docs/agents.md}.
 */
package org.kicnp.agent;

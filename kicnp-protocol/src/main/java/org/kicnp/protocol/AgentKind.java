package org.kicnp.protocol;

/** What an agent stands for: the paper's robot and user agents, other software agents, and other K-ICNP servers. */
public enum AgentKind {
    /** Represents one robot under control and executes its commands. */
    ROBOT,
    /** Represents a user: relays the user's commands and queries the robots' states. */
    USER,
    /** Any other software agent, such as the paper's sentence parser or a room camera. */
    SERVICE,
    /** Another K-ICNP server exchanging knowledge with this one. */
    PEER
}

"""The K-ICNP agent SDK for Python: a robot's or a tool's connection to a K-ICNP gateway, standard library only.

The counterpart of the Java SDK (module kicnp-agent-base): :class:`Agent` connects, authenticates, registers,
runs commands with :class:`ActionHandle` feedback, reports sensor signals, queries the knowledge base, relays and
subscribes, and reconnects by itself. See README.md beside this package, and docs/protocol.md for the wire.
"""
from .actions import ActionHandle, CommandTicket
from .agent import Agent
from .errors import (ActionFailedError, AgentError, AgentTimeoutError, AuthenticationError, NotConnectedError,
                     ProtocolError, RequestRefusedError)
from .frames import Frame, frame_xml
from .messages import (BindingOutcome, Changed, Command, Feedback, NotFired, ProofNode, Reason, Ref, Relay,
                       SlotCandidates, Snapshot)
from .options import AgentKind, AgentOptions

__all__ = ["ActionFailedError", "ActionHandle", "Agent", "AgentError", "AgentKind", "AgentOptions",
           "AgentTimeoutError", "AuthenticationError", "BindingOutcome", "Changed", "Command", "CommandTicket",
           "Feedback", "Frame", "NotConnectedError", "NotFired", "ProofNode", "ProtocolError", "Reason", "Ref",
           "Relay", "RequestRefusedError", "SlotCandidates", "Snapshot", "frame_xml"]

"""The SDK's errors: one base, one subclass per way a call can fail, as in the Java SDK (org.kicnp.agent)."""


class AgentError(Exception):
    """Base of every error the SDK raises, so a robot's loop can catch them all in one place."""


class AuthenticationError(AgentError):
    """The server refused the agent (wrong token, kind not allowed) or replaced it by a newer connection.

    The agent stops for good: retrying with the same token would be refused again.
    """


class NotConnectedError(AgentError):
    """The agent is not connected right now (it is reconnecting, or was closed); nothing was sent.

    A sensing loop catches this and goes on with its next reading.
    """


class AgentTimeoutError(AgentError):
    """No answer (or no registration, or no end of a command) came within the time allowed."""


class RequestRefusedError(AgentError):
    """The server answered a request with an ``error``; ``code`` is the protocol's error code (``rejected``, ...)."""

    def __init__(self, code, message):
        super().__init__(message)
        self.code = code


class ActionFailedError(AgentError):
    """A command this (user) agent sent ended with ``failed``; the message is the robot's reason."""


class ProtocolError(AgentError):
    """The server sent bytes that are not a K-ICNP message; the connection is dropped and made again."""

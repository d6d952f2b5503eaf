"""How an agent connects: where, as whom, and its timing (org.kicnp.agent.AgentOptions in the Java SDK)."""
import enum
import re
from dataclasses import dataclass
from typing import Optional

from .wire import DEFAULT_MAX_FRAME_BYTES, check_lengths

_NAME = re.compile(r"[^\W\d][\w-]*\Z")


class AgentKind(str, enum.Enum):
    """What an agent is to the hub (the ``kind`` of ``hello``): the server's agent file says which kinds a name may be."""
    ROBOT = "robot"
    USER = "user"
    SERVICE = "service"
    PEER = "peer"


@dataclass(frozen=True)
class AgentOptions:
    """Where and how to connect. Times are in seconds.

    The defaults are the Java SDK's: 10 s request timeout, a heartbeat after 5 s without sending, server silence
    tolerated for 40 s (above the server's heartbeat interval, a third of its 30 s timeout), reconnect backoff from
    0.1 s doubling to 5 s with jitter, 1 MiB frames, plain TCP. ``tls_trust`` names the server's certificate (PEM,
    as ``keytool -exportcert -rfc`` writes it, docs/deployment.md): the agent then speaks TLS and trusts exactly that
    certificate, checked against ``host`` (or ``tls_server_name``).
    """
    name: str
    token: str
    kind: AgentKind = AgentKind.ROBOT
    host: str = "127.0.0.1"
    port: int = 7777
    tls_trust: Optional[str] = None
    tls_server_name: Optional[str] = None
    request_timeout: float = 10.0
    heartbeat_interval: float = 5.0
    server_silence: float = 40.0
    backoff_initial: float = 0.1
    backoff_max: float = 5.0
    max_frame_bytes: int = DEFAULT_MAX_FRAME_BYTES

    def __post_init__(self):
        check_lengths("AgentOptions", name=self.name)
        if not isinstance(self.name, str) or not _NAME.match(self.name):
            raise ValueError("Agent name %r is not a name: letters, digits, '_' and '-', starting with a letter or '_'."
                             % (self.name,))
        if not isinstance(self.token, str):
            raise TypeError("The token of agent '%s' must be a str, not %s." % (self.name, type(self.token).__name__))
        object.__setattr__(self, "kind", AgentKind(self.kind))
        if not 0 <= self.port <= 65535:
            raise ValueError("Port %d of agent '%s' is not between 0 and 65535." % (self.port, self.name))
        for field in ("request_timeout", "heartbeat_interval", "server_silence", "backoff_initial", "backoff_max"):
            if getattr(self, field) <= 0:
                raise ValueError("Option %s of agent '%s' must be above 0 seconds, not %r."
                                 % (field, self.name, getattr(self, field)))
        if self.backoff_max < self.backoff_initial:
            raise ValueError("Option backoff_max of agent '%s' (%r s) is below backoff_initial (%r s)."
                             % (self.name, self.backoff_max, self.backoff_initial))
        if self.max_frame_bytes < 1024:
            raise ValueError("Option max_frame_bytes of agent '%s' is %d, below 1024." % (self.name, self.max_frame_bytes))

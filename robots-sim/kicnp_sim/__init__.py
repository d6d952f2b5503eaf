"""kicnp_sim: a headless, deterministic robot simulator for K-ICNP.

It simulates the room of the K-ICNP paper's scenario (Table 5) with its four robots (Scout,
Robovie, PINO, AIBO), users with faces, and cups of tea and coffee, and is driven over a
JSON-lines protocol on stdin/stdout (see PROTOCOL.md).
"""

__version__ = "0.1.0"
PROTOCOL_VERSION = "kicnp-sim/1"

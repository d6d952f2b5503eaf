"""The four robots of the K-ICNP scenario, in the order of Table 5."""

from .aibo import Aibo
from .base import Robot
from .pino import Pino
from .robovie import Robovie
from .scout import Scout

ROBOT_CLASSES: dict[str, type[Robot]] = {"robovie": Robovie, "pino": Pino, "scout": Scout, "aibo": Aibo}

__all__ = ["Aibo", "Pino", "Robot", "Robovie", "Scout", "ROBOT_CLASSES"]

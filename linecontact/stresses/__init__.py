"""Subsurface stresses (being split into modules of one concern)."""
import importlib as _importlib

from .search import __all__  # noqa: F401
from .search import *  # noqa: F401,F403


def __getattr__(name):
    return getattr(_importlib.import_module(".search", __name__), name)

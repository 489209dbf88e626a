"""Tangential contact (being split into modules of one concern)."""
import importlib as _importlib

from .contact import __all__  # noqa: F401
from .contact import *  # noqa: F401,F403


def __getattr__(name):
    return getattr(_importlib.import_module(".contact", __name__), name)

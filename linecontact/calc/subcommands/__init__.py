"""The subcommands of ``linecontact`` besides ``calc`` (see
:class:`linecontact.calc.feature.Subcommand` for the shape of one and how to add one).
:data:`SUBCOMMANDS` is the one registration point: each module becomes ``linecontact
NAME`` with its options, CSV batch, JSON, ``--plot`` and DataFrame
(:mod:`linecontact.calc.command`)."""
from . import bearing

__all__ = ["SUBCOMMANDS"]

SUBCOMMANDS = (bearing,)

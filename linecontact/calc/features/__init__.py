"""The calculator's features (see :mod:`linecontact.calc.feature` for the shape of one
and how to add one). :data:`FEATURES` is the one registration point: its order is the
order of the ``--help`` sections, of the rules and of the output columns."""
from . import raceways, roller, tangential, viscoelastic

__all__ = ["FEATURES"]

FEATURES = (raceways, roller, tangential, viscoelastic)

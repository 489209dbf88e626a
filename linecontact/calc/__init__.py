"""The calculator behind ``linecontact calc``: a layer above the library (nothing in
:mod:`linecontact` imports it) that parses options and CSV batches, evaluates the
library on whole arrays of cases and renders tables, CSV and JSON. It holds no physics.

Modules: :mod:`.cli` (argument parsing, dispatch), :mod:`.feature` (the plug-in shape
of a feature, and how to add one), :mod:`.cases` (the core parameters and one resolve
loop over the features), :mod:`.compute` (model evaluation; asks each active feature for
its columns), :mod:`.render` (table, JSON, CSV), :mod:`.batch` (CSV files),
:mod:`.features` (raceways, roller, tangential, viscoelastic, ...).
"""

__all__: list = []

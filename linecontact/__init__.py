"""linecontact: stiffness and deflection of a finite rigid cylinder on an elastic half-space.

A rigid cylinder (radius R, length L) lies on its side on an elastic half-space of
effective modulus E* and is pressed in by a depth d. This package gives F(d), d(F) and
the contact stiffness k = dF/dd from the Li & Popov (2017) MDR model, the classical
closed forms it is compared with, and the BEM-tabulated universal curve (the default
model; docs/theory.md, section 'Self-similarity'). SI units in and out (m, N, Pa);
everything is vectorised over numpy arrays. Each model states its error against the BEM
(``model.measured_error``, from tables/model_accuracy.csv).

Layers, each importing only from the layers before it (and the helpers below):

- formulas: :mod:`~linecontact.classical` (Eq. 1-4, Kunz, Palmgren, ISO 16281),
  :mod:`~linecontact.lipopov` (Eq. 7-12), :mod:`~linecontact.mdr` (general MDR
  transforms), :mod:`~linecontact.hertz` (elliptical point contact),
  :mod:`~linecontact.universal` (the universal curve), :mod:`~linecontact.profiles`
  (roller profiles);
- models: :mod:`~linecontact.models`, one interface for every straight-roller law;
- what follows from a normal contact of any model: :mod:`~linecontact.stresses`
  (subsurface stresses, case-hardening check), :mod:`~linecontact.tangential` (stick,
  partial slip, fretting), :mod:`~linecontact.adhesion` and
  :mod:`~linecontact.viscoelastic`;
- roller / raceway / contact: :mod:`~linecontact.roller` (profiled rollers by coupled
  slices), :mod:`~linecontact.raceway` (a roller between two raceways),
  :mod:`~linecontact.contact` (one contact from its parts: the front door);
- :mod:`~linecontact.bearing` (radial roller bearings: load distribution, stiffness,
  rating life);
- the calculator, :mod:`linecontact.calc` (the command line and batches; no physics of
  its own, and nothing in the library imports it).

Helpers every layer uses: :mod:`~linecontact.errors` (the input errors, e.g.
:class:`OutOfRangeError`), :mod:`~linecontact.checks` (validity ranges as
:class:`Interval` data and the checks that enforce them), :mod:`~linecontact.tables`
(the shipped data).

Examples
--------
Steel on steel, R = 5 mm, L = 10 mm, 1 kN:

>>> import linecontact as lc
>>> estar = lc.effective_modulus(210e9, 0.3, 210e9, 0.3)
>>> d = lc.depth(1e3, 5e-3, 10e-3, estar, model="li-popov")
>>> f"{d * 1e6:.2f} um"
'3.05 um'
>>> f"{lc.stiffness(d, 5e-3, 10e-3, estar, model='puttock-thwaite'):.3e} N/m"
'3.209e+08 N/m'
"""
from __future__ import annotations

import importlib as _importlib

# Names re-exported from the submodules, imported on first use (PEP 562), so that
# `import linecontact` (and the CLI) loads only what a computation needs: a one-case
# call never pays for scipy.integrate (mdr) or the models it does not evaluate.
_LAZY = {
    "classical": ("effective_modulus", "hertz_half_width", "iso16281_depth",
                  "johnson_depth", "kunz_force", "palmgren_depth",
                  "puttock_thwaite_depth", "puttock_thwaite_force",
                  "puttock_thwaite_stiffness"),
    "lipopov": ("lipopov_coefficients", "lipopov_depth", "lipopov_force",
                "lipopov_profile", "lipopov_stiffness"),
    "mdr": ("mdr_contact_radius", "mdr_force", "mdr_profile_from_force",
            "mdr_profile_from_stiffness", "mdr_stiffness"),
    "models": ("DEFAULT_MODEL", "MODELS", "ContactModel", "get_model", "register",
               "standard_models"),
    "checks": ("Interval",),
    "errors": ("OutOfRangeError",),
}
_ORIGIN = {name: module for module, names in _LAZY.items() for name in names}


def _installed_version():
    """The installed distribution's version, or '0+unknown' in a bare source checkout.

    Read on first access of ``linecontact.__version__`` only: importlib.metadata scans
    the environment's distributions, which a one-case calculation need not pay for.
    """
    from importlib.metadata import PackageNotFoundError, version
    try:
        return version("linecontact")
    except PackageNotFoundError:
        return "0+unknown"


def __getattr__(name):
    if name == "__version__":
        value = globals()["__version__"] = _installed_version()
        return value
    module = _ORIGIN.get(name)
    if module is None:
        raise AttributeError(f"module 'linecontact' has no attribute {name!r}")
    value = getattr(_importlib.import_module(f".{module}", __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_ORIGIN) | {"__version__"})


__all__ = [
    "__version__",
    "force",
    "depth",
    "stiffness",
    "effective_modulus",
    "get_model",
    "standard_models",
    "register",
    "ContactModel",
    "MODELS",
    "DEFAULT_MODEL",
    "OutOfRangeError",
    "Interval",
    "hertz_half_width",
    "puttock_thwaite_depth",
    "puttock_thwaite_force",
    "puttock_thwaite_stiffness",
    "johnson_depth",
    "kunz_force",
    "palmgren_depth",
    "iso16281_depth",
    "lipopov_coefficients",
    "lipopov_profile",
    "lipopov_force",
    "lipopov_depth",
    "lipopov_stiffness",
    "mdr_contact_radius",
    "mdr_force",
    "mdr_stiffness",
    "mdr_profile_from_force",
    "mdr_profile_from_stiffness",
]


def force(depth, radius, length, estar, model=None, **options):
    return _model(model, radius, length, estar, options).force(depth)


def depth(force, radius, length, estar, model=None, **options):
    return _model(model, radius, length, estar, options).depth(force)


def stiffness(depth, radius, length, estar, model=None, **options):
    return _model(model, radius, length, estar, options).stiffness(depth)


# The three one-liners share their parameters; one template documents them.
_ONE_LINER_DOC = """{summary}

    The model's own law (:class:`~linecontact.models.ContactModel`), vectorised over
    `{given}`.

    Parameters
    ----------
    {given} : float or array_like
        {given_text}
    radius : float
        Cylinder radius R, 0 < R < inf [m].
    length : float
        Cylinder length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].
    model : str, optional
        A key of :data:`MODELS`; None (default): :data:`DEFAULT_MODEL`, the universal
        curve.
    **options
        Passed to the model, e.g. ``coefficients="eq11"`` or ``c=0.72``.

    Returns
    -------
    float or ndarray
        {returns}

    Notes
    -----
    Valid where the chosen model is: each model states its range of L/R, E* and
    depth, and raises :class:`~linecontact.errors.OutOfRangeError` outside it.

    Examples
    --------
    {example}
    """
force.__doc__ = _ONE_LINER_DOC.format(
    summary="Normal force F [N] of a cylinder at depth d on an elastic half-space.",
    given="depth", given_text="Indentation depth d, 0 < d < inf [m].", returns="F [N].",
    example='>>> round(force(3.0548e-6, 5e-3, 10e-3, 115.38e9, model="li-popov"))\n    1000')
depth.__doc__ = _ONE_LINER_DOC.format(
    summary="Depth d [m] of a cylinder under a normal force F on an elastic half-space.",
    given="force", given_text="Normal force F, 0 < F < inf [N].", returns="d [m].",
    example=">>> f\"{depth(1e3, 5e-3, 10e-3, 115.38e9, model='palmgren') * 1e6:.2f} um\"\n"
            "    '3.05 um'")
stiffness.__doc__ = _ONE_LINER_DOC.format(
    summary="Contact stiffness k = dF/dd [N/m] of a cylinder at depth d.",
    given="depth", given_text="Indentation depth d, 0 < d < inf [m].", returns="k [N/m].",
    example=">>> f\"{stiffness(3.0548e-6, 5e-3, 10e-3, 115.38e9, model='li-popov'):.3e}\"\n"
            "    '3.570e+08'")


def _model(key, radius, length, estar, options):
    from .models import DEFAULT_MODEL, get_model
    return get_model(DEFAULT_MODEL if key is None else key, radius, length, estar,
                     **options)

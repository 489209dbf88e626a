"""The stresses of a whole roller between two raceways: each contact's, the worse, the case.

A roller between raceways (:func:`linecontact.raceway.roller_between_raceways`) has two
contacts, each carrying the roller load: the inner one (the roller on the inner
raceway, effective radius R1 Ri/(Ri + R1)) and the outer one (R1 Ro/(Ro - R1)). Each is
a contact of its own below its raceway; its stress maxima are those of its slices
(:func:`~linecontact.stresses.roller_stresses`, the worst 3D-corrected) where it was
solved by slices, else the plane-strain Hertz strip of its effective radius at the
mean line load F/L (:func:`~linecontact.stresses.line_contact_stresses`; Johnson 1985,
sections 4.2 and 7.2). The roller's maxima are, per measure, the larger of the two
contacts' (the contact named); the case-hardening check
(:func:`~linecontact.stresses.case_check`) is made on each contact, the worse being
the larger stress/allowable ratio, and the case depth that carries the roller is the
larger of the two contacts' minima. A maximum not converged in a contact (an
edge-loaded one: the slice width's number, ``withheld``) is not reported, and neither
is the case check then. This is the one rule of ``linecontact calc --stresses`` with
raceways and of :class:`linecontact.bearing.RadialRollerBearing` (its most loaded
roller; docs/stresses.md, docs/bearings.md).

References
----------
.. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   4.2 and 7.2.
.. [2] T. A. Harris, M. N. Kotzalas, Essential Concepts of Bearing Technology, 5th ed.,
   CRC Press (2006), chapter 6 (the two contacts of a roller and their radii).
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import SimpleNamespace

from ..errors import OutOfRangeError
from .along_roller import line_contact_stresses, roller_stresses
from .hardening import case_check
from .measures import MEASURES

__all__ = ["RacewayStresses", "RacewayCaseCheck", "raceway_stresses", "noted_case_check",
           "NO_CASE_DEPTH", "NO_CASE_NEEDED"]

#: The note of a case check whose stress exceeds even the surface hardness's allowable.
NO_CASE_DEPTH = ("CHD min: none, the stress exceeds the allowable of the surface "
                 "hardness itself")
#: The note of a case check the core hardness alone passes.
NO_CASE_NEEDED = "CHD min: 0, none needed (the core hardness carries the load)"

SIDES = ("inner", "outer")


def raceway_stresses(solution, length, estar, profile=None, friction=0.0, poisson=0.3):
    """Subsurface stresses of a whole roller's two contacts, each measure's worse.

    Parameters
    ----------
    solution : RacewaySolution
        One roller between raceways at one load
        (:func:`linecontact.raceway.roller_between_raceways`; scalar force).
    length : float
        Roller length L [m] (the strip's mean line load F/L under a law; the measured
        range of a slice solution's note).
    estar : float
        Effective modulus E* [Pa].
    profile : object, optional
        The roller's axial profile as the roller model took it (for the slice
        solutions' note: checked against the measured range as a roller of each
        contact's effective radius).
    friction : float, optional
        Coefficient mu of the sliding traction, 0 <= mu <= 1 [-].
    poisson : float, optional
        Poisson's ratio of the stressed body, 0 <= nu <= 0.5 [-].

    Returns
    -------
    RacewayStresses
        ``"inner"`` and ``"outer"`` -> :class:`~linecontact.stresses.SubsurfaceStresses`,
        with each measure's worse contact and the case check over both.

    Notes
    -----
    Valid as the contact model of the solution (slices: b << R, |theta| < 0.1 rad;
    a law: the plane-strain strip, no end effect).

    Examples
    --------
    >>> from linecontact.raceway import Raceways, roller_between_raceways
    >>> sol = roller_between_raceways(5e-3, 10e-3, 115.38e9, Raceways(20e-3, 30e-3),
    ...                               force=1e3)
    >>> s = raceway_stresses(sol, 10e-3, 115.38e9)
    >>> w = s.worst["tresca"]
    >>> f"{w['value'] / 1e6:.0f} MPa, {w['contact']} contact"
    '288 MPa, inner contact'
    """
    parts = {}
    for side in SIDES:
        part = getattr(solution, side)
        R = float(getattr(solution, f"radius_{side}"))
        if part is not None:
            measured = SimpleNamespace(radius=R, length=length, estar=estar,
                                       profile=profile)
            parts[side] = roller_stresses(part, friction, poisson, roller=measured)
        else:
            parts[side] = line_contact_stresses(float(solution.force), R, length, estar,
                                                friction, poisson)
    return RacewayStresses(**parts)


@dataclass(frozen=True)
class RacewayStresses(Mapping):
    """The stresses of a roller's two contacts: ``"inner"``, ``"outer"`` -> each one's.

    Returned by :func:`raceway_stresses`; not built by hand. A mapping of the contact
    name to its :class:`~linecontact.stresses.SubsurfaceStresses`.

    Parameters
    ----------
    inner, outer : SubsurfaceStresses
        The inner and the outer contact's stresses.

    Notes
    -----
    Valid as the two contacts' stresses it holds.

    Examples
    --------
    >>> from linecontact.raceway import Raceways, roller_between_raceways
    >>> sol = roller_between_raceways(5e-3, 10e-3, 115.38e9, Raceways(20e-3, 30e-3),
    ...                               force=1e3)
    >>> sorted(raceway_stresses(sol, 10e-3, 115.38e9))
    ['inner', 'outer']
    """

    inner: object
    outer: object

    def __getitem__(self, side):
        if side not in SIDES:
            raise KeyError(side)
        return getattr(self, side)

    def __iter__(self):
        return iter(SIDES)

    def __len__(self):
        return len(SIDES)

    @property
    def withheld(self):
        """Contact -> {measure: why its maximum is not reported}, for the contacts
        with a maximum not converged (edge loaded); empty if none."""
        return {k: st.withheld for k, st in self.items() if st.withheld}

    @property
    def worst(self):
        """Measure -> {"value" [Pa], "depth" [m], "x" [m], "contact"}: the larger of
        the two contacts' maxima (the inner one on a tie), with "withheld" (why) where
        that measure's maximum is not converged in some contact (then not reported)."""
        worst = {}
        for m in MEASURES:
            name, st = max(self.items(), key=lambda kv: kv[1].worst[m]["value"])
            w = st.worst[m]
            worst[m] = {"value": float(w["value"]), "depth": float(w["z"]),
                        "x": float(w["x"]), "contact": name}
            held = [n for n, f in self.items() if m in getattr(f, "withheld", {})]
            if held:
                worst[m]["withheld"] = (" and ".join(held) + " contact: "
                                        + self[held[0]].withheld[m])
        return worst

    @property
    def notes(self):
        """Each contact's notes (its measured accuracy), named, and what is withheld."""
        worst = self.worst
        notes = []
        for name, st in self.items():
            notes.extend(f"stress ({name} contact): {t}" for t in st.notes)
        held = sorted(m for m in MEASURES if "withheld" in worst[m])
        if held:
            notes.append("stress maxima not reported (" + ", ".join(held) + "): "
                         + worst[held[0]]["withheld"])
        return notes

    def case_check(self, hardness):
        """The case-hardening check of both contacts (:func:`case_check` of each, von
        Mises) against `hardness` (:class:`~linecontact.stresses.HardnessProfile`).

        Returns
        -------
        RacewayCaseCheck
            Each contact's check, the worse and the case depth for both; not made
            (no checks, the reason in the notes) where a maximum is withheld.
        """
        held = self.withheld
        if held:
            return RacewayCaseCheck({}, ("case check not reported: " + "; ".join(
                f"{k} contact: {next(iter(h.values()))}" for k, h in held.items()),),
                None)
        checks, texts = {}, []
        for side, st in self.items():
            c, text = noted_case_check(st, hardness)
            checks[side] = c
            if text:
                texts.append(f"{side}: {text}")
        done = {k: c for k, c in checks.items() if c is not None}
        worse = max(done, key=lambda k: done[k].max_ratio) if done else None
        return RacewayCaseCheck(checks, tuple(texts), worse)


@dataclass(frozen=True)
class RacewayCaseCheck:
    """The case-hardening check of a roller's two contacts.

    Returned by :meth:`RacewayStresses.case_check`; not built by hand.

    Parameters
    ----------
    checks : dict
        Contact -> its :class:`~linecontact.stresses.CaseCheck`, None where it could
        not be made (the notes say why); empty where a maximum is withheld.
    notes : tuple of str
        What to say beside the ratios (no case depth, none needed, not made: why).
    worse : str or None
        The contact of the larger stress/allowable ratio (None if neither was made).

    Notes
    -----
    Valid as the two contacts' stresses and the hardness profile.

    Examples
    --------
    >>> from linecontact.raceway import Raceways, roller_between_raceways
    >>> from linecontact.stresses import HardnessProfile
    >>> sol = roller_between_raceways(5e-3, 10e-3, 115.38e9, Raceways(20e-3, 30e-3),
    ...                               force=1e3)
    >>> c = raceway_stresses(sol, 10e-3, 115.38e9).case_check(
    ...     HardnessProfile(700.0, 0.3e-3, 350.0))
    >>> c.worse
    'inner'
    """

    checks: dict
    notes: tuple
    worse: object

    @property
    def min_case_depth(self):
        """The smallest case depth that carries both contacts: the larger of their
        minima (None if either has none or none was checked) [m]."""
        need = [c.min_case_depth for c in self.checks.values() if c is not None]
        if not need or any(d is None for d in need):
            return None
        return max(need)


def noted_case_check(stresses, hardness):
    """The case-hardening check of one contact's stresses with the note a result shows.

    Parameters
    ----------
    stresses : SubsurfaceStresses
        One contact's subsurface stresses (:func:`roller_stresses` or
        :func:`line_contact_stresses`).
    hardness : HardnessProfile
        The part's hardness against depth.

    Returns
    -------
    check : CaseCheck or None
        :func:`case_check` of `stresses` against `hardness`; None where the check
        refused (the hardness or the stresses outside its range).
    note : str
        The refusal's message; :data:`NO_CASE_DEPTH` where no case depth suffices (a
        case given by its depth); :data:`NO_CASE_NEEDED` where the core alone carries
        the load; else "".

    Examples
    --------
    >>> from linecontact.stresses import HardnessProfile, line_contact_stresses
    >>> light = line_contact_stresses(1e3, 5e-3, 10e-3, 115.38e9)
    >>> check, note = noted_case_check(light, HardnessProfile(700.0, 1e-3, 350.0))
    >>> check.min_case_depth, note
    (0.0, 'CHD min: 0, none needed (the core hardness carries the load)')
    """
    try:
        c = case_check(stresses, hardness)
    except OutOfRangeError as exc:
        return None, str(exc)
    if c.min_case_depth is None and hardness.case_depth is not None:
        return c, NO_CASE_DEPTH
    if c.min_case_depth == 0.0:
        return c, NO_CASE_NEEDED
    return c, ""

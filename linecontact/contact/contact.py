"""The facade :class:`Contact`: one roller contact composed of its parts
(:mod:`linecontact.contact.parts`), every output computed by the library's models and
returned as :mod:`linecontact.contact.results` (the package docstring describes it).
"""
from __future__ import annotations

import math

import numpy as np

from ..models import DEFAULT_SLICE_MODEL, SLICE_MODELS, ContactModel
from ..profiles import CircularCrownProfile, as_profile
from ..raceway import DEFAULT_STRAIGHT_MODEL, Raceways, roller_between_raceways
from ..errors import CombinationError, OutOfRangeError, UnknownNameError
from .._numerics import out
from ..checks import check_positive
from .parts import FREE, Concave, Convex, Elastic, Flat, Roller, Viscoelastic
from .results import ContactResult, CreepResult, TangentialResult

__all__ = ["Contact"]

#: Law used for a straight, aligned roller when no model is named.
DEFAULT_LAW = DEFAULT_STRAIGHT_MODEL
#: Model used for a profiled or tilted roller when no model is named.
DEFAULT_SLICES = DEFAULT_SLICE_MODEL


# --------------------------------------------------------------------------------------
# a slice model as a contact law in the approach (for the tangential and creep laws)
# --------------------------------------------------------------------------------------
class _ApproachLaw(ContactModel):
    """F(e) of a slice-solved roller at a fixed tilt, e = depth - first-contact depth, so
    that F(0) = 0 as the MDR and Lee-Radok laws take it (not registered)."""

    key = "approach-law"

    def __init__(self, roller, tilt, solver):
        super().__init__(roller.radius, roller.length, roller.estar)
        self.roller, self.tilt, self.solver = roller, tilt, solver
        self.d0 = roller.first_contact_depth(tilt)

    @property
    def label(self):
        return f"{self.solver} (tilt {self.tilt:g} rad), approach from first contact"

    @property
    def provenance(self):
        return {"model": self.label}

    def _each(self, values, fn):
        v = np.asarray(values, dtype=float)
        return out(np.array([fn(float(e)) for e in v.ravel()]).reshape(v.shape))

    def force(self, depth):
        return self._each(depth, lambda e: self.roller.at_depth(self.d0 + e,
                                                                self.tilt).force)

    def depth(self, force):
        return self._each(force, lambda f: self.roller.at_force(f, self.tilt).depth
                          - self.d0)

    def stiffness(self, depth):
        return self._each(depth, lambda e: self.roller.at_depth(self.d0 + e,
                                                                self.tilt).stiffness)


def _split(sol):
    """A RacewaySolution over an array of loads as one RacewaySolution per load."""
    from dataclasses import fields, replace

    arrays = {f.name: np.asarray(getattr(sol, f.name)) for f in fields(sol)
              if isinstance(getattr(sol, f.name), np.ndarray)}
    shape = np.shape(sol.force)
    return tuple(replace(sol, **{k: float(v[idx]) for k, v in arrays.items()})
                 for idx in np.ndindex(*shape))


# --------------------------------------------------------------------------------------
class Contact:
    """A roller against a counter-body, of given materials: every output of the contact.

    Parameters
    ----------
    roller : Roller
        The roller (radius, length, profile, tilt).
    counterbody : Flat or Convex or Concave or Raceways, optional
        The counter-body (default :class:`Flat`).
    material1 : Elastic or Viscoelastic, optional
        The roller's material.
    material2 : Elastic or Viscoelastic, optional
        The counter-body's material (the rings' between raceways).
    estar : float, optional
        The effective modulus E* instead of the two materials (no G*: no tangential
        law) [Pa].
    model : str, optional
        The contact law (a key of :func:`linecontact.models.available_models`); default
        ``"universal"`` for a straight, aligned roller and ``"profiled-roller"``
        (coupled slices) for a profiled or tilted one.
    n_slices : int, optional
        Slices of a slice model (default: the model's) [-].
    **options
        Options of the law (e.g. ``c=0.72`` for Johnson's).

    Raises
    ------
    CombinationError
        A combination not defined: both materials viscoelastic; a profile or tilt with
        a straight-cylinder law; materials and estar together; a concave body or
        raceways that do not fit the roller.
    UnknownNameError
        An unknown model key.

    Attributes
    ----------
    estar : float
        E* [Pa] (instantaneous, E*(0), with a viscoelastic body).
    gstar : float or None
        G* [Pa]; None when the contact was given by estar or is viscoelastic.
    relaxation : PronySeries or None
        E*(t) with a viscoelastic body.
    radius : float or None
        Effective radius of the single contact [m] (None between raceways).
    profile : Profile
        The roller's profile, read.
    tilt : float or str
        The roller's tilt [rad] or ``"free"``.
    model : str
        The model used; ``sliced`` True for a slice model, ``raceways`` True between
        raceways; ``n_slices`` and ``options`` as given.

    Notes
    -----
    Valid within the parts' ranges (0 < R, L, E* < inf, |theta| < 0.1 rad) and the
    model's. With a viscoelastic body the instantaneous modulus E*(0) gives the
    instantaneous response (:meth:`normal`), and its relaxation the histories.

    Examples
    --------
    The crowned cam follower of docs/composition.md (steel on steel):

    >>> steel = Elastic(210e9, 0.3)
    >>> c = Contact(Roller(8e-3, 12e-3, crown_radius=0.3), Convex(25e-3), steel, steel,
    ...             n_slices=40)
    >>> r = c.normal(force=2e3)
    >>> f"{r.depth * 1e6:.2f} um, k {r.stiffness / 1e6:.0f} N/um"
    '13.21 um, k 227 N/um'
    """

    def __init__(self, roller, counterbody=None, material1=None, material2=None, *,
                 estar=None, model=None, n_slices=None, **options):
        from ..classical import effective_modulus
        from ..models import available_models

        if not isinstance(roller, Roller):
            raise OutOfRangeError("roller", repr(roller), "a linecontact.contact.Roller")
        self.roller = roller
        self.counterbody = Flat() if counterbody is None else counterbody
        if not isinstance(self.counterbody, (Flat, Convex, Concave, Raceways)):
            raise OutOfRangeError("counterbody", repr(counterbody),
                                  "Flat(), Convex(R), Concave(R) or Raceways(Ri, Ro)")
        self.raceways = isinstance(self.counterbody, Raceways)
        # materials -> E* (instantaneous), G*, the relaxation of E*
        self.relaxation = None
        self.gstar = None
        if estar is not None:
            if material1 is not None or material2 is not None:
                raise CombinationError({"estar": estar, "material1": repr(material1),
                                        "material2": repr(material2)},
                                       "give the materials or estar, not both")
            self.estar = float(check_positive("estar", estar, "Pa"))
        else:
            if material1 is None or material2 is None:
                raise CombinationError({"material1": repr(material1),
                                        "material2": repr(material2)},
                                       "give both materials (Elastic(math.inf) for a "
                                       "rigid one) or the effective modulus estar")
            self._materials(material1, material2, effective_modulus)
        R1, L = roller.radius, roller.length
        self.profile = as_profile(roller.profile, R1, L, self.estar)
        self.tilt = roller.tilt
        straight = type(self.profile).__name__ == "StraightProfile"
        misaligned = self.raceways and self.counterbody.misalignment != 0.0
        plain = straight and self.tilt in (0.0, FREE) and not misaligned
        self.model = model if model is not None else (DEFAULT_LAW if plain
                                                      else DEFAULT_SLICES)
        if self.model not in available_models():
            raise UnknownNameError("model", self.model, available_models())
        self.sliced = self.model in SLICE_MODELS
        if not self.sliced and not plain:
            raise CombinationError(
                {"model": self.model, "profile": self.profile.label,
                 "tilt": self.tilt},
                "a straight-cylinder law has no profile or tilt; use "
                "model='profiled-roller' (coupled slices)")
        if self.sliced and options:
            raise CombinationError({"model": self.model, "options": sorted(options)},
                                   "a slice model takes no law options")
        self.n_slices = n_slices
        self.options = options
        if self.raceways:
            self.counterbody.check_fit(R1)
            self.radius = None
        else:
            self.radius = self.counterbody.effective_radius(R1)
        self._law = None
        self._slices = None

    def _materials(self, m1, m2, effective_modulus):
        from ..viscoelastic import effective_relaxation

        for name, m in (("material1", m1), ("material2", m2)):
            if not isinstance(m, (Elastic, Viscoelastic)):
                raise OutOfRangeError(name, repr(m), "Elastic(E, nu) or Viscoelastic("
                                                     "relaxation, nu)")
        visco = [isinstance(m, Viscoelastic) for m in (m1, m2)]
        if all(visco):
            raise CombinationError({"material1": "Viscoelastic", "material2":
                                    "Viscoelastic"}, "the correspondence principle is "
                                   "applied here to one viscoelastic body against an "
                                   "elastic one")
        if any(visco):
            v, e = (m1, m2) if visco[0] else (m2, m1)
            self.relaxation = effective_relaxation(v.relaxation, v.poisson, e.modulus,
                                                   e.poisson)
            self.estar = float(self.relaxation.instantaneous)
            self.viscoelastic = "material1" if visco[0] else "material2"
            return
        self.viscoelastic = None
        if math.isinf(m1.modulus) and math.isinf(m2.modulus):
            raise CombinationError({"material1": "rigid", "material2": "rigid"},
                                   "two rigid bodies have no contact stiffness")
        self.estar = 1.0 / (m1.compliance + m2.compliance)
        self.gstar = 1.0 / (m1.shear_compliance + m2.shear_compliance)

    # ---- the models ------------------------------------------------------------------
    def law(self):
        """The normal contact law of a single contact as a
        :class:`~linecontact.models.ContactModel` in the approach (F(0) = 0).

        Returns
        -------
        ContactModel
            The registered law (straight, aligned), or the slice model at this tilt
            with the depth measured from first contact.

        Examples
        --------
        >>> c = Contact(Roller(5e-3, 10e-3), estar=115.38e9)
        >>> c.law().key
        'universal'
        """
        return self._law_for("the contact law")

    def _law_for(self, what):
        if self.raceways:
            raise CombinationError({"counterbody": "Raceways"},
                                   "a whole roller has two contact laws in series; "
                                   "ask normal(), or Contact with Convex/Concave for "
                                   "one contact")
        if self._law is None:
            from ..models import get_model

            if not self.sliced:
                self._law = get_model(self.model, self.radius, self.roller.length,
                                      self.estar, **self.options)
            else:
                tilt = self._fixed_tilt(what)
                self._law = _ApproachLaw(self._slice_roller(), tilt, self.model)
        return self._law

    def _slice_roller(self):
        if self.model != "profiled-roller":
            raise CombinationError({"model": self.model}, "the tangential and creep "
                                   "laws use the coupled-slice model; use "
                                   "model='profiled-roller'")
        return self._solver()

    def _solver(self):
        """The single contact's slice solver (kept: coupled slices start each solve
        from the last)."""
        if self._slices is None:
            from ..roller.solvers import slice_solver

            self._slices = slice_solver(self.model, self.radius, self.roller.length,
                                        self.estar, self.profile, n_slices=self.n_slices)
        return self._slices

    def _fixed_tilt(self, what):
        """The tilt to hold for a law: the given one, or a free tilt that symmetry makes
        zero at every load (a profile with P(-x) = P(x))."""
        if self.tilt != FREE:
            return self.tilt
        from ..profiles import roller_drop

        L = self.roller.length
        x = np.linspace(-L / 2, L / 2, 401)[1:-1]
        P = roller_drop(self.profile, L, x)
        if np.allclose(P, P[::-1], rtol=1e-9, atol=1e-15 * L):
            return 0.0
        raise CombinationError(
            {"tilt": FREE, "profile": self.profile.label},
            f"{what} needs a contact geometry fixed while it is loaded, and the free tilt "
            "of an asymmetric profile changes with the load: give the tilt as a number "
            "(normal(force=F).tilt at your load)")

    # ---- normal ----------------------------------------------------------------------
    def normal(self, *, force=None, depth=None):
        """The normal state at a force or a depth.

        Parameters
        ----------
        force : float or array_like, optional
            Normal force F > 0 [N].
        depth : float or array_like, optional
            Depth at the roller's centre (between raceways: the ring approach), instead
            of `force` [m].

        Returns
        -------
        ContactResult

        Raises
        ------
        CombinationError
            Neither or both of force and depth.

        Notes
        -----
        Valid within the model's range. A law is evaluated on the whole array at once;
        a slice model solves each value.

        Examples
        --------
        >>> c = Contact(Roller(5e-3, 10e-3), estar=115.38e9)
        >>> f"{c.normal(force=1e3).depth * 1e6:.3f} um"
        '3.154 um'
        """
        if (force is None) == (depth is None):
            raise CombinationError({"force": force, "depth": depth},
                                   "give exactly one of force and depth")
        if self.raceways:
            return self._raceways(force, depth)
        if not self.sliced:
            return self._law_normal(force, depth)
        return self._slices_normal(force, depth)

    def _law_normal(self, force, depth):
        from ..classical import hertz_half_width, hertz_peak_pressure

        m = self.law()
        m.check_applicable()
        r = m.evaluate(force=force) if force is not None else m.evaluate(depth=depth)
        F = r["force"]
        zero = out(np.zeros(np.shape(F)))
        why = ({"model": self.model}, "a straight-cylinder law gives F(d), not the load "
               "along the roller; use model='profiled-roller' (coupled slices)")
        return ContactResult(
            force=F, depth=r["depth"], approach=r["depth"], stiffness=r["stiffness"],
            moment=zero, tilt=zero, tilt_stiffness=None, x=None, q=None,
            peak_pressure=hertz_peak_pressure(F, self.radius, self.roller.length,
                                              self.estar),
            half_width=hertz_half_width(F, self.radius, self.roller.length, self.estar),
            model=self.model,
            reasons={"tilt_stiffness": (why[0], "a straight-cylinder law has no tilt "
                                        "stiffness; use model='profiled-roller'"),
                     "x": why, "q": why})

    def _solve_one(self, force, depth):
        r = self._solver()
        if force is not None:
            return r.at_force(force, self.tilt)
        return r.at_depth(depth, self.tilt)

    def _slices_normal(self, force, depth):
        given = force if force is not None else depth
        vals = np.asarray(given, dtype=float)
        flat = vals.ravel()
        # in increasing order, so that each slice solve starts from its neighbour's
        # (the coupled-slice roller keeps its last solution)
        sols = [None] * flat.size
        for k in np.argsort(flat, kind="stable"):
            v = float(flat[k])
            sols[k] = (self._solve_one(v, None) if force is not None
                       else self._solve_one(None, v))
        sols = tuple(sols)

        def arr(fn):
            return out(np.array([fn(s) for s in sols]).reshape(vals.shape))

        one = vals.ndim == 0
        p = [s.p_max for s in sols]
        reasons = {}
        if any(v is None for v in p):
            reasons["peak_pressure"] = ({"profile": self.profile.label},
                                        sols[[v is None for v in p].index(True)].message)
        if not one:
            why = ({"force" if force is not None else "depth": "an array"},
                   "q(x) is given for one load at a time (see solutions)")
            reasons.update(x=why, q=why)
        d0 = [self._slice_first_contact(s.tilt) for s in sols]
        notes = tuple(dict.fromkeys(n for s in sols for n in s.notes))
        return ContactResult(
            force=arr(lambda s: s.force), depth=arr(lambda s: s.depth),
            approach=out(np.array([s.depth - z for s, z in zip(sols, d0)]).reshape(
                vals.shape)),
            stiffness=arr(lambda s: self._free_stiffness(s)),
            moment=arr(lambda s: s.moment), tilt=arr(lambda s: s.tilt),
            tilt_stiffness=arr(lambda s: s.stiffness_matrix[1, 1]
                               - s.stiffness_matrix[1, 0] * s.stiffness_matrix[0, 1]
                               / s.stiffness_matrix[0, 0]),
            x=sols[0].x if one else None, q=sols[0].q if one else None,
            peak_pressure=(None if "peak_pressure" in reasons else
                           arr(lambda s: s.p_max)),
            half_width=arr(lambda s: float(np.max(s.half_width))),
            model=self.model, notes=notes, reasons=reasons, solutions=sols)

    def _slice_first_contact(self, tilt):
        return self._solver().first_contact_depth(tilt)

    def first_contact_depth(self, tilt=0.0):
        """Depth d0 of the roller's centre (x = 0) at first contact, at tilt `tilt`
        [rad]: nothing touches for d <= d0, and a solution's approach from first
        contact is d - d0 (:attr:`ContactResult.approach`). 0 for an aligned roller
        whose drop is least at its centre; negative where a tilt brings an end closer
        (the depth at the centre of a contact at one end is then negative).

        Parameters
        ----------
        tilt : float, optional
            Tilt theta of the roller axis [rad], within (-0.1, 0.1).

        Returns
        -------
        float
            d0 [m], on the slice model's own grid (the coupled slices' or ISO 16281's).

        Examples
        --------
        >>> c = Contact(Roller(5e-3, 10e-3, profile="straight", tilt=1e-3),
        ...             estar=115.38e9)
        >>> f"{c.first_contact_depth(1e-3) * 1e6:.2f} um"
        '-5.00 um'
        """
        if self.raceways or not self.sliced:
            raise CombinationError({"model": self.model},
                                   "the first-contact depth is a single roller contact "
                                   "solved by slices (a profile or a tilt)")
        from ..profiles import TILT_RANGE

        return self._slice_first_contact(TILT_RANGE.check(tilt).item())

    def _free_stiffness(self, s):
        """dF/dd: at the held tilt, or with the tilt free (M = 0 kept)."""
        K = s.stiffness_matrix
        if self.tilt != FREE:
            return float(K[0, 0])
        return float(K[0, 0] - K[0, 1] * K[1, 0] / K[1, 1])

    def _raceways(self, force, depth):
        kw = dict(model=self.model, profile=self.profile, tilt=self.tilt,
                  n_slices=self.n_slices, **self.options)
        if not self.sliced or np.ndim(force if force is not None else depth) == 0:
            vals = [force if force is not None else depth]
            one = True
        else:
            vals = list(np.asarray(force if force is not None else depth, float).ravel())
            one = False
        sols = tuple(roller_between_raceways(
            self.roller.radius, self.roller.length, self.estar, self.counterbody,
            **({"force": v} if force is not None else {"deflection": v}), **kw)
            for v in vals)

        s0 = sols[0]

        def arr(name):
            if one:
                return getattr(s0, name)
            return out(np.array([getattr(s, name) for s in sols]))

        if one and np.ndim(s0.force):
            sols = _split(s0)       # one solution per load, as for a slice model
        reasons = {}
        why_q = ({"counterbody": "Raceways"}, "a whole roller has two load distributions: "
                 "see solutions[i].inner.q and .outer.q")
        reasons.update(x=why_q, q=why_q)
        p = None
        if self.sliced:
            pk = [max((v for v in (s.peak_pressure_inner, s.peak_pressure_outer)
                       if v is not None), default=None) for s in sols]
            if all(v is not None for v in pk):
                p = pk[0] if one else out(np.array(pk))
            else:
                reasons["peak_pressure"] = ({"profile": self.profile.label},
                                            "a contact is edge loaded: its peak pressure "
                                            "is singular (see solutions)")
        else:
            p = np.maximum(s0.peak_pressure_inner, s0.peak_pressure_outer)
        if s0.tilt_stiffness is None:
            reasons["tilt_stiffness"] = ({"model": self.model}, "a straight-cylinder law "
                                         "has no tilt stiffness; use "
                                         "model='profiled-roller'")
        half = None
        reasons["half_width"] = ({"counterbody": "Raceways"},
                                 "two contacts, two half-widths (see solutions)")
        return ContactResult(
            force=arr("force"), depth=arr("deflection"), approach=arr("deflection"),
            stiffness=arr("stiffness"), moment=arr("moment"), tilt=arr("tilt"),
            tilt_stiffness=None if s0.tilt_stiffness is None else arr("tilt_stiffness"),
            x=None, q=None, peak_pressure=p, half_width=half, model=s0.model,
            notes=tuple(dict.fromkeys(n for s in sols for n in s.notes)),
            reasons=reasons, solutions=sols)

    # ---- tangential ------------------------------------------------------------------
    def tangential(self, friction, *, force=None, depth=None, tangential_force=None,
                   shift=None, method=None, direction="across"):
        r"""The tangential state under a tangential force or shift (Cattaneo-Mindlin).

        .. math:: k_t = r\,k_n, \qquad
                  F_t(u) = \mu\left[F(e) - F\!\left(e - \frac{r u}{\mu}\right)
                  \right]

        with F(e) this contact's own normal law in the approach e (a crowned roller's
        from its coupled slices) and the stiffness ratio r: the MDR's G*/E* (the same
        in every direction), or, for a crowned roller whose Hertz ellipse lies inside
        the roller, Mindlin's ratio k_t/k_n of the ellipse in the direction asked
        (:func:`linecontact.mindlin.stiffness_ratio`; it does not depend on the load).
        The law is then Mindlin's for the ellipse (Cattaneo-Mindlin partial slip with a
        similar stick ellipse): for F ~ e^(3/2) the formula above is
        :math:`Q = \mu F[1 - (1 - u/u^*)^{3/2}]`, :math:`u^* = 3\mu F/(2 k_t)`.

        Parameters
        ----------
        friction : float
            Coulomb friction coefficient mu > 0 [-].
        force : float or array_like, optional
            Normal force F, held [N].
        depth : float or array_like, optional
            Normal depth at the roller's centre, held, instead of `force` [m].
        tangential_force : float or array_like, optional
            Tangential force Q, either sign (the sign is the direction) [N].
        shift : float or array_like, optional
            Tangential shift u instead of Q, either sign [m].
        method : {None, "mdr", "bem", "mindlin", "ellipse"}, optional
            None (default): ``"mindlin"`` for a crowned roller (circular crown, coupled
            slices), ``"ellipse"`` for any other profile solved by slices, ``"mdr"``
            otherwise. ``"mdr"``: the ratio G*/E* in every direction; ``"bem"``: a
            straight cylinder's direction-dependent k_t/k_n and partial-slip
            correction from the BEM table
            (:class:`linecontact.tangential.TangentialContact`; straight-cylinder
            laws only); ``"mindlin"``: Mindlin's ratio of the Hertz ellipse (circular
            crown only; at a load whose ellipse reaches the roller's ends the
            equivalent ellipse's, with a note); ``"ellipse"``: Mindlin's ratio of the
            equivalent ellipse of the slices' footprint, the ellipse of the same
            half-length and normal stiffness
            (:func:`linecontact.mindlin.equivalent_ellipse_ratio`; slice models only),
            its error measured against the 3D tangential BEM in
            tables/tangential_profiles.csv and stated in the notes.
        direction : {"across", "along"}, optional
            With ``method="bem"``, ``"mindlin"`` or ``"ellipse"``: the shift across the
            axis (the rolling direction, default: the direction of the traction in a
            rolling bearing, a cam follower or a support roller) or along it.

        Returns
        -------
        TangentialResult

        Raises
        ------
        CombinationError
            No G* (the contact was given by estar), a viscoelastic body, raceways,
            a free tilt that is not zero, both Q and u.

        Notes
        -----
        Valid for mu > 0 and the model's range, under the assumptions of
        :mod:`linecontact.tangential` (exact at nu = 0 for any shape). |Q| > mu F is
        gross slip: the shift is None with the reason. A shift beyond u* is refused.
        For an elongated contact the MDR's ratio is direction-free, which it is not:
        for a crowned roller with a/b = 12 it is 8.6 % below Mindlin's across and
        8.6 % above along (its notes say so); Mindlin's k_t here is the slices'
        k_n times Mindlin's ratio, within 0.05 % of Mindlin's closed form at 20 to 80
        slices (tests/test_contact_mindlin.py). Other profiles (logarithmic, end
        relief, straight by slices) get the equivalent ellipse's ratio by direction,
        within 0.43 % of the 3D tangential BEM (its grid error included) over the
        profiles, L/D 1-3, loads q/(E* D) 1e-4 to 2e-3 and nu 0-0.5 of
        tables/tangential_profiles.csv; its partial-slip force within 2.1 % of mu F and
        its energy per fretting cycle within 19 % there (the notes give the table's
        figures and say when a case lies outside its range).

        Examples
        --------
        >>> steel = Elastic(210e9, 0.3)
        >>> c = Contact(Roller(8e-3, 12e-3, crown_radius=0.3), Convex(25e-3), steel, steel,
        ...             n_slices=40)
        >>> t = c.tangential(0.15, force=2e3, tangential_force=100.0)
        >>> f"k_t {t.stiffness / 1e6:.0f} N/um, {t.state}, {t.method} {t.direction}"
        'k_t 205 N/um, partial slip, mindlin across'
        >>> t = c.tangential(0.15, force=2e3, method="mdr")
        >>> f"k_t {t.stiffness / 1e6:.0f} N/um"
        'k_t 187 N/um'

        References
        ----------
        Popov & Hess (2015), chapter 4; C. Cattaneo (1938); R. D. Mindlin (1949).
        """
        from .. import tangential as tg

        if self.raceways:
            raise CombinationError({"counterbody": "Raceways", "friction": friction},
                                   "the traction of a whole roller between raceways "
                                   "splits between its two contacts by its rolling, "
                                   "which is not modelled; compute one contact")
        if self.relaxation is not None:
            raise CombinationError({self.viscoelastic: "Viscoelastic",
                                    "friction": friction},
                                   "the tangential law of a viscoelastic contact (G*(t)) "
                                   "is not modelled")
        if self.gstar is None:
            raise CombinationError({"estar": self.estar, "friction": friction},
                                   "G* needs the bodies' Poisson ratios: give "
                                   "material1 and material2", unit={"estar": "Pa"})
        if tangential_force is not None and shift is not None:
            raise CombinationError({"tangential_force": tangential_force,
                                    "shift": shift},
                                   "give a tangential force or a shift, not both")
        mu = tg.FRICTION.check(friction, name="friction")
        if method is None:
            method = ("mindlin" if self._crowned() else
                      "ellipse" if self.sliced and not self.raceways else "mdr")
        methods = ("mdr", "bem", "mindlin", "ellipse")
        if method not in methods:
            raise UnknownNameError("method", method, methods)
        if method in ("mindlin", "ellipse"):
            if direction not in ("across", "along"):
                raise UnknownNameError("direction", direction, ("across", "along"))
        if method == "ellipse" and not self.sliced:
            raise CombinationError({"method": "ellipse", "model": self.model},
                                   "the equivalent ellipse is built from the footprint "
                                   "of a slice model (model='profiled-roller' or "
                                   "'iso16281-slicing'); for a straight cylinder's law "
                                   "use method='bem'")
        if method == "mindlin":
            if not self._crowned():
                raise CombinationError({"method": "mindlin", "model": self.model,
                                        "profile": self.profile.label},
                                       "Mindlin's elliptical solution is for a crowned "
                                       "roller (circular crown, model='profiled-roller')")
        if method == "bem":
            if self.sliced or self.model not in tg.STRAIGHT_CYLINDER_MODELS:
                raise CombinationError({"method": "bem", "model": self.model,
                                        "profile": self.profile.label},
                                       "the BEM table is for a straight, aligned "
                                       "cylinder; use method='mdr'")
            return self._tangential_bem(mu, force, depth, tangential_force, shift,
                                        direction)
        n = self.normal(force=force, depth=depth)
        law = self._law_for("the tangential law")
        e = np.asarray(n.approach, dtype=float)
        F = np.asarray(n.force, dtype=float)
        r = float(tg.SHEAR_RATIO.check(self.gstar / self.estar, name="gstar/estar"))
        shear = r
        if method == "mindlin":
            r, notes, used = self._mindlin_ratio(F, direction, r, n)
            if not used:        # no load's Hertz ellipse inside the roller
                method = "ellipse"
        elif method == "ellipse":
            r, notes = self._ellipse_ratio(n, direction, r)
        else:
            notes = self._mdr_notes(law, e, r, n)
        kt = out(r * np.asarray(n.stiffness))
        ustar = out(mu * e / r)
        rkw = {} if method == "mdr" else {"ratio": r}
        reasons = {}
        Q = u = frac = None
        state = "stick"
        if tangential_force is not None:
            Q = np.asarray(tangential_force, dtype=float)
            frac = np.abs(Q) / (mu * F)
            slide = frac > 1 + 1e-12
            u = np.full(np.broadcast(Q, F).shape, np.nan)
            ok = ~np.broadcast_to(slide, u.shape)
            if np.any(ok):
                eb, Qb = np.broadcast_arrays(e, Q)
                if rkw:
                    rb = np.broadcast_to(rkw["ratio"], eb.shape)[ok]
                    u[ok] = tg.tangential_shift(law, eb[ok], Qb[ok], mu, self.gstar,
                                                ratio=rb)
                else:
                    u[ok] = tg.tangential_shift(law, eb[ok], Qb[ok], mu, self.gstar)
            state = np.where(slide, "gross slip", np.where(
                frac >= 1 - 1e-12, "gross slip", np.where(Q == 0, "stick",
                                                          "partial slip")))
            if np.any(slide):
                reasons["shift"] = ({"tangential_force": float(np.max(np.abs(Q))),
                                     "friction": float(mu)},
                                    "beyond mu F the contact slides: no static shift")
                u = None if u.size == 1 else out(u)
            else:
                u = out(u)
            Q, frac = out(Q), out(frac)
        elif shift is not None:
            u = np.asarray(shift, dtype=float)
            Q = out(tg.tangential_force(law, e, u, mu, self.gstar, **rkw))
            frac = out(np.abs(np.asarray(Q)) / (mu * F))
            state = np.where(np.asarray(frac) >= 1 - 1e-12, "gross slip",
                             np.where(u == 0, "stick", "partial slip"))
            u = out(u)
        else:
            why = ({"tangential_force": None, "shift": None},
                   "no tangential load given")
            reasons.update(tangential_force=why, shift=why, slip_fraction=why)
        if isinstance(state, np.ndarray) and state.ndim == 0:
            state = str(state)
        return TangentialResult(
            normal=n, friction=float(mu), shear_ratio=float(shear), stiffness=kt,
            tangential_force=Q, shift=u, slip_fraction=frac, state=state,
            gross_slip_force=out(mu * F), gross_slip_shift=ustar, reasons=reasons,
            method=method, stiffness_ratio=float(r) if method == "mdr" else r,
            direction=None if method == "mdr" else direction, notes=notes)

    def _mdr_notes(self, law, approach, mdr_ratio, normal=None):
        """The MDR's direction-free ratio and its error: against Mindlin's ellipse for a
        crowned roller, against the equivalent ellipse (itself measured against the 3D
        tangential BEM) for another profile solved by slices, against the BEM table for
        a straight cylinder's law."""
        from .. import tangential as tg

        head = f"MDR: k_t/k_n = G*/E* = {mdr_ratio:.4f} in every direction"
        if self._crowned():
            from .. import mindlin

            err = [mdr_ratio / mindlin.stiffness_ratio(
                self.profile.crown_radius, self.radius, self.gstar, self.estar, d) - 1
                for d in ("y", "x")]
            return (f"{head}: {err[0]:+.1%} from Mindlin's Hertz ellipse across, "
                    f"{err[1]:+.1%} along (the default method gives the law by "
                    "direction)",)
        if self.sliced:
            err = []
            for direction in ("across", "along"):
                ell = np.atleast_1d(self._ellipse_ratio(normal, direction,
                                                        mdr_ratio)[0])
                err.append(float(np.max(mdr_ratio / ell - 1)) if direction == "along"
                           else float(np.min(mdr_ratio / ell - 1)))
            return (f"{head}: {err[0]:+.1%} from the equivalent ellipse of the "
                    f"footprint across, {err[1]:+.1%} along (the default "
                    "method='ellipse' gives the law by direction, with its error "
                    "measured against the 3D tangential BEM)",)
        if self.model not in tg.STRAIGHT_CYLINDER_MODELS:
            return (head,)
        try:
            r = tg.cylinder_stiffness_ratios(law, approach, self.gstar)
        except (OutOfRangeError, FileNotFoundError, ValueError):
            return (f"{head}: its error against the finite cylinder's BEM is not "
                    "measured at this depth",)
        ea = float(np.max(np.abs(r["mdr_error_across"])))
        el = float(np.max(np.abs(r["mdr_error_along"])))
        return (f"{head}: up to {ea:.1%} from the finite cylinder's BEM table across "
                f"and {el:.1%} along (method='bem' gives those)",)

    def _crowned(self):
        """A single contact of a circular crown solved by coupled slices: Mindlin's
        elliptical solution applies while its Hertz ellipse stays inside the roller."""
        return (isinstance(self.profile, CircularCrownProfile) and not self.raceways
                and self.model == "profiled-roller")

    def _ellipse_ratio(self, n, direction, mdr_ratio):
        """The equivalent ellipse's k_t/k_n at each load of the normal state `n`: the
        ellipse of the slices' half-length (half their contact length) and held-tilt
        normal stiffness, Mindlin's ratio in `direction`
        (:func:`linecontact.mindlin.equivalent_ellipse_ratio`); the MDR's ratio where
        the footprint is not longer than wide. Returns (ratio [-], notes), the notes
        with the error measured in tables/tangential_profiles.csv or why it is not
        known for this case."""
        from .. import mindlin

        F = np.asarray(n.force, dtype=float)
        r = np.full(F.size, float(mdr_ratio))
        short = 0
        for k, s in enumerate(n.solutions):
            try:
                r[k] = mindlin.equivalent_ellipse_ratio(
                    0.5 * s.contact_length, float(s.stiffness_matrix[0, 0]), self.gstar,
                    self.estar, "y" if direction == "across" else "x")
            except OutOfRangeError:
                short += 1
        notes = []
        if short:
            notes.append(f"at {short} of {F.size} loads the footprint is not longer "
                         "along the axis than across it: the MDR's direction-free ratio "
                         f"G*/E* = {mdr_ratio:.4f} there, its error not measured")
        notes.append(self._ellipse_note(n, direction))
        return out(r.reshape(F.shape)), tuple(notes)

    def _ellipse_note(self, n, direction):
        """The equivalent ellipse's measured error (tables/tangential_profiles.csv) for
        this case, or what lies outside the range measured there."""
        from .. import tangential as tg
        from ..accuracy import tangential_coverage

        cov = tangential_coverage()
        where = "the 3D tangential BEM (tables/tangential_profiles.csv)"
        if cov is None:
            return (f"equivalent ellipse {direction}: its error against {where} is not "
                    "known here")
        D = 2 * self.roller.radius
        L = self.roller.length
        F = np.asarray(n.force, dtype=float)
        nu = float(tg.equivalent_poisson(self.gstar, self.estar))
        checks = [("L/D", np.array([L / D]), cov["l_over_d"]),
                  ("mean line load q/(E* D)", F / (L * self.estar * D), cov["line_load"]),
                  ("Poisson's ratio nu", np.array([nu]), cov["nu"])]
        slack = 1e-5
        outside = [f"{name} {np.min(v):.2g}-{np.max(v):.2g} (measured {lo:.2g}-{hi:.2g})"
                   for name, v, (lo, hi) in checks
                   if np.any(v < lo * (1 - slack)) or np.any(v > hi * (1 + slack))]
        key = getattr(self.profile, "key", "")
        if key not in cov["profiles"]:
            outside.append(f"profile '{key}' (measured: {', '.join(cov['profiles'])})")
        if np.any(np.asarray(n.tilt, dtype=float) != 0):
            outside.append("a tilted roller (measured aligned)")
        e = cov[direction]
        errs = (f"k_t/k_n {100 * e['stiffness_ratio']:.2g} %, partial-slip force "
                f"{100 * e['partial_slip']:.2g} % of mu F, energy per fretting cycle "
                f"{100 * e['dissipation']:.2g} %")
        if outside:
            return (f"equivalent ellipse {direction}: {'; '.join(outside)}: outside the "
                    f"range where its error was measured against {where}; inside it "
                    f"the largest errors are {errs}")
        return (f"equivalent ellipse {direction}: inside the range measured against "
                f"{where}, largest errors {errs} (the slices' own normal errors "
                "aside)")

    def _mindlin_ratio(self, force, direction, mdr_ratio, normal=None):
        """Mindlin's k_t/k_n across or along the roller at each normal force [N] where
        the Hertz ellipse (radii Rc along the axis, the effective radius across) lies
        inside the roller, |x0| + a_x < L/2 with x0 = apex + Rc tan(tilt); elsewhere
        the equivalent ellipse's of the slices' footprint (:meth:`_ellipse_ratio`,
        `normal` the normal state), or the MDR's without one, with a note. Returns
        (ratio [-], notes, whether Mindlin's ratio was used at any load)."""
        from .. import mindlin
        from ..hertz import hertz_contact

        Rc, L = self.profile.crown_radius, self.roller.length
        F = np.asarray(force, dtype=float)
        try:
            ratio = mindlin.stiffness_ratio(Rc, self.radius, self.gstar, self.estar,
                                            "y" if direction == "across" else "x")
        except OutOfRangeError as exc:     # radii beyond the ellipse's range: a line
            return out(np.full(F.shape, mdr_ratio)), (
                f"Mindlin's ellipse not evaluated ({exc}): the MDR's direction-free "
                f"ratio G*/E* = {mdr_ratio:.4f}, its error not measured",), False
        h = hertz_contact(F, Rc, self.radius, self.estar)
        semi_x = np.asarray(h.b if h.swapped else h.a, dtype=float)
        tilt = self._fixed_tilt("the tangential law")
        x0 = self.profile.offset + Rc * math.tan(tilt)
        inside = np.abs(x0) + semi_x < L / 2
        if inside.all():
            return out(np.full(F.shape, ratio)), (), True
        worst = float(np.max(np.where(inside, 0.0, semi_x)))
        head = (f"at {int(np.count_nonzero(~inside))} of {inside.size} loads the Hertz "
                f"ellipse reaches the roller's ends (a = {worst * 1e3:.4g} mm, apex at "
                f"{x0 * 1e3:.4g} mm, L/2 = {L * 500:.4g} mm)")
        if normal is None:
            r = out(np.where(inside, ratio, mdr_ratio))
            return r, (f"{head}: there the MDR's direction-free ratio G*/E* = "
                       f"{mdr_ratio:.4f} (Mindlin's {direction}: {ratio:.4f}), its "
                       "error not measured",), bool(inside.any())
        ell, notes = self._ellipse_ratio(normal, direction, mdr_ratio)
        r = out(np.where(inside, ratio, ell))
        return r, (f"{head}: there the equivalent ellipse of the slices' footprint "
                   f"(Mindlin's {direction} ratio of the Hertz ellipse: {ratio:.4f})",
                   ) + notes, bool(inside.any())

    def _tangential_bem(self, mu, force, depth, Q, u, direction):
        """Contact.tangential with the BEM table's ratio and slip correction, one
        TangentialContact per normal load."""
        from .. import tangential as tg

        n = self.normal(force=force, depth=depth)
        law = self._law_for("the tangential law")
        e = np.atleast_1d(np.asarray(n.approach, dtype=float))
        F = np.atleast_1d(np.asarray(n.force, dtype=float))
        shape = np.shape(n.force)
        Qb = None if Q is None else np.broadcast_to(np.asarray(Q, float), e.shape)
        ub = None if u is None else np.broadcast_to(np.asarray(u, float), e.shape)
        cols = {k: np.full(e.shape, np.nan) for k in ("kt", "ratio", "Q", "u", "ustar")}
        states = []
        reasons = {}
        for k in range(e.size):
            tc = tg.TangentialContact(law, mu, self.gstar, depth=float(e[k]),
                                      method="bem", direction=direction)
            cols["kt"][k], cols["ratio"][k] = tc.stiffness, tc.ratio
            cols["ustar"][k] = tc.gross_slip_shift
            if Qb is not None:
                cols["Q"][k] = Qb[k]
                if abs(Qb[k]) <= mu * F[k] * (1 + 1e-12):
                    cols["u"][k] = tc.shift(float(Qb[k]))
                else:
                    reasons["shift"] = ({"tangential_force": float(Qb[k]),
                                         "friction": float(mu)},
                                        "beyond mu F the contact slides: no static shift")
            elif ub is not None:
                cols["u"][k] = ub[k]
                cols["Q"][k] = tc.force(float(ub[k]))
            frac = abs(cols["Q"][k]) / (mu * F[k]) if Qb is not None or ub is not None \
                else 0.0
            states.append("gross slip" if frac >= 1 - 1e-12 else
                          "stick" if frac == 0 else "partial slip")

        def shaped(v):
            return out(v.reshape(shape))

        loaded = Qb is not None or ub is not None
        if not loaded:
            why = ({"tangential_force": None, "shift": None}, "no tangential load given")
            reasons.update(tangential_force=why, shift=why, slip_fraction=why)
        state = states[0] if not shape else np.array(states).reshape(shape)
        shift_out = None if "shift" in reasons else (shaped(cols["u"]) if loaded
                                                     else None)
        return TangentialResult(
            normal=n, friction=float(mu),
            shear_ratio=float(tg.SHEAR_RATIO.check(self.gstar / self.estar,
                                                   name="gstar/estar")),
            stiffness=shaped(cols["kt"]),
            tangential_force=shaped(cols["Q"]) if loaded else None, shift=shift_out,
            slip_fraction=shaped(np.abs(cols["Q"]) / (mu * F)) if loaded else None,
            state=state, gross_slip_force=shaped(mu * F),
            gross_slip_shift=shaped(cols["ustar"]), reasons=reasons, method="bem",
            stiffness_ratio=shaped(cols["ratio"]), direction=direction)

    # ---- time ------------------------------------------------------------------------
    def _visco(self, what, whole=False):
        """The laws of the contacts whose Lee-Radok history is asked: one, or the two of
        a whole roller (creep only: a held force passes through both)."""
        if self.relaxation is None:
            raise CombinationError({"material1": "Elastic", "material2": "Elastic"},
                                   f"{what} needs a viscoelastic body")
        if not self.raceways:
            return [self._law_for(what)]
        if not whole:
            raise CombinationError({"counterbody": "Raceways", self.viscoelastic:
                                    "Viscoelastic"},
                                   f"{what} of a whole roller between raceways (a held "
                                   "ring approach shared by two relaxing contacts) is "
                                   "not modelled; ask creep under a held force")
        from ..models import get_model

        radii = self.counterbody.effective_radii(self.roller.radius)
        if not self.sliced:
            return [get_model(self.model, R, self.roller.length, self.estar,
                              **self.options) for R in radii]
        psi = self.counterbody.misalignment
        if self.tilt == FREE and psi != 0.0:
            raise CombinationError({"tilt": FREE, "misalignment": psi},
                                   f"{what} needs each contact's geometry fixed while it "
                                   "is loaded; the free tilt between misaligned rings "
                                   "changes with the load: give the tilt as a number",
                                   unit={"misalignment": "rad"})
        th = self._fixed_tilt(what)
        from ..roller.solvers import slice_solver

        if self.model != "profiled-roller":
            raise CombinationError({"model": self.model}, "the creep laws use the "
                                   "coupled-slice model; use model='profiled-roller'")
        return [_ApproachLaw(slice_solver(self.model, R, self.roller.length, self.estar,
                                          self.profile, n_slices=self.n_slices), t,
                             self.model) for R, t in zip(radii, (th, psi - th))]

    def creep(self, time, *, force):
        r"""Depth under a held force or a force history (Lee & Radok's creep).

        .. math:: F_1\bigl(e(t)\bigr) = \int_{0^-}^t J^*(t - t')\,\dot F(t')\,dt'

        Parameters
        ----------
        time : array_like
            Sample times t_0 <= t_1 <= ... [s].
        force : float or array_like
            Force applied at t_0 and held, or one per sample [N].

        Returns
        -------
        CreepResult

        Notes
        -----
        Valid while the depth grows (refused otherwise, see
        :func:`linecontact.viscoelastic.creep_depth`), a fixed tilt (a free one only
        where it is zero). Between raceways the two contacts creep in series under the
        same force: their depths add (the ring approach). A depth d(t) beyond the law's
        range is refused naming the first time at which it leaves the range; where only
        the long-term depth is beyond it, the history is returned with
        ``long_term_depth`` None and its reason in ``reasons["long_term_depth"]``.

        Examples
        --------
        >>> from linecontact.viscoelastic import StandardLinearSolid
        >>> c = Contact(Roller(5e-3, 10e-3, crown_radius=0.2), material1=Elastic(210e9, 0.3),
        ...             material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.4),
        ...             n_slices=40)
        >>> r = c.creep([0.0, 1e4], force=100.0)
        >>> f"{r.depth[1] / r.depth[0]:.3f}"
        '2.066'

        References
        ----------
        E. H. Lee, J. R. M. Radok, J. Appl. Mech. 27 (1960) 438-444.
        """
        from ..viscoelastic import creep_depth

        laws = self._visco("creep", whole=True)
        t = np.asarray(time, dtype=float)
        F = np.broadcast_to(np.asarray(force, dtype=float), t.shape).astype(float)
        jinf = self.relaxation.creep_terms[0]
        depth, long_term, reasons = np.zeros(t.shape), 0.0, {}
        for law in laws:                                # contacts in series: depths add
            d0 = getattr(law, "d0", 0.0)
            depth += creep_depth(law, self.relaxation, t, F) + d0
            if long_term is None:
                continue
            try:
                long_term += (float(law.depth(F[-1] * jinf * self.estar)) if F[-1] > 0
                              else 0.0) + d0
            except OutOfRangeError as exc:  # d(t) is within the range, d(inf) is not
                long_term = None
                shown = (f"{exc.value:.6g}" if isinstance(exc.value, float)
                         else str(exc.value))
                reasons["long_term_depth"] = (
                    {"force": float(F[-1])},
                    "beyond the model's range: its elastic-equivalent force F E*_0/E*_inf "
                    f"= {shown} {exc.unit} is outside {exc.valid}".replace("  ", " "))
        return CreepResult(time=t, force=F, depth=out(depth), long_term_depth=long_term,
                           model=self.model, reasons=reasons)

    def relaxation_history(self, time, *, depth):
        r"""Force under a held depth or a depth history (Lee & Radok's relaxation).

        .. math:: F(t) = \int_{0^-}^t E^*(t - t')\,\frac{d}{dt'}F_1\bigl(e(t')\bigr)\,dt'

        Parameters
        ----------
        time : array_like
            Sample times [s].
        depth : float or array_like
            Depth at the roller's centre, applied at t_0 and held, or one per sample
            (non-decreasing) [m].

        Returns
        -------
        CreepResult

        Notes
        -----
        Valid for a non-decreasing depth (a growing contact).

        Examples
        --------
        >>> from linecontact.viscoelastic import StandardLinearSolid
        >>> c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
        ...             material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
        >>> r = c.relaxation_history([0.0, 1e4], depth=2e-6)
        >>> f"{r.force[1] / r.force[0]:.4f}"
        '0.3333'

        References
        ----------
        E. H. Lee, J. R. M. Radok, J. Appl. Mech. 27 (1960) 438-444.
        """
        from ..viscoelastic import force_history

        law = self._visco("relaxation")[0]
        t = np.asarray(time, dtype=float)
        d = np.broadcast_to(np.asarray(depth, dtype=float), t.shape).astype(float)
        d0 = getattr(law, "d0", 0.0)
        F = force_history(law, self.relaxation, t, d - d0)
        why = ({"depth": "given"}, "the depth is prescribed: no long-term creep depth")
        return CreepResult(time=t, force=out(F), depth=d, long_term_depth=None,
                           model=self.model, reasons={"long_term_depth": why})

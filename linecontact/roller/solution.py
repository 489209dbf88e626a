"""The solution of a roller model (:class:`RollerSolution`) and the helpers that read the
contact's extent and peak pressure off the slices.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, fields

import numpy as np

__all__ = ["RollerSolution"]


@dataclass(frozen=True)
class RollerSolution:
    """The state of a profiled, tilted roller in contact: loads, stiffness, pressure.

    Returned by :meth:`ProfiledRoller.at_depth`, :meth:`ProfiledRoller.at_force`,
    :func:`roller_contact` and :func:`iso_slicing`; not built by hand.

    .. math:: F = \\sum_k q_k w, \\qquad M = \\sum_k q_k x_k w

    Parameters
    ----------
    depth : float
        Depth (approach) d of the roller point x = 0 [m].
    tilt : float
        Tilt theta, positive when the +x end goes deeper [rad].
    force : float
        Normal force F [N].
    moment : float
        Moment about x = 0, positive when +x carries more [N m].
    stiffness : float
        dF/dd at fixed tilt [N/m].
    tilt_stiffness : float
        dM/dtheta at fixed depth [N m/rad].
    stiffness_matrix : ndarray
        [[dF/dd, dF/dtheta], [dM/dd, dM/dtheta]] [N/m, N/rad; N, N m/rad]. At a
        force (coupled slices) the last Newton step's linearisation: the derivative at
        a state within about 3e-7 (relative) of the returned one.
    x : ndarray
        Slice centres [m].
    width : ndarray
        Slice widths [m] (graded towards the contact's ends for the coupled slices):
        F = sum q w [m].
    q : ndarray
        Line load q(x_k), 0 outside the contact [N/m].
    half_width : ndarray
        Contact half-width b_k across the roller, 0 outside the contact [m].
    pressure : ndarray
        Peak pressure of each slice, 2 q_k/(pi b_k) [Pa].
    p_max : float or None
        Peak pressure, interpolated between slices; None when edge loaded [Pa].
    x_at_p_max : float
        Where the peak sits, the loaded end when edge loaded [m].
    contact_start : float
        Start of the contact along x, where q falls to zero [m].
    contact_end : float
        End of the contact along x [m].
    contact_length : float
        contact_end - contact_start [m].
    edge_loaded : bool
        True if the contact reaches an end of the roller (within a slice width or
        L/1000 of it).
    edge : str or None
        ``"-x"``, ``"+x"``, ``"both"`` or None.
    message : str
        What p_max means here, or why it is None.
    method : str
        ``"coupled slices"`` or ``"ISO 16281 slicing"``.
    n_slices : int
        Number of slices [-].
    iterations : int
        Newton iterations used [-].
    notes : tuple of str
        Warnings about the validity of this solution.
    p_max_resolved : bool
        False if the peak sits within two slices of the contact's end (a concentration
        narrower than the slices, e.g. at a sharp relief): then p_max is not converged.

    Notes
    -----
    Valid as the model that produced it (see :class:`ProfiledRoller`): |theta| < 0.1
    rad, b << R; q, half_width and pressure are per slice, 0 <= q < inf.

    Examples
    --------
    >>> from linecontact.roller import roller_contact
    >>> s = roller_contact(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5", force=1000.0)
    >>> f"{s.force:.0f} N, {abs(s.moment):.0f} N m, {s.contact_length * 1e3:.1f} mm"
    '1000 N, 0 N m, 4.6 mm'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2 (Hertz pressure across).
    """

    depth: float
    tilt: float
    force: float
    moment: float
    stiffness: float
    tilt_stiffness: float
    stiffness_matrix: np.ndarray
    x: np.ndarray
    q: np.ndarray
    half_width: np.ndarray
    pressure: np.ndarray
    p_max: object
    x_at_p_max: float
    contact_start: float
    contact_end: float
    contact_length: float
    edge_loaded: bool
    edge: object
    message: str
    method: str
    n_slices: int
    iterations: int = 0
    notes: tuple = field(default_factory=tuple)
    p_max_resolved: bool = True
    width: np.ndarray = None

    @classmethod
    def _built(cls, **fields):
        """The solution holding `fields` (every field, by name), as the constructor
        builds it (the attributes in the order of the fields) without its per-field
        frozen-dataclass assignments: a solver returns one per solve, and the
        constructor's 25 keyword arguments cost several microseconds there."""
        if len(fields) != len(_FIELDS):
            raise TypeError(f"RollerSolution fields: {sorted(set(fields) ^ set(_FIELDS))}")
        obj = object.__new__(cls)
        d = obj.__dict__
        for name in _FIELDS:
            d[name] = fields[name]
        return obj

    def to_dict(self, arrays=True):
        """Plain-Python dict (for JSON): scalars in SI, arrays as lists if `arrays`.

        Returns
        -------
        dict
            Keys as the attributes, with units in ``"units"``.

        Examples
        --------
        >>> from linecontact.roller import roller_contact
        >>> s = roller_contact(5e-3, 10e-3, 115.385e9, "circular:Rc=0.1", force=500.0)
        >>> sorted(s.to_dict(arrays=False))[:4]
        ['contact_end', 'contact_length', 'contact_start', 'depth']
        """
        d = {}
        for k, v in self.__dict__.items():
            if isinstance(v, np.ndarray):
                if arrays:
                    d[k] = v.tolist()
            elif isinstance(v, tuple):
                d[k] = list(v)
            else:
                d[k] = v
        d["units"] = {"depth": "m", "tilt": "rad", "force": "N", "moment": "N m",
                      "stiffness": "N/m", "tilt_stiffness": "N m/rad", "x": "m",
                      "width": "m", "q": "N/m", "half_width": "m", "pressure": "Pa",
                      "p_max": "Pa",
                      "x_at_p_max": "m", "contact_start": "m", "contact_end": "m",
                      "contact_length": "m"}
        return d


#: the field names of RollerSolution, in their order (RollerSolution._built)
_FIELDS = tuple(f.name for f in fields(RollerSolution))


def contact_extent(x, q, w, L, lo=None, hi=None, loaded=None):
    """Ends of the contact from the loaded slices, q extrapolated to zero (w: the slice
    widths, an array or one width for all; `loaded`: the first and last loaded slice
    where the caller has them, else found here)."""
    w = np.asarray(w, dtype=float)
    if w.shape != np.shape(x):                 # one width for all
        w = np.broadcast_to(w, np.shape(x))
    if loaded is None:
        on = np.flatnonzero(q > 0)
        loaded = int(on[0]), int(on[-1])
    i0, i1 = loaded
    n = len(x)
    # the few slices read below as Python floats (the same IEEE arithmetic as numpy's
    # scalars, at a fraction of the cost per operation)
    xl, ql, wl = np.asarray(x, dtype=float).tolist(), np.asarray(q).tolist(), w.tolist()

    def end(i, step):
        # q near a smooth contact edge falls linearly; use the last three loaded slices
        # (slice i is loaded: the line through two where the third is not, or i alone)
        j1, j2 = i - step, i - 2 * step
        two = 0 <= j1 < n and ql[j1] > 0
        three = two and 0 <= j2 < n and ql[j2] > 0
        if not two:
            return xl[i] + step * wl[i] / 2
        # the line or parabola through them, in u = x - x[i]: q0 + s1 u + a u (u - u1)
        # (Newton's divided differences), its real roots in closed form
        u1 = xl[j1] - xl[i]
        q0, q1 = float(ql[i]), float(ql[j1])
        s1 = (q1 - q0) / u1
        a = 0.0
        if three:
            u2 = xl[j2] - xl[i]
            a = ((float(ql[j2]) - q1) / (u2 - u1) - s1) / u2
        bq = s1 - a * u1
        if a == 0.0:
            roots = [-q0 / bq] if bq != 0.0 else []
        else:
            disc = bq * bq - 4.0 * a * q0
            if disc < 0.0:
                roots = []
            else:
                h = -0.5 * (bq + math.copysign(math.sqrt(disc), bq))
                roots = [h / a, q0 / h] if h != 0.0 else [0.0]
        lo, hi = sorted((0.0, step * wl[i]))
        roots = [r for r in roots if lo <= r <= hi]
        if not roots:
            return xl[i] + step * wl[i] / 2
        return xl[i] + min(roots, key=abs)

    lo = -L / 2 if lo is None else lo
    hi = L / 2 if hi is None else hi
    start = lo if i0 == 0 else end(i0, -1)
    stop = hi if i1 == n - 1 else end(i1, +1)
    tol = 1e-9 * L
    return start, stop, i0 == 0 and lo <= -L / 2 + tol, i1 == n - 1 and hi >= L / 2 - tol


def peak_pressure(x, p):
    """Peak of p over the slices, refined by a parabola through p^2 (exact for Hertz;
    the slice centres x may be unevenly spaced)."""
    p = np.asarray(p)
    k = int(p.argmax())
    # as Python floats (the same arithmetic as numpy's scalars, faster)
    if 0 < k < len(x) - 1 and p[k - 1] > 0 and p[k + 1] > 0:
        (p0, p1, p2), (x0, x1, x2) = p[k - 1:k + 2].tolist(), x[k - 1:k + 2].tolist()
        y0, y1, y2 = p0 ** 2, p1 ** 2, p2 ** 2
        h0, h1 = x1 - x0, x2 - x1
        s0, s1 = (y1 - y0) / h0, (y2 - y1) / h1           # divided differences
        curv = (s1 - s0) / (h0 + h1)                       # y = y1 + g u + curv u^2
        if curv < 0:
            g = s0 + curv * h0                             # slope at x[k]
            u = -g / (2 * curv)
            return math.sqrt(y1 - g * g / (4 * curv)), x1 + u
    return float(p[k]), float(x[k])

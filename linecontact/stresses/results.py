r"""The result of the stresses along a roller: per slice and the worst of all.

:class:`SubsurfaceStresses` holds the strip maxima of every slice and the worst of
each measure (3D-corrected where :func:`~linecontact.stresses.roller_stresses` made
the correction), with the field on a section, along the axis and its depth
envelope on request (McEwen's strip of the slice).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..checks import check_interval
from ..errors import OutOfRangeError
from .measures import MEASURES
from .strip import StripStresses, _maxima, _unit_strip, strip_stresses

__all__ = ["SubsurfaceStresses"]

@dataclass(frozen=True)
class SubsurfaceStresses:
    """Stress maxima along a roller (one strip per slice) and the worst of all.

    Returned by :func:`line_contact_stresses` and :func:`roller_stresses`; not built by
    hand. Per-measure dicts are keyed by :data:`MEASURES`.

    Parameters
    ----------
    x : ndarray
        Slice centres along the roller [m].
    half_width : ndarray
        Contact half-width b(x), 0 where unloaded [m].
    peak_pressure : ndarray
        Peak pressure p0(x) = 2 q(x)/(pi b(x)), 0 where unloaded [Pa].
    friction : float
        Coefficient of the sliding traction [-].
    poisson : float
        Poisson's ratio [-].
    value : dict
        Measure -> its maximum below each slice [Pa].
    depth : dict
        Measure -> its depth below each slice [m].
    y : dict
        Measure -> its position across the contact below each slice [m].
    worst : dict
        Measure -> dict(value [Pa], x [m], y [m], z [m], slice index).
    notes : tuple of str
        The measured accuracy of the slice method (or why it is not known here).
    edge_loaded : bool
        The contact reaches a roller end (the end slice's stresses are those of a
        singular pressure peak, resolved only to the slice width).
    strip_worst : dict or None
        With the 3D correction: the plane-strain strips' worst (as `worst`), for
        comparison; None without it.
    error : dict or None
        Measure -> the largest |value/value_3D - 1| measured for this kind of case in
        tables/stress_accuracy.csv [-]; None where the case lies outside the measured
        range (the notes say why).
    method : str
        "plane-strain strip" or "strip + 3D correction".
    withheld : dict
        Measure -> why its maximum is not a converged number (empty where every one
        is): an edge-loaded roller, whose singular end pressure makes the maxima grow
        without limit as the slices are refined. ``worst`` still holds the slice
        solution's values (the slice width's numbers), as diagnostics; a report prints
        "-" with the reason, as for the peak pressure.

    Notes
    -----
    Valid as the plane-strain strip per slice: b << R, b(x) slowly varying along x
    (see the notes for the measured error where it is not).

    Examples
    --------
    >>> from linecontact.stresses import line_contact_stresses
    >>> s = line_contact_stresses(1000.0, 5e-3, 10e-3, 115.385e9)
    >>> f"{s.worst['tresca']['value'] / 1e6:.0f} MPa at {s.worst['tresca']['z'] * 1e6:.1f} um"
    '257 MPa at 58.4 um'
    """

    x: np.ndarray
    half_width: np.ndarray
    peak_pressure: np.ndarray
    friction: float
    poisson: float
    value: dict
    depth: dict
    y: dict
    worst: dict
    notes: tuple = field(default_factory=tuple)
    edge_loaded: bool = False
    strip_worst: dict = None
    error: dict = None
    method: str = "plane-strain strip"
    withheld: dict = field(default_factory=dict)

    def _slice(self, x):
        x = float(x)
        lo, hi = self.x[0], self.x[-1]
        if self.x.size == 1:
            return float(self.half_width[0]), float(self.peak_pressure[0])
        if not lo <= x <= hi:
            raise OutOfRangeError("x", x, f"[{lo:.6g}, {hi:.6g}] m", unit="m",
                                  hint="the slices span the contact's overlap interval")
        # interpolate the line load and b; p0 from them
        q = 0.5 * np.pi * self.peak_pressure * self.half_width
        qx = float(np.interp(x, self.x, q))
        bx = float(np.interp(x, self.x, self.half_width))
        return bx, (2 * qx / (np.pi * bx) if bx > 0 else 0.0)

    def section(self, x, y, z):
        """The field on a section across the roller at x, on the grid y x z.

        Parameters
        ----------
        x : float
            Position along the roller, within the slices' span [m].
        y : array_like
            Positions across the contact [m].
        z : array_like
            Depths, z >= 0 [m].

        Returns
        -------
        StripStresses
            Components on the (len(y), len(z)) grid [Pa].
        """
        b, p0 = self._slice(x)
        Y, Z = np.meshgrid(np.asarray(y, float), np.asarray(z, float), indexing="ij")
        if b <= 0:
            zero = np.zeros_like(Y)
            return StripStresses(zero, zero, zero, zero)
        return strip_stresses(Y, Z, b, p0, self.friction, self.poisson)

    def along_axis(self, z, y=0.0):
        """The field along the roller (every slice) at depths z and position y.

        Parameters
        ----------
        z : array_like
            Depths, z >= 0 [m].
        y : float, optional
            Position across the contact [m].

        Returns
        -------
        StripStresses
            Components on the (n_slices, len(z)) grid, 0 below unloaded slices [Pa].
        """
        z = np.atleast_1d(check_interval("z", z, 0.0, np.inf, unit="m"))
        loaded = self.half_width > 0
        b = np.where(loaded, self.half_width, 1.0)[:, None]
        p0 = np.where(loaded, self.peak_pressure, 0.0)[:, None]
        mu, nu = self.friction, self.poisson
        comps = _unit_strip(float(y) / b, z[None, :] / b, mu, nu)
        return StripStresses(*(c * p0 for c in comps))

    def depth_envelope(self, measure, depths, x=None, n_y=241):
        """The largest stress over y at each depth, below the worst slice (or at x).

        Parameters
        ----------
        measure : str
            One of :data:`MEASURES`.
        depths : array_like
            Depths, z >= 0 [m].
        x : float, optional
            Position along the roller [m] (default: the slice of the measure's worst).
        n_y : int, optional
            Points over |y| <= 2 b [-].

        Returns
        -------
        ndarray
            The envelope at each depth [Pa].
        """
        if measure not in MEASURES:
            raise ValueError(f"measure = {measure!r} is not one of {MEASURES}")
        if x is None:
            k = self.worst[measure]["slice"]
            b, p0 = float(self.half_width[k]), float(self.peak_pressure[k])
        else:
            b, p0 = self._slice(x)
        z = np.atleast_1d(check_interval("depths", depths, 0.0, np.inf, unit="m"))
        ys = np.linspace(-2.0, 2.0, n_y)[:, None]
        s = StripStresses(*_unit_strip(ys, z[None, :] / b, self.friction, self.poisson))
        return s.measure(measure).max(axis=0) * p0

    def to_dict(self, arrays=True):
        """Plain-Python dict for JSON: the worst per measure, the along-axis profile if
        `arrays` (SI units; see ``units``).

        Parameters
        ----------
        arrays : bool, optional
            Include the per-slice arrays.

        Returns
        -------
        dict
            Keys worst, notes, edge_loaded, friction, poisson, method, error
            (strip_worst with the 3D correction; withheld where a maximum is not
            converged; and x, half_width, peak_pressure, value, depth, y), units.
        """
        d = {"worst": {k: dict(v) for k, v in self.worst.items()},
             "friction": self.friction, "poisson": self.poisson,
             "edge_loaded": self.edge_loaded, "notes": list(self.notes),
             "method": self.method, "error": self.error}
        if self.strip_worst is not None:
            d["strip_worst"] = {k: dict(v) for k, v in self.strip_worst.items()}
        if self.withheld:
            d["withheld"] = dict(self.withheld)
        if arrays:
            d.update(x=self.x.tolist(), half_width=self.half_width.tolist(),
                     peak_pressure=self.peak_pressure.tolist(),
                     value={k: v.tolist() for k, v in self.value.items()},
                     depth={k: v.tolist() for k, v in self.depth.items()},
                     y={k: v.tolist() for k, v in self.y.items()})
        d["units"] = {"x": "m", "half_width": "m", "peak_pressure": "Pa", "value": "Pa",
                      "depth": "m", "y": "m", "z": "m"}
        return d


def _assemble(x, b, p0, mu, nu, notes=(), edge_loaded=False):
    m = _maxima(mu, nu)
    loaded = b > 0
    value, depth, yy, worst = {}, {}, {}, {}
    for name in MEASURES:
        value[name] = np.where(loaded, m.value[name] * p0, 0.0)
        depth[name] = np.where(loaded, m.z[name] * b, 0.0)
        yy[name] = np.where(loaded, m.y[name] * b, 0.0)
        k = int(np.argmax(value[name]))
        worst[name] = dict(value=float(value[name][k]), x=float(x[k]),
                           y=float(yy[name][k]), z=float(depth[name][k]), slice=k)
    return SubsurfaceStresses(x, b, p0, mu, nu, value, depth, yy, worst, tuple(notes),
                              bool(edge_loaded))

"""3D stress field below a half-space surface pressure: Love's rectangle, DC-FFT per plane.

Uniform pressure p on the rectangle |x'| <= a, |y'| <= b of the surface of an elastic
half-space (z >= 0 into the body, compression negative). With Boussinesq's potentials
(Love 1929; Johnson 1985, Eqs. 3.18-3.19 in the notation H1 = int p ln(rho + z) dA,
psi1 = dH1/dz = int p/rho dA, rho the distance to the load point)

    sigma_x = [2 nu d(psi1)/dz - z d2(psi1)/dx2 - (1 - 2 nu) d2(H1)/dx2] / (2 pi)
    sigma_y = [2 nu d(psi1)/dz - z d2(psi1)/dy2 - (1 - 2 nu) d2(H1)/dy2] / (2 pi)
    sigma_z = [d(psi1)/dz - z d2(psi1)/dz2] / (2 pi)
    tau_xy  = -[(1 - 2 nu) d2(H1)/dxdy + z d2(psi1)/dxdy] / (2 pi)
    tau_xz  = -z d2(psi1)/dxdz / (2 pi)
    tau_yz  = -z d2(psi1)/dydz / (2 pi)

and for the rectangle every derivative is a sum over its corners,
f = g(x+a, y+b) - g(x+a, y-b) - g(x-a, y+b) + g(x-a, y-b), of elementary corner
functions of X, Y (the offsets from a corner) and rho = sqrt(X^2 + Y^2 + z^2):

    d(psi1)/dz    : -atan(X Y / (z rho))
    d2(psi1)/dz2  :  X Y (rho^2 + z^2) / (rho (X^2 + z^2) (Y^2 + z^2))
    d2(psi1)/dx2  : -X Y / (rho (X^2 + z^2))        d2(psi1)/dy2 : -X Y / (rho (Y^2 + z^2))
    d2(psi1)/dxdy :  1/rho
    d2(psi1)/dxdz : -Y z / (rho (X^2 + z^2))        d2(psi1)/dydz : -X z / (rho (Y^2 + z^2))
    d2(H1)/dx2    :  atan(X Y (rho - z) / (X^2 rho + Y^2 z))
    d2(H1)/dy2    :  atan(X Y (rho - z) / (Y^2 rho + X^2 z))
    d2(H1)/dxdy   :  ln(rho + z)

(derived by differentiating the corner primitives; psi1 is harmonic, which the
three second derivatives satisfy identically). The one home of these formulas is
:func:`linecontact.stresses.rectangle_stresses` (the runtime's 3D correction uses
them too); this module imports it. tests/test_stress_bem.py checks the
result against a direct quadrature of Boussinesq's point-load stresses (Johnson 1985,
Eq. 3.21), the surface value sigma_z = -p inside the rectangle, and the Hertz contact
on its axis (Johnson Eq. 3.45).

The field of a pressure on a grid of nx x ny equal cells is, in each depth plane, the
linear convolution of the cell pressures with these coefficients at the cell-centre
offsets: one DC-FFT per component and plane (Liu & Wang 2002), with the zero-padded
operator of tools.bem.halfspace (the shear kernels are odd, so the kernel is given at
every offset, :func:`tools.bem.halfspace.wraparound_offsets`). The pressure's transform
is made once and shared by the six components.

Traction: a uniform tangential traction on a cell has no closed form here; its
coefficients are Cerruti's point-force stresses (Johnson 1985, section 3.3)
integrated over the cell by Gauss quadrature (:func:`rectangle_quadrature`, sub-cells
no longer than z/2 near the field point, checked on Boussinesq's load against Love's
closed form), convolved like the pressure's (:meth:`StressField.plane` with
``traction``).

The surface z = 0: both loads in closed form (:func:`surface_pressure_stresses`,
Love's corner functions in their limit z -> 0; :func:`surface_traction_stresses`,
Cerruti's surface point-force stresses integrated over the rectangle by corner
primitives), exact at the cell centres with the local terms (sigma_z = -p,
tau_yz = -q in the loaded cell) and the principal values of the in-plane
components; convolved like a depth plane (:meth:`StressField.surface`). Checked
against the quadratures off the rectangle, against the limits z -> 0 of the depth
planes, and, on a long strip, against McEwen's plane-strain surface values
(tests/test_stress_bem.py).

References
----------
A. E. H. Love, "The stress produced in a semi-infinite solid by pressure on part of the
boundary", Phil. Trans. R. Soc. A 228 (1929) 377-420.
K. L. Johnson, Contact Mechanics (1985), sections 3.2-3.4.
S. Liu, Q. Wang, "Studying contact stress fields caused by surface tractions with a
discrete convolution and fast Fourier transform algorithm", J. Tribology 124 (2002)
36-45.
"""
from __future__ import annotations

import numpy as np

from linecontact.stresses import MEASURES, rectangle_stresses, stress_measures

from .halfspace import DCFFTOperator, wraparound_offsets

COMPONENTS = ("sigma_x", "sigma_y", "sigma_z", "tau_xy", "tau_xz", "tau_yz")


def point_load_stresses(x, y, z, poisson=0.3):
    """Boussinesq's stresses under a unit compressive point force at the origin.

    Johnson (1985) Eq. 3.21, in cylindrical components turned to Cartesian: an
    independent check of :func:`rectangle_stresses` by quadrature.

    Parameters
    ----------
    x, y : array_like
        Field point [m].
    z : array_like
        Depth > 0 [m].
    poisson : float
        Poisson's ratio [-].

    Returns
    -------
    dict
        Component name -> stress per unit force [1/m^2].
    """
    x, y, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (x, y, z)))
    nu = poisson
    r2 = x * x + y * y
    r = np.sqrt(r2)
    rho = np.sqrt(r2 + z * z)
    k = 1 / (2 * np.pi)
    with np.errstate(invalid="ignore", divide="ignore"):
        # (1 - z/rho)/r^2 = 1/(rho (rho + z)), free of cancellation on the axis
        g = 1.0 / (rho * (rho + z))
        s_r = k * ((1 - 2 * nu) * g - 3 * z * r2 / rho ** 5)
        s_t = -k * (1 - 2 * nu) * (g - z / rho ** 3)
        c = np.where(r > 0, x / np.where(r > 0, r, 1), 1.0)
        s = np.where(r > 0, y / np.where(r > 0, r, 1), 0.0)
    s_z = -3 * k * z ** 3 / rho ** 5
    t_rz = -3 * k * r * z * z / rho ** 5
    return dict(sigma_x=s_r * c * c + s_t * s * s, sigma_y=s_r * s * s + s_t * c * c,
                sigma_z=s_z, tau_xy=(s_r - s_t) * s * c, tau_xz=t_rz * c, tau_yz=t_rz * s)


def cerruti_point_stresses(x, y, z, poisson=0.3):
    """Cerruti's stresses under a unit tangential point force in +x at the origin.

    Johnson (1985), section 3.3 (the point force Q_x on the surface of a half-space,
    z into the body, tension positive):

        sigma_x = [-3x^3/rho^5 + (1-2nu)(x/rho^3 - 3x/(rho(rho+z)^2) + x^3/(rho^3(rho+z)^2)
                   + 2x^3/(rho^2(rho+z)^3))] / (2 pi)
        sigma_y = [-3xy^2/rho^5 + (1-2nu)(x/rho^3 - x/(rho(rho+z)^2) + xy^2/(rho^3(rho+z)^2)
                   + 2xy^2/(rho^2(rho+z)^3))] / (2 pi)
        tau_xy  = [-3x^2y/rho^5 + (1-2nu)(-y/(rho(rho+z)^2) + x^2y/(rho^3(rho+z)^2)
                   + 2x^2y/(rho^2(rho+z)^3))] / (2 pi)
        sigma_z = -3xz^2/(2 pi rho^5), tau_xz = -3x^2z/(2 pi rho^5), tau_yz = -3xyz/(2 pi rho^5)

    tests/test_stress_bem.py checks equilibrium (div sigma = 0), the free surface,
    the force balance on a depth plane (integral of tau_xz = -1) and, integrated over
    a long strip, the plane-strain traction field of linecontact.stresses.

    Parameters
    ----------
    x, y : array_like
        Field point [m].
    z : array_like
        Depth > 0 [m].
    poisson : float
        Poisson's ratio [-].

    Returns
    -------
    dict
        Component name -> stress per unit force [1/m^2].
    """
    x, y, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (x, y, z)))
    r = np.sqrt(x * x + y * y + z * z)
    k = 1.0 / (2.0 * np.pi)
    c = 1.0 - 2.0 * poisson
    rz = r + z
    r5 = r ** 5
    a = 1.0 / (r * rz * rz)
    bq = 1.0 / (r ** 3 * rz * rz) + 2.0 / (r * r * rz ** 3)
    return dict(
        sigma_x=k * (-3 * x ** 3 / r5 + c * (x / r ** 3 - 3 * x * a + x ** 3 * bq)),
        sigma_y=k * (-3 * x * y * y / r5 + c * (x / r ** 3 - x * a + x * y * y * bq)),
        sigma_z=-3 * k * x * z * z / r5,
        tau_xy=k * (-3 * x * x * y / r5 + c * (-y * a + x * x * y * bq)),
        tau_xz=-3 * k * x * x * z / r5,
        tau_yz=-3 * k * x * y * z / r5)


def rectangle_quadrature(point, x, y, z, dx, dy, poisson=0.3, per_depth=2.0, order=4):
    """The stresses below a uniform unit traction on a dx-by-dy rectangle centred at 0,
    by Gauss-Legendre quadrature of a point-force solution `point`
    (:func:`cerruti_point_stresses` or :func:`point_load_stresses`).

    The rectangle is cut into sub-cells no longer than z/per_depth per side, each
    integrated with an order x order Gauss rule: the point-force field varies over
    the depth z, so the rule resolves it (tests/test_stress_bem.py: on Boussinesq's
    point load it reproduces Love's closed form to 1e-6 of the surface traction).

    Parameters
    ----------
    point : callable
        point(x, y, z, poisson) -> dict of components per unit force.
    x, y : array_like
        Field points relative to the rectangle's centre [m].
    z : float
        Depth > 0 [m].
    dx, dy : float
        Rectangle sides [m].
    poisson : float
        Poisson's ratio [-].
    per_depth : float
        Sub-cells per depth z along each side (at least).
    order : int
        Gauss points per sub-cell side.

    Returns
    -------
    dict
        Component name -> stress per unit traction [-].
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    g, w = np.polynomial.legendre.leggauss(order)
    out = None
    nx = max(1, int(np.ceil(per_depth * dx / z)))
    ny = max(1, int(np.ceil(per_depth * dy / z)))
    ux = ((np.arange(nx)[:, None] + 0.5 * (g[None, :] + 1)) / nx - 0.5).ravel() * dx
    wx = np.tile(w * 0.5 / nx, nx) * dx
    uy = ((np.arange(ny)[:, None] + 0.5 * (g[None, :] + 1)) / ny - 0.5).ravel() * dy
    wy = np.tile(w * 0.5 / ny, ny) * dy
    for xi, wxi in zip(ux, wx):
        f = point(x[..., None] - xi, y[..., None] - uy, z, poisson)
        f = {k: (v * wy).sum(-1) * wxi for k, v in f.items()}
        if out is None:
            out = f
        else:
            for k in out:
                out[k] += f[k]
    return out


def traction_rectangle_stresses(x, y, z, dx, dy, poisson=0.3, direction="y"):
    """Stresses below a uniform unit tangential traction on a dx-by-dy rectangle.

    Cerruti's point force (:func:`cerruti_point_stresses`) integrated over the
    rectangle (:func:`rectangle_quadrature`); `direction` 'x' or 'y' is the
    traction's (in +y, the rolling direction across a roller, the x-traction field
    with x and y exchanged).

    Returns
    -------
    dict
        Component name -> stress per unit traction [-] (tension positive).
    """
    if direction == "x":
        return rectangle_quadrature(cerruti_point_stresses, x, y, z, dx, dy, poisson)
    f = rectangle_quadrature(cerruti_point_stresses, y, x, z, dy, dx, poisson)
    return dict(sigma_x=f["sigma_y"], sigma_y=f["sigma_x"], sigma_z=f["sigma_z"],
                tau_xy=f["tau_xy"], tau_xz=f["tau_yz"], tau_yz=f["tau_xz"])


def _edge_offsets(x, y, dx, dy):
    """The offsets X, Y (4, ...) of the points from the rectangle's corners and the
    corner signs, in the order of Love's sum (module docstring); refuses a point on
    a line through an edge, where the surface field is singular (log) or undefined."""
    a, b = 0.5 * float(dx), 0.5 * float(dy)
    x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
    X = np.stack([x + a, x + a, x - a, x - a])
    Y = np.stack([y + b, y - b, y + b, y - b])
    if np.any(X == 0) or np.any(Y == 0):
        raise ValueError("surface stresses: a field point lies on a line x = +-dx/2 or "
                         "y = +-dy/2 through the rectangle's edges, where the surface "
                         "field is singular; evaluate off those lines (e.g. at the "
                         "centres of a grid of such cells)")
    s = np.array([1.0, -1.0, -1.0, 1.0]).reshape((4,) + (1,) * x.ndim)
    return X, Y, s, (np.abs(x) < a) & (np.abs(y) < b)


def surface_pressure_stresses(x, y, dx, dy, poisson=0.3):
    """Stresses on the surface z = 0 of a uniform unit pressure on a dx-by-dy
    rectangle centred at 0 (Love 1929 at z = 0).

    Love's corner functions (module docstring) have finite limits as z -> 0 wherever
    the offsets X, Y from the corner are both non-zero, i.e. off the lines through
    the rectangle's edges; the terms with a factor z vanish, and

        d(psi1)/dz  : -(pi/2) sign(X) sign(Y)  (its corner sum: -2 pi inside, 0 outside)
        d2(H1)/dx2  :  atan(Y/X)        d2(H1)/dy2 : atan(X/Y)      d2(H1)/dxdy : ln r

    with r = sqrt(X^2 + Y^2), so that

        sigma_x = [2 nu d(psi1)/dz - (1 - 2 nu) d2(H1)/dx2] / (2 pi),
        sigma_y = [2 nu d(psi1)/dz - (1 - 2 nu) d2(H1)/dy2] / (2 pi),
        sigma_z = d(psi1)/dz / (2 pi) = -1 inside, 0 outside,
        tau_xy  = -(1 - 2 nu) d2(H1)/dxdy / (2 pi),  tau_xz = tau_yz = 0.

    Inside, sigma_x + sigma_y = -(1 + 2 nu) (Johnson 1985, section 3.2: the local
    term of Boussinesq's surface field; the rest, (1 - 2 nu)/(2 pi r^2) radial and
    its negative hoop, integrates to the atan terms). At the centre of a long cell
    (dx >> dy) sigma_x -> -2 nu, sigma_y -> -1: plane strain.

    Parameters
    ----------
    x, y : array_like
        Field points relative to the rectangle's centre, off the lines x = +-dx/2,
        y = +-dy/2 [m].
    dx, dy : float
        Rectangle sides [m].
    poisson : float
        Poisson's ratio [-].

    Returns
    -------
    dict
        Component name -> stress per unit pressure [-] (compression negative).
    """
    nu = float(poisson)
    X, Y, s, inside = _edge_offsets(x, y, dx, dy)
    k = 1.0 / (2.0 * np.pi)
    pz = -2.0 * np.pi * inside
    hxx = (s * np.arctan(Y / X)).sum(0)
    hyy = (s * np.arctan(X / Y)).sum(0)
    hxy = (s * 0.5 * np.log(X * X + Y * Y)).sum(0)
    zero = np.zeros(pz.shape)
    return dict(sigma_x=k * (2 * nu * pz - (1 - 2 * nu) * hxx),
                sigma_y=k * (2 * nu * pz - (1 - 2 * nu) * hyy),
                sigma_z=k * pz, tau_xy=-k * (1 - 2 * nu) * hxy, tau_xz=zero,
                tau_yz=zero.copy())


def surface_traction_stresses(x, y, dx, dy, poisson=0.3, direction="y"):
    """Stresses on the surface z = 0 of a uniform unit tangential traction on a
    dx-by-dy rectangle centred at 0, in closed form.

    Cerruti's point force Q_x (:func:`cerruti_point_stresses`; Johnson 1985, section
    3.3) at z = 0 (rho = r = sqrt(x^2 + y^2), rho + z = r) leaves on the surface

        sigma_x = -[2 (1 - 2 nu) x/r^3 + 6 nu x^3/r^5] / (2 pi),
        sigma_y = -6 nu x y^2 / (2 pi r^5),
        tau_xy  = -[(1 - 2 nu) y/r^3 + 6 nu x^2 y/r^5] / (2 pi),

    and sigma_z = tau_xz = tau_yz = 0 off the point. Over the rectangle each kernel
    K is Love's signed corner sum of a primitive F with d2F/dXdY = K (X, Y the
    offsets from a corner, r^2 = X^2 + Y^2; A = asinh(Y/|X|), B = asinh(X/|Y|), which
    are ln(Y + r) and ln(X + r) less a function of one offset that the corner sum
    cancels):

        x/r^3 : -A,   x^3/r^5 : -(2 A + Y/r)/3,   x y^2/r^5 : -(A - Y/r)/3,
        y/r^3 : -B,   x^2 y/r^5 : -(B - X/r)/3,

    so that (the 1 - 2 nu terms combine)

        sigma_x = sum [2 A + 2 nu Y/r] / (2 pi),   sigma_y = sum 2 nu [A - Y/r] / (2 pi),
        tau_xy  = sum [B - 2 nu X/r] / (2 pi).

    The kernels are odd (in x for sigma_x, sigma_y; in y for tau_xy) at every depth,
    so a neighbourhood of the field point symmetric about it contributes nothing at
    any z and the limit z -> 0 of the field inside the rectangle is this principal
    value (0 at its centre); the local terms are those of the boundary condition:
    tau_xz = -1 inside (the module's sign: Cerruti's tau_xz integrates to -Q_x over
    a depth plane), sigma_z = tau_yz = 0 (their point kernels z^2 x/rho^5, x y z/rho^5
    are odd as well). `direction` 'y' exchanges x and y (the traction in +y).

    Parameters
    ----------
    x, y : array_like
        Field points relative to the rectangle's centre, off the lines x = +-dx/2,
        y = +-dy/2 [m].
    dx, dy : float
        Rectangle sides [m].
    poisson : float
        Poisson's ratio [-].
    direction : {'x', 'y'}
        The traction's direction.

    Returns
    -------
    dict
        Component name -> stress per unit traction [-] (tension positive).
    """
    if direction not in ("x", "y"):
        raise ValueError(f"direction = {direction!r} is not 'x' or 'y'")
    if direction == "y":
        f = surface_traction_stresses(y, x, dy, dx, poisson, "x")
        return dict(sigma_x=f["sigma_y"], sigma_y=f["sigma_x"], sigma_z=f["sigma_z"],
                    tau_xy=f["tau_xy"], tau_xz=f["tau_yz"], tau_yz=f["tau_xz"])
    nu = float(poisson)
    X, Y, s, inside = _edge_offsets(x, y, dx, dy)
    k = 1.0 / (2.0 * np.pi)
    r = np.sqrt(X * X + Y * Y)
    A = np.arcsinh(Y / np.abs(X))
    B = np.arcsinh(X / np.abs(Y))
    zero = np.zeros(inside.shape)
    return dict(sigma_x=k * (s * (2 * A + 2 * nu * Y / r)).sum(0),
                sigma_y=k * (s * 2 * nu * (A - Y / r)).sum(0),
                sigma_z=zero, tau_xy=k * (s * (B - 2 * nu * X / r)).sum(0),
                tau_xz=-1.0 * inside, tau_yz=zero.copy())


def measures(f):
    """Tresca (max shear), von Mises and orthogonal shear |tau_yz| of a field dict
    (:func:`linecontact.stresses.stress_measures`, the measures' one home)."""
    return stress_measures(f["sigma_x"], f["sigma_y"], f["sigma_z"], f["tau_xy"],
                           f["tau_xz"], f["tau_yz"])


class StressField:
    """The 3D field below a pressure on an nx x ny grid of dx x dy cells, plane by plane.

    Parameters
    ----------
    nx, ny : int
        Cells along x and y.
    dx, dy : float
        Cell sides [m].
    poisson : float
        Poisson's ratio [-].
    backend, workers
        As tools.bem.halfspace.DCFFTOperator.

    Call :meth:`plane` with the cell pressures and a depth: the six components at the
    cell centres (nx x ny each) [Pa].
    """

    def __init__(self, nx, ny, dx, dy, poisson=0.3, backend="scipy", workers=None):
        self.shape = (int(nx), int(ny))
        self.dx, self.dy, self.poisson = float(dx), float(dy), float(poisson)
        self.backend, self.workers = backend, workers
        ox = wraparound_offsets(self.shape[0]) * self.dx
        oy = wraparound_offsets(self.shape[1]) * self.dy
        self._X, self._Y = np.meshgrid(ox, oy, indexing="ij")
        self._ops = {}

    def operators(self, z):
        """The six convolution operators of depth z (kept for reuse)."""
        key = float(z)
        if key not in self._ops:
            k = rectangle_stresses(self._X, self._Y, key, self.dx, self.dy, self.poisson)
            self._ops[key] = {c: DCFFTOperator(*self.shape, self.dx, self.dy,
                                               backend=self.backend, workers=self.workers,
                                               kernel_wrapped=k[c]) for c in COMPONENTS}
        return self._ops[key]

    def traction_kernels(self, z):
        """The six kernels of a unit traction in +y on one cell at depth z, at the
        wrapped offsets: a 2 x 2 Gauss rule per cell where the offset exceeds three
        times max(z, cell sides) along either axis, the subdivided rule of
        :func:`rectangle_quadrature` (sub-cells <= z/2, 4 x 4 Gauss) nearer."""
        z = float(z)
        k = {c: np.zeros(self._X.shape) for c in COMPONENTS}
        g, w = np.polynomial.legendre.leggauss(2)
        for gi, wi in zip(g, w):
            for gj, wj in zip(g, w):
                f = cerruti_point_stresses(self._Y - 0.5 * gj * self.dy,
                                           self._X - 0.5 * gi * self.dx, z, self.poisson)
                f = dict(sigma_x=f["sigma_y"], sigma_y=f["sigma_x"], sigma_z=f["sigma_z"],
                         tau_xy=f["tau_xy"], tau_xz=f["tau_yz"], tau_yz=f["tau_xz"])
                for c in COMPONENTS:
                    k[c] += 0.25 * wi * wj * f[c] * self.dx * self.dy
        reach = 3 * max(z, self.dx, self.dy)
        near = (np.abs(self._X) <= reach) & (np.abs(self._Y) <= reach)
        fn = traction_rectangle_stresses(self._X[near], self._Y[near], z, self.dx,
                                         self.dy, self.poisson, direction="y")
        for c in COMPONENTS:
            k[c][near] = fn[c]
        return k

    def traction_operators(self, z):
        """The six convolution operators of a traction in +y at depth z."""
        key = ("t", float(z))
        if key not in self._ops:
            k = self.traction_kernels(z)
            self._ops[key] = {c: DCFFTOperator(*self.shape, self.dx, self.dy,
                                               backend=self.backend, workers=self.workers,
                                               kernel_wrapped=k[c]) for c in COMPONENTS}
        return self._ops[key]

    def plane(self, pressure, z, keep=False, traction=None):
        """Six stress components at depth z > 0 below the cell pressures [Pa], and
        with `traction` (cell tractions in +y [Pa]) the traction's field as well:
        then a pair (pressure's, traction's)."""
        ops = self.operators(z)
        first = ops[COMPONENTS[0]]
        phat = first.transform(np.asarray(pressure, dtype=float))
        out = {c: ops[c].from_transform(phat) for c in COMPONENTS}
        if traction is not None:
            tops = self.traction_operators(z)
            that = tops[COMPONENTS[0]].transform(np.asarray(traction, dtype=float))
            tout = {c: tops[c].from_transform(that) for c in COMPONENTS}
        if not keep:
            self._ops.pop(float(z), None)
            self._ops.pop(("t", float(z)), None)
        return out if traction is None else (out, tout)

    def surface_operators(self):
        """The twelve convolution operators of the surface z = 0: the pressure's and
        the traction's in +y (:func:`surface_pressure_stresses`,
        :func:`surface_traction_stresses`: closed forms at every offset, the
        cell-centre offsets lying off the cells' edge lines), kept for reuse."""
        if "s" not in self._ops:
            kp = surface_pressure_stresses(self._X, self._Y, self.dx, self.dy,
                                           self.poisson)
            kt = surface_traction_stresses(self._X, self._Y, self.dx, self.dy,
                                           self.poisson, direction="y")
            for key, k in (("s", kp), ("st", kt)):
                self._ops[key] = {c: DCFFTOperator(*self.shape, self.dx, self.dy,
                                                   backend=self.backend,
                                                   workers=self.workers,
                                                   kernel_wrapped=k[c])
                                  for c in COMPONENTS}
        return self._ops["s"], self._ops["st"]

    def surface(self, pressure, traction=None, keep=False):
        """Six stress components on the surface z = 0 at the cell centres below the
        cell pressures [Pa], as :meth:`plane` (with `traction`, cell tractions in +y
        [Pa]: a pair (pressure's, traction's)); exact for the piecewise-constant
        cells, local terms included (sigma_z = -p, tau_yz = -q in the cell)."""
        ops, tops = self.surface_operators()
        phat = ops[COMPONENTS[0]].transform(np.asarray(pressure, dtype=float))
        out = {c: ops[c].from_transform(phat) for c in COMPONENTS}
        if traction is not None:
            that = tops[COMPONENTS[0]].transform(np.asarray(traction, dtype=float))
            tout = {c: tops[c].from_transform(that) for c in COMPONENTS}
        if not keep:
            self._ops.pop("s", None)
            self._ops.pop("st", None)
        return out if traction is None else (out, tout)

    def maxima(self, pressure, depths):
        """Largest of each measure over the grid and the given depths, with where.

        Returns
        -------
        dict
            Measure -> dict(value [Pa], i, j (cell indices), z [m]).
        """
        best = {m: dict(value=-1.0, i=0, j=0, z=0.0) for m in MEASURES}
        for z in depths:
            f = measures(self.plane(pressure, z))
            for m in MEASURES:
                v = f[m]
                k = int(np.argmax(v))
                if v.flat[k] > best[m]["value"]:
                    i, j = np.unravel_index(k, v.shape)
                    best[m] = dict(value=float(v.flat[k]), i=int(i), j=int(j), z=float(z))
        return best

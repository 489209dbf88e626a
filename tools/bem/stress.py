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

Traction: the tangential (Cerruti) rectangle is not implemented here; the study of
tools/studies/stress_study.py compares frictionless fields (docs/stresses.md).

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

from linecontact.stresses import rectangle_stresses

from .halfspace import DCFFTOperator, wraparound_offsets

COMPONENTS = ("sigma_x", "sigma_y", "sigma_z", "tau_xy", "tau_xz", "tau_yz")
MEASURES = ("tresca", "von_mises", "orthogonal_shear")


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


def measures(f):
    """Tresca (max shear), von Mises and orthogonal shear |tau_yz| of a field dict."""
    sx, sy, sz = f["sigma_x"], f["sigma_y"], f["sigma_z"]
    txy, txz, tyz = f["tau_xy"], f["tau_xz"], f["tau_yz"]
    T = np.stack([np.stack([sx, txy, txz], -1), np.stack([txy, sy, tyz], -1),
                  np.stack([txz, tyz, sz], -1)], -2)
    ev = np.linalg.eigvalsh(T)
    vm = np.sqrt(np.maximum(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2)
                            + 3 * (txy ** 2 + txz ** 2 + tyz ** 2), 0.0))
    return dict(tresca=0.5 * (ev[..., -1] - ev[..., 0]), von_mises=vm,
                orthogonal_shear=np.abs(tyz))


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

    def plane(self, pressure, z, keep=False):
        """Six stress components at depth z > 0 below the cell pressures [Pa]."""
        ops = self.operators(z)
        first = ops[COMPONENTS[0]]
        phat = first.transform(np.asarray(pressure, dtype=float))
        out = {c: ops[c].from_transform(phat) for c in COMPONENTS}
        if not keep:
            self._ops.pop(float(z), None)
        return out

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

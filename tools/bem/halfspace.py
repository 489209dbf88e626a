"""Convolution operators of the free (non-periodic) elastic half-space.

Two operators map cell pressures to cell-centre displacements, u = K * p, with the
influence coefficients of :mod:`tools.bem.influence`:

``DCFFTOperator``
    The DC-FFT of Liu, Wang & Liu (2000): pressures on nx x ny cells are zero-padded
    to 2nx x 2ny, the kernel is stored in wrap-around order, and one real FFT
    convolution gives the exact linear (free-space) result. Any pressure field.

``SymmetricOperator``
    The same linear convolution for fields even in x and in y (both mirror planes of
    the cylinder and of a sphere), acting on one quarter. The quarter, zero-padded to
    the full nx x ny, is a half-sample-symmetric sequence of period 2nx x 2ny, whose
    DFT is a type-II DCT; the even kernel's DFT is a type-I DCT. The convolution
    theorem then reads u = IDCT-II( DCT-I(K) * DCT-II(p) ), on nx x ny points
    instead of 2nx x 2ny: four times fewer points than the DC-FFT, same numbers
    (tests/test_bem.py checks the two against each other to 1e-12).

FFT backends are chosen by name: ``"scipy"`` (scipy.fft, always present, threads via
``workers``) or ``"pyfftw"`` (planned FFTW transforms, when the package is installed). An unknown name lists the valid ones.
"""
from __future__ import annotations

import os

import numpy as np

from .influence import kernel_offsets

BACKENDS = ("scipy", "pyfftw")


def default_workers(backend="scipy"):
    """Threads for the transforms: all cores for scipy.fft; one for FFTW.

    FFTW's multi-threaded plans were measured far slower on this 2-core machine
    whenever anything else ran (128 x 128 quarter: plan 38 s and 8 ms per call with
    two threads against 0.5 s and 0.9 ms with one; docs/history.md, "3D BEM"), and
    the studies run one process per core anyway.
    """
    if backend == "pyfftw":
        return 1
    return os.cpu_count() or 1


def _fft_module(backend):
    if backend == "scipy":
        import scipy.fft as fft
        return fft
    if backend == "pyfftw":
        try:
            import pyfftw
            import pyfftw.interfaces.scipy_fft as fft
        except ImportError as exc:  # pragma: no cover - depends on the machine
            raise ImportError("backend 'pyfftw' needs the pyfftw package "
                              "(pip install pyfftw)") from exc
        pyfftw.interfaces.cache.enable()
        pyfftw.interfaces.cache.set_keepalive_time(60.0)
        return fft
    raise ValueError(f"backend = {backend!r} is not one of the valid FFT backends "
                     f"{BACKENDS}")


def best_backend():
    """'pyfftw' when it is installed, else 'scipy'."""
    try:
        import pyfftw  # noqa: F401
    except ImportError:
        return "scipy"
    return "pyfftw"


def _offsets(kernel, nx, ny, dx, dy, estar):
    """The kernel at offsets 0..nx, 0..ny: the given one (its shape checked) or Love's."""
    if kernel is None:
        return kernel_offsets(nx, ny, dx, dy, estar)
    k = np.asarray(kernel, dtype=float)
    if k.shape != (nx + 1, ny + 1):
        raise ValueError(f"kernel shape = {k.shape} is not the {(nx + 1, ny + 1)} of "
                         f"offsets 0..{nx}, 0..{ny} that this grid needs")
    return k


class DCFFTOperator:
    """Free-space displacement of an nx x ny grid of cells (any pressure field).

    Parameters
    ----------
    nx, ny : int
        Cells along x and y.
    dx, dy : float
        Cell sides [m].
    estar : float
        Effective modulus [Pa].
    backend : {'scipy', 'pyfftw'}
    workers : int, optional
        Threads for the FFTs.
    kernel : ndarray, optional
        Another kernel even in both offsets, as its values at offsets 0..nx, 0..ny
        ((nx + 1) x (ny + 1), e.g. tools.bem.influence.cerruti_kernel_offsets) [m/Pa]; by
        default Love's normal one, tools.bem.influence.kernel_offsets with `estar`
        (ignored when a kernel is given).
    """

    def __init__(self, nx, ny, dx, dy, estar=1.0, backend="scipy", workers=None,
                 kernel=None, kernel_wrapped=None):
        self.shape = (int(nx), int(ny))
        self.dx, self.dy, self.estar = float(dx), float(dy), float(estar)
        self._fft = _fft_module(backend)
        self.workers = default_workers(backend) if workers is None else workers
        if kernel_wrapped is not None:
            # any parity (odd shear kernels of tools.bem.stress): the caller gives the
            # kernel at wraparound_offsets(nx) x wraparound_offsets(ny)
            kw = np.asarray(kernel_wrapped, dtype=float)
            if kw.shape != (2 * nx, 2 * ny):
                raise ValueError(f"kernel_wrapped shape = {kw.shape} is not the "
                                 f"{(2 * nx, 2 * ny)} of wraparound_offsets")
        else:
            k = _offsets(kernel, nx, ny, dx, dy, estar)        # offsets 0..n
            # wrap-around order on 2n: offsets 0..n-1, then n (either sign), then
            # -(n-1)..-1
            kx = np.concatenate([k, k[-2:0:-1]], axis=0)
            kw = np.concatenate([kx, kx[:, -2:0:-1]], axis=1)
        self._khat = self._fft.rfft2(kw, workers=self.workers)
        self._pad = np.zeros((2 * nx, 2 * ny))

    def precondition(self, g):
        """M g with M ~ K^-1: the inverse of the periodic (circulant) embedding of K on
        the padded 2nx x 2ny grid, applied to g padded with zeros and cropped (a
        conjugate-gradient preconditioner; tools.bem.solver.bounded_cg). Divisors are kept
        at least 1e-3 of the largest (the embedding of a free-space kernel can have
        symbol values near zero)."""
        if not hasattr(self, "_kinv"):
            kh = self._khat.real
            self._kinv = 1.0 / np.maximum(kh, 1e-3 * np.abs(kh).max())
        nx, ny = self.shape
        self._pad[:nx, :ny] = g
        z = self._fft.irfft2(self._kinv * self._fft.rfft2(self._pad, workers=self.workers),
                             s=self._pad.shape, workers=self.workers)
        return z[:nx, :ny].copy()

    def transform(self, p):
        """The zero-padded field's real FFT (reusable by several operators on one grid)."""
        nx, ny = self.shape
        self._pad[:nx, :ny] = p
        return self._fft.rfft2(self._pad, workers=self.workers)

    def from_transform(self, phat):
        """The convolution K * p from the transform of p (:meth:`transform`)."""
        nx, ny = self.shape
        u = self._fft.irfft2(self._khat * phat, s=self._pad.shape, workers=self.workers)
        return u[:nx, :ny].copy()

    def __call__(self, p):
        return self.from_transform(self.transform(p))


def wraparound_offsets(n):
    """Cell offsets 0..n-1, n, -(n-1)..-1: the wrap-around order of a 2n-point DC-FFT
    (the offset n never reaches the n cells' result)."""
    i = np.arange(2 * n)
    return np.where(i <= n, i, i - 2 * n)


class SymmetricOperator:
    """Free-space displacement of a field even in x and y, acting on one quarter.

    The full grid has 2mx x 2my cells, symmetric about x = 0 and y = 0; the operator
    takes and returns the quarter x > 0, y > 0 (mx x my cells, cell (0, 0) touching
    both mirror planes). Parameters as :class:`DCFFTOperator`, with the quarter's
    cell counts. With ``backend='pyfftw'`` the two transforms are FFTW r2r plans
    (REDFT10 = DCT-II, REDFT01 = its unnormalised inverse) made once with
    FFTW_MEASURE; the normalisation 1/(4 * 2mx * 2my) is folded into the kernel.
    A ``kernel`` given instead of Love's holds the offsets 0..2mx, 0..2my
    ((2mx + 1) x (2my + 1)).
    """

    def __init__(self, mx, my, dx, dy, estar=1.0, backend="scipy", workers=None,
                 kernel=None):
        self.shape = (int(mx), int(my))
        self.dx, self.dy, self.estar = float(dx), float(dy), float(estar)
        self.backend = backend
        self.workers = default_workers(backend) if workers is None else workers
        fft = _fft_module("scipy" if backend == "pyfftw" else backend)
        k = _offsets(kernel, 2 * mx, 2 * my, dx, dy, estar)  # offsets 0..2m: DCT-I samples
        self._k = k
        khat = fft.dctn(k, type=1, workers=self.workers)[:2 * mx, :2 * my]
        # the preconditioner's spectrum: the same kernel embedded symmetric-periodically
        # on the quarter itself (offsets 0..m, period 2m: no zero padding)
        kq = fft.dctn(k[:mx + 1, :my + 1], type=1, workers=self.workers)[:mx, :my]
        self._kinv = np.ascontiguousarray(1.0 / np.maximum(kq, 1e-3 * np.abs(kq).max()))
        shape = (2 * mx, 2 * my)
        if backend == "pyfftw":
            _fft_module("pyfftw")
            import pyfftw
            self._pad = pyfftw.zeros_aligned(shape)
            self._spec = pyfftw.empty_aligned(shape)
            self._out = pyfftw.empty_aligned(shape)
            flags = ("FFTW_MEASURE", "FFTW_DESTROY_INPUT")
            self._dct2 = pyfftw.FFTW(self._pad, self._spec, axes=(0, 1),
                                     direction=("FFTW_REDFT10",) * 2, flags=flags,
                                     threads=self.workers)
            self._dct3 = pyfftw.FFTW(self._spec, self._out, axes=(0, 1),
                                     direction=("FFTW_REDFT01",) * 2, flags=flags,
                                     threads=self.workers)
            self._khat = khat / (4.0 * shape[0] * shape[1])
            self._q_in = pyfftw.empty_aligned(self.shape)
            self._q_spec = pyfftw.empty_aligned(self.shape)
            self._q_out = pyfftw.empty_aligned(self.shape)
            self._q_dct2 = pyfftw.FFTW(self._q_in, self._q_spec, axes=(0, 1),
                                       direction=("FFTW_REDFT10",) * 2, flags=flags,
                                       threads=self.workers)
            self._q_dct3 = pyfftw.FFTW(self._q_spec, self._q_out, axes=(0, 1),
                                       direction=("FFTW_REDFT01",) * 2, flags=flags,
                                       threads=self.workers)
            self._kinv /= 4.0 * mx * my
        else:
            self._fft = fft
            self._pad = np.zeros(shape)
            self._khat = np.ascontiguousarray(khat)

    def precondition(self, g):
        """M g with M ~ K^-1: the inverse of the kernel's symmetric-periodic embedding on
        the quarter itself (period 2 mx x 2 my, no zero padding: one DCT pair of the
        quarter's size, a quarter of an operator application's transform), a
        conjugate-gradient preconditioner (tools.bem.solver.bounded_cg). Divisors are
        kept at least 1e-3 of the largest. (The padded embedding, the operator's own
        transforms with the spectrum inverted, needed about 7 % fewer iterations at
        4 times the cost per application: docs/history.md, "3D BEM".)"""
        if self.backend == "pyfftw":
            self._q_in[...] = g
            self._q_dct2()
            self._q_spec *= self._kinv
            self._q_dct3(normalise_idft=False)
            return self._q_out.copy()
        c = self._fft.dctn(g, type=2, workers=self.workers)
        c *= self._kinv
        return self._fft.idctn(c, type=2, workers=self.workers)

    @property
    def sparse_limit(self):
        """Most cells for which :meth:`add_columns` costs less than one operator
        application: a column is about five passes over the quarter, a transform pair
        grows like its log (19-23 times a column on 256 x 64 to 256 x 256 quarters,
        docs/history.md, "3D BEM"); half that, for margin."""
        mx, my = self.shape
        return max(2, int(np.log2(mx * my)) // 2)

    def add_columns(self, u, cells, values):
        """u += K x for an x nonzero on a few cells only (``cells``: their flat indices,
        ``values``: x there), by direct summation of the kernel's columns instead of a
        transform pair: for cell (a, b) of the quarter, the field of the cell and of its
        three mirror images, k(|i - a|, |j - b|) + k(i + a + 1, |j - b|) +
        k(|i - a|, j + b + 1) + k(i + a + 1, j + b + 1). Equal to ``u + self(x)`` to
        rounding; cheaper than it for up to :attr:`sparse_limit` cells."""
        mx, my = self.shape
        k = self._k
        for c, v in zip(np.asarray(cells).ravel(), np.asarray(values).ravel()):
            a, b = divmod(int(c), my)
            ncol = my + b + 1
            rows = np.empty((mx, ncol))
            rows[:a] = k[a:0:-1, :ncol]
            rows[a:] = k[:mx - a, :ncol]
            rows += k[a + 1:a + 1 + mx, :ncol]
            rows *= v
            u[:, :b] += rows[:, b:0:-1]
            u[:, b:] += rows[:, :my - b]
            u += rows[:, b + 1:b + 1 + my]
        return u

    def __call__(self, p):
        mx, my = self.shape
        if self.backend == "pyfftw":
            # FFTW_DESTROY_INPUT may overwrite the padding: clear it every call
            self._pad[...] = 0.0
            self._pad[:mx, :my] = p
            self._dct2()
            self._spec *= self._khat
            self._dct3(normalise_idft=False)
            return self._out[:mx, :my].copy()
        self._pad[:mx, :my] = p
        c = self._fft.dctn(self._pad, type=2, workers=self.workers)
        c *= self._khat
        return self._fft.idctn(c, type=2, workers=self.workers)[:mx, :my].copy()


def unfold(quarter):
    """The full field (2mx x 2my) from its quarter x > 0, y > 0, by the two mirrors."""
    top = np.concatenate([quarter[::-1, :], quarter], axis=0)
    return np.concatenate([top[:, ::-1], top], axis=1)

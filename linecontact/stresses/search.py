r"""The 3D correction of the roller stresses: the worst point of each measure.

Where the load varies along the roller (a crown, a relief, a tilt) the field is
three-dimensional and the strips are up to 5 % low; the worst of each measure
therefore gets a 3D correction: below the worst slices, McEwen's strip of the slice
plus the 3D field of the difference between the slices' Hertz pressures and that strip
extended to infinity, from Love's uniformly loaded rectangles
(:func:`~linecontact.stresses.love.rectangle_stresses`; Love 1929) on a grid of 24 cells across and one cell per slice along (one per slice
and across beyond 8 b). Its error against a 3D field (Love's and Cerruti's rectangles
below a 3D boundary-element pressure, tools/bem/stress.py) is measured in
tables/stress_accuracy.csv (tools/studies/stress_study.py) and stated in each
result's ``error`` and notes.

The search (:func:`_worst_3d`): the strips' optimum points score candidate slices,
the best are refined by a zoomed grid search in (y, z) (docs/stresses.md).

References
----------
.. [1] A. E. H. Love, "The stress produced in a semi-infinite solid by pressure on
   part of the boundary", Phil. Trans. R. Soc. A 228 (1929) 377-420.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   2.2-2.3 (line loads), 4.2 (Hertz strip), 7.2 (sliding).
"""
from __future__ import annotations

import numpy as np

from .love import _CORNERS, _PYZ, _corners_c, _love_batches, _love_c, _love_components
from .measures import MEASURES, _measure_3d
from .strip import _unit_strip

__all__ = []


def _hertz_cell_means(edges, b):
    """Mean of sqrt(1 - y^2/b^2) over each cell [edges[i], edges[i+1]] (0 beyond b);
    b a scalar, or an array of half-widths (one row of cells each; 0 for none); edges
    one row for all, or one row per half-width."""
    b = np.asarray(b, dtype=float)[..., None]
    pos = b > 0
    bs = np.where(pos, b, 1.0)
    u = np.minimum(np.maximum(edges / bs, -1.0), 1.0)
    prim = 0.5 * (u * np.sqrt(1.0 - u * u) + np.arcsin(u))     # int sqrt(1-u^2) du
    out = (prim[..., 1:] - prim[..., :-1]) * bs / (edges[..., 1:] - edges[..., :-1])
    return np.where(pos, out, 0.0)


#: 3D correction: cells across the contact, near-field half-window over b
_N_Y = 24
_NEAR = 8.0
#: 3D search: zooms after the first 5 x 5 grid (3 x 3 each), window shrink per zoom
_ZOOMS = 3
_SHRINK = 2.5
#: the 3D search: every loaded slice's parts scanned first (a stride of n/this), and
#: how many best slices of each measure get the first (coarse) window (and the end
#: slices where p0 rises towards the end)
_STRIDE_PARTS = 4
_COARSE_SLICES = 1
#: off the ends, how many best slices of each measure (by its score at the strip's
#: optimum point) get the first (coarse) grid of the search (None: every candidate,
#: p0's largest +-2 and its other peaks +-1), and how many of those, the best after
#: it, go on to the zooms: below a narrow pressure peak (an end relief's junction with
#: the straight part) the best-scored slice is not always the one whose 3D worst is
#: largest. Over the 68 rollers off the ends of tools/benchmarks/bench_stress_search.py
#: (the stress study's 106 with the relief set's drawn end reliefs) the largest
#: shortfall below the search under every slice was 8.216 % with the former choice
#: (the best-scored slice and the best of p0's largest +-2 zoomed) and 0.042 % with
#: every candidate's first grid and the best zoomed
#: (tools/benchmarks/results/stress_search.txt)
_TOP = None
_ZOOMED = 1
#: p0's local maxima within this factor of the largest are candidates too
_PEAK_MARGIN = 1.1
#: where the contact reaches an end, each measure is also scored at these depths
#: over b (towards an end the 3D worst rises from the strip's 0.5-0.79 b to 0.35-0.4 b
#: below an end slice, and to ~0.15-0.2 b on the thin slices next to an end peak)
_SHALLOW_Z = (0.4, 0.2)
_SHALLOW_NEAR = 1.5


def _slice_edges(xc):
    """The slices' edges along the roller (midpoints; the end slices mirrored)."""
    n = xc.size
    xe = np.empty(n + 1)
    xe[1:-1] = 0.5 * (xc[1:] + xc[:-1])
    xe[0] = xc[0] - 0.5 * (xc[1] - xc[0])
    xe[-1] = xc[-1] + 0.5 * (xc[-1] - xc[-2])
    return xe


#: 0, 1, ..., _N_Y: the near grid's edges are -B + (2B/_N_Y) i (np.linspace's)
_STEPS_Y = np.arange(_N_Y + 1, dtype=float)


def _corners_3d(xc, b, p0, k0, xe=None):
    """Corner positions and weights of the pressure difference p - p_k0 (a row of
    Hertz strips, one per slice, minus the strip of slice k0 extended to infinity);
    `xe` the slices' edges (:func:`_slice_edges`, computed if not given)."""
    return _corners_many(xc, b, p0, [k0], xe)[0]


def _corners_many(xc, b, p0, ks, xe=None):
    """:func:`_corners_3d` of each slice k0 of `ks`: a list of (cx, cy, w); the
    slices' Hertz cell means on every k0's grid in one evaluation."""
    n = xc.size
    if xe is None:
        xe = _slice_edges(xc)
    L = xe[-1] - xe[0]
    q = 0.5 * np.pi * p0 * b                        # the line loads
    # near field: a common grid across |y| <= B, each slice's Hertz profile averaged
    # onto its cells; minus slice k0's profile; the extension of k0's strip beyond the
    # roller's ends (to +-1e6 L) closes the infinite strip whose field is McEwen's
    heads, rows_b = [], []
    for k0 in ks:
        b0, x0 = b[k0], xc[k0]
        near = np.abs(xc - x0) <= _NEAR * b0
        near[max(k0 - 2, 0):k0 + 3] = True
        at = np.flatnonzero(near)
        i0, i1 = int(at[0]), int(at[-1])
        bn = b[i0:i1 + 1]
        heads.append((k0, i0, i1, max(float(bn.max()), b0)))
        rows_b += [b[k0:k0 + 1], bn]
    B = np.array([h[3] for h in heads])
    ye = _STEPS_Y * ((B + B) / _N_Y)[:, None] - B[:, None]   # np.linspace(-B, B, _N_Y + 1)
    ye[:, -1] = B
    sizes = [h[2] - h[1] + 2 for h in heads]
    means_all = _hertz_cell_means(np.repeat(ye, sizes, axis=0), np.concatenate(rows_b))
    out, off = [], 0
    for (k0, i0, i1, _), ye, size in zip(heads, ye, sizes):
        means = means_all[off:off + size]
        off += size
        out.append(_corners_assemble(xe, L, b, p0, q, k0, i0, i1, ye, means))
    return out


def _corners_assemble(xe, L, b, p0, q, k0, i0, i1, ye, means):
    """The corners of :func:`_corners_3d` from k0's near window [i0, i1], its grid
    across ye and the cell means (k0's row, then the window's slices')."""
    if _CORNERS[0] == "c":
        got = _corners_c(xe, L, b, p0, q, k0, i0, i1, ye, means)
        if got is not None:
            return got
    n = b.size
    b0 = b[k0]
    ref = p0[k0] * means[0]
    lo_ext, hi_ext = int(i0 == 0), int(i1 == n - 1)
    rows = i1 - i0 + 1 + lo_ext + hi_ext
    # the cells' pressures with a frame of zeros: their corners' weights are the
    # mixed differences
    Pp = np.zeros((rows + 2, _N_Y + 2))
    Pp[1 + lo_ext:rows + 1 - hi_ext, 1:-1] = p0[i0:i1 + 1, None] * means[1:] - ref
    if lo_ext:
        Pp[1, 1:-1] = -ref
    if hi_ext:
        Pp[rows, 1:-1] = -ref
    xs = np.empty(rows + 1)
    xs[lo_ext:rows + 1 - hi_ext] = xe[i0:i1 + 2]
    if lo_ext:
        xs[0] = xe[0] - 1e6 * L
    if hi_ext:
        xs[-1] = xe[-1] + 1e6 * L
    W = Pp[1:, 1:] - Pp[1:, :-1] - Pp[:-1, 1:] + Pp[:-1, :-1]
    nn = W.size
    # far field (beyond _NEAR b0, where the distribution across matters to (b/r)^2
    # of a small difference): one cell per slice across |y| <= max(b, b0) with the
    # difference of the mean pressures (q - q_k0)/(2 max(b, b0)); beyond the roller's
    # ends (if the near grid does not reach them) k0's strip, one cell
    nl, nr = i0, n - 1 - i1                         # far slices left and right
    m = nl + nr + (1 - lo_ext) + (1 - hi_ext)       # far cells, the ends' included
    cx, cy, w = np.empty(nn + 4 * m), np.empty(nn + 4 * m), np.empty(nn + 4 * m)
    cx[:nn].reshape(rows + 1, _N_Y + 1)[:] = xs[:, None]
    cy[:nn].reshape(rows + 1, _N_Y + 1)[:] = ye
    w[:nn] = W.ravel()
    if m == 0:
        keep = w != 0
        return cx[keep], cy[keep], w[keep]
    q0 = q[k0]
    lo_x, hi_x, bf, dq = np.empty(m), np.empty(m), np.empty(m), np.empty(m)
    lo_x[:nl], hi_x[:nl] = xe[:nl], xe[1:nl + 1]
    lo_x[nl:nl + nr], hi_x[nl:nl + nr] = xe[i1 + 1:n], xe[i1 + 2:]
    bf[:nl], bf[nl:nl + nr] = b[:nl], b[i1 + 1:]
    np.maximum(bf[:nl + nr], b0, out=bf[:nl + nr])
    dq[:nl], dq[nl:nl + nr] = q[:nl], q[i1 + 1:]
    dq[:nl + nr] -= q0
    j = nl + nr
    if not lo_ext:
        lo_x[j], hi_x[j], bf[j], dq[j] = xe[0] - 1e6 * L, xe[0], b0, -q0
        j += 1
    if not hi_ext:
        lo_x[j], hi_x[j], bf[j], dq[j] = xe[-1], xe[-1] + 1e6 * L, b0, -q0
    pm = dq / (2 * bf)
    fx, fy, fw = cx[nn:].reshape(4, m), cy[nn:].reshape(4, m), w[nn:].reshape(4, m)
    fx[0], fx[1], fx[2], fx[3] = lo_x, lo_x, hi_x, hi_x
    fy[0], fy[2] = -bf, -bf
    fy[1], fy[3] = bf, bf
    fw[0], fw[3] = pm, pm
    fw[1], fw[2] = -pm, -pm
    # adjacent far cells of the same half-width share the corners on their common
    # edge (every cell below a slice narrower than b0, and the ends' extensions, has
    # half-width b0), and the near grid's end corners at +-B those of a far cell as
    # wide: one corner each, with the sum of the weights (exactly 0 between two
    # unloaded slices)
    order = np.lexsort((cy, cx))
    cx, cy, w = cx[order], cy[order], w[order]
    first = np.empty(cx.size, dtype=bool)
    first[0] = True
    np.not_equal(cx[1:], cx[:-1], out=first[1:])
    first[1:] |= cy[1:] != cy[:-1]
    at = np.flatnonzero(first)
    cx, cy, w = cx[at], cy[at], np.add.reduceat(w, at)
    keep = w != 0
    return cx[keep], cy[keep], w[keep]


def _field_3d(x, b, p0, mu, nu, batches, corners):
    """Stresses at points below slices: McEwen's strip of the slice (pressure and
    traction) plus the 3D field of the pressure's difference from it (Love's
    rectangles; `corners(k)` gives slice k's offsets along the roller (1, n), its
    corners across (n,) and weights (n,), from :func:`_corners_3d`). `batches`: a list
    of (k, py, pz, shear_only), the points (py, pz) below slice k; returns per batch
    the six components (sigma_x, sigma_y, sigma_z, tau_xy, tau_xz, tau_yz), or with
    `shear_only` tau_yz alone (the orthogonal shear's one component, one corner
    function). The corner sums are per slice; the strips' fields and the components
    of all batches are evaluated at once."""
    sums = [None] * len(batches)
    full = [i for i, bt in enumerate(batches) if not bt[3]]
    for group, only in ((full, None), ([i for i in range(len(batches)) if batches[i][3]],
                                       _PYZ)):
        items = []
        for i in group:
            k, py, pz, _ = batches[i]
            X, cy, w = corners(k)
            t = _love_c(X, cy, w, py, pz, only) if _CORNERS[0] == "c" else None
            if t is not None:
                sums[i] = t
            else:
                items.append((i, (X, py[:, None] - cy[None, :], pz[:, None], w)))
        for (i, _), t in zip(items, _love_batches([it for _, it in items], only)
                             if items else ()):
            sums[i] = t
    sizes = [bt[1].size for bt in batches]
    ends = [0]
    for size in sizes:
        ends.append(ends[-1] + size)
    if len(batches) == 1:
        k, py, pz = batches[0][:3]
        bk, s0 = b[k], p0[k]
    else:
        py = np.concatenate([bt[1] for bt in batches])
        pz = np.concatenate([bt[2] for bt in batches])
        ks = [bt[0] for bt in batches]
        bk, s0 = np.repeat(b[ks], sizes), np.repeat(p0[ks], sizes)
    sx, sy, sz, tyz = _unit_strip(py / bk, pz / bk, mu, nu)
    sx, sy, sz, tyz = s0 * sx, s0 * sy, s0 * sz, s0 * tyz
    if full:
        if len(full) == 1:
            T, rows = sums[full[0]], slice(ends[full[0]], ends[full[0] + 1])
        else:
            T = np.concatenate([sums[i] for i in full], axis=1)
            rows = np.concatenate([np.arange(ends[i], ends[i + 1]) for i in full])
        d = _love_components(T, pz[rows], nu)
        comps = (sx[rows] + d[0], sy[rows] + d[1], sz[rows] + d[2], d[3], d[4],
                 tyz[rows] + d[5])
    out, j = [], 0
    for i, (k, py_, pz_, shear) in enumerate(batches):
        r = slice(ends[i], ends[i + 1])
        if shear:
            out.append(tyz[r] - (1.0 / (2.0 * np.pi)) * pz[r] * sums[i][_PYZ])
        else:
            out.append(tuple(c[j:j + sizes[i]] for c in comps))
            j += sizes[i]
    return out


def _search_grids():
    grids = []
    for n in (5, 3):
        u = np.linspace(-1.0, 1.0, n)
        U, V = (a.ravel() for a in np.meshgrid(u, u, indexing="ij"))
        keep = np.arange(U.size) != U.size // 2          # the centre: the best so far
        grids.append((U[keep], V[keep]))
    return grids


#: the 3D search's grids in (y, z) over the window's half-sides: 5 x 5 then 3 x 3,
#: each without its centre (the best point so far, whose value is known)
_SEARCH_GRIDS = _search_grids()


def _worst_3d(x, b, p0, mu, nu, m, wide=False, every=False):
    """The worst of each measure with the 3D correction (:func:`_field_3d`): the
    strip's optimum point below candidate slices scores them (p0's largest and two
    either side, p0's other local maxima within _PEAK_MARGIN; with `wide`, the
    contact at an end, also _STRIDE_PARTS + 1 slices spread over the loaded ones and
    every local maximum of p0 with its neighbours, each measure's best then climbing
    along the roller to a local maximum of the scanned slices, and every measure
    scored at shallower points too, z = _SHALLOW_Z b, where the worst lies near an
    end); each measure's candidate slices (the _TOP best, all by default, of which
    the _ZOOMED best after the first grid go on to the zooms; _COARSE_SLICES where
    the contact reaches an end) and the best of p0's largest +-2 (the former search's
    choice) each get a 5 x 5 grid in (y, z) around its better point (+-0.4 b, +-0.3
    b), then (off the ends the _ZOOMED best of them after that grid) three zooms of a
    3 x 3 grid (window / 2.5 each); the best is the worst.
    Measures whose strip optimum lies within 0.1 b of the surface keep the strip's
    value (None here).

    Each grid's centre is the best point so far, whose value is known, so it is not
    evaluated again; the points below the same slice are summed in one batch per
    pass (the orthogonal shear's apart, with tau_yz alone), each slice's corners
    built once (:func:`_corners_3d`) with their offsets along the roller. With
    `every`, every loaded slice is scanned and searched (a check of the choice)."""
    cache = {}
    xe = _slice_edges(x)

    def corners(k):
        if k not in cache:
            add([k])
        return cache[k]

    def add(ks):
        for k, (cx, cy, w) in zip(ks, _corners_many(x, b, p0, ks, xe)):
            cache[k] = ((x[k] - cx)[None, :], cy, w)

    def evaluate(pts):
        """pts: (name, ...) -> (k, py, pz); the measure `name` at those points below
        slice k, the points below one slice in one batch (the orthogonal shear's
        apart)."""
        batches, groups = [], []
        for shear in (False, True):
            rest = [n for n in pts if (n[0] == "orthogonal_shear") == shear]
            while rest:
                k = pts[rest[0]][0]
                group = [n for n in rest if pts[n][0] == k]
                rest = [n for n in rest if pts[n][0] != k]
                if len(group) == 1:
                    py, pz = pts[group[0]][1:]
                else:
                    py = np.concatenate([pts[n][1] for n in group])
                    pz = np.concatenate([pts[n][2] for n in group])
                batches.append((k, py, pz, shear))
                groups.append(group)
        out = {}
        for group, res in zip(groups, _field_3d(x, b, p0, mu, nu, batches, corners)):
            i0 = 0
            for n in group:
                i1 = i0 + pts[n][1].size
                out[n] = (np.abs(res[i0:i1]) if n[0] == "orthogonal_shear"
                          else _measure_3d(n[0], *(c[i0:i1] for c in res)))
                i0 = i1
        return out

    names = [n for n in MEASURES if m.z[n] >= 0.1]
    if not names:                       # every maximum at the surface (mu >= ~0.4)
        return {name: None for name in MEASURES}
    # the candidate slices, each scored by the 3D field at every measure's strip
    # optimum: p0's largest and two either side (every measure's strip maximum is a
    # constant times p0, so this is each measure's strip worst; taken from p0 itself,
    # so that rounding cannot split two mirror slices), p0's other local maxima along
    # the roller and their neighbours (a two-peaked pressure); where the contact
    # reaches an end (the 3D field departs from the strip's there: the worst can sit
    # on an end slice or well inside it) also every s-th loaded slice, the ends
    # included, and every local maximum of p0, each measure's best then climbing
    # along the roller (every measure scored at shallower points too)
    loaded = np.flatnonzero(b > 0)
    k = int(np.argmax(p0))
    seen = set()

    def scan(ks):
        ks = sorted({int(kk) for kk in ks if 0 <= kk < x.size and b[kk] > 0
                     and (in_half is None or not wide or in_half(kk))} - seen)
        if not ks:
            return 0
        seen.update(ks)
        add([kk for kk in ks if kk not in cache])
        # each measure's strip optimum and, where the contact reaches an end, on
        # the slices within _SHALLOW_NEAR b of a loaded end, its shallower points
        # (there the 3D worst rises far above the strip's depth); a slice's score is
        # the best of them, which the zooms start from
        base = [(m.y[n], m.z[n]) for n in names]
        more = base + [(m.y[n], zz) for n in shallow for zz in _SHALLOW_Z]
        near = [kk for kk in ks if shallow and min(x[kk] - xe[loaded[0]],
                                                   xe[loaded[-1] + 1] - x[kk])
                < _SHALLOW_NEAR * b[kk]]
        groups = [(g, p) for g, p in (([kk for kk in ks if kk not in near], base),
                                      (near, more)) if g]
        batches = [(kk, np.array([u for u, _ in p]) * b[kk],
                    np.array([v for _, v in p]) * b[kk], False)
                   for g, p in groups for kk in g]
        res = iter(_field_3d(x, b, p0, mu, nu, batches, corners))
        for g, p in groups:
            cols = [np.array(c) for c in zip(*(next(res) for _ in g))]
            for i, name in enumerate(names):
                js = [i] + ([len(names) + shallow.index(name) * len(_SHALLOW_Z) + d
                             for d in range(len(_SHALLOW_Z))]
                            if p is more and name in shallow else [])
                v = _measure_3d(name, *(c[:, js] for c in cols))
                best = np.argmax(v, axis=1)
                for s_, kk in enumerate(g):
                    j = js[best[s_]]
                    score[name][kk] = float(v[s_, best[s_]])
                    start[name][kk] = (p[j][0] * b[kk], p[j][1] * b[kk])
        return len(ks)

    score = {name: {} for name in names}
    start = {name: {} for name in names}
    shallow = ([n for n in names if m.z[n] > max(_SHALLOW_Z)]
               if wide or every else [])
    # p0's other local maxima whose strip worst is within the 3D correction's reach
    # off the ends (the strips up to 5 % low: a margin of 10 %) of the largest
    inner = ((p0[1:-1] > p0[:-2]) & (p0[1:-1] >= p0[2:])
             & (_PEAK_MARGIN * p0[1:-1] >= p0[k]))
    peaks = np.flatnonzero(inner) + 1
    if x.size > 2 and np.allclose(x, -x[::-1], rtol=0, atol=1e-12 * np.ptp(x)) \
            and np.allclose(p0, p0[::-1], rtol=1e-12, atol=0):
        # a mirror-symmetric load: its mirror slices tie, so one half is scanned
        mid = (x.size - 1) / 2
        in_half = (lambda kk: kk <= mid + 1) if k <= mid else (lambda kk: kk >= mid - 1)
        peaks = peaks[[in_half(pk) for pk in peaks]] if peaks.size else peaks
    else:
        in_half = None
    if every:
        in_half = None
        scan(loaded)
    elif not wide:
        scan(list(range(k - 2, k + 3)) + [pk + d for pk in peaks for d in (-1, 0, 1)])
    else:
        # every s-th loaded slice, counted from either end (a mirror-symmetric set),
        # and every local maximum of p0 with its neighbours (where the orthogonal
        # shear, whose 3D correction is small, has its worst off the ends)
        j = np.arange(_STRIDE_PARTS + 1)
        half = np.floor(np.minimum(j, _STRIDE_PARTS - j) * (loaded.size - 1)
                        / _STRIDE_PARTS + 0.5).astype(int)
        even = loaded[np.where(2 * j <= _STRIDE_PARTS, half, loaded.size - 1 - half)]
        tops = np.flatnonzero((p0[1:-1] > p0[:-2]) & (p0[1:-1] >= p0[2:])) + 1
        scan(list(range(k - 2, k + 3)) + list(even)
             + [pk + d for pk in tops for d in (-1, 0, 1)])
        # then each measure's best climbs along the roller until both its neighbours
        # are scanned and lower (a local maximum of the scanned slices)
        while scan([kb + d for name in names
                    for kb in (max(score[name], key=score[name].get),)
                    for d in (-1, 1)]):
            pass
    st = {}
    near_k = [kk for kk in range(k - 2, k + 3) if kk in score[names[0]]]
    for name in names:
        # the best slices by their one point (_TOP, or _COARSE_SLICES where the contact
        # reaches an end), each given the first grid (off the ends the _ZOOMED best of
        # them then the zooms, at an end all); the best result is the worst
        top = sorted(score[name], key=score[name].get,
                     reverse=True)[:_COARSE_SLICES if wide else _TOP]
        if every:
            top = sorted(score[name])
        # and the best of p0's largest +-2 (the former search's choice; at an end its
        # zooms may start from a shallower point and end up to ~0.7 % below the
        # former search's; off the ends, where only the best after the first grid
        # is zoomed, it was never below the former choice over bench_stress_search's
        # 68 rollers, though that is not guaranteed)
        kk = max(near_k, key=score[name].get)
        top += [kk] if kk not in top else []
        st[name] = [dict(k=kk, val=score[name][kk], by=start[name][kk][0],
                         bz=start[name][kk][1], hy=0.4 * b[kk], hz=0.3 * b[kk])
                    for kk in top]
    # every candidate: a 5 x 5 grid, then three zooms of a 3 x 3 grid, all candidates'
    # points below one slice in one batch per pass
    for it in range(_ZOOMS + 1):
        U, V = _SEARCH_GRIDS[min(it, 1)]
        pts = {(name, j): (c["k"], c["by"] + c["hy"] * U,
                           np.maximum(c["bz"] + c["hz"] * V, 0.05 * b[c["k"]]))
               for name in names for j, c in enumerate(st[name])}
        for key, v in evaluate(pts).items():
            c = st[key[0]][key[1]]
            i = int(np.argmax(v))
            if v[i] > c["val"]:
                c["val"], c["by"], c["bz"] = float(v[i]), pts[key][1][i], pts[key][2][i]
            c["hy"] /= _SHRINK
            c["hz"] /= _SHRINK
        if it == 0 and _ZOOMED is not None and not wide and not every:
            # after the first (coarse) grid, the best _ZOOMED candidates go on
            st = {name: sorted(c, key=lambda d: d["val"], reverse=True)[:_ZOOMED]
                  for name, c in st.items()}
    st = {name: max(c, key=lambda d: d["val"]) for name, c in st.items()}
    out = {name: None for name in MEASURES}
    for name in names:
        c = st[name]
        out[name] = dict(value=c["val"], x=float(x[c["k"]]), y=float(c["by"]),
                         z=float(c["bz"]), slice=c["k"])
    return out

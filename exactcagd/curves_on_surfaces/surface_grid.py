"""A surface seen as a grid of rational Bézier patches, with exact derivative bounds.

Yang et al. (004), section 2 step 1 / section 3: a NURBS surface is split into
rational Bézier patches by knot insertion.  :class:`SurfaceGrid` extracts a patch
only when a curve needs it (blossoming, :func:`exactcagd.exact.knots.span_bezier`),
and gives for each patch, in its local coordinates ``[0, 1]^2``:

* the exact partial derivatives ``S_u = (N_u W - N W_u) / W^2`` (same for ``v``) as
  homogeneous nets (a polynomial patch gives its hodographs);
* :meth:`SurfaceGrid.lipschitz_sq`: an exact rational bound
  ``max_box |S_u|^2 + max_box |S_v|^2`` over a box, from the convex-hull property of
  the derivative nets restricted to the box (their weights ``W^2`` have positive
  Bernstein coefficients, so each derivative value is a convex combination of the
  projected coefficients).  This is the constant of the 3-D bound of
  ``proofs/yang_hausdorff.py``.

>>> from exactcagd import BezierSurface
>>> g = SurfaceGrid(BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]))
>>> g.lipschitz_sq((0, 0), (0, 1), (0, 1))        # |S_u|^2 <= 2, |S_v|^2 <= 2
mpq(4,1)
"""

from __future__ import annotations

import bisect
from functools import lru_cache

import flint
import numpy as np
from gmpy2 import mpq

from ..errors import DomainError, InputError
from ..exact import bernstein as bz
from ..exact import knots as kn
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineSurface

__all__ = ["SurfaceGrid", "MAX_LEVEL"]

#: Finest dyadic level of the cached derivative-bound cells of a patch.
MAX_LEVEL = 4


class SurfaceGrid:
    """Lazy patch access for a ``BezierSurface`` or ``BSplineSurface`` (NURBS)."""

    def __init__(self, surface):
        if isinstance(surface, BezierSurface):
            self._bspline = None
            self._single = surface.homogeneous()
            self.u_breaks = (mpq(0), mpq(1))
            self.v_breaks = (mpq(0), mpq(1))
            self.degree = surface.degree
        elif isinstance(surface, BSplineSurface):
            self._bspline = surface
            self._single = None
            self.u_breaks, self.v_breaks = surface.breakpoints()
            self.degree = surface.degree
        else:
            raise InputError(f"surface must be a BezierSurface or BSplineSurface, got {type(surface).__name__}")
        self.dimension = surface.dimension
        self.rational = surface.is_rational
        self._strips: dict = {}
        self._patches: dict = {}
        self._derivs: dict = {}
        self._full_bounds: dict = {}
        self._hom_net = None
        self._cells: dict = {}
        self._partials: dict = {}
        self._matrices: dict = {}

    # ------------------------------------------------------------------ layout
    @property
    def domain(self) -> tuple:
        return (self.u_breaks[0], self.u_breaks[-1]), (self.v_breaks[0], self.v_breaks[-1])

    @property
    def shape(self) -> tuple[int, int]:
        return len(self.u_breaks) - 1, len(self.v_breaks) - 1

    def spans(self, key) -> tuple:
        i, j = key
        return (self.u_breaks[i], self.u_breaks[i + 1]), (self.v_breaks[j], self.v_breaks[j + 1])

    def locate(self, u, v) -> tuple[int, int]:
        """Patch index ``(i, j)`` whose closed span contains ``(u, v)`` (lower span on a knot line)."""
        (u0, u1), (v0, v1) = self.domain
        if not (u0 <= u <= u1 and v0 <= v <= v1):
            raise DomainError(f"point ({float(u):.6g}, {float(v):.6g}) lies outside the surface domain")
        i = min(max(bisect.bisect_left(self.u_breaks, u) - 1, 0), self.shape[0] - 1)
        j = min(max(bisect.bisect_left(self.v_breaks, v) - 1, 0), self.shape[1] - 1)
        return i, j

    def to_local(self, key, point) -> tuple:
        (ua, ub), (va, vb) = self.spans(key)
        return (point[0] - ua) / (ub - ua), (point[1] - va) / (vb - va)

    def to_global(self, key, point) -> tuple:
        (ua, ub), (va, vb) = self.spans(key)
        return ua + (ub - ua) * point[0], va + (vb - va) * point[1]

    def direction_to_local(self, key, d) -> tuple:
        (ua, ub), (va, vb) = self.spans(key)
        return d[0] / (ub - ua), d[1] / (vb - va)

    # ------------------------------------------------------------------ patches
    def patch_hom(self, key) -> np.ndarray:
        """Homogeneous net ``(w P, w)`` of patch ``key`` over its local ``[0, 1]^2``."""
        if self._single is not None:
            if key != (0, 0):
                raise DomainError(f"a Bézier surface has one patch, not {key}")
            return self._single
        if key not in self._patches:
            s = self._bspline
            p, q = s.degree
            i, j = key
            if i not in self._strips:
                if self._hom_net is None:
                    self._hom_net = s._array() if s.is_rational else _with_unit_weights(s._array())
                _, strip = kn.span_bezier(self._hom_net, s.knots_u, p, i)
                self._strips[i] = np.moveaxis(strip, 1, 0)
            _, patch = kn.span_bezier(self._strips[i], s.knots_v, q, j)
            self._patches[key] = np.moveaxis(patch, 0, 1)
        return self._patches[key]

    def patch(self, key) -> BezierSurface:
        hom = self.patch_hom(key)
        if not self.rational:
            return BezierSurface._trusted(hom[..., :-1] / hom[..., -1:], None)
        return BezierSurface.from_homogeneous(hom)

    # ------------------------------------------------------------------ derivatives
    def derivative_nets(self, key) -> tuple[np.ndarray, np.ndarray]:
        """Homogeneous nets of ``S_u`` and ``S_v`` (local coordinates), exact."""
        if key not in self._derivs:
            hom = self.patch_hom(key)
            out = []
            for axis in (0, 1):
                if not self.rational:
                    pts = hom[..., :-1] / hom[..., -1:]
                    if hom.shape[axis] == 1:
                        d = pts * 0
                    else:
                        d = bz.along(axis, bz.derivative, pts)
                    ones = np.full(d.shape[:-1] + (1,), mpq(1), dtype=object)
                    out.append(np.concatenate([d, ones], axis=-1))
                    continue
                num, w = hom[..., :-1], hom[..., -1:]
                if hom.shape[axis] == 1:
                    top = bz.product_tensor(num, w) * 0
                else:
                    d_num, d_w = bz.along(axis, bz.derivative, num), bz.along(axis, bz.derivative, w)
                    top = bz.along(axis, bz.elevate, bz.product_tensor(d_num, w) - bz.product_tensor(num, d_w), 1)
                out.append(np.concatenate([top, bz.product_tensor(w, w)], axis=-1))
            self._derivs[key] = tuple(out)
        return self._derivs[key]

    def lipschitz_sq(self, key, u_range, v_range) -> mpq:
        """Exact bound ``max |S_u|^2 + max |S_v|^2`` over the box (local coordinates).

        Valid because each derivative net restricted to a sub-box of ``[0, 1]^2`` has
        positive weights; its projected coefficients' convex hull contains every
        derivative value there.  The box is covered by dyadic cells of the patch (side
        ``2^-k`` not smaller than the box, ``k <= MAX_LEVEL``) whose bounds are cached;
        the maximum over the covering cells is returned.
        """
        u0, u1 = (mpq(x) for x in u_range)
        v0, v1 = (mpq(x) for x in v_range)
        size = max(u1 - u0, v1 - v0)
        level = 0
        while level < MAX_LEVEL and size <= mpq(1, 2 ** (level + 1)):
            level += 1
        n = 2**level
        cells_u = range(min(int(u0 * n), n - 1), min(int(u1 * n), n - 1) + 1)
        cells_v = range(min(int(v0 * n), n - 1), min(int(v1 * n), n - 1) + 1)
        best_u, best_v = mpq(0), mpq(0)
        for cu in cells_u:
            for cv in cells_v:
                bu, bv = self._cell_bounds(key, level, cu, cv)
                best_u, best_v = max(best_u, bu), max(best_v, bv)
        return best_u + best_v

    def _cell_bounds(self, key, level: int, cu: int, cv: int) -> tuple:
        ck = (key, level, cu, cv)
        if ck not in self._cells:
            out = []
            for net, matrix in zip(self.derivative_nets(key), self._derivative_matrices(key)):
                (p, q), d = net.shape[:2], net.shape[-1]
                # restricted net: rows (i, k), columns j; (M_u (x) I_d) X M_v^T in exact rationals
                r = _restriction_kron(p - 1, level, cu, d) * matrix * _restriction_matrix(q - 1, level, cv).transpose()
                entries = r.entries()
                best = flint.fmpq(0)
                for i in range(p):
                    for j in range(q):
                        row = [entries[(i * d + k) * q + j] for k in range(d)]
                        w = row[-1]
                        if w <= 0:  # pragma: no cover - W^2 restricted inside [0,1]^2 stays positive
                            raise ArithmeticError("derivative net lost weight positivity")
                        sq = sum((x * x for x in row[:-1]), flint.fmpq(0)) / (w * w)
                        if sq > best:
                            best = sq
                out.append(mpq(int(best.p), int(best.q)))
            self._cells[ck] = tuple(out)
        return self._cells[ck]

    def _derivative_matrices(self, key) -> tuple:
        """The derivative nets as flint matrices, rows ``(i, k)`` (u index, coordinate), columns ``j``."""
        if key not in self._matrices:
            mats = []
            for net in self.derivative_nets(key):
                p, q, d = net.shape
                flat = [net[i, j, k] for i in range(p) for k in range(d) for j in range(q)]
                mats.append(flint.fmpq_mat(p * d, q, [_fmpq(x) for x in flat]))
            self._matrices[key] = tuple(mats)
        return self._matrices[key]

    def global_lipschitz_sq(self, key) -> mpq:
        """Bound of ``|S_u|^2 + |S_v|^2`` over the whole patch in *global* coordinates."""
        if key not in self._full_bounds:
            (ua, ub), (va, vb) = self.spans(key)
            total = mpq(0)
            for net, width in zip(self.derivative_nets(key), (ub - ua, vb - va)):
                best = max(sum(x * x for x in row[:-1]) / (row[-1] * row[-1]) for row in net.reshape(-1, net.shape[-1]))
                total += best / (width * width)
            self._full_bounds[key] = total
        return self._full_bounds[key]

    def tangent(self, key, point, direction) -> tuple:
        """Exact surface tangent ``S_u du + S_v dv`` at a local point for a local direction."""
        vec = None
        for partial, c in zip(self.partials(key, point), direction):
            val = [x * c for x in partial]
            vec = val if vec is None else [a + b for a, b in zip(vec, val)]
        return tuple(vec)

    def partials(self, key, point) -> tuple:
        """Exact ``(S_u, S_v)`` at a local point (cached: the joints ask for them several times)."""
        ck = (key, tuple(point))
        try:
            return self._partials[ck]
        except KeyError:
            pass
        except TypeError:  # pragma: no cover - unhashable coordinates
            return self._partials_at(key, point)
        self._partials[ck] = out = self._partials_at(key, point)
        return out

    def _partials_at(self, key, point) -> tuple:
        u, v = point
        out = []
        for net in self.derivative_nets(key):
            h = bz.de_casteljau(bz.de_casteljau(net, u), v)
            out.append(tuple(x / h[-1] for x in h[:-1]))
        return tuple(out)

    def patches_near(self, u_range, v_range) -> list:
        """Keys of the patches whose closed spans meet the box (global coordinates)."""
        (ua, ub), (va, vb) = u_range, v_range
        ilo = max(bisect.bisect_right(self.u_breaks, ua) - 2, 0)
        ihi = min(bisect.bisect_left(self.u_breaks, ub), self.shape[0] - 1)
        jlo = max(bisect.bisect_right(self.v_breaks, va) - 2, 0)
        jhi = min(bisect.bisect_left(self.v_breaks, vb), self.shape[1] - 1)
        out = []
        for i in range(ilo, ihi + 1):
            for j in range(jlo, jhi + 1):
                (a, b), (c, d) = self.spans((i, j))
                if a <= ub and ua <= b and c <= vb and va <= d:
                    out.append((i, j))
        return out


def _fmpq(x) -> flint.fmpq:
    x = mpq(x)
    return flint.fmpq(int(x.numerator), int(x.denominator))


@lru_cache(maxsize=None)
def _restriction_matrix(n: int, level: int, cell: int) -> flint.fmpq_mat:
    """``M`` with ``restrict(c, cell / 2^level, (cell + 1) / 2^level) = M c`` for degree ``n``
    (the restriction of the identity's columns, :func:`exactcagd.exact.bernstein.restrict`)."""
    eye = np.array([[mpq(int(i == j)) for j in range(n + 1)] for i in range(n + 1)], dtype=object)
    scale = 2**level
    m = eye if level == 0 else bz.restrict(eye, mpq(cell, scale), mpq(cell + 1, scale))
    return flint.fmpq_mat(n + 1, n + 1, [_fmpq(x) for x in m.flat])


@lru_cache(maxsize=None)
def _restriction_kron(n: int, level: int, cell: int, d: int) -> flint.fmpq_mat:
    """``M (x) I_d``: the restriction along ``u`` acting on rows ``(i, k)``."""
    m = _restriction_matrix(n, level, cell).entries()
    size = (n + 1) * d
    out = [flint.fmpq(0)] * (size * size)
    for i in range(n + 1):
        for j in range(n + 1):
            for k in range(d):
                out[(i * d + k) * size + j * d + k] = m[i * (n + 1) + j]
    return flint.fmpq_mat(size, size, out)


def _with_unit_weights(net: np.ndarray) -> np.ndarray:
    ones = np.full(net.shape[:-1] + (1,), mpq(1), dtype=object)
    return np.concatenate([net, ones], axis=-1)

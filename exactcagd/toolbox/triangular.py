"""Triangular (rational) Bézier patches, exact (Sederberg's notes (003) 15.9.2).

``r(u, v) = sum_{i+j+k=n} w_ijk P_ijk B^n_ijk(u, v) / sum w_ijk B^n_ijk(u, v)`` with
``B^n_ijk = n!/(i! j! k!) u^i v^j (1 - u - v)^k`` (15.58).  The patch is also a
tensor-product patch of degree ``n x n`` (:meth:`TriangularBezier.to_tensor_product`),
which is how the notes derive its corner curvature.

>>> from exactcagd.toolbox.triangular import TriangularBezier
>>> t = TriangularBezier({(1, 0, 0): [1, 0, 0], (0, 1, 0): [0, 1, 0], (0, 0, 1): [0, 0, 0]})
>>> t.evaluate("1/4", "1/2")
(mpq(1,4), mpq(1,2), mpq(0,1))
"""

from __future__ import annotations

from math import factorial

import numpy as np
from gmpy2 import mpq

from ..errors import DomainError, InputError, WeightError
from ..exact import bernstein as bz
from ..exact.scalars import to_rational, to_rational_array, to_sympy
from ..geometry.bezier_surface import BezierSurface

__all__ = ["TriangularBezier"]


def _multinomial(n, i, j, k) -> int:
    return factorial(n) // (factorial(i) * factorial(j) * factorial(k))


class TriangularBezier:
    """A triangular Bézier patch of degree ``n`` with exact control points and optional weights.

    Parameters
    ----------
    control_points : dict ``{(i, j, k): point}`` with ``i + j + k = n`` for all ``(n+1)(n+2)/2`` indices
    weights : dict ``{(i, j, k): w}``, optional (non-zero; positive for a proper patch)
    """

    __slots__ = ("_n", "_pts", "_w", "_dim")

    def __init__(self, control_points: dict, weights: dict | None = None):
        if not control_points:
            raise InputError("no control points")
        keys = list(control_points)
        n = sum(keys[0])
        expected = {(i, j, n - i - j) for i in range(n + 1) for j in range(n + 1 - i)}
        if set(keys) != expected:
            raise InputError(f"a degree-{n} triangular patch needs exactly the indices i+j+k={n}")
        self._n = n
        self._pts = {key: tuple(to_rational_array(p, where=f"P{key}")) for key, p in control_points.items()}
        dims = {len(p) for p in self._pts.values()}
        if len(dims) != 1:
            raise InputError("control points of different dimension")
        self._dim = dims.pop()
        if weights is None:
            self._w = None
        else:
            if set(weights) != expected:
                raise WeightError("one weight per control point")
            self._w = {key: to_rational(w, where=f"w{key}") for key, w in weights.items()}
            if any(w == 0 for w in self._w.values()):
                raise WeightError("weights must be non-zero")

    @property
    def degree(self) -> int:
        return self._n

    @property
    def dimension(self) -> int:
        return self._dim

    @property
    def is_rational(self) -> bool:
        return self._w is not None

    def point(self, i, j, k) -> tuple:
        return self._pts[(i, j, k)]

    def weight(self, i, j, k):
        return mpq(1) if self._w is None else self._w[(i, j, k)]

    def _hom(self, key):
        w = self.weight(*key)
        return tuple(w * x for x in self._pts[key]) + (w,)

    def evaluate(self, u, v) -> tuple:
        """Exact point (Bernstein sum; ``u, v >= 0``, ``u + v <= 1`` not enforced)."""
        u, v = to_rational(u, where="u"), to_rational(v, where="v")
        n = self._n
        acc = [mpq(0)] * (self._dim + 1)
        for key in self._pts:
            i, j, k = key
            b = _multinomial(n, i, j, k) * u**i * v**j * (1 - u - v) ** k
            acc = [a + b * h for a, h in zip(acc, self._hom(key))]
        if acc[-1] == 0:
            raise DomainError("weight function vanishes here")
        return tuple(a / acc[-1] for a in acc[:-1])

    def tensor_homogeneous(self) -> np.ndarray:
        """Homogeneous net ``(w P, w)`` of the same patch as a degree ``n x n`` tensor-product patch.

        Each ``B^n_ijk`` is expanded in powers ``u^a v^b`` and converted to the tensor
        Bernstein basis of degree ``n`` in each variable (notes 3.3 per axis).  Weights of
        the tensor form may vanish or be negative away from the corner ``(0, 0)`` (the
        square extends beyond the triangle).
        """
        n = self._n
        power = np.empty((n + 1, n + 1, self._dim + 1), dtype=object)
        power[...] = mpq(0)
        for key in self._pts:
            i, j, k = key
            h = self._hom(key)
            c = _multinomial(n, i, j, k)
            # u^i v^j (1 - u - v)^k = sum_{a+b<=k} k!/(a! b! (k-a-b)!) (-u)^a (-v)^b u^i v^j
            for a in range(k + 1):
                for b in range(k + 1 - a):
                    coef = c * _multinomial(k, a, b, k - a - b) * (-1) ** (a + b)
                    power[i + a, j + b] += np.array([coef * x for x in h], dtype=object)
        hom = bz.along(0, bz.from_power, power, n)
        return bz.along(1, bz.from_power, hom, n)

    def to_tensor_product(self) -> BezierSurface:
        """The patch as a tensor-product :class:`BezierSurface` (raises :class:`WeightError` when
        a tensor weight vanishes; use :meth:`tensor_homogeneous` then)."""
        hom = self.tensor_homogeneous()
        if self._w is None:
            return BezierSurface._trusted(hom[..., :-1] / hom[..., -1:], None)
        return BezierSurface.from_homogeneous(hom)

    def to_sympy(self, u=None, v=None):
        """The patch as a sympy column Matrix of rational functions of ``u, v``."""
        import sympy

        u = sympy.Symbol("u") if u is None else u
        v = sympy.Symbol("v") if v is None else v
        n = self._n
        comps = [0] * (self._dim + 1)
        for key in self._pts:
            i, j, k = key
            b = _multinomial(n, i, j, k) * u**i * v**j * (1 - u - v) ** k
            comps = [c + b * to_sympy(h) for c, h in zip(comps, self._hom(key))]
        return sympy.Matrix([sympy.expand(c) / sympy.expand(comps[-1]) for c in comps[:-1]])

    def __repr__(self) -> str:
        kind = "rational " if self.is_rational else ""
        return f"<{kind}TriangularBezier degree={self._n} dimension={self._dim}>"

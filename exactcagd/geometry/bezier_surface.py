"""Exact polynomial and rational tensor-product Bézier surfaces.

Source: Sederberg's notes (003), chapter 15 (15.1 tensor-product patches, 15.2
de Casteljau on surfaces, 15.3 tangents and normals); Lasser & Bonneau (000) section II.

The control net has shape ``(l + 1, m + 1, d)``: axis 0 runs with ``u`` (degree ``l``),
axis 1 with ``v`` (degree ``m``).  ``F(u, v) = sum_ij w_ij P_ij B^l_i(u) B^m_j(v) /
sum_ij w_ij B^l_i(u) B^m_j(v)``.

>>> from exactcagd import BezierSurface
>>> s = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
>>> s.degree
(1, 1)
>>> s.evaluate("1/2", "1/2")
(mpq(1,2), mpq(1,2), mpq(1,4))
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DimensionError, DomainError, InputError
from ..exact import bernstein as bz
from ..exact.scalars import rational_str, short_repr, to_count, to_float, to_rational, to_sympy
from ._validate import check_stored_degree, dehomogenize, exchange_fields, homogeneous, point_array, unit_parameter, weight_array
from .bezier_curve import BezierCurve

__all__ = ["BezierSurface"]


class BezierSurface:
    """A tensor-product Bézier surface of degree ``(l, m)`` with exact data.

    Parameters
    ----------
    control_net : nested sequence, shape ``(l + 1, m + 1, d)``
    weights : nested sequence, shape ``(l + 1, m + 1)``, optional
        Positive weights; ``None`` for a polynomial surface.

    Examples
    --------
    >>> s = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    >>> s.iso_u("1/2").control_points
    ((mpq(1,2), mpq(0,1), mpq(0,1)), (mpq(1,2), mpq(1,1), mpq(1,2)))
    """

    __slots__ = ("_net", "_weights")

    def __init__(self, control_net, weights=None):
        net = point_array(control_net, 2, "control_net", bezier=True)
        self._net = net
        self._weights = weight_array(weights, net.shape[:2], "weights")

    @classmethod
    def _trusted(cls, net: np.ndarray, weights: np.ndarray | None) -> "BezierSurface":
        surface = object.__new__(cls)
        surface._net, surface._weights = net, weights
        return surface

    @classmethod
    def from_homogeneous(cls, hom) -> "BezierSurface":
        """Surface from a homogeneous net ``(w P, w)`` (weights non-zero, any sign)."""
        net, weights = dehomogenize(np.asarray(hom, dtype=object))
        return cls._trusted(net, weights)

    def homogeneous(self) -> np.ndarray:
        """Homogeneous net ``(w P, w)``, shape ``(l + 1, m + 1, d + 1)``."""
        return homogeneous(self._net, self._weights)

    def _array(self) -> np.ndarray:
        return self._net if self._weights is None else self.homogeneous()

    def _wrap(self, array: np.ndarray) -> "BezierSurface":
        if self._weights is None:
            return BezierSurface._trusted(array, None)
        return BezierSurface.from_homogeneous(array)

    def _wrap_curve(self, array: np.ndarray) -> BezierCurve:
        if self._weights is None:
            return BezierCurve._trusted(array, None)
        return BezierCurve.from_homogeneous(array)

    # ------------------------------------------------------------------ properties
    @property
    def degree(self) -> tuple[int, int]:
        """Stored bidegree ``(l, m)``."""
        return self._net.shape[0] - 1, self._net.shape[1] - 1

    @property
    def dimension(self) -> int:
        return self._net.shape[2]

    @property
    def is_rational(self) -> bool:
        return self._weights is not None

    @property
    def control_net(self) -> tuple:
        """Control net as nested tuples of ``mpq``, indexed ``[i][j][coordinate]``."""
        return tuple(tuple(tuple(p) for p in row) for row in self._net)

    @property
    def weights(self) -> tuple | None:
        return None if self._weights is None else tuple(tuple(row) for row in self._weights)

    def net_array(self) -> np.ndarray:
        """A copy of the control net as an exact object array."""
        return self._net.copy()

    def weights_array(self) -> np.ndarray:
        """A copy of the weights (all ones for a polynomial surface)."""
        if self._weights is None:
            out = np.empty(self._net.shape[:2], dtype=object)
            out[...] = mpq(1)
            return out
        return self._weights.copy()

    # ------------------------------------------------------------------ evaluation
    def evaluate(self, u, v, extrapolate: bool = False) -> tuple:
        """Exact point ``F(u, v)`` by tensor-product de Casteljau (notes 15.2)."""
        u = unit_parameter(u, "u", allow_outside=extrapolate)
        v = unit_parameter(v, "v", allow_outside=extrapolate)
        row = bz.de_casteljau(self._array(), u)  # shape (m + 1, ...)
        point = bz.de_casteljau(row, v)
        if self._weights is None:
            return tuple(point)
        if point[-1] == 0:
            raise DomainError(f"the rational surface has a pole at (u, v) = ({u}, {v})")
        return tuple(x / point[-1] for x in point[:-1])

    __call__ = evaluate

    def iso_u(self, u, extrapolate: bool = False) -> BezierCurve:
        """The iso-parameter curve ``v -> F(u0, v)`` (degree ``m``), exact (notes 15.2)."""
        u = unit_parameter(u, "u", allow_outside=extrapolate)
        return self._wrap_curve(bz.de_casteljau(self._array(), u))

    def iso_v(self, v, extrapolate: bool = False) -> BezierCurve:
        """The iso-parameter curve ``u -> F(u, v0)`` (degree ``l``), exact."""
        v = unit_parameter(v, "v", allow_outside=extrapolate)
        return self._wrap_curve(bz.de_casteljau(np.moveaxis(self._array(), 1, 0), v))

    def boundary_curves(self) -> dict:
        """The four boundary curves ``{"u0", "u1", "v0", "v1"}``."""
        return {"u0": self.iso_u(0), "u1": self.iso_u(1), "v0": self.iso_v(0), "v1": self.iso_v(1)}

    # ------------------------------------------------------------------ operations
    def subdivide_u(self, u) -> tuple["BezierSurface", "BezierSurface"]:
        """Split at ``u`` into the patches over [0, u] x [0, 1] and [u, 1] x [0, 1]."""
        u = unit_parameter(u, "subdivision parameter u")
        left, right = bz.along(0, bz.subdivide, self._array(), u)
        return self._wrap(left), self._wrap(right)

    def subdivide_v(self, v) -> tuple["BezierSurface", "BezierSurface"]:
        """Split at ``v`` into the patches over [0, 1] x [0, v] and [0, 1] x [v, 1]."""
        v = unit_parameter(v, "subdivision parameter v")
        low, high = bz.along(1, bz.subdivide, self._array(), v)
        return self._wrap(low), self._wrap(high)

    def reparametrize(self, u_range=(0, 1), v_range=(0, 1)) -> "BezierSurface":
        """The patch over ``u_range x v_range`` reparametrized to [0, 1]^2 (polar form)."""
        (u0, u1), (v0, v1) = [_range(r, name) for r, name in ((u_range, "u_range"), (v_range, "v_range"))]
        if u0 == u1 or v0 == v1:
            raise DomainError("reparametrize needs non-degenerate ranges")
        array = bz.along(0, bz.restrict, self._array(), u0, u1)
        return self._wrap(bz.along(1, bz.restrict, array, v0, v1))

    def elevate(self, ru: int = 1, rv: int = 0) -> "BezierSurface":
        """Degree elevation by ``ru`` in u and ``rv`` in v; the surface is unchanged."""
        ru = to_count(ru, where="elevation amount ru", error=DegreeError)
        rv = to_count(rv, where="elevation amount rv", error=DegreeError)
        array = bz.along(0, bz.elevate, self._array(), ru)
        return self._wrap(bz.along(1, bz.elevate, array, rv))

    def derivative_u(self) -> "BezierSurface":
        """``dF/du`` as an exact surface.

        Polynomial: degree ``(l - 1, m)`` (hodograph net).  Rational: quotient rule
        ``(N_u W - N W_u) / W^2`` of degree ``(2l, 2m)``.
        """
        return self._partial(0)

    def derivative_v(self) -> "BezierSurface":
        """``dF/dv`` as an exact surface (see :meth:`derivative_u`)."""
        return self._partial(1)

    def _partial(self, axis: int) -> "BezierSurface":
        if self._weights is None:
            return BezierSurface._trusted(bz.along(axis, bz.derivative, self._net), None)
        hom = self.homogeneous()
        num, w = hom[..., :-1], hom[..., -1:]
        d_num, d_w = bz.along(axis, bz.derivative, num), bz.along(axis, bz.derivative, w)
        top = bz.product_tensor(d_num, w) - bz.product_tensor(num, d_w)
        if self.degree[axis] > 0:
            top = bz.along(axis, bz.elevate, top, 1)
        else:  # derivative of a constant direction: zero, shaped like w*w
            top = bz.product_tensor(num, w) * 0
        bottom = bz.product_tensor(w, w)
        return BezierSurface.from_homogeneous(np.concatenate([top, bottom], axis=-1))

    def corner_normals(self) -> dict:
        """Exact normal vectors ``F_u x F_v`` at the four corners (3-D surfaces).

        Returns ``{(0, 0): n00, (1, 0): n10, (0, 1): n01, (1, 1): n11}`` with the exact
        cross products of the partial derivatives (not normalized; a zero vector marks
        a degenerate corner).  From the control net: at ``(0, 0)``,
        ``F_u = l w10/w00 (P10 - P00)`` and ``F_v = m w01/w00 (P01 - P00)`` (notes 15.3).
        """
        if self.dimension != 3:
            raise DimensionError(f"corner normals need a surface in 3-D, got dimension {self.dimension}")
        l, m = self.degree
        w = self.weights_array()
        out = {}
        for cu, cv in ((0, 0), (1, 0), (0, 1), (1, 1)):
            i, j = (l if cu else 0), (m if cv else 0)
            di, dj = (-1 if cu else 1), (-1 if cv else 1)
            if l == 0 or m == 0:
                out[(cu, cv)] = (mpq(0),) * 3
                continue
            fu = (self._net[i + di, j] - self._net[i, j]) * (l * w[i + di, j] / w[i, j]) * di
            fv = (self._net[i, j + dj] - self._net[i, j]) * (m * w[i, j + dj] / w[i, j]) * dj
            out[(cu, cv)] = _cross(fu, fv)
        return out

    # ------------------------------------------------------------------ comparison / conversion
    def __eq__(self, other) -> bool:
        if not isinstance(other, BezierSurface):
            return NotImplemented
        return (
            self._net.shape == other._net.shape
            and bool(np.all(self._net == other._net))
            and (self._weights is None) == (other._weights is None)
            and (self._weights is None or bool(np.all(self._weights == other._weights)))
        )

    def __hash__(self):
        return hash((self.control_net, self.weights))

    def to_sympy(self, u=None, v=None):
        """The surface as a sympy column ``Matrix`` of rational functions of ``u, v``."""
        import sympy

        u = sympy.Symbol("u") if u is None else u
        v = sympy.Symbol("v") if v is None else v
        l, m = self.degree
        bu = [sympy.binomial(l, i) * u**i * (1 - u) ** (l - i) for i in range(l + 1)]
        bv = [sympy.binomial(m, j) * v**j * (1 - v) ** (m - j) for j in range(m + 1)]
        hom = self.homogeneous()
        comps = [
            sympy.expand(sum(to_sympy(hom[i, j, k]) * bu[i] * bv[j] for i in range(l + 1) for j in range(m + 1)))
            for k in range(hom.shape[2])
        ]
        if self._weights is None:
            return sympy.Matrix(comps[:-1])
        return sympy.Matrix([c / comps[-1] for c in comps[:-1]])

    def to_float(self) -> tuple[np.ndarray, np.ndarray | None]:
        """Net (and weights) rounded to float64 (correctly; beyond the float range: ``inf``)."""
        net = np.vectorize(to_float, otypes=[float])(self._net)
        w = None if self._weights is None else np.vectorize(to_float, otypes=[float])(self._weights)
        return net, w

    def to_dict(self) -> dict:
        out = {"degree": list(self.degree), "control_net": [[[rational_str(x) for x in p] for p in row] for row in self._net]}
        if self._weights is not None:
            out["weights"] = [[rational_str(x) for x in row] for row in self._weights]
        return out

    @classmethod
    def from_dict(cls, data: dict) -> "BezierSurface":
        """The surface written by :meth:`to_dict` (``"degree"`` optional, checked if present).

        >>> s = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, "1/3"]]])
        >>> BezierSurface.from_dict(s.to_dict()).evaluate(1, 1)
        (mpq(1,1), mpq(1,1), mpq(1,3))
        """
        data = exchange_fields(data, ("control_net",), ("degree", "weights"), "BezierSurface")
        surface = cls(data["control_net"], data.get("weights"))
        check_stored_degree(data, surface.degree, "BezierSurface")
        return surface

    def __repr__(self) -> str:
        from ._display import points_preview

        kind = "rational " if self.is_rational else ""
        first_row = points_preview(self.control_net[0])
        return f"<{kind}BezierSurface degree={self.degree} dimension={self.dimension} net[0]={first_row}>"

    def _repr_latex_(self) -> str:
        """Jupyter shows the patch typeset: ``S(u, v) =`` its sympy form."""
        from ._display import latex

        return latex(self, "S(u, v)")

    def plot(self, ax=None, **style):
        """Draw the patch as a wireframe in 3-D (matplotlib; see :func:`exactcagd.plotting.plot`)."""
        from ._display import plot

        return plot(self, ax=ax, **style)


def _cross(a, b) -> tuple:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _range(pair, name: str) -> tuple:
    """``(a, b)`` as two exact numbers; anything else is an :class:`InputError` naming ``name``."""
    if isinstance(pair, (str, bytes, bytearray)) or not hasattr(pair, "__len__") or len(pair) != 2:
        raise InputError(f"{name}: expected a pair (a, b) of numbers, got {short_repr(pair, 40)}")
    return to_rational(pair[0], where=f"{name}[0]"), to_rational(pair[1], where=f"{name}[1]")

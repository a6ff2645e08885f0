"""Exact B-spline and NURBS curves and surfaces with clamped knot vectors.

Sources: Sederberg's notes (003) chapter 6 (6.3 extraction, 6.7 knot insertion,
6.8 de Boor) and 15.7 (NURBS surfaces); Yang et al. (004) section 3 (splitting a
NURBS surface into rational Bézier patches by knot insertion).

Rational (NURBS) objects are handled in homogeneous form ``(w P, w)``, so every
algorithm is the polynomial one applied one dimension up.

>>> from exactcagd import BSplineCurve
>>> c = BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], knots=[0, 0, 0, 1, 2, 2, 2])
>>> c.degree, c.domain
(2, (mpq(0,1), mpq(2,1)))
>>> c.evaluate(1)
(mpq(3,2), mpq(1,2))
"""

from __future__ import annotations

import numpy as np

from ..errors import KnotError
from ..exact import knots as kn
from ..exact.scalars import rational_str, to_count, to_rational
from ._validate import check_stored_degree, dehomogenize, exchange_fields, homogeneous, point_array, weight_array
from .bezier_curve import BezierCurve
from .bezier_surface import BezierSurface

__all__ = ["BSplineCurve", "BSplineSurface"]


def _knot_list(knots, what: str) -> list:
    """The user's knot vector as a list (a flat sequence of numbers is required)."""
    if isinstance(knots, (str, bytes)) or not hasattr(knots, "__iter__"):
        raise KnotError(f"{what}: expected a sequence of knots, got {type(knots).__name__}")
    return list(knots)


def _degree_from(n_points: int, knots: list, degree, what: str = "knots") -> int:
    inferred = len(knots) - n_points - 1
    if degree is not None:
        degree = to_count(degree, where=f"{what}: degree", error=KnotError)
    if degree is not None and degree != inferred:
        raise KnotError(
            f"{what}: degree {degree} does not match {n_points} control points and {len(knots)} knots "
            f"(which give degree {inferred})"
        )
    if inferred < 0:
        raise KnotError(f"{what}: {len(knots)} knots are too few for {n_points} control points (need at least {n_points + 1})")
    return inferred


def _project(hom: np.ndarray, rational: bool) -> tuple:
    if not rational:
        return tuple(hom[:-1])
    return tuple(x / hom[-1] for x in hom[:-1])


class _ByValue:
    """Equality and hashing by the stored representation (``_key()``: degrees, knots, points,
    weights), exactly; so a pickle or ``to_dict``/``from_dict`` round trip compares equal."""

    def _key(self) -> tuple:
        raise NotImplementedError

    def __eq__(self, other) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self):
        return hash(self._key())


class BSplineCurve(_ByValue):
    """A clamped B-spline (NURBS with ``weights``) curve with exact data.

    Parameters
    ----------
    control_points : sequence of ``n`` points of dimension ``d``
    knots : sequence of ``n + p + 1`` non-decreasing numbers, clamped
    weights : ``n`` positive numbers, optional
    degree : int, optional
        Checked against ``len(knots) - n - 1`` if given.

    Examples
    --------
    >>> c = BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], knots=[0, 0, 0, 1, 2, 2, 2])
    >>> [piece.control_points[0] for _, piece in c.to_bezier()]
    [(mpq(0,1), mpq(0,1)), (mpq(3,2), mpq(1,2))]
    """

    __slots__ = ("_points", "_weights", "_knots", "_degree")

    def __init__(self, control_points, knots, weights=None, degree: int | None = None):
        points = point_array(control_points, 1, "control_points")
        knots = _knot_list(knots, "knots")
        p = _degree_from(points.shape[0], knots, degree)
        self._knots = kn.check_knots(knots, points.shape[0], p, what="knots")
        self._degree = p
        self._points = points
        self._weights = weight_array(weights, (points.shape[0],), "weights")

    @classmethod
    def _trusted(cls, points, weights, knots, degree) -> "BSplineCurve":
        curve = object.__new__(cls)
        curve._points, curve._weights, curve._knots, curve._degree = points, weights, knots, degree
        return curve

    def _array(self) -> np.ndarray:
        return self._points if self._weights is None else homogeneous(self._points, self._weights)

    def _from_array(self, array, knots) -> "BSplineCurve":
        if self._weights is None:
            return BSplineCurve._trusted(array, None, knots, self._degree)
        points, weights = dehomogenize(array)
        return BSplineCurve._trusted(points, weights, knots, self._degree)

    # ------------------------------------------------------------------ properties
    @property
    def degree(self) -> int:
        return self._degree

    @property
    def dimension(self) -> int:
        return self._points.shape[1]

    @property
    def is_rational(self) -> bool:
        return self._weights is not None

    @property
    def knots(self) -> tuple:
        return self._knots

    @property
    def domain(self) -> tuple:
        """Parameter interval ``(knots[p], knots[-p-1])``."""
        return kn.domain(self._knots, self._degree)

    @property
    def control_points(self) -> tuple:
        return tuple(tuple(p) for p in self._points)

    @property
    def weights(self) -> tuple | None:
        return None if self._weights is None else tuple(self._weights)

    def breakpoints(self) -> tuple:
        """Distinct knots inside the domain, ends included."""
        lo, hi = self.domain
        return tuple(sorted(set(k for k in self._knots if lo <= k <= hi)))

    # ------------------------------------------------------------------ algorithms
    def evaluate(self, t) -> tuple:
        """Exact point at ``t`` by de Boor's algorithm (notes 6.8)."""
        value = kn.de_boor(self._array(), self._knots, self._degree, t)
        return _project(np.append(value, 1) if self._weights is None else value, self._weights is not None)

    __call__ = evaluate

    def insert_knot(self, t, times: int = 1) -> "BSplineCurve":
        """Insert ``t`` ``times`` times (Boehm, notes 6.7); the curve is unchanged."""
        array, knots = kn.insert_knot(self._array(), self._knots, self._degree, t, times)
        return self._from_array(array, knots)

    def to_bezier(self) -> list[tuple[tuple, BezierCurve]]:
        """Exact Bézier extraction (notes 6.3): ``[((a, b), BezierCurve), ...]``.

        Each piece is parametrized over [0, 1]; ``(a, b)`` is its knot span.
        """
        pieces = kn.extract_bezier(self._array(), self._knots, self._degree)
        if self._weights is None:
            return [(span, BezierCurve._trusted(arr, None)) for span, arr in pieces]
        return [(span, BezierCurve.from_homogeneous(arr)) for span, arr in pieces]

    def to_sympy(self, t=None):
        """The curve as a sympy column ``Matrix`` of ``Piecewise`` rational functions of ``t``:
        on each knot span ``[a, b)`` (the last one closed) the exact Bézier piece of
        :meth:`to_bezier` at ``(t - a)/(b - a)`` (notes 6.3)."""
        import sympy

        from ..exact.scalars import to_sympy as exact_to_sympy

        t = sympy.Symbol("t") if t is None else t
        pieces = self.to_bezier()
        rows = []
        for k in range(self.dimension):
            branches = []
            for j, ((a, b), piece) in enumerate(pieces):
                a, b = exact_to_sympy(a), exact_to_sympy(b)
                local = piece.to_sympy((t - a) / (b - a))[k]
                branches.append((sympy.cancel(local), (t <= b) if j == len(pieces) - 1 else (t < b)))
            rows.append(sympy.Piecewise(*branches))
        return sympy.Matrix(rows)

    def _repr_latex_(self) -> str:
        """Jupyter shows the curve typeset, piece by piece."""
        from ._display import latex

        return latex(self, "P(t)")

    def to_dict(self) -> dict:
        out = {
            "degree": self._degree,
            "knots": [rational_str(k) for k in self._knots],
            "control_points": [[rational_str(x) for x in p] for p in self._points],
        }
        if self._weights is not None:
            out["weights"] = [rational_str(w) for w in self._weights]
        return out

    @classmethod
    def from_dict(cls, data: dict) -> "BSplineCurve":
        """The curve written by :meth:`to_dict` (``"degree"`` optional, checked if present).

        >>> c = BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], knots=[0, 0, 0, 1, 2, 2, 2])
        >>> BSplineCurve.from_dict(c.to_dict()).evaluate(1)
        (mpq(3,2), mpq(1,2))
        """
        data = exchange_fields(data, ("control_points", "knots"), ("degree", "weights"), "BSplineCurve")
        return cls(data["control_points"], data["knots"], data.get("weights"), degree=data.get("degree"))

    def __repr__(self) -> str:
        from ._display import points_preview

        kind = "NURBS" if self.is_rational else "BSpline"
        return (f"<{kind}Curve degree={self.degree} points={len(self._points)} dimension={self.dimension} "
                f"control_points={points_preview(self.control_points)}>")

    def _key(self) -> tuple:
        return (self.degree, self.knots, self.control_points, self.weights)

    def plot(self, ax=None, **style):
        """Draw the curve, its control polygon and its knots (matplotlib; :func:`exactcagd.plotting.plot`)."""
        from ._display import plot

        return plot(self, ax=ax, **style)


class BSplineSurface(_ByValue):
    """A clamped tensor-product B-spline (NURBS with ``weights``) surface, exact.

    Parameters
    ----------
    control_net : nested sequence, shape ``(n_u, n_v, d)``
    knots_u, knots_v : clamped knot vectors of lengths ``n_u + p + 1`` and ``n_v + q + 1``
    weights : shape ``(n_u, n_v)``, positive, optional

    Examples
    --------
    >>> net = [[[i, j, 0] for j in range(3)] for i in range(3)]
    >>> s = BSplineSurface(net, [0, 0, 1, 2, 2], [0, 0, 0, 1, 1, 1])
    >>> s.degree, len(s.to_bezier_patches())
    ((1, 2), 2)
    """

    __slots__ = ("_net", "_weights", "_knots_u", "_knots_v", "_p", "_q")

    def __init__(self, control_net, knots_u, knots_v, weights=None):
        net = point_array(control_net, 2, "control_net")
        knots_u, knots_v = _knot_list(knots_u, "knots_u"), _knot_list(knots_v, "knots_v")
        self._p = _degree_from(net.shape[0], knots_u, None, "knots_u")
        self._q = _degree_from(net.shape[1], knots_v, None, "knots_v")
        self._knots_u = kn.check_knots(knots_u, net.shape[0], self._p, what="knots_u")
        self._knots_v = kn.check_knots(knots_v, net.shape[1], self._q, what="knots_v")
        self._net = net
        self._weights = weight_array(weights, net.shape[:2], "weights")

    @classmethod
    def _trusted(cls, net, weights, knots_u, knots_v, p, q) -> "BSplineSurface":
        s = object.__new__(cls)
        s._net, s._weights, s._knots_u, s._knots_v, s._p, s._q = net, weights, knots_u, knots_v, p, q
        return s

    def _array(self) -> np.ndarray:
        return self._net if self._weights is None else homogeneous(self._net, self._weights)

    def _from_array(self, array, knots_u, knots_v) -> "BSplineSurface":
        if self._weights is None:
            return BSplineSurface._trusted(array, None, knots_u, knots_v, self._p, self._q)
        net, weights = dehomogenize(array)
        return BSplineSurface._trusted(net, weights, knots_u, knots_v, self._p, self._q)

    # ------------------------------------------------------------------ properties
    @property
    def degree(self) -> tuple[int, int]:
        return self._p, self._q

    @property
    def dimension(self) -> int:
        return self._net.shape[2]

    @property
    def is_rational(self) -> bool:
        return self._weights is not None

    @property
    def knots_u(self) -> tuple:
        return self._knots_u

    @property
    def knots_v(self) -> tuple:
        return self._knots_v

    @property
    def domain(self) -> tuple:
        """``((u_min, u_max), (v_min, v_max))``."""
        return kn.domain(self._knots_u, self._p), kn.domain(self._knots_v, self._q)

    @property
    def shape(self) -> tuple[int, int]:
        """Number of control points in u and v."""
        return self._net.shape[:2]

    @property
    def control_net(self) -> tuple:
        return tuple(tuple(tuple(p) for p in row) for row in self._net)

    @property
    def weights(self) -> tuple | None:
        return None if self._weights is None else tuple(tuple(r) for r in self._weights)

    def breakpoints(self) -> tuple[tuple, tuple]:
        """Distinct knots of the domain in u and in v (ends included)."""
        (u0, u1), (v0, v1) = self.domain
        return (
            tuple(sorted(set(k for k in self._knots_u if u0 <= k <= u1))),
            tuple(sorted(set(k for k in self._knots_v if v0 <= k <= v1))),
        )

    # ------------------------------------------------------------------ algorithms
    def evaluate(self, u, v) -> tuple:
        """Exact point at ``(u, v)``: de Boor in u on every column, then in v."""
        u, v = to_rational(u, where="u"), to_rational(v, where="v")
        column = kn.de_boor(self._array(), self._knots_u, self._p, u)  # shape (n_v, ...)
        value = kn.de_boor(column, self._knots_v, self._q, v)
        return _project(np.append(value, 1) if self._weights is None else value, self._weights is not None)

    __call__ = evaluate

    def insert_knot_u(self, u, times: int = 1) -> "BSplineSurface":
        """Insert ``u`` into the u knot vector (Boehm on every column of the net)."""
        array, knots = kn.insert_knot(self._array(), self._knots_u, self._p, u, times)
        return self._from_array(array, knots, self._knots_v)

    def insert_knot_v(self, v, times: int = 1) -> "BSplineSurface":
        """Insert ``v`` into the v knot vector (Boehm on every row of the net)."""
        moved = np.moveaxis(self._array(), 1, 0)
        array, knots = kn.insert_knot(moved, self._knots_v, self._q, v, times)
        return self._from_array(np.moveaxis(array, 0, 1), self._knots_u, knots)

    def to_bezier_patches(self, u_spans=None, v_spans=None, pairs=None) -> dict:
        """Exact extraction into Bézier patches (notes 15.7; Yang et al. section 3).

        Returns ``{(i, j): ((u_span, v_span), BezierSurface)}`` for the non-empty knot
        spans.  With ``u_spans``/``v_spans`` (sets of span indices) only the patches of
        those rows x columns are built, and with ``pairs`` (a set of ``(i, j)``) only
        those patches, each from its own ``(p+1) x (q+1)`` control points by blossoming
        (:func:`exactcagd.exact.knots.span_bezier`); without any of them the whole net
        is extracted by knot insertion.
        """
        if pairs is not None:
            pairs = {(int(i), int(j)) for i, j in pairs}
            u_spans = {i for i, _ in pairs}
            v_spans = {j for _, j in pairs}
        array = self._array()
        if u_spans is None and v_spans is None:
            u_pieces = list(enumerate(kn.extract_bezier(array, self._knots_u, self._p)))
        else:
            n_u = len(self.breakpoints()[0]) - 1
            wanted = sorted(set(range(n_u) if u_spans is None else u_spans))
            u_pieces = [(i, kn.span_bezier(array, self._knots_u, self._p, i)) for i in wanted]
        out = {}
        for i, (u_span, strip) in u_pieces:
            moved = np.moveaxis(strip, 1, 0)
            if v_spans is None:
                v_pieces = list(enumerate(kn.extract_bezier(moved, self._knots_v, self._q)))
            else:
                wanted_v = sorted(j for j in set(v_spans) if pairs is None or (i, j) in pairs)
                v_pieces = [(j, kn.span_bezier(moved, self._knots_v, self._q, j)) for j in wanted_v]
            for j, (v_span, patch) in v_pieces:
                patch = np.moveaxis(patch, 0, 1)
                surface = (
                    BezierSurface._trusted(patch, None) if self._weights is None else BezierSurface.from_homogeneous(patch)
                )
                out[(i, j)] = ((u_span, v_span), surface)
        return out

    def bezier_patch(self, i: int, j: int) -> tuple[tuple, BezierSurface]:
        """The single Bézier patch over the ``i``-th u span and ``j``-th v span."""
        return self.to_bezier_patches(u_spans={i}, v_spans={j})[(i, j)]

    def to_dict(self) -> dict:
        out = {
            "degree": list(self.degree),
            "knots_u": [rational_str(k) for k in self._knots_u],
            "knots_v": [rational_str(k) for k in self._knots_v],
            "control_net": [[[rational_str(x) for x in p] for p in row] for row in self._net],
        }
        if self._weights is not None:
            out["weights"] = [[rational_str(x) for x in row] for row in self._weights]
        return out

    @classmethod
    def from_dict(cls, data: dict) -> "BSplineSurface":
        """The surface written by :meth:`to_dict` (``"degree"`` optional, checked if present).

        >>> net = [[[i, j, 0] for j in range(3)] for i in range(3)]
        >>> s = BSplineSurface(net, [0, 0, 1, 2, 2], [0, 0, 0, 1, 1, 1])
        >>> BSplineSurface.from_dict(s.to_dict()).degree
        (1, 2)
        """
        data = exchange_fields(data, ("control_net", "knots_u", "knots_v"), ("degree", "weights"), "BSplineSurface")
        surface = cls(data["control_net"], data["knots_u"], data["knots_v"], data.get("weights"))
        check_stored_degree(data, surface.degree, "BSplineSurface")
        return surface

    def __repr__(self) -> str:
        from ._display import points_preview

        kind = "NURBS" if self.is_rational else "BSpline"
        return (f"<{kind}Surface degree={self.degree} shape={self.shape} dimension={self.dimension} "
                f"net[0]={points_preview(self.control_net[0])}>")

    def _key(self) -> tuple:
        return (self.degree, self.knots_u, self.knots_v, self.control_net, self.weights)

    def plot(self, ax=None, **style):
        """Draw the surface as a wireframe in 3-D (matplotlib; see :func:`exactcagd.plotting.plot`)."""
        from ._display import plot

        return plot(self, ax=ax, **style)

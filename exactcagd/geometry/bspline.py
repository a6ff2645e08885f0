"""Exact B-spline and NURBS curves (any knot vector) and surfaces (clamped knot vectors).

Sources: Sederberg's notes (003) chapter 6 (6.3 extraction, 6.7 knot insertion,
6.8 de Boor) and 15.7 (NURBS surfaces); Yang et al. (004) section 3 (splitting a
NURBS surface into rational Bézier patches by knot insertion).

Rational (NURBS) objects are handled in homogeneous form ``(w P, w)``, so every
algorithm is the polynomial one applied one dimension up.

A curve's knot vector need not be clamped (periodic and uniform B-splines, notes
6.5); its domain is ``[knots[p], knots[n]]``.  Knot insertion, clamping, degree
elevation and knot removal are all one computation: a control point with polar
label ``(u_1, ..., u_p)`` over a new knot vector is the blossom of the old spline
at that label (notes 6.1 rule 4, 6.8; :func:`exactcagd.exact.knots.blossom_de_boor`).

>>> from exactcagd import BSplineCurve
>>> c = BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], knots=[0, 0, 0, 1, 2, 2, 2])
>>> c.degree, c.domain
(2, (mpq(0,1), mpq(2,1)))
>>> c.evaluate(1)
(mpq(3,2), mpq(1,2))
"""

from __future__ import annotations


import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DomainError, InputError, KnotError, NotSupportedError
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


def _refines(new: tuple, old: tuple, lo, hi) -> bool:
    """Does ``new`` contain every old knot strictly inside ``(lo, hi)`` with at least its multiplicity?"""
    for v in set(k for k in old if lo < k < hi):
        if new.count(v) < old.count(v):
            return False
    return True


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
    """A B-spline (NURBS with ``weights``) curve with exact data, on any knot vector.

    The knot vector may be clamped (the curve interpolates its end control points) or
    not (uniform and periodic B-splines, notes 6.5); the curve is defined on its domain
    ``[knots[p], knots[n]]`` (``n`` control points, degree ``p``).

    Parameters
    ----------
    control_points : sequence of ``n`` points of dimension ``d``
    knots : sequence of ``n + p + 1`` non-decreasing numbers (standard convention;
        interior multiplicity at most ``p``)
    weights : ``n`` positive numbers, optional
    degree : int, optional
        Checked against ``len(knots) - n - 1`` if given.

    Examples
    --------
    >>> c = BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], knots=[0, 0, 0, 1, 2, 2, 2])
    >>> [piece.control_points[0] for _, piece in c.to_bezier()]
    [(mpq(0,1), mpq(0,1)), (mpq(3,2), mpq(1,2))]
    >>> u = BSplineCurve([[0, 0], [1, 2], [3, 2], [4, 0]], knots=range(7))   # uniform, unclamped
    >>> u.domain, u.evaluate(3)
    ((mpq(2,1), mpq(4,1)), (mpq(2,1), mpq(2,1)))
    >>> u.clamp().evaluate(3) == u.evaluate(3)
    True
    """

    __slots__ = ("_points", "_weights", "_knots", "_degree")

    def __init__(self, control_points, knots, weights=None, degree: int | None = None):
        points = point_array(control_points, 1, "control_points")
        knots = _knot_list(knots, "knots")
        p = _degree_from(points.shape[0], knots, degree)
        self._knots = kn.check_knots(knots, points.shape[0], p, clamped=False, what="knots")
        self._degree = p
        self._points = points
        self._weights = weight_array(weights, (points.shape[0],), "weights")

    @classmethod
    def _trusted(cls, points, weights, knots, degree) -> "BSplineCurve":
        curve = object.__new__(cls)
        curve._points, curve._weights, curve._knots, curve._degree = points, weights, tuple(knots), degree
        return curve

    @classmethod
    def _from_hom(cls, hom: np.ndarray, knots, rational: bool) -> "BSplineCurve":
        """The curve with homogeneous control points ``hom`` (weights dropped unless ``rational``)."""
        knots = tuple(knots)
        degree = len(knots) - hom.shape[0] - 1
        if not rational:
            return cls._trusted(hom[:, :-1].copy(), None, knots, degree)
        points, weights = dehomogenize(hom)
        return cls._trusted(points, weights, knots, degree)

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
    def is_clamped(self) -> bool:
        """Are both end knots of multiplicity exactly ``p + 1`` (Bézier end conditions, notes 6.6)?"""
        p, ks = self._degree, self._knots
        return kn.multiplicity(ks, ks[0]) == p + 1 and kn.multiplicity(ks, ks[-1]) == p + 1

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

    def homogeneous(self) -> np.ndarray:
        """Homogeneous control points ``(w P, w)`` (weights 1 for a polynomial curve)."""
        return homogeneous(self._points, self._weights)

    def breakpoints(self) -> tuple:
        """Distinct knots inside the domain, ends included."""
        lo, hi = self.domain
        return tuple(sorted(set(k for k in self._knots if lo <= k <= hi)))

    def spans(self) -> list[int]:
        """Indices ``l`` of the non-empty knot spans ``[knots[l], knots[l+1]]`` of the domain."""
        p, n = self._degree, self._points.shape[0]
        return [l for l in range(p, n) if self._knots[l] < self._knots[l + 1]]

    # ------------------------------------------------------------------ polar form
    def segment(self, l: int) -> tuple[np.ndarray, tuple]:
        """Homogeneous control points and ``2p`` local knots of the segment over span ``l``."""
        p = self._degree
        if l not in self.spans():
            raise DomainError(f"span {l} is not a non-empty span of the domain")
        return self.homogeneous()[l - p : l + 1], self._knots[l - p + 1 : l + p + 1]

    def polar_value(self, l: int, args) -> np.ndarray:
        """Homogeneous polar value ``f_l(args)`` of the segment over span ``l`` (notes 6.1 rule 4, 6.8).

        >>> c = BSplineCurve([[0], [1], [0]], knots=[0, 1, 2, 3, 4, 5])
        >>> c.polar_value(2, [mpq(5, 2), mpq(5, 2)])     # the point at 5/2, homogeneous
        array([mpq(3,4), mpq(1,1)], dtype=object)
        """
        if l not in self.spans():
            raise DomainError(f"span {l} is not a non-empty span of the domain")
        args = [to_rational(x, where="polar argument") for x in args]
        if len(args) != self._degree:
            raise InputError(f"the polar form of a degree-{self._degree} segment takes {self._degree} arguments, got {len(args)}")
        return kn.blossom_de_boor(self.homogeneous(), self._knots, self._degree, l, args)

    def span_of(self, t) -> int:
        """The span index containing ``t`` (the last non-empty span for the right end of the domain)."""
        return kn.find_span(self._knots, self._degree, to_rational(t, where="t"))

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

    def insert_knots(self, values) -> "BSplineCurve":
        """Insert the given knots (each inside the open domain) at once (notes 6.7)."""
        vals = [to_rational(v, where="inserted knot") for v in values]
        lo, hi = self.domain
        for v in vals:
            if not lo < v < hi:
                raise DomainError(f"inserted knot {v} is not inside the open domain ({lo}, {hi})")
        return self.rebase(sorted(self._knots + tuple(vals)))

    def to_bezier(self) -> list[tuple[tuple, BezierCurve]]:
        """Exact Bézier extraction (notes 6.3): ``[((a, b), BezierCurve), ...]``.

        Each piece is parametrized over [0, 1]; ``(a, b)`` is its knot span.  A clamped
        curve of degree >= 1 is extracted by knot insertion, any other one span by span by
        blossoming (control point ``i`` of a piece is ``f(a^{p-i}, b^i)``).
        """
        if self.is_clamped and self._degree > 0:  # extract_bezier's piece offsets assume degree >= 1
            pieces = kn.extract_bezier(self._array(), self._knots, self._degree)
        else:
            array = self._array()
            pieces = [kn.span_bezier(array, self._knots, self._degree, i) for i in range(len(self.spans()))]
        if self._weights is None:
            return [(span, BezierCurve._trusted(arr, None)) for span, arr in pieces]
        return [(span, BezierCurve.from_homogeneous(arr)) for span, arr in pieces]

    def rebase(self, new_knots) -> "BSplineCurve":
        """The same curve over another knot vector of the same degree (control points = blossoms).

        Knot insertion (notes 6.7) when ``new_knots`` refines the old ones; knot removal
        when the curve happens to lie in the coarser space -- then the result is verified
        to reproduce the curve exactly (:class:`KnotError` otherwise).  The new domain
        must lie inside the old one.

        >>> c = BSplineCurve([[0, 0], [1, 2], [3, 2], [4, 0]], knots=range(7))
        >>> c.rebase([0, 1, 2, 3, 3, 4, 5, 6]).evaluate(3) == c.evaluate(3)
        True
        """
        p = self._degree
        ks = tuple(to_rational(k, where="new knot") for k in new_knots)
        n_new = len(ks) - p - 1
        if n_new < 1:
            raise KnotError(f"new knots: {len(ks)} knots are too few for degree {p}")
        ks = kn.check_knots(ks, n_new, p, clamped=False, what="new knots")
        lo, hi = self.domain
        if not (lo <= ks[p] and ks[n_new] <= hi):
            raise DomainError(f"new domain [{ks[p]}, {ks[n_new]}] is not inside [{lo}, {hi}]")
        hom = np.stack([self._label_point(ks, j, p) for j in range(n_new)])
        out = BSplineCurve._from_hom(hom, ks, self.is_rational)
        if not _refines(ks, self._knots, ks[p], ks[n_new]) and not out._same_on(self):
            raise KnotError("the curve does not lie in the spline space of the new knot vector")
        return out

    def clamp(self) -> "BSplineCurve":
        """Bézier end conditions (notes 6.6): the same curve with ``(p+1)``-fold end knots
        over the same domain; it interpolates its end control points."""
        if self.is_clamped:
            return self
        return self.rebase(self._clamped_knots())

    def greville(self) -> tuple:
        """Greville abscissae (notes (6.1)): averages of the ``p`` knots of each polar label."""
        p = self._degree
        if p == 0:
            raise DegreeError("Greville abscissae need degree >= 1")
        return tuple(sum(self._knots[i + 1 : i + p + 1], start=mpq(0)) / p for i in range(self._points.shape[0]))

    def derivative(self) -> "BSplineCurve":
        """Hodograph (notes (6.2)): ``H_i = p (P_{i+1} - P_i) / (t_{i+p+1} - t_{i+1})``, knots minus the ends.

        Polynomial curves only.  A zero denominator (a ``(p+1)``-fold knot) is not
        possible inside the domain; at the ends the coefficient is irrelevant and set to 0.
        """
        if self.is_rational:
            raise NotSupportedError("the hodograph of a rational spline is not a spline of lower degree")
        p = self._degree
        if p == 0:
            raise DegreeError("the derivative of a degree-0 spline is not a spline")
        pts = self._points
        rows = []
        for i in range(pts.shape[0] - 1):
            den = self._knots[i + p + 1] - self._knots[i + 1]
            rows.append((pts[i + 1] - pts[i]) * (mpq(p) / den) if den != 0 else pts[i] * 0)
        return BSplineCurve._trusted(np.stack(rows), None, self._knots[1:-1], p - 1)

    def elevate(self) -> "BSplineCurve":
        """Degree elevation by one (Ramshaw, notes (6.7)-(6.8)) of the clamped curve.

        The curve is first given Bézier end conditions; every knot's multiplicity then
        rises by one, and the control point with label ``(u_1..u_{p+1})`` is the average
        of the old polar values over the ``p``-subsets of the label.
        """
        p = self._degree
        base = self.clamp()
        values = sorted(set(base._knots))
        new = tuple(v for v in values for _ in range(base._knots.count(v) + 1))
        n_new = len(new) - (p + 1) - 1
        hom = np.stack([base._label_point(new, j, p + 1) for j in range(n_new)])
        return BSplineCurve._from_hom(hom, new, self.is_rational)

    # ------------------------------------------------------------------ helpers of the polar form
    def _label_point(self, new_knots: tuple, j: int, degree: int) -> np.ndarray:
        """Control point ``j`` (degree ``degree``) over ``new_knots``: a blossom of this spline.

        The span used is one of the non-empty spans ``l`` in ``[j, j + degree]`` of the
        new knot vector inside this domain (any of them gives the same value when this
        spline belongs to the new spline space).
        """
        label = new_knots[j + 1 : j + degree + 1]
        lo, hi = self.domain
        old = None
        for l in sorted(range(j, j + degree + 1), key=lambda l: abs(2 * l - 2 * j - degree)):
            a, b = new_knots[l], new_knots[l + 1]
            if a < b and lo <= a and b <= hi:
                old = self.span_of((a + b) / 2)
                break
        if old is None:
            # the basis function of this control point vanishes on the domain (e.g. a
            # (p+1)-fold end knot): its value is irrelevant; use the nearest segment
            mid = sum(label, start=mpq(0)) / len(label) if label else lo
            old = self.span_of(min(max(mid, lo), hi))
        if degree == self._degree:
            return self.polar_value(old, label)
        if degree == self._degree + 1:  # Ramshaw (6.7)-(6.8): average over p-subsets
            acc = None
            for drop in range(degree):
                val = self.polar_value(old, label[:drop] + label[drop + 1 :])
                acc = val if acc is None else acc + val
            return acc * mpq(1, degree)
        raise DegreeError("elevation by one degree at a time")

    def _clamped_knots(self) -> list:
        p = self._degree
        lo, hi = self.domain
        return [lo] * (p + 1) + [k for k in self._knots if lo < k < hi] + [hi] * (p + 1)

    def _same_on(self, other: "BSplineCurve") -> bool:
        """Exact identity of the homogeneous spline functions on ``self``'s domain
        (``p + 1`` points inside every span of the merged breakpoints)."""
        lo, hi = self.domain
        cuts = sorted(set(k for k in self._knots + other._knots if lo <= k <= hi))
        p = self._degree
        for a, b in zip(cuts[:-1], cuts[1:]):
            for t in [a + (b - a) * mpq(i + 1, p + 2) for i in range(p + 1)]:
                if not np.all(self.polar_value(self.span_of(t), [t] * p) == other.polar_value(other.span_of(t), [t] * p)):
                    return False
        return True

    # ------------------------------------------------------------------ display and exchange
    def to_sympy_pieces(self, t=None) -> list:
        """Piecewise description ``[((a, b), sympy Matrix of the piece in t)]`` in the global parameter ``t``."""
        import sympy

        from ..exact.scalars import to_sympy as exact_to_sympy

        t = sympy.Symbol("t") if t is None else t
        out = []
        for (a, b), piece in self.to_bezier():
            u = sympy.Symbol("_s_")
            s = (t - exact_to_sympy(a)) / (exact_to_sympy(b) - exact_to_sympy(a))
            out.append(((a, b), piece.to_sympy(u).subs(u, s).applyfunc(sympy.expand)))
        return out

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

    def to_sympy(self, u=None, v=None):
        r"""The surface as a sympy column ``Matrix`` of ``Piecewise`` rational functions of ``u, v``.

        Tensor product of :meth:`BSplineCurve.to_sympy`'s construction: on each pair of knot
        spans ``[a, b) x [c, d)`` (the last span of each direction closed) the exact Bézier
        patch of :meth:`to_bezier_patches` at ``((u - a)/(b - a), (v - c)/(d - c))``
        (notes 15.5, tensor-product B-splines; 6.3 for the pieces).

        >>> net = [[[i, j, i * j] for j in range(3)] for i in range(3)]
        >>> s = BSplineSurface(net, [0, 0, 1, 2, 2], [0, 0, 0, 1, 1, 1])
        >>> import sympy
        >>> u, v = sympy.symbols("u v")
        >>> s.to_sympy().subs({u: sympy.Rational(3, 2), v: sympy.Rational(1, 3)}).T
        Matrix([[3/2, 2/3, 1]])
        """
        import sympy

        from ..exact.scalars import to_sympy as exact_to_sympy

        u = sympy.Symbol("u") if u is None else u
        v = sympy.Symbol("v") if v is None else v
        patches = sorted(self.to_bezier_patches().items())
        last_i = max(i for i, _ in (key for key, _ in patches))
        last_j = max(j for _, j in (key for key, _ in patches))
        rows = [[] for _ in range(self.dimension)]
        for (i, j), (((a, b), (c, d)), patch) in patches:
            a, b, c, d = (exact_to_sympy(x) for x in (a, b, c, d))
            local = patch.to_sympy((u - a) / (b - a), (v - c) / (d - c))
            inside = sympy.And((u <= b) if i == last_i else (u < b), (v <= d) if j == last_j else (v < d))
            for k in range(self.dimension):
                rows[k].append((sympy.cancel(local[k]), inside))
        return sympy.Matrix([sympy.Piecewise(*branches) for branches in rows])

    def _repr_latex_(self) -> str:
        """Jupyter shows the surface typeset, patch by patch."""
        from ._display import latex

        return latex(self, "S(u, v)")

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

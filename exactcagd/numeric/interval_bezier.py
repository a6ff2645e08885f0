"""Interval Bézier curves and interval approximation (Sederberg's notes, 12.2-12.4).

An interval Bézier curve ``[P](t) = sum_k [P_k] B_k^n(t)`` (12.15) has boxes
``[P_k] = [a_k1, b_k1] x ... x [a_kd, b_kd]`` (12.12) as control points, here with exact
rational endpoints.  For every ``t``, ``[P](t)`` is a box that contains ``P(t)`` for every
Bézier curve with ``P_k in [P_k]``; for boxes this enclosure is exact (no overestimation):

* for ``0 <= t <= 1`` it is ``center(t) + e(t) [-1, 1]`` with the center curve of the box
  centers and the error curve of the half widths (centered form, (12.21)-(12.23));
* for any real ``t`` it is ``center(t) + sum_k e_k |B_k(t)| [-1, 1]`` (12.26)-(12.29),
  which is what the interval de Casteljau algorithm (12.19) computes.

Interval *approximants* of exact curves (12.3-12.4): :func:`hermite_interval`
(end-point Hermite interpolant plus the remainder (12.52) in the middle coefficient),
:func:`lagrange_interval` (Lagrange interpolant plus the Cauchy remainder (12.42) in
Bernstein form (12.43)), and :func:`enclose` (any polynomial approximant of any exact
curve, rational ones included, plus the Bernstein hull of the exact difference).  The
exact curve lies inside each of them for every ``t`` in [0, 1].

>>> from exactcagd import BezierCurve
>>> from exactcagd.numeric.interval_bezier import IntervalBezierCurve, hermite_interval
>>> box = IntervalBezierCurve([[(0, 0), (0, 0)], [(1, 2), (2, 2)], [(3, 3), (0, 1)]])
>>> box.evaluate("1/2")
(Interval(5/4, 7/4), Interval(1, 5/4))
>>> cubic = BezierCurve([[0, 0], [1, 3], [2, -1], [4, 1], [5, 0]])
>>> approx = hermite_interval(cubic, 2)          # quartic ... here exact: degree 4 = 2m
>>> approx.width()
(mpq(0,1), mpq(0,1))
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DimensionError, DomainError, InputError, NotSupportedError
from ..exact import bernstein as bz
from ..exact.scalars import rational_str, to_count, to_rational, to_rational_array
from ..geometry.bezier_curve import BezierCurve
from .fp_error import down, up
from .interval import FloatInterval, Interval, as_interval

__all__ = [
    "IntervalBezierCurve",
    "interval_polynomial",
    "affine_map",
    "derivative_bounds",
    "hermite_interval",
    "hermite_interval_from_data",
    "lagrange_interval",
    "enclose",
    "approximate",
]


def _box(entries, d: int | None, where: str) -> list[Interval]:
    """A vector interval (12.12): a sequence of intervals / (lo, hi) pairs / numbers."""
    if isinstance(entries, (Interval, FloatInterval)) or not isinstance(entries, (list, tuple, np.ndarray)):
        entries = [entries]
    box = []
    for j, x in enumerate(entries):
        try:
            box.append(as_interval(x))
        except InputError as exc:
            raise InputError(f"{where}[{j}]: {exc}") from None
    if d is not None and len(box) != d:
        raise DimensionError(f"{where}: expected {d} coordinate intervals, got {len(box)}")
    return box


def affine_map(p0, p1, t):
    """The affine map ``(1 - t)[p0] + t[p1]`` of two (vector) intervals (12.17)-(12.18).

    ``p0`` and ``p1`` are intervals or boxes (sequences of intervals); computed with
    exact interval arithmetic.  In centered form this is ``(1-t) c0 + t c1 +
    (e0 |1 - t| + e1 |t|)[-1, 1]`` for every real ``t`` (12.26).

    >>> affine_map(Interval(0, 2), Interval(4, 6), "1/2")
    Interval(2, 4)
    >>> affine_map(Interval(0, 2), Interval(4, 6), 2)
    Interval(6, 12)
    """
    t = to_rational(t, where="t")
    scalar = isinstance(p0, (Interval, FloatInterval)) or not isinstance(p0, (list, tuple))
    a, b = _box(p0, None, "p0"), _box(p1, None, "p1")
    if len(a) != len(b):
        raise DimensionError(f"affine map of boxes of dimensions {len(a)} and {len(b)}")
    out = tuple((1 - t) * x + t * y for x, y in zip(a, b))
    return out[0] if scalar else out


class IntervalBezierCurve:
    """A Bézier curve whose control points are boxes with exact rational bounds (12.15).

    Parameters
    ----------
    control_boxes : sequence of ``n + 1`` boxes
        Each box is a sequence of ``d`` coordinate intervals, each given as an
        :class:`Interval`, an ``(lo, hi)`` pair or a number (degenerate interval).

    Examples
    --------
    >>> c = IntervalBezierCurve([[(0, 1)], [(2, 2)], [(1, 3)]])   # interval polynomial
    >>> c.width()                                                 # (12.10)
    (mpq(1,1),)
    >>> c.evaluate(0), c.evaluate("1/2")
    ((Interval(0, 1),), (Interval(5/4, 2),))
    """

    __slots__ = ("_lo", "_hi")

    def __init__(self, control_boxes):
        boxes = list(control_boxes)
        if not boxes:
            raise InputError("an interval Bézier curve needs at least one control box")
        first = _box(boxes[0], None, "control_boxes[0]")
        rows = [first] + [_box(b, len(first), f"control_boxes[{k}]") for k, b in enumerate(boxes[1:], 1)]
        self._lo = np.array([[x.lo for x in row] for row in rows], dtype=object)
        self._hi = np.array([[x.hi for x in row] for row in rows], dtype=object)

    # ------------------------------------------------------------------ construction
    @classmethod
    def _trusted(cls, lo: np.ndarray, hi: np.ndarray) -> "IntervalBezierCurve":
        out = object.__new__(cls)
        out._lo, out._hi = lo, hi
        return out

    @classmethod
    def from_bounds(cls, lower, upper) -> "IntervalBezierCurve":
        """From arrays of lower and upper control-point bounds, shape ``(n + 1, d)``."""
        lo, hi = to_rational_array(lower, where="lower"), to_rational_array(upper, where="upper")
        if lo.ndim != 2 or lo.shape != hi.shape or lo.shape[0] == 0:
            raise InputError(f"lower/upper bounds need equal shapes (n+1, d); got {lo.shape} and {hi.shape}")
        if any(a > b for a, b in zip(lo.reshape(-1), hi.reshape(-1))):
            raise InputError("a lower bound exceeds its upper bound")
        return cls._trusted(lo, hi)

    @classmethod
    def from_centered(cls, centers, errors) -> "IntervalBezierCurve":
        """From centers ``P_k`` and non-negative errors ``e_k`` (centered form (12.21))."""
        c, e = to_rational_array(centers, where="centers"), to_rational_array(errors, where="errors")
        if c.ndim != 2 or c.shape != e.shape:
            raise InputError(f"centers and errors need equal shapes (n+1, d); got {c.shape} and {e.shape}")
        if any(x < 0 for x in e.reshape(-1)):
            raise InputError("centered form needs non-negative errors")
        return cls._trusted(c - e, c + e)

    @classmethod
    def from_curve(cls, curve: BezierCurve) -> "IntervalBezierCurve":
        """A polynomial Bézier curve as a degenerate interval curve."""
        _polynomial(curve, "from_curve")
        p = curve.points_array()
        return cls._trusted(p, p.copy())

    # ------------------------------------------------------------------ properties
    @property
    def degree(self) -> int:
        return self._lo.shape[0] - 1

    @property
    def dimension(self) -> int:
        return self._lo.shape[1]

    def lo_array(self) -> np.ndarray:
        """Lower bounds of the control boxes, exact ``(n + 1, d)``."""
        return self._lo.copy()

    def hi_array(self) -> np.ndarray:
        """Upper bounds of the control boxes, exact ``(n + 1, d)``."""
        return self._hi.copy()

    @property
    def control_boxes(self) -> tuple:
        """The control boxes as tuples of :class:`Interval`."""
        return tuple(
            tuple(Interval._make(a, b) for a, b in zip(lo_row, hi_row)) for lo_row, hi_row in zip(self._lo, self._hi)
        )

    def center_curve(self) -> BezierCurve:
        """The curve of the box centers (12.21)-(12.23)."""
        return BezierCurve._trusted((self._lo + self._hi) / 2, None)

    def error_curve(self) -> BezierCurve:
        """The error curve ``e(t) = sum_k e_k B_k(t)`` with ``e_k`` the half widths (12.23).

        Its control points lie in the closed positive orthant, hence so does ``e(t)``
        on [0, 1]."""
        return BezierCurve._trusted((self._hi - self._lo) / 2, None)

    def bound_curves(self) -> tuple[BezierCurve, BezierCurve]:
        """The curves of lower and of upper bounds, ``p_min`` and ``p_max`` per coordinate (12.9)."""
        return BezierCurve._trusted(self._lo.copy(), None), BezierCurve._trusted(self._hi.copy(), None)

    def corner_curves(self) -> dict:
        """The ``2^d`` Bézier curves through corresponding corners of the control boxes (12.2.4).

        Keys are tuples of ``"lo"``/``"hi"`` per coordinate; e.g. in the plane
        ``("lo", "hi")`` is the curve of the top-left corners.  For ``t`` in [0, 1] the
        corners of the box ``[P](t)`` are the points of these curves at ``t``.
        """
        out = {}
        d = self.dimension
        for mask in range(2**d):
            key = tuple("hi" if mask >> j & 1 else "lo" for j in range(d))
            pts = np.empty_like(self._lo)
            for j, side in enumerate(key):
                pts[:, j] = (self._hi if side == "hi" else self._lo)[:, j]
            out[key] = BezierCurve._trusted(pts, None)
        return out

    def stationary_parameters(self) -> list:
        """Parameters in [0, 1] where a bound coordinate ``p_min_j`` or ``p_max_j`` is stationary.

        The boundary of the region swept by the boxes ``[P](t)``, ``t in [0, 1]``, lies on
        the corner curves, on the boxes at ``t = 0`` and ``t = 1``, and on box edges at
        these parameters only (an edge whose coordinate moves is interior to nearby boxes);
        see the ledger entry of notes 12.2.4.  Returns ``[(RealAlgebraic, j, "lo"|"hi")]``.
        """
        from ..exact.algebraic import real_roots_bernstein

        out = []
        if self.degree == 0:
            return out
        for side, array in (("lo", self._lo), ("hi", self._hi)):
            deriv = bz.derivative(array)
            for j in range(self.dimension):
                column = deriv[:, j]
                if all(x == 0 for x in column):
                    continue
                out += [(root, j, side) for root, _ in real_roots_bernstein(list(column), 0, 1)]
        return out

    # ------------------------------------------------------------------ measures
    def width(self) -> tuple:
        """Width ``int_0^1 (p_max - p_min) dt = (1/(n+1)) sum_k (b_k - a_k)`` per coordinate (12.10)."""
        n = self.degree
        return tuple(sum(self._hi[:, j] - self._lo[:, j]) / (n + 1) for j in range(self.dimension))

    def max_error(self) -> tuple:
        """``max_k e_k`` per coordinate: a bound of the error curve on [0, 1] (convex hull)."""
        return tuple(max((self._hi[:, j] - self._lo[:, j]) / 2) for j in range(self.dimension))

    # ------------------------------------------------------------------ evaluation
    def evaluate(self, t, extrapolate: bool = False) -> tuple:
        """The box ``[P](t)`` by the interval de Casteljau algorithm (12.19), exact.

        ``t`` must lie in [0, 1] unless ``extrapolate=True`` (then the boxes grow as
        described in 12.2.3).
        """
        t = _unit(t, extrapolate)
        level = [list(row) for row in self.control_boxes]
        s = 1 - t
        while len(level) > 1:
            level = [[s * a + t * b for a, b in zip(p, q)] for p, q in zip(level[:-1], level[1:])]
        return tuple(level[0])

    def evaluate_centered(self, t, extrapolate: bool = False) -> tuple:
        """The box ``[P](t)`` in centered form (12.23) / (12.27)-(12.29): ``center(t) + r(t)[-1, 1]``."""
        t = _unit(t, extrapolate)
        center = bz.de_casteljau(self.center_curve().points_array(), t)
        radius = self.error_radius(t, extrapolate=True)
        return tuple(Interval._make(c - r, c + r) for c, r in zip(center, radius))

    def error_radius(self, t, extrapolate: bool = False) -> tuple:
        """``sum_k e_k |B_k^n(t)|`` per coordinate (12.29); equals ``e(t)`` on [0, 1] and
        ``|e~(t)|`` (12.28) outside."""
        t = _unit(t, extrapolate)
        n = self.degree
        err = (self._hi - self._lo) / 2
        basis = [abs(bz.binomial(n, k) * (1 - t) ** (n - k) * t**k) for k in range(n + 1)]
        return tuple(sum(err[k, j] * basis[k] for k in range(n + 1)) for j in range(self.dimension))

    def evaluate_float(self, ts, method: str = "horner"):
        """Outward-rounded float boxes at many float parameters, vectorized.

        The center curve is evaluated with its certified radius (:func:`exactcagd.numeric.evaluate`);
        the error radius with the error curve ``e(t)`` on [0, 1] and with ``e~(t)``
        of (12.28) (signs ``(-1)^k`` for ``t < 0``, ``(-1)^(n+k)`` for ``t > 1``) outside.

        Returns
        -------
        lo, hi : float arrays ``(len(ts), d)`` with ``lo <= [P](t) <= hi`` exactly.
        """
        from .evaluation import _parameters, evaluate

        t = _parameters(ts, "ts")
        c_val, c_rad = evaluate(self.center_curve(), t, method=method)
        n = self.degree
        err = (self._hi - self._lo) / 2
        e_bound = np.empty_like(c_val)
        regions = ((t < 0, [(-1) ** k for k in range(n + 1)]), ((t >= 0) & (t <= 1), [1] * (n + 1)),
                   (t > 1, [(-1) ** (n + k) for k in range(n + 1)]))
        for mask, signs in regions:
            if mask.any():
                signed = BezierCurve._trusted(err * np.array(signs, dtype=object)[:, None], None)
                ev, er = evaluate(signed, t[mask], method=method)
                e_bound[mask] = up(np.abs(ev) + er)
        with np.errstate(all="ignore"):
            lo = down(down(c_val - c_rad) - e_bound)
            hi = up(up(c_val + c_rad) + e_bound)
        bad = ~(np.isfinite(lo) & np.isfinite(hi))
        lo[bad], hi[bad] = -np.inf, np.inf
        return lo, hi

    def contains_point(self, t, point, extrapolate: bool = False) -> bool:
        """True if ``point`` lies in the box ``[P](t)`` (exact)."""
        box = self.evaluate_centered(t, extrapolate)
        pt = _box(point, self.dimension, "point")
        return all(b.contains(p) for b, p in zip(box, pt))

    def contains_curve(self, curve: BezierCurve) -> bool:
        """True if the polynomial ``curve`` (after elevation to this degree) has its control
        points in the control boxes; then ``curve(t) in [P](t)`` for every ``t`` (12.15).

        A sufficient test only: ``False`` does not prove that the curve leaves the region.
        """
        _polynomial(curve, "contains_curve")
        if curve.dimension != self.dimension:
            raise DimensionError(f"curve of dimension {curve.dimension} vs interval curve of dimension {self.dimension}")
        pts = curve.points_array()
        if curve.degree > self.degree:
            try:
                pts = bz.reduce_degree(pts, self.degree)
            except DegreeError:
                return False
        else:
            pts = bz.elevate(pts, self.degree - curve.degree)
        return bool(np.all(self._lo <= pts) and np.all(pts <= self._hi))

    # ------------------------------------------------------------------ operations
    def subdivide(self, t) -> tuple["IntervalBezierCurve", "IntervalBezierCurve"]:
        """Split at ``t`` in [0, 1] by the interval de Casteljau algorithm (12.19)-(12.20).

        The pieces' boxes at corresponding parameters equal the original boxes (no
        interval inflation inside [0, 1], 12.2.3).
        """
        t = _unit(t, False)
        left_c, right_c = bz.subdivide(self.center_curve().points_array(), t)
        left_e, right_e = bz.subdivide(self.error_curve().points_array(), t)
        return (IntervalBezierCurve._trusted(left_c - left_e, left_c + left_e),
                IntervalBezierCurve._trusted(right_c - right_e, right_c + right_e))

    def elevate(self, r: int = 1) -> "IntervalBezierCurve":
        """Degree elevation by ``r`` (convex combinations, applied to lower and upper bounds)."""
        r = to_count(r, where="elevation amount", error=DegreeError)
        return IntervalBezierCurve._trusted(bz.elevate(self._lo, r), bz.elevate(self._hi, r))

    def hodograph(self) -> "IntervalBezierCurve":
        """The interval hodograph with boxes ``n([P_{k+1}] - [P_k])`` (12.2.5).

        It bounds ``P'(t)`` for every curve with *fixed* control points ``P_k in [P_k]``
        (not for control points that move with ``t``, see the notes)."""
        n = self.degree
        if n == 0:
            zero = self._lo * 0
            return IntervalBezierCurve._trusted(zero, zero.copy())
        return IntervalBezierCurve._trusted(n * (self._lo[1:] - self._hi[:-1]), n * (self._hi[1:] - self._lo[:-1]))

    def reparametrize(self, a, b) -> "IntervalBezierCurve":
        """The interval curve restricted to [a, b] within [0, 1], reparametrized to [0, 1]."""
        a, b = _unit(a, False), _unit(b, False)
        if a >= b:
            raise DomainError(f"reparametrize needs 0 <= a < b <= 1, got [{a}, {b}]")
        c = bz.restrict(self.center_curve().points_array(), a, b)
        e = bz.restrict(self.error_curve().points_array(), a, b)
        return IntervalBezierCurve._trusted(c - e, c + e)

    def __add__(self, other) -> "IntervalBezierCurve":
        """Sum of two interval curves (Minkowski sum of the boxes, degrees matched by elevation)."""
        if not isinstance(other, IntervalBezierCurve):
            return NotImplemented
        if other.dimension != self.dimension:
            raise DimensionError("interval curves of different dimensions")
        n = max(self.degree, other.degree)
        a, b = self.elevate(n - self.degree), other.elevate(n - other.degree)
        return IntervalBezierCurve._trusted(a._lo + b._lo, a._hi + b._hi)

    def __mul__(self, other) -> "IntervalBezierCurve":
        """Product with a number, an interval, or a 1-d interval polynomial (12.6).

        For two interval polynomials of degrees ``m`` and ``n`` the Bernstein product
        (notes 9.3) is formed in interval arithmetic,
        ``[c_k] = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) [a_i][b_j]``; on [0, 1] it contains
        ``p(t) q(t)`` for all members ``p in [p]``, ``q in [q]``.  A 1-d factor multiplies
        every coordinate.
        """
        if isinstance(other, IntervalBezierCurve):
            if other.dimension != 1 and self.dimension != 1:
                raise DimensionError("a product of interval curves needs a 1-d factor (an interval polynomial)")
            a, b = (self, other) if other.dimension == 1 else (other, self)
            m, n = b.degree, a.degree
            scalar = b.control_boxes
            boxes = a.control_boxes
            out = []
            for k in range(m + n + 1):
                acc = [Interval._make(mpq(0), mpq(0)) for _ in range(a.dimension)]
                for i in range(max(0, k - n), min(m, k) + 1):
                    w = mpq(bz.binomial(m, i) * bz.binomial(n, k - i), bz.binomial(m + n, k))
                    acc = [x + w * (scalar[i][0] * y) for x, y in zip(acc, boxes[k - i])]
                out.append(acc)
            return IntervalBezierCurve(out)
        try:
            factor = as_interval(other)
        except InputError:
            return NotImplemented
        return IntervalBezierCurve([[factor * x for x in box] for box in self.control_boxes])

    __rmul__ = __mul__

    # ------------------------------------------------------------------ misc
    def __eq__(self, other) -> bool:
        if not isinstance(other, IntervalBezierCurve):
            return NotImplemented
        return self._lo.shape == other._lo.shape and bool(np.all(self._lo == other._lo) and np.all(self._hi == other._hi))

    def __hash__(self):
        return hash((tuple(self._lo.reshape(-1)), tuple(self._hi.reshape(-1))))

    def to_dict(self) -> dict:
        return {
            "degree": self.degree,
            "lower": [[rational_str(x) for x in row] for row in self._lo],
            "upper": [[rational_str(x) for x in row] for row in self._hi],
        }

    def __repr__(self) -> str:
        return f"<IntervalBezierCurve degree={self.degree} dimension={self.dimension}>"


def interval_polynomial(coefficients) -> IntervalBezierCurve:
    """An interval polynomial ``sum_k [a_k, b_k] B_k^n(t)`` (12.6) as a 1-d interval curve.

    >>> p = interval_polynomial([(0, 1), 2, (1, 3)])
    >>> p.evaluate("1/2")[0]                      # [p_min(1/2), p_max(1/2)] (12.8)
    Interval(5/4, 2)
    """
    return IntervalBezierCurve([[c] for c in coefficients])


# ---------------------------------------------------------------------------- approximation
def derivative_bounds(curve: BezierCurve, r: int) -> tuple:
    """Bounds of the ``r``-th derivative of a polynomial curve on [0, 1] (12.68)-(12.69).

    ``n!/(n-r)! min_k Delta^r P_k <= P^(r)(t) <= n!/(n-r)! max_k Delta^r P_k`` per coordinate
    (convex hull of the Bernstein coefficients of the derivative); zero for ``r > n``.

    >>> derivative_bounds(BezierCurve([[0], [1], [4]]), 2)
    (Interval(4, 4),)
    """
    _polynomial(curve, "derivative_bounds")
    if not isinstance(r, int) or r < 0:
        raise InputError(f"derivative order must be a non-negative integer, got {r!r}")
    if r > curve.degree:
        return tuple(Interval._make(mpq(0), mpq(0)) for _ in range(curve.dimension))
    c = curve.points_array()
    for _ in range(r):
        c = bz.derivative(c)
    return tuple(Interval._make(min(c[:, j]), max(c[:, j])) for j in range(curve.dimension))


def _derivatives_at_ends(curve: BezierCurve, count: int) -> tuple[list, list]:
    c = curve.points_array()
    start, end = [], []
    for _ in range(count):
        start.append(list(c[0]))
        end.append(list(c[-1]))
        c = bz.derivative(c)
    return start, end


def hermite_interval_from_data(start, end, bound) -> IntervalBezierCurve:
    """Interval Bézier curve of degree ``2m`` from symmetric end-point Hermite data (12.49)-(12.64).

    The Hermite interpolant ``H`` of odd degree ``N = 2m - 1`` matches ``f^(i)(0)`` and
    ``f^(i)(1)`` for ``i < m``; by (12.52) ``f(t) - H(t) = f^(2m)(xi)/(2m)! t^m (t - 1)^m``
    and ``t^m (t-1)^m = (-1)^m B_m^{2m}(t) / C(2m, m)``, so

        f(t) in H(t) + (-1)^m [f^(2m)] / ((2m)! C(2m, m)) B_m^{2m}(t),

    i.e. ``H`` elevated to degree ``2m`` with the interval added to the middle coefficient
    only (12.58)-(12.59), (12.62)-(12.63), (12.77).

    Parameters
    ----------
    start, end : sequences of length ``m``
        ``[f(0), f'(0), ..., f^(m-1)(0)]`` and the same at 1; each entry a number, an
        interval, or a point (sequence of those) for a curve.
    bound : interval or box
        ``[f^(2m)]`` on [0, 1].

    Examples
    --------
    >>> p = hermite_interval_from_data([1], [3], Interval(-2, 2))   # linear, |f''| <= 2
    >>> [b[0] for b in p.control_boxes]                              # (12.59)
    [Interval(1, 1), Interval(3/2, 5/2), Interval(3, 3)]
    """
    m = len(start)
    if m == 0 or len(end) != m:
        raise InputError(f"Hermite data need m >= 1 derivatives at each end, got {len(start)} and {len(end)}")
    s = [_box(x, None, f"start[{i}]") for i, x in enumerate(start)]
    e = [_box(x, len(s[0]), f"end[{i}]") for i, x in enumerate(end)]
    d = len(s[0])
    for i, x in enumerate(s):
        if len(x) != d:
            raise DimensionError(f"start[{i}] has dimension {len(x)}, expected {d}")
    rem = _box(bound, d, "bound")
    big_n = 2 * m - 1
    coeffs: list = [None] * (big_n + 1)
    for i in range(m):
        scale = mpq(math.factorial(big_n - i), math.factorial(big_n))
        # H^(i)(0) = N!/(N-i)! sum_{j<=i} (-1)^(i-j) C(i,j) c_j
        coeffs[i] = [
            scale * s[i][k] - sum((((-1) ** (i - j) * bz.binomial(i, j)) * coeffs[j][k] for j in range(i)), mpq(0))
            for k in range(d)
        ]
        # H^(i)(1) = N!/(N-i)! sum_{j<=i} (-1)^j C(i,j) c_{N-j}
        coeffs[big_n - i] = [
            (-1) ** i * (scale * e[i][k] - sum(((-1) ** j * bz.binomial(i, j) * coeffs[big_n - j][k] for j in range(i)), mpq(0)))
            for k in range(d)
        ]
    lo = np.array([[as_interval(x).lo for x in row] for row in coeffs], dtype=object)
    hi = np.array([[as_interval(x).hi for x in row] for row in coeffs], dtype=object)
    lo, hi = bz.elevate(lo, 1), bz.elevate(hi, 1)
    factor = mpq((-1) ** m, math.factorial(2 * m) * bz.binomial(2 * m, m))
    for k in range(d):
        middle = Interval._make(lo[m, k], hi[m, k]) + factor * rem[k]
        lo[m, k], hi[m, k] = middle.lo, middle.hi
    return IntervalBezierCurve._trusted(lo, hi)


def hermite_interval(curve: BezierCurve, m: int) -> IntervalBezierCurve:
    """Interval curve of degree ``2m`` containing a polynomial curve (12.49)-(12.64), (12.77).

    End-point derivatives of orders ``< m`` are interpolated exactly; the remainder uses
    the bounds (12.69) of ``P^(2m)``.  Exact (zero width) when ``2m >= degree``.

    >>> from exactcagd import BezierCurve
    >>> c = BezierCurve([[0], [0], [3], [0], [0], [1]])
    >>> hermite_interval(c, 2).width()[0] > 0
    True
    """
    _polynomial(curve, "hermite_interval")
    if not isinstance(m, int) or m < 1:
        raise InputError(f"hermite_interval needs an integer m >= 1, got {m!r}")
    start, end = _derivatives_at_ends(curve, m)
    return hermite_interval_from_data(start, end, derivative_bounds(curve, 2 * m))


def _newton_power(nodes: list, values: np.ndarray) -> np.ndarray:
    """Power coefficients of the interpolating polynomial (Newton divided differences), exact."""
    k = len(nodes) - 1
    table = [values[i].copy() for i in range(k + 1)]
    coef = [table[0]]
    for level in range(1, k + 1):
        table = [(table[i + 1] - table[i]) / (nodes[i + level] - nodes[i]) for i in range(k + 1 - level)]
        coef.append(table[0])
    zero = coef[0] * 0
    power = [coef[k]]  # p = coef[k]; p <- p (t - t_l) + coef[l] for l = k-1, ..., 0
    for level in range(k - 1, -1, -1):
        shifted = [zero] + power
        tail = power + [zero]
        power = [a - nodes[level] * b for a, b in zip(shifted, tail)]
        power[0] = power[0] + coef[level]
    return np.array([list(p) for p in power], dtype=object)


def _interpolate(nodes: list, values: np.ndarray) -> np.ndarray:
    """Bernstein coefficients (degree ``len(nodes) - 1``) of the Lagrange interpolant (12.36)."""
    return bz.from_power(_newton_power(nodes, values), len(nodes) - 1)


def _nodes(nodes) -> list:
    qs = [to_rational(x, where="node") for x in nodes]
    if len(set(qs)) != len(qs):
        raise InputError("interpolation nodes must be distinct")
    bad = [q for q in qs if not 0 <= q <= 1]
    if bad:
        raise DomainError(f"interpolation nodes must lie in [0, 1]; got {bad[0]}")
    return sorted(qs)


def lagrange_interval(curve: BezierCurve, nodes) -> IntervalBezierCurve:
    """Interval curve of degree ``k + 1`` (``k + 1`` nodes) containing a polynomial curve.

    ``P(t) in P_k(t) + [P^(k+1)] / (k+1)! prod_j (t - t_j)`` (12.42), (12.74), with the
    Lagrange interpolant ``P_k`` at the exact nodes in [0, 1], the derivative box (12.69),
    and the node polynomial written in the Bernstein basis of degree ``k + 1`` (12.43):
    each coefficient ``w_i [D] / (k+1)!`` is an interval; on [0, 1] the basis is
    non-negative, so the sum contains ``[D] omega(t) / (k+1)!``.

    >>> from exactcagd import BezierCurve
    >>> c = BezierCurve([[0], [2], [-1], [3]])
    >>> lagrange_interval(c, [0, 1]).contains_point("1/3", c.evaluate("1/3"))
    True
    """
    _polynomial(curve, "lagrange_interval")
    ts = _nodes(nodes)
    k = len(ts) - 1
    values = np.array([list(curve.evaluate(t)) for t in ts], dtype=object)
    base = bz.elevate(_interpolate(ts, values), 1)
    omega_power = np.array([[mpq(1)]], dtype=object)
    for t in ts:
        omega_power = np.concatenate([np.array([[mpq(0)]], dtype=object), omega_power]) - np.concatenate(
            [omega_power * t, np.array([[mpq(0)]], dtype=object)]
        )
    omega = bz.from_power(omega_power, k + 1)[:, 0] / math.factorial(k + 1)
    deriv = derivative_bounds(curve, k + 1)
    lo, hi = base.copy(), base.copy()
    for i in range(k + 2):
        for j in range(curve.dimension):
            term = omega[i] * deriv[j]
            lo[i, j] += term.lo
            hi[i, j] += term.hi
    return IntervalBezierCurve._trusted(lo, hi)


def enclose(curve: BezierCurve, approximant: BezierCurve, pieces: int = 8) -> IntervalBezierCurve:
    """The approximant with every control box widened so that the exact curve lies inside.

    For ``P = X / W`` (``W = 1`` for a polynomial curve) and a polynomial approximant ``Q``
    of degree ``m``: ``P - Q = (X - Q W) / W``; the numerator ``D`` is an exact Bernstein
    polynomial of degree ``n + m``.  On each of ``pieces`` equal parameter intervals the
    hull of the Bernstein coefficients of ``D`` and of ``W`` restricted to the piece
    bounds both (convex hull property, 12.69 with ``r = 0``), so
    ``P(t) - Q(t) in R = union_pieces [D]/[W]``, and, since ``sum_k B_k = 1``,
    ``P(t) in sum_k (Q_k + R) B_k(t)`` for all ``t`` in [0, 1].  Raises
    :class:`DomainError` if the weight hull of a piece contains 0.

    >>> from exactcagd import BezierCurve
    >>> quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    >>> box = enclose(quarter, BezierCurve([[1, 0], [1, "1/2"], ["1/2", 1], [0, 1]]))
    >>> box.contains_point("1/2", quarter.evaluate("1/2"))
    True
    """
    _polynomial(approximant, "enclose (approximant)")
    if not isinstance(curve, BezierCurve):
        raise InputError(f"enclose needs a BezierCurve, got {type(curve).__name__}")
    if curve.dimension != approximant.dimension:
        raise DimensionError(f"curve of dimension {curve.dimension} vs approximant of dimension {approximant.dimension}")
    if not isinstance(pieces, int) or pieces < 1:
        raise InputError(f"pieces must be a positive integer, got {pieces!r}")
    q = approximant.points_array()
    if curve.is_rational:
        hom = curve.homogeneous()
        x, w = hom[:, :-1], hom[:, -1:]
        diff = bz.elevate(x, approximant.degree) - bz.product(q, w)
    else:
        p = curve.points_array()
        top = max(curve.degree, approximant.degree)
        diff = bz.elevate(p, top - curve.degree) - bz.elevate(q, top - approximant.degree)
        w = np.array([[mpq(1)]], dtype=object)
    rem = None
    for i in range(pieces):
        a, b = mpq(i, pieces), mpq(i + 1, pieces)
        d_piece = bz.restrict(diff, a, b) if pieces > 1 else diff
        w_piece = bz.restrict(w, a, b) if pieces > 1 else w
        w_hull = Interval._make(min(w_piece[:, 0]), max(w_piece[:, 0]))
        if w_hull.lo <= 0 <= w_hull.hi:
            raise DomainError("the weight hull of the curve contains 0; subdivide the curve first")
        box = [Interval._make(min(d_piece[:, j]), max(d_piece[:, j])) / w_hull for j in range(curve.dimension)]
        rem = box if rem is None else [r.hull(x) for r, x in zip(rem, box)]
    lo = q + np.array([r.lo for r in rem], dtype=object)
    hi = q + np.array([r.hi for r in rem], dtype=object)
    return IntervalBezierCurve._trusted(lo, hi)


def approximate(curve: BezierCurve, degree: int, pieces: int = 8) -> IntervalBezierCurve:
    """An interval Bézier curve of the given degree containing ``curve`` on [0, 1].

    The center is the Lagrange interpolant of the exact curve (polynomial or rational)
    at ``degree + 1`` rational nodes near the Chebyshev nodes of [0, 1]; the boxes come
    from :func:`enclose` (with ``pieces``).  Subdividing the curve first (``curve.subdivide``) and
    approximating the pieces shrinks the boxes (12.1, "uniformly decreasing width").

    >>> from exactcagd import BezierCurve
    >>> quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    >>> float(max(approximate(quarter, 6).max_error())) < 1e-3
    True
    """
    if not isinstance(curve, BezierCurve):
        raise InputError(f"approximate needs a BezierCurve, got {type(curve).__name__}")
    if not isinstance(degree, int) or degree < 0:
        raise InputError(f"degree must be a non-negative integer, got {degree!r}")
    if degree == 0:
        nodes = [mpq(1, 2)]
    else:
        nodes = [_chebyshev_node(i, degree) for i in range(degree + 1)]
    values = np.array([list(curve.evaluate(t)) for t in nodes], dtype=object)
    center = BezierCurve._trusted(_interpolate(nodes, values), None)
    return enclose(curve, center, pieces)


def _chebyshev_node(i: int, k: int) -> mpq:
    """A rational near the i-th of k+1 Chebyshev-Lobatto points of [0, 1] (ends exact)."""
    if i == 0:
        return mpq(0)
    if i == k:
        return mpq(1)
    f = Fraction((1 - math.cos(math.pi * i / k)) / 2).limit_denominator(1 << 12)
    return mpq(f.numerator, f.denominator)


def _polynomial(curve, where: str) -> None:
    if not isinstance(curve, BezierCurve):
        raise InputError(f"{where} needs a BezierCurve, got {type(curve).__name__}")
    if curve.is_rational:
        raise NotSupportedError(f"{where}: rational curves are not supported here; use enclose/approximate")


def _unit(t, extrapolate: bool):
    q = to_rational(t, where="t")
    if not extrapolate and not 0 <= q <= 1:
        raise DomainError(f"t = {q} lies outside [0, 1] (pass extrapolate=True to evaluate outside)")
    return q

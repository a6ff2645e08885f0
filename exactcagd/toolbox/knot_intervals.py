"""B-spline curves in knot-interval form (Sederberg's notes (003) 6.13), exact.

A knot interval is the difference of two consecutive knots.  For odd degree the
interval ``d_i`` belongs to the control edge ``P_i P_{i+1}``, for even degree to the
control point ``P_i``.  In knot-vector terms (standard convention, 0-based control
points, ``P_i`` has polar label ``(k_{i+1}, ..., k_{i+p})``)::

    k_{j+1} - k_j = d_{j - c},   c = ceil(p / 2),   k_c = origin.

Every operation is a resampling of the polar form
(:func:`exactcagd.toolbox.bspline_extras.segment_blossom`): the new control points are
the polar values at the labels of the new knot intervals.  The notes' explicit
formulas -- interval halving (6.3)-(6.5), hodograph (6.6), degree elevation (6.9) and
the degree-3 elevation -- are provided separately and checked against it.

>>> from exactcagd.toolbox.knot_intervals import KnotIntervalCurve
>>> c = KnotIntervalCurve([[0, 0], [4, 0], [4, 4], [0, 4]], [1, 1, 1, 1], degree=3)
>>> c.evaluate(0)
(mpq(2,3), mpq(2,3))
>>> len(c.split_interval(1, "1/2").control_points)
5
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DomainError, InputError, KnotError, NotSupportedError
from ..exact.scalars import to_rational
from ..geometry._validate import point_array
from .bspline_extras import SplineCurve, segment_blossom

__all__ = [
    "KnotIntervalCurve",
    "halving_quadratic",
    "halving_cubic",
    "hodograph_points",
    "elevate_quadratic",
    "elevate_cubic",
    "split_cubic_construction",
]


class KnotIntervalCurve:
    """A polynomial B-spline curve given by control points and knot intervals (notes 6.13).

    Parameters
    ----------
    control_points : ``N`` points
    intervals : knot intervals.  Periodic: ``N`` of them (``d_i`` of edge ``P_i P_{i+1}``
        for odd degree, of point ``P_i`` for even degree, indices mod ``N``).  Open:
        ``N + p - 2`` of them, i.e. including the ``floor((p-1)/2)`` end-condition intervals
        hung past each end (notes 6.13); the list starts with ``d_{1-c}``.
    degree : int >= 1
    periodic : bool, default True
    origin : the knot value ``k_c`` (default 0); it only translates the parameter.

    Examples
    --------
    >>> c = KnotIntervalCurve([[0, 0], [2, 0], [2, 2], [0, 2]], [1, 3, 1, 1], degree=2)
    >>> c.polar_labels()[1]
    (mpq(1,1), mpq(4,1))
    """

    __slots__ = ("_points", "_d", "_p", "_periodic", "_origin")

    def __init__(self, control_points, intervals, degree: int, periodic: bool = True, origin=0):
        pts = point_array(control_points, 1, "control_points")
        p = int(degree)
        if p < 1:
            raise DegreeError("knot-interval curves need degree >= 1")
        d = [to_rational(x, where=f"intervals[{i}]") for i, x in enumerate(intervals)]
        if any(x < 0 for x in d):
            raise KnotError("knot intervals must be non-negative")
        n = pts.shape[0]
        if periodic:
            if len(d) != n:
                raise KnotError(f"a periodic curve with {n} control points needs {n} knot intervals, got {len(d)}")
            if n < p + 1:
                raise InputError(f"a periodic degree-{p} curve needs at least {p + 1} control points")
            if sum(d) == 0:
                raise KnotError("the period (sum of the knot intervals) must be positive")
        elif len(d) != n + p - 2:
            raise KnotError(f"an open degree-{p} curve with {n} control points needs {n + p - 2} knot intervals, got {len(d)}")
        self._points, self._d, self._p, self._periodic = pts, d, p, bool(periodic)
        self._origin = to_rational(origin, where="origin")
        if not periodic:
            self.to_spline()  # validates the domain and multiplicities

    # ------------------------------------------------------------------ properties
    @property
    def degree(self) -> int:
        return self._p

    @property
    def intervals(self) -> tuple:
        return tuple(self._d)

    @property
    def periodic(self) -> bool:
        return self._periodic

    @property
    def origin(self):
        return self._origin

    @property
    def control_points(self) -> tuple:
        return tuple(tuple(p) for p in self._points)

    def points_array(self) -> np.ndarray:
        return self._points.copy()

    @property
    def _c(self) -> int:
        return (self._p + 1) // 2

    # ------------------------------------------------------------------ knots and labels
    def knot(self, j: int):
        """Knot ``k_j`` (any integer ``j`` for a periodic curve; ``0 <= j < N + p + 1`` for an open one)."""
        c, d = self._c, self._d
        if self._periodic:
            n = len(d)
            q, r = divmod(j - c, n)
            return self._origin + q * sum(d) + sum(d[:r])
        n_knots = self._points.shape[0] + self._p + 1
        if not 0 <= j < n_knots:
            raise InputError(f"knot index {j} outside 0..{n_knots - 1}")
        # intervals list starts with d_{1-c} = k_2 - k_1; k_0 = k_1 and k_{last} = k_{last-1} are dummies
        diffs = [mpq(0)] + d + [mpq(0)]
        base = self._origin - sum(diffs[:c])
        return base + sum(diffs[:j])

    def polar_labels(self) -> list[tuple]:
        """Polar label of every control point (notes 6.13, Figure 6.14): sums of knot intervals."""
        p = self._p
        return [tuple(self.knot(i + j) for j in range(1, p + 1)) for i in range(self._points.shape[0])]

    def to_spline(self) -> SplineCurve:
        """The same curve as a :class:`~exactcagd.toolbox.bspline_extras.SplineCurve`.

        Periodic curves are unrolled over one period (the first ``p`` points repeated).
        """
        p, n = self._p, self._points.shape[0]
        if self._periodic:
            pts = np.concatenate([self._points, self._points[:p]])
            knots = [self.knot(j) for j in range(n + 2 * p + 1)]
        else:
            pts = self._points
            knots = [self.knot(j) for j in range(n + p + 1)]
        return SplineCurve(pts, knots)

    @property
    def domain(self) -> tuple:
        return self.to_spline().domain

    def evaluate(self, t) -> tuple:
        """Exact point at ``t``; periodic curves accept any ``t`` (reduced mod the period)."""
        t = to_rational(t, where="t")
        spline = self.to_spline()
        if self._periodic:
            lo, hi = spline.domain
            period = hi - lo
            t = lo + (t - lo) - period * ((t - lo) // period)
        return spline.evaluate(t)

    # ------------------------------------------------------------------ the resampling mechanism
    def _segment(self, m: int) -> tuple[np.ndarray, list]:
        """Control points and local knots of segment ``m`` (span ``[k_m, k_{m+1}]``)."""
        p, n = self._p, self._points.shape[0]
        if self._periodic:
            ctrl = np.stack([self._points[(m - p + i) % n] for i in range(p + 1)])
        else:
            if not p <= m < n:
                raise DomainError(f"segment {m} outside the open curve's domain")
            ctrl = self._points[m - p : m + 1]
        return ctrl, [self.knot(j) for j in range(m - p + 1, m + p + 1)]

    def _segment_containing(self, a, b) -> int:
        """Index ``m`` of the non-empty segment with ``k_m <= a < b <= k_{m+1}``."""
        n = self._points.shape[0]
        if self._periodic:
            period = sum(self._d)
            start = self._c + n * int(((a - self._origin) // period)) - n
            candidates = range(start, start + 3 * n + 1)
        else:
            candidates = range(self._p, n)
        for m in candidates:
            if self.knot(m) <= a and b <= self.knot(m + 1) and self.knot(m) < self.knot(m + 1):
                return m
        raise KnotError(f"the interval [{a}, {b}] straddles a knot of the curve (not a refinement)")

    def _resample(self, new_intervals, new_degree: int, origin=None) -> "KnotIntervalCurve":
        """Control points for new knot intervals / degree: polar values at the new labels."""
        origin = self._origin if origin is None else origin
        shell = KnotIntervalCurve.__new__(KnotIntervalCurve)
        shell._d, shell._p, shell._periodic, shell._origin = list(new_intervals), new_degree, self._periodic, origin
        if self._periodic:
            n_new = len(shell._d)
        else:
            n_new = len(shell._d) - new_degree + 2
        shell._points = np.empty((n_new, self._points.shape[1]), dtype=object)
        for j in range(n_new):
            label = [shell.knot(j + r) for r in range(1, new_degree + 1)]
            spans = sorted(range(j, j + new_degree + 1), key=lambda l: abs(2 * l - 2 * j - new_degree))
            value = None
            for l in spans:
                if not self._periodic and not (new_degree <= l < n_new):
                    continue
                a, b = shell.knot(l), shell.knot(l + 1)
                if a < b:
                    ctrl, local = self._segment(self._segment_containing(a, b))
                    value = _polar(ctrl, local, label, self._p)
                    break
            if value is None:  # the point's basis function vanishes on the domain: any segment will do
                ctrl, local = self._segment(self._p if not self._periodic else self._c)
                value = _polar(ctrl, local, label, self._p)
            shell._points[j] = value
        return shell

    # ------------------------------------------------------------------ operations (6.13)
    def split_interval(self, i: int, left) -> "KnotIntervalCurve":
        """Knot insertion as interval splitting (6.13.1): ``d_i -> (left, d_i - left)``.

        ``left = 0`` or ``left = d_i`` inserts a zero knot interval (a double knot).
        """
        d = list(self._d)
        if not 0 <= i < len(d):
            raise InputError(f"interval index {i} outside 0..{len(d) - 1}")
        left = to_rational(left, where="left")
        if not 0 <= left <= d[i]:
            raise DomainError(f"split point {left} outside [0, {d[i]}]")
        if d[i] == 0:
            raise DomainError("cannot split a zero knot interval")
        new = d[:i] + [left, d[i] - left] + d[i + 1 :]
        return self._resample(new, self._p)

    def halve(self) -> "KnotIntervalCurve":
        """Interval halving (6.13.2): every knot interval cut in half (generic resampling)."""
        new = [x / 2 for x in self._d for _ in range(2)]
        if not self._periodic:
            raise NotSupportedError("interval halving is defined here for periodic curves (as in the notes)")
        return self._resample(new, self._p)

    def hodograph(self) -> "KnotIntervalCurve":
        """The derivative curve (6.13.4): degree ``p - 1``, control points ``c_i (P_{i+1} - P_i)``.

        Periodic curves only (the notes' setting).  For even ``p`` the interval list is
        rotated by one and the origin moves by ``d_0`` (the interval of ``P_i`` becomes
        the interval of the edge ``Q_{i-1} Q_i``); the parameter is the same.
        """
        if not self._periodic:
            raise NotSupportedError("use to_spline().derivative() for open curves")
        if self._p == 1:
            raise DegreeError("the hodograph of a degree-1 curve is piecewise constant (degree 0)")
        q = hodograph_points(self._points, self._d, self._p)
        if self._p % 2 == 1:
            return KnotIntervalCurve(q, self._d, self._p - 1, origin=self._origin)
        return KnotIntervalCurve(q, self._d[1:] + self._d[:1], self._p - 1, origin=self._origin + self._d[0])

    def elevate(self) -> "KnotIntervalCurve":
        """Degree elevation (6.13.5): intervals ``d_0, 0, d_1, 0, ...``; Ramshaw's averages (6.7)-(6.8)."""
        if not self._periodic:
            raise NotSupportedError("use to_spline().elevate() for open curves")
        new = [x for v in self._d for x in (v, mpq(0))]
        return self._resample(new, self._p + 1)

    def same_curve(self, other: "KnotIntervalCurve", shift=0) -> bool:
        """Exact identity ``self(t) == other(t + shift)`` (periodic curves: on one period)."""
        a, b = self.to_spline(), other.to_spline()
        lo, hi = a.domain
        shift = to_rational(shift)
        cuts = sorted(set(a.breakpoints()) | {k - shift for k in b.breakpoints() if lo <= k - shift <= hi} | {lo, hi})
        p = max(a.degree, b.degree)
        for x, y in zip(cuts[:-1], cuts[1:]):
            for r in range(p + 1):
                t = x + (y - x) * mpq(r + 1, p + 2)
                if self.evaluate(t) != other.evaluate(t + shift):
                    return False
        return True

    def __repr__(self) -> str:
        kind = "periodic" if self._periodic else "open"
        return f"<KnotIntervalCurve {kind} degree={self._p} points={self._points.shape[0]}>"


def _polar(ctrl, local, label, p):
    """Polar value at ``label``; a label one longer than the degree is Ramshaw's average."""
    if len(label) == p:
        return segment_blossom(ctrl, local, label)
    if len(label) == p + 1:
        acc = None
        for drop in range(p + 1):
            v = segment_blossom(ctrl, local, label[:drop] + label[drop + 1 :])
            acc = v if acc is None else acc + v
        return acc * mpq(1, p + 1)
    raise DegreeError("resampling changes the degree by at most +1")


# ---------------------------------------------------------------------------- the notes' explicit formulas
def _prep(points, intervals):
    pts = point_array(points, 1, "control_points")
    d = [to_rational(x, where="interval") for x in intervals]
    if len(d) != pts.shape[0]:
        raise KnotError("periodic formulas: one knot interval per control point")
    return pts, d, pts.shape[0]


def halving_quadratic(points, intervals) -> np.ndarray:
    """Interval halving of a periodic quadratic curve, notes (6.3) (a non-uniform Chaikin).

    ``Q_{2i} = ((d_i + 2 d_{i+1}) P_i + d_i P_{i+1}) / (2 (d_i + d_{i+1}))``,
    ``Q_{2i+1} = (d_{i+1} P_i + (2 d_i + d_{i+1}) P_{i+1}) / (2 (d_i + d_{i+1}))``.
    ``Q_{2i}`` carries the interval ``d_i / 2`` and ``Q_{2i+1}`` the interval ``d_{i+1} / 2``:
    the new curve is ``KnotIntervalCurve(Q, [d_0/2, d_1/2, d_1/2, ..., d_0/2], 2,
    origin=d_0 / 2)`` (the generic resampling numbers the same points from ``Q_{-1}``).
    """
    pts, d, n = _prep(points, intervals)
    out = []
    for i in range(n):
        a, b = d[i], d[(i + 1) % n]
        p0, p1 = pts[i], pts[(i + 1) % n]
        out.append(((a + 2 * b) * p0 + a * p1) / (2 * (a + b)))
        out.append((b * p0 + (2 * a + b) * p1) / (2 * (a + b)))
    return np.stack(out)


def halving_cubic(points, intervals) -> np.ndarray:
    """Interval halving of a periodic cubic curve, notes (6.4)-(6.5).

    ``Q_{2i+1} = ((d_i + 2 d_{i+1}) P_i + (d_i + 2 d_{i-1}) P_{i+1}) / (2 (d_{i-1} + d_i + d_{i+1}))``,
    ``Q_{2i} = (d_i Q_{2i-1} + (d_{i-1} + d_i) P_i + d_{i-1} Q_{2i+1}) / (2 (d_{i-1} + d_i))``.
    """
    pts, d, n = _prep(points, intervals)
    odd = []
    for i in range(n):
        dm, d0, dp = d[i - 1], d[i], d[(i + 1) % n]
        odd.append(((d0 + 2 * dp) * pts[i] + (d0 + 2 * dm) * pts[(i + 1) % n]) / (2 * (dm + d0 + dp)))
    out = []
    for i in range(n):
        dm, d0 = d[i - 1], d[i]
        even = (d0 * odd[i - 1] + (dm + d0) * pts[i] + dm * odd[i]) / (2 * (dm + d0))
        out.extend([even, odd[i]])
    return np.stack(out)


def hodograph_points(points, intervals, degree: int) -> np.ndarray:
    """Hodograph control points, notes (6.6): ``Q_i = c_i (P_{i+1} - P_i)``.

    ``c_i = n / (d_{i-m+1} + ... + d_{i+m})`` for even ``n = 2m``,
    ``c_i = n / (d_{i-m} + ... + d_{i+m})`` for odd ``n = 2m + 1`` (indices mod ``N``).
    """
    pts, d, n_pts = _prep(points, intervals)
    n = int(degree)
    m = n // 2
    rng = range(-m + 1, m + 1) if n % 2 == 0 else range(-m, m + 1)
    out = []
    for i in range(n_pts):
        s = sum(d[(i + k) % n_pts] for k in rng)
        if s == 0:
            raise KnotError(f"knot intervals around edge {i} sum to zero (a {n + 1}-fold knot)")
        out.append((pts[(i + 1) % n_pts] - pts[i]) * (mpq(n) / s))
    return np.stack(out)


def elevate_quadratic(points, intervals) -> np.ndarray:
    """Degree elevation 2 -> 3 of a periodic quadratic, notes (6.9).

    Edge ``P_i P_j`` (``j = i + 1``) gets ``P_{i,j} = ((2 d_i + 3 d_j) P_i + d_i P_j) / (3 d_i + 3 d_j)``
    and ``P_{j,i}``; returned in the order ``P_{0,1}, P_{1,0}, P_{1,2}, P_{2,1}, ...``.
    """
    pts, d, n = _prep(points, intervals)
    out = []
    for i in range(n):
        j = (i + 1) % n
        for a, b in ((i, j), (j, i)):
            out.append(((2 * d[a] + 3 * d[b]) * pts[a] + d[a] * pts[b]) / (3 * d[a] + 3 * d[b]))
    return np.stack(out)


def elevate_cubic(points, intervals) -> np.ndarray:
    """Degree elevation 3 -> 4 of a periodic cubic (notes 6.13.5, Figure 6.27).

    ``P_{i,i+1} = ((d_i + 2 d_{i+1}) P_i + (2 d_{i-1} + d_i) P_{i+1}) / (2 (d_{i-1} + d_i + d_{i+1}))``
    and the printed vertex rule for ``Q_i``; returned in the order ``Q_0, P_{0,1}, Q_1, P_{1,2}, ...``.
    """
    pts, d, n = _prep(points, intervals)
    out = []
    for i in range(n):
        dmm, dm, d0, dp = d[i - 2], d[i - 1], d[i], d[(i + 1) % n]
        q = (
            pts[i - 1] * (d0 / (4 * (dmm + dm + d0)))
            + pts[i] * ((dmm + dm) / (4 * (dmm + dm + d0)) + (d0 + dp) / (4 * (dm + d0 + dp)) + mpq(1, 2))
            + pts[(i + 1) % n] * (dm / (4 * (dm + d0 + dp)))
        )
        e = ((d0 + 2 * dp) * pts[i] + (2 * dm + d0) * pts[(i + 1) % n]) / (2 * (dm + d0 + dp))
        out.extend([q, e])
    return np.stack(out)


def split_cubic_construction(points, intervals, i: int, left) -> np.ndarray:
    """The notes' geometric construction for splitting interval ``d_i`` of a periodic cubic (Figure 6.16).

    Each of the edges ``P_{i-1}P_i``, ``P_iP_{i+1}``, ``P_{i+1}P_{i+2}`` is divided into three
    parts proportional to its neighbouring knot intervals; the part labelled ``d_i`` is
    split in the ratio ``left : (d_i - left)``.  Returns the new control polygon
    ``..., P_{i-1}, A, B, C, P_{i+2}, ...`` (``P_i``, ``P_{i+1}`` replaced; ``N + 1`` points,
    same start index).
    """
    pts, d, n = _prep(points, intervals)
    left = to_rational(left, where="left")
    D = lambda k: d[k % n]  # noqa: E731
    P = lambda k: pts[k % n]  # noqa: E731

    def on_edge(j, before):
        total = D(j - 1) + D(j) + D(j + 1)
        f = (before + left) / total
        return (1 - f) * P(j) + f * P(j + 1)

    a = on_edge(i - 1, D(i - 2) + D(i - 1))
    b = on_edge(i, D(i - 1))
    c = on_edge(i + 1, mpq(0))
    if not 0 <= i <= n - 2:
        raise InputError(f"split_cubic_construction: interval index must be in 0..{n - 2} (rotate the polygon)")
    rows = [P(k) for k in range(n)]
    return np.stack(rows[:i] + [a, b, c] + rows[i + 2 :])

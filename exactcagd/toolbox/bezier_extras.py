"""Chapter 2 of Sederberg's notes beyond the foundation, exact.

Sources (Sederberg, CAGD notes, 003): 2.5 convex hull property, 2.6 distance between
two Bézier curves, 2.9.2-2.9.3 end derivatives (2.10)-(2.12) and end curvature (2.13) of
rational curves, 2.10 continuity C^k / G^k (2.14)-(2.15), 2.11 circular arcs, 2.12
(rational) reparametrization, 2.14 explicit Bézier curves, 2.15 integrals (2.16)-(2.20).

Foundation operations (evaluation, subdivision, elevation, hodograph) live in
:mod:`exactcagd.geometry.bezier_curve`; this module builds on them.  A Bézier curve
over ``[t0, t1]`` is a :class:`~exactcagd.geometry.bezier_curve.BezierCurve` plus an
``interval`` argument (the curve object itself is always on [0, 1]).

>>> from exactcagd import BezierCurve
>>> from exactcagd.toolbox.bezier_extras import curvature
>>> curvature(BezierCurve([[0, 0], [4, 3], [0, 5]], weights=[1, 2, 4]), 0)   # notes 2.9.3
mpq(2,25)
"""

from __future__ import annotations

import math

import numpy as np
from gmpy2 import mpq

from .. import limits
from ..errors import DegreeError, DimensionError, DomainError, InputError, NotSupportedError
from ..exact import bernstein as bz
from ..exact.algebraic import RealAlgebraic
from ..exact.quadratic import QuadraticNumber, sqrt_rational
from ..exact.scalars import to_count, to_rational
from ..geometry.bezier_curve import BezierCurve
from . import _exact as ex

__all__ = [
    "convex_hull_2d",
    "in_convex_hull",
    "hull_edge_values",
    "difference_curve",
    "distance_bound_squared",
    "distance_bound",
    "max_distance_squared",
    "derivatives_at",
    "end_first_derivative",
    "end_second_derivative",
    "curvature_squared",
    "curvature",
    "signed_curvature",
    "end_curvature",
    "parametric_continuity",
    "geometric_continuity",
    "partial_bell",
    "circular_arc",
    "arc_half_angle_cos_squared",
    "arc_symmetric_form",
    "rational_point_on_circle",
    "full_circle_degree5",
    "domain_map",
    "substitute_linear",
    "mobius_reparametrize",
    "rational_linear_reparametrize",
    "explicit_curve",
    "explicit_rational_curve",
    "is_explicit",
    "area_under_explicit",
]

_MPQ = type(mpq(0))


def _pts(points, what="points") -> list:
    out = [tuple(to_rational(x, where=what) for x in p) for p in points]
    if not out:
        raise InputError(f"{what}: empty")
    d = len(out[0])
    if any(len(p) != d for p in out):
        raise DimensionError(f"{what}: points of different dimensions")
    return out


def _cross2(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


# ---------------------------------------------------------------- 2.5 convex hull
def convex_hull_2d(points) -> list:
    """Vertices of the convex hull of planar points, counter-clockwise (exact monotone chain).

    Collinear points on hull edges are dropped; a degenerate hull (all points on a line)
    returns its two extreme points (or one point).
    """
    pts = sorted(set(_pts(points)))
    if len(pts[0]) != 2:
        raise DimensionError("convex_hull_2d needs planar points")
    if len(pts) <= 2:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and _cross2(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and _cross2(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    hull = lower[:-1] + upper[:-1]
    return hull if len(hull) >= 2 else pts[:1]


def in_convex_hull(point, points) -> bool:
    """Exact test: is ``point`` a convex combination of ``points``?  Any dimension.

    Planar: against the exact hull; otherwise by exact linear-programming feasibility
    (``lambda >= 0``, ``sum lambda = 1``, ``sum lambda_i P_i = point``; phase-1 simplex
    in rationals).
    """
    p = _pts([point], "point")[0]
    pts = _pts(points)
    if len(p) != len(pts[0]):
        raise DimensionError("point and hull points differ in dimension")
    if len(p) == 2:
        hull = convex_hull_2d(pts)
        if len(hull) == 1:
            return p == hull[0]
        if len(hull) == 2:
            a, b = hull
            if _cross2(a, b, p) != 0:
                return False
            return min(a, b) <= p <= max(a, b)
        return all(_cross2(hull[i], hull[(i + 1) % len(hull)], p) >= 0 for i in range(len(hull)))
    rows = [[P[k] for P in pts] for k in range(len(p))] + [[mpq(1)] * len(pts)]
    return ex.feasible_nonnegative(rows, list(p) + [mpq(1)]) is not None


def hull_edge_values(curve: BezierCurve) -> list:
    """Convex hull property of a planar curve with positive weights, as an exact certificate.

    For every edge of the control points' hull, with ``f`` its line equation (positive
    outside), ``f(P(t)) = sum w_i B_i f(P_i) / sum w_i B_i`` has coefficients
    ``f(P_i) <= 0``; the list returned holds ``max_i f(P_i)`` per edge (all ``<= 0``,
    which proves the whole curve lies in the hull, notes 2.5).
    """
    if curve.dimension != 2:
        raise DimensionError("hull_edge_values needs a planar curve")
    if curve.is_rational and any(w <= 0 for w in curve.weights):
        raise DomainError("the convex hull property needs positive weights")
    hull = convex_hull_2d(curve.control_points)
    if len(hull) < 3:
        return []
    out = []
    for i in range(len(hull)):
        a, b = hull[i], hull[(i + 1) % len(hull)]
        out.append(max(-_cross2(a, b, p) for p in curve.control_points))
    return out


# ---------------------------------------------------------------- 2.6 distance
def _poly_only(curve, what):
    if curve.is_rational:
        raise NotSupportedError(f"{what}: polynomial curves only (the difference of rational curves is not a Bézier curve of the same form)")


def difference_curve(p: BezierCurve, q: BezierCurve) -> BezierCurve:
    """``D(t) = P(t) - Q(t)`` with control points ``P_i - Q_i`` (notes 2.6), after degree
    elevation to a common degree."""
    _poly_only(p, "difference_curve")
    _poly_only(q, "difference_curve")
    if p.dimension != q.dimension:
        raise DimensionError("curves of different dimension")
    n = max(p.degree, q.degree)
    a, b = p.elevate(n - p.degree), q.elevate(n - q.degree)
    return BezierCurve._trusted(a.points_array() - b.points_array(), None)


def distance_bound_squared(p: BezierCurve, q: BezierCurve):
    """``max_i |D_i|^2``: by the convex hull property ``|P(t) - Q(t)| <= max_i |D_i|`` (notes 2.6)."""
    d = difference_curve(p, q)
    return max(sum((x * x for x in pt), mpq(0)) for pt in d.control_points)


def distance_bound(p: BezierCurve, q: BezierCurve):
    """The bound ``max_i |D_i|`` exactly (``mpq`` or ``QuadraticNumber``)."""
    return sqrt_rational(distance_bound_squared(p, q))


def max_distance_squared(p: BezierCurve, q: BezierCurve) -> tuple[RealAlgebraic, list]:
    """Exact ``max_t |P(t) - Q(t)|^2`` over [0, 1] and where it is attained.

    This parametric distance lies between the Hausdorff distance (2.9) and the
    control-point bound: ``d_H(P, Q) <= sqrt(max) <= max_i |D_i|``.
    """
    d = difference_curve(p, q)
    power = bz.to_power(d.points_array())
    total = [mpq(0)]
    for k in range(power.shape[1]):
        col = list(power[:, k])
        total = ex.padd(total, ex.pmul(col, col))
    return ex.poly_max(total, 0, 1)


# ---------------------------------------------------------------- 2.9 derivatives, curvature
def _interval(interval):
    t0, t1 = (to_rational(x, where="interval") for x in interval)
    if t0 == t1:
        raise DomainError("empty parameter interval")
    return t0, t1


def derivatives_at(curve: BezierCurve, t, order: int, interval=(0, 1)) -> list:
    """Exact ``[P(t), P'(t), ..., P^(order)(t)]`` of a (rational) Bézier curve over ``interval``.

    Homogeneous form ``N = W P``: the derivatives of ``N`` and ``W`` come from repeated
    hodographs (notes 2.7); Leibniz' rule ``N^(k) = sum_j C(k, j) W^(j) P^(k-j)`` is solved
    for ``P^(k)`` -- the quotient rule of notes 2.9.2 to any order.
    """
    t0, t1 = _interval(interval)
    u = (to_rational(t, where="t") - t0) / (t1 - t0)
    order = to_count(order, where="order")
    limits.check("max_degree", order, "derivatives_at: order")
    h = curve.homogeneous()
    derivs = []
    c = h
    for k in range(order + 1):
        value = bz.de_casteljau(c, u) if c.shape[0] > 0 else h[0] * 0
        derivs.append(value / (t1 - t0) ** k)
        c = bz.derivative(c) if c.shape[0] > 1 else c * 0
    W = [d[-1] for d in derivs]
    N = [d[:-1] for d in derivs]
    if W[0] == 0:
        raise DomainError(f"the weight function vanishes at t = {t}")
    out = []
    for k in range(order + 1):
        acc = N[k].copy()
        for j in range(1, k + 1):
            acc = acc - bz.binomial(k, j) * W[j] * out[k - j]
        out.append(acc / W[0])
    return [tuple(v) for v in out]


def end_first_derivative(curve: BezierCurve, interval=(0, 1)) -> tuple:
    """(2.11): ``P'(t0) = (w1 / w0) n / (t1 - t0) (P1 - P0)``."""
    t0, t1 = _interval(interval)
    n = curve.degree
    if n < 1:
        return tuple(mpq(0) for _ in range(curve.dimension))
    w, P = curve.weights_array(), curve.control_points
    return tuple(w[1] / w[0] * n / (t1 - t0) * (b - a) for a, b in zip(P[0], P[1]))


def end_second_derivative(curve: BezierCurve, interval=(0, 1)) -> tuple:
    """(2.12): ``P''(t0) = n(n-1)/(t1-t0)^2 (w2/w0)(P2 - P0) - 2n/(t1-t0)^2 (w1/w0)((n w1 - w0)/w0)(P1 - P0)``."""
    t0, t1 = _interval(interval)
    n = curve.degree
    if n < 2:
        raise DegreeError("end_second_derivative needs degree >= 2")
    w, P = curve.weights_array(), curve.control_points
    h2 = (t1 - t0) ** 2
    return tuple(
        n * (n - 1) / h2 * w[2] / w[0] * (c - a) - 2 * n / h2 * w[1] / w[0] * (n * w[1] - w[0]) / w[0] * (b - a)
        for a, b, c in zip(P[0], P[1], P[2])
    )


def curvature_squared(curve: BezierCurve, t, interval=(0, 1)):
    """``kappa^2 = |P' x P''|^2 / |P'|^6`` (rational), any dimension (Lagrange identity)."""
    _, d1, d2 = derivatives_at(curve, t, 2, interval)
    s11 = sum((x * x for x in d1), mpq(0))
    if s11 == 0:
        raise DomainError(f"P'(t) = 0 at t = {t}: curvature undefined")
    s22 = sum((x * x for x in d2), mpq(0))
    s12 = sum((x * y for x, y in zip(d1, d2)), mpq(0))
    return (s11 * s22 - s12 * s12) / s11**3


def curvature(curve: BezierCurve, t, interval=(0, 1)):
    """Curvature (notes 2.9.3) exactly: ``mpq`` or ``QuadraticNumber``."""
    return sqrt_rational(curvature_squared(curve, t, interval))


def signed_curvature(curve: BezierCurve, t, interval=(0, 1)):
    """Planar signed curvature ``(x' y'' - y' x'') / (x'^2 + y'^2)^(3/2)``, exact."""
    if curve.dimension != 2:
        raise DimensionError("signed curvature is planar")
    _, (x1, y1), (x2, y2) = derivatives_at(curve, t, 2, interval)
    s = x1 * x1 + y1 * y1
    if s == 0:
        raise DomainError("P'(t) = 0: curvature undefined")
    value = (x1 * y2 - y1 * x2) / (s * sqrt_rational(s))
    return value.rational if isinstance(value, QuadraticNumber) and value.is_rational else value


def end_curvature(curve: BezierCurve):
    """(2.13): ``kappa(t0) = (w0 w2 / w1^2) ((n - 1) / n) h / a^2`` with ``a = |P1 - P0|`` and
    ``h`` the distance of ``P2`` from the line ``P0 P1``; independent of ``[t0, t1]``.

    Computed as ``sqrt(kappa^2)`` with ``h^2 / a^4`` rational (``h^2 = |P2 - P0|^2 - ((P2 - P0).(P1 - P0))^2 / a^2``).
    """
    n = curve.degree
    if n < 2:
        raise DegreeError("end curvature needs degree >= 2")
    w, P = curve.weights_array(), curve.control_points
    a_vec = [y - x for x, y in zip(P[0], P[1])]
    b_vec = [y - x for x, y in zip(P[0], P[2])]
    a2 = sum((x * x for x in a_vec), mpq(0))
    if a2 == 0:
        raise DomainError("P1 = P0: the end tangent is undefined")
    h2 = sum((x * x for x in b_vec), mpq(0)) - sum((x * y for x, y in zip(a_vec, b_vec)), mpq(0)) ** 2 / a2
    factor = (w[0] * w[2] / w[1] ** 2) * mpq(n - 1, n)
    return sqrt_rational(factor * factor * h2 / (a2 * a2))


# ---------------------------------------------------------------- 2.10 continuity
def _junction_derivs(p, q, order, p_interval, q_interval):
    p0, p1 = _interval(p_interval)
    q0, q1 = _interval(q_interval)
    return derivatives_at(p, p1, order, (p0, p1)), derivatives_at(q, q0, order, (q0, q1))


def parametric_continuity(p: BezierCurve, q: BezierCurve, p_interval=(0, 1), q_interval=(1, 2), max_order=None):
    """Highest ``k`` with ``P^(j)(t1) = Q^(j)(t1)`` for ``j <= k`` (C^k, (2.14)); ``-1`` if not C^0.

    ``P`` lives on ``p_interval = [t0, t1]``, ``Q`` on ``q_interval = [t1, t2]`` (the joint is
    ``P``'s end and ``Q``'s start; the parameter values need not agree).  Returns
    ``math.inf`` when all derivatives up to ``deg P + deg Q`` agree: then both are pieces of
    one curve (for rational curves ``N_P W_Q - N_Q W_P`` vanishes to that order).
    """
    if p.dimension != q.dimension:
        raise DimensionError("curves of different dimension")
    cap = p.degree + q.degree if max_order is None else int(max_order)
    dp, dq = _junction_derivs(p, q, cap, p_interval, q_interval)
    for k in range(cap + 1):
        if dp[k] != dq[k]:
            return k - 1
    return math.inf if max_order is None else cap


def partial_bell(n: int, k: int, xs) -> object:
    """Partial Bell polynomial ``B_{n,k}(x_1, ..., x_{n-k+1})`` (Faà di Bruno), exact.

    ``B_{n,k} = sum_{i=1}^{n-k+1} C(n-1, i-1) x_i B_{n-i,k-1}``, ``B_{0,0} = 1``.
    """
    if n == 0 and k == 0:
        return mpq(1)
    if n == 0 or k == 0:
        return mpq(0)
    return sum((bz.binomial(n - 1, i - 1) * xs[i - 1] * partial_bell(n - i, k - 1, xs) for i in range(1, n - k + 2)), mpq(0))


def geometric_continuity(p: BezierCurve, q: BezierCurve, max_order=None, p_interval=(0, 1), q_interval=(1, 2)):
    """Highest ``k`` such that ``P`` and ``Q`` are ``G^k`` at the joint, with the reparametrization.

    G^k (notes 2.10): ``Q`` can be reparametrized to meet ``P`` with C^k contact.  With
    ``s = phi(u)``, ``phi'(t1) = beta_1 > 0`` and ``phi^(j)(t1) = beta_j``, Faà di Bruno gives
    ``Q^(k) = sum_j P^(j) B_{k,j}(beta_1, ...)``; the unknown ``beta_k`` enters only as
    ``beta_k P'``, so each order is solved exactly in turn.  Requires a regular joint
    (``P' != 0``, ``Q' != 0``); otherwise only G^0 is reported.

    Returns ``(k, betas)`` (``k = -1``: not even G^0); ``k`` is capped at ``max_order``
    (default ``deg P + deg Q``).
    """
    if p.dimension != q.dimension:
        raise DimensionError("curves of different dimension")
    cap = p.degree + q.degree if max_order is None else int(max_order)
    dp, dq = _junction_derivs(p, q, max(cap, 1), p_interval, q_interval)
    if dp[0] != dq[0]:
        return -1, []
    p1 = dp[1]
    s11 = sum((x * x for x in p1), mpq(0))
    q1 = dq[1]
    if s11 == 0 or all(x == 0 for x in q1):
        return 0, []
    betas = []
    for k in range(1, cap + 1):
        rest = [mpq(0)] * len(p1)
        if k > 1:
            for j in range(2, k + 1):
                bell = partial_bell(k, j, betas + [mpq(0)])
                rest = [r + dp[j][i] * bell for i, r in enumerate(rest)]
        residual = [dq[k][i] - rest[i] for i in range(len(p1))]
        beta = sum((r * x for r, x in zip(residual, p1)), mpq(0)) / s11
        if any(residual[i] != beta * p1[i] for i in range(len(p1))):
            return k - 1, betas
        if k == 1 and beta <= 0:
            return 0, []
        betas.append(beta)
    return cap, betas


# ---------------------------------------------------------------- 2.11 circular arcs
def _circle_data(center, start, end):
    c, a, b = _pts([center, start, end], "center/start/end")
    if len(c) != 2:
        raise DimensionError("circular arcs are planar")
    va, vb = (a[0] - c[0], a[1] - c[1]), (b[0] - c[0], b[1] - c[1])
    r2 = va[0] ** 2 + va[1] ** 2
    if r2 == 0:
        raise DomainError("start point equals the center")
    if vb[0] ** 2 + vb[1] ** 2 != r2:
        raise DomainError("start and end are not at the same distance from the center")
    return c, a, b, va, vb, r2


def arc_half_angle_cos_squared(center, start, end):
    """``cos^2(theta / 2) = (1 + cos theta) / 2`` of the arc (rational; ``theta`` the arc angle)."""
    _, _, _, va, vb, r2 = _circle_data(center, start, end)
    return (1 + (va[0] * vb[0] + va[1] * vb[1]) / r2) / 2


def _tangent_intersection(c, a, b, va, vb):
    # tangent at a: (X - a).va = 0, tangent at b: (X - b).vb = 0
    det = va[0] * vb[1] - va[1] * vb[0]
    if det == 0:
        raise DomainError("the arc spans 0 or 180 degrees: the tangents do not meet")
    ra = a[0] * va[0] + a[1] * va[1]
    rb = b[0] * vb[0] + b[1] * vb[1]
    return ((ra * vb[1] - rb * va[1]) / det, (va[0] * rb - vb[0] * ra) / det)


def _single_arc(center, start, end) -> BezierCurve:
    c, a, b, va, vb, r2 = _circle_data(center, start, end)
    p1 = _tangent_intersection(c, a, b, va, vb)
    k = arc_half_angle_cos_squared(center, start, end)  # = w1^2 / (w0 w2)
    root = sqrt_rational(k)
    if isinstance(root, _MPQ):
        return BezierCurve([a, p1, b], weights=[1, root, 1])
    return BezierCurve([a, p1, b], weights=[1, 1, 1 / k])


def _ccw_angle_class(va, vb):
    """Sign data of the counter-clockwise angle from va to vb: (cross, dot)."""
    return va[0] * vb[1] - va[1] * vb[0], va[0] * vb[0] + va[1] * vb[1]


def circular_arc(center, start, end, ccw: bool = True, full: bool = False) -> list[BezierCurve]:
    """Exact circular arc from ``start`` to ``end`` about ``center`` as rational quadratics (notes 2.11).

    The middle control point is the intersection of the end tangents.  The shape
    invariant ``w1^2 / (w0 w2) = cos^2(theta/2) = (1 + cos theta) / 2`` is rational, so the
    arc is exact with rational weights: ``(1, cos(theta/2), 1)`` when ``cos(theta/2)`` is
    rational, otherwise the Möbius-equivalent ``(1, 1, 1 / cos^2(theta/2))`` (same arc,
    different speed; notes 2.12).  Arcs of 180 degrees or more are split at rational
    points of the circle (:func:`rational_point_on_circle`) into pieces below 180 degrees.
    ``full=True`` with ``start == end`` gives the whole circle.
    """
    c, a, b, va, vb, r2 = _circle_data(center, start, end)
    if a == b and not full:
        raise DomainError("start == end: pass full=True for the whole circle")
    if not ccw:
        return [arc.reversed() for arc in reversed(circular_arc(center, end, start, ccw=True, full=full))]
    cr, dt = _ccw_angle_class(va, vb)
    angle = math.atan2(float(cr), float(dt)) % (2 * math.pi)
    if a == b:
        angle = 2 * math.pi
    pieces = 1 if (cr > 0) else (2 if angle < 1.5 * math.pi else 3)
    if a == b:
        pieces = 3
    points = [a]
    for k in range(1, pieces):
        target = angle * k / pieces
        points.append(rational_point_on_circle(center, start, math.atan2(float(va[1]), float(va[0])) + target))
    points.append(b)
    return [_single_arc(center, points[i], points[i + 1]) for i in range(pieces)]


def rational_point_on_circle(center, on_circle, direction_angle: float, bits: int = 20) -> tuple:
    """A rational point of the circle near polar angle ``direction_angle`` (a float hint).

    The line through the rational point ``on_circle`` with rational direction ``d`` meets
    the circle again at ``A - 2 ((A - C).d / d.d) d`` -- rational for every rational ``d``
    (stereographic projection); ``d`` is the chord direction to the hinted point, rounded
    to ``bits`` bits.
    """
    c, a = _pts([center, on_circle], "center/point")
    r = math.sqrt(float((a[0] - c[0]) ** 2 + (a[1] - c[1]) ** 2))
    target = (float(c[0]) + r * math.cos(direction_angle), float(c[1]) + r * math.sin(direction_angle))
    scale = 2**bits
    d = (mpq(round((target[0] - float(a[0])) * scale), scale), mpq(round((target[1] - float(a[1])) * scale), scale))
    if d == (0, 0):
        return a
    dd = d[0] ** 2 + d[1] ** 2
    k = 2 * ((a[0] - c[0]) * d[0] + (a[1] - c[1]) * d[1]) / dd
    return (a[0] - k * d[0], a[1] - k * d[1])


def arc_symmetric_form(center, start, end) -> tuple[list, list]:
    """The standard form of an arc below 180 degrees: control points and weights
    ``(1, cos(theta/2), 1)`` with ``cos(theta/2)`` exact (``mpq`` or ``QuadraticNumber``).

    (:class:`~exactcagd.geometry.bezier_curve.BezierCurve` holds rational weights only; use
    :func:`circular_arc` for a curve object.)
    """
    c, a, b, va, vb, r2 = _circle_data(center, start, end)
    cr, _ = _ccw_angle_class(va, vb)
    p1 = _tangent_intersection(c, a, b, va, vb)
    w1 = sqrt_rational(arc_half_angle_cos_squared(center, start, end))
    return [a, p1, b], [mpq(1), w1, mpq(1)]


def full_circle_degree5(center=(0, 0), radius=1) -> BezierCurve:
    """The whole circle as one degree-5 rational Bézier curve with weights
    ``(1, 1/5, 1/5, 1/5, 1/5, 1)`` (notes 2.11, Figure 2.19).

    Control points (unit circle, start at the bottom): ``(0,-1), (-4,-1), (-2,3), (2,3),
    (4,-1), (0,-1)``, found by undetermined coefficients (``X^2 + Y^2 - W^2 = 0``) and checked
    exactly in the tests; the weight function is ``(2t^2 - 2t + 1)^2 > 0``.
    """
    c = _pts([center], "center")[0]
    r = to_rational(radius, where="radius")
    if r <= 0:
        raise DomainError("radius must be positive")
    unit = [(0, -1), (-4, -1), (-2, 3), (2, 3), (4, -1), (0, -1)]
    pts = [(c[0] + r * x, c[1] + r * y) for x, y in unit]
    return BezierCurve(pts, weights=[1, mpq(1, 5), mpq(1, 5), mpq(1, 5), mpq(1, 5), 1])


# ---------------------------------------------------------------- 2.12 reparametrization
def domain_map(t_interval, s_interval) -> tuple:
    """``t = (t0 s1 - s0 t1)/(s1 - s0) + (t1 - t0)/(s1 - s0) s`` (notes 2.12): ``(offset, slope)``."""
    t0, t1 = _interval(t_interval)
    s0, s1 = _interval(s_interval)
    return (t0 * s1 - s0 * t1) / (s1 - s0), (t1 - t0) / (s1 - s0)


def substitute_linear(curve: BezierCurve, offset, slope) -> BezierCurve:
    """``Q(s) = P(offset + slope s)`` on [0, 1] (polar form: ``restrict`` to [offset, offset + slope])."""
    a = to_rational(offset, where="offset")
    b = a + to_rational(slope, where="slope")
    return curve.reparametrize(a, b)


def mobius_reparametrize(curve: BezierCurve, b) -> BezierCurve:
    """``t = b u / ((1 - u) + b u)``: same end points, weights ``w_i b^i`` (notes 2.12).

    ``b < 0`` alternates the weight signs and traces the complementary part of the curve
    (``t`` in ``(-inf, 0] U [1, inf)``), e.g. the rest of a circle.
    """
    b = to_rational(b, where="b")
    if b == 0:
        raise DomainError("b = 0 collapses the parametrization")
    h = curve.homogeneous()
    scale = np.array([b**i for i in range(curve.degree + 1)], dtype=object).reshape(-1, 1)
    return BezierCurve.from_homogeneous(h * scale)


def rational_linear_reparametrize(curve: BezierCurve, a, b, c, d) -> BezierCurve:
    """General ``t = (a (1 - u) + b u) / (c (1 - u) + d u)`` (notes 2.12), exact.

    In homogeneous parameters ``(1 - t, t) ~ ((c - a)(1 - u) + (d - b) u, a (1 - u) + b u)``,
    so the new homogeneous control points are the homogeneous polar form at
    ``(c - a, a)^(n - k) (d - b, b)^k``.
    """
    a, b, c, d = (to_rational(x) for x in (a, b, c, d))
    if a * d - b * c == 0:
        raise DomainError("ad - bc = 0: the substitution is constant")
    left, right = (c - a, a), (d - b, b)
    h = curve.homogeneous()
    n = curve.degree
    out = np.empty_like(h)
    for k in range(n + 1):
        level = h
        for j in range(n):
            s0, s1 = left if j < n - k else right
            level = s0 * level[:-1] + s1 * level[1:]
        out[k] = level[0]
    return BezierCurve.from_homogeneous(out)


# ---------------------------------------------------------------- 2.14 explicit curves
def explicit_curve(y_coeffs, t0=0, t1=1) -> BezierCurve:
    """Explicit Bézier curve ``x = t, y = f(t)``: ``P_i = ((t0 (n - i) + t1 i) / n, y_i)`` (notes 2.14).

    Returned as a planar curve on [0, 1] whose x-coordinate runs linearly from ``t0`` to ``t1``.
    """
    ys = [to_rational(y, where="y") for y in y_coeffs]
    t0, t1 = _interval((t0, t1))
    n = len(ys) - 1
    if n == 0:
        raise DegreeError("an explicit curve needs degree >= 1 (two control points)")
    return BezierCurve([((t0 * (n - i) + t1 * i) / n, y) for i, y in enumerate(ys)])


def explicit_rational_curve(y_values, weights) -> BezierCurve:
    """Explicit rational curve ``x = t``, ``y = sum w_i y_i B_i / sum w_i B_i`` (notes 2.14):
    degree ``n + 1``, since ``x = t W(t) / W(t)`` has degree ``n + 1``."""
    ys = [to_rational(y) for y in y_values]
    w = [to_rational(x) for x in weights]
    if len(ys) != len(w):
        raise InputError("one weight per y value")
    W = np.array([[x] for x in w], dtype=object)
    tW = bz.product(np.array([[mpq(0)], [mpq(1)]], dtype=object), W)  # t * W(t)
    Y = bz.elevate(np.array([[wi * yi] for wi, yi in zip(w, ys)], dtype=object), 1)
    hom = np.concatenate([tW, Y, bz.elevate(W, 1)], axis=1)
    return BezierCurve.from_homogeneous(hom)


def is_explicit(curve: BezierCurve, t0=0, t1=1) -> bool:
    """True when ``x(t) = t0 + (t1 - t0) t`` exactly (as a rational function)."""
    h = curve.homogeneous()
    t0, t1 = _interval((t0, t1))
    # x W - (t0 + (t1 - t0) t) W == 0
    lin = np.array([[t0], [t1]], dtype=object)
    lhs = bz.elevate(h[:, :1], 1)
    rhs = bz.product(lin, h[:, -1:])
    return bool(np.all(lhs == rhs))


# ---------------------------------------------------------------- 2.15 integrals
def area_under_explicit(curve: BezierCurve):
    """Area under an explicit polynomial Bézier curve over its x-range (2.20):
    the average of the y control values times the x-range."""
    _poly_only(curve, "area_under_explicit")
    P = curve.control_points
    t0, t1 = P[0][0], P[-1][0]
    if not is_explicit(curve, t0, t1):
        raise InputError("the curve is not explicit (x-coordinates not evenly spaced)")
    return (t1 - t0) * bz.integral(np.array([p[1] for p in P], dtype=object))

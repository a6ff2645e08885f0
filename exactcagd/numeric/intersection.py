"""Intersections of two planar Bézier curves (polynomial or rational), certified.

Sources: Sederberg's notes (003), chapter 7: 7.5 Bézier subdivision, 7.6 interval
subdivision, 7.7 Bézier clipping (fat lines 7.7.1, clipping 7.7.2, iterating 7.7.3,
both fat lines 7.7.4, multiple intersections 7.7.5, rational curves 7.7.6); the
exact reference route is implicitization + resultants (7.3, chapter 17), in
:mod:`exactcagd.numeric.intersect_exact`.

How the float methods stay certified
------------------------------------
The exact control points are enclosed in outward-rounded float intervals
(:mod:`exactcagd.numeric.enclose`); every piece of a curve carries interval
coefficients and an enclosure of its parameter range.  A region of parameter space
is discarded only when a rigorous test proves it holds no intersection (disjoint
boxes, a parameter range outside a fat line, a Krawczyk test with empty result).  So
the union of what is left always contains every exact intersection.  What is left is
then grouped into components, and each component is tested with the interval
Krawczyk operator for ``F(s, t) = P(s) - Q(t)``: ``K(X) ⊂ int X`` proves exactly one
intersection in ``X`` (transversal: the Jacobian is regular there) and gives a tight
enclosure.  Components where this cannot succeed — tangent intersections (singular
Jacobian), clusters closer than the float resolution — are reported with
``certified=False`` and ``tangent=True`` and an enclosure that still holds every
intersection near them.  None is ever dropped without proof.  A proven zero whose
box crosses an end of a curve (``s = 1 - 2^-60`` lies within a float step of 1) is
placed inside or outside [0, 1]^2 by exact Krawczyk steps (rational centre and Newton
step, outward-rounded Jacobian); one outside is no intersection and is dropped.

>>> from exactcagd import BezierCurve
>>> p = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> q = BezierCurve([[0, "1/2"], [2, "1/2"]])
>>> [round(x.t1, 9) for x in intersect(p, q)]
[0.146446609, 0.853553391]
>>> all(x.certified for x in intersect(p, q, method="clipping"))
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DimensionError, InputError, NotSupportedError, WeightError
from ..exact import bernstein as bz
from ..geometry.bezier_curve import BezierCurve
from . import enclose as iv
from .fatline import clip_range, fat_lines
from .interval import Interval

__all__ = ["Intersection", "intersect", "METHODS"]

METHODS = ("subdivision", "interval", "clipping", "exact")
U = iv.U


@dataclass(frozen=True)
class Intersection:
    """One intersection (or one unresolved cluster) of two planar curves.

    Attributes
    ----------
    t1, t2 : float
        Parameter estimates on ``curve1`` and ``curve2``.
    t1_interval, t2_interval : (float, float)
        Enclosures: the exact intersection parameters lie inside (proven).
    point : (float, float)
        ``curve1(t1)`` in float.
    certified : bool
        Exactly one intersection lies in the box, and it is transversal (proven).
    tangent : bool
        The box may hold a tangent (multiple) intersection or a cluster of
        intersections that float arithmetic cannot separate; every intersection in
        the region lies in the box, but their number is not proven.
    multiplicity : int or None
        Intersection multiplicity, when known exactly (method="exact"; 1 for certified).
    exact : tuple or None
        ``(RealAlgebraic, RealAlgebraic)`` exact parameters (method="exact", or an exact
        endpoint intersection).
    """

    t1: float
    t2: float
    t1_interval: tuple[float, float]
    t2_interval: tuple[float, float]
    point: tuple[float, float]
    certified: bool
    tangent: bool = False
    multiplicity: int | None = None
    exact: tuple | None = None

    def contains(self, s, t) -> bool:
        """True when exact parameters ``(s, t)`` (rationals or RealAlgebraic) lie in the box."""
        (a, b), (c, d) = self.t1_interval, self.t2_interval
        return bool(mpq(a) <= s) and bool(s <= mpq(b)) and bool(mpq(c) <= t) and bool(t <= mpq(d))


# =============================================================== curve data
class _Curve:
    """Float interval data of one exact planar curve (scaled exactly by powers of 2)."""

    def __init__(self, curve: BezierCurve, shift: int):
        hom = curve.homogeneous()
        w = hom[:, 2]
        if any(x <= 0 for x in w):
            if all(x < 0 for x in w):
                hom = -hom
            else:
                raise WeightError("curve intersection needs weights of one sign (the convex hull property)")
        wk = iv.power2_scale(hom[:, 2]) if curve.is_rational else 0  # W stays 1 for polynomials
        scale_xy, scale_w = mpq(2) ** (shift + wk), mpq(2) ** wk
        exact = np.empty_like(hom)
        exact[:, :2] = hom[:, :2] * scale_xy
        exact[:, 2] = hom[:, 2] * scale_w
        self.exact = exact
        self.rational = curve.is_rational
        self.n = curve.degree
        self.lo, self.hi = iv.enclose(exact)
        self.mid, self.rad = iv.midrad(self.lo, self.hi)
        self.scale = float(mpq(2) ** shift)
        # derivative data for the Krawczyk test
        if not self.rational:
            d = bz.derivative(exact[:, :2])
            self.dlo, self.dhi = iv.enclose(d)
        else:
            num, wt = exact[:, :2], exact[:, 2:3]
            d = bz.product(bz.derivative(num), wt) - bz.product(num, bz.derivative(wt))
            self.dlo, self.dhi = iv.enclose(d)
            self.w2lo, self.w2hi = iv.enclose(bz.product(wt, wt))

    # -------------------------------------------------------------- pieces
    def cart(self, lo, hi):
        """Interval Cartesian control points of interval homogeneous ones."""
        if not self.rational:
            return lo[:, :2], hi[:, :2]
        return iv.iv_div(lo[:, :2], hi[:, :2], lo[:, 2:3], hi[:, 2:3])

    def point(self, t: float):
        """Interval point at a float parameter (Horner in Bernstein form with error bound)."""
        value, bound = iv.horner_bound(self.mid, self.rad, t)
        lo, hi = iv.down(value - bound), iv.up(value + bound)
        if not self.rational:
            return lo[:2], hi[:2]
        return iv.iv_div(lo[:2], hi[:2], lo[2], hi[2])

    def point_float(self, t: float) -> tuple[float, float]:
        value, _ = iv.horner_bound(self.mid, self.rad, min(max(t, 0.0), 1.0))
        xy = value[:2] / value[2]
        return float(xy[0] / self.scale), float(xy[1] / self.scale)

    def range_derivative(self, a, b):
        """Interval enclosure of P'(s) for s in [a, b] (a < 0 or b > 1 allowed)."""
        dlo, dhi = iv.restrict(self.dlo, self.dhi, a, b)
        lo, hi = iv.hull(dlo, dhi)
        if not self.rational:
            return lo, hi
        wlo, whi = iv.hull(*iv.restrict(self.w2lo, self.w2hi, a, b))
        return iv.iv_div(lo, hi, wlo, whi)

    def value_at(self, s: float):
        """Interval point at a float parameter by interval de Casteljau (any real s)."""
        lo, hi = iv.evaluate(self.lo, self.hi, s)
        if not self.rational:
            return lo[:2], hi[:2]
        return iv.iv_div(lo[:2], hi[:2], lo[2], hi[2])


@dataclass
class _Piece:
    """A piece of a curve: interval coefficients and an enclosure of its parameter range."""

    lo: np.ndarray
    hi: np.ndarray
    a: tuple  # interval enclosing the exact left parameter
    b: tuple  # interval enclosing the exact right parameter

    @property
    def width(self) -> float:
        return self.b[1] - self.a[0]

    @property
    def span(self) -> tuple[float, float]:
        return self.a[0], self.b[1]

    def sub(self, u0: float, u1: float, curve: "_Curve") -> "_Piece":
        """A piece holding local [u0, u1]: float end parameters rounded outward, and the
        coefficients restricted from the whole curve (no error build-up, no widening
        of parameter enclosures from one clip to the next)."""
        A, B = self.a[0], self.b[1]
        width = B - A
        a = A if u0 <= 0.0 else max(A, float(iv.down(A + u0 * width - 4 * U * abs(A + u0 * width))))
        b = B if u1 >= 1.0 else min(B, float(iv.up(A + u1 * width + 4 * U * abs(A + u1 * width))))
        if b <= a:
            b = min(B, float(iv.up(a)))
        lo, hi = iv.restrict(curve.lo, curve.hi, a, b)
        return _Piece(lo, hi, (a, a), (b, b))


def _param(piece: _Piece, u: float) -> tuple:
    """Enclosure of the global parameter a + u (b - a) for exact local u."""
    if u == 0.0:
        return piece.a
    if u == 1.0:
        return piece.b
    wl, wh = iv.iv_sub(piece.b[0], piece.b[1], piece.a[0], piece.a[1])
    pl, ph = iv.iv_mul(wl, wh, u, u)
    lo, hi = iv.iv_add(pl, ph, piece.a[0], piece.a[1])
    return float(max(lo, 0.0)), float(min(hi, 1.0))


def _box(curve: _Curve, piece: _Piece):
    lo, hi = curve.cart(piece.lo, piece.hi)
    return lo.min(axis=0), hi.max(axis=0)


def _disjoint(b1, b2) -> bool:
    (l1, h1), (l2, h2) = b1, b2
    if not (np.all(np.isfinite(l1)) and np.all(np.isfinite(h1)) and np.all(np.isfinite(l2)) and np.all(np.isfinite(h2))):
        return False
    return bool(np.any(h1 < l2) or np.any(h2 < l1))


def _prepare(curve1, curve2) -> tuple[_Curve, _Curve]:
    for name, c in (("curve1", curve1), ("curve2", curve2)):
        if not isinstance(c, BezierCurve):
            raise InputError(f"{name} must be a BezierCurve, got {type(c).__name__}")
        if c.dimension != 2:
            raise DimensionError(f"{name}: curve intersection is planar; got dimension {c.dimension}")
        if c.degree < 1:
            raise DegreeError(f"{name}: a degree-0 curve is a point, not a curve")
    cart = []
    for c in (curve1, curve2):
        hom = c.homogeneous()
        for h in hom:
            if h[2] != 0:
                cart.extend([abs(h[0] / h[2]), abs(h[1] / h[2])])
    shift = iv.power2_scale(np.array(cart, dtype=object)) if cart else 0
    return _Curve(curve1, shift), _Curve(curve2, shift)


def _root_piece(curve: _Curve) -> _Piece:
    return _Piece(curve.lo, curve.hi, (0.0, 0.0), (1.0, 1.0))


# =============================================================== 7.5 Bézier subdivision
def _flatness(curve: _Curve, piece: _Piece) -> float:
    """Deviation bound of the piece from its chord: (10.4) with r = 0, i.e. sqrt(Lx^2 + Ly^2)/8
    with ``L = n(n-1) max |second difference|`` (notes 10.6); for rational pieces the
    largest distance of a control point from the chord line (convex hull)."""
    lo, hi = curve.cart(piece.lo, piece.hi)
    mid = 0.5 * (lo + hi)
    n = len(mid) - 1
    if not np.all(np.isfinite(mid)):
        return math.inf
    if n < 2:
        return float(np.max(hi - lo))
    if not curve.rational:
        second = mid[2:] - 2 * mid[1:-1] + mid[:-2]
        lx, ly = n * (n - 1) * np.max(np.abs(second), axis=0)
        return math.hypot(lx, ly) / 8.0 + float(np.max(hi - lo))
    p0, pn = mid[0], mid[-1]
    d = pn - p0
    length = math.hypot(d[0], d[1])
    if length == 0.0:
        return float(np.max(np.abs(mid - p0)))
    dist = np.abs((mid[:, 0] - p0[0]) * d[1] - (mid[:, 1] - p0[1]) * d[0]) / length
    return float(dist.max()) + float(np.max(hi - lo))


def _chord_estimate(c1: _Curve, p: _Piece, c2: _Curve, q: _Piece):
    """Parameters where the chords of two flat pieces meet (clamped), as global estimates."""
    (pl, ph), (ql, qh) = c1.cart(p.lo, p.hi), c2.cart(q.lo, q.hi)
    p0, p1 = 0.5 * (pl[0] + ph[0]), 0.5 * (pl[-1] + ph[-1])
    q0, q1 = 0.5 * (ql[0] + qh[0]), 0.5 * (ql[-1] + qh[-1])
    d1, d2, r = p1 - p0, q1 - q0, q0 - p0
    det = d1[0] * (-d2[1]) - d1[1] * (-d2[0])
    if det == 0 or not math.isfinite(det):
        s = u = 0.5
    else:
        s = (r[0] * (-d2[1]) - r[1] * (-d2[0])) / det
        u = (d1[0] * r[1] - d1[1] * r[0]) / det
        s, u = min(max(s, 0.0), 1.0), min(max(u, 0.0), 1.0)
    return p.a[0] + s * (p.b[1] - p.a[0]), q.a[0] + u * (q.b[1] - q.a[0])


_W_TANGENT = 2.0**-16  # pieces of possibly tangent pairs are not split below this width


def _directions(curve: _Curve, lo, hi):
    """Float directions of the control polygon legs (a proxy of the tangent cone)."""
    clo, chi = curve.cart(lo, hi)
    mid = 0.5 * (clo + chi)
    return np.diff(mid, axis=0)


def _possibly_tangent(c1: _Curve, p_lo, p_hi, c2: _Curve, q_lo, q_hi) -> bool:
    """Heuristic (it only decides when to stop splitting, never what to discard): the
    control-polygon leg directions of the two pieces are not all crossing one way."""
    d1, d2 = _directions(c1, p_lo, p_hi), _directions(c2, q_lo, q_hi)
    if not (np.all(np.isfinite(d1)) and np.all(np.isfinite(d2))):
        return True
    cross = d1[:, None, 0] * d2[None, :, 1] - d1[:, None, 1] * d2[None, :, 0]
    return not (np.all(cross > 0) or np.all(cross < 0))


def _fat_excluded(c1: _Curve, p: "_Piece", c2: _Curve, q: "_Piece") -> bool:
    """Rigorous: one piece misses a fat line of the other (7.7.1)."""
    return _clip(c1, p, c2, q) is None or _clip(c2, q, c1, p) is None


class _Guard:
    """Work budget; when the pending work explodes, test once (exactly) whether the curves
    share a piece (then there are infinitely many intersections)."""

    def __init__(self, budget: int, on_blowup=None):
        self.budget = budget
        self.on_blowup = on_blowup
        self.checked = False

    def tick(self, pending: int) -> bool:
        self.budget -= 1
        if pending > 400 and not self.checked and self.on_blowup is not None:
            self.checked = True
            self.on_blowup()
        return self.budget >= 0


def _subdivision(c1: _Curve, c2: _Curve, tol: float, budget):
    """Bézier subdivision (notes 7.5): split both curves while their boxes overlap;
    flat pairs (within eps, (10.4)) become candidates, estimated by their chords."""
    eps = tol
    stack = [(_root_piece(c1), _root_piece(c2))]
    out = []
    while stack:
        if not budget.tick(len(stack) + len(out)):
            out.extend((p.span, q.span, None) for p, q in stack)
            break
        p, q = stack.pop()
        bp, bq = _box(c1, p), _box(c2, q)
        if _disjoint(bp, bq):
            continue
        fp, fq = _flatness(c1, p), _flatness(c2, q)
        small = p.width <= tol and q.width <= tol
        if (fp <= eps and fq <= eps) or small:
            out.append((p.span, q.span, _chord_estimate(c1, p, c2, q)))
            continue
        if max(p.width, q.width) <= 64 * _W_TANGENT and _possibly_tangent(c1, p.lo, p.hi, c2, q.lo, q.hi):
            # near a tangency boxes keep many pairs alive: use the (thinner) fat lines
            # too, and stop at a width float arithmetic can still resolve
            if _fat_excluded(c1, p, c2, q):
                continue
            if max(p.width, q.width) <= _W_TANGENT:
                out.append((p.span, q.span, _chord_estimate(c1, p, c2, q)))
                continue
        # split what is not flat; a flat piece is split too while its box is much the
        # larger one (otherwise a long flat piece keeps every small piece of the other)
        sp, sq = _size(bp), _size(bq)
        split_p = p.width > tol and (fp > eps or sp > 2 * sq)
        split_q = q.width > tol and (fq > eps or sq > 2 * sp)
        ps = _halves(p) if split_p else [p]
        qs = _halves(q) if split_q else [q]
        stack.extend((x, y) for x in ps for y in qs)
    return out


def _size(box) -> float:
    lo, hi = box
    return float(np.max(hi - lo)) if np.all(np.isfinite(lo)) and np.all(np.isfinite(hi)) else math.inf


def _halves(piece: _Piece):
    (llo, lhi), (rlo, rhi) = iv.split(piece.lo, piece.hi, 0.5)
    m = _param(piece, 0.5)
    return [_Piece(llo, lhi, piece.a, m), _Piece(rlo, rhi, m, piece.b)]


# =============================================================== 7.6 interval subdivision
def _monotone_partition(curve: _Curve) -> list[tuple[float, float, bool]]:
    """Split [0, 1] where x'(t) or y'(t) may vanish (notes 7.6 preprocessing).

    The zeros of the derivative numerators (hodograph, or ``N'W - NW'`` for rational
    curves) are enclosed by the certified root finder (:mod:`roots`); between the
    enclosures both coordinates are proven monotone, and the box spanned by two
    points of such an interval bounds the curve there.  The tiny enclosures
    themselves become pieces bounded by their control polygon.
    Returns ``(a, b, monotone)`` triples covering [0, 1].
    """
    from .roots import bernstein_roots

    exact = curve.exact
    if not curve.rational:
        num = bz.derivative(exact[:, :2])
    else:
        nn, ww = exact[:, :2], exact[:, 2:3]
        num = bz.product(bz.derivative(nn), ww) - bz.product(nn, bz.derivative(ww))
    cuts = []
    for k in range(2):
        col = num[:, k]
        if all(x == 0 for x in col):
            continue
        for r in bernstein_roots(col, method="isolate"):
            cuts.append(r.interval)
    cuts.sort()
    merged: list[list[float]] = []
    for lo, hi in cuts:
        if merged and lo <= merged[-1][1]:
            merged[-1][1] = max(merged[-1][1], hi)
        else:
            merged.append([lo, hi])
    parts = []
    pos = 0.0
    for lo, hi in merged:
        if lo > pos:
            parts.append((pos, lo, True))
        parts.append((lo, hi, False) if hi > lo else (lo, hi, False))
        pos = max(pos, hi)
    if pos < 1.0:
        parts.append((pos, 1.0, True))
    return [(a, b, m) for a, b, m in parts if b > a or not m]


@dataclass
class _Span:
    """Piece of the interval method: exact float end parameters and end-point enclosures."""

    a: float
    b: float
    monotone: bool
    pa: tuple
    pb: tuple


def _span_box(curve: _Curve, sp: _Span):
    if sp.monotone:
        lo = np.minimum(sp.pa[0], sp.pb[0])
        hi = np.maximum(sp.pa[1], sp.pb[1])
        return lo, hi
    if sp.b <= sp.a:
        return sp.pa
    lo, hi = iv.restrict(curve.lo, curve.hi, sp.a, sp.b)
    clo, chi = curve.cart(lo, hi)
    return clo.min(axis=0), chi.max(axis=0)


def _interval_method(c1: _Curve, c2: _Curve, tol: float, budget):
    """Interval subdivision (notes 7.6): monotone spans, boxes from end points, halving by
    Horner evaluation only (O(n) per step).

    Below width ``64 * _W_TANGENT`` a span's box is also met with the box of its restricted
    control polygon: both enclose the piece, and the polygon box is much thinner where
    the end-point enclosures are dominated by the Horner error bound (near a tangency
    that noise kept bands of tol-sized pairs alive until the work budget ran out).
    """
    spans = []
    for curve in (c1, c2):
        items = []
        for a, b, mono in _monotone_partition(curve):
            items.append(_Span(a, b, mono, curve.point(a), curve.point(b)))
        spans.append(items)
    stack = [(p, q) for p in spans[0] for q in spans[1]]
    out = []
    while stack:
        if not budget.tick(len(stack) + len(out)):
            out.extend(((p.a, p.b), (q.a, q.b), None) for p, q in stack)
            break
        p, q = stack.pop()
        bp, bq = _span_box(c1, p), _span_box(c2, q)
        if _disjoint(bp, bq):
            continue
        sizes = (float(np.max(bp[1] - bp[0])), float(np.max(bq[1] - bq[0])))
        done_p = p.b - p.a <= tol or sizes[0] <= tol
        done_q = q.b - q.a <= tol or sizes[1] <= tol
        if max(p.b - p.a, q.b - q.a) <= 64 * _W_TANGENT and p.b > p.a and q.b > q.a:
            pp = _Piece(*iv.restrict(c1.lo, c1.hi, p.a, p.b), (p.a, p.a), (p.b, p.b))
            qq = _Piece(*iv.restrict(c2.lo, c2.hi, q.a, q.b), (q.a, q.a), (q.b, q.b))
            if _disjoint(_meet(bp, _box(c1, pp)), _meet(bq, _box(c2, qq))):
                continue
            if not (done_p and done_q) and _possibly_tangent(c1, pp.lo, pp.hi, c2, qq.lo, qq.hi):
                if _fat_excluded(c1, pp, c2, qq):
                    continue
                if max(p.b - p.a, q.b - q.a) <= _W_TANGENT:
                    out.append(((p.a, p.b), (q.a, q.b), _span_estimate(p, q)))
                    continue
        if done_p and done_q:
            out.append(((p.a, p.b), (q.a, q.b), _span_estimate(p, q)))
            continue
        ps = _span_halves(c1, p) if not done_p else [p]
        qs = _span_halves(c2, q) if not done_q else [q]
        stack.extend((x, y) for x in ps for y in qs)
    return out


def _meet(b1, b2):
    """Intersection of two boxes that both enclose the same piece of curve."""
    return np.maximum(b1[0], b2[0]), np.minimum(b1[1], b2[1])


def _span_halves(curve: _Curve, sp: _Span):
    m = 0.5 * (sp.a + sp.b)
    if not (sp.a < m < sp.b):
        return [sp]
    pm = curve.point(m)
    return [_Span(sp.a, m, sp.monotone, sp.pa, pm), _Span(m, sp.b, sp.monotone, pm, sp.pb)]


def _span_estimate(p: _Span, q: _Span):
    """Intersection of the chords between the span end points (linear interpolation)."""
    p0, p1 = 0.5 * (p.pa[0] + p.pa[1]), 0.5 * (p.pb[0] + p.pb[1])
    q0, q1 = 0.5 * (q.pa[0] + q.pa[1]), 0.5 * (q.pb[0] + q.pb[1])
    d1, d2, r = p1 - p0, q1 - q0, q0 - p0
    det = -d1[0] * d2[1] + d1[1] * d2[0]
    if det == 0 or not math.isfinite(det):
        return 0.5 * (p.a + p.b), 0.5 * (q.a + q.b)
    s = (-r[0] * d2[1] + r[1] * d2[0]) / det
    u = (d1[0] * r[1] - d1[1] * r[0]) / det
    s, u = min(max(s, 0.0), 1.0), min(max(u, 0.0), 1.0)
    return p.a + s * (p.b - p.a), q.a + u * (q.b - q.a)


# =============================================================== 7.7 Bézier clipping
def _clip(target: _Curve, piece: _Piece, other: _Curve, against: _Piece):
    """Clip ``piece`` against both fat lines of ``against`` (7.7.4: the parallel and the
    perpendicular one; both are valid, so their ranges are intersected)."""
    clo, chi = other.cart(against.lo, against.hi)
    t0, t1 = 0.0, 1.0
    for line in fat_lines(clo, chi):
        r = clip_range(piece.lo, piece.hi, line)
        if r is None:
            return None
        t0, t1 = max(t0, r[0]), min(t1, r[1])
        if t0 > t1:
            return None
    return t0, t1


def _clipping(c1: _Curve, c2: _Curve, tol: float, budget, history: list | None = None):
    """Bézier clipping (notes 7.7): clip each curve against the other's fat lines in turn;
    when a round shrinks neither parameter range by 20 %, split the longer piece (7.7.5)."""
    stack = [(_root_piece(c1), _root_piece(c2))]
    out = []
    while stack:
        p, q = stack.pop()
        while True:
            if not budget.tick(len(stack) + len(out)):
                out.append((p.span, q.span, None))
                break
            if p.width <= tol and q.width <= tol:
                out.append((p.span, q.span, (0.5 * (p.a[0] + p.b[1]), 0.5 * (q.a[0] + q.b[1]))))
                break
            wp, wq = p.width, q.width
            r = _clip(c1, p, c2, q)
            if r is None:
                break
            if r != (0.0, 1.0):
                p = p.sub(*r, c1)
            r = _clip(c2, q, c1, p)
            if r is None:
                break
            if r != (0.0, 1.0):
                q = q.sub(*r, c2)
            if history is not None:
                history.append((p.width, q.width))
            if p.width > 0.8 * wp and q.width > 0.8 * wq:
                if max(p.width, q.width) <= _W_TANGENT and _possibly_tangent(c1, p.lo, p.hi, c2, q.lo, q.hi):
                    out.append((p.span, q.span, (0.5 * (p.a[0] + p.b[1]), 0.5 * (q.a[0] + q.b[1]))))
                    break
                if p.width >= q.width:
                    stack.extend((h, q) for h in _halves(p))
                else:
                    stack.extend((p, h) for h in _halves(q))
                break
        if budget.budget < 0:
            out.extend((p.span, q.span, None) for p, q in stack)
            break
    return out


# =============================================================== certification
def _iv(x):
    return (float(x[0]), float(x[1]))


def _imul(a, b):
    lo, hi = iv.iv_mul(np.float64(a[0]), np.float64(a[1]), np.float64(b[0]), np.float64(b[1]))
    return float(lo), float(hi)


def _iadd(a, b):
    lo, hi = iv.iv_add(np.float64(a[0]), np.float64(a[1]), np.float64(b[0]), np.float64(b[1]))
    return float(lo), float(hi)


def _isub(a, b):
    lo, hi = iv.iv_sub(np.float64(a[0]), np.float64(a[1]), np.float64(b[0]), np.float64(b[1]))
    return float(lo), float(hi)


def _krawczyk(c1: _Curve, c2: _Curve, S, T):
    """Krawczyk operator for F(s, t) = P(s) - Q(t) on the box S x T.

    Returns ``("unique", S', T')`` when ``K(X) ⊂ int X`` (exactly one zero, in
    ``K ∩ X``), ``("empty",)`` when ``K(X) ∩ X = ∅`` (no zero), else
    ``("unknown", singular)`` with ``singular`` = the Jacobian may be singular on X.
    """
    sm, tm = 0.5 * (S[0] + S[1]), 0.5 * (T[0] + T[1])
    plo, phi = c1.value_at(sm)
    qlo, qhi = c2.value_at(tm)
    if not (np.all(np.isfinite(plo)) and np.all(np.isfinite(phi)) and np.all(np.isfinite(qlo)) and np.all(np.isfinite(qhi))):
        return ("unknown", True)
    F = [_isub((plo[k], phi[k]), (qlo[k], qhi[k])) for k in range(2)]
    dp_lo, dp_hi = c1.range_derivative(S[0], S[1])
    dq_lo, dq_hi = c2.range_derivative(T[0], T[1])
    J = [[(float(dp_lo[k]), float(dp_hi[k])), (float(-dq_hi[k]), float(-dq_lo[k]))] for k in range(2)]
    if not all(math.isfinite(x) for row in J for e in row for x in e):
        return ("unknown", True)
    det_iv = _isub(_imul(J[0][0], J[1][1]), _imul(J[0][1], J[1][0]))
    singular = det_iv[0] <= 0.0 <= det_iv[1]
    M = [[0.5 * (J[i][j][0] + J[i][j][1]) for j in range(2)] for i in range(2)]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    if det == 0.0 or not math.isfinite(det):
        return ("unknown", True)
    Y = [[M[1][1] / det, -M[0][1] / det], [-M[1][0] / det, M[0][0] / det]]
    X = [S, T]
    mvec = [sm, tm]
    K = []
    for i in range(2):
        # m_i - (Y F(m))_i
        yf = _iadd(_imul((Y[i][0], Y[i][0]), F[0]), _imul((Y[i][1], Y[i][1]), F[1]))
        acc = _isub((mvec[i], mvec[i]), yf)
        for j in range(2):
            # (I - Y J)_{ij}
            yj = _iadd(_imul((Y[i][0], Y[i][0]), J[0][j]), _imul((Y[i][1], Y[i][1]), J[1][j]))
            e = _isub((1.0, 1.0) if i == j else (0.0, 0.0), yj)
            acc = _iadd(acc, _imul(e, _isub(X[j], (mvec[j], mvec[j]))))
        K.append(acc)
    if any(K[i][1] < X[i][0] or K[i][0] > X[i][1] for i in range(2)):
        return ("empty",)
    if all(X[i][0] < K[i][0] and K[i][1] < X[i][1] for i in range(2)):
        return ("unique", (max(K[0][0], S[0]), min(K[0][1], S[1])), (max(K[1][0], T[0]), min(K[1][1], T[1])))
    return ("unknown", singular)


def _components(rects, slack: float):
    """Connected components of overlapping rectangles (union-find)."""
    n = len(rects)
    parent = list(range(n))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    order = sorted(range(n), key=lambda i: rects[i][0][0])
    active: list[int] = []
    for i in order:
        (a0, a1), (b0, b1), _ = rects[i]
        keep = []
        for j in active:
            (c0, c1), (d0, d1), _ = rects[j]
            if c1 + slack < a0:
                continue
            keep.append(j)
            if b0 <= d1 + slack and d0 <= b1 + slack:
                parent[find(i)] = find(j)
        keep.append(i)
        active = keep
    groups: dict[int, list] = {}
    for i in range(n):
        groups.setdefault(find(i), []).append(rects[i])
    return list(groups.values())


def _hull(group):
    s0 = min(r[0][0] for r in group)
    s1 = max(r[0][1] for r in group)
    t0 = min(r[1][0] for r in group)
    t1 = max(r[1][1] for r in group)
    ests = [r[2] for r in group if r[2] is not None]
    return (s0, s1), (t0, t1), ests


def _widen(X, frac: float = 0.25):
    w = X[1] - X[0]
    pad = max(w * frac, abs(X[0]) * 8 * U, abs(X[1]) * 8 * U, 2.0**-1000)
    return (float(iv.down(X[0] - pad)), float(iv.up(X[1] + pad)))


def _certify(c1: _Curve, c2: _Curve, rects, tol: float, ends) -> list[Intersection]:
    out: list[Intersection] = []
    work = list(_components(rects, 0.0))
    guard = 0
    while work:
        group = work.pop()
        S, T, ests = _hull(group)
        guard += 1
        result = _try_box(c1, c2, S, T)
        if result[0] == "empty":
            continue
        if result[0] == "unique":
            S2, T2 = result[1], result[2]
            inside = S2[0] >= 0.0 and S2[1] <= 1.0 and T2[0] >= 0.0 and T2[1] <= 1.0
            outside = S2[1] < 0.0 or S2[0] > 1.0 or T2[1] < 0.0 or T2[0] > 1.0
            if outside:
                continue
            known = [e for e in ends if _in_box(e, S2, T2)]
            s_est, t_est = _estimate(ests, S2, T2)
            side = "inside" if inside or known else _boundary_side(c1, c2, S2, T2)
            if side == "outside":
                continue  # the box's only zero lies beyond an end of a curve (proven)
            if side == "inside":
                exact = known[0] if known else None
                if exact is not None:
                    S2, T2 = _exact_box(exact[0], S2), _exact_box(exact[1], T2)
                    s_est, t_est = float(exact[0]), float(exact[1])
                out.append(_make(c1, s_est, t_est, _clamp(S2), _clamp(T2), True, False, 1, exact))
                continue
            # straddles the domain boundary closer than the exact side test resolves
            out.append(_make(c1, s_est, t_est, _clamp(S2), _clamp(T2), False, False, None, None))
            continue
        singular = result[1]
        if len(group) > 1 and guard < 2000 and not singular:
            # a loose hull of several pieces: try them one by one
            for r in group:
                work.append([r])
            continue
        big = max(S[1] - S[0], T[1] - T[0])
        if guard < 600 and big > 4 * tol and (not singular or big > 4 * _W_TANGENT):
            subs = _split_rect(c1, c2, S, T, ests)
            if len(subs) != 1 or subs[0][:2] != (S, T):
                work.extend(_components(subs, 0.0))
                continue
        s_est, t_est = _estimate(ests, S, T)
        known = [e for e in ends if _in_box(e, S, T)]
        out.append(_make(c1, s_est, t_est, _clamp(S), _clamp(T), False, True, None, known[0] if known else None))
    out.sort(key=lambda x: (x.t1, x.t2))
    return _dedupe(out)


# =============================================================== zeros at the domain boundary
_SIDE_STEPS = 8  # exact Krawczyk contractions per side test (each gains ~45 bits)


def _boundary_side(c1: _Curve, c2: _Curve, S, T) -> str:
    """Decide exactly on which side of the boundary of [0, 1]^2 the zero in ``S x T`` lies.

    ``S x T`` holds exactly one zero of ``F(s, t) = P(s) - Q(t)`` (proven by the float
    Krawczyk test) and crosses ``s = 0``, ``s = 1``, ``t = 0`` or ``t = 1``.  Float
    arithmetic cannot place the zero relative to the face when it is closer than the
    float resolution (``s = 1 - 2^-60``), so the box is contracted by exact Krawczyk
    steps (:func:`_krawczyk_exact`; every zero in ``X`` lies in ``K(X) ∩ X``, each step
    gains about as many bits as float resolves) until it lies on one side of every face.

    Returns
    -------
    str
        ``"inside"`` (the zero lies in [0, 1]^2), ``"outside"`` (it does not), or
        ``"unknown"`` (too close to a face to tell in a few steps; a zero exactly on a
        face is found by the exact endpoint test instead).
    """
    unit = Interval(0, 1)
    start = (Interval(S[0], S[1]), Interval(T[0], T[1]))
    box = start
    for _ in range(_SIDE_STEPS):
        if all(unit.contains(X) for X in box):
            return "inside"
        if any(X.intersection(unit) is None for X in box):
            return "outside"
        nxt = _krawczyk_exact(c1, c2, *box)
        if nxt is None or nxt == box:
            # (None cannot happen: the box holds the zero; stay uncommitted if it does)
            return "unknown"
        box = tuple(_round_out(X, Z) for X, Z in zip(nxt, start))
    return "unknown"


def _round_out(X: Interval, within: Interval) -> Interval:
    """``X`` widened to dyadic end points (a 2^-12 fraction of its width), kept in ``within``.

    Keeps the rationals of the exact contraction short (the exact centre of the next
    step would otherwise double their size); widening never loses a zero, and staying
    in ``within`` (the box proven to hold exactly one zero) keeps it the same zero.
    """
    width = X.width()
    if width == 0:
        return X
    e = 12 + int(width.denominator).bit_length() - int(width.numerator).bit_length()
    scale = mpq(2) ** e
    lo = mpq(math.floor(X.lo * scale)) / scale
    hi = mpq(math.ceil(X.hi * scale)) / scale
    return Interval(max(lo, within.lo), min(hi, within.hi))


def _krawczyk_exact(c1: _Curve, c2: _Curve, S: Interval, T: Interval):
    """``K(X) ∩ X`` for ``X = S x T`` with exact rational arithmetic, ``None`` when empty.

    ``K(X) = m - Y F(m) + (I - Y J(X)) (X - m)`` with the exact midpoint ``m``, the exact
    value ``F(m)`` (rational de Casteljau on the exact control points), any rational
    matrix ``Y`` (the float inverse of the midpoint Jacobian) and an outward-rounded
    float enclosure ``J(X)`` of the Jacobian on a float box containing ``X``.  Only
    ``J`` is rounded, and only outward, so ``K(X)`` contains every zero in ``X``
    (mean value theorem).  Returns ``(S, T)`` unchanged when nothing can be computed.
    """
    X = (S, T)
    m = (S.midpoint(), T.midpoint())
    p, q = _exact_point(c1, m[0]), _exact_point(c2, m[1])
    J = _jacobian_enclosure(c1, c2, S, T)
    if p is None or q is None or J is None:
        return X
    F = [p[k] - q[k] for k in range(2)]
    M = [[0.5 * (float(J[i][j].lo) + float(J[i][j].hi)) for j in range(2)] for i in range(2)]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    if det == 0.0 or not math.isfinite(det):
        return X
    Y = [[mpq(M[1][1] / det), mpq(-M[0][1] / det)], [mpq(-M[1][0] / det), mpq(M[0][0] / det)]]
    out = []
    for i in range(2):
        acc = Interval(m[i] - Y[i][0] * F[0] - Y[i][1] * F[1])
        for j in range(2):
            e = (1 if i == j else 0) - (J[0][j] * Y[i][0] + J[1][j] * Y[i][1])
            acc = acc + e * (X[j] - m[j])
        cut = acc.intersection(X[i])
        if cut is None:
            return None
        out.append(cut)
    return out[0], out[1]


def _exact_point(curve: _Curve, s):
    """Exact (scaled) Cartesian point of the curve at a rational ``s`` (None at a pole)."""
    h = bz.de_casteljau(curve.exact, s)
    if not curve.rational:
        return h[0], h[1]
    if h[2] == 0:
        return None
    return h[0] / h[2], h[1] / h[2]


def _jacobian_enclosure(c1: _Curve, c2: _Curve, S: Interval, T: Interval):
    """Exact intervals enclosing ``J = [P'(s), -Q'(t)]`` on ``S x T`` (None if unbounded)."""
    dp = c1.range_derivative(*_outward(S))
    dq = c2.range_derivative(*_outward(T))
    values = [float(x) for pair in (dp, dq) for x in np.concatenate(pair)]
    if not all(math.isfinite(x) for x in values):
        return None
    (dp_lo, dp_hi), (dq_lo, dq_hi) = dp, dq
    return [[Interval(float(dp_lo[k]), float(dp_hi[k])), Interval(-float(dq_hi[k]), -float(dq_lo[k]))] for k in range(2)]


def _outward(X: Interval) -> tuple[float, float]:
    """A float box of positive width containing the rational interval ``X``."""
    return float(iv.down(iv.enclose_scalar(X.lo)[0])), float(iv.up(iv.enclose_scalar(X.hi)[1]))


def _split_rect(c1: _Curve, c2: _Curve, S, T, ests):
    """Quarter a parameter box; keep the quarters not excluded by boxes or fat lines."""
    out = []
    sm, tm = 0.5 * (S[0] + S[1]), 0.5 * (T[0] + T[1])
    for s0, s1 in ((S[0], sm), (sm, S[1])):
        for t0, t1 in ((T[0], tm), (tm, T[1])):
            if s1 <= s0 or t1 <= t0:
                continue
            p = _Piece(*iv.restrict(c1.lo, c1.hi, s0, s1), (s0, s0), (s1, s1))
            q = _Piece(*iv.restrict(c2.lo, c2.hi, t0, t1), (t0, t0), (t1, t1))
            if _disjoint(_box(c1, p), _box(c2, q)):
                continue
            if _clip(c1, p, c2, q) is None or _clip(c2, q, c1, p) is None:
                continue
            inside = [e for e in ests if s0 <= e[0] <= s1 and t0 <= e[1] <= t1]
            out.append(((s0, s1), (t0, t1), inside[0] if inside else None))
    return out


def _try_box(c1, c2, S, T):
    """Krawczyk on a slightly widened box (the zero may sit on a face), a few contractions."""
    S1, T1 = _widen(S), _widen(T)
    res = _krawczyk(c1, c2, S1, T1)
    for pad in (2.0**-44, 2.0**-36):
        # a box near the float resolution of the coordinates is too small for the
        # operator to contract (e.g. a crossing at a corner of the domain, where the
        # widening relative to |s| is tiny): retry on absolutely padded boxes; a
        # "unique" answer there is just as proven, only less tight before contraction
        if res[0] != "unknown" or res[1]:
            break
        res = _krawczyk(c1, c2, _pad(S1, pad), _pad(T1, pad))
    if res[0] != "unique":
        return res
    for _ in range(3):
        S2, T2 = res[1], res[2]
        nxt = _krawczyk(c1, c2, S2, T2)
        if nxt[0] != "unique" or (nxt[1][1] - nxt[1][0] >= 0.5 * (S2[1] - S2[0]) and nxt[2][1] - nxt[2][0] >= 0.5 * (T2[1] - T2[0])):
            break
        res = nxt
    # a contraction step of the operator keeps the zero: K(X) ∩ X
    return res


def _pad(X, pad: float):
    return (float(iv.down(X[0] - pad)), float(iv.up(X[1] + pad)))


def _in_box(e, S, T) -> bool:
    s, t = e
    return bool(mpq(S[0]) <= s) and bool(s <= mpq(S[1])) and bool(mpq(T[0]) <= t) and bool(t <= mpq(T[1]))


def _exact_box(x, X):
    from ..exact.algebraic import RealAlgebraic

    if isinstance(x, RealAlgebraic):
        if x.is_rational:
            v = x.value
            lo, hi = iv.enclose_scalar(v)
            return (lo, hi)
        x.refine(mpq(1, 2**60))
        return (iv.enclose_scalar(x.lo)[0], iv.enclose_scalar(x.hi)[1])
    lo, hi = iv.enclose_scalar(x)
    return (lo, hi)


def _clamp(X):
    return (max(0.0, X[0]), min(1.0, X[1]))


def _estimate(ests, S, T):
    inside = [e for e in ests if S[0] <= e[0] <= S[1] and T[0] <= e[1] <= T[1]]
    if inside:
        return float(np.mean([e[0] for e in inside])), float(np.mean([e[1] for e in inside]))
    return 0.5 * (S[0] + S[1]), 0.5 * (T[0] + T[1])


def _make(c1, s, t, S, T, certified, tangent, mult, exact):
    s = min(max(s, S[0]), S[1])
    t = min(max(t, T[0]), T[1])
    return Intersection(float(s), float(t), (float(S[0]), float(S[1])), (float(T[0]), float(T[1])), c1.point_float(s), certified, tangent, mult, exact)


def _dedupe(items: list[Intersection]) -> list[Intersection]:
    """Certified boxes that overlap hold the same unique zero only if one holds the other's
    estimate; boxes of uncertified clusters that overlap are merged."""
    out: list[Intersection] = []
    for x in items:
        merged = False
        for k, y in enumerate(out):
            overlap = not (x.t1_interval[1] < y.t1_interval[0] or y.t1_interval[1] < x.t1_interval[0] or x.t2_interval[1] < y.t2_interval[0] or y.t2_interval[1] < x.t2_interval[0])
            if not overlap:
                continue
            if x.certified and y.certified:
                # each box holds exactly one zero; if one box holds the other, they are the same
                if _inside(x, y):
                    out[k] = x
                    merged = True
                elif _inside(y, x):
                    merged = True
                if merged:
                    break
                continue
            if not x.certified and not y.certified:
                S = (min(x.t1_interval[0], y.t1_interval[0]), max(x.t1_interval[1], y.t1_interval[1]))
                T = (min(x.t2_interval[0], y.t2_interval[0]), max(x.t2_interval[1], y.t2_interval[1]))
                out[k] = Intersection(y.t1, y.t2, S, T, y.point, False, x.tangent or y.tangent, None, y.exact or x.exact)
                merged = True
                break
        if not merged:
            out.append(x)
    return out


def _inside(x: Intersection, y: Intersection) -> bool:
    return y.t1_interval[0] <= x.t1_interval[0] and x.t1_interval[1] <= y.t1_interval[1] and y.t2_interval[0] <= x.t2_interval[0] and x.t2_interval[1] <= y.t2_interval[1]


# =============================================================== endpoint intersections
def _endpoint_intersections(curve1: BezierCurve, curve2: BezierCurve):
    """Exact parameter pairs where an end point of one curve lies on the other (gcd test)."""
    import flint

    from ..exact.algebraic import RealAlgebraic, real_roots

    def on_curve(point, curve):
        px, py = point
        power = bz.to_power(curve.homogeneous())

        def fq(col):
            return flint.fmpq_poly([flint.fmpq(int(x.numerator), int(x.denominator)) for x in col])

        gx = fq(power[:, 0]) - fq(power[:, 2]) * flint.fmpq(int(px.numerator), int(px.denominator))
        gy = fq(power[:, 1]) - fq(power[:, 2]) * flint.fmpq(int(py.numerator), int(py.denominator))
        if gx == 0 and gy == 0:
            raise NotSupportedError("a curve is constant at an end point of the other; degenerate input")
        g = gx.gcd(gy) if (gx != 0 and gy != 0) else (gx if gy == 0 else gy)
        if g.degree() < 1:
            return []
        coeffs = [mpq(int(c.p), int(c.q)) for c in g.coeffs()]
        return [r for r, _ in real_roots(coeffs, 0, 1)]

    out = []
    for s in (0, 1):
        for t in on_curve(curve1.evaluate(s), curve2):
            out.append((RealAlgebraic.from_rational(s), t))
    for t in (0, 1):
        for s in on_curve(curve2.evaluate(t), curve1):
            if not any(e[0] == s and e[1] == t for e in out):
                out.append((s, RealAlgebraic.from_rational(t)))
    return out


# =============================================================== public entry
def intersect(curve1, curve2, method: str = "subdivision", tol: float = 1e-12) -> list[Intersection]:
    """All intersections of two planar Bézier curves (polynomial or rational) on [0, 1]^2.

    Parameters
    ----------
    curve1, curve2 : BezierCurve
        Planar (dimension 2), degree >= 1; rational curves need weights of one sign.
    method : {"subdivision", "interval", "clipping", "exact"}
        Bézier subdivision (notes 7.5), interval subdivision (7.6), Bézier clipping
        (7.7), or the exact algebraic route (resultant of the implicit equation,
        exact real algebraic parameters; the reference).
    tol : float
        Parameter tolerance of the float methods (stopping width); the reported
        enclosures are the proven ones, often tighter.

    Returns
    -------
    list of Intersection, sorted by ``t1``.  Every exact intersection lies in the box
    of some returned item (proven); see :class:`Intersection` for the flags.

    Raises
    ------
    InputError, DimensionError, DegreeError, WeightError
        Bad curves.
    NotSupportedError
        Curves that share a piece (infinitely many intersections).

    Examples
    --------
    >>> from exactcagd import BezierCurve
    >>> a = BezierCurve([[0, 0], [1, 1]])
    >>> b = BezierCurve([[0, 1], [1, 0]])
    >>> x = intersect(a, b, method="interval")[0]
    >>> x.certified, x.t1_interval[0] <= 0.5 <= x.t1_interval[1]
    (True, True)
    """
    if method not in METHODS:
        raise InputError(f"unknown intersection method {method!r}; expected one of {METHODS}")
    try:
        tol = float(tol)
    except (TypeError, ValueError):
        raise InputError(f"tol must be a positive number, got {tol!r}") from None
    if not (tol > 0 and math.isfinite(tol)):
        raise InputError(f"tol must be a positive number, got {tol!r}")
    c1, c2 = _prepare(curve1, curve2)
    if method == "exact":
        from .intersect_exact import intersect_exact

        return intersect_exact(curve1, curve2)
    tol = max(tol, 64 * U)
    budget = _Guard(200_000, lambda: _check_overlap(curve1, curve2))
    if method == "subdivision":
        rects = _subdivision(c1, c2, tol, budget)
    elif method == "interval":
        rects = _interval_method(c1, c2, tol, budget)
    else:
        rects = _clipping(c1, c2, tol, budget)
    if len(rects) > 2000 and not budget.checked:
        _check_overlap(curve1, curve2)
    ends = _endpoint_intersections(curve1, curve2)
    result = _certify(c1, c2, rects, tol, ends)
    if not budget.checked and any(not x.certified for x in result):
        # an unresolved box may be a shared piece (flat overlapping pieces pass every
        # float test): decide it exactly before returning boxes for it
        _check_overlap(curve1, curve2)
    return result


def _check_overlap(curve1, curve2) -> None:
    from .intersect_exact import share_component

    if share_component(curve1, curve2):
        raise NotSupportedError("the curves share a piece: infinitely many intersections")

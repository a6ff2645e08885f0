"""Interval subdivision (Sederberg's notes 003, 7.6): monotone spans, boxes spanned by
the end points, halving by Horner evaluation only.

>>> from exactcagd import BezierCurve
>>> from exactcagd.numeric.intersection import intersect
>>> p = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> q = BezierCurve([[0, "1/2"], [2, "1/2"]])
>>> len(intersect(p, q, method="interval"))
2
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...exact import bernstein as bz
from .. import enclose as iv
from .curve_data import _W_TANGENT, _box, _Curve, _disjoint, _fat_excluded, _Piece, _possibly_tangent


def _monotone_partition(curve: _Curve) -> list[tuple[float, float, bool]]:
    """Split [0, 1] where x'(t) or y'(t) may vanish (notes 7.6 preprocessing).

    The zeros of the derivative numerators (hodograph, or ``N'W - NW'`` for rational
    curves) are enclosed by the certified root finder (:mod:`roots`); between the
    enclosures both coordinates are proven monotone, and the box spanned by two
    points of such an interval bounds the curve there.  The tiny enclosures
    themselves become pieces bounded by their control polygon.
    Returns ``(a, b, monotone)`` triples covering [0, 1].
    """
    from ..roots import bernstein_roots

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
    piece: _Piece | None = field(default=None, compare=False, repr=False)  # restricted control points, on demand


def _span_piece(curve: _Curve, sp: _Span) -> _Piece:
    """The span's control points (restricted from the whole curve), computed once per span:
    a span meets many spans of the other curve, and the restriction (de Casteljau) is the
    costliest step of the method (3/4 of its time before the cache, degree 15)."""
    if sp.piece is None:
        sp.piece = _Piece(*iv.restrict(curve.lo, curve.hi, sp.a, sp.b), (sp.a, sp.a), (sp.b, sp.b))
    return sp.piece


def _span_box(curve: _Curve, sp: _Span):
    if sp.monotone:
        lo = np.minimum(sp.pa[0], sp.pb[0])
        hi = np.maximum(sp.pa[1], sp.pb[1])
        return lo, hi
    if sp.b <= sp.a:
        return sp.pa
    return _box(curve, _span_piece(curve, sp))


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
            pp, qq = _span_piece(c1, p), _span_piece(c2, q)
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



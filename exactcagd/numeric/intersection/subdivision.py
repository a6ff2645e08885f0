"""Bézier subdivision (Sederberg's notes 003, 7.5): split both curves while their
control-polygon boxes overlap; flat pairs ((10.4)) become candidate boxes.

>>> from exactcagd import BezierCurve
>>> from exactcagd.numeric.intersection import intersect
>>> p = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> q = BezierCurve([[0, "1/2"], [2, "1/2"]])
>>> len(intersect(p, q, method="subdivision"))
2
"""

from __future__ import annotations

import math

import numpy as np

from .curve_data import (
    _W_TANGENT,
    _box,
    _Curve,
    _disjoint,
    _fat_excluded,
    _halves,
    _Piece,
    _possibly_tangent,
    _root_piece,
    _size,
)


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


#: geometric flatness below which a pair is a candidate whatever ``tol`` says: the
#: coordinates are scaled to [-1, 1], so smaller deviations drown in rounding noise
#: (at tol = 8e-15 the noise kept every piece "not flat" and the split never ended);
#: candidates are contracted to full precision by the Krawczyk step anyway
_FLAT_FLOOR = 2.0**-43


def _subdivision(c1: _Curve, c2: _Curve, tol: float, budget):
    """Bézier subdivision (notes 7.5): split both curves while their boxes overlap;
    flat pairs (within eps, (10.4)) become candidates, estimated by their chords."""
    eps = max(tol, _FLAT_FLOOR)
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



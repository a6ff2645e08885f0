"""Bézier clipping (Sederberg's notes 003, 7.7): clip each curve against both fat lines
of the other (7.7.1-7.7.4); split when a round shrinks neither range by 20 % (7.7.5).

>>> from exactcagd import BezierCurve
>>> from exactcagd.numeric.intersection import intersect
>>> p = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> q = BezierCurve([[0, "1/2"], [2, "1/2"]])
>>> all(x.certified for x in intersect(p, q, method="clipping"))
True
"""

from __future__ import annotations

from .curve_data import _W_TANGENT, _clip, _Curve, _halves, _possibly_tangent, _root_piece


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



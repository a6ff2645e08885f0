"""Test surfaces and domain curves for the curves-on-surfaces experiments (Tables 1-4 analogues).

The models of Yang et al. (004) (a face with 17 x 17 control points, a Venus with
145 x 55, a car roof) are not available; these stand-ins are built the same way
every time, exactly:

* :func:`analytic_surface`: a bicubic clamped B-spline surface with uniform knots on
  ``[0, 1]``, control points ``(g_i, g_j, f(g_i, g_j))`` at the Greville abscissae
  ``g`` (so ``x = u`` and ``y = v`` exactly) and ``f`` a smooth analytic "relief"
  (Gaussian bumps and waves), rounded to multiples of ``2^-12``;
* :func:`closed_domain_curve`: a closed cubic NURBS curve: a uniform *periodic* cubic
  B-spline with the given control points and weights, converted exactly to clamped
  form on ``[0, 1]`` by blossoming (so it is C2 everywhere, also at the seam);
* :func:`open_domain_curve`: an open cubic B-spline with a given number of pieces (the
  "car roof" example has 19).

>>> S = analytic_surface(8, 6, "face")
>>> S.shape, S.degree
((8, 6), (3, 3))
>>> D = closed_domain_curve(8)
>>> D.degree, len(D.control_points), D.evaluate(0) == D.evaluate(1)
(3, 11, True)
"""

from __future__ import annotations

import math

import numpy as np
from gmpy2 import mpq

from ..exact import bernstein as bz
from ..geometry.bspline import BSplineCurve, BSplineSurface

__all__ = ["analytic_surface", "closed_domain_curve", "open_domain_curve", "relief"]


def relief(kind: str, x: float, y: float) -> float:
    """The height functions (float; rounded to ``2^-12`` before entering the exact layer)."""
    g = math.exp
    if kind == "face":
        head = 0.30 * g(-((x - 0.5) ** 2 / 0.10 + (y - 0.5) ** 2 / 0.14))
        nose = 0.08 * g(-((x - 0.5) ** 2 + (y - 0.45) ** 2) / 0.004)
        eyes = -0.04 * (g(-((x - 0.38) ** 2 + (y - 0.6) ** 2) / 0.003) + g(-((x - 0.62) ** 2 + (y - 0.6) ** 2) / 0.003))
        mouth = -0.02 * g(-((x - 0.5) ** 2 / 0.01 + (y - 0.3) ** 2 / 0.001))
        return head + nose + eyes + mouth
    if kind == "venus":
        body = 0.25 * g(-((x - 0.5) ** 2 / 0.08 + (y - 0.5) ** 2 / 0.3))
        folds = 0.015 * math.sin(14 * math.pi * x) * math.cos(3 * math.pi * y)
        detail = 0.03 * g(-((x - 0.3) ** 2 + (y - 0.7) ** 2) / 0.002) + 0.03 * g(-((x - 0.7) ** 2 + (y - 0.4) ** 2) / 0.002)
        return body + folds + detail
    if kind == "roof":
        crown = 0.12 * (1 - (2 * x - 1) ** 2) * (1 - 0.6 * (2 * y - 1) ** 2)
        slope = 0.05 * y
        return crown + slope + 0.01 * math.sin(2 * math.pi * x) * math.sin(math.pi * y)
    raise ValueError(f"unknown relief {kind!r}")


def _uniform_clamped(n_points: int, p: int = 3) -> list:
    spans = n_points - p
    return [mpq(0)] * (p + 1) + [mpq(i, spans) for i in range(1, spans)] + [mpq(1)] * (p + 1)


def _greville(knots: list, p: int) -> list:
    n = len(knots) - p - 1
    return [sum(knots[i + 1 : i + p + 1]) / p for i in range(n)]


def analytic_surface(nu: int, nv: int, kind: str = "face", scale_bits: int = 12) -> BSplineSurface:
    """Bicubic clamped B-spline surface with ``nu x nv`` control points over ``[0, 1]^2``."""
    ku, kv = _uniform_clamped(nu), _uniform_clamped(nv)
    gu, gv = _greville(ku, 3), _greville(kv, 3)
    q = 2**scale_bits
    net = [[[x, y, mpq(round(relief(kind, float(x), float(y)) * q), q)] for y in gv] for x in gu]
    return BSplineSurface(net, ku, kv)


def _default_points(count: int) -> tuple[list, list]:
    pts, ws = [], []
    for k in range(count):
        th = 2 * math.pi * k / count
        r = 0.30 + 0.07 * math.cos(3 * th) + 0.03 * math.sin(2 * th)
        x = 0.5 + r * math.cos(th)
        y = 0.5 + 0.9 * r * math.sin(th)
        pts.append((mpq(round(x * 1000), 1000), mpq(round(y * 1000), 1000)))
        ws.append(mpq(1) if k % 3 else mpq(3, 2))
    return pts, ws


def closed_domain_curve(count: int = 8, points=None, weights=None) -> BSplineCurve:
    """Closed C2 cubic NURBS curve from ``count`` periodic control points (clamped, domain [0, 1])."""
    if points is None:
        points, weights = _default_points(count)
    K = len(points)
    weights = [mpq(1)] * K if weights is None else [mpq(w) for w in weights]
    Q = np.array([[p[0] * w, p[1] * w, w] for p, w in zip(points, weights)], dtype=object)
    pieces = []
    for j in range(K):
        a, b, c, d = (Q[(j + r) % K] for r in range(4))
        pieces.append(np.array([(a + 4 * b + c) / 6, (2 * b + c) / 3, (b + 2 * c) / 3, (b + 4 * c + d) / 6], dtype=object))
    knots = [mpq(0)] * 4 + [mpq(i) for i in range(1, K)] + [mpq(K)] * 4
    ctrl = []
    for i in range(K + 3):
        k = min(max(i, 3), K + 2)
        j = k - 3
        args = [knots[i + r] - j for r in (1, 2, 3)]
        ctrl.append(bz.blossom(pieces[j], args))
    pts = [(h[0] / h[2], h[1] / h[2]) for h in ctrl]
    ws = [h[2] for h in ctrl]
    return BSplineCurve(pts, [k / K for k in knots], ws)


def open_domain_curve(segments: int = 19) -> BSplineCurve:
    """Open cubic B-spline domain curve with ``segments`` polynomial pieces (uniform clamped
    knots on [0, 1]), a wave running across ``[0.1, 0.9] x [0.25, 0.75]``."""
    n = segments + 3
    pts = []
    for i in range(n):
        x = 0.1 + 0.8 * i / (n - 1)
        y = 0.5 + 0.2 * math.sin(3 * math.pi * x) * (0.6 + 0.4 * math.cos(5 * x))
        pts.append((mpq(round(x * 1000), 1000), mpq(round(y * 1000), 1000)))
    return BSplineCurve(pts, _uniform_clamped(n))

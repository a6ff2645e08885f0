"""Exact data for the examples of Lasser & Bonneau (000), figures 3-9 ("in spirit").

The report prints the degrees and weights of its figures but not the control points;
the nets and curves below are chosen (exact rationals) to match every stated property:

=====  ===================================================  ==========================
fig.   domain curves                                        surface
=====  ===================================================  ==========================
3      closed cubic C1 subspline, quartic                   degree (2, 4)
4      quintic, closed GC1 linear/cubic spline              degree (5, 3)
5      cubic curves                                         bicubic
6      closed cubic GC1 subspline, quintic                  biquadratic
7      rational quartic, closed rational C1 cubic spline    rational biquadratic
8      rational quadratics, beta_1 = 1/4, 1/2, 1, 2, 4      rational bicubic, w_i1 = w_i2 = 2
9      lines and quadratics (a planar form)                 biquintic FFD lattice
=====  ===================================================  ==========================

Every function returns a dict with ``surface`` and ``curves`` (a list of BezierCurve /
BSplineCurve, or lists of Bézier curves forming a GC1 loop).

>>> fig = figure8()
>>> fig["surface"].degree, [c.weights[1] for c in fig["curves"]]
((3, 3), [mpq(1,4), mpq(1,2), mpq(1,1), mpq(2,1), mpq(4,1)])
"""

from __future__ import annotations

from fractions import Fraction as Fr

from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve

__all__ = [
    "height_surface",
    "closed_c1_cubic",
    "gc1_loop",
    "figure3",
    "figure4",
    "figure5",
    "figure6",
    "figure7",
    "figure8",
    "figure9",
    "figure9_lattices",
    "FIGURES",
]


def height_surface(l: int, m: int, weights=None) -> BezierSurface:
    """A graph-like patch ``F_ij = (i/l, j/m, z_ij)`` with a saddle-and-bump height field."""
    def z(i, j):
        x, y = Fr(i, l), Fr(j, m)
        return Fr(1, 2) * (x - Fr(1, 2)) ** 2 - Fr(3, 4) * (y - Fr(1, 2)) ** 2 + Fr(1, 3) * x * y + Fr((i * 3 + j * 5) % 4, 20)

    net = [[[Fr(i, l), Fr(j, m), z(i, j)] for j in range(m + 1)] for i in range(l + 1)]
    return BezierSurface(net, weights)


def closed_c1_cubic(joints, tangents, weights=None) -> BSplineCurve:
    """Closed C1 cubic B-spline through ``joints`` with tangent handles ``tangents``.

    Double interior knots (uniform): control points ``J_0, J_0 + T_0, J_1 - T_1, J_1 + T_1, ...,
    J_0 - T_0, J_0``; the spline passes through every ``J_k`` (midpoint of its two
    neighbours) and is C1 everywhere, also at the closure.
    """
    n = len(joints)
    pts = [list(joints[0]), [joints[0][0] + tangents[0][0], joints[0][1] + tangents[0][1]]]
    for k in range(1, n):
        j, t = joints[k], tangents[k]
        pts += [[j[0] - t[0], j[1] - t[1]], [j[0] + t[0], j[1] + t[1]]]
    pts += [[joints[0][0] - tangents[0][0], joints[0][1] - tangents[0][1]], list(joints[0])]
    knots = [0] * 4 + [k for k in range(1, n) for _ in range(2)] + [n] * 4
    return BSplineCurve(pts, knots, weights)


def gc1_loop(corners, inset) -> list:
    """Closed GC1 loop of line segments and cubic corner arcs (a rounded polygon)."""
    n = len(corners)
    pieces = []
    for k in range(n):
        prev, c, nxt = corners[k - 1], corners[k], corners[(k + 1) % n]
        a = [c[0] + inset * (prev[0] - c[0]), c[1] + inset * (prev[1] - c[1])]
        b = [c[0] + inset * (nxt[0] - c[0]), c[1] + inset * (nxt[1] - c[1])]
        h1 = [a[0] + Fr(1, 2) * (c[0] - a[0]), a[1] + Fr(1, 2) * (c[1] - a[1])]
        h2 = [b[0] + Fr(1, 2) * (c[0] - b[0]), b[1] + Fr(1, 2) * (c[1] - b[1])]
        pieces.append(BezierCurve([a, h1, h2, b]))
        d = [nxt[0] + inset * (c[0] - nxt[0]), nxt[1] + inset * (c[1] - nxt[1])]
        pieces.append(BezierCurve([b, d]))
    return pieces


_H = Fr(1, 2)
_DIAMOND = [(Fr(1, 2), Fr(3, 20)), (Fr(17, 20), Fr(1, 2)), (Fr(1, 2), Fr(17, 20)), (Fr(3, 20), Fr(1, 2))]
_DIAMOND_T = [(Fr(1, 8), 0), (0, Fr(1, 8)), (-Fr(1, 8), 0), (0, -Fr(1, 8))]


def figure3() -> dict:
    """Closed cubic C1 subspline and a quartic curve on a degree (2, 4) patch."""
    quartic = BezierCurve([[Fr(1, 20), Fr(19, 20)], [Fr(3, 10), Fr(1, 2)], [Fr(1, 10), Fr(1, 10)], [Fr(7, 10), Fr(1, 5)], [Fr(19, 20), Fr(1, 20)]])
    return {"surface": height_surface(2, 4), "curves": [closed_c1_cubic(_DIAMOND, _DIAMOND_T), quartic], "title": "Figure 3: closed cubic C1 subspline and quartic on a (2,4) patch"}


def figure4() -> dict:
    """A quintic and a closed GC1 linear/cubic loop on a degree (5, 3) patch."""
    quintic = BezierCurve([[Fr(1, 20), Fr(1, 20)], [Fr(1, 2), Fr(1, 20)], [Fr(19, 20), Fr(3, 10)], [Fr(1, 20), Fr(7, 10)], [Fr(1, 2), Fr(19, 20)], [Fr(19, 20), Fr(19, 20)]])
    loop = gc1_loop([(Fr(1, 5), Fr(1, 5)), (Fr(4, 5), Fr(3, 10)), (Fr(7, 10), Fr(4, 5)), (Fr(1, 4), Fr(7, 10))], Fr(1, 4))
    return {"surface": height_surface(5, 3), "curves": [quintic, loop], "title": "Figure 4: quintic and GC1 linear/cubic loop on a (5,3) patch"}


def figure5() -> dict:
    """Cubic trimming curves on a bicubic patch."""
    curves = [
        BezierCurve([[Fr(1, 10), Fr(1, 10)], [Fr(9, 10), Fr(1, 5)], [Fr(1, 10), Fr(4, 5)], [Fr(9, 10), Fr(9, 10)]]),
        BezierCurve([[Fr(1, 20), Fr(1, 2)], [Fr(1, 3), Fr(19, 20)], [Fr(2, 3), Fr(1, 20)], [Fr(19, 20), Fr(1, 2)]]),
    ]
    return {"surface": height_surface(3, 3), "curves": curves, "title": "Figure 5: cubic trimming curves on a bicubic patch"}


def figure6() -> dict:
    """Closed cubic GC1 subspline and a quintic on a biquadratic patch."""
    quintic = BezierCurve([[Fr(1, 20), Fr(1, 2)], [Fr(1, 5), Fr(1, 20)], [Fr(2, 5), Fr(19, 20)], [Fr(3, 5), Fr(1, 20)], [Fr(4, 5), Fr(19, 20)], [Fr(19, 20), Fr(1, 2)]])
    # GC1: tangent lengths differ on the two sides of a joint (directions agree)
    joints = _DIAMOND
    pieces = []
    for k in range(4):
        j0, j1 = joints[k], joints[(k + 1) % 4]
        t0, t1 = _DIAMOND_T[k], _DIAMOND_T[(k + 1) % 4]
        s0, s1 = Fr(3, 2), Fr(1, 2)
        pieces.append(BezierCurve([list(j0), [j0[0] + s0 * t0[0], j0[1] + s0 * t0[1]], [j1[0] - s1 * t1[0], j1[1] - s1 * t1[1]], list(j1)]))
    return {"surface": height_surface(2, 2), "curves": [pieces, quintic], "title": "Figure 6: closed GC1 cubic subspline and quintic on a biquadratic patch"}


def figure7() -> dict:
    """Rational quartic and closed rational C1 cubic spline on a rational biquadratic patch."""
    w = [[1, 2, 1], [Fr(1, 2), 3, Fr(1, 2)], [1, 2, 1]]
    quartic = BezierCurve(
        [[Fr(1, 20), Fr(1, 20)], [Fr(9, 10), Fr(1, 10)], [Fr(1, 2), Fr(1, 2)], [Fr(1, 10), Fr(9, 10)], [Fr(19, 20), Fr(19, 20)]],
        weights=[1, 3, Fr(1, 2), 3, 1],
    )
    spline = closed_c1_cubic(_DIAMOND, _DIAMOND_T, weights=[1, 2, 2, 2, 2, 2, 2, 2, 2, 1])
    return {"surface": height_surface(2, 2, w), "curves": [quartic, spline], "title": "Figure 7: rational quartic and closed rational C1 cubic on a rational biquadratic patch"}


def figure8() -> dict:
    """Rational quadratics (beta_1 = 1/4 ... 4) on a rational bicubic with w_i1 = w_i2 = 2."""
    w = [[2 if j in (1, 2) else 1 for j in range(4)] for _ in range(4)]
    pts = [[Fr(1, 10), Fr(1, 10)], [Fr(3, 10), Fr(9, 10)], [Fr(9, 10), Fr(1, 10)]]
    curves = [BezierCurve(pts, weights=[1, b, 1]) for b in (Fr(1, 4), Fr(1, 2), 1, 2, 4)]
    return {"surface": height_surface(3, 3, w), "curves": curves, "title": "Figure 8: rational quadratics on a rational bicubic (w_i1 = w_i2 = 2)"}


def figure9_lattices() -> tuple:
    """The biquintic FFD of figure 9: the identity lattice ``(i/5, j/5, 0)`` and a displaced one."""
    ident = [[[Fr(i, 5), Fr(j, 5), 0] for j in range(6)] for i in range(6)]

    def moved(i, j):
        x, y = Fr(i, 5), Fr(j, 5)
        e1, e2 = Fr((3 * i + 7 * j + i * j) % 7 - 3, 200), Fr((5 * i + 2 * j + 2 * i * j) % 5 - 2, 200)
        return [x + y * (1 - y) * (1 - 2 * x) / 2 + e1, y + x * x * (1 - x) * Fr(3, 4) - Fr(1, 10) * x * y + e2, 0]

    deformed = [[moved(i, j) for j in range(6)] for i in range(6)]
    return BezierSurface(ident), BezierSurface(deformed)


def figure9() -> dict:
    """A planar form bounded by lines (iso and general) and quadratics under a biquintic FFD.

    ``curves``: horizontal line (iso), vertical line (iso), diagonal line (general),
    quadratic, quadratic, vertical line (iso) -- a closed boundary.
    """
    p = {k: [Fr(a, 20), Fr(b, 20)] for k, (a, b) in {"A": (4, 4), "B": (16, 4), "C": (16, 10), "D": (10, 17), "E": (4, 12)}.items()}
    curves = [
        BezierCurve([p["A"], p["B"]]),
        BezierCurve([p["B"], p["C"]]),
        BezierCurve([p["C"], p["D"]]),
        BezierCurve([p["D"], [Fr(6, 20), Fr(19, 20)], [Fr(5, 20), Fr(15, 20)]]),
        BezierCurve([[Fr(5, 20), Fr(15, 20)], [Fr(2, 20), Fr(14, 20)], p["E"]]),
        BezierCurve([p["E"], p["A"]]),
    ]
    identity, deformed = figure9_lattices()
    return {"surface": deformed, "identity": identity, "curves": curves, "title": "Figure 9: biquintic deformation of a planar form"}


FIGURES = {3: figure3, 4: figure4, 5: figure5, 6: figure6, 7: figure7, 8: figure8, 9: figure9}

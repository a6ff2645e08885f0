"""Independent sympy reference for F(K(t)) and the strategies the composition tests share.

The reference never calls exactcagd.composition: it builds the surface's homogeneous
components as sympy polynomials in (u, v) from the Bernstein definition (Lasser &
Bonneau eqs. (2), (4)), substitutes ``u = X/W``, ``v = Y/W`` (the curve's homogeneous
components, eqs. (1), (3)) and clears ``W^(l+m)``.  The result is compared with a
composed curve as rational functions of t (cross-multiplied polynomials over QQ).
This module also tests the reference itself against exact point evaluation.
"""

from __future__ import annotations

from fractions import Fraction as Fr

import sympy
from hypothesis import strategies as st

from exactcagd import BezierCurve, BezierSurface

T, U, V = sympy.symbols("t u v")


def _q(x) -> sympy.Rational:
    return sympy.Rational(int(x.numerator), int(x.denominator))


def _bern(n, i, x):
    return sympy.binomial(n, i) * x**i * (1 - x) ** (n - i)


def curve_polys(curve: BezierCurve):
    """Homogeneous components (X, Y, W) of a planar curve as sympy Polys in t."""
    n = curve.degree
    pts, w = curve.points_array(), curve.weights_array()
    comps = []
    for k in range(2):
        comps.append(sympy.Poly(sum(_q(w[i] * pts[i, k]) * _bern(n, i, T) for i in range(n + 1)), T, domain="QQ"))
    comps.append(sympy.Poly(sum(_q(w[i]) * _bern(n, i, T) for i in range(n + 1)), T, domain="QQ"))
    return comps


def reference(surface: BezierSurface, curve: BezierCurve):
    """``(numerators, denominator)``: Polys in t with F(K(t))_k = numerators[k] / denominator."""
    l, m = surface.degree
    net, w = surface.net_array(), surface.weights_array()
    X, Y, W = curve_polys(curve)
    bu = [sympy.Poly(_bern(l, i, U), U, V, domain="QQ") for i in range(l + 1)]
    bv = [sympy.Poly(_bern(m, j, V), U, V, domain="QQ") for j in range(m + 1)]
    xs, ys, ws = [X**0], [Y**0], [W**0]
    for _ in range(l + m):
        xs.append(xs[-1] * X)
        ys.append(ys[-1] * Y)
        ws.append(ws[-1] * W)
    comps = []
    for k in list(range(surface.dimension)) + [None]:
        poly = sympy.Poly(0, U, V, domain="QQ")
        for i in range(l + 1):
            for j in range(m + 1):
                c = w[i, j] * (net[i, j, k] if k is not None else 1)
                if c != 0:
                    poly += bu[i] * bv[j] * _q(c)
        total = sympy.Poly(0, T, domain="QQ")
        for (a, b), c in poly.terms():
            total += xs[a] * ys[b] * ws[l + m - a - b] * c
        comps.append(total)
    return comps[:-1], comps[-1]


def result_polys(curve: BezierCurve):
    """Homogeneous components of a composed (space) curve as Polys in t."""
    n = curve.degree
    pts, w = curve.points_array(), curve.weights_array()
    nums = [sympy.Poly(sum(_q(w[i] * pts[i, k]) * _bern(n, i, T) for i in range(n + 1)), T, domain="QQ") for k in range(curve.dimension)]
    den = sympy.Poly(sum(_q(w[i]) * _bern(n, i, T) for i in range(n + 1)), T, domain="QQ")
    return nums, den


def same_as_reference(result: BezierCurve, surface: BezierSurface, curve: BezierCurve) -> bool:
    """Is ``result`` the rational function F(K(t))?  (exact, cross-multiplied)"""
    ref_nums, ref_den = reference(surface, curve)
    nums, den = result_polys(result)
    return all((a * ref_den - b * den).is_zero for a, b in zip(nums, ref_nums)) and len(nums) == len(ref_nums)


# ----------------------------------------------------------------------------- strategies
def rationals(lo=0, hi=1, den=12):
    return st.integers(lo * den, hi * den).map(lambda k: Fr(k, den))


weights_st = st.integers(1, 6).flatmap(lambda d: st.integers(1, 12).map(lambda k: Fr(k, d)))


@st.composite
def surfaces(draw, max_l=4, max_m=4, rational=None, dim=3):
    l, m = draw(st.integers(0, max_l)), draw(st.integers(0, max_m))
    if l + m == 0:
        l = 1
    net = [[[draw(rationals(-2, 2)) for _ in range(dim)] for _ in range(m + 1)] for _ in range(l + 1)]
    rat = draw(st.booleans()) if rational is None else rational
    w = [[draw(weights_st) for _ in range(m + 1)] for _ in range(l + 1)] if rat else None
    return BezierSurface(net, w)


@st.composite
def domain_curves(draw, max_n=4, rational=None, min_n=1):
    n = draw(st.integers(min_n, max_n))
    pts = [[draw(rationals()), draw(rationals())] for _ in range(n + 1)]
    rat = draw(st.booleans()) if rational is None else rational
    w = [draw(weights_st) for _ in range(n + 1)] if rat else None
    return BezierCurve(pts, w)


# ----------------------------------------------------------------------------- the reference itself
def test_reference_matches_point_evaluation():
    surface = BezierSurface([[[0, 0, 1], [0, 1, 0]], [[1, 0, 0], [1, 1, 2]], [[2, 0, 1], [2, 1, 0]]], [[1, 2], [3, 1], [1, 1]])
    curve = BezierCurve([["1/10", "1/5"], ["9/10", "1/2"], ["1/3", "1"]], [1, 2, "1/2"])
    nums, den = reference(surface, curve)
    assert den.degree() <= 2 * 3
    for t in (Fr(0), Fr(1, 3), Fr(5, 7), Fr(1)):
        u, v = curve.evaluate(t)
        expected = surface.evaluate(u, v)
        got = [num.eval(sympy.Rational(t.numerator, t.denominator)) / den.eval(sympy.Rational(t.numerator, t.denominator)) for num in nums]
        assert got == [_q(x) for x in expected]


def test_reference_detects_a_wrong_curve():
    surface = BezierSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
    curve = BezierCurve([[0, 0], [1, 1]])
    wrong = BezierCurve([[0, 0], ["1/2", "1/2"], [1, "9/10"]])
    right = BezierCurve([[0, 0], ["1/2", "1/2"], [1, 1]])
    assert same_as_reference(right, surface, curve)
    assert not same_as_reference(wrong, surface, curve)

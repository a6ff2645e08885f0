"""Inversion formulas t = f(x, y) / g(x, y) (notes 17.5, 17.6.1, 17.7, 18.4.3).

Reference: exact evaluation of the curve at random rational parameters (the point
is computed by sympy from the Bernstein definition, not by exactcagd); the formula
must return the parameter back exactly, except at double points (0/0).
"""

import random

import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.algebra import (
    ImproperParametrizationError,
    curve_from_polynomials,
    double_points,
    inversion,
    inversion_bezier,
    inversion_cramer,
    inversion_linear_algebra,
    inversion_moving_line,
)
from exactcagd.errors import DegreeError

x, y, t = sp.symbols("x y t")


def _point(points, weights, tv):
    n = len(points) - 1
    w = weights or [1] * (n + 1)
    B = [sp.binomial(n, i) * tv**i * (1 - tv) ** (n - i) for i in range(n + 1)]
    W = sum(w[i] * B[i] for i in range(n + 1))
    return (sum(w[i] * points[i][0] * B[i] for i in range(n + 1)) / W, sum(w[i] * points[i][1] * B[i] for i in range(n + 1)) / W)


def _double_point_params(curve):
    out = set()
    for d in double_points(curve):
        if d.params:
            out.update(p for p in d.params if p is not None)
    return out


@settings(max_examples=20, deadline=None)
@given(st.integers(2, 4), st.randoms(use_true_random=False), st.lists(st.fractions(0, 1, max_denominator=50), min_size=3, max_size=3))
def test_inversion_recovers_random_rational_parameters(n, rnd, params):
    pts = [(rnd.randint(-9, 9), rnd.randint(-9, 9)) for _ in range(n + 1)]
    w = [rnd.randint(1, 4) for _ in range(n + 1)]
    curve = BezierCurve(pts, w)
    try:
        formula = inversion_linear_algebra(curve)
    except (ImproperParametrizationError, DegreeError):
        assume(False)
    bad = _double_point_params(curve) if n >= 3 else set()
    expr = formula.expr()
    for p in params:
        tv = sp.Rational(p.numerator, p.denominator)
        if any(float(b) == float(tv) and b == tv for b in bad):
            continue
        px, py = _point(pts, w, tv)
        den = formula.den.subs({x: px, y: py})
        if den == 0:  # only at singular points
            assert formula.num.subs({x: px, y: py}) == 0
            continue
        assert expr.subs({x: px, y: py}) == tv


def test_routes_on_a_cubic():
    r = random.Random(11)
    pts = [(r.randint(-9, 9), r.randint(-9, 9)) for _ in range(4)]
    w = [r.randint(1, 4) for _ in range(4)]
    c = BezierCurve(pts, w)
    formulas = [inversion_linear_algebra(c), inversion_cramer(c), inversion_bezier(c), inversion_moving_line(c)]
    for tv in (sp.Rational(1, 5), sp.Rational(2, 3), sp.Rational(7, 9)):
        px, py = _point(pts, w, tv)
        for f in formulas:
            assert f(px, py) == tv


def test_notes_example_and_double_point():
    c = BezierCurve([[1, 0], [5, 0], [5, 2], [4, 3]])
    assert inversion(c) == 2 * y / (x + y - 1)
    f = inversion_linear_algebra(c)
    assert f(1, 0) is None  # 0/0 at the double point (t = 0 and t = 2)


def test_quadratic_and_line():
    c = curve_from_polynomials(t**2 + 1, t**2 + 2 * t - 2)
    e = inversion(c)
    for tv in (-2, 0, sp.Rational(3, 7)):
        assert e.subs({x: tv**2 + 1, y: tv**2 + 2 * tv - 2}) == tv
    line = BezierCurve([[1, 1], [4, -1]])
    e = inversion(line)
    assert e.subs({x: 1 + 3 * sp.Rational(1, 4), y: 1 - 2 * sp.Rational(1, 4)}) == sp.Rational(1, 4)


def test_improper_and_degenerate():
    with pytest.raises(ImproperParametrizationError):
        inversion(curve_from_polynomials(t**2, t**4 + t**2))  # t and -t give the same point
    with pytest.raises(DegreeError):
        inversion(BezierCurve([[2, 3], [2, 3]]))
    with pytest.raises(DegreeError):
        inversion_bezier(BezierCurve([[0, 0], [1, 1], [2, 0], [3, 3], [4, 0]]))

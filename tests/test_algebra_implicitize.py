"""Implicitization of rational planar curves (notes 17.5, 17.6, 18.4.6).

Reference: exact sympy substitution of the curve (written from the Bernstein
definition, independent of exactcagd's conversions) into the implicit polynomial.
"""

import warnings

import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.algebra import (
    BasePointWarning,
    ImproperParametrizationWarning,
    curve_from_polynomials,
    implicit_equation,
    implicitize,
)
from exactcagd.algebra.implicitize import ROUTES
from exactcagd.errors import DegreeError, DimensionError, InputError, WeightError

x, y, t = sp.symbols("x y t")


def _components(points, weights=None):
    n = len(points) - 1
    w = weights or [1] * (n + 1)
    B = [sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]
    W = sp.expand(sum(w[i] * B[i] for i in range(n + 1)))
    X = sp.expand(sum(w[i] * points[i][0] * B[i] for i in range(n + 1)))
    Y = sp.expand(sum(w[i] * points[i][1] * B[i] for i in range(n + 1)))
    return X, Y, W


def _vanishes(F, X, Y, W):
    d = sp.Poly(F, x, y).total_degree()
    hom = sum(c * X**i * Y**j * W ** (d - i - j) for (i, j), c in sp.Poly(F, x, y).terms())
    return sp.expand(hom) == 0


coord = st.integers(-6, 6)
point = st.tuples(coord, coord)


@st.composite
def curves(draw, max_degree=4):
    n = draw(st.integers(1, max_degree))
    pts = draw(st.lists(point, min_size=n + 1, max_size=n + 1))
    rational = draw(st.booleans())
    w = draw(st.lists(st.integers(1, 4), min_size=n + 1, max_size=n + 1)) if rational else None
    return pts, w


@settings(max_examples=15, deadline=None)
@given(curves())
def test_vanishes_identically_and_routes_agree(data):
    pts, w = data
    curve = BezierCurve(pts, w)
    X, Y, W = _components(pts, w)
    assume(sp.simplify(sp.diff(X / W, t)) != 0 or sp.simplify(sp.diff(Y / W, t)) != 0)  # not constant
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", (BasePointWarning, ImproperParametrizationWarning))
        results = {m: implicit_equation(curve, m) for m in ROUTES}
    F = results["resultant"].poly.as_expr()
    assert _vanishes(F, X, Y, W)
    for m in ROUTES:
        assert results[m].poly.as_expr() == F  # same normalization -> identical
    P = results["resultant"].poly
    assert P.domain == sp.ZZ and P.primitive()[0] == 1 and P.LC(order="grevlex") > 0
    # degree * index = true degree of the reduced parametrization
    eq = results["resultant"]
    assert eq.degree * eq.index == eq.curve_degree


@settings(max_examples=12, deadline=None)
@given(st.integers(2, 5), st.randoms(use_true_random=False))
def test_degree_n_for_generic_proper_curves(n, rnd):
    pts = [(rnd.randint(-9, 9), rnd.randint(-9, 9)) for _ in range(n + 1)]
    w = [rnd.randint(1, 5) for _ in range(n + 1)]
    assume(len(set(pts)) > 1)
    curve = BezierCurve(pts, w)
    X, Y, W = _components(pts, w)
    g = sp.gcd(sp.gcd(X, Y), W)
    assume(sp.Poly(g, t).degree() == 0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ImproperParametrizationWarning)
        eq = implicit_equation(curve)
    # the resultant has degree n; it is F^r with r the index
    assert eq.degree * eq.index == n
    if eq.index == 1:
        assert eq.degree == n


def test_notes_examples():
    c = curve_from_polynomials(t**2 + 1, t**2 + 2 * t - 2)
    assert implicitize(c).as_expr() == x**2 - 2 * x * y + y**2 - 10 * x + 6 * y + 13
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    for m in ROUTES:
        assert implicitize(quarter, m).as_expr() == x**2 + y**2 - 1


def test_base_points_warn_and_are_removed():
    # x = t (t - 1/2) / (t (t - 1/2) + ...): common factor t - 1/3 in X, Y, W
    f = t - sp.Rational(1, 3)
    c = curve_from_polynomials(sp.expand(f * (t + 1)), sp.expand(f * (2 * t - 3)), sp.expand(f * (t + 2)))
    with pytest.warns(BasePointWarning, match=r"common factor 3\*t - 1 of X, Y, W"):
        eq = implicit_equation(c)
    assert eq.base_factor.degree() == 1 and eq.degree == 1
    X, Y, W = t + 1, 2 * t - 3, t + 2
    assert _vanishes(eq.poly.as_expr(), X, Y, W)


def test_improper_parametrization_warns_with_index():
    c = curve_from_polynomials(t**2, t**4 + t**2)  # traces y = x^2 + x twice
    for m in ROUTES:
        with pytest.warns(ImproperParametrizationWarning):
            eq = implicit_equation(c, m)
        assert eq.index == 2 and eq.poly.as_expr() == x**2 + x - y


def test_line_and_degenerate_images():
    assert implicitize(BezierCurve([[0, 0], [1, 2]])).as_expr() == 2 * x - y
    with pytest.warns(ImproperParametrizationWarning):  # a quadratic parametrization of a line
        assert implicitize(BezierCurve([[0, 0], [1, 2], [3, 6]])).as_expr() == 2 * x - y
    vertical = BezierCurve([[2, 0], [2, 1], [2, 5]])
    for m in ROUTES:
        assert implicitize(vertical, m).as_expr() == x - 2


def test_bad_input():
    with pytest.raises(DegreeError):
        implicitize(BezierCurve([[1, 1], [1, 1], [1, 1]]))
    with pytest.raises(DegreeError):
        implicitize(BezierCurve([[1, 2], [1, 2]], weights=[1, 2]))  # constant point (1, 2)
    with pytest.raises(DimensionError):
        implicitize(BezierCurve([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(InputError):
        implicitize([[0, 0], [1, 1]])
    with pytest.raises(InputError):
        implicitize(BezierCurve([[0, 0], [1, 1]]), method="gauss")
    with pytest.raises(WeightError):
        curve_from_polynomials(t, t**2, t)  # w(t) = t has a zero Bernstein coefficient


def test_strict_mode_rejects_degenerate_parametrizations():
    from exactcagd.algebra import BasePointError, ImproperParametrizationError
    from exactcagd.errors import InputError as _InputError

    f = t - sp.Rational(1, 3)
    based = curve_from_polynomials(sp.expand(f * (t + 1)), sp.expand(f * (2 * t - 3)), sp.expand(f * (t + 2)))
    improper = curve_from_polynomials(t**2, t**4 + t**2)  # y = x^2 + x traced twice
    for m in ROUTES:
        with pytest.raises(BasePointError, match=r"share the factor 3\*t - 1"):
            implicitize(based, m, strict=True)
        with pytest.raises(ImproperParametrizationError, match=r"F\^2"):
            implicitize(improper, m, strict=True)
    assert issubclass(BasePointError, _InputError) and issubclass(ImproperParametrizationError, _InputError)
    # a proper cubic passes strict mode unchanged; the equation vanishes on it (sympy substitution)
    c = BezierCurve([[1, 0], [5, 0], [5, 2], [4, 3]])
    F = implicitize(c, strict=True)
    X, Y = (sp.expand(e) for e in c.to_sympy(t))
    assert sp.simplify(F.as_expr().subs({x: X, y: Y}, simultaneous=True)) == 0

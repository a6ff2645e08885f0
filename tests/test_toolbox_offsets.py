"""Offset curves (notes ch. 8): values checked against sympy's (8.2) with exact square roots,
mpmath at 50 digits for the parabola's foot points, exact root comparison for cusps."""
from __future__ import annotations

from fractions import Fraction as Fr

import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import DegreeError, DimensionError, DomainError, NotSupportedError
from exactcagd.toolbox.offsets import offset_curve, offset_cusps, offset_point, parabola_offset, pythagorean_hodograph

T = sp.Symbol("t", real=True)
PH_CUBIC = BezierCurve([[0, 0], ["1/3", 0], ["2/3", "1/3"], ["2/3", 1]])  # P' = (1 - t^2, 2t), sigma = 1 + t^2


def _sym(curve):
    return [sp.expand(c) for c in curve.to_sympy(T)]


def _sympy_offset(curve, rho, t):
    """(8.2) with sympy's exact square root."""
    x, y = _sym(curve)
    dx, dy = sp.diff(x, T).subs(T, t), sp.diff(y, T).subs(T, t)
    speed = sp.sqrt(dx**2 + dy**2)
    return x.subs(T, t) + rho * dy / speed, y.subs(T, t) - rho * dx / speed


def _to_sp(v):
    return v.to_sympy() if hasattr(v, "to_sympy") else sp.Rational(int(v.numerator), int(v.denominator))


rationals = st.fractions(min_value=-3, max_value=3, max_denominator=7)


@settings(max_examples=20, deadline=None)
@given(st.lists(st.lists(rationals, min_size=2, max_size=2), min_size=3, max_size=4), rationals, st.fractions(0, 1, max_denominator=9))
def test_offset_point_matches_8_2(points, rho, t):
    curve = BezierCurve(points)
    x, y = _sym(curve)
    if sp.diff(x, T).subs(T, t) == 0 and sp.diff(y, T).subs(T, t) == 0:
        with pytest.raises(DomainError):
            offset_point(curve, rho, t)
        return
    got = offset_point(curve, rho, t)
    want = _sympy_offset(curve, sp.Rational(rho.numerator, rho.denominator), sp.Rational(t.numerator, t.denominator))
    assert all(sp.simplify(_to_sp(g) - w) == 0 for g, w in zip(got, want))


def test_offset_point_rational_curve():
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])  # unit circle arc, CCW
    for t in (Fr(0), Fr(1, 3), Fr(1)):
        x, y = offset_point(quarter, Fr(1, 2), t)  # right of a CCW circle = outside
        assert x * x + y * y == Fr(9, 4)


@settings(max_examples=15, deadline=None)
@given(rationals, rationals, rationals, rationals)
def test_ph_curves_from_u_v(u0, u1, v0, v1):
    """P' = (u^2 - v^2, 2uv) is PH with sigma = u^2 + v^2 (independent construction)."""
    u, v = u0 + (u1 - u0) * T, v0 + (v1 - v0) * T
    xs, ys = sp.integrate(sp.expand(u**2 - v**2), T), sp.integrate(sp.expand(2 * u * v), T)
    if sp.expand(u**2 + v**2) == 0:
        return
    curve = _bezier_from_sympy([xs, ys], 3)
    sigma = pythagorean_hodograph(curve)
    expected = sp.expand(u**2 + v**2)
    got = sum(_to_sp(c) * T**k for k, c in enumerate(sigma))
    assert sp.expand(got - expected) == 0 or sp.expand(got + expected) == 0


def _bezier_from_sympy(coords, n):
    from exactcagd.exact import bernstein as bz
    import numpy as np

    cols = []
    for c in coords:
        poly = sp.Poly(c, T)
        a = [sp.Rational(poly.coeff_monomial(T**k)) for k in range(n + 1)]
        cols.append(bz.from_power([Fr(int(q.p), int(q.q)) for q in a], n))
    return BezierCurve(np.stack(cols, axis=1).tolist())


def test_non_ph_curve_is_detected():
    assert pythagorean_hodograph(BezierCurve([[0, 0], [1, 2], [3, 1], [4, 4]])) is None
    with pytest.raises(NotSupportedError):
        offset_curve(BezierCurve([[0, 0], [1, 2], [3, 1], [4, 4]]), 1)


@pytest.mark.parametrize("rho", [Fr(1, 4), Fr(-1, 8)])
def test_ph_offset_is_exact_rational_offset(rho):
    off = offset_curve(PH_CUBIC, rho)
    assert off.is_rational and off.degree == 5
    ox, oy = [sp.together(c) for c in off.to_sympy(T)]
    x, y = _sym(PH_CUBIC)
    dx, dy = sp.diff(x, T), sp.diff(y, T)
    r = sp.Rational(rho.numerator, rho.denominator)
    assert sp.simplify((ox - x) ** 2 + (oy - y) ** 2 - r**2) == 0  # distance |rho|
    assert sp.simplify((ox - x) * dx + (oy - y) * dy) == 0  # along the normal
    cross = sp.simplify(dx * (oy - y) - dy * (ox - x))
    assert sp.simplify(cross + r * sp.sqrt(sp.factor(dx**2 + dy**2))) == 0  # on the right for rho > 0


@pytest.mark.parametrize("t", [Fr(0), Fr(1, 5), Fr(2, 3), Fr(1)])
def test_offset_of_offset_is_the_curve_8_3(t):
    rho = Fr(1, 10)  # smaller than the minimal radius of curvature
    back = offset_point(offset_curve(PH_CUBIC, rho), -rho, t)
    assert tuple(back) == tuple(PH_CUBIC.evaluate(t))


PARABOLA = BezierCurve([[0, 0], [3, 4], [7, 1]])  # legs (3,4), (4,-3): rational lengths


@pytest.mark.parametrize("rho", [Fr(1, 2), Fr(-2)])
def test_parabola_offset(rho):
    off = parabola_offset(PARABOLA, rho)
    assert off.degree == 6 and off.is_rational
    # ends are the exact offset points of the parabola's ends
    assert tuple(off.evaluate(0)) == tuple(offset_point(PARABOLA, rho, 0))
    assert tuple(off.evaluate(1)) == tuple(offset_point(PARABOLA, rho, 1))
    # every point is at distance |rho| along the right normal of some P(t), t in [0, 1] (mpmath, 50 digits)
    mpmath.mp.dps = 50
    x, y = _sym(PARABOLA)
    for s in (Fr(1, 7), Fr(1, 2), Fr(5, 6)):
        ox, oy = (mpmath.mpf(int(c.numerator)) / int(c.denominator) for c in off.evaluate(s))
        foot = sp.Poly(sp.expand((ox_s := sp.Rational(*_pq(off.evaluate(s)[0])) - x) * sp.diff(x, T)
                                 + (sp.Rational(*_pq(off.evaluate(s)[1])) - y) * sp.diff(y, T)), T)
        roots = [r for r in mpmath.polyroots([mpmath.mpf(sp.Rational(c).p) / sp.Rational(c).q for c in foot.all_coeffs()], extraprec=200)
                 if abs(mpmath.im(r)) < mpmath.mpf(10) ** -40 and -1e-30 <= mpmath.re(r) <= 1 + 1e-30]
        ok = False
        for r in roots:
            r = mpmath.re(r)
            px, py = (mpmath.polyval([mpmath.mpf(sp.Rational(c).p) / sp.Rational(c).q for c in sp.Poly(v, T).all_coeffs()], r) for v in (x, y))
            dist = mpmath.sqrt((ox - px) ** 2 + (oy - py) ** 2)
            ok |= abs(dist - abs(mpmath.mpf(rho.numerator) / rho.denominator)) < mpmath.mpf(10) ** -35
        assert ok


def _pq(v):
    return int(v.numerator), int(v.denominator)


def test_parabola_offset_implicit_degree_six():
    from exactcagd.algebra import implicitize

    assert implicitize(parabola_offset(PARABOLA, 1)).total_degree() == 6


def test_cusps_of_parabola_offset():
    parabola = BezierCurve([[-1, 1], [0, -1], [1, 1]])  # (2t-1, (2t-1)^2): min radius 1/2 at t = 1/2
    cusps = offset_cusps(parabola, -4)  # concave side, radius 4: 16 t^2 - 16 t + 1 = 0
    mpmath.mp.dps = 40  # the intervals below are 2^-60 wide (restored by tests/conftest.py)
    expected = [(2 - mpmath.sqrt(3)) / 4, (2 + mpmath.sqrt(3)) / 4]
    assert len(cusps) == 2
    for c, e in zip(cusps, expected):
        c.refine(Fr(1, 2**60))
        assert mpmath.mpf(int(c.lo.numerator)) / int(c.lo.denominator) <= e <= mpmath.mpf(int(c.hi.numerator)) / int(c.hi.denominator)
    assert offset_cusps(parabola, 4) == []  # convex side: never a cusp
    assert offset_cusps(parabola, Fr(-1, 4)) == []  # radius below the minimal radius of curvature


def test_bad_input():
    with pytest.raises(DimensionError):
        offset_point(BezierCurve([[0, 0, 0], [1, 1, 1]]), 1, 0)
    with pytest.raises(NotSupportedError):
        offset_curve(BezierCurve([[0, 0], [1, 1], [2, 0]], weights=[1, 2, 1]), 1)
    with pytest.raises(DegreeError):
        parabola_offset(PH_CUBIC, 1)
    with pytest.raises(DegreeError):
        parabola_offset(BezierCurve([[0, 0], [1, 1], [2, 2]]), 1)
    with pytest.raises(NotSupportedError):
        parabola_offset(BezierCurve([[-1, 1], [0, -1], [1, 1]]), 1)  # legs of length sqrt 5
    with pytest.raises(DomainError):
        offset_point(BezierCurve([[0, 0], [1, 1], [0, 0]]), 1, Fr(1, 2))

"""Chapter 20 toolbox: exact integrals over polynomial Bézier curves, hybrid curves, and the
certified integrals of rational curves -- against sympy integration and mpmath quadrature."""
from fractions import Fraction

import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import DegreeError, DimensionError, DomainError, InputError
from exactcagd.toolbox import integrals as ig
from tests._sympy_ref import T, R, bernstein_vec, point_lists, rational_curve

fast = settings(max_examples=12, deadline=None)


def pint(expr):
    """int_0^1 of a polynomial in T (sympy Poly antiderivative)."""
    p = sp.Poly(sp.expand(expr), T).integrate()
    return p.eval(1) - p.eval(0)


def weights_for(pts):
    return st.lists(st.builds(Fraction, st.integers(1, 6), st.integers(1, 3)), min_size=len(pts), max_size=len(pts))


rational_data = point_lists(2, 1, 4).flatmap(lambda pts: st.tuples(st.just(pts), weights_for(pts)))


@fast
@given(point_lists(2, 0, 5))
def test_polynomial_integrals_against_sympy(pts):
    c = BezierCurve(pts)
    x, y = bernstein_vec(pts)
    dx, dy = sp.diff(x, T), sp.diff(y, T)
    assert R(ig.area_under(c)) == pint(y * dx)
    assert R(ig.sector_area(c)) == pint((x * dy - y * dx) / 2)
    ix, iy = ig.first_moments(c)
    assert R(ix) == pint(y**2 * dx / 2) and R(iy) == pint(x * y * dx)
    assert R(ig.volume_over_pi(c)) == pint(y**2 * dx)
    if c.degree >= 1:
        assert ig.area_under_by_formula(c) == ig.area_under(c)
        assert ig.sector_area_by_formula(c) == ig.sector_area(c)
        assert ig.first_moments_by_formula(c) == (ix, iy)


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_d_coefficients_against_sympy_integrals(n):
    B = lambda k, i: sp.binomial(k, i) * T**i * (1 - T) ** (k - i)  # noqa: E731
    C2 = lambda i, j: pint(B(n, i) * B(n - 1, j)) if 0 <= j <= n - 1 else 0  # noqa: E731
    D = ig.d2_coefficients(n)
    for i in range(n + 1):
        for j in range(n + 1):
            assert R(D[i, j]) == C2(i, j - 1) - C2(i, j)
    if n <= 3:
        D3 = ig.d3_coefficients(n)
        for i in range(n + 1):
            for j in range(n + 1):
                C3 = lambda k: pint(B(n, i) * B(n, j) * B(n - 1, k)) if 0 <= k <= n - 1 else 0  # noqa: E731
                for k in range(n + 1):
                    assert R(D3[i, j, k]) == C3(k - 1) - C3(k)


def test_enclosed_area_of_closed_chain():
    square = [BezierCurve([[0, 0], [2, 0]]), BezierCurve([[2, 0], [2, 2]]), BezierCurve([[2, 2], [0, 2]]), BezierCurve([[0, 2], [0, 0]])]
    assert ig.enclosed_area(square) == 4
    lens = [BezierCurve([[0, 0], [1, 1], [2, 0]]), BezierCurve([[2, 0], [1, -1], [0, 0]])]
    assert ig.enclosed_area(lens) == Fraction(-4, 3)  # clockwise
    with pytest.raises(DomainError):
        ig.enclosed_area(square[:3])


@fast
@given(rational_data, st.integers(2, 6), st.data())
def test_hybrid_curve_is_the_rational_curve(data, n, draw):
    pts, w = data
    m = draw.draw(st.integers(1, n - 1))
    c = BezierCurve(pts, w)
    h = ig.hybrid_curve(c, n, m)
    assert h.moving.weights == c.weights
    x, y = rational_curve(pts, w)
    Mx, My = rational_curve(h.moving.control_points, h.moving.weights)
    Bn = lambda i: sp.binomial(n, i) * T**i * (1 - T) ** (n - i)  # noqa: E731
    Hx = sum(Bn(i) * R(p[0]) for i, p in enumerate(h.points) if p is not None) + Bn(m) * Mx
    Hy = sum(Bn(i) * R(p[1]) for i, p in enumerate(h.points) if p is not None) + Bn(m) * My
    assert sp.cancel(Hx - x) == 0 and sp.cancel(Hy - y) == 0


@fast
@given(rational_data, st.sampled_from([2, 4, 6]))
def test_polynomial_approximation_bound(data, n):
    pts, w = data
    c = BezierCurve(pts, w)
    a = ig.polynomial_approximation(c, n)
    for k in range(9):
        t = Fraction(k, 8)
        p, r = a.curve.evaluate(t), c.evaluate(t)
        assert sum((u - v) ** 2 for u, v in zip(p, r)) <= a.bound_sq
        assert all(abs(u - v) <= b for u, v, b in zip(p, r, a.coordinate_bounds))


@fast
@given(rational_data)
def test_derivative_and_value_bounds(data):
    pts, w = data
    c = BezierCurve(pts, w)
    bx, by = ig.derivative_bounds(c)
    vx, vy = ig.value_bounds(c)
    x, y = rational_curve(pts, w)
    dx, dy = sp.diff(x, T), sp.diff(y, T)
    for k in range(7):
        t = sp.Rational(k, 6)
        assert abs(dx.subs(T, t)) <= R(bx) and abs(dy.subs(T, t)) <= R(by)
        assert abs(x.subs(T, t)) <= R(vx) and abs(y.subs(T, t)) <= R(vy)


def _reference(pts, w, kind):
    mpmath.mp.dps = 30
    x, y = rational_curve(pts, w)
    integrand = {"area": y * sp.diff(x, T), "sector": (x * sp.diff(y, T) - y * sp.diff(x, T)) / 2,
                 "Ix": y**2 * sp.diff(x, T) / 2, "Iy": x * y * sp.diff(x, T), "volume": y**2 * sp.diff(x, T)}[kind]
    f = sp.lambdify(T, sp.cancel(integrand), "mpmath")
    return mpmath.quad(f, [0, 0.5, 1])


@settings(max_examples=5, deadline=None)
@given(rational_data, st.sampled_from(["area", "sector", "Ix", "Iy", "volume"]))
def test_rational_integral_encloses_the_true_value(data, kind):
    pts, w = data
    c = BezierCurve(pts, w)
    value, bound = ig.rational_integral(c, kind, Fraction(1, 100))
    assert bound <= Fraction(1, 100)
    ref = _reference(pts, w, kind)
    assert abs(mpmath.mpf(value.numerator) / value.denominator - ref) <= mpmath.mpf(bound.numerator) / bound.denominator + mpmath.mpf(10) ** -20


def test_semicircle_area_is_pi_over_8():
    semi = BezierCurve([[0, 0], [0, 1], [1, 1], [1, 0]], [1, Fraction(1, 3), Fraction(1, 3), 1])
    x, y = rational_curve(semi.control_points, semi.weights)
    assert sp.simplify((x - sp.Rational(1, 2)) ** 2 + y**2 - sp.Rational(1, 4)) == 0
    for tol in (Fraction(1, 10**3), Fraction(1, 10**6)):
        value, bound = ig.rational_integral(semi, "area", tol)
        assert abs(float(value) - float(sp.pi / 8)) <= float(bound) + 1e-15


def test_bad_input():
    c = BezierCurve([[0, 0], [1, 1], [2, 0]], [1, 2, 1])
    with pytest.raises(InputError):
        ig.area_under(c)
    with pytest.raises(DimensionError):
        ig.area_under(BezierCurve([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(DegreeError):
        ig.hybrid_curve(c, 2, 2)
    with pytest.raises(InputError):
        ig.rational_integral(c, "length")
    with pytest.raises(DomainError):
        ig.rational_integral(c, "area", 0)
    with pytest.raises(DomainError):
        ig.polynomial_approximation(BezierCurve.from_homogeneous([[0, 0, 1], [-1, -1, -1], [2, 0, 1]]), 4)

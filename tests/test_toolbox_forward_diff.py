"""Chapter 4 toolbox: forward differencing (exact and float) against sympy evaluation."""
from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import DegreeError, InputError
from exactcagd.toolbox import forward_diff as fd
from tests._sympy_ref import R, bernstein_sum, coeff_lists, point_lists, small_rationals

x = sp.Symbol("x")
fast = settings(max_examples=20, deadline=None)


@fast
@given(coeff_lists(0, 5), small_rationals, st.builds(Fraction, st.integers(1, 5), st.integers(1, 7)), st.integers(1, 12))
def test_forward_difference_matches_direct_evaluation(a, t0, delta, count):
    poly = sum(R(c) * x**k for k, c in enumerate(a))
    got = fd.forward_difference(a, t0, delta, count)
    assert [R(v) for v in got] == [poly.subs(x, R(t0) + k * R(delta)) for k in range(count)]


@fast
@given(coeff_lists(0, 5), st.builds(Fraction, st.integers(1, 5), st.integers(1, 9)), st.integers(1, 10))
def test_forward_difference_bernstein_and_curves(c, delta, count):
    poly = bernstein_sum(c, x)
    got = fd.forward_difference(c, 0, delta, count, basis="bernstein")
    assert [R(v) for v in got] == [poly.subs(x, k * R(delta)) for k in range(count)]


@fast
@given(st.lists(small_rationals, min_size=1, max_size=6), st.integers(1, 6))
def test_extend_matches_interpolating_polynomial(values, count):
    p = sp.interpolate([(k, R(v)) for k, v in enumerate(values)], x) if len(values) > 1 else R(values[0])
    got = fd.extend(values, count)
    assert [R(v) for v in got] == [sp.sympify(p).subs(x, len(values) + k) for k in range(count)]


def test_notes_cubic_initial_differences():
    a0, a1, a2, a3, d = sp.symbols("a0 a1 a2 a3 delta")
    f = lambda t: a0 + a1 * t + a2 * t**2 + a3 * t**3  # noqa: E731
    assert sp.expand(f(d) - f(0) - (a1 * d + a2 * d**2 + a3 * d**3)) == 0
    assert sp.expand(f(2 * d) - 2 * f(d) + f(0) - (2 * a2 * d**2 + 6 * a3 * d**3)) == 0
    got = fd.power_initial_differences([5, -1, 2, 3], 0, Fraction(1, 3))
    ref = [5, sp.Rational(-1, 3) + 2 * sp.Rational(1, 9) + 3 * sp.Rational(1, 27), 2 * 2 * sp.Rational(1, 9) + 6 * 3 * sp.Rational(1, 27), 6 * 3 * sp.Rational(1, 27)]
    assert [R(v) for v in got] == ref


@settings(max_examples=15, deadline=None)
@given(coeff_lists(1, 4), st.builds(Fraction, st.integers(1, 3), st.integers(7, 300)), st.integers(2, 200))
def test_float_error_within_certified_bound(a, delta, count):
    report = fd.float_error_report(a, 0, delta, count)
    assert all(e <= b for e, b in zip(report["errors"], report["bounds"]))


def test_float_drift_is_real_and_exact_is_not():
    report = fd.float_error_report([0, 0, 0, 1], 0, Fraction(1, 3), 100)  # t^3 at t = k/3
    assert report["max_error"] > 0          # floats drift (1/3 is not a binary fraction)
    exact = fd.forward_difference([0, 0, 0, 1], 0, Fraction(1, 3), 100)
    assert exact[-1] == Fraction(99, 3) ** 3


def test_solve_missing_examples():
    assert fd.solve_missing([1, 2, 4, None, 15], 3)[3] == 8  # notes: f(4) = 8
    with pytest.raises(InputError):
        fd.solve_missing([1, None, None, 4, 15], 3)
    with pytest.raises(DegreeError):
        fd.solve_missing([1, 2, 4, 9, 15], 3)


@fast
@given(point_lists(2, 1, 4))
def test_rasterization_is_gap_free(pts):
    c = BezierCurve([[10 * p[0], 10 * p[1]] for p in pts])
    px = fd.rasterize(c)
    assert fd.pixels_connected(px)
    assert px[0] == (int(sp.floor(R(c.control_points[0][0]) + sp.Rational(1, 2))), int(sp.floor(R(c.control_points[0][1]) + sp.Rational(1, 2))))


def test_rasterization_needs_absolute_values():
    # a curve whose control points move left/down only: the printed d = max(x_i - x_{i-1}, ...) is negative
    c = BezierCurve([[40, 40], [20, 30], [0, 0]])
    assert fd.rasterization_steps(c) == 60  # n d = 2 * 30
    assert fd.pixels_connected(fd.rasterize(c))
    assert not fd.pixels_connected(fd.rasterize(c, steps=10))


def test_bad_input():
    with pytest.raises(DegreeError):
        fd.extend([0, 1, 4, 9, 17], 1, degree=2)
    with pytest.raises(InputError):
        fd.forward_difference([1, 2], 0, 1, -1)
    with pytest.raises(InputError):
        fd.forward_difference([1, 2], 0, 1, 2, basis="chebyshev")
    with pytest.raises(InputError):
        fd.rasterization_steps(BezierCurve([[0, 0], [1, 1]], [1, 2]))
    with pytest.raises(InputError):
        fd.difference_table([])

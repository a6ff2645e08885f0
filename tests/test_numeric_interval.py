"""Interval arithmetic and interval Bézier curves (notes chapter 12) against independent references.

References: brute force over endpoint combinations in ``fractions.Fraction`` (interval
rules 12.3), exact Bernstein sums written out here, ``math.nextafter`` for the
tightness of outward rounding, sympy integration for the width (12.10).
"""

import math
import sys
from fractions import Fraction

import numpy as np
import pytest
import sympy
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import DimensionError, DomainError, InexactInputError, InputError, NotSupportedError
from exactcagd.numeric.interval import FloatInterval, Interval, as_interval
from exactcagd.numeric.interval_bezier import (
    IntervalBezierCurve,
    affine_map,
    approximate,
    derivative_bounds,
    enclose,
    hermite_interval,
    hermite_interval_from_data,
    interval_polynomial,
    lagrange_interval,
)

FAST = settings(max_examples=50, deadline=None)


def F(x) -> Fraction:
    return Fraction(int(x.numerator), int(x.denominator)) if not isinstance(x, float) else Fraction(x)


def basis(n: int, t: Fraction) -> list:
    return [math.comb(n, k) * (1 - t) ** (n - k) * t**k for k in range(n + 1)]


def bernstein_sum(points, t: Fraction) -> list:
    b = basis(len(points) - 1, t)
    return [sum(F(points[k][j]) * b[k] for k in range(len(points))) for j in range(len(points[0]))]


fractions_st = st.fractions(min_value=-50, max_value=50, max_denominator=64)


@st.composite
def intervals(draw):
    a, b = draw(fractions_st), draw(fractions_st)
    return min(a, b), max(a, b)


def brute(op, u, v):
    values = [op(x, y) for x in u for y in v]
    return min(values), max(values)


# ---------------------------------------------------------------------------- exact intervals (12.3)
@FAST
@given(intervals(), intervals())
def test_exact_rules_match_brute_force(u, v):
    iu, iv = Interval(*u), Interval(*v)
    for result, op in ((iu + iv, lambda x, y: x + y), (iu - iv, lambda x, y: x - y), (iu * iv, lambda x, y: x * y)):
        assert (F(result.lo), F(result.hi)) == brute(op, u, v)
    if v[0] <= 0 <= v[1]:
        with pytest.raises(DomainError):
            iu / iv
    else:
        result = iu / iv
        assert (F(result.lo), F(result.hi)) == brute(lambda x, y: x / y, u, v)


@FAST
@given(intervals(), st.integers(0, 7))
def test_powers_are_exact_ranges(u, k):
    got = Interval(*u) ** k
    candidates = [u[0] ** k, u[1] ** k] + ([Fraction(0)] if u[0] <= 0 <= u[1] and k > 0 else [])
    assert (F(got.lo), F(got.hi)) == (min(candidates), max(candidates))
    if not (u[0] <= 0 <= u[1]) and k > 0:
        inv = Interval(*u) ** -k
        assert inv.contains(1 / u[0] ** k) and inv.contains(1 / u[1] ** k)


@FAST
@given(intervals(), intervals(), st.fractions(0, 1), st.fractions(0, 1))
def test_inclusion_property(u, v, a, b):
    x, y = u[0] + a * (u[1] - u[0]), v[0] + b * (v[1] - v[0])
    iu, iv = Interval(*u), Interval(*v)
    assert (iu + iv).contains(x + y) and (iu - iv).contains(x - y) and (iu * iv).contains(x * y)
    assert (iu**3).contains(x**3) and (iu**2).contains(x**2)


def test_printed_examples_12_33_and_laws():
    assert (Interval(1, 2) + Interval(3, 4)) - Interval(3, 4) == Interval(0, 3)  # (12.33)
    u, v, w = Interval(-1, 2), Interval(1, 3), Interval(-2, -1)
    assert u * (v + w) == Interval(-2, 4) and u * v + u * w == Interval(-7, 8)  # sub-distributive only
    assert 3 * (v + w) == 3 * v + 3 * w  # (12.5)
    assert Interval(1, 2) - Interval(1, 2) == Interval(-1, 1)  # [u] - [u] != 0


def test_interval_accessors_and_errors():
    x = Interval("1/3", 2)
    assert x.midpoint() == mpq(7, 6) and x.radius() == mpq(5, 6) and x.width() == mpq(5, 3)
    assert x.contains("1/2") and not x.contains(3) and x.contains(Interval(1, 2))
    assert Interval.centered(1, "1/2") == Interval("1/2", "3/2")
    assert x.hull(5) == Interval("1/3", 5) and x.intersection(Interval(3, 4)) is None
    assert as_interval((1, 2)) == Interval(1, 2) and Interval(-2, -1).magnitude() == 2
    with pytest.raises(InputError):
        Interval(2, 1)
    with pytest.raises(InexactInputError):
        Interval(float("nan"))
    with pytest.raises(InputError):
        Interval(1, 2) ** 0.5
    with pytest.raises(DomainError):
        1 / Interval(-1, 1)
    with pytest.raises(InputError):
        Interval.centered(0, -1)


# ---------------------------------------------------------------------------- float intervals
float_st = st.floats(-1e6, 1e6, allow_nan=False, allow_subnormal=True)


@st.composite
def float_intervals(draw):
    a, b = draw(float_st), draw(float_st)
    return min(a, b), max(a, b)


def assert_tight_outward(result: FloatInterval, lo: Fraction, hi: Fraction):
    """lo is rounded down and hi up, each to the adjacent float (or to -inf/inf past the range)."""
    def above(x: float, q: Fraction) -> bool:
        return x == math.inf or Fraction(x) > q

    def below(x: float, q: Fraction) -> bool:
        return x == -math.inf or Fraction(x) < q

    if result.lo == -math.inf:
        assert lo < -Fraction(sys.float_info.max)
    else:
        assert Fraction(result.lo) <= lo and above(math.nextafter(result.lo, math.inf), lo)
    if result.hi == math.inf:
        assert hi > Fraction(sys.float_info.max)
    else:
        assert Fraction(result.hi) >= hi and below(math.nextafter(result.hi, -math.inf), hi)


@settings(max_examples=120, deadline=None)
@given(float_intervals(), float_intervals())
def test_float_intervals_are_outward_and_tight(u, v):
    fu, fv = FloatInterval(*u), FloatInterval(*v)
    U, V = tuple(map(Fraction, u)), tuple(map(Fraction, v))
    assert_tight_outward(fu + fv, *brute(lambda x, y: x + y, U, V))
    assert_tight_outward(fu - fv, *brute(lambda x, y: x - y, U, V))
    assert_tight_outward(fu * fv, *brute(lambda x, y: x * y, U, V))
    if U[0] <= 0 <= U[1]:
        with pytest.raises(DomainError):
            fv / fu
    else:
        assert_tight_outward(fv / fu, *brute(lambda x, y: x / y, V, U))
    cube = [U[0] ** 3, U[1] ** 3]
    assert_tight_outward(fu**3, min(cube), max(cube))


def test_float_interval_construction_and_mixing():
    tenth = FloatInterval("1/10")
    assert tenth.lo < 0.1 <= tenth.hi or tenth.lo <= 0.1 < tenth.hi
    assert tenth.contains("1/10") and not FloatInterval(0.1).contains("1/10")
    third = FloatInterval(1.0) / 3.0
    assert third.contains(Fraction(1, 3)) and third.hi == math.nextafter(third.lo, 1)
    mixed = Interval("1/3") + FloatInterval(1.0)
    assert isinstance(mixed, FloatInterval) and mixed.contains(Fraction(4, 3))
    assert (2 - FloatInterval(0.5, 1.0)) == FloatInterval(1.0, 1.5)
    assert FloatInterval(-2.0, 1.0) ** 2 == FloatInterval(0.0, 4.0)
    assert FloatInterval(5e-324) * FloatInterval(0.5) == FloatInterval(0.0, 5e-324)  # underflow, outward
    huge = FloatInterval(1e308) * 10.0
    assert huge.hi == math.inf and huge.lo == 1.7976931348623157e308
    assert Interval(1, 2).to_float().to_exact() == Interval(1, 2)
    with pytest.raises(InexactInputError):
        FloatInterval(float("nan"))
    with pytest.raises(InputError):
        FloatInterval(2.0, 1.0)
    with pytest.raises(DomainError):
        FloatInterval(1.0) / FloatInterval(-1.0, 0.0)


# ---------------------------------------------------------------------------- interval Bézier curves
@st.composite
def interval_curves(draw, max_degree=6):
    n = draw(st.integers(0, max_degree))
    d = draw(st.integers(1, 3))
    lo = [[draw(fractions_st) for _ in range(d)] for _ in range(n + 1)]
    wid = [[draw(st.fractions(0, 3, max_denominator=16)) for _ in range(d)] for _ in range(n + 1)]
    hi = [[a + w for a, w in zip(r, s)] for r, s in zip(lo, wid)]
    return lo, hi


def exact_box(lo, hi, t: Fraction):
    """min/max of sum_k P_k B_k(t) over P_k in the boxes: per term pick the right endpoint."""
    b = basis(len(lo) - 1, t)
    out = []
    for j in range(len(lo[0])):
        low = sum(min(lo[k][j] * b[k], hi[k][j] * b[k]) for k in range(len(lo)))
        high = sum(max(lo[k][j] * b[k], hi[k][j] * b[k]) for k in range(len(lo)))
        out.append((low, high))
    return out


def as_pairs(box):
    return [(F(x.lo), F(x.hi)) for x in box]


@FAST
@given(interval_curves(), st.fractions(-2, 3, max_denominator=50))
def test_interval_de_casteljau_is_the_exact_box(bounds, t):
    lo, hi = bounds
    curve = IntervalBezierCurve.from_bounds(lo, hi)
    expected = exact_box(lo, hi, t)
    assert as_pairs(curve.evaluate(t, extrapolate=True)) == expected  # (12.19) with (12.17)
    assert as_pairs(curve.evaluate_centered(t, extrapolate=True)) == expected  # (12.27)-(12.29)
    if 0 <= t <= 1:
        centre = bernstein_sum(curve.center_curve().control_points, t)
        error = bernstein_sum(curve.error_curve().control_points, t)
        assert [(c - e, c + e) for c, e in zip(centre, error)] == expected  # (12.23)
        corners = curve.corner_curves()
        for key, corner in corners.items():
            point = bernstein_sum(corner.control_points, t)
            assert all(p == (lh[0] if side == "lo" else lh[1]) for p, side, lh in zip(point, key, expected))


@FAST
@given(interval_curves(), st.lists(st.fractions(0, 1), min_size=1, max_size=4), st.data())
def test_member_curves_and_hodographs_lie_inside(bounds, ts, data):
    lo, hi = bounds
    curve = IntervalBezierCurve.from_bounds(lo, hi)
    fracs = [[data.draw(st.fractions(0, 1, max_denominator=20)) for _ in row] for row in lo]
    member = [[a + f * (b - a) for a, b, f in zip(r, s, g)] for r, s, g in zip(lo, hi, fracs)]
    member_curve = BezierCurve(member)
    assert curve.contains_curve(member_curve)
    hodo = curve.hodograph()
    n = len(member) - 1
    for t in ts:
        assert curve.contains_point(t, bernstein_sum(member, t))
        if n > 0:
            deriv_pts = [[n * (member[k + 1][j] - member[k][j]) for j in range(len(member[0]))] for k in range(n)]
            box = hodo.evaluate(t)
            assert all(b.contains(x) for b, x in zip(box, bernstein_sum(deriv_pts, t)))


@FAST
@given(interval_curves(max_degree=4), interval_curves(max_degree=4), st.fractions(0, 1), st.data())
def test_products_of_interval_polynomials_contain_member_products(first, second, t, data):
    p = IntervalBezierCurve.from_bounds([[row[0]] for row in first[0]], [[row[0]] for row in first[1]])
    curve = IntervalBezierCurve.from_bounds(*second)

    def member(lo, hi):
        return [[a + data.draw(st.fractions(0, 1, max_denominator=9)) * (b - a) for a, b in zip(r, s)] for r, s in zip(lo, hi)]

    mp = member(p.lo_array(), p.hi_array())
    mc = member(curve.lo_array(), curve.hi_array())
    product_curve = p * curve
    assert product_curve.degree == p.degree + curve.degree
    scale = bernstein_sum(mp, t)[0]
    box = product_curve.evaluate(t)
    assert all(b.contains(scale * x) for b, x in zip(box, bernstein_sum(mc, t)))
    assert (3 * curve).evaluate(t) == tuple(3 * x for x in curve.evaluate(t))  # (12.5)
    widened = (Interval(-1, 2) * curve).evaluate(t)
    assert all(w.contains(Interval(-1, 2) * x) for w, x in zip(widened, curve.evaluate(t)))


def test_product_needs_a_scalar_factor():
    plane = IntervalBezierCurve([[1, 2], [(3, 4), 0]])
    with pytest.raises(DimensionError):
        plane * plane


@FAST
@given(interval_curves(), st.fractions(0, 1), st.fractions(0, 1))
def test_subdivision_and_elevation_do_not_inflate(bounds, tau, s):
    curve = IntervalBezierCurve.from_bounds(*bounds)
    left, right = curve.subdivide(tau)
    assert left.evaluate(s) == curve.evaluate(tau * s)
    assert right.evaluate(s) == curve.evaluate(tau + (1 - tau) * s)
    assert curve.elevate(2).evaluate(s) == curve.evaluate(s)
    part = curve.reparametrize(0, tau) if tau > 0 else None
    if part is not None:
        assert part.evaluate(s) == curve.evaluate(tau * s)


@settings(max_examples=8, deadline=None)
@given(interval_curves(max_degree=5))
def test_width_is_the_area_between_bound_curves(bounds):
    curve = IntervalBezierCurve.from_bounds(*bounds)
    t = sympy.Symbol("t")
    lower, upper = curve.bound_curves()
    lo_expr, hi_expr = lower.to_sympy(t), upper.to_sympy(t)
    for j, w in enumerate(curve.width()):
        assert sympy.integrate(hi_expr[j] - lo_expr[j], (t, 0, 1)) == sympy.Rational(int(w.numerator), int(w.denominator))


@FAST
@given(interval_curves(max_degree=5))
def test_error_grows_monotonically_outside_unit_interval(bounds):
    curve = IntervalBezierCurve.from_bounds(*bounds)
    right = [curve.error_radius(1 + Fraction(k, 4), extrapolate=True) for k in range(8)]
    left = [curve.error_radius(-Fraction(k, 4), extrapolate=True) for k in range(8)]
    for seq in (right, left):
        assert all(all(a <= b for a, b in zip(x, y)) for x, y in zip(seq, seq[1:]))


@FAST
@given(interval_curves(), st.lists(st.floats(-1.5, 2.5, allow_nan=False), min_size=1, max_size=6))
def test_float_boxes_contain_the_exact_boxes(bounds, ts):
    lo, hi = bounds
    curve = IntervalBezierCurve.from_bounds(lo, hi)
    flo, fhi = curve.evaluate_float(ts)
    for i, t in enumerate(ts):
        for j, (a, b) in enumerate(exact_box(lo, hi, Fraction(t))):
            assert Fraction(flo[i, j]) <= a and b <= Fraction(fhi[i, j])
            assert (Fraction(fhi[i, j]) - Fraction(flo[i, j])) - (b - a) <= Fraction(1, 10**9) * (1 + abs(a) + abs(b))


def test_affine_maps_12_17_and_12_26():
    assert affine_map(Interval(0, 2), Interval(4, 6), "1/4") == Interval(1, 3)
    assert affine_map(Interval(0, 2), Interval(4, 6), -1) == Interval(-6, 0)  # width e0|1-t| + e1|t|
    box = affine_map([Interval(0, 1), (2, 4)], [(2, 2), 6], "1/2")
    assert box == (Interval(1, "3/2"), Interval(4, 5))
    with pytest.raises(DimensionError):
        affine_map([1, 2], [1], "1/2")


def test_interval_polynomial_and_constructors():
    p = interval_polynomial([(0, 1), 2, (1, 3)])
    assert p.evaluate("1/2") == (Interval("5/4", 2),) and p.width() == (mpq(1),)
    c = IntervalBezierCurve.from_centered([[0, 0], [1, 1]], [[1, 0], [0, "1/2"]])
    assert c.control_boxes[1][1] == Interval("1/2", "3/2")
    assert IntervalBezierCurve.from_curve(BezierCurve([[1], [2]])).width() == (0,)
    with pytest.raises(DimensionError):
        IntervalBezierCurve([[(0, 1), 2], [3]])
    with pytest.raises(InputError):
        IntervalBezierCurve.from_bounds([[1]], [[0]])
    with pytest.raises(InputError):
        IntervalBezierCurve.from_centered([[0]], [[-1]])
    with pytest.raises(DomainError):
        p.evaluate(2)
    with pytest.raises(InputError):
        IntervalBezierCurve([])


def test_stationary_parameters_and_corners():
    curve = IntervalBezierCurve.from_bounds([[0, 0], [2, 1], [0, 0]], [[1, 0], [3, 1], [1, 0]])
    roots = curve.stationary_parameters()
    assert {(float(r), j, side) for r, j, side in roots} == {(0.5, 0, "lo"), (0.5, 0, "hi"), (0.5, 1, "lo"), (0.5, 1, "hi")}
    assert len(curve.corner_curves()) == 4


# ---------------------------------------------------------------------------- approximation (12.3-12.4)
@st.composite
def poly_curves(draw, max_degree=9):
    n = draw(st.integers(0, max_degree))
    d = draw(st.integers(1, 2))
    return BezierCurve([[draw(fractions_st) for _ in range(d)] for _ in range(n + 1)])


SAMPLE_T = [Fraction(k, 16) for k in range(17)] + [Fraction(1, 3), Fraction(5, 7), Fraction(99, 100)]


def assert_contains(curve, approx):
    for t in SAMPLE_T:
        assert approx.contains_point(t, curve.evaluate(t)), t


@settings(max_examples=30, deadline=None)
@given(poly_curves(), st.integers(1, 3))
def test_hermite_interval_contains_curve(curve, m):
    approx = hermite_interval(curve, m)
    assert approx.degree == 2 * m
    assert_contains(curve, approx)
    for t in (0, 1):  # end-point interpolation: degenerate boxes at the ends
        assert all(b.is_degenerate() for b in approx.evaluate(t))
    if curve.degree <= 2 * m:
        assert all(w == 0 for w in approx.width())


@settings(max_examples=30, deadline=None)
@given(poly_curves(), st.lists(st.fractions(0, 1, max_denominator=30), min_size=1, max_size=5, unique=True))
def test_lagrange_interval_contains_curve(curve, nodes):
    approx = lagrange_interval(curve, nodes)
    assert approx.degree == len(nodes)
    assert_contains(curve, approx)
    for t in nodes:  # the remainder vanishes at the nodes
        assert all(b.is_degenerate() for b in approx.evaluate_centered(t)) or approx.contains_point(t, curve.evaluate(t))


def test_enclose_and_approximate_rational_curves():
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    twisted = BezierCurve([[0, 0, 1], [1, 2, 0], [2, -1, 3], [3, 1, 1]], weights=[1, "1/3", 4, 2])
    for curve in (quarter, twisted):
        widths = []
        for degree in (2, 4, 6):
            approx = approximate(curve, degree)
            assert approx.degree == degree
            assert_contains(curve, approx)
            widths.append(max(approx.max_error()))
        assert widths[0] > widths[1] > widths[2]
    left, right = quarter.subdivide("1/2")
    assert max(approximate(left, 4).max_error()) < max(approximate(quarter, 4).max_error()) / 4
    exact = approximate(BezierCurve([[0], [3], [1]]), 3)  # degree >= n: exact interpolation
    assert exact.width() == (0,)


def test_derivative_bounds_12_69():
    curve = BezierCurve([[0, 1], [1, 3], [4, 0], [2, 2]])
    t = sympy.Symbol("t")
    expr = curve.to_sympy(t)
    for r in (1, 2, 3, 4):
        bounds = derivative_bounds(curve, r)
        for j in range(2):
            deriv = sympy.diff(expr[j], t, r)
            for tv in [sympy.Rational(k, 10) for k in range(11)]:
                assert bounds[j].contains(to_mpq(deriv.subs(t, tv)))


def to_mpq(x):
    x = sympy.nsimplify(x)
    return mpq(int(x.p), int(x.q))


def test_hermite_from_data_12_59_and_12_63():
    p = hermite_interval_from_data([1], [3], Interval(-2, 4))
    assert [b[0] for b in p.control_boxes] == [Interval(1), Interval(1, "5/2"), Interval(3)]
    f0, d0, f1, d1 = mpq(1), mpq(2), mpq(5), mpq(-1)
    q = hermite_interval_from_data([f0, d0], [f1, d1], Interval(0, 144))
    boxes = [b[0] for b in q.control_boxes]
    assert boxes[1] == Interval(f0 + d0 / 4) and boxes[3] == Interval(f1 - d1 / 4)
    mid = (f0 + f1) / 2 + (d0 - d1) / 6
    assert boxes[2] == Interval(mid, mid + 1)


def test_approximation_input_errors():
    rational = BezierCurve([[0], [1]], weights=[1, 2])
    with pytest.raises(NotSupportedError):
        hermite_interval(rational, 1)
    with pytest.raises(NotSupportedError):
        lagrange_interval(rational, [0, 1])
    with pytest.raises(InputError):
        lagrange_interval(BezierCurve([[0], [1]]), [0, 0])
    with pytest.raises(DomainError):
        lagrange_interval(BezierCurve([[0], [1]]), [0, 2])
    with pytest.raises(InputError):
        hermite_interval(BezierCurve([[0], [1]]), 0)
    pole = BezierCurve.from_homogeneous(np.array([[mpq(1), mpq(1)], [mpq(-1), mpq(-1)]], dtype=object))
    with pytest.raises(DomainError):
        enclose(pole, BezierCurve([[1], [1]]), pieces=1)
    with pytest.raises(DimensionError):
        enclose(BezierCurve([[0], [1]]), BezierCurve([[0, 0], [1, 1]]))


# ---------------------------------------------------------------------------- directed rounding (issue 18)
def _gmpy2_directed(op, a, b):
    """Reference: MPFR's correctly rounded operation in RoundDown / RoundUp (53-bit IEEE contexts)."""
    import gmpy2

    out = []
    for mode in (gmpy2.RoundDown, gmpy2.RoundUp):
        ctx = gmpy2.ieee(64)
        ctx.round = mode
        out.append(float(getattr(ctx, op)(gmpy2.mpfr(a), gmpy2.mpfr(b))))
    return out


_any_float = st.one_of(
    st.floats(allow_nan=False),
    st.floats(allow_nan=False, min_value=-1e-300, max_value=1e-300),
    st.sampled_from([0.0, -0.0, 5e-324, -5e-324, 2.0**-1022, 2.0**960, 2.0**-960, 1.7976931348623157e308]),
)


@settings(max_examples=400, deadline=None)
@given(_any_float, _any_float, _any_float, _any_float)
def test_float_interval_endpoints_are_the_correctly_directed_roundings(a, b, c, d):
    """The error-free-transformation arithmetic gives exactly MPFR's directed roundings
    (same bits, signed zeros included) for [a, b] op [c, d]."""
    lo1, hi1 = sorted((a, b))
    lo2, hi2 = sorted((c, d))
    x, y = FloatInterval(lo1, hi1), FloatInterval(lo2, hi2)

    def same(u, v):
        return (math.isnan(u) and math.isnan(v)) or (u == v and math.copysign(1, u) == math.copysign(1, v))

    s = x + y
    assert same(s.lo, _gmpy2_directed("add", lo1, lo2)[0]) and same(s.hi, _gmpy2_directed("add", hi1, hi2)[1])
    t = x - y
    assert same(t.lo, _gmpy2_directed("sub", lo1, hi2)[0]) and same(t.hi, _gmpy2_directed("sub", hi1, lo2)[1])
    corners = [_gmpy2_directed("mul", p, q) for p in (lo1, hi1) for q in (lo2, hi2)]
    if not any(math.isnan(v) for pair in corners for v in pair):
        m = x * y
        assert m.lo == min(p[0] for p in corners) and m.hi == max(p[1] for p in corners)
    if not lo2 <= 0 <= hi2:
        corners = [_gmpy2_directed("div", p, q) for p in (lo1, hi1) for q in (lo2, hi2)]
        if not any(math.isnan(v) for pair in corners for v in pair):
            r = x / y
            assert r.lo == min(p[0] for p in corners) and r.hi == max(p[1] for p in corners)

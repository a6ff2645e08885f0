"""Chapter 10 toolbox: interpolation (undetermined coefficients, Lagrange, Newton, Neville),
error bounds, Chebyshev nodes, points and normals -- against sympy / mpmath references."""
from fractions import Fraction

import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import DegreeError, DimensionError, DomainError, InputError
from exactcagd.toolbox import interpolation as ip
from tests._sympy_ref import R, bernstein_vec, point_lists, small_rationals

x = sp.Symbol("t")
fast = settings(max_examples=15, deadline=None)

distinct_params = st.lists(st.fractions(min_value=-3, max_value=3, max_denominator=6), min_size=1, max_size=5, unique=True)


def data(dim=2):
    return distinct_params.flatmap(lambda ts: st.tuples(st.just(ts), st.lists(st.lists(small_rationals, min_size=dim, max_size=dim), min_size=len(ts), max_size=len(ts))))


def sym_interp(ts, pts, k):
    if len(ts) == 1:
        return R(pts[0][k])
    return sp.expand(sp.interpolate([(R(t), R(p[k])) for t, p in zip(ts, pts)], x))


@settings(max_examples=10, deadline=None)
@given(data(), st.fractions(min_value=-4, max_value=4, max_denominator=5))
def test_all_four_methods_agree_with_sympy(d, tau):
    ts, pts = d
    ref = [sym_interp(ts, pts, k) for k in range(2)]
    power = ip.undetermined_coefficients(ts, pts)
    assert [sp.expand(e) for e in power.to_sympy(x)] == ref
    assert ip.lagrange_interpolate(ts, pts) == power
    newton = ip.newton_interpolate(ts, pts)
    assert newton.to_power() == power
    val = tuple(r.subs(x, R(tau)) if hasattr(r, "subs") else r for r in ref)
    assert tuple(R(v) for v in newton(tau)) == val
    assert tuple(R(v) for v in ip.neville(ts, pts, tau)[-1][0]) == val
    if tau not in ts:
        assert tuple(R(v) for v in ip.extend_divided_differences(ts, pts, tau)["value"]) == val


@fast
@given(data(), st.sampled_from([(0, 1), (-1, 2)]))
def test_bernstein_undetermined_coefficients(d, interval):
    ts, pts = d
    c = ip.undetermined_coefficients(ts, pts, basis="bernstein", interval=interval)
    a, b = (R(v) for v in interval)
    for k, expr in enumerate(bernstein_vec(c.control_points, x)):
        assert sp.expand(expr.subs(x, (x - a) / (b - a)) - sym_interp(ts, pts, k)) == 0


@settings(max_examples=8, deadline=None)
@given(st.lists(st.fractions(min_value=0, max_value=1, max_denominator=8), min_size=2, max_size=5, unique=True))
def test_node_polynomial_max_against_sympy(nodes):
    w = sp.expand(sp.prod([x - R(v) for v in nodes]))
    crit = [sp.Integer(0), sp.Integer(1)] + [r for r in sp.Poly(sp.diff(w, x), x).real_roots() if 0 < r < 1]
    ref = max(abs(sp.N(w.subs(x, r), 40)) for r in crit)
    got = ip.node_polynomial_max(nodes, 0, 1)
    assert abs(sp.Float(float(got), 40) - ref) <= 1e-15 * max(ref, 1e-300)


@pytest.mark.parametrize("n,a,b", [(0, -1, 1), (3, 0, 1), (6, -2, 5), (9, 0, 1)])
def test_chebyshev_nodes_and_max(n, a, b):
    nodes = ip.chebyshev_nodes(n, a, b)
    mpmath.mp.dps = 40
    ref = sorted(mpmath.mpf(a + b) / 2 + mpmath.mpf(b - a) / 2 * mpmath.cos((2 * i + 1) * mpmath.pi / (2 * n + 2)) for i in range(n + 1))
    for node, r in zip(nodes, ref):
        lo, hi = node.interval(Fraction(1, 2**100))
        tol = mpmath.mpf(10) ** -35
        assert mpmath.mpf(lo.numerator) / lo.denominator - tol <= r <= mpmath.mpf(hi.numerator) / hi.denominator + tol
    m = ip.chebyshev_node_polynomial_max(n, a, b)
    w = ip.chebyshev_node_polynomial(n, a, b)
    wf = [Fraction(int(c.numerator), int(c.denominator)) for c in w]
    samples = [sum(c * (a + (b - a) * Fraction(k, 400)) ** j for j, c in enumerate(wf)) for k in range(401)]
    assert max(abs(s_) for s_ in samples) == Fraction(int(m.numerator), int(m.denominator))  # attained at the ends (|T| = 1)


@fast
@given(st.lists(small_rationals, min_size=1, max_size=8), st.integers(0, 5))
def test_chebyshev_interpolant_is_the_remainder(f, n):
    p = ip.chebyshev_interpolant(f, n, -1, 2)
    fx = sum(R(c) * x**k for k, c in enumerate(f))
    w = sum(R(c) * x**k for k, c in enumerate(ip.chebyshev_node_polynomial(n, -1, 2)))
    assert sp.expand(sp.rem(fx - p.to_sympy(x), w, x)) == 0 and p.degree <= n
    # interpolates at the (float) Chebyshev nodes
    for node in ip.chebyshev_nodes_float(n, -1, 2):
        assert abs(float(fx.subs(x, node)) - float(p.to_sympy(x).subs(x, node))) < 1e-8 * (1 + abs(float(fx.subs(x, node))))
    # error formula (10.1) is an identity for f of degree n + 1
    if len(f) == n + 2 and f[-1] != 0:
        assert sp.expand(fx - p.to_sympy(x) - R(f[-1]) * w) == 0


@settings(max_examples=10, deadline=None)
@given(point_lists(2, 2, 4), st.sampled_from([Fraction(1, 2), Fraction(1, 10), Fraction(1, 50)]))
def test_polyline_tolerance_is_certified(pts, eps):
    c = BezierCurve(pts)
    m = ip.bezier_segments_for_tolerance(c, eps)
    assert ip.polyline_max_deviation_squared(c, m) <= eps * eps
    r = ip.bisection_depth(c, eps)
    assert 2**r >= m and (r == 0 or 2 ** (r - 1) < m)
    # (10.2): the bounds dominate the true second derivative on a sample
    Lx, Ly = ip.second_derivative_bounds(c)
    X, Y = bernstein_vec(pts, x)
    for k in range(11):
        s = sp.Rational(k, 10)
        assert abs(sp.diff(X, x, 2).subs(x, s)) <= R(Lx) and abs(sp.diff(Y, x, 2).subs(x, s)) <= R(Ly)


def test_error_bound_helpers():
    assert ip.linear_error_bound(8, Fraction(1, 2)) == Fraction(1, 4)
    assert ip.segments_needed(8, Fraction(1, 100), 1) == 10  # sqrt(8 / 0.08) = 10
    assert ip.segments_needed(8, Fraction(1, 99), 1) == 10 and ip.segments_needed(8, Fraction(1, 101), 1) == 11
    assert ip.interpolation_error_bound(6, [0, 1, 2], 3) == 6  # 6/3! * 3*2*1


@fast
@given(point_lists(2, 1, 1), st.lists(st.lists(small_rationals, min_size=2, max_size=2), min_size=2, max_size=2))
def test_hermite_cubic_against_notes_blending_functions(ends, tangents):
    p0, p1 = ends
    d0, d1 = tangents
    c = ip.hermite_cubic(p0, p1, d0, d1)
    h = [2 * x**3 - 3 * x**2 + 1, -2 * x**3 + 3 * x**2, x**3 - 2 * x**2 + x, x**3 - x**2]
    ref = [sp.expand(R(p0[k]) * h[0] + R(p1[k]) * h[1] + R(d0[k]) * h[2] + R(d1[k]) * h[3]) for k in range(2)]
    assert bernstein_vec(c.control_points, x) == ref


@fast
@given(st.integers(1, 5), st.lists(st.tuples(st.fractions(min_value=-2, max_value=2, max_denominator=3), st.integers(0, 2),
                                               st.lists(small_rationals, min_size=2, max_size=2)), min_size=1, max_size=4))
def test_interpolate_conditions_family(degree, conds):
    try:
        part, null = ip.interpolate_conditions(degree, conds)
    except InputError:
        # inconsistent: sympy finds no solution either
        a = sp.symbols(f"a0:{degree + 1}"), sp.symbols(f"b0:{degree + 1}")
        eqs = []
        for t, k, v in conds:
            for comp in range(2):
                p = sum(a[comp][j] * x**j for j in range(degree + 1))
                eqs.append(sp.diff(p, x, k).subs(x, R(t)) - R(v[comp]))
        assert sp.solve(eqs, list(a[0]) + list(a[1]), dict=True) == []
        return
    for member in [part] + [PolyPlus(part, n_) for n_ in null]:
        expr = member.to_sympy(x)
        for t, k, v in conds:
            assert [sp.diff(e, x, k).subs(x, R(t)) for e in expr] == [R(v[0]), R(v[1])]


def PolyPlus(p, q):
    return ip.PolynomialCurve(p.coefficients + q.coefficients)


def test_points_and_normals_family():
    part, null = ip.interpolate_points_normals([0, 1], [[0, 0], [1, 0]], [[-1, 1], [1, 1]], 3)
    assert len(null) == 2  # the two tangent lengths
    for member in [part, PolyPlus(part, null[0]), PolyPlus(part, null[1])]:
        P = member.to_sympy(x)
        assert list(P.subs(x, 0)) == [0, 0] and list(P.subs(x, 1)) == [1, 0]
        d0, d1 = P.diff(x).subs(x, 0), P.diff(x).subs(x, 1)
        assert d0.dot(sp.Matrix([-1, 1])) == 0 and d1.dot(sp.Matrix([1, 1])) == 0


def test_bad_input():
    with pytest.raises(InputError):
        ip.lagrange_basis([0, 1, 1])
    with pytest.raises(DimensionError):
        ip.undetermined_coefficients([0, 1], [[0, 0]])
    with pytest.raises(InputError):
        ip.undetermined_coefficients([0, 1], [0, 1], basis="chebyshev")
    with pytest.raises(DomainError):
        ip.chebyshev_node_polynomial(3, 1, 1)
    with pytest.raises(DomainError):
        ip.segments_needed(1, 0, 1)
    with pytest.raises(DegreeError):
        ip.interpolate_conditions(-1, [])
    with pytest.raises(InputError):
        ip.interpolate_conditions(1, [(0, 0, [0, 0]), (0, 0, [1, 1])])

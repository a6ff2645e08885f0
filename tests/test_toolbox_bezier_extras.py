"""Chapter 2 extras (hull, distance, rational derivatives/curvature, continuity, arcs,
reparametrization, explicit curves, integrals) against independent sympy references."""
import math
from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import DegreeError, DimensionError, DomainError, InputError, NotSupportedError
from exactcagd.exact.quadratic import QuadraticNumber
from exactcagd.toolbox import bezier_extras as bx
from tests._sympy_ref import T, R, bernstein_vec, point_lists, rational_curve, small_rationals, unit_params

settings_fast = settings(max_examples=20, deadline=None)


def S(x):
    return x.to_sympy() if isinstance(x, QuadraticNumber) else R(x)


def rational_curves(dim=2, min_degree=1, max_degree=4):
    return point_lists(dim, min_degree, max_degree).flatmap(
        lambda pts: st.tuples(st.just(pts), st.lists(st.builds(Fraction, st.integers(1, 6), st.integers(1, 4)),
                                                     min_size=len(pts), max_size=len(pts))))


@settings_fast
@given(rational_curves(2, 1, 4), unit_params)
def test_curve_points_lie_in_hull(data, t):
    pts, w = data
    c = BezierCurve(pts, w)
    assert bx.in_convex_hull(c.evaluate(t), pts)
    assert all(v <= 0 for v in bx.hull_edge_values(c))


@settings_fast
@given(point_lists(3, 0, 4), st.lists(small_rationals, min_size=3, max_size=3))
def test_in_convex_hull_3d_lp_matches_definition(pts, p):
    """Cross-check the exact LP with a sympy solve over barycentric weights for simplices."""
    inside = bx.in_convex_hull(p, pts)
    if inside:
        # certificate: the point is the average-weighted combination returned by the LP
        from exactcagd.toolbox import _exact as ex

        lam = ex.feasible_nonnegative([[P[k] for P in pts] for k in range(3)] + [[1] * len(pts)], list(p) + [1])
        assert all(x >= 0 for x in lam) and sum(lam) == 1
        assert all(sum(l_ * P[k] for l_, P in zip(lam, pts)) == p[k] for k in range(3))
    else:
        # separation check: sympy finds no non-negative solution of the same system
        lams = sp.symbols(f"l0:{len(pts)}", nonnegative=True)
        eqs = [sum(l_ * R(P[k]) for l_, P in zip(lams, pts)) - R(p[k]) for k in range(3)] + [sum(lams) - 1]
        sols = sp.solve(eqs, lams, dict=True)
        for sol in sols:  # any parametric family must contain no non-negative member
            free = [l_ for l_ in lams if l_ not in sol]
            if not free:
                assert any(v < 0 for v in sol.values())


def test_hull_2d_simple():
    hull = bx.convex_hull_2d([[0, 0], [2, 0], [1, 1], [2, 2], [0, 2], [1, 0]])
    assert hull == [(0, 0), (2, 0), (2, 2), (0, 2)]
    assert bx.in_convex_hull([1, 2], [[0, 0], [2, 0], [2, 2], [0, 2]])
    assert not bx.in_convex_hull([3, 1], [[0, 0], [2, 0], [2, 2], [0, 2]])


@settings_fast
@given(point_lists(2, 1, 4), point_lists(2, 1, 4))
def test_distance_bounds(p_pts, q_pts):
    p, q = BezierCurve(p_pts), BezierCurve(q_pts)
    bound = bx.distance_bound_squared(p, q)
    mx, where = bx.max_distance_squared(p, q)
    assert mx <= bound
    # independent: sympy max over the critical points of |P - Q|^2
    d = [a - b for a, b in zip(bernstein_vec(p_pts), bernstein_vec(q_pts))]
    f = sp.expand(sum(x**2 for x in d))
    crit = [0, 1] + [r for r in sp.Poly(sp.diff(f, T), T).real_roots() if 0 < r < 1] if sp.diff(f, T) != 0 else [0, 1]
    ref = max(f.subs(T, r) for r in crit)
    assert abs(float(mx) - float(ref)) < 1e-9 * max(1.0, float(ref))
    for w in where:
        assert sp.simplify(f.subs(T, w.to_sympy()) - ref) == 0


@settings(max_examples=10, deadline=None)
@given(rational_curves(2, 1, 4), unit_params, st.sampled_from([(0, 1), (2, 5), (-1, 3)]))
def test_derivatives_and_curvature_against_sympy(data, u, interval):
    pts, w = data
    c = BezierCurve(pts, w)
    t0, t1 = interval
    t = t0 + (t1 - t0) * u
    ref = [sp.cancel(e.subs(T, (T - t0) / R(t1 - t0))) for e in rational_curve(pts, w)]
    got = bx.derivatives_at(c, t, 3, interval)
    for k in range(4):
        assert [R(x) for x in got[k]] == [sp.diff(e, T, k).subs(T, R(t)) for e in ref]
    x1, y1 = (sp.diff(e, T).subs(T, R(t)) for e in ref)
    x2, y2 = (sp.diff(e, T, 2).subs(T, R(t)) for e in ref)
    if x1 == y1 == 0:
        with pytest.raises(DomainError):
            bx.curvature(c, t, interval)
        return
    kappa2 = (x1 * y2 - y1 * x2) ** 2 / (x1**2 + y1**2) ** 3
    assert R(bx.curvature_squared(c, t, interval)) == kappa2
    assert sp.simplify(S(bx.curvature(c, t, interval)) - sp.sqrt(kappa2)) == 0
    signed = (x1 * y2 - y1 * x2) / (x1**2 + y1**2) ** sp.Rational(3, 2)
    assert sp.simplify(S(bx.signed_curvature(c, t, interval)) - signed) == 0


@settings_fast
@given(rational_curves(2, 2, 5), st.sampled_from([(0, 1), (1, 3)]))
def test_end_formulas_2_11_to_2_13(data, interval):
    pts, w = data
    c = BezierCurve(pts, w)
    exact = bx.derivatives_at(c, interval[0], 2, interval)
    assert bx.end_first_derivative(c, interval) == exact[1]
    assert bx.end_second_derivative(c, interval) == exact[2]
    if any(exact[1]):
        assert bx.end_curvature(c) == bx.curvature(c, interval[0], interval)


@settings_fast
@given(point_lists(2, 1, 4), st.integers(1, 3))
def test_parametric_and_geometric_continuity_of_split_curve(pts, extra):
    c = BezierCurve(pts)
    left, right = c.subdivide(Fraction(1, 3))
    # on [0, 1/3] and [1/3, 1] the two halves are one curve: C^inf
    assert bx.parametric_continuity(left, right, (0, Fraction(1, 3)), (Fraction(1, 3), 1)) == math.inf
    # on [0, 1], [1, 2] they are G^k with beta_1 = 2 (speed ratio) when regular
    k, betas = bx.geometric_continuity(left, right)
    d1 = bx.derivatives_at(left, 1, 1)[1]
    if any(d1):
        assert k == left.degree + right.degree and betas[0] == 2
        # the reparametrization u -> s with phi(1) = 0, phi' = 2 is linear: higher betas vanish
        assert all(b_ == 0 for b_ in betas[1:])


def test_continuity_examples():
    p = BezierCurve([[0, 0], [1, 1], [2, 0]])
    q1 = BezierCurve([[2, 0], [3, -1], [5, 0]])    # C1, not C2
    q2 = BezierCurve([[2, 0], [4, -2], [5, 0]])    # G1 only (beta = 2)
    q3 = BezierCurve([[2, 1], [3, -1], [5, 0]])    # gap
    assert bx.parametric_continuity(p, q1) == 1
    assert bx.geometric_continuity(p, q1)[0] == 1
    assert bx.parametric_continuity(p, q2) == 0 and bx.geometric_continuity(p, q2) == (1, [2])
    assert bx.parametric_continuity(p, q3) == -1 and bx.geometric_continuity(p, q3) == (-1, [])
    # G2 but not C2: curvature-continuous reparametrized joint (beta_2 != 0)
    a = BezierCurve([[0, 0], [1, 0], [2, 0], [3, 1]])
    b = BezierCurve([[3, 1], [4, 2], [5, 3], [6, 3]])
    assert bx.geometric_continuity(a, b)[0] >= 1


def test_partial_bell_against_sympy():
    xs = sp.symbols("x1:8")
    for n in range(0, 7):
        for k in range(0, n + 1):
            vals = [Fraction(i + 2, i + 1) for i in range(7)]
            ref = sp.bell(n, k, xs[: n - k + 1]).subs(dict(zip(xs, [R(v) for v in vals]))) if n > 0 else (1 if k == 0 else 0)
            assert R(bx.partial_bell(n, k, [v for v in vals])) == ref


@pytest.mark.parametrize("start,end", [((5, 0), (3, 4)), ((5, 0), (0, 5)), ((3, 4), (-4, 3)), ((5, 0), (-5, 0)),
                                       ((5, 0), (0, -5)), ((5, 0), (4, -3)), ((3, 4), (3, 4))])
def test_circular_arcs_are_exact_and_cover_the_right_angle(start, end):
    full = start == end
    arcs = bx.circular_arc((1, 2), (1 + start[0], 2 + start[1]), (1 + end[0], 2 + end[1]), full=full)
    total = 0.0
    prev_end = (1 + start[0], 2 + start[1])
    for arc in arcs:
        assert arc.control_points[0] == prev_end
        prev_end = arc.control_points[-1]
        x, y = (e for e in rational_curve(arc.control_points, arc.weights))
        assert sp.simplify((x - 1) ** 2 + (y - 2) ** 2 - 25) == 0
        (ax, ay), (bx_, by) = ((p[0] - 1, p[1] - 2) for p in (arc.control_points[0], arc.control_points[-1]))
        piece = math.atan2(float(ax * by - ay * bx_), float(ax * bx_ + ay * by)) % (2 * math.pi)
        assert 0 < piece < math.pi
        total += piece
    expected = (math.atan2(end[1], end[0]) - math.atan2(start[1], start[0])) % (2 * math.pi) or 2 * math.pi
    assert abs(total - expected) < 1e-9


def test_arc_symmetric_form_and_cw():
    pts, w = bx.arc_symmetric_form((0, 0), (1, 0), (0, 1))
    assert sp.simplify(S(w[1]) - sp.sqrt(2) / 2) == 0
    pts, w = bx.arc_symmetric_form((0, 0), (5, 0), (3, 4))  # cos(theta/2) = 2/sqrt(5): irrational
    assert isinstance(w[1], QuadraticNumber)
    cw = bx.circular_arc((0, 0), (1, 0), (0, 1), ccw=False)
    assert len(cw) == 3 and cw[0].control_points[0] == (1, 0) and cw[-1].control_points[-1] == (0, 1)
    with pytest.raises(DomainError):
        bx.circular_arc((0, 0), (1, 0), (0, 2))


def test_full_circle_degree5():
    c = bx.full_circle_degree5((1, 1), 2)
    x, y = rational_curve(c.control_points, c.weights)
    assert sp.simplify((x - 1) ** 2 + (y - 1) ** 2 - 4) == 0
    # traversed once: the polar angle is monotone (x y' - y x' keeps one sign)
    xs, ys = x - 1, y - 1
    num = sp.numer(sp.together(xs * sp.diff(ys, T) - ys * sp.diff(xs, T)))
    roots = [r for r in sp.Poly(num, T).real_roots() if 0 <= r <= 1]
    assert roots == []


@settings_fast
@given(rational_curves(2, 1, 4), st.fractions(min_value=Fraction(1, 5), max_value=5, max_denominator=5), unit_params)
def test_mobius_reparametrization(data, bval, u):
    pts, w = data
    c = BezierCurve(pts, w)
    m = bx.mobius_reparametrize(c, bval)
    t = R(bval) * R(u) / ((1 - R(u)) + R(bval) * R(u))
    assert m.evaluate(u) == c.evaluate(Fraction(int(t.p), int(t.q)))
    general = bx.rational_linear_reparametrize(c, 0, bval, 1, bval)
    assert general.same_curve(m)


def test_negative_weight_gives_complementary_circle():
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    rest = bx.mobius_reparametrize(quarter, -1)
    x, y = rational_curve(rest.control_points, rest.weights)
    assert sp.simplify(x**2 + y**2 - 1) == 0
    assert rest.evaluate("1/2") == (-1, 0)  # the far side of the circle


def test_domain_map_and_linear_substitution():
    assert bx.domain_map((0, 1), (5, 9)) == (Fraction(-5, 4), Fraction(1, 4))
    assert bx.domain_map((5, 9), (0, 1)) == (5, 4)
    # notes 2.12: P(t) = (t^2 + t - 1, 2t^2 - t + 3), t = 2s + 1
    from exactcagd.exact.bernstein import from_power

    P = BezierCurve(from_power([[-1, 3], [1, -1], [1, 2]]).tolist())
    Q = bx.substitute_linear(P, 1, 2)
    assert [sp.expand(e) for e in bernstein_vec(Q.control_points)] == [4 * T**2 + 6 * T + 1, 8 * T**2 + 6 * T + 4]


@settings_fast
@given(st.lists(small_rationals, min_size=2, max_size=6), st.sampled_from([(0, 1), (-1, 2)]))
def test_explicit_curve_and_area(ys, interval):
    c = bx.explicit_curve(ys, *interval)
    assert bx.is_explicit(c, *interval)
    t0, t1 = (R(v) for v in interval)
    x, y = bernstein_vec(c.control_points)
    assert sp.expand(x - (t0 + (t1 - t0) * T)) == 0
    area = sp.integrate(y * sp.diff(x, T), (T, 0, 1))
    assert R(bx.area_under_explicit(c)) == area


@settings(max_examples=8, deadline=None)
@given(st.lists(small_rationals, min_size=2, max_size=5).flatmap(
    lambda ys: st.tuples(st.just(ys), st.lists(st.builds(Fraction, st.integers(1, 5), st.integers(1, 3)), min_size=len(ys), max_size=len(ys)))))
def test_explicit_rational_curve(data):
    ys, w = data
    c = bx.explicit_rational_curve(ys, w)
    assert c.degree == len(ys)
    x, y = (sp.cancel(e) for e in rational_curve(c.control_points, c.weights))
    assert sp.cancel(x - T) == 0
    ref = sum(R(wi) * R(yi) * sp.binomial(len(ys) - 1, i) * T**i * (1 - T) ** (len(ys) - 1 - i) for i, (wi, yi) in enumerate(zip(w, ys)))
    ref /= sum(R(wi) * sp.binomial(len(ys) - 1, i) * T**i * (1 - T) ** (len(ys) - 1 - i) for i, wi in enumerate(w))
    assert sp.cancel(y - ref) == 0
    assert bx.is_explicit(c)


def test_bad_input():
    with pytest.raises(NotSupportedError):
        bx.difference_curve(BezierCurve([[0, 0], [1, 1]], [1, 2]), BezierCurve([[0, 0], [1, 1]]))
    with pytest.raises(DimensionError):
        bx.difference_curve(BezierCurve([[0, 0], [1, 1]]), BezierCurve([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(DegreeError):
        bx.end_curvature(BezierCurve([[0, 0], [1, 1]]))
    with pytest.raises(DomainError):
        bx.end_curvature(BezierCurve([[0, 0], [0, 0], [1, 1]]))
    with pytest.raises(DomainError):
        bx.mobius_reparametrize(BezierCurve([[0, 0], [1, 1]]), 0)
    with pytest.raises(DomainError):
        bx.derivatives_at(BezierCurve([[0, 0], [1, 1]]), 0, 1, (1, 1))
    with pytest.raises(InputError):
        bx.area_under_explicit(BezierCurve([[0, 0], [3, 1], [1, 0]]))
    with pytest.raises(DomainError):
        bx.rational_linear_reparametrize(BezierCurve([[0, 0], [1, 1]]), 1, 2, 2, 4)

"""Chapter 1 toolbox (vectors, rotation, lines, conics) against independent sympy references."""
import itertools
from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.errors import DimensionError, DomainError, InputError, NotSupportedError
from exactcagd.exact.quadratic import QuadraticNumber
from exactcagd.toolbox import basics as b
from tests._sympy_ref import R, small_rationals

vec3 = st.lists(small_rationals, min_size=3, max_size=3)
vec2 = st.lists(small_rationals, min_size=2, max_size=2)


def S(x):
    """Exact number of the package (mpq / QuadraticNumber) -> sympy."""
    return x.to_sympy() if isinstance(x, QuadraticNumber) else R(x)


def rodrigues(p, base, d, c, s):
    """Rotation by Rodrigues' formula in sympy (independent of the notes' construction)."""
    p, base, d = (sp.Matrix([R(x) for x in v]) for v in (p, base, d))
    n = d / sp.sqrt(d.dot(d))
    v = p - base
    rot = v * c + n.cross(v) * s + n * n.dot(v) * (1 - c)
    return base + rot


@settings(max_examples=25, deadline=None)
@given(vec3, vec3, vec3, st.fractions(min_value=-3, max_value=3, max_denominator=5))
def test_rotation_matches_rodrigues(p, base, d, t):
    if all(x == 0 for x in d):
        return
    c, s = b.cos_sin_from_tan_half(t)
    got = b.rotate_about_axis(p, base, d, c, s)
    ref = rodrigues(p, base, d, R(c), R(s))
    for g, r in zip(got, ref):
        assert sp.simplify(S(g) - r) == 0


@settings(max_examples=20, deadline=None)
@given(vec3, st.integers(-4, 4), st.integers(-4, 4), st.integers(-4, 4), st.integers(-4, 4))
def test_quaternion_rotation_is_orthogonal_and_matches_axis_angle(p, qa, qb, qc, qd):
    if qb == qc == qd == 0 or qa == 0:
        return
    Rm, axis, (cos, sin_over) = b.rotation_from_quaternion(qa, qb, qc, qd)
    M = sp.Matrix(3, 3, [R(x) for x in Rm.reshape(-1)])
    assert sp.simplify(M.T * M - sp.eye(3)) == sp.zeros(3)
    assert M.det() == 1
    v = sp.sqrt(qb**2 + qc**2 + qd**2)
    ref = rodrigues(p, [0, 0, 0], axis, R(cos), R(sin_over) * v)
    got = M * sp.Matrix([R(x) for x in p])
    assert sp.simplify(got - ref) == sp.zeros(3, 1)


def test_rotation_matrix_equals_vector_form():
    c, s = b.cos_sin_from_triple(3, 4, 5)
    M = b.rotation_matrix([1, 2, 3], [2, 1, 2], c, s)
    for p in ([5, 7, 3], [0, 0, 0], [-1, 2, "1/2"]):
        image = [sum(M[i, j] * x for j, x in enumerate(list(b.vec(p)) + [1])) for i in range(3)]
        assert tuple(image) == b.rotate_about_axis(p, [1, 2, 3], [2, 1, 2], c, s)


def test_irrational_axis_length_is_exact_in_quadratic_field():
    got = b.rotate_about_axis([1, 0, 0], [0, 0, 0], [1, 1, 1], 0, 1)
    ref = rodrigues([1, 0, 0], [0, 0, 0], [1, 1, 1], 0, 1)
    assert any(isinstance(x, QuadraticNumber) for x in got)
    for g, r in zip(got, ref):
        assert sp.simplify(S(g) - r) == 0
    assert b.rotate_about_axis_sympy([1, 0, 0], [0, 0, 0], [1, 1, 1], sp.pi / 2) == tuple(sp.simplify(x) for x in ref)


@settings(max_examples=30, deadline=None)
@given(vec3, vec3, vec3)
def test_triangle_area_cross_product_and_heron(p1, p2, p3):
    a = sp.Matrix([R(x) for x in p2]) - sp.Matrix([R(x) for x in p1])
    c = sp.Matrix([R(x) for x in p3]) - sp.Matrix([R(x) for x in p1])
    ref = a.cross(c).dot(a.cross(c)) / 4
    assert R(b.triangle_area_squared(p1, p2, p3)) == ref
    sq = [b.length_squared(b.relative(x, y)) for x, y in ((p2, p1), (p3, p2), (p1, p3))]
    assert R(b.heron_area_squared(*sq)) == ref


@settings(max_examples=30, deadline=None)
@given(vec2, vec2, vec2)
def test_line_through_and_distance(p0, p1, q):
    if p0 == p1:
        with pytest.raises(DomainError):
            b.line_through(p0, p1)
        return
    line = b.line_through(p0, p1)
    assert line(p0) == 0 and line(p1) == 0
    x0, y0, x1, y1, qx, qy = (R(v) for v in (*p0, *p1, *q))
    num = sp.Abs((x1 - x0) * (y0 - qy) - (x0 - qx) * (y1 - y0))
    ref2 = num**2 / ((x1 - x0) ** 2 + (y1 - y0) ** 2)
    assert R(b.distance_squared_to_line(q, line)) == ref2
    assert sp.simplify(S(b.distance_to_line(q, line)) - sp.sqrt(ref2)) == 0
    assert R(b.distance_squared_point_line(q, p0, b.relative(p1, p0))) == ref2
    assert sp.simplify(sp.Abs(S(b.signed_distance(q, line))) - sp.sqrt(ref2)) == 0


def test_line_forms():
    a0, a1 = b.line_parametric([1, 2], [4, 8], 1, 4)
    assert a1 == (1, 2) and a0 == (0, 0)
    assert b.affine_point([1, 2], 1, [4, 8], 4, 2) == (2, 4)  # one third of the way (notes 1.5.1)
    line = b.line_point_normal([1, 1], [3, 4])
    assert line.normal == (3, 4) and line([1, 1]) == 0
    assert b.Line(3, 4, -7).normalized() == (Fraction(3, 5), Fraction(4, 5), Fraction(-7, 5))
    rl = b.rational_line_implicit([1, 2], [0, 1], [1, 1])  # x = (1+2t)/(1+t), y = t/(1+t)
    for t in (0, 1, 5, Fraction(-1, 3)):
        assert rl([Fraction(1 + 2 * t) / (1 + t), Fraction(t) / (1 + t)]) == 0


conic_coeffs = st.lists(st.integers(-4, 4), min_size=6, max_size=6)


@settings(max_examples=40, deadline=None)
@given(conic_coeffs)
def test_classify_conic_against_sympy_discriminant(coeffs):
    if coeffs[0] == coeffs[1] == coeffs[2] == 0:
        with pytest.raises(DomainError):
            b.classify_conic(coeffs)
        return
    kind = b.classify_conic(coeffs)
    a_, b_, c_ = coeffs[:3]
    disc = b_ * b_ - 4 * a_ * c_
    expected = "hyperbola" if disc > 0 else ("parabola" if disc == 0 else "ellipse")
    assert kind.endswith(expected)
    x, y = sp.symbols("x y")
    f = sum(k * m for k, m in zip(coeffs, (x**2, x * y, y**2, x, y, 1)))
    M = sp.hessian(f, (x, y))
    degenerate = sp.Matrix([[coeffs[0], sp.Rational(coeffs[1], 2), sp.Rational(coeffs[3], 2)],
                            [sp.Rational(coeffs[1], 2), coeffs[2], sp.Rational(coeffs[4], 2)],
                            [sp.Rational(coeffs[3], 2), sp.Rational(coeffs[4], 2), coeffs[5]]]).det() == 0
    assert kind.startswith("degenerate") == degenerate
    if kind == "imaginary ellipse":  # no real point: f keeps the sign of its minimum
        assert M.is_positive_definite or M.is_negative_definite
        sol = sp.solve([f.diff(x), f.diff(y)], [x, y], dict=True)[0]
        assert f.subs(sol) * (coeffs[0] + coeffs[2]) > 0


@settings(max_examples=25, deadline=None)
@given(conic_coeffs)
def test_parametrize_then_implicitize_round_trip(coeffs):
    if coeffs[0] == coeffs[1] == coeffs[2] == 0:
        return
    kind = b.classify_conic(coeffs)
    if kind.startswith(("degenerate", "imaginary")):
        with pytest.raises(DomainError):
            b.parametrize_conic(coeffs)
        return
    try:
        X, Y, W = b.parametrize_conic(coeffs)
    except NotSupportedError:  # no rational point claimed: no small integer point may exist
        # (sympy's own ternary solver is not a reliable reference: it returned (1, 2, 0) for
        # 2x^2 - y^2 + 2w^2, which is not a solution)
        a, bb, c, d, e, f = coeffs
        for x, y, w in itertools.product(range(-8, 9), repeat=3):
            if (x, y, w) != (0, 0, 0):
                assert a * x * x + bb * x * y + c * y * y + d * x * w + e * y * w + f * w * w != 0, (x, y, w)
        return
    t = sp.Symbol("t")
    xs, ys, ws = (sum(R(c) * t**k for k, c in enumerate(p)) for p in (X, Y, W))
    f = sum(k * m for k, m in zip(coeffs, (xs**2, xs * ys, ys**2, xs * ws, ys * ws, ws**2)))
    assert sp.expand(f) == 0
    back = b.implicitize_conic(X, Y, W)
    assert back.same_conic(b.Conic.of(coeffs))
    assert b.classify_parametric_conic(X, Y, W) == kind


def _small_conic_points(coeffs, bound):
    """Brute force: the nonzero integer points (x, y, w), |.| <= bound, of the form (the reference)."""
    a, bb, c, d, e, f = coeffs
    rng = range(-bound, bound + 1)
    return [(x, y, w) for x, y, w in itertools.product(rng, rng, rng)
            if (x, y, w) != (0, 0, 0) and a * x * x + bb * x * y + c * y * y + d * x * w + e * y * w + f * w * w == 0]


def _on_conic_sympy(coeffs, point):
    X, Y, W = (R(v) for v in point)
    return sum(R(k) * m for k, m in zip(coeffs, (X * X, X * Y, Y * Y, X * W, Y * W, W * W))) == 0


def test_rational_point_of_a_conic_sympy_missed():
    """-3x^2 + 2xy + 2y^2 + 2xw - 3yw + 2w^2 has the point (-8, -6, -4) (substitution), but
    sympy's ternary solver (the old finder) answered non-solutions or None for every variable
    order, and parametrize_conic claimed there is no rational point."""
    coeffs = [-3, 2, 2, 2, -3, 2]
    assert _on_conic_sympy(coeffs, (-8, -6, -4))
    X, Y, W = b.parametrize_conic(coeffs)
    t = sp.Symbol("t")
    xs, ys, ws = (sum(R(c) * t**k for k, c in enumerate(p)) for p in (X, Y, W))
    assert sp.expand(sum(k * m for k, m in zip(coeffs, (xs**2, xs * ys, ys**2, xs * ws, ys * ws, ws**2)))) == 0
    assert any(v != 0 for v in X + Y + W)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.integers(-6, 6), min_size=6, max_size=6))
def test_conic_rational_point_finder_agrees_with_brute_force(coeffs):
    """Any small non-degenerate conic: a returned point lies on it exactly (sympy
    substitution); "no rational point" only when brute force finds no integer point
    with coordinates up to 12 (a point that exists is then found)."""
    a, bb, c, d, e, f = coeffs
    M = sp.Matrix([[2 * a, bb, d], [bb, 2 * c, e], [d, e, 2 * f]])
    if a == bb == c == 0 or M.det() == 0:
        return
    point = b._rational_point(b.Conic.of(coeffs))
    if point is None:
        assert _small_conic_points(coeffs, 12) == []
    else:
        assert any(v != 0 for v in point) and _on_conic_sympy(coeffs, point)


def test_rational_point_finder_decides_by_legendre():
    """x^2 + y^2 = 3 w^2 (3 = 3 mod 4: no point), 7x^2 - 5y^2 = 2w^2 (point (1, 1, 1)),
    and coefficients with square factors and common factors (12x^2 + 20y^2 - 32w^2,
    18x^2 - 50y^2 + 32w^2: point (1, 1, 1))."""
    assert b._rational_point(b.Conic.of([1, 0, 1, 0, 0, -3])) is None
    for coeffs in ([7, 0, -5, 0, 0, -2], [12, 0, 20, 0, 0, -32], [18, 0, -50, 0, 0, 32]):
        assert _small_conic_points(coeffs, 6) != []
        point = b._rational_point(b.Conic.of(coeffs))
        assert point is not None and _on_conic_sympy(coeffs, point)


def test_parametrize_without_rational_point_and_through_given_point():
    with pytest.raises(NotSupportedError):
        b.parametrize_conic([1, 0, 1, 0, 0, -3])  # x^2 + y^2 = 3 has no rational point
    X, Y, W = b.parametrize_conic([1, 0, 1, 0, 0, -25], point=[3, 4])
    t = sp.Symbol("t")
    xs, ys, ws = (sum(R(c) * t**k for k, c in enumerate(p)) for p in (X, Y, W))
    assert sp.expand(xs**2 + ys**2 - 25 * ws**2) == 0
    with pytest.raises(DomainError):
        b.parametrize_conic([1, 0, 1, 0, 0, -25], point=[3, 3])


def test_bad_input():
    with pytest.raises(DimensionError):
        b.cross([1, 2], [3, 4])
    with pytest.raises(InputError):
        b.rotate_about_axis([1, 0, 0], [0, 0, 0], [0, 0, 1], "1/2", "1/2")
    with pytest.raises(DomainError):
        b.rotate_about_axis([1, 0, 0], [0, 0, 0], [0, 0, 0], 1, 0)
    with pytest.raises(InputError):
        b.cos_sin_from_triple(3, 4, 6)
    with pytest.raises(DomainError):
        b.heron_area_squared(1, 1, 9)
    with pytest.raises(DomainError):
        b.cos_angle([0, 0, 0], [1, 0, 0])
    with pytest.raises(InputError):
        b.dot("ab", [1, 2])


def test_conic_where_sympys_ternary_solver_errs():
    """2x^2 - y^2 + 2 = 0 has the rational point (1, 2); sympy's solver alone returns a non-solution."""
    X, Y, W = b.parametrize_conic([2, 0, -1, 0, 0, 2])
    t = sp.Symbol("t")
    xs, ys, ws = (sum(R(c) * t**k for k, c in enumerate(p)) for p in (X, Y, W))
    assert sp.expand(2 * xs**2 - ys**2 + 2 * ws**2) == 0

"""BezierCurve (polynomial and rational, 1-3 D) against independent sympy formulas.

The reference curve is built in the test from the definition
sum w_i P_i B_i(t) / sum w_i B_i(t) (notes 003, 2.9) with sympy, never from the class.
"""

import pytest
import sympy as sp
from _sympy_ref import (
    R,
    S,
    T,
    any_params,
    bernstein_coeffs,
    bernstein_vec,
    positive_rationals,
    rational_curve,
    same_function,
    small_rationals,
    unit_params,
)
from gmpy2 import mpq
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import DegreeError, DomainError, ExactCAGDError, InexactInputError, InputError, WeightError
from exactcagd.exact import bernstein as bz

FAST = settings(max_examples=15, deadline=None)


@st.composite
def curves(draw, rational=None, max_degree=4, min_degree=0):
    dim = draw(st.integers(1, 3))
    n = draw(st.integers(min_degree, max_degree))
    pts = draw(st.lists(st.lists(small_rationals, min_size=dim, max_size=dim), min_size=n + 1, max_size=n + 1))
    is_rat = draw(st.booleans()) if rational is None else rational
    w = draw(st.lists(positive_rationals, min_size=n + 1, max_size=n + 1)) if is_rat else None
    return pts, w


def reference(pts, w, t=T):
    return bernstein_vec(pts, t) if w is None else rational_curve(pts, w, t)


def curve_expr(curve, t=T):
    """The curve as sympy expressions, built independently from its control data."""
    pts = [[R(x) for x in p] for p in curve.control_points]
    w = None if curve.weights is None else [R(x) for x in curve.weights]
    return reference(pts, w, t)


def same_curve_expr(a, b):
    return len(a) == len(b) and all(same_function(x, y) for x, y in zip(a, b))


# ---------------------------------------------------------------- evaluation
@given(curves(), any_params)
@FAST
def test_evaluate_matches_definition(data, t):
    pts, w = data
    c = BezierCurve(pts, w)
    ref = reference(pts, w)
    expected = tuple(e.subs(T, R(t)) for e in ref)  # positive weights: no pole on [0, 1]
    assume(all(x.is_finite for x in expected))  # outside [0, 1] the weight function may vanish
    if 0 <= t <= 1:
        assert tuple(R(x) for x in c.evaluate(t)) == expected
        assert tuple(R(x) for x in c.evaluate_horner(t)) == expected
        assert c(t) == c.evaluate(t)
    else:
        with pytest.raises(DomainError):
            c.evaluate(t)
        with pytest.raises(DomainError):
            c.evaluate_horner(t)
    assert tuple(R(x) for x in c.evaluate(t, extrapolate=True)) == expected
    assert tuple(R(x) for x in c.evaluate_horner(t, extrapolate=True)) == expected


@given(curves())
@FAST
def test_to_sympy_matches_definition(data):
    pts, w = data
    c = BezierCurve(pts, w)
    assert same_curve_expr(list(c.to_sympy(T)), reference(pts, w))
    assert c.degree == len(pts) - 1 and c.dimension == len(pts[0]) and c.is_rational == (w is not None)


def test_endpoints_interpolated_and_properties():
    c = BezierCurve([[0, 0, 0], [1, 2, 3], ["1/2", 0, 1]], weights=[1, 3, "1/4"])
    assert c.evaluate(0) == (0, 0, 0)
    assert c.evaluate(1) == (mpq(1, 2), 0, 1)
    assert c.weights == (1, 3, mpq(1, 4))
    assert list(c.weights_array()) == [1, 3, mpq(1, 4)]
    assert c.homogeneous().shape == (3, 4)
    assert list(c.homogeneous()[1]) == [3, 6, 9, 3]
    p = BezierCurve([[0, 1], [2, 3]])
    assert list(p.weights_array()) == [1, 1] and p.weights is None
    assert p.to_dict() == {"degree": 1, "control_points": [["0", "1"], ["2", "3"]]}
    assert c.to_dict()["weights"] == ["1", "3", "1/4"]
    pts, ws = c.to_float()
    assert pts.dtype == float and ws[2] == 0.25


def test_quarter_circle_example():
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    for t in ["0", "1/7", "1/2", "2/3", "1"]:
        x, y = quarter.evaluate(t)
        assert x * x + y * y == 1


# ---------------------------------------------------------------- blossom
@given(curves(min_degree=1), st.data())
@FAST
def test_blossom_diagonal_and_symmetry(data, draw):
    pts, w = data
    c = BezierCurve(pts, w)
    n = c.degree
    args = draw.draw(st.lists(unit_params, min_size=n, max_size=n))
    assert c.blossom(args) == c.blossom(list(reversed(args)))
    t = draw.draw(unit_params)
    assert c.blossom([t] * n) == c.evaluate(t)
    # control points are the polar values f(0^{n-i}, 1^i)
    for i in range(n + 1):
        assert c.blossom([0] * (n - i) + [1] * i) == c.control_points[i]


# ---------------------------------------------------------------- operations preserving the curve
@given(curves(), unit_params)
@FAST
def test_subdivide_preserves_curve(data, t):
    pts, w = data
    c = BezierCurve(pts, w)
    left, right = c.subdivide(t)
    ref = reference(pts, w)
    tq = R(t)
    assert left.degree == right.degree == c.degree and left.is_rational == c.is_rational
    assert same_curve_expr(curve_expr(left, S), [e.subs(T, tq * S) for e in ref])
    assert same_curve_expr(curve_expr(right, S), [e.subs(T, tq + (1 - tq) * S) for e in ref])
    assert left.evaluate(1) == right.evaluate(0) == c.evaluate(t)


@given(curves(), st.integers(0, 3))
@FAST
def test_elevate_preserves_curve(data, r):
    pts, w = data
    c = BezierCurve(pts, w)
    e = c.elevate(r)
    assert e.degree == c.degree + r
    assert same_curve_expr(curve_expr(e), reference(pts, w))
    assert e.same_curve(c) and c.same_curve(e)


@given(curves(), any_params, any_params)
@FAST
def test_reparametrize_is_substitution(data, a, b):
    assume(a != b)
    pts, w = data
    c = BezierCurve(pts, w)
    if w is not None:
        # the new weights are the Bernstein coefficients of W(a + (b - a) s); a zero one
        # cannot be dehomogenized and must raise WeightError
        wfun = sum(R(w[i]) * sp.binomial(c.degree, i) * T**i * (1 - T) ** (c.degree - i) for i in range(c.degree + 1))
        new_w = bernstein_coeffs(wfun.subs(T, R(a) + (R(b) - R(a)) * S), c.degree, S)
        if 0 in new_w:
            with pytest.raises(WeightError):
                c.reparametrize(a, b)
            return
    q = c.reparametrize(a, b)
    if w is not None:
        assert [R(x) for x in q.weights] == new_w
    ref = reference(pts, w)
    assert same_curve_expr(curve_expr(q, S), [e.subs(T, R(a) + (R(b) - R(a)) * S) for e in ref])


@given(curves())
@FAST
def test_reversed_is_substitution(data):
    pts, w = data
    c = BezierCurve(pts, w)
    r = c.reversed()
    assert same_curve_expr(curve_expr(r, S), [e.subs(T, 1 - S) for e in reference(pts, w)])
    assert r.reversed() == c


def test_reparametrize_rejects_degenerate_interval():
    with pytest.raises(DomainError):
        BezierCurve([[0], [1]]).reparametrize("1/2", "1/2")


# ---------------------------------------------------------------- derivatives
@given(curves())
@FAST
def test_derivative_matches_sympy_diff(data):
    pts, w = data
    c = BezierCurve(pts, w)
    d = c.derivative()
    if w is None:
        assert d.degree == max(c.degree - 1, 0) and not d.is_rational
    else:
        assert d.degree == 2 * c.degree
    assert same_curve_expr(curve_expr(d), [sp.diff(e, T) for e in reference(pts, w)])


def test_second_derivative_of_rational_curve():
    pts, w = [[0, 0], [4, 3], [0, 5]], [1, 2, 4]
    c = BezierCurve(pts, w)
    dd = c.derivative().derivative()
    assert same_curve_expr(curve_expr(dd), [sp.diff(e, T, 2) for e in reference(pts, w)])


# ---------------------------------------------------------------- exact degree
@given(curves(rational=False), st.integers(0, 3))
@FAST
def test_true_degree_and_reduce_polynomial(data, r):
    pts, _ = data
    c = BezierCurve(pts)
    e = c.elevate(r)
    true = max(max(sp.Poly(x, T).degree() for x in bernstein_vec(pts)), 0)
    assert e.true_degree() == true
    red = e.reduce()
    assert red.degree == true and not red.is_rational
    assert same_curve_expr(curve_expr(red), bernstein_vec(pts))


@given(curves(rational=True, min_degree=1, max_degree=3), st.integers(1, 2))
@FAST
def test_true_degree_and_reduce_rational_elevated(data, r):
    pts, w = data
    c = BezierCurve(pts, w)
    e = c.elevate(r)
    assert e.true_degree() == c.true_degree() <= c.degree
    red = e.reduce()
    assert red.degree == c.true_degree()
    assert same_curve_expr(curve_expr(red), reference(pts, w))


@given(curves(rational=True, min_degree=1, max_degree=3), st.lists(positive_rationals, min_size=2, max_size=3))
@FAST
def test_reduce_cancels_common_factor(data, factor):
    """N_k = f N0_k, W = f W0 with a positive factor f: the true degree is that of (N0, W0)."""
    pts, w = data
    c = BezierCurve(pts, w)
    f = bz.as_coefficients(factor).reshape(len(factor), 1)
    hom = bz.product(f, c.homogeneous())
    big = BezierCurve.from_homogeneous(hom)
    # public constructor with the same data (weights are positive products)
    big = BezierCurve(big.points_array(), big.weights_array())
    assert big.degree == c.degree + len(factor) - 1
    assert big.same_curve(c)
    assert big.true_degree() == c.true_degree()
    red = big.reduce()
    assert red.degree == c.true_degree()
    assert same_curve_expr(curve_expr(red), reference(pts, w))


def test_reduce_rational_with_constant_weight_function_is_polynomial():
    c = BezierCurve([[0, 0], [1, 2], [2, 0]], weights=[3, 3, 3])
    red = c.reduce()
    assert not red.is_rational and red.control_points == c.control_points
    # weights 1,2 with W = (1-t) + 2t ... times (x = P with W): degree-1 rational line stays rational
    line = BezierCurve([[0], [1]], weights=[1, 2])
    assert line.true_degree() == 1 and line.reduce().is_rational


# ---------------------------------------------------------------- same_curve
def test_same_curve_cases():
    pts, w = [[0, 0], [1, 2], [3, 1]], [1, 2, 3]
    c = BezierCurve(pts, w)
    # rational reparametrization t = b u / ((1-u) + b u): weights scaled by b^i (notes 2.12) -> different parametrization
    b = mpq(2)
    c2 = BezierCurve(pts, [w[i] * b**i for i in range(3)])
    assert not c.same_curve(c2)
    # common scaling of all weights is the same parametric curve
    assert c.same_curve(BezierCurve(pts, [5 * x for x in w]))
    assert not c.same_curve(BezierCurve(pts))
    assert not c.same_curve(BezierCurve([[0, 0, 0], [1, 2, 0], [3, 1, 0]], w))
    assert BezierCurve([[0], [2]]).same_curve(BezierCurve([[0], [1], [2]]))
    assert c == BezierCurve(pts, w) and c != BezierCurve(pts) and hash(c) == hash(BezierCurve(pts, w))


# ---------------------------------------------------------------- homogeneous form
def test_from_homogeneous_allows_negative_weights():
    # b = -1 reparametrization of the quarter circle (notes 2.12, "Negative Weights")
    c = BezierCurve.from_homogeneous(bz.as_coefficients([[1, 0, 1], [-1, -1, -1], [0, 2, 2]]))
    assert c.weights == (1, -1, 2)
    for t in ["0", "1/3", "1/2", "1"]:
        x, y = c.evaluate(t)
        assert x * x + y * y == 1
    with pytest.raises(WeightError):
        BezierCurve.from_homogeneous(bz.as_coefficients([[1, 0, 1], [1, 1, 0]]))


def test_pole_raises_domain_error():
    c = BezierCurve.from_homogeneous(bz.as_coefficients([[0, 1], [1, -1]]))  # W(t) = 1 - 2t
    with pytest.raises(DomainError):
        c.evaluate("1/2")
    with pytest.raises(DomainError):
        c.evaluate_horner("1/2")


# ---------------------------------------------------------------- bad input
@pytest.mark.parametrize(
    "points, weights, error",
    [
        ([[0, 0], [1]], None, InputError),  # ragged
        ([[0, 0], [1, 1, 1]], None, InputError),
        ([0, 1, 2], None, InputError),  # no coordinate axis
        ([[[0, 0]], [[1, 1]]], None, InputError),  # too many axes
        ([], None, InputError),
        ([[]], None, InputError),
        ([[0, 0], [1, 1]], [1], WeightError),  # wrong weight count
        ([[0, 0], [1, 1]], [1, 2, 3], WeightError),
        ([[0, 0], [1, 1]], [[1, 2]], WeightError),
        ([[0, 0], [1, 1]], [1, 0], WeightError),  # zero weight
        ([[0, 0], [1, 1]], [1, "-1/2"], WeightError),  # negative weight
        ([[0, 0], [float("nan"), 1]], None, InexactInputError),
        ([[0, 0], [float("inf"), 1]], None, InexactInputError),
        ([[0, 0], [1, 1]], [1, float("nan")], InexactInputError),
        ([[0, "a"], [1, 1]], None, InputError),
        ([[0, True], [1, 1]], None, InputError),
    ],
)
def test_bad_construction(points, weights, error):
    with pytest.raises(error):
        BezierCurve(points, weights)


def test_bad_operation_arguments():
    c = BezierCurve([[0, 0], [1, 2], [2, 0]], weights=[1, 2, 1])
    for t in [-1, "3/2", mpq(-1, 10**9)]:
        with pytest.raises(DomainError):
            c.evaluate(t)
        with pytest.raises(DomainError):
            c.subdivide(t)
    with pytest.raises(InexactInputError):
        c.evaluate(float("nan"))
    with pytest.raises(DegreeError):
        c.elevate(-1)
    with pytest.raises(DegreeError):
        c.elevate("1")
    with pytest.raises(InputError):
        c.blossom([0])
    with pytest.raises(ExactCAGDError):
        c.reparametrize(0, float("inf"))


def test_reduce_refuses_a_zero_bernstein_weight_but_true_degree_answers():
    """x = 2t, y = 2t^2 over W = (1-t)^2 + t^2 (Bernstein weights 1, 0, 1), times the common
    factor (1 + t): a degree-3 curve with positive weights whose reduced form cannot be stored."""
    t = sp.Symbol("t")
    W, X, Y = (1 - t) ** 2 + t**2, 2 * t, 2 * t**2  # X, Y: homogeneous numerators (x W, y W)
    g = 1 + t
    # Bernstein coefficients of degree 3 from the power form, by sympy (independent of exactcagd)
    def bern3(p):
        coeffs = sp.Poly(sp.expand(p), t).all_coeffs()[::-1] + [0] * 4
        return [sum(sp.Rational(sp.binomial(i, k), sp.binomial(3, k)) * coeffs[k] for k in range(i + 1)) for i in range(4)]

    hx, hy, hw = bern3(X * g), bern3(Y * g), bern3(W * g)
    assert all(w > 0 for w in hw)
    curve = BezierCurve([[x / w, y / w] for x, y, w in zip(hx, hy, hw)], weights=hw)
    ref = sp.Matrix([sp.cancel(X / W), sp.cancel(Y / W)])
    assert sp.simplify(curve.to_sympy(t) - ref) == sp.zeros(2, 1)
    assert curve.true_degree() == 2
    with pytest.raises(WeightError, match="true degree 2.*Bernstein weight 1 is exactly 0"):
        curve.reduce()


@pytest.mark.parametrize("bad", [True, False, 1.0, 2.5, -1, "2", None])
def test_counts_must_be_integers(bad):
    """Elevation amounts, degrees and insertion counts are non-negative integers: True (== 1)
    and 2.0 are refused, not silently taken as numbers."""
    from exactcagd import BezierSurface, BSplineCurve
    from exactcagd.errors import ExactCAGDError

    curve = BezierCurve([[0, 0], [1, 2], [2, 0]])
    with pytest.raises(ExactCAGDError, match="non-negative integer"):
        curve.elevate(bad)
    with pytest.raises(ExactCAGDError, match="non-negative integer"):
        BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]).elevate(1, bad)
    if bad is not None:  # degree=None means "infer it"
        with pytest.raises(ExactCAGDError, match="non-negative integer"):
            BSplineCurve([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 1, 1, 1], degree=bad)


def test_counts_accept_numpy_integers():
    import numpy as np

    assert BezierCurve([[0, 0], [1, 2], [2, 0]]).elevate(np.int64(2)).degree == 4

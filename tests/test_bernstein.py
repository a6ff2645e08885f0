"""exactcagd.exact.bernstein against sympy expansions of the Bernstein sums.

Every reference is the polynomial sum_i c_i C(n,i) t^i (1-t)^(n-i) expanded by sympy
(notes 003, (2.2)); the library's algorithms never produce the expected values.
"""

import itertools
from fractions import Fraction

import pytest
import sympy as sp
from _sympy_ref import R, S, T, U, V, any_params, bernstein_sum, coeff_lists, point_lists, small_rationals, unit_params
from gmpy2 import mpq
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from exactcagd.errors import DegreeError, InexactInputError, InputError
from exactcagd.exact import bernstein as bz

FAST = settings(max_examples=25, deadline=None)
MPQ = type(mpq(0))


def arr(coeffs):
    return bz.as_coefficients(list(coeffs))


def poly_of(c, t=T):
    """sympy polynomial of a 1-D exact coefficient array."""
    return bernstein_sum(list(c), t)


def same_poly(a, b, *gens):
    return sp.expand(a - b) == 0


# ---------------------------------------------------------------- evaluation
@given(coeff_lists(), any_params)
@FAST
def test_de_casteljau_horner_and_sympy_agree(coeffs, t):
    c = arr(coeffs)
    expected = poly_of(coeffs).subs(T, R(t))
    a, b = bz.de_casteljau(c, t), bz.horner_bernstein(c, t)
    assert isinstance(a, MPQ) and isinstance(b, MPQ)
    assert R(a) == expected and R(b) == expected


@given(coeff_lists(max_degree=5), unit_params)
@FAST
def test_de_casteljau_triangle_levels(coeffs, t):
    c = arr(coeffs)
    levels = bz.de_casteljau_triangle(c, t)
    n = len(coeffs) - 1
    assert [lv.shape[0] for lv in levels] == list(range(n + 1, 0, -1))
    assert R(levels[-1][0]) == poly_of(coeffs).subs(T, R(t))
    # level r, entry i is the polar value f(0^{n-r-i}, t^r, 1^i) (notes 6.1)
    p = poly_of(coeffs)
    for r, level in enumerate(levels):
        for i, x in enumerate(level):
            args = [0] * (n - r - i) + [t] * r + [1] * i
            assert R(x) == _blossom_reference(p, n, args)


def test_evaluation_with_vector_coefficients():
    pts = bz.as_coefficients([[0, 0, 1], [1, 2, 0], [3, -1, 2], [4, 4, 4]])
    t = mpq(2, 7)
    expected = [bernstein_sum([p[k] for p in pts], T).subs(T, R(t)) for k in range(3)]
    assert [R(x) for x in bz.de_casteljau(pts, t)] == expected
    assert [R(x) for x in bz.horner_bernstein(pts, t)] == expected


def test_horner_endpoints_and_branch_switch():
    c = arr([3, -1, 4, 1, -5])
    p = poly_of([3, -1, 4, 1, -5])
    for t in ["0", "1", "1/2", "1/2", "-3", "5/2", "499/1000", "501/1000"]:
        assert R(bz.horner_bernstein(c, t)) == p.subs(T, R(t))


def test_sederberg_b_horner_transcription_agrees():
    """The C routine b_horner of notes 3.2, transcribed literally, gives the same values."""

    def b_horner(b, n, t):
        u = 1 - t
        bc, tn, tmp = 1, 1, b[0] * u
        for i in range(1, n):
            tn = tn * t
            bc = bc * (n - i + 1) / Fraction(i)
            tmp = (tmp + tn * bc * b[i]) * u
        return tmp + tn * t * b[n]

    coeffs = [Fraction(x) for x in [2, -3, 5, 7, 1, 0, 4]]
    for t in [Fraction(1, 3), Fraction(5, 6), Fraction(-1, 2)]:
        assert R(bz.horner_bernstein(arr(coeffs), t)) == R(b_horner(coeffs, 6, t))


# ---------------------------------------------------------------- subdivision / restriction
@given(coeff_lists(), any_params)
@FAST
def test_subdivision_halves_reproduce_polynomial(coeffs, t):
    c = arr(coeffs)
    left, right = bz.subdivide(c, t)
    p = poly_of(coeffs)
    tq = R(t)
    assert left.shape == right.shape == c.shape
    assert same_poly(poly_of(left, S), p.subs(T, tq * S))
    assert same_poly(poly_of(right, S), p.subs(T, tq + S * (1 - tq)))
    assert left[-1] == right[0]


@given(coeff_lists(), any_params, any_params)
@FAST
def test_restrict_is_affine_substitution(coeffs, a, b):
    c = arr(coeffs)
    q = bz.restrict(c, a, b)
    p = poly_of(coeffs)
    assert same_poly(poly_of(q, S), p.subs(T, R(a) + S * (R(b) - R(a))))


def test_restrict_reversal_is_reverse_order():
    c = arr([1, 5, -2, 7])
    assert list(bz.restrict(c, 1, 0)) == list(c[::-1])
    assert list(bz.restrict(c, 0, 1)) == list(c)


# ---------------------------------------------------------------- degree operations
@given(coeff_lists(max_degree=6), st.integers(0, 4))
@FAST
def test_elevation_preserves_polynomial(coeffs, r):
    c = arr(coeffs)
    e = bz.elevate(c, r)
    assert e.shape[0] == c.shape[0] + r
    assert all(isinstance(x, MPQ) for x in e)
    assert same_poly(poly_of(e), poly_of(coeffs))


def test_elevation_closed_form_notes_2_8():
    """Single-step elevation equals P*_i = i/(n+1) P_{i-1} + (1 - i/(n+1)) P_i (notes (2.8))."""
    coeffs = [Fraction(x) for x in [3, -2, 7, 1]]
    n = 3
    star = [coeffs[0]] + [Fraction(i, n + 1) * coeffs[i - 1] + (1 - Fraction(i, n + 1)) * coeffs[i] for i in range(1, n + 1)] + [coeffs[-1]]
    assert [R(x) for x in bz.elevate(arr(coeffs), 1)] == [R(x) for x in star]


@given(coeff_lists(max_degree=5), st.integers(0, 3))
@FAST
def test_reduce_returns_elevated_input(coeffs, r):
    c = arr(coeffs)
    n = len(coeffs) - 1
    e = bz.elevate(c, r)
    back = bz.reduce_degree(e, n)
    assert list(back) == list(c)
    true = sp.Poly(poly_of(coeffs), T).degree()
    true = max(true, 0)
    assert bz.true_degree(e) == true
    reduced = bz.reduce_degree(e)
    assert reduced.shape[0] == true + 1
    assert same_poly(poly_of(reduced), poly_of(coeffs))


@given(coeff_lists(min_degree=1, max_degree=6))
@FAST
def test_reduce_refuses_inexact_reduction(coeffs):
    p = poly_of(coeffs)
    d = sp.Poly(p, T).degree()
    assume(d >= 1)
    with pytest.raises(DegreeError):
        bz.reduce_degree(arr(coeffs), d - 1)


def test_reduce_to_higher_degree_elevates():
    c = arr([1, 2])
    out = bz.reduce_degree(c, 3)
    assert out.shape[0] == 4 and same_poly(poly_of(out), poly_of([1, 2]))


def test_true_degree_examples():
    assert bz.true_degree(arr([5])) == 0
    assert bz.true_degree(arr([0, 0, 0])) == 0
    assert bz.true_degree(arr([1, 1, 1, 1])) == 0
    assert bz.true_degree(arr([0, 1, 2, 3])) == 1  # t elevated to degree 3 (times 3)
    assert bz.true_degree(arr([0, 0, 1])) == 2


# ---------------------------------------------------------------- calculus
@given(coeff_lists())
@FAST
def test_derivative_matches_sympy(coeffs):
    d = bz.derivative(arr(coeffs))
    assert d.shape[0] == max(len(coeffs) - 1, 1)
    assert same_poly(poly_of(d), sp.diff(poly_of(coeffs), T))


@given(coeff_lists())
@FAST
def test_antiderivative_and_integral_match_sympy(coeffs):
    c = arr(coeffs)
    a = bz.antiderivative(c)
    p = poly_of(coeffs)
    assert a.shape[0] == c.shape[0] + 1
    big = sp.Poly(p, T).integrate()  # sympy antiderivative, then fix P(0) = 0
    assert same_poly(poly_of(a), big.as_expr() - big.eval(0))
    assert R(bz.integral(c)) == big.eval(1) - big.eval(0)
    # notes (2.20): the area is the average of the coefficients
    assert R(bz.integral(c)) == sum(R(x) for x in coeffs) / len(coeffs)


@given(coeff_lists(), coeff_lists())
@FAST
def test_product_matches_sympy(a, b):
    prod = bz.product(arr(a), arr(b))
    assert prod.shape[0] == len(a) + len(b) - 1
    assert all(isinstance(x, MPQ) for x in prod)
    assert same_poly(poly_of(prod), poly_of(a) * poly_of(b))


def test_product_long_uses_flint_path_and_agrees():
    a = [Fraction(i * i - 7, i + 1) for i in range(12)]
    b = [Fraction(3 - 2 * i, 5) for i in range(10)]
    prod = bz.product(arr(a), arr(b))
    assert same_poly(poly_of(prod), poly_of(a) * poly_of(b))


def test_product_broadcasts_trailing_axes():
    w = arr([1, 2, 3])  # scalar polynomial
    pts = bz.as_coefficients([[1, 0], [2, 5], [0, 1]])
    out = bz.product(w.reshape(3, 1), pts)
    assert out.shape == (5, 2)
    for k in range(2):
        assert same_poly(poly_of(out[:, k]), poly_of([1, 2, 3]) * poly_of([p[k] for p in pts]))


# ---------------------------------------------------------------- basis conversion
@given(coeff_lists())
@FAST
def test_to_power_matches_sympy_expand(coeffs):
    a = bz.to_power(arr(coeffs))
    expected = sp.Poly(poly_of(coeffs), T).all_coeffs()[::-1]
    expected = expected + [0] * (len(coeffs) - len(expected))
    assert [R(x) for x in a] == [sp.Rational(x) for x in expected]
    assert list(bz.from_power(a)) == list(arr(coeffs))


@given(point_lists(3, max_degree=16))
@settings(max_examples=15, deadline=None)
def test_to_power_of_point_columns_matches_sympy_expand(points):
    """Each coordinate column converts separately (the flint Taylor-shift path for n > 2)."""
    a = bz.to_power(arr(points))
    for k in range(3):
        column = [p[k] for p in points]
        expected = sp.Poly(poly_of(column), T).all_coeffs()[::-1]
        expected = expected + [0] * (len(points) - len(expected))
        assert [R(x) for x in a[:, k]] == [sp.Rational(x) for x in expected]


@given(coeff_lists(), st.integers(0, 3))
@FAST
def test_from_power_matches_sympy(power, extra):
    n = len(power) - 1 + extra
    c = bz.from_power(list(power), n)
    assert c.shape[0] == n + 1
    expected = sum(R(x) * T**k for k, x in enumerate(power))
    assert same_poly(poly_of(c), expected)


def test_from_power_degree_too_low():
    assert list(bz.from_power([1, 2, 0, 0], 1)) == list(bz.from_power([1, 2]))
    with pytest.raises(DegreeError):
        bz.from_power([1, 2, 3], 1)


# ---------------------------------------------------------------- blossom
def _blossom_reference(p, n, args):
    """Polar form from the power coefficients: sum_k a_k e_k(args) / C(n, k) (notes 6.11)."""
    coeffs = sp.Poly(p, T).all_coeffs()[::-1] if p != 0 else [0]
    args = [R(x) for x in args]
    total = sp.Integer(0)
    for k, a in enumerate(coeffs):
        if k > n:
            assert a == 0
            continue
        ek = sum((sp.Mul(*comb) for comb in itertools.combinations(args, k)), sp.Integer(0)) if k else sp.Integer(1)
        total += sp.Rational(a) * ek / sp.binomial(n, k)
    return total


@given(coeff_lists(min_degree=1, max_degree=5), st.data())
@FAST
def test_blossom_properties(coeffs, data):
    c = arr(coeffs)
    n = len(coeffs) - 1
    args = data.draw(st.lists(any_params, min_size=n, max_size=n))
    value = bz.blossom(c, args)
    p = poly_of(coeffs)
    assert R(value) == _blossom_reference(p, n, args)
    # symmetric
    perm = data.draw(st.permutations(args))
    assert bz.blossom(c, perm) == value
    # multi-affine in every argument
    k = data.draw(st.integers(0, n - 1))
    a, b, lam = data.draw(any_params), data.draw(any_params), data.draw(any_params)
    mix = list(args)
    mix[k] = (1 - lam) * a + lam * b
    at_a, at_b = list(args), list(args)
    at_a[k], at_b[k] = a, b
    assert bz.blossom(c, mix) == (1 - mpq(lam)) * bz.blossom(c, at_a) + mpq(lam) * bz.blossom(c, at_b)
    # diagonal
    t = data.draw(any_params)
    assert R(bz.blossom(c, [t] * n)) == p.subs(T, R(t))
    # Bernstein coefficients are the polar values f(0^{n-i}, 1^i)
    assert [bz.blossom(c, [0] * (n - i) + [1] * i) for i in range(n + 1)] == list(c)


def test_blossom_wrong_number_of_arguments():
    with pytest.raises(InputError):
        bz.blossom(arr([1, 2, 3]), [0])
    with pytest.raises(InputError):
        bz.blossom(arr([1, 2, 3]), [0, 1, 1])


# ---------------------------------------------------------------- tensor product
tensor_nets = st.tuples(st.integers(0, 3), st.integers(0, 3)).flatmap(
    lambda lm: st.lists(
        st.lists(small_rationals, min_size=lm[1] + 1, max_size=lm[1] + 1), min_size=lm[0] + 1, max_size=lm[0] + 1
    )
)


def tensor_poly(net, u=U, v=V):
    l, m = len(net) - 1, len(net[0]) - 1
    return sp.expand(
        sum(R(net[i][j]) * sp.binomial(l, i) * u**i * (1 - u) ** (l - i) * sp.binomial(m, j) * v**j * (1 - v) ** (m - j) for i in range(l + 1) for j in range(m + 1))
    )


@given(tensor_nets, tensor_nets)
@settings(max_examples=10, deadline=None)
def test_product_tensor_matches_sympy(a, b):
    A, Bn = bz.as_coefficients(a), bz.as_coefficients(b)
    out = bz.product_tensor(A, Bn)
    assert out.shape == (A.shape[0] + Bn.shape[0] - 1, A.shape[1] + Bn.shape[1] - 1)
    assert sp.expand(tensor_poly(out.tolist()) - tensor_poly(a) * tensor_poly(b)) == 0


@given(tensor_nets, unit_params)
@settings(max_examples=15, deadline=None)
def test_along_axis_operations(net, t):
    A = bz.as_coefficients(net)
    p = tensor_poly(net)
    tq = R(t)
    lo, hi = bz.along(1, bz.subdivide, A, t)
    assert sp.expand(tensor_poly(lo.tolist()) - p.subs(V, tq * V)) == 0
    assert sp.expand(tensor_poly(hi.tolist()) - p.subs(V, tq + V * (1 - tq))) == 0
    e = bz.along(0, bz.elevate, A, 2)
    assert e.shape == (A.shape[0] + 2, A.shape[1])
    assert sp.expand(tensor_poly(e.tolist()) - p) == 0
    d = bz.along(0, bz.derivative, A)
    assert sp.expand(tensor_poly(d.tolist()) - sp.diff(p, U)) == 0
    row = bz.de_casteljau(A, t)  # evaluation in u leaves a Bernstein polynomial in v
    assert sp.expand(poly_of(list(row), V) - p.subs(U, tq)) == 0


# ---------------------------------------------------------------- bad input
def test_bad_coefficients_and_parameters():
    with pytest.raises(InputError):
        bz.as_coefficients([])
    with pytest.raises(InputError):
        bz.as_coefficients(5)
    with pytest.raises(InputError):
        bz.as_coefficients([[1, 2], [3]])
    with pytest.raises(InexactInputError):
        bz.as_coefficients([1, float("nan")])
    c = arr([1, 2, 3])
    with pytest.raises(InexactInputError):
        bz.de_casteljau(c, float("inf"))
    with pytest.raises(InexactInputError):
        bz.horner_bernstein(c, float("nan"))
    with pytest.raises(InputError):
        bz.subdivide(c, "half")
    with pytest.raises(DegreeError):
        bz.elevate(c, -1)

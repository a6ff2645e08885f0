"""Resultants, Bezout/Sylvester matrices and common roots (notes 17.3, 17.4, 19.4).

References: the product formula Res(f, g) = a^n b^m prod(alpha_i - beta_j) for
polynomials built from known integer roots, sympy determinants of independently
written Sylvester matrices, sympy gcd.
"""

import random

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.algebra import (
    bezout_matrix_bernstein,
    common_root_count,
    common_roots_linear,
    discriminant,
    euclid_steps,
    gcd_subresultant,
    resultant,
)
from exactcagd.algebra.resultants import bezout_sign, det_bareiss, resultant_coeffs
from exactcagd.errors import InputError

t, x, y, z = sp.symbols("t x y z")


def _from_roots(lead, roots):
    return sp.expand(lead * sp.prod([t - r for r in roots]))


def _product_formula(a, roots_f, b, roots_g):
    m, n = len(roots_f), len(roots_g)
    out = sp.Integer(a) ** n * sp.Integer(b) ** m
    for r in roots_f:
        for s in roots_g:
            out *= r - s
    return out


roots = st.lists(st.integers(-4, 4), min_size=1, max_size=5)
leads = st.sampled_from([1, -1, 2, -3])


@settings(max_examples=40, deadline=None)
@given(roots, roots, leads, leads)
def test_all_methods_equal_product_formula(rf, rg, a, b):
    f, g = _from_roots(a, rf), _from_roots(b, rg)
    expected = _product_formula(a, rf, b, rg)
    for method in ("sylvester", "bezout", "flint"):
        assert resultant(f, g, t, method=method) == expected


@settings(max_examples=10, deadline=None)
@given(st.lists(st.integers(-3, 3), min_size=2, max_size=4), st.lists(st.integers(-3, 3), min_size=2, max_size=3))
def test_polynomial_coefficients_against_sylvester_det(ca, cb):
    # coefficients polynomial in x, y: f = sum (c_i x + i y) t^i
    f = sum((c * x + i * y + 1) * t**i for i, c in enumerate(ca))
    g = sum((c * y - i * x + 2) * t**i for i, c in enumerate(cb))
    fa = sp.Poly(f, t).all_coeffs()
    ga = sp.Poly(g, t).all_coeffs()
    m, n = len(fa) - 1, len(ga) - 1
    rows = [[0] * i + fa + [0] * (n - 1 - i) for i in range(n)] + [[0] * i + ga + [0] * (m - 1 - i) for i in range(m)]
    ref = sp.expand(sp.Matrix(rows).det(method="berkowitz")) if rows else 1
    for method in ("sylvester", "bezout", "flint"):
        assert sp.expand(resultant(f, g, t, method=method) - ref) == 0


def test_poly_inputs_return_poly():
    f = sp.Poly(x - t**2 - 1, t, x)
    g = sp.Poly(y - t**2 - 2 * t + 2, t, y)
    R = resultant(f, g, t)
    assert isinstance(R, sp.Poly) and set(R.gens) == {x, y}
    assert sp.expand(R.as_expr() - (x**2 - 2 * x * y - 10 * x + y**2 + 6 * y + 13)) == 0
    R0 = resultant(sp.Poly(t - 2, t), sp.Poly(t**3 + 1, t), t)
    assert isinstance(R0, sp.Poly) and R0.as_expr() == 9


def test_rational_coefficients_and_constants():
    assert resultant(t / 2 - 1, t**2 - 4, t) == 0
    assert resultant(t / 2 - 1, t - 3, t) == _product_formula(1, [2], 1, [3]) / 2
    assert resultant(sp.Integer(3), t**2 + 1, t) == 9
    assert resultant(sp.Integer(0), t + 1, t) == 0


def test_sympy_sign_issue_is_not_inherited():
    # sympy issue #10666: resultant(t - 2, t**3) returns -8; the Sylvester value is g(2) = 8
    assert resultant(t - 2, t**3, t) == 8
    assert resultant(t**3, t - 2, t) == -8  # (-1)^(m n) Res(g, f)


def test_bezout_bernstein_determinant():
    r = random.Random(3)
    for n in range(1, 6):
        a = [r.randint(-5, 5) for _ in range(n + 1)]
        b = [r.randint(-5, 5) for _ in range(n + 1)]
        fa = sum(a[i] * sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1))
        fb = sum(b[i] * sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1))
        pa = [int(c) for c in sp.Poly(fa, t).all_coeffs()[::-1]] + [0] * n
        pb = [int(c) for c in sp.Poly(fb, t).all_coeffs()[::-1]] + [0] * n
        pa, pb = pa[: n + 1], pb[: n + 1]
        size = 2 * n
        rows = [[0] * i + pa[::-1] + [0] * (n - 1 - i) for i in range(n)] + [[0] * i + pb[::-1] + [0] * (n - 1 - i) for i in range(n)]
        formal = sp.Matrix(rows).det() if size else 1
        assert det_bareiss(bezout_matrix_bernstein(a, b)) == bezout_sign(n) * formal


def test_common_roots_linear_against_gcd():
    r = random.Random(7)
    for _ in range(20):
        common = [r.randint(-3, 3) for _ in range(r.randint(0, 3))]
        f = _from_roots(r.choice([1, 2]), common + [r.randint(4, 6) for _ in range(r.randint(1, 2))])
        g = _from_roots(r.choice([1, -1]), common + [r.randint(-7, -5) for _ in range(r.randint(1, 3))])
        out = common_roots_linear(f, g)
        G = sp.gcd(f, g)
        assert out["count"] == sp.Poly(G, t).degree() == common_root_count(f, g)
        if out["count"]:
            assert sp.simplify(out["gcd"] / G).is_constant()
            assert sp.expand(gcd_subresultant(f, g) - sp.Poly(G, t).monic().as_expr()) == 0
        if out["count"] == 1:
            assert out["root"] == sp.roots(G, t).popitem()[0]


def test_euclid_steps_structure():
    steps, g = euclid_steps(t**3 - 6 * t**2 + 11 * t - 6, t**3 - 7 * t**2 + 14 * t - 8)
    for s in steps:
        assert sp.expand(s["dividend"] - (s["quotient"] * s["divisor"] + s["remainder"])) == 0
    assert sp.expand(g - (t**2 - 3 * t + 2)) == 0


def test_discriminant_normalization():
    a, b, c = sp.symbols("a b c")
    assert sp.expand(discriminant(a * t**2 + b * t + c, t) + a * (b**2 - 4 * a * c)) == 0
    assert sp.expand(discriminant(a * t**2 + b * t + c, t, normalized=True) - (b**2 - 4 * a * c)) == 0
    cubic = t**3 + 2 * t + 5
    assert discriminant(cubic, t, normalized=True) == sp.discriminant(cubic, t)


def test_bad_input():
    with pytest.raises(InputError):
        resultant(t**2 + sp.sqrt(2), t - 1, t)
    with pytest.raises(InputError):
        resultant(t**2, t - 1, t, method="magic")
    with pytest.raises(InputError):
        resultant_coeffs([1, 2], [1, 1], "magic")
    with pytest.raises(InputError):
        common_roots_linear(x + y, x - y)


@settings(max_examples=15, deadline=None)
@given(st.lists(st.fractions(min_value=-5, max_value=5, max_denominator=7), min_size=2, max_size=5),
       st.lists(st.integers(-4, 4), min_size=2, max_size=4))
def test_default_route_is_flint_and_matches_sympy(ca, cb):
    # issue 18: resultant() defaults to python-flint; reference: the determinant of sympy's
    # own Sylvester matrix (sympy.resultant flips the sign when deg f < deg g, so it is not
    # used), rational coefficients and polynomial coefficients in x, y
    from sympy.polys.subresultants_qq_zz import sylvester

    f = sum(sp.Rational(c.numerator, c.denominator) * x**(i % 2) * t**i for i, c in enumerate(ca)) + y * t
    g = sum(c * t**i for i, c in enumerate(cb)) + x
    expected = sylvester(f, g, t, 1).det()
    assert sp.expand(resultant(f, g, t) - expected) == 0
    assert sp.expand(resultant(f, g, t, method="sylvester") - expected) == 0

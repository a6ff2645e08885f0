"""RealAlgebraic / real_roots against sympy's real_roots and mpmath at 50 digits."""

from fractions import Fraction

import mpmath
import pytest
import sympy as sp
from _sympy_ref import R, T, bernstein_sum
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.errors import InputError
from exactcagd.exact.algebraic import RealAlgebraic, integer_poly, real_roots, real_roots_bernstein

FAST = settings(max_examples=20, deadline=None)


def power_coeffs(expr):
    return [sp.Rational(c) for c in sp.Poly(sp.expand(expr), T).all_coeffs()[::-1]]


def mp_real_roots(expr, dps=50):
    """Distinct real roots of expr by mpmath.polyroots on the square-free part (high precision)."""
    sqf = sp.Poly(sp.quo(sp.expand(expr), sp.gcd(sp.expand(expr), sp.diff(expr, T))), T)
    coeffs = [mpmath.mpf(sp.Rational(c).p) / sp.Rational(c).q for c in sqf.all_coeffs()]
    if len(coeffs) <= 1:
        return []
    with mpmath.workdps(dps + 20):
        roots = mpmath.polyroots(coeffs, maxsteps=400, extraprec=400)
        return sorted(mpmath.re(r) for r in roots if abs(mpmath.im(r)) < mpmath.mpf(10) ** (-dps))


def in_interval(r: RealAlgebraic, x) -> bool:
    lo, hi = mpmath.mpf(int(r.lo.numerator)) / int(r.lo.denominator), mpmath.mpf(int(r.hi.numerator)) / int(r.hi.denominator)
    slack = mpmath.mpf(10) ** -50 if r.is_rational else 0  # a point interval vs a 60-digit approximation
    return lo - slack <= x <= hi + slack


factor_pool = [T - 1, T + 2, 2 * T - 1, T**2 - 2, T**2 - 3 * T + 1, T**2 + 1, T**3 - T - 1, 5 * T**2 - 1, T**3 - 2, 3 * T - 4, T**4 - 10 * T**2 + 1]
polys = st.lists(st.tuples(st.sampled_from(factor_pool), st.integers(1, 3)), min_size=1, max_size=3).map(
    lambda fs: (sp.Integer(1) * sp.Mul(*[f**k for f, k in fs])) * 3
)


@given(polys)
@FAST
def test_real_roots_match_sympy_and_mpmath(expr):
    expr = sp.expand(expr)
    ours = real_roots(power_coeffs(expr))
    theirs = sp.Poly(expr, T).real_roots()  # with multiplicity, sorted
    distinct = sorted(set(theirs), key=lambda r: r.evalf(60))
    assert len(ours) == len(distinct)
    assert sum(m for _, m in ours) == len(theirs)
    for (r, m), ref in zip(ours, distinct):
        assert m == theirs.count(ref)
        assert r.to_sympy() == ref
        if ref.is_Rational:
            assert r.is_rational and r.value == mpq(int(ref.p), int(ref.q))
        else:
            assert not r.is_rational and r.lo < r.hi
    # ordering
    for (a, _), (b, _) in zip(ours, ours[1:]):
        assert a < b and b > a and a != b
    # values at 50 digits, twice: sympy's CRootOf evaluation and mpmath's polyroots
    mp = mp_real_roots(expr)
    assert len(mp) == len(ours)
    for (r, _), ref, x in zip(ours, distinct, mp):
        r.refine(mpq(1, 10**48))
        assert r.hi - r.lo < mpq(1, 10**48)
        with mpmath.workdps(60):
            assert in_interval(r, x)
            assert in_interval(r, mpmath.mpf(str(ref.evalf(60))))
            assert abs(mpmath.mpf(float(r)) - x) <= abs(x) * mpmath.mpf(2) ** -52 + mpmath.mpf(10) ** -300


@given(polys, st.fractions(-3, 3, max_denominator=4), st.fractions(-3, 3, max_denominator=4))
@FAST
def test_real_roots_in_closed_interval(expr, lo, hi):
    expr = sp.expand(expr)
    lo, hi = min(lo, hi), max(lo, hi)
    ours = real_roots(power_coeffs(expr), lo, hi)
    expected = [r for r in sorted(set(sp.Poly(expr, T).real_roots()), key=lambda r: r.evalf(60)) if R(lo) <= r <= R(hi)]
    assert [r.to_sympy() for r, _ in ours] == expected
    for r, _ in ours:  # the isolating interval was clipped into [lo, hi]
        assert mpq(lo) <= r.lo and r.hi <= mpq(hi)


def test_endpoints_are_included():
    ours = real_roots([-1, 0, 1], -1, 1)  # t^2 - 1
    assert [(r.value, m) for r, m in ours] == [(-1, 1), (1, 1)]
    assert real_roots([-1, 0, 1], mpq(-1, 2), mpq(1, 2)) == []


def test_refine_width_and_isolation():
    [(r, _)] = real_roots([-2, 0, 1], 0, None)  # sqrt(2)
    for width in ["1/10", "1/1000", mpq(1, 2**80)]:
        r.refine(width)
        assert r.hi - r.lo < mpq(width)
        assert r.lo * r.lo < 2 < r.hi * r.hi
    with pytest.raises(InputError):
        r.refine(0)
    with pytest.raises(InputError):
        r.refine("-1/2")
    with pytest.raises(InputError):
        r.value
    assert r.interval("1/100") == (r.lo, r.hi)


def test_equal_numbers_with_different_intervals():
    [(a, _)] = real_roots([-2, 0, 1], 0, None)
    [(b, _)] = real_roots([-2, 0, 1], 1, 2)
    b.refine(mpq(1, 10**30))
    assert (a.lo, a.hi) != (b.lo, b.hi)
    assert a == b and not a < b and not b < a and hash(a) == hash(b)
    # the same number as a root of a different polynomial (sqrt 2 is a root of t^4 - 4)
    c = [r for r, _ in real_roots([-4, 0, 0, 0, 1]) if r > 0][0]
    assert c == a
    # and of a multiple factor
    d = [r for r, m in real_roots(power_coeffs((T**2 - 2) ** 2 * (T - 5))) if m == 2 and r > 0][0]
    assert d == a


def test_close_distinct_roots_and_rationals():
    eps = sp.Rational(1, 10**20)
    expr = (T**2 - 2) * (T**2 - 2 - eps)
    roots = [r for r, _ in real_roots(power_coeffs(expr), 0, None)]
    assert len(roots) == 2 and roots[0] < roots[1] and roots[0] != roots[1]
    assert roots[0] == real_roots([-2, 0, 1], 0, None)[0][0]
    sqrt2 = roots[0]
    q_above = mpq(14142135623730951, 10**16)  # 1.4142135623730951 > sqrt(2)
    q_below = mpq(14142135623730950, 10**16)
    assert sqrt2 < q_above and sqrt2 > q_below and sqrt2 != q_above
    assert sqrt2 < Fraction(3, 2) and sqrt2 > 1 and sqrt2 <= "3/2"
    # nearly equal roots of two different polynomials
    a = real_roots(power_coeffs(T**2 - 2), 0, None)[0][0]
    b = real_roots(power_coeffs(10**40 * T**2 - 2 * 10**40 - 1), 0, None)[0][0]
    assert a < b and a != b


def test_rational_and_from_rational():
    r = RealAlgebraic.from_rational("-3/7")
    assert r.is_rational and r.value == mpq(-3, 7) and float(r) == -3 / 7
    assert r == mpq(-3, 7) and r < 0 and r.to_dict() == {"rational": "-3/7"}
    assert str(r) == "-3/7" and r.to_sympy() == sp.Rational(-3, 7)
    roots = real_roots(power_coeffs((3 * T - 4) * (T**2 + 1)))
    assert [(x.value, m) for x, m in roots] == [(mpq(4, 3), 1)]


def test_float_dict_and_str():
    [(r, _)] = real_roots([-1, -1, 0, 1])  # plastic number, root of t^3 - t - 1
    assert float(r) == float(sp.CRootOf(T**3 - T - 1, 0).evalf(30))
    d = r.to_dict()
    assert d["polynomial"] == ["-1", "-1", "0", "1"]
    lo, hi = (Fraction(x) for x in d["interval"])
    with mpmath.workdps(50):
        plastic = mpmath.findroot(lambda x: x**3 - x - 1, mpmath.mpf("1.3247"))
        assert mpmath.mpf(lo.numerator) / lo.denominator < plastic < mpmath.mpf(hi.numerator) / hi.denominator
    assert str(r).startswith("root of t^3 - t - 1 in (")


@given(st.lists(st.builds(Fraction, st.integers(-9, 9), st.integers(1, 4)), min_size=1, max_size=6))
@FAST
def test_real_roots_bernstein_match_sympy(coeffs):
    expr = bernstein_sum(coeffs, T)
    if expr == 0:
        with pytest.raises(InputError):
            real_roots_bernstein(coeffs)
        return
    ours = real_roots_bernstein(coeffs)
    expected = [r for r in sorted(set(sp.Poly(expr, T).real_roots()), key=lambda r: r.evalf(60)) if 0 <= r <= 1] if sp.Poly(expr, T).degree() > 0 else []
    assert [r.to_sympy() for r, _ in ours] == expected


def test_bad_input():
    with pytest.raises(InputError):
        real_roots([0, 0, 0])
    with pytest.raises(InputError):
        integer_poly([])
    with pytest.raises(InputError):
        real_roots([1, "x"])
    assert real_roots([5]) == []
    assert integer_poly(["1/2", "-1/3"]).coeffs() == [-3, 2]  # 1/2 - t/3 -> 2t - 3 (primitive, positive lead)


def test_constructor_normalizes_polynomial():
    """RealAlgebraic(poly, lo, hi) with a non-primitive or reducible poly is brought to the
    normal form (regression: == with such a number looped forever)."""
    import flint

    sqrt2 = real_roots([-2, 0, 1], 0, None)[0][0]
    a = RealAlgebraic(flint.fmpz_poly([-4, 0, 2]), 1, 2)  # 2 t^2 - 4
    assert a.poly == flint.fmpz_poly([-2, 0, 1]) and a == sqrt2
    b = RealAlgebraic(flint.fmpz_poly([2, 0, -1]), 1, 2)  # negative leading coefficient
    assert b == sqrt2
    c = RealAlgebraic(flint.fmpz_poly([10, -2, -5, 1]), 1, 2)  # (t^2 - 2)(t - 5)
    assert c == sqrt2 and c.poly.degree() == 2
    d = RealAlgebraic(flint.fmpz_poly([10, -2, -5, 1]), 4, 6)
    assert d.is_rational and d.value == 5
    with pytest.raises(InputError):
        RealAlgebraic(flint.fmpz_poly([-2, 0, 1]), -2, 2)  # two roots inside
    with pytest.raises(InputError):
        RealAlgebraic(flint.fmpz_poly([-2, 0, 1]), 2, 3)  # none inside
    with pytest.raises(InputError):
        RealAlgebraic(flint.fmpz_poly([7]), 0, 1)


@given(st.lists(st.tuples(st.integers(-(2**40), 2**40), st.integers(1, 2**12), st.integers(-300, 300)), min_size=1, max_size=9))
@FAST
def test_bernstein_integer_poly_is_the_primitive_power_form(entries):
    """The integer power form of sum c_i B_i^n equals sympy's expansion of the Bernstein sum
    made primitive with a positive leading coefficient (coefficients up to 2^+-300)."""
    from exactcagd.exact.algebraic import bernstein_integer_poly

    coeffs = [Fraction(p, q) * Fraction(2) ** e for p, q, e in entries]
    expr = sp.expand(bernstein_sum(coeffs, T))
    if expr == 0:
        with pytest.raises(InputError):
            bernstein_integer_poly([mpq(c.numerator, c.denominator) for c in coeffs])
        return
    poly = bernstein_integer_poly([mpq(c.numerator, c.denominator) for c in coeffs])
    reference = sp.Poly(expr, T).clear_denoms()[1].primitive()[1]
    if reference.LC() < 0:
        reference = -reference
    assert [int(c) for c in poly.coeffs()] == [int(c) for c in reference.all_coeffs()[::-1]]


def test_real_roots_takes_a_flint_polynomial_and_the_helpers_are_exact():
    """real_roots(fmpz_poly) = real_roots(its coefficients); exact_dyadic and sign_at against
    exact fractions."""
    import flint

    from exactcagd.exact.algebraic import exact_dyadic, sign_at

    poly = flint.fmpz_poly([2, 0, -7, 0, 3])  # 3 t^4 - 7 t^2 + 2
    assert [(str(r), m) for r, m in real_roots(poly)] == [(str(r), m) for r, m in real_roots([2, 0, -7, 0, 3])]
    with pytest.raises(InputError):
        real_roots(flint.fmpz_poly([]))
    with flint.ctx.workprec(200):
        x = flint.arb(3) / 2**70 + 5
        assert exact_dyadic(x.mid()) == mpq(5) + mpq(3, 2**70) and exact_dyadic(flint.arb(0).mid()) == 0
    assert [sign_at(poly, mpq(v)) for v in ("0", "1/2", "1", "-1", "2")] == [1, 1, -1, -1, 1]

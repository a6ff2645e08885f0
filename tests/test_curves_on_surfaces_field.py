"""Exact real quadratic fields Q(sqrt(D)) (exactcagd.exact.quadratic), checked against mpmath
at 60 digits and sympy, and the FieldBezierCurve built on them."""
import mpmath
import pytest
import sympy
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.curves_on_surfaces.field_curve import FieldBezierCurve, make_curve
from exactcagd.errors import InputError
from exactcagd.exact.quadratic import QuadraticNumber, sqrt_rational


@pytest.fixture(autouse=True)
def _sixty_digits():
    """The references below compare at 1e-45: they need 60 digits, whatever ran before."""
    with mpmath.workdps(60):
        yield


rats = st.builds(lambda p, q: mpq(p, q), st.integers(-50, 50), st.integers(1, 30))
radicands = st.sampled_from([2, 3, 5, 6, 7, 10, 13, 9999991])


def _mp(x: QuadraticNumber):
    return mpmath.mpf(int(x.a.numerator)) / int(x.a.denominator) + mpmath.mpf(int(x.b.numerator)) / int(x.b.denominator) * mpmath.sqrt(int(x.D or 0))


def _close(x, y):
    return abs(x - y) <= mpmath.mpf(10) ** -45 * (1 + abs(y))


@settings(max_examples=60, deadline=None)
@given(rats, rats, rats, rats, radicands)
def test_arithmetic_against_mpmath(a, b, c, d, D):
    x, y = QuadraticNumber(a, b, D), QuadraticNumber(c, d, D)
    X, Y = _mp(x), _mp(y)
    assert _close(_mp(x + y), X + Y)
    assert _close(_mp(x - y), X - Y)
    assert _close(_mp(x * y), X * Y)
    assert _close(_mp(3 - x), 3 - X) and _close(_mp(x * mpq(2, 7)), X * 2 / 7)
    if y != 0:
        assert _close(_mp(x / y), X / Y)
        assert (x / y) * y == x  # exact
        assert _close(_mp(1 / y), 1 / Y)
    # exact sign and order agree with high precision
    assert x.sign() == (0 if X == 0 else (1 if X > 0 else -1))
    assert (x < y) == (X < Y) and (x == y) == (a == c and b == d)
    lo, hi = x.bounds(40)
    assert mpmath.mpf(int(lo.numerator)) / int(lo.denominator) <= X <= mpmath.mpf(int(hi.numerator)) / int(hi.denominator)
    assert abs(float(x) - float(X)) <= 1e-12 * (1 + abs(float(X)))


def test_sign_with_cancellation_and_float():
    # 99/70 is a convergent of sqrt(2): a - b sqrt(2) is tiny and positive
    x = QuadraticNumber(mpq(99, 70), -1, 2)
    assert x.sign() == 1 and x > 0 and float(x) == pytest.approx(float(mpmath.mpf(99) / 70 - mpmath.sqrt(2)), rel=1e-12)
    assert QuadraticNumber(-mpq(577, 408), 1, 2).sign() == -1


def test_sqrt_rational_and_sympy():
    assert sqrt_rational("9/4") == mpq(3, 2)
    r = sqrt_rational("8/3")  # = 2 sqrt(6) / 3
    assert r * r == mpq(8, 3)
    assert sympy.simplify(r.to_sympy() - sympy.sqrt(sympy.Rational(8, 3))) == 0
    with pytest.raises(InputError):
        sqrt_rational(-1)
    with pytest.raises(InputError):
        QuadraticNumber(1, 1, 4)  # square radicand
    with pytest.raises(InputError):
        _ = sqrt_rational(2) + sqrt_rational(3)  # two different fields


def test_field_curve_against_sympy():
    r = sqrt_rational(5)
    hom = [[0, 0, 1], [r, 1, 2], [1, 1 - r / 4, 1]]
    c = FieldBezierCurve(hom)
    t = sympy.Symbol("t")
    expr = c.to_sympy(t)
    for tv in (mpq(0), mpq(1, 3), mpq(3, 4)):
        p = c.evaluate(tv)
        for x, e in zip(p, expr):
            ref = e.subs(t, sympy.Rational(int(tv.numerator), int(tv.denominator)))
            mine = x.to_sympy() if isinstance(x, QuadraticNumber) else sympy.Rational(int(x.numerator), int(x.denominator))
            assert sympy.simplify(mine - ref) == 0
    # elevation and conjugation keep / mirror the curve
    assert c.elevate(2).same_curve(c)
    conj = c.conjugate()
    assert conj.evaluate(mpq(1, 3)) == tuple(x.conjugate() if isinstance(x, QuadraticNumber) else x for x in c.evaluate(mpq(1, 3)))
    # rational coefficients come back as an ordinary BezierCurve
    plain = make_curve([[0, 0, 1], [1, 2, 2], [2, 0, 1]])
    assert isinstance(plain, BezierCurve) and plain.evaluate(mpq(1, 2)) == (mpq(2, 3), mpq(2, 3))

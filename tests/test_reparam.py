"""Reparameterizations of rational Bézier surfaces (Yang et al. 2012, section 4).

Every identity is checked against an independent reference: exact evaluation of the
original surface at the transformed parameters (formulas (2)-(5) written out here),
and sympy rational-function identities for small cases.
"""
import random

import numpy as np
import pytest
import sympy
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierSurface
from exactcagd.errors import DomainError, InputError
from exactcagd.reparam import cubic, mobius, quadratic, substitute
from exactcagd.reparam.closed_forms import coefficient_c, coefficient_d, cubic_closed_form, mobius_weights

# ----------------------------------------------------------------------------- helpers


def _surface(m, n, rng, rational=True, dim=3):
    net = [[[mpq(rng.randint(-9, 9), rng.randint(1, 4)) for _ in range(dim)] for _ in range(n + 1)] for _ in range(m + 1)]
    w = [[mpq(rng.randint(1, 5), rng.randint(1, 3)) for _ in range(n + 1)] for _ in range(m + 1)] if rational else None
    return BezierSurface(net, w)


def _coef(rng):
    return mpq(rng.randint(1, 19), 20)


def _mob(a, s):
    """Eq. (2) as printed: u = (a - 1) s / (2 a s - s - a)."""
    return (a - 1) * s / (2 * a * s - s - a)


def _bern2(c, x):
    return c[0] * (1 - x) ** 2 + 2 * c[1] * x * (1 - x) + c[2] * x**2


def _points(rng, k=4):
    return [(mpq(rng.randint(0, 12), 12), mpq(rng.randint(0, 12), 12)) for _ in range(k)]


degrees = st.tuples(st.integers(0, 3), st.integers(0, 3))
seeds = st.integers(0, 10**6)


# ----------------------------------------------------------------------------- Möbius (2), (3)
@settings(max_examples=15, deadline=None)
@given(degrees, seeds)
def test_mobius_is_substitution(deg, seed):
    rng = random.Random(seed)
    X = _surface(*deg, rng)
    a, b = _coef(rng), _coef(rng)
    Y = mobius(X, a, b)
    assert Y.degree == X.degree
    for s, t in _points(rng):
        assert Y.evaluate(s, t) == X.evaluate(_mob(a, s), _mob(b, t))


def test_mobius_printed_weights_and_points():
    rng = random.Random(3)
    X = _surface(3, 2, rng)
    a, b = mpq(1, 3), mpq(3, 5)
    Y = mobius(X, a, b)
    # control points unchanged, weights as printed (up to one common factor)
    assert np.all(Y.net_array() == X.net_array())
    printed = mobius_weights(X.weights_array(), a, b)
    ratio = Y.weights_array() / printed
    assert len(set(ratio.reshape(-1))) == 1


# ----------------------------------------------------------------------------- quadratic (4)
@settings(max_examples=12, deadline=None)
@given(degrees, seeds)
def test_quadratic_is_substitution(deg, seed):
    rng = random.Random(seed)
    m, n = deg
    X = _surface(m, n, rng)
    (a1, a2), (b1, b2) = (_coef(rng), _coef(rng)), (_coef(rng), _coef(rng))
    Y = quadratic(X, (a1, a2), (b1, b2))
    assert Y.degree == (m + n, m + n)
    for s, t in _points(rng, 3):
        alpha = a1 * t + a2 * (1 - t)
        beta = b1 * s + b2 * (1 - s)
        assert Y.evaluate(s, t) == X.evaluate(_mob(alpha, s), _mob(beta, t))


# ----------------------------------------------------------------------------- cubic (5)
@settings(max_examples=12, deadline=None)
@given(degrees, seeds)
def test_cubic_is_substitution_and_bidegree(deg, seed):
    rng = random.Random(seed)
    m, n = deg
    X = _surface(m, n, rng)
    al = [_coef(rng) for _ in range(3)]
    be = [_coef(rng) for _ in range(3)]
    Y = cubic(X, al, be)
    assert Y.degree == (m + 2 * n, 2 * m + n)  # (m + 2n) in s, (2m + n) in t
    for s, t in _points(rng, 3):
        assert Y.evaluate(s, t) == X.evaluate(_mob(_bern2(al, t), s), _mob(_bern2(be, s), t))


def _sym_hom(surface, u_num, u_den, v_num, v_den):
    """Homogeneous components of X(u_num/u_den, v_num/v_den) times u_den^m v_den^n (sympy)."""
    m, n = surface.degree
    hom = surface.homogeneous()
    R = lambda q: sympy.Rational(int(q.numerator), int(q.denominator))  # noqa: E731
    out = []
    for k in range(hom.shape[2]):
        expr = 0
        for i in range(m + 1):
            for j in range(n + 1):
                bu = u_num**i * (u_den - u_num) ** (m - i) * int(sympy.binomial(m, i))
                bv = v_num**j * (v_den - v_num) ** (n - j) * int(sympy.binomial(n, j))
                expr = bu * bv * R(hom[i, j, k]) + expr
        out.append(expr)
    return out


def _sym_bernstein_hom(surface, s, t):
    ls, lt = surface.degree
    hom = surface.homogeneous()
    R = lambda q: sympy.Rational(int(q.numerator), int(q.denominator))  # noqa: E731
    return [
        sympy.expand(sum(R(hom[i, j, k]) * sympy.binomial(ls, i) * s**i * (1 - s) ** (ls - i) * sympy.binomial(lt, j) * t**j * (1 - t) ** (lt - j) for i in range(ls + 1) for j in range(lt + 1)))
        for k in range(hom.shape[2])
    ]


def test_cubic_symbolic_identity():
    """X(u(s,t), v(s,t)) == cubic(X)(s, t) as rational functions (sympy polynomials, bidegree (2, 1))."""
    rng = random.Random(11)
    X = _surface(2, 1, rng)
    al, be = (mpq(1, 5), mpq(4, 5), mpq(3, 10)), (mpq(2, 5), mpq(1, 3), mpq(7, 9))
    Y = cubic(X, al, be)
    s, t = sympy.symbols("s t")
    R = sympy.Rational
    alpha = sum(R(str(c)) * f for c, f in zip(al, [(1 - t) ** 2, 2 * t * (1 - t), t**2]))
    beta = sum(R(str(c)) * f for c, f in zip(be, [(1 - s) ** 2, 2 * s * (1 - s), s**2]))
    # printed (2), (3): u = (alpha - 1) s / (2 alpha s - s - alpha)
    P = lambda e: sympy.Poly(e, s, t, domain="QQ")  # noqa: E731
    lhs = _sym_hom(X, P((alpha - 1) * s), P(2 * alpha * s - s - alpha), P((beta - 1) * t), P(2 * beta * t - t - beta))
    rhs = [P(e) for e in _sym_bernstein_hom(Y, s, t)]
    for k in range(3):
        assert (lhs[k] * rhs[3] - rhs[k] * lhs[3]).is_zero


def test_cubic_true_bidegree_is_reached():
    """No common factor: the x-coordinate's reduced numerator has bidegree (m+2n, 2m+n)."""
    rng = random.Random(5)
    X = _surface(2, 1, rng)
    Y = cubic(X, (mpq(1, 5), mpq(4, 5), mpq(3, 10)), (mpq(2, 5), mpq(1, 3), mpq(7, 9)))
    s, t = sympy.symbols("s t")
    num, den = sympy.fraction(sympy.cancel(Y.to_sympy(s, t)[0]))
    assert (sympy.degree(den, s), sympy.degree(den, t)) == (4, 5)
    assert max(sympy.degree(num, s), sympy.degree(den, s)) == 4


def test_cubic_closed_form_reconstructed_and_printed_sign():
    rng = random.Random(7)
    al, be = (mpq(1, 5), mpq(4, 5), mpq(3, 10)), (mpq(2, 5), mpq(1, 3), mpq(7, 9))
    for m, n in [(1, 1), (2, 1), (1, 2), (3, 2)]:
        X = _surface(m, n, rng)
        Y = cubic(X, al, be)
        mine = Y.homogeneous()
        closed = cubic_closed_form(X.homogeneous(), al, be)
        # same surface: homogeneous nets equal up to one common factor
        ratio = {mine[i, j, k] / closed[i, j, k] for i, j, k in np.ndindex(*mine.shape) if closed[i, j, k] != 0}
        assert len(ratio) == 1
        printed = cubic_closed_form(X.homogeneous(), al, be, printed_sign=True)
        assert np.all(printed == (-1) ** (m + n) * closed)


def test_c_and_d_are_multinomial_coefficients():
    """c_{l,k}: coefficient of t^l (1-t)^(2m-l) in (1 - alpha)^k alpha^(m-k) (sympy expansion)."""
    t = sympy.Symbol("t")
    al = (mpq(1, 5), mpq(4, 5), mpq(3, 10))
    R = sympy.Rational
    alpha = sum(R(str(c)) * f for c, f in zip(al, [(1 - t) ** 2, 2 * t * (1 - t), t**2]))
    for m in (1, 2, 3):
        for k in range(m + 1):
            poly = sympy.expand((1 - alpha) ** k * alpha ** (m - k))
            rebuilt = sum(R(str(coefficient_c(l, k, m, al))) * t**l * (1 - t) ** (2 * m - l) for l in range(2 * m + 1))
            assert sympy.expand(rebuilt - poly) == 0
            assert coefficient_d(1, k, m, al) == coefficient_c(1, k, m, al)


def test_iso_line_half_is_parabola_image():
    """s = 1/2 iso-line of the cubic reparameterization == X(1 - alpha(t), M_beta(t))."""
    rng = random.Random(2)
    X = _surface(2, 3, rng)
    al = (mpq(1, 5), mpq(4, 5), mpq(3, 10))
    b = mpq(2, 5)
    iso = cubic(X, al, (b, b, b)).iso_u(mpq(1, 2))
    for t in [mpq(0), mpq(1, 7), mpq(1, 2), mpq(5, 6), mpq(1)]:
        assert iso.evaluate(t) == X.evaluate(1 - _bern2(al, t), _mob(b, t))


def test_polynomial_surface_and_general_substitute():
    rng = random.Random(9)
    X = _surface(2, 2, rng, rational=False)
    Y = mobius(X, mpq(1, 4), mpq(2, 3))
    assert Y.is_rational and Y.evaluate(mpq(1, 3), mpq(1, 2)) == X.evaluate(_mob(mpq(1, 4), mpq(1, 3)), _mob(mpq(2, 3), mpq(1, 2)))
    # identity maps: u = s, v = t
    ident_u = (np.array([[mpq(0)], [mpq(1)]], dtype=object), np.array([[mpq(1)], [mpq(1)]], dtype=object))
    ident_v = (np.array([[mpq(0), mpq(1)]], dtype=object), np.array([[mpq(1), mpq(1)]], dtype=object))
    Z = substitute(X, ident_u, ident_v)
    assert Z.evaluate(mpq(2, 7), mpq(3, 5)) == X.evaluate(mpq(2, 7), mpq(3, 5))


# ----------------------------------------------------------------------------- bad input
def test_bad_input():
    X = _surface(1, 1, random.Random(1))
    with pytest.raises(DomainError):
        mobius(X, 0, "1/2")
    with pytest.raises(DomainError):
        cubic(X, ("1/2", "1", "1/2"), ("1/2", "1/2", "1/2"))
    with pytest.raises(InputError):
        quadratic(X, ("1/2",), ("1/2", "1/2"))
    with pytest.raises(InputError):
        cubic("not a surface", ("1/2",) * 3, ("1/2",) * 3)
    with pytest.raises(InputError):
        mobius(X, "one half", "1/2")


@pytest.mark.parametrize("kind", ["mobius", "quadratic"])
def test_mobius_and_quadratic_symbolic_identity(kind):
    """X(u(s,t), v(s,t)) == reparameterized X(s,t) as rational functions (sympy), printed (2)-(4)."""
    rng = random.Random(13)
    X = _surface(2, 2, rng)
    s, t = sympy.symbols("s t")
    R = lambda q: sympy.Rational(int(q.numerator), int(q.denominator))  # noqa: E731
    if kind == "mobius":
        a, b = mpq(2, 7), mpq(3, 5)
        Y = mobius(X, a, b)
        alpha, beta = R(a), R(b)
        assert Y.degree == (2, 2)
    else:
        (a1, a2), (b1, b2) = (mpq(2, 5), mpq(3, 4)), (mpq(1, 6), mpq(5, 9))
        Y = quadratic(X, (a1, a2), (b1, b2))
        alpha = R(a1) * t + R(a2) * (1 - t)  # (4)
        beta = R(b1) * s + R(b2) * (1 - s)
        assert Y.degree == (4, 4)  # m + n in both directions
    P = lambda e: sympy.Poly(e, s, t, domain="QQ")  # noqa: E731
    lhs = _sym_hom(X, P((alpha - 1) * s), P(2 * alpha * s - s - alpha), P((beta - 1) * t), P(2 * beta * t - t - beta))
    rhs = [P(e) for e in _sym_bernstein_hom(Y, s, t)]
    for k in range(3):
        assert (lhs[k] * rhs[3] - rhs[k] * lhs[3]).is_zero
    # and a wrong map is detected: swapping alpha and 1 - alpha changes the surface
    bad = _sym_hom(X, P(-alpha * s), P(2 * (1 - alpha) * s - s - (1 - alpha)), P((beta - 1) * t), P(2 * beta * t - t - beta))
    assert any(not (bad[k] * rhs[3] - rhs[k] * bad[3]).is_zero for k in range(3))


@settings(max_examples=15, deadline=None)
@given(degrees, seeds, st.booleans())
def test_fast_curve_substitution_equals_generic(deg, seed, irrational):
    """The flint route of substitute_curve (scaled Bernstein form, pairs over Q(sqrt D)) gives
    exactly the coefficients of the generic Bernstein-product route."""
    from exactcagd.exact.quadratic import sqrt_rational
    from exactcagd.reparam import substitute_curve

    rng = random.Random(seed)
    hom = _surface(*deg, rng).homogeneous()
    r = sqrt_rational(mpq(rng.randint(2, 40), rng.randint(1, 9))) if irrational else mpq(rng.randint(1, 9), 7)
    u_map = ([mpq(1, 5), r / 4 + mpq(1, 3), mpq(4, 5)][: rng.randint(1, 3)], [mpq(1)] * rng.randint(1, 2))
    v_map = ([(r + 1) / 10, mpq(3, 2)], [r + 1, mpq(2)])
    fast = substitute_curve(hom, u_map, v_map, fast=True)
    slow = substitute_curve(hom, u_map, v_map, fast=False)
    du, dv = max(len(x) for x in u_map) - 1, 1
    assert fast.shape == slow.shape == (deg[0] * du + deg[1] * dv + 1, 4)
    assert all(x == y for x, y in zip(fast.reshape(-1), slow.reshape(-1)))

"""``proper_at_fiber``: the cheap properness proof that lets ``implicitize`` skip the
squarefree factorization of the resultant.

Reference (independent of exactcagd's resultant): sympy's ``resultant`` of
``W x - X``, ``W y - Y`` and its ``sqf_list`` give the index ``r`` (resultant ``c F^r``).
The proof may say "undecided" (``False``) for a proper curve, never ``True`` for an
improper one; the planted curve below has the fibre point at infinity that the degree
condition exists for.
"""

from __future__ import annotations

import warnings

import flint
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.algebra import implicit_equation
from exactcagd.algebra._poly import curve_from_polynomials
from exactcagd.algebra.implicitize import proper_at_fiber, reduced_components

t, x, y = sympy.symbols("t x y")


def _sympy_index(X, Y, W) -> int:
    """``r`` with ``Res_t(W x - X, W y - Y) = c F^r`` (sympy)."""
    P = lambda p: sum(int(c) * t**k for k, c in enumerate(p.coeffs()))  # noqa: E731
    res = sympy.resultant(sympy.expand(P(W) * x - P(X)), sympy.expand(P(W) * y - P(Y)), t)
    _, factors = sympy.sqf_list(res, x, y)
    (_, r), = [(f, e) for f, e in factors if sympy.Poly(f, x, y).total_degree() > 0]
    return r


_coeffs = st.lists(st.integers(-6, 6), min_size=1, max_size=4)


@st.composite
def parametrizations(draw):
    """Power-form ``(x(t), y(t), w(t))``, optionally composed with a degree-2 map (improper)."""
    xs, ys, ws = draw(_coeffs), draw(_coeffs), draw(st.lists(st.integers(1, 6), min_size=1, max_size=3))
    inner = draw(st.sampled_from([t, t, t**2, t**2 + t, t / (t**2 + 1), (t**2 + 2) / (t + 3)]))
    poly = lambda cs: sum(c * inner**k for k, c in enumerate(cs))  # noqa: E731
    num_x, den_x = sympy.fraction(sympy.together(poly(xs) / poly(ws)))
    num_y, den_y = sympy.fraction(sympy.together(poly(ys) / poly(ws)))
    common = sympy.lcm(den_x, den_y)
    return sympy.expand(num_x * sympy.cancel(common / den_x)), sympy.expand(num_y * sympy.cancel(common / den_y)), sympy.expand(common)


@settings(max_examples=40, deadline=None)
@given(parametrizations())
def test_proper_claim_is_never_wrong(polys):
    try:
        curve = curve_from_polynomials(*polys)
        X, Y, W, _ = reduced_components(curve, warn=False)
    except Exception:  # noqa: BLE001 - constant curves, zero Bernstein weights: not this test's subject
        return
    r = _sympy_index(X, Y, W)
    for t0 in (0, 1, -2):
        if proper_at_fiber(X, Y, W, t0):
            assert r == 1


def test_fibre_point_at_infinity_is_not_taken_for_proper():
    """x = s/(s^2+1), y = x^2: phi = s/(s^2+1) has phi(0) = phi(oo) = 0 (index 2).  At t0 = 0
    A = s(s^2+1), B = s^2 have gcd s (degree 1): only the degree condition (both < n = 4)
    stops the wrong claim."""
    X, Y, W = flint.fmpz_poly([0, 1, 0, 1]), flint.fmpz_poly([0, 0, 1]), flint.fmpz_poly([1, 0, 2, 0, 1])
    assert _sympy_index(X, Y, W) == 2
    A, B = X * W(0) - W * X(0), Y * W(0) - W * Y(0)
    assert A.gcd(B).degree() == 1 and max(A.degree(), B.degree()) < 4
    assert not proper_at_fiber(X, Y, W, 0)
    curve = curve_from_polynomials("t*(t**2+1)", "t**2", "(t**2+1)**2")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert implicit_equation(curve).index == 2


def test_proper_cubic_is_decided_and_skips_nothing_of_the_answer():
    """A proper rational cubic: decided proper, and the returned equation equals sympy's
    resultant made primitive (independent)."""
    curve = curve_from_polynomials("t**3 - t", "t**2 + 2", "t**2 + 1")
    X, Y, W, _ = reduced_components(curve, warn=False)
    assert proper_at_fiber(X, Y, W)
    P = lambda p: sum(int(c) * t**k for k, c in enumerate(p.coeffs()))  # noqa: E731
    res = sympy.Poly(sympy.resultant(sympy.expand(P(W) * x - P(X)), sympy.expand(P(W) * y - P(Y)), t), x, y)
    _, prim = res.primitive()
    got = implicit_equation(curve)
    assert got.index == 1
    assert got.poly.as_expr() in (prim.as_expr(), -prim.as_expr())

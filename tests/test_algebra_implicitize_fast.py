"""The fast resultant route of ``implicitize`` (issue 18): the integer power form by one
matrix product, the resultant left in ``Z[x, y, t]`` and projected on demand, the sympy
``Poly`` filled from the grevlex term list without reading monomials.

References, independent of exactcagd's conversions: the Bernstein form expanded by sympy
(``sum c_i C(n,i) t^i (1-t)^(n-i)``), sympy's own ``resultant`` of ``W x - X`` and
``W y - Y`` (normalized here: primitive, positive grevlex leading coefficient), and sympy's
``Poly`` of the same expression (its dense representation, not only equal values).
"""

from __future__ import annotations

import warnings
from fractions import Fraction

import flint
import sympy as sp
from gmpy2 import mpq
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.algebra import ImproperParametrizationWarning, implicit_equation, implicitize
from exactcagd.algebra._poly import XY, curve_power, grevlex_full_poly, mpoly_to_sympy, sympy_to_mpoly, zctx

x, y, t = sp.symbols("x y t")


def _bernstein_components(points, weights):
    """``(X, Y, W)`` of the curve as sympy polynomials in ``t`` (rational coefficients)."""
    n = len(points) - 1
    w = weights or [1] * (n + 1)
    B = [sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]
    W = sp.expand(sum(sp.Rational(w[i]) * B[i] for i in range(n + 1)))
    X = sp.expand(sum(sp.Rational(w[i]) * sp.Rational(points[i][0]) * B[i] for i in range(n + 1)))
    Y = sp.expand(sum(sp.Rational(w[i]) * sp.Rational(points[i][1]) * B[i] for i in range(n + 1)))
    return X, Y, W


def _sympy_implicit(X, Y, W) -> sp.Poly:
    """sympy's resultant ``Res_t(W x - X, W y - Y)``, primitive with positive grevlex leading coefficient."""
    res = sp.Poly(sp.resultant(sp.expand(W * x - X), sp.expand(W * y - Y), t), x, y)
    _, prim = res.clear_denoms(convert=True)[1].primitive()
    return -prim if prim.LC(order="grevlex") < 0 else prim


rationals = st.fractions(min_value=-20, max_value=20, max_denominator=12)


@st.composite
def curves(draw, max_degree=5):
    n = draw(st.integers(1, max_degree))
    pts = draw(st.lists(st.tuples(rationals, rationals), min_size=n + 1, max_size=n + 1))
    w = draw(st.one_of(st.none(), st.lists(st.fractions(min_value=Fraction(1, 5), max_value=9, max_denominator=6), min_size=n + 1, max_size=n + 1)))
    return pts, w


def _mpq_points(pts):
    return [[mpq(c.numerator, c.denominator) for c in p] for p in pts]


@settings(max_examples=60, deadline=None)
@given(curves())
def test_curve_power_is_the_expanded_bernstein_form(data):
    pts, w = data
    curve = BezierCurve(_mpq_points(pts), None if w is None else [mpq(v.numerator, v.denominator) for v in w])
    got = curve_power(curve)
    X, Y, W = _bernstein_components(pts, w)
    ref = [sp.Poly(p, t, domain="QQ") for p in (X, Y, W)]
    # one positive common scale makes the reference integer and jointly primitive
    den = sp.ilcm(*[sp.Rational(c).q for p in ref for c in p.all_coeffs()])
    ints = [[int(c * den) for c in reversed(p.all_coeffs())] for p in ref]
    g = sp.igcd(*[c for p in ints for c in p])
    expected = [flint.fmpz_poly([c // g for c in p]) for p in ints]
    assert list(got) == expected


@settings(max_examples=40, deadline=None)
@given(curves())
def test_resultant_route_equals_sympy_resultant(data):
    pts, w = data
    X, Y, W = _bernstein_components(pts, w)
    assume(sp.diff(sp.cancel(X / W), t) != 0 or sp.diff(sp.cancel(Y / W), t) != 0)  # not a point
    assume(sp.degree(sp.gcd(sp.gcd(X, Y), W), t) <= 0)  # no base points (those are divided out)
    curve = BezierCurve(_mpq_points(pts), None if w is None else [mpq(v.numerator, v.denominator) for v in w])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ImproperParametrizationWarning)
        eq = implicit_equation(curve)
        P = implicitize(curve)
    ref = _sympy_implicit(X, Y, W)
    sqf = sp.sqf_list(ref.as_expr(), x, y)[1]
    (F, r), = [(f, e) for f, e in sqf if sp.Poly(f, x, y).total_degree() > 0]
    F = sp.Poly(F, x, y)
    F = -F if F.LC(order="grevlex") < 0 else F
    assert P == F and P.rep.to_list() == F.rep.to_list() and P.domain == sp.ZZ
    assert eq.index == r and eq.degree == F.total_degree()
    assert eq.mpoly.context() is XY and eq.mpoly == sympy_to_mpoly(F, (x, y), XY)[0]


def test_generic_cubic_and_quartic_against_sympy():
    for pts, w in [([(1, 2), (1, 3), (4, -1), (5, 2)], [1, 2, 3, 1]),
                   ([(Fraction(1, 3), 0), (1, 3), (4, Fraction(-7, 2)), (5, 2), (-2, 9)], [2, 1, Fraction(1, 2), 3, 1])]:
        X, Y, W = _bernstein_components(pts, w)
        curve = BezierCurve(_mpq_points(pts), [mpq(Fraction(v).numerator, Fraction(v).denominator) for v in w])
        eq = implicit_equation(curve)
        ref = _sympy_implicit(X, Y, W)
        assert eq.index == 1 and eq.poly == ref and eq.poly.rep.to_list() == ref.rep.to_list()
        assert len(eq.mpoly) == (eq.degree + 1) * (eq.degree + 2) // 2  # dense: the fast Poly path ran
        assert eq == implicit_equation(curve) and "ImplicitEquation(mpoly=" in repr(eq)


full_triangles = st.integers(0, 7).flatmap(
    lambda d: st.lists(st.integers(-(2**70), 2**70).filter(bool), min_size=(d + 1) * (d + 2) // 2, max_size=(d + 1) * (d + 2) // 2).map(
        lambda cs: {(i, k - i): c for (k, i), c in zip(((k, i) for k in range(d + 1) for i in range(k + 1)), cs)}))


@settings(max_examples=60, deadline=None)
@given(full_triangles)
def test_full_grevlex_poly_equals_sympy_poly(data):
    ref = sp.Poly(sum(c * x**i * y**j for (i, j), c in data.items()), x, y, domain="ZZ")
    got = grevlex_full_poly(XY.from_dict(data), (x, y))
    assert got == ref and got.rep.to_list() == ref.rep.to_list() and got.gens == (x, y)
    assert mpoly_to_sympy(XY.from_dict(data), (x, y)).rep.to_list() == ref.rep.to_list()
    # the same polynomial in (x, y, t) grevlex, free of t (the resultant's ring)
    xyt = zctx(("x", "y", "_t_"), "degrevlex")
    assert grevlex_full_poly(xyt.from_dict({(i, j, 0): c for (i, j), c in data.items()}), (x, y)).rep.to_list() == ref.rep.to_list()


def test_full_grevlex_poly_refuses_a_missing_monomial():
    data = {(i, k - i): 1 + i for k in range(4) for i in range(k + 1)}
    del data[(1, 1)]
    assert grevlex_full_poly(XY.from_dict(data), (x, y)) is None
    ref = sp.Poly(sum(c * x**i * y**j for (i, j), c in data.items()), x, y)
    assert mpoly_to_sympy(XY.from_dict(data), (x, y)).rep.to_list() == ref.rep.to_list()


@settings(max_examples=40, deadline=None)
@given(st.integers(1, 7).flatmap(lambda n: st.tuples(*[st.lists(st.integers(-50, 50), min_size=n + 1, max_size=n + 1) for _ in range(3)])))
def test_bezout_pencil_is_the_notes_bezout_matrix(data):
    """``x A_x + y A_y + C`` equals the notes' Bezout matrix of ``W x - X``, ``W y - Y``
    (``resultants._bezout_rows``, brackets summed entry by entry) at integer points, up to
    its display flip (rows and columns reversed)."""
    from exactcagd.algebra.implicitize import _bezout_pencil
    from exactcagd.algebra.resultants import _bezout_rows

    cx, cy, cw = data
    n = len(cx) - 1
    Ax, Ay, C = _bezout_pencil(flint.fmpz_poly(cx), flint.fmpz_poly(cy), flint.fmpz_poly(cw), n)
    for px, py in [(0, 0), (2, -3), (7, 5)]:
        f = [w * px - a for w, a in zip(cw, cx)]
        g = [w * py - b for w, b in zip(cw, cy)]
        ref = _bezout_rows(f, g, n)
        got = (Ax * px + Ay * py + C).tolist()
        assert [[int(v) for v in row] for row in got] == [[ref[n - 1 - i][n - 1 - j] for j in range(n)] for i in range(n)]


def test_higher_degrees_agree_with_the_moving_line_route():
    import random

    rng = random.Random(7)
    for n in (6, 7, 8):
        pts = [[rng.randint(-40, 40), rng.randint(-40, 40)] for _ in range(n + 1)]
        w = [rng.randint(1, 9) for _ in range(n + 1)]
        curve = BezierCurve(pts, w)
        fast = implicit_equation(curve)
        assert fast.index == 1 and fast.degree == n
        assert fast.poly == implicit_equation(curve, "moving_lines").poly
        assert fast.mpoly == implicit_equation(curve, "moving_lines").mpoly


def test_sparse_equations_with_zero_leading_and_constant_terms():
    """Equations by hand: zero coefficients at the front (x^3 missing) and at the end (no
    constant term) of the grevlex list, and a negative first coefficient to flip."""
    from exactcagd.algebra import curve_from_polynomials

    cases = [(("t", "t**3"), x**3 - y), (("t**3", "t"), y**3 - x), (("-t", "t**3 + 2"), x**3 + y - 2)]
    for (px, py), expected in cases:
        eq = implicit_equation(curve_from_polynomials(px, py))
        assert eq.poly.as_expr() == sp.expand(expected) and eq.index == 1
        assert eq.mpoly == sympy_to_mpoly(sp.expand(expected), (x, y), XY)[0]

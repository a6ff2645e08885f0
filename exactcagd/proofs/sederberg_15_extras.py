"""Ledger: Sederberg's notes chapter 15 beyond the foundation.

15.3 (corner derivatives), 15.4 (tessellation bounds and the worked example), 15.5
(C^n patches), 15.7 (T-splines: the equation, the numerical example, refinement
equations, the matrix M, local refinement, standardness) and 15.9 (curvature at
corners of rational tensor-product and triangular patches, implicit surfaces).
The foundation's worked examples of chapter 15 (surface de Casteljau, normals at
corners, NURBS knot insertion) are in ``sederberg_15_surfaces.py``; 15.8 is checked
with chapter 16 in ``sederberg_16_points_tangents.py``.
"""

from __future__ import annotations

import functools
from fractions import Fraction

import random

import numpy as np
import sympy as sp
from gmpy2 import mpq

from exactcagd.geometry.bezier_curve import BezierCurve
from exactcagd.geometry.bezier_surface import BezierSurface
from exactcagd.geometry.bspline import BSplineSurface
from exactcagd.toolbox import bspline_extras as bx
from exactcagd.toolbox import curvature as cv
from exactcagd.toolbox import surfaces as sf
from exactcagd.toolbox.triangular import TriangularBezier
from exactcagd.toolbox.tsplines import TMesh
from exactcagd.proofs import _ledger as L
from exactcagd.proofs.sederberg_15_nurbs import _ref_point as _cox_de_boor_point, _sympy_continuity_order
from exactcagd.proofs._ledger import claim, erratum, not_checkable, reconstructed, verified, verified_range

U, V, T = sp.symbols("u v t")


def _rng(seed):
    return random.Random(seed)


def _R(x):
    return sp.Rational(int(x.numerator), int(x.denominator))


def _q(rng, lo=-9, hi=9, den=4):
    return mpq(rng.randint(lo, hi), rng.randint(1, den))


def _patch(rng, m, n, rational=True, dim=3):
    net = [[[_q(rng) for _ in range(dim)] for _ in range(n + 1)] for _ in range(m + 1)]
    w = [[mpq(rng.randint(1, 6), rng.randint(1, 3)) for _ in range(n + 1)] for _ in range(m + 1)] if rational else None
    return BezierSurface(net, w)


def _at(expr, point):
    return [sp.Rational(sp.cancel(e).subs({U: point[0], V: point[1]})) for e in expr]


def _poly_form(S):
    """Numerator components and denominator of a (rational) patch as expanded sympy polynomials."""
    l, m = S.degree
    H = S.homogeneous()
    B = lambda n, i, x: sp.binomial(n, i) * x**i * (1 - x) ** (n - i)  # noqa: E731
    comps = [sp.expand(sum(_R(H[i, j, k]) * B(l, i, U) * B(m, j, V) for i in range(l + 1) for j in range(m + 1))) for k in range(H.shape[2])]
    return comps[:-1], comps[-1]


def _derivs(S, point, scale=(1, 1)):
    """Derivatives of r = N/W at ``point`` up to order 2 from N = r W (Leibniz), with sympy polynomials.

    ``scale`` = (1/(s1-s0), 1/(t1-t0)) for a patch over a general domain (chain rule).
    """
    nums, W = _poly_form(S) if isinstance(S, BezierSurface) else S
    at = lambda e: e.subs({U: point[0], V: point[1]})  # noqa: E731
    w, wu, wv, wuu, wuv, wvv = (at(W), at(W.diff(U)), at(W.diff(V)), at(W.diff(U, 2)), at(W.diff(U, V)), at(W.diff(V, 2)))
    out = {k: [] for k in ("P", "Pu", "Pv", "Puu", "Puv", "Pvv")}
    su, sv = (sp.Rational(x) for x in scale)
    for N in nums:
        r = at(N) / w
        ru = (at(N.diff(U)) - r * wu) / w
        rv = (at(N.diff(V)) - r * wv) / w
        ruu = (at(N.diff(U, 2)) - 2 * ru * wu - r * wuu) / w
        ruv = (at(N.diff(U, V)) - ru * wv - rv * wu - r * wuv) / w
        rvv = (at(N.diff(V, 2)) - 2 * rv * wv - r * wvv) / w
        for k, x in zip(out, (r, ru * su, rv * sv, ruu * su * su, ruv * su * sv, rvv * sv * sv)):
            out[k].append(x)
    return out


def _vec(x):
    return [_R(c) for c in x]


# ---------------------------------------------------------------------------- 15.3
@functools.lru_cache(maxsize=None)
def _sympy_basis(kn):
    T = sp.Symbol("T_")
    return sp.bspline_basis(len(kn) - 2, kn, 0, T), T


def _sympy_N(knots, x):
    """B-spline basis function N[knots](x) by sympy's bspline_basis (independent of exactcagd.bspline); degree len - 2.

    (Substituted, not lambdified: the lambdified Piecewise returned 0 for every argument, which made the
    refinement check below vacuous.)
    """
    kn = tuple(sp.Rational(str(k)) for k in knots)
    expr, T_ = _sympy_basis(kn)
    val = sp.sympify(expr.subs(T_, sp.Rational(str(x))))
    return mpq(int(sp.numer(val)), int(sp.denom(val)))


@claim(doc="sederberg", section="15.3", ref="P_s, P_t, P_st", statement="first and mixed partial derivatives at the corner of a rational patch over [s0,s1] x [t0,t1]")
def corner_first_mixed():
    rng = _rng(153)
    s0, s1, t0, t1 = mpq(-1), mpq(2), mpq(1, 2), mpq(3)
    for m, n in ((3, 2), (2, 4), (1, 1)):
        S = _patch(rng, m, n)
        d = sf.corner_derivatives(S, u_range=(s0, s1), v_range=(t0, t1))
        ref = _derivs(S, (0, 0), (1 / _R(s1 - s0), 1 / _R(t1 - t0)))
        for key in ("P", "Pu", "Pv", "Puv"):
            assert _vec(d[key]) == ref[key], (m, n, key)
    return verified("degrees (3,2), (2,4), (1,1) over [-1,2] x [1/2,3] against sympy (N = r W differentiated, chain rule)",
        compared='printed 15.3 corner P, P_s, P_t, P_st vs sympy derivatives of N = rW (Leibniz, chain rule for the domain) of the rational patch',
        reference='sympy')


@claim(doc="sederberg", section="15.3", ref="P_ss, P_tt",
       statement="P_ss(s0,t0) = (n(n-1) w20/w00 (P20 - P00) - 2n w10/w00 (n w10 - w00)/w00 (P10 - P00))/(s1 - s0)^2, P_tt likewise with n")
def corner_second():
    rng = _rng(1532)
    s0, s1, t0, t1 = mpq(-1), mpq(2), mpq(1, 2), mpq(3)
    S = _patch(rng, 3, 2)  # m = 3 in s, n = 2 in t
    d = sf.corner_derivatives(S, u_range=(s0, s1), v_range=(t0, t1))
    ref = _derivs(S, (0, 0), (1 / _R(s1 - s0), 1 / _R(t1 - t0)))
    assert _vec(d["Puu"]) == ref["Puu"] and _vec(d["Pvv"]) == ref["Pvv"]
    P, w = S.net_array(), S.weights_array()

    def pss(k):
        return (k * (k - 1) * w[2, 0] / w[0, 0] * (P[2, 0] - P[0, 0]) - 2 * k * w[1, 0] / w[0, 0] * (k * w[1, 0] - w[0, 0]) / w[0, 0] * (P[1, 0] - P[0, 0])) / (s1 - s0) ** 2

    assert _vec(pss(3)) == _vec(d["Puu"]) and _vec(pss(2)) != _vec(d["Puu"])
    def pss_degree(k):
        return None if _vec(pss(k)) == ref["Puu"] else f"with {k} the printed P_ss = {_vec(pss(k))}, sympy {ref['Puu']}"
    return erratum(
        printed="P_ss uses n (the t-degree): n(n-1) w20/w00 (P20 - P00) - 2n w10/w00 (n w10 - w00)/w00 (P10 - P00)",
        corrected="P_ss uses m (the s-degree, as in P_s = m/(s1-s0) ...); P_tt with n is correct",
        detail="checked on a rational (3, 2) patch against sympy; with n = 2 instead of m = 3 the printed P_ss is wrong",
        printed_form=2, corrected_form=3, check=L.predicate(pss_degree), reference='sympy',
    )


@claim(doc="sederberg", section="15.3", ref="normals", statement="P_s x P_t is normal; elsewhere subdivide to move the point to a corner")
def normals_by_subdivision():
    rng = _rng(1533)
    S = _patch(rng, 2, 3)
    for pt in ((mpq(1, 3), mpq(1, 2)), (mpq(1), mpq(1, 4)), (mpq(3, 4), mpq(1))):
        n = sf.normal_at(S, *pt)
        ref = _derivs(S, [_R(x) for x in pt])
        assert _vec(n) == list(sp.Matrix(ref["Pu"]).cross(sp.Matrix(ref["Pv"])))
    return verified("exact normal at interior and edge points (subdivision to a corner) equals sympy r_u x r_v",
        compared='printed normal P_s x P_t (via subdivision to a corner) vs sympy r_u x r_v of the rational patch at interior and edge points',
        reference='sympy')


# ---------------------------------------------------------------------------- 15.4
@claim(doc="sederberg", section="15.4.1", ref="chord bound",
       statement="max ||r(t) - L(t)|| <= (1/8) max ||r''|| (beta - alpha)^2, max ||r''|| <= n(n-1) max ||P_{i+2} - 2P_{i+1} + P_i||")
def chord_bound():
    rng = _rng(1541)
    for n in (2, 3, 4, 5):
        for _ in range(3):
            c = BezierCurve([[_q(rng), _q(rng), _q(rng)] for _ in range(n + 1)])
            a = mpq(rng.randint(0, 5), 10)
            b = a + mpq(rng.randint(1, 5), 10)
            assert sf.chord_bound_holds(c, a, b)
            # ||r''(t)||^2 <= bound^2 on [0, 1], exactly
            from exactcagd.exact import bernstein as bz

            h2 = bz.derivative(bz.derivative(c.points_array()))
            sq = sum((bz.product(h2[:, k : k + 1], h2[:, k : k + 1]) for k in range(3)), start=np.zeros((2 * n - 3, 1), dtype=object) * mpq(0))
            power = list(bz.to_power(sq[:, 0]))
            bound = sf.curve_second_derivative_bound(c)
            assert sf._nonnegative_on_unit([bound - power[0]] + [-x for x in power[1:]])
            # independent (sympy): the printed M^2 = (n(n-1))^2 max ||P_{i+2} - 2P_{i+1} + P_i||^2 from the control points
            Pm = [sp.Matrix([_R(x) for x in p]) for p in c.control_points]
            M2 = (n * (n - 1)) ** 2 * max((Pm[i + 2] - 2 * Pm[i + 1] + Pm[i]).dot(Pm[i + 2] - 2 * Pm[i + 1] + Pm[i]) for i in range(n - 1))
            assert _R(bound) == M2
            r = sum((sp.binomial(n, i) * T**i * (1 - T) ** (n - i) * Pm[i] for i in range(n + 1)), sp.zeros(3, 1))
            gap = sp.Poly(sp.expand(M2 - r.diff(T, 2).dot(r.diff(T, 2))), T)  # >= 0 on [0, 1]: at the ends and every stationary point
            stationary = [x for x in sp.real_roots(gap.diff(T)) if 0 <= x <= 1] if gap.degree() > 1 else []
            assert all(sp.simplify(gap.as_expr().subs(T, x)) >= 0 for x in [sp.Integer(0), sp.Integer(1)] + stationary)
            ra, rb = r.subs(T, _R(a)), r.subs(T, _R(b))
            for j in range(9):  # the chord bound (1/8) M (b - a)^2 at 9 exact parameters, squared
                x = _R(a) + (_R(b) - _R(a)) * sp.Rational(j, 8)
                d = r.subs(T, x) - (ra + (rb - ra) * sp.Rational(j, 8))
                assert 64 * d.dot(d) <= M2 * (_R(b) - _R(a)) ** 4
    return verified_range("degrees 2..5, random space curves and sub-intervals", "both inequalities decided exactly (polynomial non-negativity on [0, 1])",
        compared="printed M = n(n-1) max ||P_{i+2} - 2P_{i+1} + P_i|| computed from the control points vs sympy ||r''(t)||^2 on [0, 1] (root count) and the chord distance ||r - L||^2 <= (M (b-a)^2 / 8)^2 at 9 exact parameters",
        reference='sympy')


@claim(doc="sederberg", section="15.4.2", ref="Cases 1-3",
       statement="Case 1: delta_t = (sqrt(M2^2 + 8 M3 eps) - M2)/M3; Case 3: delta_t = sqrt(8 eps/(M1 k^2 + 2 M2 k + M3)), k = sqrt(M3/M1) maximizes delta_s delta_t")
def cases():
    M1, M2, M3, eps, k = sp.symbols("M1 M2 M3 epsilon k", positive=True)
    dt = (sp.sqrt(M2**2 + 8 * M3 * eps) - M2) / M3
    assert sp.simplify(2 * M2 * 1 * dt + M3 * dt**2 - 8 * eps) == 0  # delta_s = 1, M1 = 0: equality
    dt3 = sp.sqrt(8 * eps / (M1 * k**2 + 2 * M2 * k + M3))
    assert sp.simplify(M1 * (k * dt3) ** 2 + 2 * M2 * (k * dt3) * dt3 + M3 * dt3**2 - 8 * eps) == 0
    area = 8 * eps * k / (M1 * k**2 + 2 * M2 * k + M3)
    assert sp.simplify(area - k * dt3**2) == 0
    crit = sp.solve(sp.diff(area, k), k)
    assert crit == [sp.sqrt(M3) / sp.sqrt(M1)] or sp.simplify(crit[0] - sp.sqrt(M3 / M1)) == 0
    return verified("symbolically: the three choices meet the inequality with equality; k = sqrt(M3/M1) is the stationary point of delta_s delta_t",
        compared='printed Case 1 / Case 3 step sizes and k = sqrt(M3/M1) vs sympy simplification of the inequality with equality and the stationary point of delta_s delta_t',
        reference='sympy')


@claim(doc="sederberg", section="15.4.2", ref="two triangles",
       statement="L(s,t) consists of the triangles r(alpha,beta) r(zeta,beta) r(alpha,eta) and r(zeta,eta) r(alpha,eta) r(zeta,beta)")
def triangles():
    rng = _rng(1542)
    S = _patch(rng, 3, 3, rational=False)
    R1, R2, R3 = sf.surface_second_derivative_bounds(S)
    al, be, ze, et = mpq(1, 2), mpq(11, 20), mpq(1, 10), mpq(3, 20)  # sub-domain [al, be] x [ze, et]
    h, k = be - al, et - ze
    lo = lambda R: sf.sqrt_bounds(R, 64)[0]  # noqa: E731
    bound_lo = (lo(R1) * h * h + 2 * lo(R2) * h * k + lo(R3) * k * k) / 8
    corner = lambda x, y: np.array(S.evaluate(x, y), dtype=object)  # noqa: E731

    def L_(x, y, c00, c10, c01, c11):
        a, b = (x - al) / h, (y - ze) / k
        if a + b <= 1:
            return c00 + a * (c10 - c00) + b * (c01 - c00)
        return c11 + (1 - a) * (c01 - c11) + (1 - b) * (c10 - c11)

    good = (corner(al, ze), corner(be, ze), corner(al, et), corner(be, et))
    bad = (corner(al, be), corner(ze, be), corner(al, et), corner(ze, et))  # the printed labels read literally
    worst_good, worst_bad = mpq(0), mpq(0)
    for i in range(9):
        for j in range(9):
            x, y = al + h * mpq(i, 8), ze + k * mpq(j, 8)
            p = np.array(S.evaluate(x, y), dtype=object)
            worst_good = max(worst_good, sf.dot(p - L_(x, y, *good), p - L_(x, y, *good)))
            worst_bad = max(worst_bad, sf.dot(p - L_(x, y, *bad), p - L_(x, y, *bad)))
    assert worst_good <= bound_lo**2 and worst_bad > bound_lo**2
    def within_bound(corners):
        worst_ = mpq(0)
        for i in range(9):
            for j in range(9):
                x, y = al + h * mpq(i, 8), ze + k * mpq(j, 8)
                p = np.array(S.evaluate(x, y), dtype=object)
                worst_ = max(worst_, sf.dot(p - L_(x, y, *corners), p - L_(x, y, *corners)))
        return None if worst_ <= bound_lo**2 else f"max |S - L|^2 = {float(worst_):.3g} > bound^2 = {float(bound_lo**2):.3g}"
    return reconstructed(
        printed="r(alpha,beta) r(zeta,beta) r(alpha,eta) and r(zeta,eta) r(alpha,eta) r(zeta,beta)",
        corrected="r(alpha,zeta) r(beta,zeta) r(alpha,eta) and r(beta,eta) r(alpha,eta) r(beta,zeta) (the corners of [alpha,beta] x [zeta,eta])",
        detail="the printed arguments mix the s- and t-interval ends; with the corner triangles the bound (1/8)(M1 h^2 + 2 M2 h k + M3 k^2) "
        "holds on a 9x9 exact sample of a random bicubic (sub-domain 1/20 x 1/20), with the printed labels it fails",
        printed_form=bad, corrected_form=good, check=L.predicate(within_bound), reference='exact',
    )


# the net of the worked example, reconstructed from the printed second hodographs (Figure 15.5 is lost):
# x = i, y = j on a lattice, z as below; P[i][j] with i along s, j along t
_Z = [[-6, -4, 0, 0], [-2, 2, 4, 4], [-2, 2, 4, 0], [-6, -2, 0, 0]]
_PSS = [[-48, 24], [-24, -24], [-36, -24], [-24, -24]]  # printed layout: rows j = 3..0, columns i
_PST = [[0, -36, 36], [-18, 0, 0], [18, 0, 0]]
_PTT = [[-24, -12, -36, -12], [12, -12, -12, -12]]


def _example_surface():
    return BezierSurface([[[i, j, _Z[i][j]] for j in range(4)] for i in range(4)])


@claim(doc="sederberg", section="15.4.2", ref="Example (hodographs)", covers=["(15.6)"],
       statement="z-coordinates of the second hodographs P_ss, P_st, P_tt as printed; M1 = 48, M2 = 36, M3 = 36")
def example_hodographs():
    S = _example_surface()
    Z = np.array(_Z, dtype=object)
    ss = [[6 * (Z[i + 2, j] - 2 * Z[i + 1, j] + Z[i, j]) for i in range(2)] for j in range(3, -1, -1)]
    st = [[9 * (Z[i + 1, j + 1] - Z[i + 1, j] - Z[i, j + 1] + Z[i, j]) for i in range(3)] for j in range(2, -1, -1)]
    tt = [[6 * (Z[i, j + 2] - 2 * Z[i, j + 1] + Z[i, j]) for i in range(4)] for j in range(1, -1, -1)]
    assert ss == _PSS and st == _PST and tt == _PTT
    assert sf.surface_second_derivative_bounds(S) == (48**2, 36**2, 36**2)
    def reproduces_printed_hodographs(z):
        Z_ = np.array(z, dtype=object)
        ss_ = [[6 * (Z_[i + 2, j] - 2 * Z_[i + 1, j] + Z_[i, j]) for i in range(2)] for j in range(3, -1, -1)]
        return None if ss_ == _PSS else "the printed P_ss array is not reproduced"
    return reconstructed(
        printed="control grid of Figure 15.5 (lost)",
        corrected=f"z = {_Z} on the lattice x = i, y = j (unique up to an added bilinear-free affine function)",
        detail="the three printed hodograph arrays are mutually consistent (layout of (15.3): rows are t from top); "
        "this net reproduces all 25 entries exactly and gives M1 = 48, M2 = 36, M3 = 36 as printed",
        printed_form=L.LOST, lost_reason='Figure 15.5 (the control grid) is lost', corrected_form=_Z, check=L.predicate(reproduces_printed_hodographs), reference='exact',
    )


@claim(doc="sederberg", section="15.4.2", ref="Example (sampling numbers)",
       statement="k = sqrt(3)/2, delta_t = 0.0080677, delta_s = .0069861, n_s = 144, n_t = 124 for eps = .001")
def example_sampling():
    S = _example_surface()
    res = sf.surface_sampling_numbers(S, "1/1000")
    k = sp.sqrt(sp.Rational(36, 48))
    assert k == sp.sqrt(3) / 2
    dt = sp.sqrt(sp.Rational(8, 1000) / (48 * k**2 + 2 * 36 * k + 36))
    ds = k * dt
    assert abs(sp.N(dt, 30) - sp.Float("0.0077165", 30)) < 1e-7 and abs(sp.N(ds, 30) - sp.Float("0.0066827", 30)) < 1e-7
    assert (res.n_s, res.n_t) == (150, 130) and res.case == 3 and res.bound_holds
    assert int(sp.ceiling(1 / ds)) == 150 and int(sp.ceiling(1 / dt)) == 130
    def step(dt_):
        ref_ = sp.sqrt(sp.Rational(8, 1000) / (48 * k**2 + 2 * 36 * k + 36))
        return None if abs(sp.N(ref_ - dt_, 30)) < 1e-7 else f"delta_t = sqrt(0.008/(72 + 36 sqrt 3)) = {sp.N(ref_, 8)}, not {dt_}"
    return erratum(
        printed="delta_t = 0.0080677, delta_s = .0069861, n_s = 144, n_t = 124",
        corrected="delta_t = sqrt(0.008/(72 + 36 sqrt 3)) = 0.0077165..., delta_s = 0.0066827..., n_s = 150, n_t = 130",
        detail="48 k^2 + 72 k + 36 = 72 + 36 sqrt(3) = 134.35 with k = sqrt(3)/2; the printed delta_t corresponds to a denominator "
        "of about 122.9. Ceilings certified by exact rational enclosures; the final (150, 130) sampling meets the bound",
        printed_form=sp.Float('0.0080677', 30), corrected_form=sp.Float('0.0077165', 30), check=L.predicate(step),
    )


# ---------------------------------------------------------------------------- 15.5
@claim(doc="sederberg", section="15.5", ref="C^n patches", statement="two tensor-product patches are C^n iff every pair of adjacent control curves is C^n")
def cn_patches():
    rng = _rng(155)
    checked = 0
    for mult in (1, 2, 3):
        ku = [0] * 4 + [1] * mult + [mpq(5, 2)] * 4
        kv = [0, 0, 0, 0, 1, 2, 2, 2, 2]
        nu, nv = len(ku) - 4, len(kv) - 4
        net = [[[i, j, rng.randint(-4, 4)] for j in range(nv)] for i in range(nu)]
        B = BSplineSurface(net, ku, kv)
        P = B.to_bezier_patches()
        (spa, a), (spb, b) = P[(0, 0)], P[(1, 0)]
        ha, hb = spa[0][1] - spa[0][0], spb[0][1] - spb[0][0]
        r1 = sf.patch_continuity_order(a, b, "u", ha, hb)
        r2 = sf.control_curve_continuity_order(a, b, "u", ha, hb)
        assert r1 == r2 >= 3 - mult
        assert _sympy_continuity_order(a, b, ha, hb, "u") == r1  # sympy derivatives across the joint
        checked += 1
    # a pair that is C^1 along some control curves only is C^0 as patches
    a = _patch(rng, 3, 2, rational=False)
    net = a.net_array()
    bnet = net[::-1].copy()
    bnet[0] = net[-1]
    bnet[1] = 2 * net[-1] - net[-2]
    bnet[1, 0] = bnet[1, 0] + np.array([1, 0, 0], dtype=object)
    b = BezierSurface(bnet)
    assert sf.patch_continuity_order(a, b) == sf.control_curve_continuity_order(a, b) == 0
    assert _sympy_continuity_order(a, b, 1, 1, "u") == 0
    return verified_range("bicubic B-spline patches with knot multiplicity 1..3, and a broken pair", "exact cross-boundary order = min over control curves",
        compared="printed C^n criterion (adjacent control curves) vs the continuity order measured in sympy (derivatives of the two patches across the joint, scaled by the spans); exactcagd's two order functions agree",
        reference='sympy')


# ---------------------------------------------------------------------------- 15.7 T-splines
@claim(doc="sederberg", section="15.7.1", ref="rectangular T-mesh", covers=["(15.7)", "(15.8)"], statement="if a T-mesh forms a rectangular grid, the T-spline degenerates to a B-spline surface")
def tmesh_grid():
    rng = _rng(1571)
    ku = [0, 0, 0, 0, 1, 3, 4, 4, 4, 4]
    kv = [0, 0, 0, 0, 2, 3, 5, 5, 5, 5]
    net = [[[i, j, rng.randint(-3, 3)] for j in range(6)] for i in range(6)]
    w = [[rng.randint(1, 3) for _ in range(6)] for _ in range(6)]
    B = BSplineSurface(net, ku, kv, weights=w)
    M = TMesh.from_bspline(net, ku, kv, weights=w)
    for s in (0, mpq(1, 2), 2, 4):
        for t in (0, mpq(5, 2), 5):
            assert M.evaluate(s, t) == B.evaluate(s, t)
            F = lambda x: Fraction(int(mpq(x).numerator), int(mpq(x).denominator))  # noqa: E731
            ref = _cox_de_boor_point([[[F(x) for x in p] for p in row] for row in net], [[F(x) for x in row] for row in w],
                                     [F(x) for x in ku], [F(x) for x in kv], 3, 3, F(s), F(t))
            assert tuple(F(x) for x in M.evaluate(s, t)) == ref
    return verified("Rule-1 blending functions of a full grid = the tensor B-spline basis (NURBS, exact)",
        compared='printed degeneration of a grid T-spline to a B-spline surface vs an independent Cox-de Boor evaluation of the NURBS on Fractions',
        reference='independent-algorithm')


@claim(doc="sederberg", section="15.7.1", ref="Rule 1 examples", statement="knot vectors of P1, P2, P3 in Figure 15.15")
def rule1_figure():
    return not_checkable("Figure 15.15 (the T-mesh pre-image) is lost; Rule 1 is implemented by TMesh.knot_vectors and tested on explicit meshes")


def _trace_n01245():
    """Polar values of the explicit B-spline N[0,1,2,4,5] at 3 (the notes' steps)."""
    s2 = mpq(6)  # any s2 >= 5: f(3,4,5) does not depend on it
    f = {(0, 1, 2): mpq(0), (1, 2, 4): mpq(1), (2, 4, 5): mpq(0), (4, 5, s2): mpq(0)}
    ctrl = np.array([f[(0, 1, 2)], f[(1, 2, 4)], f[(2, 4, 5)], f[(4, 5, s2)]], dtype=object)
    local = [0, 1, 2, 4, 5, s2]  # segment [2, 4]
    out = {}
    out["f(1,2,3)"] = (f[(0, 1, 2)] + 3 * f[(1, 2, 4)]) / 4
    out["f(2,3,4)"] = (2 * f[(1, 2, 4)] + 2 * f[(2, 4, 5)]) / 4
    out["f(3,4,5)"] = ((s2 - 3) * f[(2, 4, 5)] + f[(4, 5, s2)]) / (s2 - 2)
    out["f(2,3,3)"] = (out["f(1,2,3)"] + 2 * out["f(2,3,4)"]) / 3
    out["f(3,3,4)"] = (2 * out["f(2,3,4)"] + out["f(3,4,5)"]) / 3
    out["f(3,3,3)"] = (out["f(2,3,3)"] + out["f(3,3,4)"]) / 2
    # the same polar values straight from the segment's polar form (de Boor levels in any order)
    for label, args in (("f(2,3,4)", [2, 3, 4]), ("f(2,3,3)", [2, 3, 3]), ("f(3,3,4)", [3, 3, 4]), ("f(3,3,3)", [3, 3, 3])):
        assert bx.segment_blossom(ctrl, local, args) == out[label], label
    return out


def _print_trace():
    for k, v in _trace_n01245().items():
        print(f"{k} = {v}")


@claim(doc="sederberg", section="15.7.1", ref="Numerical example", statement="N[0,1,2,4,5](3) = 11/24 via f(1,2,3) = 3/4, f(2,3,4) = 2/4, f(3,4,5) = 0, f(2,3,3) = 7/12, f(3,3,4) = 1/3; N[0,1,3,5,6](4) = 23/60",
       trace=_print_trace)
def tspline_numbers():
    out = _trace_n01245()
    assert [out[k] for k in ("f(1,2,3)", "f(2,3,4)", "f(3,4,5)", "f(2,3,3)", "f(3,3,4)", "f(3,3,3)")] == [mpq(3, 4), mpq(1, 2), 0, mpq(7, 12), mpq(1, 3), mpq(11, 24)]
    assert bx.basis_function([0, 1, 2, 4, 5], 3) == mpq(11, 24) and bx.basis_function([0, 1, 3, 5, 6], 4) == mpq(23, 60)
    assert _sympy_N([0, 1, 2, 4, 5], 3) == mpq(11, 24) and _sympy_N([0, 1, 3, 5, 6], 4) == mpq(23, 60)  # sympy bspline_basis
    return verified("every printed polar value, and both basis values (explicit B-spline = de Boor)",
        compared="printed polar values and N[0,1,2,4,5](3) = 11/24, N[0,1,3,5,6](4) = 23/60 vs the blossom recurrences in exact rationals and sympy's bspline_basis",
        reference='sympy')


@claim(doc="sederberg", section="15.7.1", ref="B_10(3,4)", covers=["(15.9)", "(15.10)", "(15.11)", "(15.13)"], statement="B_10(3,4) = N[0,1,2,5,7](3) N[0,1,3,5,6](4) = 253/1440")
def tspline_b10():
    a = bx.basis_function([0, 1, 2, 5, 7], 3)
    b = bx.basis_function([0, 1, 2, 4, 5], 3)
    c = bx.basis_function([0, 1, 3, 5, 6], 4)
    assert b * c == mpq(253, 1440) and a * c != mpq(253, 1440)
    assert bx.basis_function([-2, -1, 0, 1, 2], 3) == 0  # B_4(3,4) = N[s0,s1,0,1,2](3) * ... = 0 for any phantoms
    def product_value(vec):
        T_ = sp.Symbol("T_")
        n1 = sp.bspline_basis(3, tuple(sp.Integer(v) for v in vec), 0, T_).subs(T_, 3)
        n2 = sp.bspline_basis(3, (0, 1, 3, 5, 6), 0, T_).subs(T_, 4)
        return None if n1 * n2 == sp.Rational(253, 1440) else f"N{list(vec)}(3) N[0,1,3,5,6](4) = {n1 * n2} (sympy bspline_basis)"
    return erratum(
        printed="B_10(3,4) = N[0,1,2,5,7](3) N[0,1,3,5,6](4) = 253/1440",
        corrected=f"N[0,1,2,5,7](3) N[0,1,3,5,6](4) = {a * c}; 253/1440 = N[0,1,2,4,5](3) N[0,1,3,5,6](4) (the vector the worked steps use)",
        detail=f"N[0,1,2,5,7](3) = {a}, N[0,1,2,4,5](3) = 11/24, N[0,1,3,5,6](4) = 23/60; the stated s-knot vector and the one "
        "computed with disagree (Figure 15.17 is lost, so which one the mesh dictates cannot be decided). B_4(3,4) = 0 verified",
        printed_form=(0, 1, 2, 5, 7), corrected_form=(0, 1, 2, 4, 5), check=L.predicate(product_value), reference='sympy',
    )


@claim(doc="sederberg", section="15.7.3", ref="(15.14)-(15.17)", statement="N = c_i N[...] + d_i N[...] for k inserted in each of the four knot spans; unchanged for k <= s0 or k >= s4")
def refinement_equations():
    rng = _rng(1573)
    s = sp.Symbol("s")
    for _ in range(4):
        kv = sorted(set(mpq(rng.randint(0, 24), 2) for _ in range(9)))[:5]
        if len(kv) < 5:
            continue
        for i in range(4):
            k = kv[i] + (kv[i + 1] - kv[i]) * mpq(rng.randint(1, 4), 5)
            (c, left), (d, right) = bx.refine_basis_function(kv, k)
            expected_c = (k - kv[0]) / (kv[3] - kv[0]) if i < 3 else mpq(1)
            expected_d = (kv[4] - k) / (kv[4] - kv[1]) if i > 0 else mpq(1)
            assert (c, d) == (expected_c, expected_d)
            for j in (1, 4, 7, 10):
                x = kv[0] + (kv[4] - kv[0]) * mpq(j, 11)
                assert _sympy_N(kv, x) == _sympy_N([0] * 0 + list(left), x) * c + d * _sympy_N(list(right), x)
                assert _sympy_N(kv, x) > 0  # inside the support: the identity is not 0 = 0
        assert bx.refine_basis_function(kv, kv[0] - 1) == [(1, tuple(kv))]
    return verified_range("random cubic knot vectors, all four positions", "the printed c_i, d_i and the identity, exactly at 4 points per case",
                          compared="printed (15.14)-(15.16) c_i, d_i vs the refinement identity evaluated with sympy's bspline_basis", reference="sympy")


def _tspline_point_sympy(mesh, s, t):
    """(15.7) evaluated from the definition: sum w_i P_i B_i / sum w_i B_i, B_i = N[s_i](s) N[t_i](t) by sympy's
    bspline_basis (the knot vectors s_i, t_i are the mesh's Rule 1 vectors)."""
    num, den = [mpq(0)] * 3, mpq(0)
    for node, p in mesh.points.items():
        sk, tk = mesh.knot_vectors(node)
        b = _sympy_N(sk, s) * _sympy_N(tk, t) * mesh.weight(node)
        den += b
        num = [a + b * x for a, x in zip(num, p)]
    return tuple(x / den for x in num)


def _bspline_point_cox_de_boor(B, s, t):
    """A tensor B-spline (homogeneous net ``B.hom``, knots ``B.S``, ``B.T``) by the Cox-de Boor recursion on Fractions."""
    F = lambda x: Fraction(int(mpq(x).numerator), int(mpq(x).denominator))  # noqa: E731
    H = B.hom
    net = [[[F(H[i][j][k] / H[i][j][-1]) for k in range(3)] for j in range(H.shape[1])] for i in range(H.shape[0])]
    w = [[F(H[i][j][-1]) for j in range(H.shape[1])] for i in range(H.shape[0])]
    p, q = len(B.S) - H.shape[0] - 1, len(B.T) - H.shape[1] - 1
    return _cox_de_boor_point(net, w, [F(x) for x in B.S], [F(x) for x in B.T], p, q, F(s), F(t))


def _tmesh(seed=1574, weights=False):
    """Columns 0..6, rows 0..5; column 3 only between rows 0-1 and 4-5; row 3 only from column 0 to 2."""
    rng = _rng(seed)
    pts, w = {}, {}
    for c in range(7):
        for r in range(6):
            if (c == 3 and r in (2, 3)) or (r == 3 and c > 2):
                continue
            pts[(c, r)] = (c, r, rng.randint(-2, 2))
            w[(c, r)] = rng.randint(1, 3)
    se = [(c, 0, 5) for c in range(7) if c != 3] + [(3, 0, 1), (3, 4, 5)]
    te = [(r, 0, 6) for r in (0, 1, 2, 4, 5)] + [(3, 0, 2)]
    return TMesh(range(7), [0, 1, 2, 3, 5, 6], pts, se, te, w if weights else None)


_INSIDE = [(mpq(5, 2), mpq(5, 2)), (mpq(3), mpq(3)), (mpq(3, 2), mpq(7, 2)), (mpq(13, 4), mpq(7, 4)), (mpq(31, 10), mpq(29, 10))]


@claim(doc="sederberg", section="15.7.4", ref="(15.19)-(15.23)", covers=["(15.18)"], statement="P~_j = sum_i c_i^j P_i maps a T-spline to an equivalent one in a superspace (here: the tensor B-spline space)")
def matrix_m():
    M = _tmesh(weights=True)
    B = M.to_bspline()
    for s, t in _INSIDE:
        assert B.evaluate(s, t) == M.evaluate(s, t)
        direct = _tspline_point_sympy(M, s, t)
        assert tuple(Fraction(int(x.numerator), int(x.denominator)) for x in direct) == _bspline_point_cox_de_boor(B, s, t)
    return verified("rational T-spline with T-junctions; the tensor B-spline with homogeneous points sum c_i^j (w_i P_i, w_i) is identical",
        compared="printed (15.19)-(15.23) map P~ = M P vs two independent evaluations: the T-spline (15.7) from its definition with sympy's bspline_basis (Rule 1 knot vectors from the mesh) and the resulting tensor B-spline by Cox-de Boor on Fractions, at 5 interior points",
        reference='independent-algorithm')


@claim(doc="sederberg", section="15.7.5", ref="Figure 15.20", statement="inserting P2 at (s3, t2) requires one more control point P3 at (s3, t3) and no other")
def local_refinement():
    M = _tmesh(weights=True)
    R = M.refine([(3, 2)])
    assert sorted(set(R.points) - set(M.points)) == [(3, 2), (3, 3)]
    for s, t in _INSIDE:
        assert R.evaluate(s, t) == M.evaluate(s, t)
    full = M.refine([(c, r) for c in range(7) for r in range(6)])
    a, b = full.to_bspline(), M.to_bspline()
    assert len(full.points) == 42 and (a.S, a.T) == (b.S, b.T) and np.all(a.hom == b.hom)
    def new_points(pts_):
        got = sorted(set(M.refine([(3, 2)]).points) - set(M.points))
        return None if got == sorted(pts_) else f"refinement adds {got}"
    return reconstructed(
        printed="Figure 15.20 (T-mesh lost): P2 at (s3, t2) forces P3 at (s3, t3)",
        corrected="mesh rebuilt from the text: column s3 stops below t2 and above t3, row t3 ends in a T-junction at s2",
        detail="the topology phase finds exactly P3 (violation 2 of the blending function centred at P2), the geometry phase "
        "reproduces the surface exactly; refining at every node yields the tensor B-spline of 15.7.6",
        printed_form=L.LOST, lost_reason='Figure 15.20 (the T-mesh) is lost', corrected_form=[(3, 2), (3, 3)], check=L.predicate(new_points), reference='independent-algorithm',
    )


@claim(doc="sederberg", section="15.7.6", ref="standard T-splines", statement="a T-spline is standard iff each row of M_{1,n} sums to 1")
def standard_rows():
    grid = TMesh.full_grid(range(5), range(4), lambda c, r: (c, r, c * r))
    tm = _tmesh()
    refined = tm.refine([(3, 2)])
    for mesh, expect in ((grid, "standard"), (tm, "non-standard"), (refined, "standard")):
        Mx, S, T_ = mesh.refinement_matrix()
        sums = {}
        for row in Mx.values():
            for ab, c in row.items():
                sums[ab] = sums.get(ab, 0) + c
        from exactcagd.toolbox.tsplines import _meets_domain

        rows_one = all(v == 1 for ab, v in sums.items() if _meets_domain(S, ab[0]) and _meets_domain(T_, ab[1]))
        assert rows_one == (expect == "standard") and mesh.classify() == expect
        pt = _INSIDE[0] if mesh is not grid else (mpq(3, 2), mpq(3, 2))
        total = sum(mesh.blending(n, *pt) for n in mesh.points)
        assert (total == 1) == rows_one
        sk_tk = [mesh.knot_vectors(n) for n in mesh.points]
        total_sympy = sum(_sympy_N(sk, pt[0]) * _sympy_N(tk, pt[1]) for sk, tk in sk_tk)  # partition of unity, sympy bspline_basis
        assert total_sympy == total
    return verified("full grid and the refined mesh are standard (row sums 1, sum B_i = 1); the mesh with crossing T-junction extensions is not",
        compared="printed criterion (row sums of exactcagd's refinement matrix M equal 1) vs the partition of unity sum B_i evaluated with sympy's bspline_basis (Rule 1 knot vectors), for a full grid, a refined and a non-standard mesh",
        reference='sympy')


@claim(doc="sederberg", section="15.7.6", ref="Figure 15.21", statement="two semi-standard T-splines")
def semi_standard_figure():
    return not_checkable("Figure 15.21 (the two T-meshes) is lost; TMesh.classify decides standard / semi-standard / non-standard exactly")


# ---------------------------------------------------------------------------- 15.9 curvature
def _curve_curvature_sq_sympy(c):
    """k^2 (and the planar cross product) at t = 0 from N = r W differentiated (sympy polynomials)."""
    n = c.degree
    H = c.homogeneous()
    comps = [sp.expand(sum(_R(H[i, k]) * sp.binomial(n, i) * T**i * (1 - T) ** (n - i) for i in range(n + 1))) for k in range(H.shape[1])]
    W = comps[-1]
    at = lambda e: e.subs(T, 0)  # noqa: E731
    w, w1, w2 = at(W), at(W.diff(T)), at(W.diff(T, 2))
    d1, d2 = [], []
    for N in comps[:-1]:
        r = at(N) / w
        r1 = (at(N.diff(T)) - r * w1) / w
        d1.append(r1)
        d2.append((at(N.diff(T, 2)) - 2 * r1 * w1 - r * w2) / w)
    d1, d2 = sp.Matrix(d1), sp.Matrix(d2)
    if len(d1) == 2:
        cr = d1[0] * d2[1] - d1[1] * d2[0]
        return cr**2 / d1.dot(d1) ** 3, cr
    cr = d1.cross(d2)
    return cr.dot(cr) / d1.dot(d1) ** 3, None


@claim(doc="sederberg", section="15.9", ref="(15.44)", statement="k = (n-1)/n w0 w2/w1^2 h/a^2 at the start of a rational Bézier curve")
def curve_curvature():
    rng = _rng(1590)
    for n in (2, 3, 5):
        for dim in (2, 3):
            c = BezierCurve([[_q(rng) for _ in range(dim)] for _ in range(n + 1)], [mpq(rng.randint(1, 5)) for _ in range(n + 1)])
            k2, cr = _curve_curvature_sq_sympy(c)
            res = cv.curve_start_curvature(c)
            assert _R(res.squared) == k2
            if dim == 2:
                assert res.sign == sp.sign(cr)
    return verified_range("degrees 2, 3, 5, planar (signed) and spatial, random weights", "k^2 against sympy |r' x r''|^2/|r'|^6",
        compared="printed (15.44) k at the start vs sympy |r' x r''|^2/|r'|^6 from N = rW differentiated",
        reference='sympy')


def _curvature_from(d):
    ru, rv = sp.Matrix(d["Pu"]), sp.Matrix(d["Pv"])
    ruu, ruv, rvv = sp.Matrix(d["Puu"]), sp.Matrix(d["Puv"]), sp.Matrix(d["Pvv"])
    N = ru.cross(rv)
    E, F, G = ru.dot(ru), ru.dot(rv), rv.dot(rv)
    L, M, Nn = ruu.dot(N), ruv.dot(N), rvv.dot(N)
    NN = N.dot(N)
    K = (L * Nn - M**2) / (NN * (E * G - F**2))
    X = L * G - 2 * M * F + Nn * E
    return K, X**2 / (4 * NN * (E * G - F**2) ** 2), sp.sign(X)


def _tri_poly_form(tri, n, pts, ws):
    from math import factorial

    comps = [0, 0, 0, 0]
    for (i, j, k), p in pts.items():
        b = factorial(n) // (factorial(i) * factorial(j) * factorial(k)) * U**i * V**j * (1 - U - V) ** k
        w = _R(ws[(i, j, k)])
        comps = [c + b * w * _R(x) for c, x in zip(comps, list(p) + [1])]
    comps = [sp.expand(c) for c in comps]
    return comps[:3], comps[3]


@claim(doc="sederberg", section="15.9.1", ref="(15.54), (15.55)", statement="Gaussian and mean curvature at the corner of a rational tensor-product patch from a, b, h_ij and the weights")
def tensor_corner():
    rng = _rng(1591)
    for m, n in ((3, 2), (2, 2), (1, 3)):
        S = _patch(rng, m, n)
        for corner in ((0, 0), (1, 1)):
            res = cv.corner_curvature(S, corner)
            K, H2, sg = _curvature_from(_derivs(S, corner))
            assert (_R(res.gaussian), _R(res.mean_squared), res.mean_sign) == (K, H2, sg), (m, n, corner)
    return verified("degrees (3,2), (2,2), (1,3), corners (0,0) and (1,1): K exact, H^2 exact and sign(H), against sympy fundamental forms",
        compared='printed (15.54), (15.55) corner curvatures vs sympy first and second fundamental forms of the rational patch',
        reference='sympy')


@claim(doc="sederberg", section="15.9.1", ref="(15.56), (15.57)", statement="K = (h~20 h~02 - h~11^2)/(4 S~^2), H = (h~20 b~^2 - 2 h~11 a~ b~ cos(theta) + h~02 a~^2)/(8 S~^2)")
def tilde_forms():
    rng = _rng(1592)
    S = _patch(rng, 3, 3)
    P, w = S.net_array(), S.weights_array()
    n = m = 3
    a, b = P[1, 0] - P[0, 0], P[0, 1] - P[0, 0]
    N = sf.cross(a, b)
    NN = sf.dot(N, N)
    Hd = lambda i, j: sf.dot(P[i, j] - P[0, 0], N)  # = h_ij |N|  # noqa: E731
    th20 = mpq(n - 1, n) * w[2, 0] / w[0, 0] * Hd(2, 0)  # h~ times |N|
    th02 = mpq(m - 1, m) * w[0, 2] / w[0, 0] * Hd(0, 2)
    th11 = w[1, 1] / w[0, 0] * Hd(1, 1)
    S2 = NN / 4 * (w[1, 0] * w[0, 1] / w[0, 0] ** 2) ** 2  # S~^2
    K = (th20 * th02 - th11**2) / NN / (4 * S2)
    ab_cos = w[1, 0] * w[0, 1] / w[0, 0] ** 2 * sf.dot(a, b)  # a~ b~ cos(theta)
    X = th20 * (w[0, 1] / w[0, 0]) ** 2 * sf.dot(b, b) - 2 * th11 * ab_cos + th02 * (w[1, 0] / w[0, 0]) ** 2 * sf.dot(a, a)
    H2 = X * X / NN / (8 * S2) ** 2
    res = cv.corner_curvature(S)
    assert (K, H2) == (res.gaussian, res.mean_squared)
    K_sym, H2_sym, _ = _curvature_from(_derivs(S, (0, 0)))  # sympy fundamental forms of the patch
    assert (_R(K), _R(H2)) == (K_sym, H2_sym)
    return verified("the tilde forms equal (15.54)-(15.55) exactly (bicubic rational patch)",
        compared='printed (15.56), (15.57) tilde forms computed from the net vs sympy fundamental forms of the patch at the corner',
        reference='sympy')


@claim(doc="sederberg", section="15.9.1", ref="Remark 3", statement="k_{1,2} = K_m +- sqrt(K_m^2 - K_g); du/dv = -(M - kF)/(L - kE) = -(N - kG)/(M - kF)")
def principal():
    E, F, G, L, M, N, k = sp.symbols("E F G L M N k")
    Kg = (L * N - M**2) / (E * G - F**2)
    Km = (L * G - 2 * M * F + N * E) / (2 * (E * G - F**2))
    char = sp.expand((k**2 - 2 * Km * k + Kg) * (E * G - F**2))
    det = sp.expand((L - k * E) * (N - k * G) - (M - k * F) ** 2)
    assert sp.simplify(char - det) == 0  # k principal  <=>  the two direction ratios agree
    rng = _rng(1593)
    S = _patch(rng, 2, 3)
    res = cv.surface_curvature(S, mpq(1, 3), mpq(2, 5))
    k1, k2 = res.principal()
    for kk in (k1, k2):
        lo, hi = kk.interval(mpq(1, 10**30))
        x = (lo + hi) / 2
        assert abs(float(x * x - 2 * float(res.mean) * x + res.gaussian)) < 1e-12
    assert k1 <= k2
    return verified("symbolically: (k^2 - 2 K_m k + K_g)(EG - F^2) = (L - kE)(N - kG) - (M - kF)^2; exact principal curvatures of a patch",
        compared='printed Remark 3 (k_{1,2} and direction ratios) vs the sympy identity (k^2 - 2 K_m k + K_g)(EG - F^2) = (L - kE)(N - kG) - (M - kF)^2',
        reference='sympy')


@claim(doc="sederberg", section="15.9.2", ref="w-bar_11, P-bar_11",
       statement="w11bar = (n-1)/n w_11(n-2) + (w_10(n-1) + w_01(n-1) - w_00n)/n; P11bar likewise; w11bar h11bar = (n-1)/n w_11(n-2) h11")
def triangular_to_tensor():
    rng = _rng(1594)
    for n in (2, 3, 4):
        pts = {(i, j, n - i - j): [_q(rng) for _ in range(3)] for i in range(n + 1) for j in range(n + 1 - i)}
        ws = {key: mpq(rng.randint(1, 5)) for key in pts}
        tri = TriangularBezier(pts, ws)
        hom = tri.tensor_homogeneous()
        wb = hom[..., -1]
        Pb = np.empty(hom.shape[:2] + (3,), dtype=object)
        for i in (0, 1, 2):
            for j in (0, 1, 2):
                if i + j <= 2 and wb[i, j] != 0:
                    Pb[i, j] = hom[i, j, :-1] / wb[i, j]
        W = lambda i, j: ws[(i, j, n - i - j)]  # noqa: E731
        P = lambda i, j: np.array(pts[(i, j, n - i - j)], dtype=object)  # noqa: E731
        for (i, j) in ((0, 0), (1, 0), (0, 1), (2, 0), (0, 2)):
            assert np.all(Pb[i, j] == P(i, j)) and wb[i, j] == W(i, j)
        w11 = mpq(n - 1, n) * W(1, 1) + (W(1, 0) + W(0, 1) - W(0, 0)) / n
        P11 = mpq(n - 1, n) * W(1, 1) / w11 * P(1, 1) + (W(1, 0) * P(1, 0) + W(0, 1) * P(0, 1) - W(0, 0) * P(0, 0)) / (n * w11)
        assert wb[1, 1] == w11 and np.all(Pb[1, 1] == P11)
        N = sf.cross(P(1, 0) - P(0, 0), P(0, 1) - P(0, 0))
        assert w11 * sf.dot(P11 - P(0, 0), N) == mpq(n - 1, n) * W(1, 1) * sf.dot(P(1, 1) - P(0, 0), N)
        u, v = mpq(1, 5), mpq(2, 7)
        from exactcagd.exact import bernstein as bz

        val = bz.de_casteljau(bz.de_casteljau(hom, u), v)
        assert tuple(x / val[-1] for x in val[:-1]) == tri.evaluate(u, v)
        nums, Wt = _tri_poly_form(tri, n, pts, ws)  # the triangular patch written out in sympy
        for u_, v_ in ((mpq(1, 5), mpq(2, 7)), (mpq(1, 2), mpq(1, 3)), (mpq(3, 4), mpq(1, 9))):
            val = bz.de_casteljau(bz.de_casteljau(hom, u_), v_)
            at = {U: _R(u_), V: _R(v_)}
            assert [_R(x / val[-1]) for x in val[:-1]] == [N_.subs(at) / Wt.subs(at) for N_ in nums]
    return verified("n = 2, 3, 4: exact tensor-product form of the triangular patch; also P20bar = P_20(n-2) etc. (used for h20, h02)",
        compared="printed w11bar, P11bar formulas vs exactcagd's tensor form of the triangular patch, which is checked against the triangular patch written out in sympy at 3 parameters",
        reference='sympy')


@claim(doc="sederberg", section="15.9.2", ref="(15.59), (15.60)", statement="Gaussian and mean curvature at the corner of a triangular rational patch")
def triangular_corner():
    rng = _rng(1595)
    for n in (2, 3):
        pts = {(i, j, n - i - j): [_q(rng) for _ in range(3)] for i in range(n + 1) for j in range(n + 1 - i)}
        ws = {key: mpq(rng.randint(1, 5)) for key in pts}
        tri = TriangularBezier(pts, ws)
        res = cv.triangular_corner_curvature(tri)
        K, H2, sg = _curvature_from(_derivs(_tri_poly_form(tri, n, pts, ws), (0, 0)))
        assert (_R(res.gaussian), _R(res.mean_squared), res.mean_sign) == (K, H2, sg)
    def matches_sympy_curvature(gaussian):
        return None if _R(gaussian) == K else f"K = {gaussian}, sympy (from the derivatives of the patch) {K}"
    return reconstructed(
        printed="(15.60) K_m = (n-1)/n w_00n / [w_10^2 w_01^2 / (w_01^2 b^2 w_20 h20 - 2 w_10 w_01 (a.b) w_11 h11 + w_10^2 a^2 w_02 h02)] (fraction bars damaged)",
        corrected="K_m = (n-1)/n w_00n/(w_10^2 w_01^2) (w_01^2 |b|^2 w_20 h20 - 2 w_10 w_01 (a.b) w_11 h11 + w_10^2 |a|^2 w_02 h02)/(2 |a x b|^2)",
        detail="(15.55) with m = n and w11bar h11bar = (n-1)/n w11 h11; (15.59) and the reconstruction agree with sympy for n = 2, 3",
        printed_form=L.LOST, lost_reason='the fraction bars of (15.60) are damaged in the extraction', corrected_form=res.gaussian, check=L.predicate(matches_sympy_curvature), reference='sympy',
    )


@claim(doc="sederberg", section="15.9.3", ref="(15.61), (15.62)", statement="mean and Gaussian curvature of an implicit surface f(x,y,z) = 0")
def implicit():
    fx, fy, fz, fxx, fyy, fzz, fxy, fxz, fyz = sp.symbols("f_x f_y f_z f_xx f_yy f_zz f_xy f_xz f_yz")
    g = sp.Matrix([fx, fy, fz])
    Hm = sp.Matrix([[fxx, fxy, fxz], [fxy, fyy, fyz], [fxz, fyz, fzz]])
    printed_K = (-2 * fx * fy * fxy * fzz + fyy * fxx * fz**2 - 2 * fy * fz * fyz * fxx + fzz * fyy * fx**2 - 2 * fz * fx * fxz * fyy
                 + fxx * fzz * fy**2 - fx**2 * fyz**2 - fy**2 * fxz**2 - fz**2 * fxy**2 + 2 * fx * fy * fxz * fyz
                 + 2 * fy * fz * fxy * fxz + 2 * fx * fz * fxy * fyz)
    printed_H = (fzz * (fy**2 + fx**2) - 2 * fx * fy * fxy + fxx * (fy**2 + fz**2) - 2 * fy * fz * fyz + fyy * (fx**2 + fz**2) - 2 * fz * fx * fxz)
    assert sp.expand(printed_K - (g.T * Hm.adjugate() * g)[0]) == 0
    assert sp.expand(printed_H - (g.dot(g) * Hm.trace() - (g.T * Hm * g)[0])) == 0
    # against the parametric formulas on a graph z = q(x, y): f = q - z, r = (u, v, q(u, v)), r_u x r_v = -grad f
    x, y, z = sp.symbols("x y z")
    q = x**3 / 3 - x * y + 2 * y**2 + x / 2
    f = q - z
    graph = ([U, V, sp.expand(q.subs({x: U, y: V}))], sp.Integer(1))
    for px, py in ((sp.Rational(1, 2), sp.Rational(-1, 3)), (sp.Integer(2), sp.Integer(1))):
        pz = q.subs({x: px, y: py})
        grad, hess = cv.implicit_derivatives(f, [px, py, pz])
        res = cv.implicit_curvature(grad, hess)
        K, H2, sg = _curvature_from(_derivs(graph, (px, py)))
        assert (_R(res.gaussian), _R(res.mean_squared), res.mean_sign) == (K, H2, sg)
    return verified("symbolically K = grad adj(Hess) grad^T/|grad|^4 and H = (|grad|^2 tr Hess - grad Hess grad^T)/(2|grad|^3); "
                    "equal to the parametric curvature of a graph surface with normal -grad f/|grad f|",
        compared='printed (15.61), (15.62) vs sympy expansion of grad adj(Hess) grad^T and |grad|^2 tr Hess - grad Hess grad^T; the implicit curvature vs the sympy parametric curvature of a graph surface',
        reference='sympy')

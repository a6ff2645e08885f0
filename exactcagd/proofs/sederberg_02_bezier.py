"""Sederberg's notes, chapter 2 (Bézier curves): the foundation's part -- 2.1-2.4
(equation, intervals, de Casteljau, elevation), 2.7 (hodograph), 2.8, 2.9, 2.9.1
(rational curves in homogeneous form).  Sections 2.5, 2.6 and 2.9.2-2.15 (end
derivatives, curvature, continuity, circular arcs, reparametrization, explicit
curves, integrals) are in ``sederberg_02_extras.py``.

Each claim computes the value with exactcagd and checks it against an independent
sympy computation of the definition and against the printed value.
"""

from __future__ import annotations

import sympy as sp
from gmpy2 import mpq

from exactcagd import BezierCurve
from exactcagd.exact import bernstein as bz
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified, verified_range
from exactcagd.proofs._sederberg_common import (
    Q,
    Rs,
    curve_exprs,
    identity_coefficients,
    matrix_str,
    rand_points,
    rand_pos,
    rng,
    s_,
    same_rational_function,
    t_,
)

DOC = "sederberg"


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


# ---------------------------------------------------------------- 2.1
@claim(DOC, "2.1", "(2.1)", "(1-t)^3 + 3t(1-t)^2 + 3t^2(1-t) + t^3 = [(1-t)+t]^3 = 1")
def cubic_partition_of_unity():
    power = bz.to_power(bz.as_coefficients([1, 1, 1, 1]))
    assert list(power) == [1, 0, 0, 0]
    assert sp.expand((1 - t_) ** 3 + 3 * t_ * (1 - t_) ** 2 + 3 * t_**2 * (1 - t_) + t_**3) == 1
    for n in range(0, 9):
        assert sp.expand(sum(sp.binomial(n, i) * (1 - t_) ** (n - i) * t_**i for i in range(n + 1))) == 1
        assert list(bz.to_power(bz.as_coefficients([1] * (n + 1)))) == [1] + [0] * n
    return verified_range("degrees 0..8", "sympy expands sum_i C(n,i) (1-t)^(n-i) t^i to 1; Bernstein coefficients all 1 convert to the power form 1 (exactcagd to_power); sympy expands the printed cubic sum to 1",
        compared="printed (2.1) vs sympy expansion of the cubic sum (and of sum_i C(n,i) (1-t)^(n-i) t^i for n <= 8) to 1; exactcagd's to_power of all-ones Bernstein coefficients agrees",
        reference='sympy',
    )


@claim(DOC, "2.1", "(2.2)", "P(t) = sum_i C(n,i) (1-t)^(n-i) t^i P_i")
def bezier_equation():
    r = rng(21)
    for n in range(0, 6):
        pts = rand_points(r, n + 1, 3)
        c = BezierCurve(pts)
        ref = [sp.expand(sum(sp.binomial(n, i) * (1 - t_) ** (n - i) * t_**i * Rs(pts[i][k]) for i in range(n + 1))) for k in range(3)]
        for tq in [mpq(0), mpq(1, 3), mpq(5, 7), mpq(1)]:
            assert tuple(Rs(x) for x in c.evaluate(tq)) == tuple(e.subs(t_, Rs(tq)) for e in ref)
    return verified_range("degrees 0..5, 3-D random rational points", "de Casteljau evaluation == the printed sum evaluated by sympy",
        compared="printed (2.2) sum evaluated by sympy vs exactcagd's de Casteljau evaluation at 4 exact parameters, degrees 0..5",
        reference='sympy',
    )


# ---------------------------------------------------------------- 2.2
@claim(DOC, "2.2", "(2.3)", "P_[t0,t1](t) = sum C(n,i) (t1-t)^(n-i) (t-t0)^i P_i / (t1-t0)^n")
def arbitrary_interval():
    r = rng(22)
    pts = rand_points(r, 4, 2)
    t0, t1 = mpq(-3, 2), mpq(5, 3)
    c = BezierCurve(pts)
    T0, T1 = Rs(t0), Rs(t1)
    left = [sum(sp.binomial(3, i) * (T1 - t_) ** (3 - i) * (t_ - T0) ** i * Rs(pts[i][k]) for i in range(4)) / (T1 - T0) ** 3 for k in range(2)]
    right = [sum(sp.binomial(3, i) * ((T1 - t_) / (T1 - T0)) ** (3 - i) * ((t_ - T0) / (T1 - T0)) ** i * Rs(pts[i][k]) for i in range(4)) for k in range(2)]
    for a, b in zip(left, right):
        assert sp.expand(a - b) == 0
    for tq in [t0, t1, mpq(0), mpq(1, 2), mpq(3, 2)]:
        expected = tuple(e.subs(t_, Rs(tq)) for e in left)
        assert tuple(Rs(x) for x in c.evaluate((tq - t0) / (t1 - t0))) == expected
    return verified("both printed forms agree (sympy) and equal the [0,1] curve at (t - t0)/(t1 - t0) (exactcagd)",
        compared='printed (2.3) vs its [0,1]-normalised form expanded by sympy, and vs the [0,1] curve (exactcagd) at (t - t0)/(t1 - t0), 5 exact parameters',
        reference='sympy',
    )


# ---------------------------------------------------------------- 2.3
@claim(DOC, "2.3", "(2.4)", "P_i^j = (1-tau) P_i^(j-1) + tau P_(i+1)^(j-1), tau = (t1-t0)/(t2-t0): "
       "left points P_0^0..P_0^n, right points P_0^n, P_1^(n-1), ..., P_n^0; P(t1) = P_0^n, tangent P_1^(n-1) - P_0^(n-1)")
def de_casteljau_subdivision():
    r = rng(23)
    for n in range(1, 6):
        pts = rand_points(r, n + 1, 2)
        t0, t1, t2 = mpq(2), mpq(13, 5), mpq(5)
        tau = (t1 - t0) / (t2 - t0)
        c = BezierCurve(pts)
        left, right = c.subdivide(tau)
        # the printed recurrence (2.4), written out here (exact rationals)
        levels = [[[mpq(x) for x in p] for p in pts]]
        while len(levels[-1]) > 1:
            prev = levels[-1]
            levels.append([[(1 - tau) * a + tau * b_ for a, b_ in zip(p, q)] for p, q in zip(prev, prev[1:])])
        assert left.control_points == tuple(tuple(lv[0]) for lv in levels)
        assert right.control_points == tuple(tuple(lv[-1]) for lv in reversed(levels))
        assert c.evaluate(tau) == tuple(levels[-1][0])
        if n > 3:
            continue  # the sympy cross-check below on degrees 1..3 (speed)
        ref = curve_exprs(pts)  # P on [0,1]; P_[t0,t2](t) = ref((t - t0)/(t2 - t0))
        T0, T1, T2 = Rs(t0), Rs(t1), Rs(t2)
        # P_[t0,t1] over its own interval, reparametrized by s in [0,1]
        for piece, (a, b) in ((left, (T0, T1)), (right, (T1, T2))):
            expect = [e.subs(t_, ((a + s_ * (b - a)) - T0) / (T2 - T0)) for e in ref]
            assert all(same_rational_function(x, y) for x, y in zip(curve_exprs(piece.control_points, None, s_), expect))
        # tangent: P'(t1) = n/(t2 - t0) (P_1^(n-1) - P_0^(n-1)) -- the printed difference is the direction
        diff = [b_ - a for a, b_ in zip(levels[-2][0], levels[-2][1])]
        deriv = [sp.diff(e, t_).subs(t_, Rs(tau)) / (T2 - T0) for e in ref]
        assert deriv == [Rs(x) * n / (T2 - T0) for x in diff]
    return verified_range(
        "degrees 1..5 (sympy cross-check on 1..3), [t0,t1,t2] = [2, 13/5, 5]",
        "exactcagd subdivision == levels of the printed recurrence == sympy substitution; the printed tangent "
        "P_1^(n-1) - P_0^(n-1) is the tangent direction, the derivative is n/(t2 - t0) times it",
        compared="printed recurrence (2.4), written out in the row (exact rationals), vs exactcagd's subdivide (left/right points, P(t1)); for degrees 1..3 both pieces vs sympy substitution of the reparametrized curve, and the printed tangent difference vs sympy's derivative",
        reference='sympy',
    )


@claim(DOC, "2.3", "Fig. 2.8", "de Casteljau works for tau outside [0,1] (quadratic subdivided at tau = 2)")
def de_casteljau_extrapolation():
    pts = [[0, 0], [1, 2], [3, 1]]
    c = BezierCurve(pts)
    left, right = bz.subdivide(c.points_array(), 2)
    ref = curve_exprs(pts)
    assert all(same_rational_function(x, y) for x, y in zip(curve_exprs(left.tolist(), None, s_), [e.subs(t_, 2 * s_) for e in ref]))
    assert all(same_rational_function(x, y) for x, y in zip(curve_exprs(right.tolist(), None, s_), [e.subs(t_, 2 - s_) for e in ref]))
    assert BezierCurve._trusted(left, None) == c.reparametrize(0, 2)
    return verified("left piece = P over [0,2], right piece = P over [2,1] (reversed), both exact; class API: reparametrize(0, 2)",
        compared='Fig. 2.8 subdivision at tau = 2 vs sympy substitution t = 2s (left) and t = 2 - s (right) of the quadratic',
        reference='sympy',
    )


# ---------------------------------------------------------------- 2.4
@claim(DOC, "2.4", "(2.5), (2.6)", "(1-t) B_i^n = (n+1-i)/(n+1) B_i^(n+1);  t B_i^n = (i+1)/(n+1) B_(i+1)^(n+1)")
def elevation_identities():
    for n in range(0, 8):
        for i in range(n + 1):
            e = bz.as_coefficients([int(j == i) for j in range(n + 1)])
            one_minus_t = bz.product(bz.as_coefficients([1, 0]), e)
            times_t = bz.product(bz.as_coefficients([0, 1]), e)
            assert list(one_minus_t) == [mpq(n + 1 - i, n + 1) if j == i else 0 for j in range(n + 2)]
            assert list(times_t) == [mpq(i + 1, n + 1) if j == i + 1 else 0 for j in range(n + 2)]
            Bn = sp.binomial(n, i) * t_**i * (1 - t_) ** (n - i)
            B1 = lambda k: sp.binomial(n + 1, k) * t_**k * (1 - t_) ** (n + 1 - k)  # noqa: E731
            assert sp.expand((1 - t_) * Bn - sp.Rational(n + 1 - i, n + 1) * B1(i)) == 0
            assert sp.expand(t_ * Bn - sp.Rational(i + 1, n + 1) * B1(i + 1)) == 0
    return verified_range("n = 0..7, all i", "exact Bernstein products (exactcagd) and sympy expansion",
        compared="printed (2.5), (2.6) vs sympy expansion of (1-t) B_i^n, t B_i^n, n <= 7; exactcagd's Bernstein product agrees",
        reference='sympy',
    )


@claim(DOC, "2.4", "(2.7)", "P(t) = sum P_i [(1+t) B_i^n(t) + t B_i^n(t)]  (third line of the derivation)")
def elevation_derivation_sign():
    # the line must read (1-t) B_i^n + t B_i^n; with (1+t) it is not an identity
    n, i = 3, 1
    Bn = sp.binomial(n, i) * t_**i * (1 - t_) ** (n - i)
    assert sp.expand((1 - t_) * Bn + t_ * Bn - Bn) == 0
    assert sp.expand((1 + t_) * Bn + t_ * Bn - Bn) != 0
    r = rng(24)
    pts = rand_points(r, 4, 2)
    c = BezierCurve(pts)
    assert c.elevate(1).same_curve(c)
    Bn_ = sp.binomial(n, i) * t_**i * (1 - t_) ** (n - i)
    return erratum(
        printed="(1+t) B_i^n(t) + t B_i^n(t)",
        corrected="(1-t) B_i^n(t) + t B_i^n(t)",
        detail="[(1-t)+t] = 1 is the factor multiplied in; (1+t)B + tB != B (sympy); the final formula (2.8) is right",
        printed_form=(1 + t_) * Bn_ + t_ * Bn_, corrected_form=(1 - t_) * Bn_ + t_ * Bn_, check=L.same_expr(Bn_),
    )


@claim(DOC, "2.4", "(2.8)", "P*_i = alpha_i P_(i-1) + (1 - alpha_i) P_i, alpha_i = i/(n+1); n = 3 example "
       "P*_0 = P0, P*_1 = 1/4 P0 + 3/4 P1, P*_2 = 2/4 P1 + 2/4 P2, P*_3 = 3/4 P2 + 1/4 P3, P*_4 = P3")
def elevation_formula_and_cubic_example():
    for n in range(0, 8):
        m = bz.elevate(identity_coefficients(n + 1), 1)  # rows: new points in terms of old ones
        P = sp.symbols(f"P0:{n + 1}")
        elevated = []
        for i in range(n + 2):
            alpha = mpq(i, n + 1)
            row = [0] * (n + 1)
            if i >= 1:
                row[i - 1] += alpha
            if i <= n:
                row[i] += 1 - alpha
            elevated.append(sum(Rs(c_) * P[k] for k, c_ in enumerate(row)))
            assert list(m[i]) == row
        # independent reference: the printed P*_i give the same polynomial (sympy, symbolic points)
        assert sp.expand(sum(elevated[i] * sp.binomial(n + 1, i) * t_**i * (1 - t_) ** (n + 1 - i) for i in range(n + 2))
                         - sum(P[i] * sp.binomial(n, i) * t_**i * (1 - t_) ** (n - i) for i in range(n + 1))) == 0
    printed = [[1, 0, 0, 0], ["1/4", "3/4", 0, 0], [0, "2/4", "2/4", 0], [0, 0, "3/4", "1/4"], [0, 0, 0, 1]]
    m3 = bz.elevate(identity_coefficients(4), 1)
    assert [[Q(x) for x in row] for row in printed] == [list(row) for row in m3]
    r = rng(25)
    pts = rand_points(r, 4, 2)
    assert all(same_rational_function(a, b) for a, b in zip(curve_exprs(BezierCurve(pts).elevate(1).control_points), curve_exprs(pts)))
    return verified_range("n = 0..7 (coefficient matrices) and the printed n = 3 table", f"exactcagd elevation matrix for n = 3: {matrix_str(m3)}",
        compared="printed (2.8) alpha_i rule and the n = 3 table vs sympy: the printed P*_i in B^(n+1) expand to the degree-n polynomial with symbolic P_i, n <= 7; exactcagd's elevation matrix equals the printed rows and table",
        reference='sympy',
    )


# ---------------------------------------------------------------- 2.7
@claim(DOC, "2.7", "hodograph", "D_i = n/(t1 - t0) (P_(i+1) - P_i); cusp where the hodograph passes through the origin")
def hodograph():
    r = rng(27)
    for n in range(1, 7):
        pts = rand_points(r, n + 1, 3)
        c = BezierCurve(pts)
        d = c.derivative()
        assert d.control_points == tuple(tuple(n * (b - a) for a, b in zip(p, q)) for p, q in zip(c.control_points, c.control_points[1:]))
        assert n > 4 or all(same_rational_function(x, sp.diff(y, t_)) for x, y in zip(curve_exprs(d.control_points), curve_exprs(pts)))
    # over [t0, t1]: chain rule, d/dt P((t - t0)/(t1 - t0)) = D(.)/(t1 - t0)
    t0, t1 = mpq(1, 2), mpq(7, 3)
    pts = rand_points(r, 4, 2)
    ref = [e.subs(t_, (t_ - Rs(t0)) / (Rs(t1) - Rs(t0))) for e in curve_exprs(pts)]
    hod = [[3 / (t1 - t0) * (b - a) for a, b in zip(p, q)] for p, q in zip(BezierCurve(pts).control_points, BezierCurve(pts).control_points[1:])]
    hod_ref = [e.subs(t_, (t_ - Rs(t0)) / (Rs(t1) - Rs(t0))) for e in curve_exprs(hod)]
    assert all(same_rational_function(sp.diff(a, t_), b) for a, b in zip(ref, hod_ref))
    # the cusp example: hodograph of (0,0),(1,1),(0,1),(1,0) vanishes at t = 1/2
    cusp = BezierCurve([[0, 0], [1, 1], [0, 1], [1, 0]])
    assert cusp.derivative().evaluate("1/2") == (0, 0)
    return verified_range("degrees 1..6, 3-D; interval [1/2, 7/3]", "exactcagd hodograph == sympy diff; a cusp example (0,0),(1,1),(0,1),(1,0) has P'(1/2) = 0",
        compared="printed D_i = n/(t1 - t0)(P_(i+1) - P_i) vs sympy diff of the curve (degrees 1..4 and an interval [1/2, 7/3]); exactcagd's derivative() control points equal the printed ones; cusp example P'(1/2) = 0",
        reference='sympy',
    )


# ---------------------------------------------------------------- 2.8
@claim(DOC, "2.8", "planarity", "every degree two curve is planar")
def quadratics_are_planar():
    r = rng(28)
    for _ in range(5):
        pts = rand_points(r, 3, 3)
        c = BezierCurve(pts)
        a = [x - y for x, y in zip(c.control_points[1], c.control_points[0])]
        b = [x - y for x, y in zip(c.control_points[2], c.control_points[0])]
        normal = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
        for k in range(11):
            p = [x - y for x, y in zip(c.evaluate(mpq(k, 10)), c.control_points[0])]
            assert _dot(p, normal) == 0
        x = [e for e in curve_exprs(pts)]
        assert sp.expand(sum(Rs(nk) * (xk - Rs(pts[0][k])) for k, (nk, xk) in enumerate(zip(normal, x)))) == 0
    return verified_range("5 random 3-D quadratics", "the curve lies in the plane of its control points (exact and sympy)",
        compared='printed planarity claim vs sympy: (P(t) - P0).n expands to 0 with n = (P1 - P0) x (P2 - P0) (exact dot products at 11 parameters too)',
        reference='sympy',
    )


# ---------------------------------------------------------------- 2.9
@claim(DOC, "2.9", "homogeneous form", "the rational curve is the projection x = X/Z, y = Y/Z of the polynomial curve with control points (w x, w y, w)")
def rational_as_projection():
    r = rng(29)
    pts, w = rand_points(r, 4, 2), [rand_pos(r) for _ in range(4)]
    c = BezierCurve(pts, w)
    hom = BezierCurve(c.homogeneous().tolist())
    for k in range(11):
        tq = mpq(k, 10)
        X, Y, Z = hom.evaluate(tq)
        assert c.evaluate(tq) == (X / Z, Y / Z)
    ref = [sp.expand(sum(Rs(w[i]) * Rs(pts[i][k]) * sp.binomial(3, i) * t_**i * (1 - t_) ** (3 - i) for i in range(4))) for k in range(2)]
    den = sp.expand(sum(Rs(w[i]) * sp.binomial(3, i) * t_**i * (1 - t_) ** (3 - i) for i in range(4)))
    assert all(same_rational_function(a, b / den) for a, b in zip(c.to_sympy(t_), ref))
    return verified("exact at 11 parameters; to_sympy equals the printed quotient",
        compared='printed homogeneous form vs sympy quotient sum w_i P_i B_i / sum w_i B_i; projection X/Z, Y/Z of the homogeneous polynomial curve at 11 exact parameters',
        reference='sympy',
    )


@claim(DOC, "2.9.1", "rational de Casteljau / elevation", "de Casteljau and degree elevation act on the homogeneous (3-D) curve; Z gives the weights")
def rational_subdivision_and_elevation():
    r = rng(291)
    pts, w = rand_points(r, 4, 2), [rand_pos(r) for _ in range(4)]
    c = BezierCurve(pts, w)
    ref = curve_exprs(pts, w)
    tau = mpq(2, 7)
    left, right = c.subdivide(tau)
    assert all(same_rational_function(a, b.subs(t_, Rs(tau) * s_)) for a, b in zip(curve_exprs(left.control_points, left.weights, s_), ref))
    assert all(same_rational_function(a, b.subs(t_, Rs(tau) + (1 - Rs(tau)) * s_)) for a, b in zip(curve_exprs(right.control_points, right.weights, s_), ref))
    e = c.elevate(2)
    assert all(same_rational_function(a, b) for a, b in zip(curve_exprs(e.control_points, e.weights), ref))
    # the weights are the Z coordinates of the subdivided homogeneous curve
    hom_left, _ = bz.subdivide(c.homogeneous(), tau)
    assert left.weights == tuple(hom_left[:, -1])
    return verified("subdivision at 2/7 and elevation by 2 of a rational cubic == sympy substitution",
        compared='2.9.1 claim vs sympy substitution: the pieces of the rational cubic at 2/7 and its elevation by 2 equal the original rational function reparametrized',
        reference='sympy',
    )


# ---------------------------------------------------------------- 2.15

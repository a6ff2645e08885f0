"""Ledger: Sederberg's notes, chapter 2 beyond the foundation: 2.5 convex hull, 2.6 distance,
2.9.2-2.9.3 rational end derivatives and curvature, 2.10 continuity, 2.11 circular arcs,
2.12 reparametrization, 2.13 perspective, 2.14 explicit curves, 2.15 integrals.

(de Casteljau, subdivision, elevation and hodographs are in ``sederberg_02_bezier.py``.)
"""

from __future__ import annotations

import random
from fractions import Fraction

import sympy as sp
from gmpy2 import mpq

from exactcagd import BezierCurve
from exactcagd.exact import bernstein as bz
from exactcagd.toolbox import bezier_extras as bx
from exactcagd.proofs._ledger import claim, verified, verified_range

t, u, s = sp.symbols("t u s")


def _B(n, i, x=t):
    return sp.binomial(n, i) * x**i * (1 - x) ** (n - i)


def _R(x):
    return x.to_sympy() if hasattr(x, "to_sympy") else sp.Rational(int(x.numerator), int(x.denominator))


def _sym_rational(n, dim=2):
    w = sp.symbols(f"w0:{n + 1}", positive=True)
    P = [sp.Matrix(sp.symbols(f"x{i} y{i}" if dim == 2 else f"x{i} y{i} z{i}")) for i in range(n + 1)]
    W = sum(w[i] * _B(n, i) for i in range(n + 1))
    N = sp.zeros(dim, 1)
    for i in range(n + 1):
        N += w[i] * _B(n, i) * P[i]
    return w, P, N / W


def _random_curve(rng, degree, rational=True, dim=2):
    pts = [[Fraction(rng.randint(-9, 9), rng.randint(1, 4)) for _ in range(dim)] for _ in range(degree + 1)]
    w = [Fraction(rng.randint(1, 9), rng.randint(1, 4)) for _ in range(degree + 1)] if rational else None
    return BezierCurve(pts, w)


def _convex_combination(c, tq) -> bool:
    """Independent certificate: P(t) = sum lambda_i P_i with lambda_i = w_i B_i(t) / sum w_j B_j(t) >= 0, sum 1 (exact)."""
    n = c.degree
    w = [Fraction(1)] * (n + 1) if c.weights is None else [Fraction(str(x)) for x in c.weights]
    basis = [w[i] * Fraction(int(sp.binomial(n, i))) * tq**i * (1 - tq) ** (n - i) for i in range(n + 1)]
    lam = [x / sum(basis) for x in basis]
    point = [sum(lam[i] * Fraction(str(p[k])) for i, p in enumerate(c.control_points)) for k in range(len(c.control_points[0]))]
    return all(x >= 0 for x in lam) and sum(lam) == 1 and point == [Fraction(str(x)) for x in c.evaluate(tq)]


@claim(doc="sederberg", section="2.5", ref="convex hull property", statement="Bézier curves always lie within the convex hull of their control points")
def convex_hull_property():
    rng = random.Random(25)
    n_points = 0
    for _ in range(40):
        c = _random_curve(rng, rng.randint(1, 5), rational=rng.random() < 0.5)
        assert all(v <= 0 for v in bx.hull_edge_values(c))
        for k in range(5):
            assert _convex_combination(c, Fraction(k, 4))
            assert bx.in_convex_hull(c.evaluate(Fraction(k, 4)), c.control_points)
            n_points += 1
    c3 = _random_curve(rng, 3, dim=3)
    assert all(_convex_combination(c3, Fraction(k, 7)) for k in range(8))
    assert all(bx.in_convex_hull(c3.evaluate(Fraction(k, 7)), c3.control_points) for k in range(8))
    # negative weights break it (notes 2.12): the complementary quarter-circle leaves the hull
    rest = bx.mobius_reparametrize(BezierCurve([[1, 0], [1, 1], [0, 1]], [1, 1, 2]), -1)
    # the hull of (1,0), (1,1), (0,1) lies in x >= 0; the curve point at u = 1/2, from the printed weights (1, -1, 2), has x = -1
    half = [sp.Rational(1, 4), sp.Rational(1, 2), sp.Rational(1, 4)]
    wts = [1, -1, 2]
    x_half = sum(wt * bb * px for wt, bb, px in zip(wts, half, (1, 1, 0))) / sum(wt * bb for wt, bb in zip(wts, half))
    assert x_half == -1 and rest.evaluate("1/2")[0] == -1
    assert not bx.in_convex_hull(rest.evaluate("1/2"), rest.control_points)
    return verified_range("40 random planar curves (degree 1-5, half rational, positive weights) + one space cubic",
                          f"edge certificate max f(P_i) <= 0 for every hull edge; {n_points} exact curve points inside; a negative-weight curve leaves its hull",
        compared="printed convex-hull property vs an exact certificate from the definition: P(t) = sum lambda_i P_i with lambda_i = w_i B_i(t) / sum w_j B_j(t) >= 0 summing to 1 (Fractions), at 5 parameters of 40 random curves and 8 of a space cubic; the negative-weight curve's point x = -1 (printed weights, exact) lies outside the hull's half-plane x >= 0; exactcagd's hull tests agree",
        reference='exact',
    )


@claim(doc="sederberg", section="2.6", ref="difference curve", statement="|P(t) - Q(t)| <= max_i |P_i - Q_i| (convex hull of the difference curve)")
def difference_curve_bound():
    rng = random.Random(26)
    for _ in range(15):
        n = rng.randint(1, 4)
        p, q = _random_curve(rng, n, False), _random_curve(rng, rng.randint(1, n), False)
        mx, _ = bx.max_distance_squared(p, q)
        bound = bx.distance_bound_squared(p, q)
        assert mx <= bound
        # independent: elevate Q to P's degree by (2.8) written out here, D_i = P_i - Q*_i, and sample |P - Q|^2 exactly
        qs = [[Fraction(str(x)) for x in pt] for pt in q.control_points]
        while len(qs) < n + 1:
            m_ = len(qs) - 1
            qs = [[Fraction(i, m_ + 1) * (qs[i - 1][k] if i else 0) + (1 - Fraction(i, m_ + 1)) * (qs[i][k] if i <= m_ else 0)
                   for k in range(2)] for i in range(m_ + 2)]
        D = [[Fraction(str(a)) - b_ for a, b_ in zip(pt, qq)] for pt, qq in zip(p.control_points, qs)]
        my_bound = max(d[0] ** 2 + d[1] ** 2 for d in D)
        assert my_bound == Fraction(str(bound))
        for k in range(41):
            tq = Fraction(k, 40)
            diff = [Fraction(str(a)) - Fraction(str(b_)) for a, b_ in zip(p.evaluate(tq), q.evaluate(tq))]
            assert diff[0] ** 2 + diff[1] ** 2 <= my_bound
    # the notes' motivation: a cubic that is a degree-elevated quadratic has distance 0 from it
    quad = BezierCurve([[0, 0], [1, 2], [3, 1]])
    assert bx.distance_bound_squared(quad.elevate(1), quad) == 0
    return verified_range("15 random pairs of planar polynomial curves (degree <= 4)",
                          "exact max_t |P - Q|^2 (RealAlgebraic) <= max |D_i|^2",
        compared="printed bound |P(t) - Q(t)| <= max |D_i| vs exact arithmetic: Q elevated to P's degree by (2.8) written out in the row, D_i = P_i - Q*_i, and |P(t) - Q(t)|^2 at 41 exact parameters below max |D_i|^2; exactcagd's bound equals it and its exact maximum (RealAlgebraic) stays below",
        reference='exact',
    )


def _derivatives_at_0(c):
    """First and second derivatives at t = 0 of the exact planar curve N_k / W: quotient rule on sympy polynomials."""
    n = c.degree
    w = [_R(x) for x in c.weights_array()]
    P = [[_R(x) for x in pt] for pt in c.control_points]
    Wp = sp.Poly(sum(w[i] * _B(n, i) for i in range(n + 1)), t)
    W0, W1, W2 = (Wp.diff((t, k)).eval(0) if k else Wp.eval(0) for k in range(3))
    d1, d2 = [], []
    for k in range(2):
        Np = sp.Poly(sum(w[i] * P[i][k] * _B(n, i) for i in range(n + 1)), t)
        N0, N1, N2 = (Np.diff((t, j)).eval(0) if j else Np.eval(0) for j in range(3))
        d1.append((N1 * W0 - N0 * W1) / W0**2)
        d2.append(((N2 * W0 - N0 * W2) * W0 - 2 * (N1 * W0 - N0 * W1) * W1) / W0**3)
    return d1, d2


@claim(doc="sederberg", section="2.9.2", ref="(2.10), (2.11)", statement="P'(t0) = (w1/w0) n/(t1 - t0) (P1 - P0)")
def rational_end_first_derivative():
    t0, t1 = sp.symbols("t_0 t_1")
    for n in (1, 2, 3, 4):
        w, P, R = _sym_rational(n)
        d = R.diff(t).subs(t, 0) / (t1 - t0)  # P_[t0,t1](tau) = R((tau - t0)/(t1 - t0))
        assert (d - w[1] / w[0] * n / (t1 - t0) * (P[1] - P[0])).applyfunc(sp.simplify) == sp.zeros(2, 1)
    return verified("quotient rule in sympy for n = 1..4, generic points, weights and [t0, t1]",
        compared='printed (2.10)-(2.11) vs sympy quotient-rule derivative of the symbolic rational curve at t0, n = 1..4, generic points, weights and [t0, t1]',
        reference='sympy',
    )


@claim(doc="sederberg", section="2.9.2", ref="(2.12)", statement="P''(0) = n(n-1)/(t1-t0)^2 (w2/w0)(P2-P0) - 2n/(t1-t0)^2 (w1/w0)((n w1 - w0)/w0)(P1-P0)")
def rational_end_second_derivative():
    for n in (2, 3, 4):
        w, P, R = _sym_rational(n)
        d2 = R.diff(t, 2).subs(t, 0)
        printed = n * (n - 1) * w[2] / w[0] * (P[2] - P[0]) - 2 * n * w[1] / w[0] * (n * w[1] - w[0]) / w[0] * (P[1] - P[0])
        assert (d2 - printed).applyfunc(sp.simplify) == sp.zeros(2, 1)
    rng = random.Random(212)
    for _ in range(10):
        c = _random_curve(rng, rng.randint(2, 6))
        assert bx.end_second_derivative(c, (1, 4)) == bx.derivatives_at(c, 1, 2, (1, 4))[2]
        # the printed (2.12) on [t0, t1] = [1, 4] vs sympy's second derivative of P((tau - 1)/3) at tau = 1
        n = c.degree
        w = [_R(x) for x in c.weights_array()]
        P = [sp.Matrix([_R(x) for x in pt]) for pt in c.control_points]
        printed = (n * (n - 1) / sp.Integer(9) * w[2] / w[0] * (P[2] - P[0])
                   - 2 * n / sp.Integer(9) * w[1] / w[0] * (n * w[1] - w[0]) / w[0] * (P[1] - P[0]))
        _, d2 = _derivatives_at_0(c)
        assert list(printed) == [x / 9 for x in d2] == [_R(x) for x in bx.end_second_derivative(c, (1, 4))]
    return verified("sympy second derivative at t = 0 for n = 2, 3, 4 (generic data); exact check on [1, 4] for 10 random curves up to degree 6",
        compared="printed (2.12) vs sympy second derivative of the symbolic rational curve at t = 0, n = 2, 3, 4; on [1, 4] the printed formula vs sympy's quotient-rule second derivative of 10 random exact curves (degree 2-6), with exactcagd's end_second_derivative and derivatives_at agreeing",
        reference='sympy',
    )


@claim(doc="sederberg", section="2.9.3", ref="(2.13)", statement="kappa(t0) = (w0 w2 / w1^2) ((n-1)/n) h / a^2, independent of [t0, t1]")
def rational_end_curvature():
    for n in (2,):  # symbolic for n = 2; higher degrees exactly on random instances below
        w, P, R = _sym_rational(n)
        x1, y1 = (e.diff(t).subs(t, 0) for e in R)
        x2, y2 = (e.diff(t, 2).subs(t, 0) for e in R)
        kappa2 = sp.cancel((x1 * y2 - y1 * x2) ** 2 / (x1**2 + y1**2) ** 3)
        a2 = (P[1] - P[0]).dot(P[1] - P[0])
        cr = (P[1][0] - P[0][0]) * (P[2][1] - P[0][1]) - (P[1][1] - P[0][1]) * (P[2][0] - P[0][0])
        h2 = cr**2 / a2
        printed2 = (w[0] * w[2] / w[1] ** 2) ** 2 * sp.Rational(n - 1, n) ** 2 * h2 / a2**2
        assert sp.cancel(kappa2 - printed2) == 0
    rng = random.Random(213)
    for _ in range(10):
        c = _random_curve(rng, rng.randint(3, 6))
        assert bx.end_curvature(c) == bx.curvature(c, 2, (2, 7)) == bx.curvature(c, 0)
        # the printed (2.13), squared, vs sympy's curvature of the exact curve at t = 0
        n = c.degree
        w = [_R(x) for x in c.weights_array()]
        P = [[_R(x) for x in pt] for pt in c.control_points]
        a2 = (P[1][0] - P[0][0]) ** 2 + (P[1][1] - P[0][1]) ** 2
        cr = (P[1][0] - P[0][0]) * (P[2][1] - P[0][1]) - (P[1][1] - P[0][1]) * (P[2][0] - P[0][0])
        printed2 = (w[0] * w[2] / w[1] ** 2) ** 2 * sp.Rational(n - 1, n) ** 2 * (cr**2 / a2) / a2**2
        d1, d2 = _derivatives_at_0(c)
        kappa2 = (d1[0] * d2[1] - d1[1] * d2[0]) ** 2 / (d1[0] ** 2 + d1[1] ** 2) ** 3
        assert kappa2 == printed2 == _R(bx.end_curvature(c)) ** 2
    return verified("kappa^2 identity in sympy for n = 2 (generic data); exact equality with the general curvature on [0,1] and [2,7] for 10 random curves of degree 3-6",
        compared="printed (2.13) kappa^2 vs sympy's (x'y'' - y'x'')^2 / (x'^2 + y'^2)^3 for the symbolic rational quadratic (cancel); for 10 random exact curves of degree 3-6 the printed (2.13) (squared) vs sympy's curvature at t = 0, and exactcagd's end_curvature / general curvature on [0,1] and [2,7] agree",
        reference='sympy',
    )


def _trace_curvature():
    c = BezierCurve([[0, 0], [4, 3], [0, 5]], weights=[1, 2, 4])
    print("distance equation of P0-P1: 3/5 x - 4/5 y; at P2 = (0, 5):", mpq(3, 5) * 0 - mpq(4, 5) * 5, "-> h = 4")
    print("a = |P1 - P0| = sqrt(4^2 + 3^2) = 5")
    print("kappa(0) = (1*4/2^2) (1/2) 4/5^2 =", mpq(1 * 4, 4) * mpq(1, 2) * mpq(4, 25))
    print("general curvature formula at t = 0:", bx.curvature(c, 0))


@claim(doc="sederberg", section="2.9.3", ref="Example", statement="P0=(0,0),w0=1; P1=(4,3),w1=2; P2=(0,5),w2=4: h = 4, a = 5, kappa(0) = 2/25", trace=_trace_curvature)
def curvature_example():
    c = BezierCurve([[0, 0], [4, 3], [0, 5]], weights=[1, 2, 4])
    assert mpq(3, 5) * 0 - mpq(4, 5) * 5 == -4  # |h| = 4
    assert bx.end_curvature(c) == mpq(2, 25) == bx.curvature(c, 0)
    x, y = (e for e in _sym_curve(c))
    kappa = sp.Abs(x.diff(t) * y.diff(t, 2) - y.diff(t) * x.diff(t, 2)) / (x.diff(t) ** 2 + y.diff(t) ** 2) ** sp.Rational(3, 2)
    assert sp.simplify(kappa.subs(t, 0)) == sp.Rational(2, 25)
    return verified("kappa(0) = 2/25 by (2.13), by the exact general formula and by sympy differentiation",
        compared="printed h = 4, a = 5, kappa(0) = 2/25 vs sympy differentiation of the example's rational quadratic at t = 0 (and hand arithmetic for h)",
        reference='sympy',
    )


def _sym_curve(c):
    n = c.degree
    w = [_R(x) for x in c.weights_array()]
    W = sum(w[i] * _B(n, i) for i in range(n + 1))
    return [sum(w[i] * _R(p[k]) * _B(n, i) for i, p in enumerate(c.control_points)) / W for k in range(c.dimension)]


@claim(doc="sederberg", section="2.10", ref="C1, C2 of cubics", statement="C1: 3/(t1-t0)(p3 - p2) = 3/(t2-t1)(q1 - q0); C2: 6/(t1-t0)^2 (p3 - 2p2 + p1) = 6/(t2-t1)^2 (q2 - 2q1 + q0)")
def cubic_continuity_conditions():
    t0, t1, t2, tau = sp.symbols("t0 t1 t2 tau")
    p = sp.symbols("p0:4")
    q = sp.symbols("q0:4")
    P = sum(p[i] * _B(3, i, (tau - t0) / (t1 - t0)) for i in range(4))
    Q = sum(q[i] * _B(3, i, (tau - t1) / (t2 - t1)) for i in range(4))
    assert sp.simplify(P.diff(tau).subs(tau, t1) - 3 / (t1 - t0) * (p[3] - p[2])) == 0
    assert sp.simplify(Q.diff(tau).subs(tau, t1) - 3 / (t2 - t1) * (q[1] - q[0])) == 0
    assert sp.simplify(P.diff(tau, 2).subs(tau, t1) - 6 / (t1 - t0) ** 2 * (p[3] - 2 * p[2] + p[1])) == 0
    assert sp.simplify(Q.diff(tau, 2).subs(tau, t1) - 6 / (t2 - t1) ** 2 * (q[2] - 2 * q[1] + q[0])) == 0
    # an instance: a C2 pair built from the conditions
    a = BezierCurve([[0, 0], [1, 2], [3, 3], [4, 3]])
    b_ = BezierCurve([[4, 3], [6, 3], [9, 2], [10, 0]])  # t-intervals [0,1], [1,3]: q1 - q0 = 2(p3 - p2)
    assert bx.parametric_continuity(a, b_, (0, 1), (1, 3)) >= 1
    return verified("symbolic end derivatives of cubics over [t0,t1], [t1,t2]; exact C^k test on an instance",
        compared='printed C1 / C2 conditions vs sympy derivatives of two symbolic cubics over [t0, t1], [t1, t2] at t1',
        reference='sympy',
    )


@claim(doc="sederberg", section="2.10", ref="(2.15)", covers=["(2.14)"], statement="C^n curves are also G^n as long as P'(t1) = Q'(t1) != 0, ...")
def c_implies_g_needs_regularity():
    # C1 joint with vanishing derivative and a turn-back: C^1 but not G^1
    p = BezierCurve([[0, 0], [1, 0], [2, 0], [2, 0]])   # P'(1) = 0
    q = BezierCurve([[2, 0], [2, 0], [2, 1], [2, 3]])   # Q'(0) = 0, leaves upward
    # sympy: P'(1) = Q'(0) = 0 (C^1), P' = (x'(t), 0) with x' > 0 on (0, 1), Q' = (0, y'(t)) with y' > 0 on (0, 1]:
    # the tangent direction turns from (1, 0) to (0, 1) at the joint, so no G^1
    Ps, Qs = (sp.Matrix(_sym_curve(c)).diff(t).applyfunc(sp.cancel) for c in (p, q))
    assert Ps.subs(t, 1) == Qs.subs(t, 0) == sp.zeros(2, 1)
    assert Ps[1] == 0 and Qs[0] == 0
    assert sp.Poly(Ps[0], t).count_roots(0, sp.Rational(999, 1000)) == 0 and Ps[0].subs(t, 0) > 0
    assert sp.Poly(Qs[1], t).count_roots(sp.Rational(1, 1000), 1) == 0 and Qs[1].subs(t, 1) > 0
    assert bx.parametric_continuity(p, q) >= 1
    k, _ = bx.geometric_continuity(p, q)
    assert k == 0
    # regular C^2 joint: G^2 with beta_1 = 1, beta_2 = 0
    a = BezierCurve([[0, 0], [1, 1], [2, 1], [3, 0]])
    left, right = a.subdivide("1/2")
    L_, R_ = (sp.Matrix(_sym_curve(c)).applyfunc(sp.cancel) for c in (left, right))
    for k in (1, 2):  # sympy: equal derivatives at the joint (beta_1 = 1, beta_2 = 0), the first one non-zero
        assert L_.diff(t, k).subs(t, 1) == R_.diff(t, k).subs(t, 0)
    assert L_.diff(t).subs(t, 1) != sp.zeros(2, 1)
    k2, betas = bx.geometric_continuity(left, right, max_order=2)
    assert k2 == 2 and betas == [1, 0]
    return verified("C^1 with P' = Q' = 0 and a 90-degree turn is not G^1; a regular C^2 joint is G^2 with beta = (1, 0)",
        compared="printed regularity condition vs sympy: for the example pair P'(1) = Q'(0) = 0 (C1), P' = (x', 0) with x' > 0 on [0, 0.999] and Q' = (0, y') with y' > 0 on [0.001, 1] (real-root counts), so the tangent turns by 90 deg (not G1); the halves of a regular cubic have equal first and second derivatives at the joint (G2, beta = (1, 0)); exactcagd's continuity tests agree",
        reference='sympy',
    )


@claim(doc="sederberg", section="2.11", ref="e", statement="cubic circular arc: e = 2 sin(theta/2) / (1 + 2 cos(theta/2)) r")
def cubic_arc_e():
    th, r = sp.symbols("theta r", positive=True)
    c = sp.cos(th / 2)
    # symmetric quadratic arc of angle theta (bisector on the x axis): P0, P1 on the tangent lines
    P0 = sp.Matrix([r * sp.cos(th / 2), -r * sp.sin(th / 2)])
    P1 = sp.Matrix([r / sp.cos(th / 2), 0])
    # degree elevation of the homogeneous points (P0, 1), (c P1, c), (P2, 1): first inner point
    Q1 = (P0 + 2 * c * P1) / (1 + 2 * c)
    e2 = sp.simplify((Q1 - P0).dot(Q1 - P0))
    printed = (2 * sp.sin(th / 2) / (1 + 2 * sp.cos(th / 2)) * r) ** 2
    assert sp.simplify(sp.expand_trig(e2 - printed)) == 0
    assert sp.cos(sp.Rational(240, 2) * sp.pi / 180) == -sp.Rational(1, 2)  # 1 + 2 cos(120 deg) = 0
    # exact instance: 90-degree arc of radius 5, weights (1, 1, 2) -> elevated arc lies on the circle
    arc = bx.circular_arc((0, 0), (5, 0), (0, 5))[0].elevate(1)
    x, y = _sym_curve(arc)
    assert sp.simplify(x**2 + y**2 - 25) == 0
    return verified("|Q1 - P0|^2 of the elevated symmetric arc equals the printed e^2 for symbolic theta, r; e -> inf exactly when 1 + 2cos(theta/2) = 0, i.e. theta = 240 deg",
        compared='printed e = 2 sin(theta/2) / (1 + 2 cos(theta/2)) r vs sympy: |Q1 - P0|^2 of the degree-elevated symmetric quadratic arc for symbolic theta, r; an elevated exact 90-degree arc satisfies x^2 + y^2 = 25 identically',
        reference='sympy',
    )


@claim(doc="sederberg", section="2.11", ref="degree two near 180 deg", statement="the degree two case has trouble when theta approaches 180 deg since P1 moves to infinity")
def quadratic_arc_180():
    th, r = sp.symbols("theta r", positive=True)
    P0 = sp.Matrix([r * sp.cos(th / 2), -r * sp.sin(th / 2)])
    P1 = sp.Matrix([r / sp.cos(th / 2), 0])  # tangent lines at P0, P2 meet on the bisector
    assert sp.simplify((P1 - P0).dot(P1 - P0) - (r * sp.tan(th / 2)) ** 2) == 0
    dist = r * sp.tan(th / 2)  # |P1 - P0| for the tangent intersection
    assert sp.limit(dist, th, sp.pi, "-") == sp.oo
    return verified("|P1 - P0| = r tan(theta/2) -> infinity as theta -> 180 deg",
        compared="printed 'P1 moves to infinity' vs sympy: |P1 - P0|^2 = r^2 tan^2(theta/2) from the tangent intersection, and its limit theta -> 180 deg is infinite",
        reference='sympy',
    )


@claim(doc="sederberg", section="2.11", ref="Figure 2.19", statement="a complete circle as a degree five rational Bézier curve with w0 = w5 = 1, w1..w4 = 1/5")
def circle_degree_five():
    xs, ys = sp.symbols("x1:5"), sp.symbols("y1:5")
    w = [1] + [sp.Rational(1, 5)] * 4 + [1]
    X = -0 + sum(w[i] * xs[i - 1] * _B(5, i) for i in range(1, 5))
    Y = -(w[0] * _B(5, 0) + w[5] * _B(5, 5)) + sum(w[i] * ys[i - 1] * _B(5, i) for i in range(1, 5))
    W = sum(w[i] * _B(5, i) for i in range(6))
    sols = sp.solve(sp.Poly(sp.expand(X**2 + Y**2 - W**2), t).coeffs(), list(xs) + list(ys), dict=True)
    proper = [sol for sol in sols if any(sol[x] != 0 for x in xs)]
    assert len(proper) == 2  # mirror images
    c = bx.full_circle_degree5()
    x, y = _sym_curve(c)
    assert sp.simplify(x**2 + y**2 - 1) == 0
    assert sp.factor(W) == (2 * t**2 - 2 * t + 1) ** 2
    num = sp.numer(sp.together(x * y.diff(t) - y * x.diff(t)))
    assert [r_ for r_ in sp.Poly(num, t).real_roots() if 0 <= r_ <= 1] == []
    return verified("undetermined coefficients with P0 = P5 = (0,-1): control points (-4,-1), (-2,3), (2,3), (4,-1) (or mirrored); "
                    "x^2 + y^2 = 1 identically, W = (2t^2 - 2t + 1)^2 > 0, angular speed never zero: one full turn",
        compared="Figure 2.19 weights vs sympy undetermined coefficients: x^2 + y^2 - W^2 = 0 solved for the inner points (two mirror solutions); exactcagd's circle satisfies x^2 + y^2 = 1 identically, W = (2t^2 - 2t + 1)^2, angular speed without roots in [0, 1]",
        reference='sympy',
    )


@claim(doc="sederberg", section="2.12", ref="Example", statement="P(t) = (t^2 + t - 1, 2t^2 - t + 3), t = 2s + 1 gives Q(s) = (4s^2 + 6s + 1, 8s^2 + 6s + 4)")
def reparam_example():
    P = sp.Matrix([t**2 + t - 1, 2 * t**2 - t + 3])
    Q = P.subs(t, 2 * s + 1).applyfunc(sp.expand)
    assert Q == sp.Matrix([4 * s**2 + 6 * s + 1, 8 * s**2 + 6 * s + 4])
    c = BezierCurve(bz.from_power(bz.as_coefficients([[-1, 3], [1, -1], [1, 2]])).tolist())
    q = bx.substitute_linear(c, 1, 2)
    assert q.control_points == BezierCurve(bz.from_power(bz.as_coefficients([[1, 4], [6, 6], [4, 8]])).tolist()).control_points
    return verified("sympy substitution and the exact polar-form restriction to [1, 3] agree",
        compared="printed Q(s) vs sympy substitution t = 2s + 1 and expansion; exactcagd's polar-form restriction to [1, 3] agrees",
        reference='sympy',
    )


@claim(doc="sederberg", section="2.12", ref="domain change", statement="t = (t0 s1 - s0 t1)/(s1 - s0) + (t1 - t0)/(s1 - s0) s; P[0,1], Q[5,9]: P(t) = Q(5 + 4t), Q(s) = P(-5/4 + s/4)")
def domain_change():
    t0, t1, s0, s1 = sp.symbols("t0 t1 s0 s1")
    f = (t0 * s1 - s0 * t1) / (s1 - s0) + (t1 - t0) / (s1 - s0) * s
    assert sp.simplify(f.subs(s, s0) - t0) == 0 and sp.simplify(f.subs(s, s1) - t1) == 0
    assert sp.expand(f.subs({t0: 0, t1: 1, s0: 5, s1: 9})) == sp.Rational(-5, 4) + s / 4
    assert sp.expand(f.subs({t0: 5, t1: 9, s0: 0, s1: 1})) == 5 + 4 * s
    assert bx.domain_map((0, 1), (5, 9)) == (mpq(-5, 4), mpq(1, 4))
    assert bx.domain_map((5, 9), (0, 1)) == (5, 4)
    return verified("the map sends s0 -> t0, s1 -> t1 (affine); the example's maps reproduced exactly",
        compared="printed map vs sympy: s0 -> t0, s1 -> t1, and the example's maps -5/4 + s/4 and 5 + 4s by substitution; exactcagd's domain_map agrees",
        reference='sympy',
    )


@claim(doc="sederberg", section="2.12", ref="rational reparametrization", statement="t = b u / ((1 - u) + b u) leaves the curve unchanged if the weights are scaled by b^i")
def mobius_weights():
    b = sp.Symbol("b", positive=True)
    for n in (1, 2, 3):
        w, P, R = _sym_rational(n)
        sub = R.subs(t, b * u / ((1 - u) + b * u))
        W2 = sum(w[i] * b**i * _B(n, i, u) for i in range(n + 1))
        N2 = sp.zeros(2, 1)
        for i in range(n + 1):
            N2 += w[i] * b**i * _B(n, i, u) * P[i]
        assert (sub - N2 / W2).applyfunc(sp.cancel) == sp.zeros(2, 1)
    return verified("sympy identity for n = 1..3 with generic points and weights",
        compared='printed weight scaling b^i vs sympy: the substituted symbolic rational curve equals the reweighted one (cancel), n = 1..3',
        reference='sympy',
    )


@claim(doc="sederberg", section="2.12", ref="Figure 2.20", statement="b = -1: signs of weights alternate; for a quarter circle the reparametrized curve on [0,1] is the rest of the circle")
def negative_weight_circle():
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], [1, 1, 2])
    rest = bx.mobius_reparametrize(quarter, -1)
    assert rest.weights == (1, -1, 2)
    x, y = _sym_curve(rest)
    assert sp.simplify(x**2 + y**2 - 1) == 0
    # u in (0,1) maps to t = -u/(1 - 2u): outside [0, 1]; the midpoint is the far point (-1, 0)
    assert rest.evaluate("1/2") == (-1, 0)
    return verified("weights (1, -1, 2); the curve satisfies x^2 + y^2 = 1 and passes through (-1, 0), outside the first quadrant",
        compared="printed b = -1 claim vs sympy: the curve with weights (1, -1, 2) satisfies x^2 + y^2 = 1 identically and passes through (-1, 0) at u = 1/2; exactcagd's mobius_reparametrize gives those weights",
        reference='sympy',
    )


@claim(doc="sederberg", section="2.13", ref="item 2 / 2.9", statement="a perspective projection of a (polynomial or rational) Bézier curve is a rational Bézier curve")
def perspective_projection():
    n = 3
    P = [sp.Matrix(sp.symbols(f"x{i} y{i} z{i}")) for i in range(n + 1)]
    C = sp.zeros(3, 1)
    for i in range(n + 1):
        C += _B(n, i) * P[i]
    proj = sp.Matrix([C[0] / C[2], C[1] / C[2]])  # perspective onto z = 1 from the origin
    w = [p[2] for p in P]
    W = sum(w[i] * _B(n, i) for i in range(n + 1))
    R = sp.zeros(2, 1)
    for i in range(n + 1):
        R += w[i] * _B(n, i) * sp.Matrix([P[i][0] / w[i], P[i][1] / w[i]])
    assert (proj - R / W).applyfunc(sp.cancel) == sp.zeros(2, 1)
    return verified("projection of a cubic space curve = rational cubic with weights z_i and points (x_i/z_i, y_i/z_i)",
        compared='2.13 claim vs sympy: the projection (x/z, y/z) of a symbolic space cubic equals the rational cubic with weights z_i and points (x_i/z_i, y_i/z_i) (cancel)',
        reference='sympy',
    )


@claim(doc="sederberg", section="2.14", ref="explicit curves", statement="x = t when P_i = ((t0 (n - i) + t1 i)/n, y_i); an explicit rational curve of degree n has degree n + 1")
def explicit_curves():
    t0, t1 = sp.symbols("t0 t1")
    for n in (1, 2, 3, 5):
        x = sum((t0 * (n - i) + t1 * i) / n * _B(n, i) for i in range(n + 1))
        assert sp.expand(x - (t0 + (t1 - t0) * t)) == 0
    # sympy: (x, y) = (t, Y/W) with y-values (0, 1, 0), weights (1, 2, 1); homogeneous (t W, Y, W) has no common factor
    Yq = sum(wi * yi * _B(2, i) for i, (wi, yi) in enumerate(zip((1, 2, 1), (0, 1, 0))))
    Wq = sum(wi * _B(2, i) for i, wi in enumerate((1, 2, 1)))
    hom = [sp.expand(t * Wq), sp.expand(Yq), sp.expand(Wq)]
    assert max(sp.degree(h, t) for h in hom) == 3 and sp.gcd(sp.gcd(hom[0], hom[1]), hom[2]) == 1
    c = bx.explicit_rational_curve([0, 1, 0], [1, 2, 1])
    assert [sp.cancel(a - b_) for a, b_ in zip(_sym_curve(c), (t, Yq / Wq))] == [0, 0]
    assert c.degree == 3 and c.true_degree() == 3 and bx.is_explicit(c)
    return verified("x(t) = t0 + (t1 - t0) t for n = 1, 2, 3, 5 symbolically; the explicit rational quadratic (0,1,0; 1,2,1) has true degree 3",
        compared="printed x-coordinate rule vs sympy expansion (x = t0 + (t1 - t0) t), n = 1, 2, 3, 5; the degree-(n+1) claim vs sympy: homogeneous (t W, Y, W) of the explicit rational quadratic has degree 3 and gcd 1, and equals exactcagd's curve",
        reference='sympy',
    )


@claim(doc="sederberg", section="2.15", ref="(2.18)-(2.20)", covers=["(2.16)", "(2.17)"], statement="q_0 = 0, q_i = sum_{j<i} p_j/(n+1); the area under an explicit curve is the average of its control values")
def bernstein_integrals():
    for n in range(0, 6):
        p = sp.symbols(f"p0:{n + 1}")
        q = [0] + [sum(p[:i]) / (n + 1) for i in range(1, n + 2)]
        Q = sum(q[i] * _B(n + 1, i) for i in range(n + 2))
        Pp = sum(p[i] * _B(n, i) for i in range(n + 1))
        assert sp.expand(Q.diff(t) - Pp) == 0 and Q.subs(t, 0) == 0
        assert sp.expand(sp.integrate(Pp, (t, 0, 1)) - sum(p) / (n + 1)) == 0
        assert all(sp.expand(p[i] - (n + 1) * (q[i + 1] - q[i])) == 0 for i in range(n + 1))
    c = bx.explicit_curve([1, 3, 2, 0])
    assert bx.area_under_explicit(c) == mpq(3, 2)
    return verified("sympy: q' = p, q(0) = 0, integral = mean of p_i for n = 0..5; (2.18) inverts (2.19)",
        compared="printed (2.16)-(2.20) vs sympy: Q' = P, Q(0) = 0, integral over [0, 1] = mean of the p_i, n = 0..5",
        reference='sympy',
    )

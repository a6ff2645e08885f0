"""Sederberg's notes, chapter 18 items without a row: 18.1 pencil (18.1), 18.1.1 homogeneous points
and lines (18.2), (18.4), (18.5), 18.1.2 curves and moving lines (18.8)-(18.16), 18.2.2 (18.25),
18.2.3 (18.32), 18.3.2 (18.41)-(18.42), 18.3.3 (18.48), 18.3.4 (18.51).

Every check is sympy from first principles (dot and cross products of triples, Bernstein
expansion, resultants); no exactcagd function is under test here.
"""

from __future__ import annotations

import random

import sympy as sp

from exactcagd.proofs._ledger import claim, verified

DOC = "sederberg"
t, tau, x, y, X, Y, W, k = sp.symbols("t tau x y X Y W k")


def _B(n, i, var=t):
    """B_i^n[t] = C(n, i) (1-t)^(n-i) t^i as printed under (18.10)."""
    return sp.binomial(n, i) * (1 - var) ** (n - i) * var**i


def _curve(ctrl, var=t):
    """(18.11): P[t] = sum P_i B_i^n[t] for homogeneous triples P_i."""
    n = len(ctrl) - 1
    return sum((sp.Matrix(p) * _B(n, i, var) for i, p in enumerate(ctrl)), sp.zeros(3, 1)).applyfunc(sp.expand)


def _triples(rng, count, lo=-6, hi=6):
    return [[rng.randint(lo, hi) for _ in range(3)] for _ in range(count)]


def _degree(vec):
    return max(sp.degree(sp.expand(v), t) for v in vec)


def _zero(vec):
    return all(sp.expand(v) == 0 for v in vec)


@claim(doc=DOC, section="18.1", ref="(18.1)",
       statement="(a0 x + b0 y + c0)(1 - t) + (a1 x + b1 y + c1) t = 0, for two distinct lines, is a pencil of lines")
def pencil_equation():
    rng = random.Random(181)
    checked = 0
    while checked < 5:
        l0, l1 = (sp.Matrix(v) for v in _triples(rng, 2))
        if l0.cross(l1)[2] == 0:  # parallel or equal lines: not two distinct intersecting lines
            continue
        A = l0.cross(l1) / l0.cross(l1)[2]  # the common point (Cartesian, W = 1)
        member = (l0 * (1 - t) + l1 * t)
        assert sp.expand(member.dot(A)) == 0  # every line of (18.1) passes through A
        # and every line through A is a member: the line through A and a point Q is (18.1) for one t
        Q = sp.Matrix([rng.randint(-9, 9), rng.randint(-9, 9), 1])
        if sp.expand(l0.dot(Q)) == sp.expand(l1.dot(Q)):
            continue
        ts = sp.solve(member.dot(Q), t)
        assert len(ts) == 1 and member.subs(t, ts[0]).cross(A.cross(Q)) == sp.zeros(3, 1)
        checked += 1
    return verified("5 random pairs of distinct intersecting lines (sympy): every member of (18.1) contains the common point, "
                    "and the line through it and any other point is the member for exactly one t",
                    compared="printed (18.1) vs sympy dot/cross products of the line triples", reference="sympy")


@claim(doc=DOC, section="18.1.1", ref="(18.2), (18.4), (18.5)",
       statement="the line aX + bY + cW = 0; (a,b,c).(d,e,f) = ad + be + cf; the line L is {P : L . P = 0}: P lies on L iff P . L = 0")
def homogeneous_incidence():
    a, b, c, d, e, f = sp.symbols("a b c d e f")
    L, P = sp.Matrix([a, b, c]), sp.Matrix([X, Y, W])
    assert sp.expand(L.dot(P) - (a * X + b * Y + c * W)) == 0  # (18.4) is the dot product used in (18.5)
    assert sp.expand(L.dot(sp.Matrix([d, e, f])) - (a * d + b * e + c * f)) == 0
    # (18.2) with W != 0 is the Cartesian line ax + by + c = 0 at (x, y) = (X/W, Y/W), for every scale of P and L
    assert sp.cancel((L * k).dot(P * k) / (k**2 * W) - (a * x + b * y + c).subs({x: X / W, y: Y / W})) == 0
    # (18.5): P on L iff L . P = 0, checked on integer data against the Cartesian line
    rng = random.Random(1825)
    for _ in range(20):
        Lv = sp.Matrix(_triples(rng, 1)[0])
        xv = sp.Rational(rng.randint(-9, 9), rng.randint(1, 4))
        if Lv[1] == 0:
            continue
        yv = -(Lv[0] * xv + Lv[2]) / Lv[1]  # a Cartesian point of the line
        wv = rng.randint(1, 5)
        assert Lv.dot(sp.Matrix([xv * wv, yv * wv, wv])) == 0
        assert Lv.dot(sp.Matrix([xv * wv, (yv + 1) * wv, wv])) != 0
    return verified("symbolic triples: L . P = aX + bY + cW, and L . P / W is a x + b y + c at (X/W, Y/W) for any scaling; "
                    "random lines: points on the Cartesian line give L . P = 0, points off it do not",
                    compared="printed (18.2), (18.4), (18.5) vs sympy expansion and the Cartesian line", reference="sympy")


@claim(doc=DOC, section="18.1.2", ref="(18.8)-(18.16)", covers=["§18.1.2"],
       statement="P[t] = (X, Y, W)[t] is the curve x = X/W, y = Y/W; Bernstein X, Y, W give P[t] = sum P_i B_i^n[t], polynomial iff W const (all W_i = gamma); L[t] = (a, b, c)[t] is the family a x + b y + c = 0; P follows L iff P . L = 0; P1 x P2 = L k; L1 x L2 = P k")
def curves_and_moving_lines():
    rng = random.Random(1812)
    for n in (2, 3):
        ctrl = [[rng.randint(-6, 6), rng.randint(-6, 6), rng.randint(1, 4)] for _ in range(n + 1)]
        P = _curve(ctrl)
        # (18.10) componentwise is (18.11)
        for j in range(3):
            assert sp.expand(P[j] - sum(ctrl[i][j] * _B(n, i) for i in range(n + 1))) == 0
        # (18.9): the Cartesian point at t = 1/3 is X/W, Y/W of the control-point combination
        tv = sp.Rational(1, 3)
        xv, yv = P[0].subs(t, tv) / P[2].subs(t, tv), P[1].subs(t, tv) / P[2].subs(t, tv)
        w = [cp[2] for cp in ctrl]
        assert xv == sum(sp.Rational(cp[0], cp[2]) * cp[2] * _B(n, i, tv) for i, cp in enumerate(ctrl)) / sum(wi * _B(n, i, tv) for i, wi in enumerate(w))
        assert yv == sum(sp.Rational(cp[1], cp[2]) * cp[2] * _B(n, i, tv) for i, cp in enumerate(ctrl)) / sum(wi * _B(n, i, tv) for i, wi in enumerate(w))
        # polynomial curve: W[t] constant iff all W_i equal (Bernstein polynomials are a basis, sum to 1)
        gs = sp.symbols(f"g0:{n + 1}")
        Wt = sp.Poly(sum(g * _B(n, i) for i, g in enumerate(gs)), t)
        sol = sp.solve(Wt.all_coeffs()[:-1], gs[1:], dict=True)
        assert sol == [{g: gs[0] for g in gs[1:]}]
        # (18.12)-(18.14): the moving line L[t] = P[t] x Q (Q fixed) satisfies P . L == 0, i.e. a x + b y + c = 0 at (x, y)
        Q = sp.Matrix(_triples(rng, 1)[0])
        Lt = P.cross(Q).applyfunc(sp.expand)
        assert sp.expand(P.dot(Lt)) == 0
        assert sp.cancel(Lt[0] * P[0] / P[2] + Lt[1] * P[1] / P[2] + Lt[2]) == 0
        # (18.15): two moving points P1, P2: L = P1 x P2 follows both; any L' following both is k[t] L
        P2 = _curve(_triples(rng, n, 1, 6))
        L12 = P.cross(P2).applyfunc(sp.expand)
        assert sp.expand(L12.dot(P)) == 0 and sp.expand(L12.dot(P2)) == 0
        Lother = (L12 * (t**2 + 1)).applyfunc(sp.expand)  # another line following both
        assert _zero(Lother.cross(L12))
        # (18.16): two moving lines meet at M = L1 x L2, which lies on both; a point on both is proportional to M
        L1, L2 = _curve(_triples(rng, n)), _curve(_triples(rng, 2))
        M = L1.cross(L2).applyfunc(sp.expand)
        assert sp.expand(M.dot(L1)) == 0 and sp.expand(M.dot(L2)) == 0
        assert _zero(((L1.cross(L2)) * (3 * t - 2)).cross(M))
    return verified("n = 2, 3 random homogeneous control points (sympy): (18.10) = (18.11), (18.9) = the weighted rational form, "
                    "W constant iff W_0 = ... = W_n; L = P x Q follows P (a x + b y + c = 0 on the curve), P1 x P2 follows both "
                    "points and L1 x L2 lies on both lines, each up to a scalar factor k[t]",
                    compared="printed (18.8)-(18.16) vs sympy Bernstein expansion, dot and cross products", reference="sympy")


@claim(doc=DOC, section="18.2.2", ref="(18.25)",
       statement="two pencils L0[t] = L00(1-t) + L01 t, L1[t] = L10(1-t) + L11 t intersect line by line in a conic; the sample points at t = 0, .25, .5, .75, 1 are not collinear")
def two_pencils_conic():
    rng = random.Random(1825)
    done = 0
    while done < 3:
        L00, L01, L10, L11 = (sp.Matrix(v) for v in _triples(rng, 4))
        L0t, L1t = L00 * (1 - t) + L01 * t, L10 * (1 - t) + L11 * t
        P = L0t.cross(L1t).applyfunc(sp.expand)
        if _degree(P) < 2 or L00.cross(L01) == sp.zeros(3, 1) or L10.cross(L11) == sp.zeros(3, 1):
            continue
        # eliminate t from the two pencil equations: the locus is a conic (total degree 2 in X, Y, W)
        Pt = sp.Matrix([X, Y, W])
        conic = sp.resultant(sp.expand(L0t.dot(Pt)), sp.expand(L1t.dot(Pt)), t)
        if conic == 0:
            continue
        assert sp.Poly(conic, X, Y, W).total_degree() == 2
        samples = [P.subs(t, sp.Rational(j, 4)) for j in range(5)]
        assert all(sp.expand(conic.subs({X: s[0], Y: s[1], W: s[2]})) == 0 for s in samples)
        assert sp.Matrix([list(s) for s in samples[:3]]).det() != 0  # not collinear
        done += 1
    return verified("3 random pairs of pencils (sympy): the resultant in t of the two pencil equations is a conic (degree 2 in X, Y, W) "
                    "through L0[t] x L1[t] at t = 0, 1/4, 1/2, 3/4, 1, and three of the samples are not collinear",
                    compared="printed (18.25) and its claim vs sympy resultant and determinants", reference="sympy")


@claim(doc=DOC, section="18.2.3", ref="(18.32)",
       statement="an arbitrary rational quadratic P0(1-t)^2 + P1 2(1-t)t + P2 t^2 is the intersection of two pencils")
def quadratic_two_pencils():
    rng = random.Random(1832)
    for _ in range(4):
        ctrl = _triples(rng, 3, 1, 7)
        P0, P1, P2 = (sp.Matrix(p) for p in ctrl)
        P = _curve(ctrl)
        # P[k] x P[t] for two fixed k: divide out the base point (t - k): a pencil (linear in t)
        pencils = []
        for kv in (sp.Rational(1, 4), sp.Rational(2, 3)):
            Lk = P.subs(t, kv).cross(P).applyfunc(lambda e: sp.cancel(sp.expand(e) / (t - kv)))
            assert all(sp.Poly(e, t).degree() <= 1 for e in Lk)
            pencils.append(Lk)
        meet = pencils[0].cross(pencils[1]).applyfunc(sp.expand)
        assert _zero(meet.cross(P))  # the pencils meet on the curve, at the same t
        assert not _zero(meet)
    return verified("4 random rational quadratics (sympy): P[k] x P[t] / (t - k) is linear in t for k = 1/4, 2/3, and the two pencils "
                    "meet in a multiple of P[t]",
                    compared="printed (18.32) claim vs sympy cross products and polynomial division", reference="sympy")


@claim(doc=DOC, section="18.3.2", ref="(18.41), (18.42)",
       statement="the moving line following P[t] (degree m) and Q[t] (degree n) is L[t] = P[t] x Q[t], of degree generally m + n")
def line_following_two_points():
    rng = random.Random(1841)
    for m, n in ((1, 2), (2, 2), (2, 3), (3, 1)):
        P, Q = _curve(_triples(rng, m + 1)), _curve(_triples(rng, n + 1))
        Lt = P.cross(Q).applyfunc(sp.expand)
        assert sp.expand(Lt.dot(P)) == 0 and sp.expand(Lt.dot(Q)) == 0
        g = sp.gcd_list(list(Lt))
        assert _degree(Lt) == m + n and sp.degree(g, t) == 0  # generic data: degree m + n, no base point
    return verified("(m, n) = (1,2), (2,2), (2,3), (3,1) random integer control points (sympy): P x Q follows both moving points "
                    "and has degree m + n with no common factor",
                    compared="printed (18.41), (18.42) vs sympy cross products and degrees of the expanded components", reference="sympy")


@claim(doc=DOC, section="18.3.3", ref="(18.48)",
       statement="two moving lines of degree m and n intersect at the moving point P[t] = L0[t] x L1[t], of degree generally m + n")
def point_of_two_moving_lines():
    rng = random.Random(1848)
    for m, n in ((1, 2), (2, 2), (1, 3)):
        L0, L1 = _curve(_triples(rng, m + 1)), _curve(_triples(rng, n + 1))
        P = L0.cross(L1).applyfunc(sp.expand)
        assert sp.expand(P.dot(L0)) == 0 and sp.expand(P.dot(L1)) == 0
        assert _degree(P) == m + n and sp.degree(sp.gcd_list(list(P)), t) == 0
    return verified("(m, n) = (1,2), (2,2), (1,3) random moving lines (sympy): L0 x L1 lies on both lines for every t and has degree m + n",
                    compared="printed (18.48) vs sympy cross products", reference="sympy")


@claim(doc=DOC, section="18.3.4", ref="(18.51)",
       statement="if P[tau] = (0, 0, 0) then t - tau divides X, Y, W: P[t] = (t - tau)(X/(t-tau), Y/(t-tau), W/(t-tau)), an equivalent curve of degree one less")
def base_point_factor():
    rng = random.Random(1851)
    for n in (2, 3, 4):
        tv = sp.Rational(rng.randint(1, 9), 10)
        reduced = _curve(_triples(rng, n, 1, 6))  # degree n - 1
        P = (reduced * (t - tv)).applyfunc(sp.expand)  # a degree n curve with a base point at tau
        assert P.subs(t, tv) == sp.zeros(3, 1)
        quot = []
        for e in P:
            q, r = sp.div(sp.Poly(e, t), sp.Poly(t - tv, t))
            assert r.is_zero  # t - tau is a factor of X, Y and W
            quot.append(q.as_expr())
        assert _degree(quot) == n - 1
        for j in range(2):  # same Cartesian curve
            assert sp.cancel(P[j] / P[2] - quot[j] / quot[2]) == 0
    return verified("n = 2, 3, 4 curves with a base point at a random tau (sympy): t - tau divides X, Y, W exactly and the quotient "
                    "is a degree n - 1 curve with the same x = X/W, y = Y/W",
                    compared="printed (18.51) vs sympy polynomial division", reference="sympy")


@claim(doc=DOC, section="18.2.2", ref="weights of P0 and P2",
       statement="P0 lies at the intersection of L00 and L10 with weight d00 d10 sin(theta0), d_ij = sqrt(a_ij^2 + b_ij^2); P2 at L01 x L11 with weight d01 d11 sin(theta1)")
def pencil_control_point_weights():
    d = sp.symbols("d00 d10 d01 d11", positive=True)
    al = sp.symbols("alpha00 alpha10 alpha01 alpha11", real=True)
    cs = sp.symbols("c00 c10 c01 c11")
    # a line with normal of length d at angle alpha: (d cos alpha, d sin alpha, c)
    Lines = [sp.Matrix([di * sp.cos(ai), di * sp.sin(ai), ci]) for di, ai, ci in zip(d, al, cs)]
    L00, L10, L01, L11 = Lines
    for A, B, da, db, aa, ab in ((L00, L10, d[0], d[1], al[0], al[1]), (L01, L11, d[2], d[3], al[2], al[3])):
        P = A.cross(B)
        assert sp.simplify(P.dot(A)) == 0  # on both lines
        assert sp.simplify(P.dot(B)) == 0
        # the weight (third homogeneous coordinate) is d d' sin(theta), theta the angle from the first normal to the second
        assert sp.simplify(P[2] - da * db * sp.sin(ab - aa)) == 0
    # (18.27) uses exactly these: P0 = L00 x L10, P2 = L01 x L11 (the intersections of the pencils at t = 0 and t = 1)
    return verified("symbolic lines (d cos alpha, d sin alpha, c) (sympy): L x L' lies on both lines and its weight is "
                    "d d' sin(alpha' - alpha); theta is the signed angle between the lines (Figure 18.7, which fixes its sense, is lost)",
                    compared="printed weights of P0, P2 vs sympy cross products of symbolic lines", reference="sympy")

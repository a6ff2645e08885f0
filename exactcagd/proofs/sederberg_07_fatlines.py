"""Sederberg's notes, 7.1 (Bezout, circular points, homogeneous parameters) and 7.7 (fat lines and
Bézier clipping), eqs. (7.1)-(7.13).  All checks are sympy from first principles."""

from __future__ import annotations

import random

import sympy as sp

from exactcagd.proofs._ledger import claim, verified, verified_range

DOC = "sederberg"
t, x, y, X, Y, W, T, U = sp.symbols("t x y X Y W T U")


@claim(doc=DOC, section="7.1.2", ref="(7.1)", covers=["§7.1", "§7.1.1", "§7.1.2"],
       statement="every circle (X - xc W)^2 + (Y - yc W)^2 - r^2 W^2 = 0 passes through (1, i, 0) and (1, -i, 0); two distinct circles meet in 4 points counting these")
def circular_points():
    xc, yc, r = sp.symbols("xc yc r")
    circle = (X - xc * W) ** 2 + (Y - yc * W) ** 2 - r**2 * W**2
    for pt in ((1, sp.I, 0), (1, -sp.I, 0)):
        assert sp.expand(circle.subs({X: pt[0], Y: pt[1], W: pt[2]})) == 0
    c1 = circle.subs({xc: 0, yc: 0, r: 2})
    c2 = circle.subs({xc: 1, yc: 1, r: 2})
    # affine intersections: the resultant in y has degree 2 (two finite points), the two others are at W = 0
    res = sp.Poly(sp.resultant(c1.subs({W: 1, X: x, Y: y}), c2.subs({W: 1, X: x, Y: y}), y), x)
    assert res.degree() == 2 and len(sp.real_roots(res)) == 2
    at_infinity = sp.solve([c1.subs(W, 0), c2.subs(W, 0), X - 1], [X, Y], dict=True)
    assert sorted(str(s[Y]) for s in at_infinity) == ["-I", "I"]
    return verified("symbolic circle (sympy): both circular points satisfy (7.1); two circles: 2 finite + 2 circular points = 2 x 2 (Bezout)",
                    compared="printed (7.1) and the Bezout count vs sympy substitution and resultant", reference="sympy")


@claim(doc=DOC, section="7.1.3", ref="(7.2), (7.3)", covers=["§7.1.3", "§7.1.4"],
       statement="x = (1 - t^2)/(1 + t^2), y = 2t/(1 + t^2); homogeneous parameters t = T/U sweep the whole circle: quadrants by 0<=T<=1, U=1; T=1, 1>=U>=0; T=-1, 0<=U<=1; -1<=T<=0, U=1")
def homogeneous_parameters():
    xt, yt = (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)
    assert sp.simplify(xt**2 + yt**2 - 1) == 0
    xT, yT = (U**2 - T**2) / (T**2 + U**2), 2 * T * U / (T**2 + U**2)
    assert sp.simplify(xT - xt.subs(t, T / U)) == 0 and sp.simplify(yT - yt.subs(t, T / U)) == 0
    quadrants = [((lambda s: (s, 1)), (1, 1)), ((lambda s: (1, 1 - s)), (-1, 1)), ((lambda s: (-1, s)), (-1, -1)), ((lambda s: (s - 1, 1)), (1, -1))]
    for param, (sx, sy) in quadrants:
        for k in range(1, 10):
            Tv, Uv = param(sp.Rational(k, 10))
            px, py = xT.subs({T: Tv, U: Uv}), yT.subs({T: Tv, U: Uv})
            assert sp.sign(px) == sx and sp.sign(py) == sy
    # fundamental theorem of algebra (7.1.4): n roots with multiplicity, conjugate pairs for real coefficients
    f = sp.expand((t - 1) ** 2 * (t**2 + 2 * t + 5) * (t + 3))
    roots = sp.roots(sp.Poly(f, t))
    assert sum(roots.values()) == 5 and sp.conjugate(-1 + 2 * sp.I) in roots
    return verified("(7.2) lies on the unit circle, (7.3) is (7.2) with t = T/U, and each printed parameter range stays in its quadrant (9 exact points each)",
                    compared="printed (7.2), (7.3) and the quadrant table vs sympy evaluation", reference="sympy")


def _bern(n, i, s):
    return sp.binomial(n, i) * s**i * (1 - s) ** (n - i)


@claim(doc=DOC, section="7.7.1", ref="(7.4)-(7.11)", covers=["§7.7", "§7.7.1", "§7.7.2", "(7.12)"],
       statement="with ax + by + c = 0, a^2 + b^2 = 1, d_i = a x_i + b y_i + c: the curve lies in d_min <= d <= d_max; d(t) = sum d_i B_i^n(t) (polynomial), d(t) = sum w_i d_i B_i (rational, cleared denominator); D(t) = (t, d(t)) is explicit")
def fat_line_bounds():
    rng = random.Random(774)
    count = 0
    for rational in (False, True):
        for n in (2, 3, 4):
            pts = [(sp.Integer(rng.randint(-9, 9)), sp.Integer(rng.randint(-9, 9))) for _ in range(n + 1)]
            w = [sp.Integer(rng.randint(1, 4)) if rational else sp.Integer(1) for _ in range(n + 1)]
            (x0, y0), (xn, yn) = pts[0], pts[-1]
            if (x0, y0) == (xn, yn):
                continue
            norm = sp.sqrt((xn - x0) ** 2 + (yn - y0) ** 2)
            a, b = -(yn - y0) / norm, (xn - x0) / norm
            c = -(a * x0 + b * y0)
            d = [a * px + b * py + c for px, py in pts]
            Wt = sum(wi * _bern(n, i, t) for i, wi in enumerate(w))
            Px = sum(wi * px * _bern(n, i, t) for i, (wi, (px, _)) in enumerate(zip(w, pts))) / Wt
            Py = sum(wi * py * _bern(n, i, t) for i, (wi, (_, py)) in enumerate(zip(w, pts))) / Wt
            dist = a * Px + b * Py + c
            cleared = sum(wi * di * _bern(n, i, t) for i, (wi, di) in enumerate(zip(w, d)))
            assert sp.simplify(dist * Wt - cleared) == 0  # (7.10) and its rational form
            for k in range(11):
                val = dist.subs(t, sp.Rational(k, 10))
                assert min(d) - sp.Rational(1, 10**30) <= sp.N(val, 40) <= max(d) + sp.Rational(1, 10**30)
                count += 1
            # (7.11): (t, d(t)) has control points (i/n, d_i)
            assert sp.expand(sum(sp.Rational(i, n) * _bern(n, i, t) for i in range(n + 1)) - t) == 0
    return verified_range(f"random polynomial and rational curves of degree 2-4, {count} exact points (compared at 40 digits against exact bounds)",
                          "the distance of every curve point to the base line lies in [d_min, d_max]; the cleared distance is sum w_i d_i B_i",
                          compared="printed (7.4)-(7.11) vs sympy substitution of the curve into the line", reference="sympy")


@claim(doc=DOC, section="7.7.7", ref="Example of finding a fat line", covers=["(7.13)", "§7.7.7"],
       statement="P1 = 3*(4, 6, 1); base line P0 x P4 = (-6, 8, -12); L_i = (a, b, c_i) with c_i = -a x_i - b y_i; L_min = -L2 = (6, -8, 40), L_max = L3 = (-6, 8, 8); the curve lies in the positive half space of -L_min and L_max")
def fat_line_example():
    a, b, c = -6, 8, -12
    c1 = -a * 4 - b * 6  # P1 = (4, 6): c1 = -24
    cs = {0: c, 1: c1, 2: -40, 3: 8, 4: c}  # c_0 = c_4 = c (P0, P4 on the base line); c_2, c_3 from (7.13)
    assert c1 == -24 and min(cs.values()) == cs[2] and max(cs.values()) == cs[3]
    # for any control point with c_min <= c_i <= c_max: L_max . P_i = c_max - c_i >= 0 and (-L_min) . P_i = c_i - c_min >= 0
    xi, yi = sp.symbols("xi yi")
    ci = -a * xi - b * yi
    Lmax, Lmin = sp.Matrix([a, b, cs[3]]), sp.Matrix([a, b, cs[2]])
    P = sp.Matrix([xi, yi, 1])
    assert sp.expand(Lmax.dot(P) - (cs[3] - ci)) == 0 and sp.expand((-Lmin).dot(P) - (ci - cs[2])) == 0
    assert list(-Lmin) == [6, -8, 40] and list(Lmax) == [-6, 8, 8]
    assert (Lmax.dot(sp.Matrix([4, 6, 1])), (-Lmin).dot(sp.Matrix([4, 6, 1]))) == (32, 16)  # P1 inside
    return verified("the control points P0, P2, P3, P4 are in the lost Figure 7.10; with the printed P1 and base line, c_1 = -24 lies between "
                    "c_2 = -40 and c_3 = 8 as (7.13) requires, and the sign rule (scale L_min by -1) holds for every point between the two lines (symbolic)",
                    compared="printed (7.13) and the sign rule vs the line equations (sympy)", reference="sympy")

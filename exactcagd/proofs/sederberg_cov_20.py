"""Sederberg's notes, chapter 20: the curve definitions (20.1) (rational Bézier) and (20.10)
(polynomial Bézier) that the chapter's hybrid-curve and integral rows build on.

Checked in sympy from the Bernstein definitions; no exactcagd function is under test here.
"""

from __future__ import annotations

import random

import sympy as sp

from exactcagd.proofs._ledger import claim, verified, verified_range

DOC = "sederberg"
t, c = sp.symbols("t c")


def _B(n, i, x=t):
    return sp.binomial(n, i) * x**i * (1 - x) ** (n - i)


def _rational(points, weights):
    """(20.1): R(t) = sum B_i^r w_i R_i / sum B_i^r w_i, componentwise (x_R, y_R)."""
    r = len(points) - 1
    den = sum(_B(r, i) * w for i, w in enumerate(weights))
    return [sum(_B(r, i) * w * p[k] for i, (p, w) in enumerate(zip(points, weights))) / den for k in range(2)]


def _polynomial(points):
    """(20.10): P(t) = sum B_i^n P_i = (x_P, y_P)."""
    n = len(points) - 1
    return [sp.expand(sum(_B(n, i) * p[k] for i, p in enumerate(points))) for k in range(2)]


@claim(doc=DOC, section="20", ref="(20.1), (20.10)",
       statement="R(t) = sum B_i^r w_i R_i / sum B_i^r w_i = (x_R, y_R) is a degree r plane rational Bézier curve; P(t) = sum B_i^n P_i = (x_P, y_P) a degree n plane Bézier curve")
def curve_definitions():
    rng = random.Random(2001)
    for r in (1, 2, 3, 4):
        pts = [[sp.Rational(rng.randint(-9, 9), rng.randint(1, 3)) for _ in range(2)] for _ in range(r + 1)]
        w = [sp.Rational(rng.randint(1, 9), rng.randint(1, 3)) for _ in range(r + 1)]
        R = _rational(pts, w)
        # end points R(0) = R_0, R(1) = R_r; a common factor of the weights leaves R unchanged
        assert [v.subs(t, 0) for v in R] == pts[0] and [v.subs(t, 1) for v in R] == pts[-1]
        assert all(sp.cancel(a - b) == 0 for a, b in zip(R, _rational(pts, [c * wi for wi in w])))
        # equal weights: (20.1) is the polynomial curve (20.10), of degree <= r in t (partition of unity)
        P = _polynomial(pts)
        assert all(sp.cancel(a - b) == 0 for a, b in zip(_rational(pts, [c] * (r + 1)), P))
        assert all(sp.Poly(p, t).degree() <= r for p in P)
        # x_R, y_R are quotients of degree-r polynomials: the numerator/denominator degrees are r (generic data)
        num, den = sp.fraction(sp.cancel(R[0]))
        assert max(sp.degree(num, t), sp.degree(den, t)) <= r
    return verified("r = 1..4 random rational control points and weights (sympy): R(0) = R_0, R(1) = R_r, invariant under w -> c w; "
                    "equal weights give (20.10), a polynomial of degree <= r",
                    compared="printed (20.1), (20.10) vs sympy Bernstein expansion (end points, weight scaling, equal weights)",
                    reference="sympy")


def _hybrid_as_printed(pts, w, n, m):
    """P_i and M_i exactly as printed in (20.4)-(20.6) (sympy rationals; no package code)."""
    r = len(pts) - 1
    R = [sp.Matrix(p) for p in pts]
    C = sp.binomial
    P = [None] * (n + 1)
    P[0] = R[0]
    for i in range(1, m):  # (20.4), i = 1 .. m - 1
        acc = sum((C(r, j) * C(n, i - j) * w[j] * (R[j] - P[i - j]) for j in range(1, min(r, i) + 1)), sp.zeros(2, 1))
        P[i] = R[0] + acc / (w[0] * C(n, i))
    P[n] = R[r]
    for i in range(n + r - 1, m + r, -1):  # (20.5), i = n + r - 1 down to m + 1 + r (i = n + r gives P_n = R_r)
        acc = sum((C(r, j) * C(n, i - j) * w[j] * (R[j] - P[i - j]) for j in range(max(0, i - n), r)), sp.zeros(2, 1))
        P[i - r] = R[r] + acc / (w[r] * C(n, i - r))
    M = []
    for i in range(r + 1):  # (20.6)
        acc = sum((C(r, j) * C(n, i + m - j) * w[j] * (R[j] - P[i + m - j])
                   for j in range(max(0, i + m - n), min(i + m, r) + 1) if j != i), sp.zeros(2, 1))
        M.append(R[i] + acc / (w[i] * C(n, m) * C(r, i)))
    return P, M


@claim(doc=DOC, section="20", ref="(20.2)-(20.6) as printed",
       statement="H(t) = sum_{i != m} B_i^n P_i + M(t) B_m^n equals R(t) for P_i, M_i computed from the printed (20.4)-(20.6); M(t) has the weights w_i")
def hybrid_formulas_as_printed():
    rng = random.Random(2046)
    for _ in range(8):
        r, n = rng.randint(1, 3), rng.randint(2, 5)
        m = rng.randint(1, n - 1)
        pts = [[sp.Rational(rng.randint(-9, 9), rng.randint(1, 3)) for _ in range(2)] for _ in range(r + 1)]
        w = [sp.Rational(rng.randint(1, 9), rng.randint(1, 3)) for _ in range(r + 1)]
        P, M = _hybrid_as_printed(pts, w, n, m)
        Mt = _rational([list(v) for v in M], w)  # (20.3): the moving point with the original weights
        H = [sum(_B(n, i) * P[i][k] for i in range(n + 1) if i != m) + _B(n, m) * Mt[k] for k in range(2)]
        assert all(sp.cancel(a - b) == 0 for a, b in zip(H, _rational(pts, w)))
    return verified_range("8 random rational curves, r = 1..3, n = 2..5, m drawn in 1..n-1",
                          "the printed recurrences (20.4)-(20.6) implemented directly in sympy give H(t) = R(t) as rational functions "
                          "(the (20.2)-(20.6) row checks the package's implementation of them)",
                          compared="printed (20.4)-(20.6) vs sympy identity H(t) = R(t) of (20.2)", reference="sympy")

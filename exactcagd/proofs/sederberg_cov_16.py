"""Sederberg's notes, chapter 16 items without a row: the homogeneous curve (16.1)-(16.2) (printed
"surface") and the tensor-product patch (16.11)-(16.12).  Chapter 15.8 repeats both as
(15.24)-(15.25) and (15.34)-(15.35); those rows use the helpers here.

Every check is sympy from first principles (projection of the homogeneous Bernstein sums,
Jacobian ranks); no exactcagd function is under test here.
"""

from __future__ import annotations

import random

import sympy as sp

from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified

DOC = "sederberg"
s, t, c = sp.symbols("s t c")


def _B(n, i, var):
    return sp.binomial(n, i) * var**i * (1 - var) ** (n - i)


def project(P):
    """Pi(x, y, z, w) = (x/w, y/w, z/w)."""
    return [sp.cancel(P[k] / P[3]) for k in range(3)]


def random_curve_data(rng, n):
    pts = [[sp.Rational(rng.randint(-9, 9), rng.randint(1, 3)) for _ in range(3)] for _ in range(n + 1)]
    w = [sp.Rational(rng.randint(1, 9), rng.randint(1, 3)) for _ in range(n + 1)]
    return pts, w


def homogeneous_curve(pts, w):
    """(16.2): P(t) = sum P_i B_i^n(t), P_i = w_i (x_i, y_i, z_i, 1)."""
    n = len(pts) - 1
    return [sp.expand(sum(w[i] * (list(p) + [1])[k] * _B(n, i, t) for i, p in enumerate(pts))) for k in range(4)]


def homogeneous_patch(pts, w):
    """(16.12): P(s, t) = sum sum P_ij B_i^m(s) B_j^n(t), P_ij = w_ij (x_ij, y_ij, z_ij, 1)."""
    m, n = len(pts) - 1, len(pts[0]) - 1
    return [sp.expand(sum(w[i][j] * (list(pts[i][j]) + [1])[k] * _B(m, i, s) * _B(n, j, t)
                          for i in range(m + 1) for j in range(n + 1))) for k in range(4)]


def check_rational_curve(rng):
    """Pi(P(t)) of (16.1)-(16.2) is the rational Bézier curve sum w_i p_i B_i / sum w_i B_i through p_0, p_n:
    a one-parameter image (Jacobian rank 1).  Returns the rank."""
    for n in (2, 3):
        pts, w = random_curve_data(rng, n)
        P = homogeneous_curve(pts, w)
        # Pi(P) = num / den: the w component is the denominator, x, y, z the numerators
        assert sp.expand(P[3] - sum(w[i] * _B(n, i, t) for i in range(n + 1))) == 0
        for k in range(3):
            assert sp.expand(P[k] - sum(w[i] * pts[i][k] * _B(n, i, t) for i in range(n + 1))) == 0
        p = project(P)
        assert [v.subs(t, 0) for v in p] == pts[0] and [v.subs(t, 1) for v in p] == pts[-1]
        # a common factor of the weights does not change the curve
        assert all(sp.cancel(a - b) == 0 for a, b in zip(project(homogeneous_curve(pts, [c * wi for wi in w])), p))
    return sp.Matrix([p]).jacobian([t]).subs(t, sp.Rational(1, 3)).rank()


def check_rational_patch(rng):
    """Pi(P(s, t)) of (16.11)-(16.12) is the tensor-product rational surface (15.2) with corners p_00, p_m0, p_0n,
    p_mn and a two-dimensional image (Jacobian rank 2 at a sample parameter)."""
    m, n = 2, 3
    pts = [[[sp.Rational(rng.randint(-9, 9), rng.randint(1, 3)) for _ in range(3)] for _ in range(n + 1)] for _ in range(m + 1)]
    w = [[sp.Rational(rng.randint(1, 9), rng.randint(1, 3)) for _ in range(n + 1)] for _ in range(m + 1)]
    P = homogeneous_patch(pts, w)
    den = sum(w[i][j] * _B(m, i, s) * _B(n, j, t) for i in range(m + 1) for j in range(n + 1))
    assert sp.expand(P[3] - den) == 0
    for k in range(3):  # (15.2): Pi(P) = num / den
        num = sum(w[i][j] * pts[i][j][k] * _B(m, i, s) * _B(n, j, t) for i in range(m + 1) for j in range(n + 1))
        assert sp.expand(P[k] - num) == 0
    p = project(P)
    for (sv, tv), (i, j) in (((0, 0), (0, 0)), ((1, 0), (m, 0)), ((0, 1), (0, n)), ((1, 1), (m, n))):
        assert [v.subs({s: sv, t: tv}) for v in p] == pts[i][j]
    J = sp.Matrix([p]).jacobian([s, t]).subs({s: sp.Rational(1, 3), t: sp.Rational(2, 5)})
    return J.rank()


@claim(doc=DOC, section="16", ref="(16.1), (16.2)",
       statement="A rational Bézier surface in R^3 is defined p(t) = Pi(P(t)) with P(t) = sum P_i B_i^n(t), P_i = w_i(x_i, y_i, z_i, 1)")
def curve_called_surface():
    rank = check_rational_curve(random.Random(161))
    kind = {1: "curve", 2: "surface"}[rank]

    def names_the_object(word):
        return None if word == kind else f"p(t) = Pi(P(t)) has one parameter: its Jacobian has rank {rank}, a {kind}, not a {word}"

    return erratum("A rational Bézier surface in R^3 is defined p(t) = Pi(P(t))", "A rational Bézier curve in R^3 is defined p(t) = Pi(P(t))",
                   "Pi(P(t)) is the rational Bézier curve sum w_i p_i B_i / sum w_i B_i (n = 2, 3, sympy), one parameter; the next "
                   "sentence says 'this curve' and the same text in 15.8 (15.24) says 'curve'",
                   printed_form="surface", corrected_form="curve", check=L.predicate(names_the_object), reference="sympy")


@claim(doc=DOC, section="16", ref="(16.11), (16.12)",
       statement="a tensor-product rational Bézier patch p(s, t) = Pi(P(s, t)), P(s, t) = sum sum P_ij B_i^m(s) B_j^n(t)")
def patch_definition():
    assert check_rational_patch(random.Random(1611)) == 2
    return verified("m = 2, n = 3 random control points and weights (sympy): Pi(P(s, t)) = sum w_ij p_ij B B / sum w_ij B B (15.2), "
                    "interpolates the four corners, Jacobian rank 2 at (1/3, 2/5)",
                    compared="printed (16.11), (16.12) vs sympy projection of the homogeneous sum and the rational form (15.2)",
                    reference="sympy")


@claim(doc=DOC, section="16", ref="(16.9) argument of Q-hat",
       statement="Pi(Q(t)) = Pi((1-t)^(n-1) Q^(u)) = Pi(Q^(t)), u = t/(1-t), Q^(u) = sum C(n-1, i) P_i u^i (printed the same in (15.32))",
       covers=["(15.32)"])
def pseudo_basis_argument():
    rng = random.Random(169)
    u = sp.Symbol("u")
    cases = []
    for n in (2, 3, 4):
        pts, w = random_curve_data(rng, n)
        H = [[wi * x for x in p] + [wi] for p, wi in zip(pts, w)]
        Q = [sum(H[i][k] * _B(n - 1, i, t) for i in range(n)) for k in range(4)]  # (16.4)
        Qhat = [sum(sp.binomial(n - 1, i) * H[i][k] * u**i for i in range(n)) for k in range(4)]  # (16.7)
        cases.append((n, project(Q), Qhat))

    def projects_like_Q(arg):
        for n, pQ, Qhat in cases:
            got = project([q.subs(u, arg) for q in Qhat])
            bad = [k for k in range(3) if sp.cancel(got[k] - pQ[k]) != 0]
            if bad:
                tv = sp.Rational(1, 3)
                return (f"at t = 1/3: Pi(Q^(arg)) = {[g.subs(t, tv) for g in got]}, Pi(Q(t)) = {[q.subs(t, tv) for q in pQ]} "
                        f"(degree {n} curve)")
        return None

    return erratum("Pi(Q(t)) = Pi((1-t)^(n-1) Q^(u)) = Pi(Q^(t))", "... = Pi(Q^(u)), u = t/(1-t)",
                   "Q^ is the pseudo-basis polynomial in u (16.7); evaluated at t it is a different point (n = 2, 3, 4 random "
                   "rational curves, sympy). The same slip is printed in (15.32)",
                   printed_form=t, corrected_form=t / (1 - t), check=L.predicate(projects_like_Q), reference="sympy")

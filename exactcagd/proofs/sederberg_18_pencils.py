"""Sederberg's notes, 18.2.1 pencils of lines (18.17)-(18.24) and 18.3.5 / 18.4.1-18.4.2 axial moving
lines (18.52)-(18.60).  All checks are sympy from first principles (cross products, expansions)."""

from __future__ import annotations

import random

import sympy as sp

from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, reconstructed, verified

DOC = "sederberg"
t, tau = sp.symbols("t tau")


def _bern(points, var=t):
    n = len(points) - 1
    return sum((sp.binomial(n, i) * var**i * (1 - var) ** (n - i) * sp.Matrix(p) for i, p in enumerate(points)), sp.zeros(3, 1))


@claim(doc=DOC, section="18.2.1", ref="(18.17)-(18.24)", covers=["§18.2.1"],
       statement="pencil L[t] = L0 (1-t) + L1 t through the axis L0 x L1; a parameter line (1-t) P0 + t P1 follows it when d0/d1 = |(a0,b0)|/|(a1,b1)|; CCW iff a0 b1 > a1 b0; L[t] = P_A x P[t] with L_i = P_A x P_i and d0/d1 = |P_A P0| W0/(|P_A P1| W1)")
def pencil_of_lines():
    rng = random.Random(1817)
    solved = 0
    for _ in range(4):
        L0, L1 = (sp.Matrix([rng.randint(-5, 5) for _ in range(3)]) for _ in range(2))
        if L0.cross(L1)[2] == 0:
            continue
        axis = L0.cross(L1)
        Lt = L0 * (1 - t) + L1 * t
        assert sp.expand(Lt.dot(axis)) == 0  # every line of the pencil contains the axis
        A = sp.Matrix([axis[0] / axis[2], axis[1] / axis[2], 1])
        # points on L0, L1 at distances d0, d1 from the axis (unit directions along the lines)
        d0, d1 = sp.symbols("d0 d1", positive=True)
        u0 = sp.Matrix([-L0[1], L0[0], 0]) / sp.sqrt(L0[0] ** 2 + L0[1] ** 2)
        u1 = sp.Matrix([-L1[1], L1[0], 0]) / sp.sqrt(L1[0] ** 2 + L1[1] ** 2)
        for s0, s1 in ((1, 1), (1, -1)):
            P0, P1 = A + s0 * d0 * u0, A + s1 * d1 * u1
            follow = sp.expand(Lt.dot(P0 * (1 - t) + P1 * t))  # quadratic in t, zero at t = 0, 1: one condition
            sol = sp.solve(follow.coeff(t, 1), d0)
            if sol:
                solved += 1
                assert sp.simplify(sol[0] / d1 - sp.sqrt(L0[0] ** 2 + L0[1] ** 2) / sp.sqrt(L1[0] ** 2 + L1[1] ** 2)) == 0
        # (18.20): the normal (a, b) turns counter-clockwise iff a0 b1 - a1 b0 > 0
        turn = sp.Matrix([Lt[0], Lt[1], 0]).cross(sp.Matrix([sp.diff(Lt[0], t), sp.diff(Lt[1], t), 0]))[2]
        assert sp.expand(turn - (L0[0] * L1[1] - L1[0] * L0[1])) == 0
    assert solved >= 2
    # (18.21)-(18.24): P_A x P[t] is the pencil of the lines P_A x P_i; distance ratio with weights
    PA = sp.Matrix([2, 1, 1])
    P0, P1 = sp.Matrix([6, 2, 2]), sp.Matrix([3, 9, 3])  # (3, 1) weight 2, (1, 3) weight 3
    Lt = PA.cross(P0 * (1 - t) + P1 * t)
    L0, L1 = PA.cross(P0), PA.cross(P1)
    assert (Lt - (L0 * (1 - t) + L1 * t)).applyfunc(sp.expand) == sp.zeros(3, 1)
    n0, n1 = sp.sqrt(L0[0] ** 2 + L0[1] ** 2), sp.sqrt(L1[0] ** 2 + L1[1] ** 2)
    dist = lambda P: sp.sqrt((P[0] / P[2] - 2) ** 2 + (P[1] / P[2] - 1) ** 2)  # noqa: E731
    assert sp.simplify(n0 / n1 - dist(P0) * P0[2] / (dist(P1) * P1[2])) == 0
    return verified("random integer pencils (sympy): the axis lies on every line, the parameter line follows the pencil exactly when "
                    "d0/d1 = |(a0,b0)|/|(a1,b1)| (18.19), the normal turns with a0 b1 - a1 b0 (18.20); P_A x P[t] = (P_A x P0)(1-t) + "
                    "(P_A x P1) t and (18.24) = (18.19) for the lines (18.23)",
                    compared="printed (18.17)-(18.24) vs sympy cross products and the following condition L[t].P[t] = 0",
                    reference="sympy")


@claim(doc=DOC, section="18.2.1", ref="(18.18)", statement="the parameter line P[t] = (1-t) P0 + t P")
def parameter_line_subscript():
    L0, L1 = sp.Matrix([1, -1, 0]), sp.Matrix([1, 1, -2])  # axis (1, 1)
    P0, P1 = sp.Matrix([0, 0, 1]), sp.Matrix([2, 0, 1])  # P0 on L0, P1 on L1

    def ends_on_L1(end):
        return None if L1.dot(end) == 0 else f"the end point {list(end)} of the parameter line is not on L1"

    return reconstructed(
        "P[t] = (1-t) P0 + t P",
        "P[t] = (1-t) P0 + t P1 (P1 on L1, as the next sentence says)",
        "the subscript of the end point is lost; the text places P1 on L1 at distance d1 from the axis",
        printed_form=L.LOST, lost_reason="the subscript 1 of P1 is missing in (18.18)", corrected_form=P1,
        check=L.predicate(ends_on_L1), reference="text",
    )


@claim(doc=DOC, section="18.3.5", ref="(18.52)-(18.55)", covers=["§18.3.5", "§18.4.1"],
       statement="axial moving line L[t] = P_A x P[t] with control lines L_i = P_A x P_i through the axis; for P_A = P[tau] on the curve it has a base point and reduces to degree n - 1")
def axial_moving_line():
    rng = random.Random(1852)
    for n in (2, 3, 4):
        pts = [[rng.randint(-6, 6), rng.randint(-6, 6), rng.randint(1, 3)] for _ in range(n + 1)]
        PA = sp.Matrix([rng.randint(-6, 6), rng.randint(-6, 6), 1])
        Lt = PA.cross(_bern(pts))
        lines = [PA.cross(sp.Matrix(p)) for p in pts]
        assert (Lt - _bern(lines)).applyfunc(sp.expand) == sp.zeros(3, 1)
        assert all(li.dot(PA) == 0 for li in lines)
        tv = sp.Rational(rng.randint(1, 9), 10)
        on = _bern(pts).subs(t, tv)
        Lon = on.cross(_bern(pts))
        g = sp.Poly(sp.gcd_list([sp.expand(c) for c in Lon]), t)
        assert g.degree() >= 1 and sp.expand(g.as_expr().subs(t, tv)) == 0  # base point t = tau: degree n - 1
    return verified("n = 2, 3, 4, random rational curves (sympy): P_A x P[t] has the control lines P_A x P_i (all through P_A); "
                    "with P_A = P[tau] every component has the factor (t - tau)",
                    compared="printed (18.52)-(18.55) vs sympy expansion of the cross products and their polynomial gcd",
                    reference="sympy")


@claim(doc=DOC, section="18.4.2", ref="(18.59), (18.60)", statement="an axis on a double point gives two base points L[tau0] = L[tau1] = 0; the cubic (0,0),(0,1),(1,2),(3,0): P_3 x P[t] = (t-1)(t+1){(0,3,0)(1-t) + (3,3,-9)t}")
def axial_double_point():
    pts = [(0, 0, 1), (0, 1, 1), (1, 2, 1), (3, 0, 1)]
    P = _bern(pts)
    Lt = (sp.Matrix([3, 0, 1]).cross(P)).applyfunc(sp.expand)
    printed = ((t - 1) * (t + 1) * (sp.Matrix([0, 3, 0]) * (1 - t) + sp.Matrix([3, 3, -9]) * t)).applyfunc(sp.expand)
    assert Lt == printed
    assert (Lt - ((t - 1) * sp.Matrix([3 * t**2 + 3 * t, 3 * t + 3, -9 * t**2 - 9 * t])).applyfunc(sp.expand)).applyfunc(sp.expand) == sp.zeros(3, 1)
    # (3, 0) is a double point of the cubic: P(1) = P(-1) = (3, 0)
    assert [sp.simplify(P[i] / P[2]).subs(t, -1) for i in range(2)] == [3, 0]
    return verified("(18.60) line by line (sympy); P(-1) = P(1) = (3, 0) is the double point, the base points are t = +-1",
                    compared="printed (18.60) vs sympy expansion of P_3 x P[t]", reference="sympy")

"""Lasser & Bonneau (000), section VIII: cubic G1 approximation, eqs. (19)-(22)."""

from __future__ import annotations

from fractions import Fraction as Fr

import sympy

from exactcagd.composition import compose
from exactcagd.composition.cubic_approx import _reparametrization, approximate_cubic_curve, fit_cubic
from exactcagd.composition.distance_bound import distance_bound
from exactcagd.composition.paper_examples import figure5
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified

t = sympy.Symbol("t")


def _bern(n, i, x):
    return sympy.binomial(n, i) * x**i * (1 - x) ** (n - i)


def _points(name, count, dim=2):
    return [sympy.Matrix(sympy.symbols(f"{name}{k}_0:{dim}")) for k in range(count)]


@claim(doc="lasser", section="VIII", ref="(19), (20)", statement="b0 = B0, b1 = B0 + l1 (B1 - B0), b3 = B_rN, b2 = B_rN + l2 (B_rN-1 - B_rN): end points and end tangents of F(t)")
def eq20():
    lam1, lam2 = sympy.symbols("lambda1 lambda2")
    for n in (2, 4, 5):
        B = _points("B", n + 1)
        w = sympy.symbols(f"w0:{n + 1}")
        b = [B[0], B[0] + lam1 * (B[1] - B[0]), B[n] + lam2 * (B[n - 1] - B[n]), B[n]]
        X = sum((b[k] * _bern(3, k, t) for k in range(4)), sympy.zeros(2, 1))
        num = sum((w[i] * B[i] * _bern(n, i, t) for i in range(n + 1)), sympy.zeros(2, 1))
        den = sum(w[i] * _bern(n, i, t) for i in range(n + 1))
        F = num / den
        dF, dX = F.diff(t), X.diff(t)
        for end in (0, 1):
            assert sympy.simplify(X.subs(t, end) - F.subs(t, end)) == sympy.zeros(2, 1)
            cross = dF.subs(t, end)[0] * dX.subs(t, end)[1] - dF.subs(t, end)[1] * dX.subs(t, end)[0]
            assert sympy.simplify(cross) == 0
        # the end derivatives: X'(0) = 3 l1 (B1 - B0), F'(0) = n w1/w0 (B1 - B0)
        assert sympy.simplify(dF.subs(t, 0) - n * w[1] / w[0] * (B[1] - B[0])) == sympy.zeros(2, 1)
    return verified("symbolic rational F of degree rN in {2, 4, 5}: X and F share end points, and X'(0), X'(1) are parallel to F'(0), F'(1) for all lambda (G1)",
        compared="printed (19)-(20) control points b0..b3 vs sympy: X(t) - F(t) at t = 0, 1 and the cross products X'(end) x F'(end) of the symbolic cubic and a symbolic rational F of degree rN in {2, 4, 5}, simplified to 0 for all lambda1, lambda2",
        reference='sympy',
    )


@claim(doc="lasser", section="VIII", ref="(21), (22)", statement="d = sum_l [D_l - l1 (B1 - B0) B^3_1(t_l) - l2 (B_rN-1 - B_rN) B^3_2(t_l)]^2 with D_l = P_l - B0 (B^3_0 + B^3_1) - B_rN (B^3_2 + B^3_3)")
def eq21_22():
    lam1, lam2 = sympy.symbols("lambda1 lambda2")
    B0, B1, Bm, Bn = _points("B", 4)  # B_0, B_1, B_{rN-1}, B_{rN}
    L = 4
    ts = sympy.symbols(f"t0:{L + 1}")
    P = _points("P", L + 1)
    b = [B0, B0 + lam1 * (B1 - B0), Bn + lam2 * (Bm - Bn), Bn]
    direct = sum(((P[k] - sum((b[j] * _bern(3, j, ts[k]) for j in range(4)), sympy.zeros(2, 1))).dot(P[k] - sum((b[j] * _bern(3, j, ts[k]) for j in range(4)), sympy.zeros(2, 1))) for k in range(L + 1)))
    formula = 0
    for k in range(L + 1):
        D = P[k] - B0 * _bern(3, 0, ts[k]) - B0 * _bern(3, 1, ts[k]) - Bn * _bern(3, 2, ts[k]) - Bn * _bern(3, 3, ts[k])
        e = D - lam1 * (B1 - B0) * _bern(3, 1, ts[k]) - lam2 * (Bm - Bn) * _bern(3, 2, ts[k])
        formula += e.dot(e)
    assert sympy.expand(direct - formula) == 0
    # d is a convex quadratic in (lambda1, lambda2): its Hessian is twice the Gram matrix of the
    # vectors a1_l = (B1 - B0) B^3_1(t_l), a2_l = (B_rN-1 - B_rN) B^3_2(t_l) (positive semidefinite),
    # so the solution of the normal equations dd/dlambda = 0 is a minimum
    H = sympy.hessian(formula, (lam1, lam2))
    a1 = [(B1 - B0) * _bern(3, 1, ts[k]) for k in range(L + 1)]
    a2 = [(Bm - Bn) * _bern(3, 2, ts[k]) for k in range(L + 1)]
    G = sympy.Matrix([[sum(x.dot(y) for x, y in zip(p, q)) for q in (a1, a2)] for p in (a1, a2)])
    assert sympy.expand(H - 2 * G) == sympy.zeros(2, 2)
    return verified(
        "symbolic points P_l, B, parameters t_l (L = 4, planar): (21) with (22) equals sum |P_l - X(t_l)|^2 after "
        "substituting (20); its Hessian in (lambda1, lambda2) is twice a Gram matrix, so the normal equations give the minimum",
        compared='printed (21) with D_l of (22) vs sympy expansion of sum_l |P_l - X(t_l)|^2 with (20) substituted (symbolic P_l, B, t_l, L = 4); its Hessian vs twice the Gram matrix',
        reference='sympy',
    )


@claim(doc="lasser", section="VIII", ref="section VIII algorithm", statement="the algorithm results in a spline curve with a minimal number of cubic Bézier curve segments")
def minimal_segments():
    fig = figure5()
    F = compose(fig["surface"], fig["curves"][0])
    tol = Fr(1, 100)
    greedy = approximate_cubic_curve(F, tol)
    assert len(greedy.segments) == 3 and greedy.tolerance_met
    left, right = F.subdivide(Fr(21, 40))
    for piece in (left, right):
        cubic, _, ts, params, _ = fit_cubic(piece)
        assert distance_bound(piece, cubic, _reparametrization(ts, params)) <= tol
    def no_more_than_exhibited(count):
        # a certified 2-cubic spline within tol exists (split at 21/40): a minimal count cannot exceed 2
        return None if count <= 2 else f"{count} cubics, but F split at t = 21/40 gives 2 cubics with certified bounds <= 1/100"
    return erratum(
        "The algorithm results in a spline curve with a minimal number of cubic Bézier curve segments",
        "splitting at the point of maximal error does not minimize the number of segments in general",
        "figure-5 cubic on the bicubic patch, tol 1/100: splitting at the maximal error gives 3 cubics, while splitting "
        "F at t = 21/40 gives 2 cubics whose certified Hausdorff bounds are both <= 1/100",
        printed_form=len(greedy.segments), corrected_form=2, check=L.predicate(no_more_than_exhibited), reference='independent-algorithm',
    )

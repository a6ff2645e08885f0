"""Sederberg's notes, 15.9.1: the fundamental forms at the corner of a rational tensor-product patch,
eqs. (15.45)-(15.53), checked by sympy differentiation of the patch (15.45) itself."""

from __future__ import annotations

import random

import sympy as sp

from exactcagd.proofs._ledger import claim, verified

u, v = sp.symbols("u v")


@claim(doc="sederberg", section="15.9.1", ref="(15.45)-(15.53)",
       statement="r_u(0,0) = n w10/w00 a, r_v = m w01/w00 b; E, F, G = n^2 (w10/w00)^2 a.a, nm w10 w01/w00^2 a.b, m^2 (w01/w00)^2 b.b; "
       "L, M, N = n(n-1) w20/w00 h20, nm w11/w00 h11, m(m-1) w02/w00 h02 (K_g, K_m by (15.46), (15.47))")
def corner_fundamental_forms():
    rng = random.Random(1545)
    for n, m in ((3, 2),):
        P = [[sp.Matrix([rng.randint(-4, 4) + i, rng.randint(-4, 4) + j, rng.randint(-3, 3)]) for j in range(m + 1)] for i in range(n + 1)]
        w = [[sp.Integer(rng.randint(1, 4)) for _ in range(m + 1)] for _ in range(n + 1)]
        B = lambda k, i, x: sp.binomial(k, i) * x**i * (1 - x) ** (k - i)  # noqa: E731
        W = sum(w[i][j] * B(n, i, u) * B(m, j, v) for i in range(n + 1) for j in range(m + 1))
        r = sum((w[i][j] * P[i][j] * B(n, i, u) * B(m, j, v) for i in range(n + 1) for j in range(m + 1)), sp.zeros(3, 1)) / W
        at0 = {u: 0, v: 0}
        ru, rv = r.diff(u).subs(at0), r.diff(v).subs(at0)
        ruu, ruv, rvv = r.diff(u, 2).subs(at0), r.diff(u, v).subs(at0), r.diff(v, 2).subs(at0)
        a, b = P[1][0] - P[0][0], P[0][1] - P[0][0]
        assert (ru - n * w[1][0] / w[0][0] * a).applyfunc(sp.simplify) == sp.zeros(3, 1)  # (15.51)
        assert (rv - m * w[0][1] / w[0][0] * b).applyfunc(sp.simplify) == sp.zeros(3, 1)
        E, F, G = ru.dot(ru), ru.dot(rv), rv.dot(rv)
        assert sp.simplify(E - n**2 * (w[1][0] / w[0][0]) ** 2 * a.dot(a)) == 0  # (15.52)
        assert sp.simplify(F - n * m * w[1][0] * w[0][1] / w[0][0] ** 2 * a.dot(b)) == 0
        assert sp.simplify(G - m**2 * (w[0][1] / w[0][0]) ** 2 * b.dot(b)) == 0
        N_ = a.cross(b) / sp.sqrt(a.cross(b).dot(a.cross(b)))
        h = lambda i, j: (P[i][j] - P[0][0]).dot(N_)  # noqa: E731 - signed distance to the plane P00 P10 P01
        Lf, Mf, Nf = ruu.dot(N_), ruv.dot(N_), rvv.dot(N_)
        assert sp.simplify(Lf - n * (n - 1) * w[2][0] / w[0][0] * h(2, 0)) == 0  # (15.53)
        assert sp.simplify(Mf - n * m * w[1][1] / w[0][0] * h(1, 1)) == 0
        assert sp.simplify(Nf - m * (m - 1) * w[0][2] / w[0][0] * h(0, 2)) == 0
        # (15.46), (15.47) with these values agree with (15.54), (15.55)
        Kg = (Lf * Nf - Mf**2) / (E * G - F**2)
        ab2 = a.cross(b).dot(a.cross(b))
        K54 = (w[0][0] / (w[1][0] * w[0][1])) ** 2 * (sp.Rational(n - 1, n) * sp.Rational(m - 1, m) * w[2][0] * w[0][2] * h(2, 0) * h(0, 2) - w[1][1] ** 2 * h(1, 1) ** 2) / ab2
        assert sp.simplify(Kg - K54) == 0
    return verified("bidegree (3, 2), a random rational patch: every printed corner quantity equals sympy's derivative of "
                    "(15.45) at (0, 0); (15.46) with (15.52), (15.53) gives (15.54)",
                    compared="printed (15.51)-(15.53) vs sympy differentiation of the rational patch (15.45)", reference="sympy")


@claim(doc="sederberg", section="15.7.1", ref="(15.12)", statement="P(s, t) = sum_{i=0}^{27} w_i P_i B_i(s, t) / sum_{i=1}^{n} w_i B_i(s, t)")
def tspline_sum_limits():
    from exactcagd.proofs import _ledger as L

    def same_control_points(limits):
        (lo_num, hi_num), (lo_den, hi_den) = limits
        # a rational surface needs numerator and denominator over the same weighted control points; with 28 points
        # (i = 0..27) and unit weights the denominator must be the partition of unity over those 28 functions
        return None if (lo_num, hi_num) == (lo_den, hi_den) else f"numerator over i = {lo_num}..{hi_num}, denominator over i = {lo_den}..{hi_den}"

    n = sp.Symbol("n")
    return L.erratum(
        "sum_{i=0}^{27} in the numerator, sum_{i=1}^{n} in the denominator",
        "sum_{i=0}^{27} in both (the 28 control points of the example)",
        "the two sums of one rational form must run over the same control points",
        printed_form=((0, 27), (1, n)), corrected_form=((0, 27), (0, 27)), check=L.predicate(same_control_points), reference="text",
    )


@claim(doc="sederberg", section="15.9.2", ref="(15.58)", statement="r(u, v) = sum_{i+j+k=n} w_ijk P_ijk B^n_ijk(u, v) / sum_{i+j+k+n} w_ijk B^n_ijk(u, v)")
def triangular_patch_index():
    from exactcagd.proofs import _ledger as L

    n = 3
    target = {(i, j, n - i - j) for i in range(n + 1) for j in range(n + 1 - i)}

    def selects_degree_n(condition):
        got = {(i, j, k) for i in range(n + 1) for j in range(n + 1) for k in range(n + 1) if condition(i, j, k, n) is True}
        return None if got == target else f"the condition selects {len(got)} index triples, the degree-{n} triangle has {len(target)}"

    u, v = sp.symbols("u v")
    B = lambda i, j, k: sp.factorial(n) / (sp.factorial(i) * sp.factorial(j) * sp.factorial(k)) * u**i * v**j * (1 - u - v) ** k  # noqa: E731
    assert sp.expand(sum(B(*ijk) for ijk in target) - 1) == 0  # the corrected denominator with unit weights is 1
    return L.reconstructed(
        "denominator sum over i+j+k+n",
        "denominator sum over i+j+k=n (as in the numerator)",
        "'+' for '=' in the extraction; with i+j+k=n the unit-weight denominator is the partition of unity (sympy)",
        printed_form=lambda i, j, k, n_: i + j + k + n_, corrected_form=lambda i, j, k, n_: i + j + k == n_,
        check=L.predicate(selects_degree_n),
    )

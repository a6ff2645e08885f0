"""Yang et al. (004), section 5: the s/t-parabolas, eqs. (6)-(17), Theorems 1 and 2, the cubic
rational Bézier form of the parabola, and the degree claims.

Notation: the s-parabola is the iso-line s = 1/2 of the cubic reparameterization (5)
with beta_1 = beta_2 = beta_3 = beta; there ``u = 1 - alpha(t)`` and ``v = M_beta(t)``.
"""

from __future__ import annotations

import random

import sympy
from gmpy2 import mpq

from exactcagd import BezierSurface
from exactcagd.curves_on_surfaces import approximate
from exactcagd.curves_on_surfaces.approximants import parabola, s_parabola
from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve
from exactcagd.reparam import cubic
from exactcagd.proofs._ledger import claim, erratum, predicate, reconstructed, same_expr, same_value, verified, verified_range

a1, a2, a3, b, t, v, u = sympy.symbols("alpha1 alpha2 alpha3 beta t v u")
ALPHA = a1 * (1 - t) ** 2 + 2 * a2 * t * (1 - t) + a3 * t**2
M = (b - 1) * t / (2 * b * t - t - b)  # eq. (8) = eq. (3) with beta


def _u_of_v():
    t_of_v = sympy.solve(sympy.Eq(v, M), t)[0]
    return sympy.together((1 - ALPHA).subs(t, t_of_v))


def _printed_6_7():
    A = (4 - a1 - 2 * a2 - a3) * b**2 + (2 * a1 + 2 * a2 - 4) * b + 1 - a1
    B = 2 * (b - 1) * (a1 * b - 2 * b + a2 * b - a1 + 1)
    C = (b - 1) ** 2 * (1 - a1)
    D = (2 * b - 1) ** 2
    E = -2 * (b - 1) * (2 * b - 1)
    F = (b - 1) ** 2
    return (A * v**2 + B * v + C) / (D * v**2 + E * v + F)


@claim(doc="yang", section="5", ref="(6), (7)", statement="the s = 1/2 iso-line in the original domain: u(v) = (a v^2 + b v + c)/(d v^2 + e v + f) with a..f of (7)")
def eq6_7():
    # iso-line s = 1/2 of (5): u = (alpha - 1)/2 / ((2 alpha - 1)/2 - alpha) = 1 - alpha(t), v = M_beta(t)
    s = sympy.Rational(1, 2)
    assert sympy.simplify((ALPHA - 1) * s / (2 * ALPHA * s - s - ALPHA) - (1 - ALPHA)) == 0
    assert sympy.simplify(_u_of_v() - _printed_6_7()) == 0
    return verified("eliminating t from u = 1 - alpha(t), v = M_beta(t) gives exactly (6) with (7) (symbolic in alpha_k, beta); d v^2 + e v + f = ((2 beta - 1) v - (beta - 1))^2",
        compared='printed (6) with the coefficients (7) vs sympy elimination of t from u = 1 - alpha(t), v = M_beta(t) (the iso-line s = 1/2 of (5)), symbolic in alpha_k, beta',
        reference='sympy',
    )


@claim(doc="yang", section="5", ref="(8), (9)", statement="substituting v = (beta-1) t/(2 beta t - t - beta) into (6): g u = h v^2 + p v + q with g = beta^2 (1-beta), h = 2 a1 + 8 b^3 - ..., p = beta(5 beta - 4 beta^2 + ...), q = -(1-a1) beta^2 (1-beta)")
def eq8_9():
    printed = _printed_6_7()
    sub = sympy.cancel(printed.subs(v, M))
    correct = (1 - a1) + 2 * (a1 - a2) * t + (2 * a2 - a1 - a3) * t**2
    assert sympy.cancel(sub - correct) == 0
    g = b**2 * (1 - b)
    h = 2 * a1 + 8 * b**3 - 14 * b**2 + 9 * b - 2 * a2 * b + 4 * a2 * b**2 - a3 * b**3 + 11 * a1 * b**2 + a3 * b**2 - 5 * a1 * b**3 - 2 * a2 * b**3 - 8 * a1 * b - 2
    p = b * (5 * b - 4 * b**2 + 4 * a1 * b**2 - 2 - 6 * a1 * b + 2 * a1)
    q = -(1 - a1) * b**2 * (1 - b)
    assert sympy.cancel(g * printed - (h * v**2 + p * v + q)) != 0  # not in v either

    def holds_after_substitution(ghpq):
        gg, hh, pp, qq = ghpq
        return same_expr(sympy.expand(gg * sub))(hh * t**2 + pp * t + qq)

    return erratum(
        "g u = h v^2 + p v + q, g = beta^2 (1 - beta), h = ..., p = ..., q = -(1 - alpha1) beta^2 (1 - beta)",
        "u = (1 - alpha1) + 2 (alpha1 - alpha2) t + (2 alpha2 - alpha1 - alpha3) t^2 (g = 1, h = 2 alpha2 - alpha1 - alpha3, "
        "p = 2 (alpha1 - alpha2), q = 1 - alpha1; the variable is t, not v)",
        "substituting (8) into (6)-(7) gives back u = 1 - alpha(t) (symbolic); the printed g, h, p, q satisfy the identity "
        "neither in t nor in v (already u(0) = q/g = -(1 - alpha1) has the wrong sign)",
        printed_form=(g, h, p, q), corrected_form=(sympy.Integer(1), 2 * a2 - a1 - a3, 2 * (a1 - a2), 1 - a1),
        check=predicate(holds_after_substitution),
    )


@claim(doc="yang", section="5", ref="Theorem 2", statement="The curve in Eq. (6) is a parabola")
def theorem2():
    # (u, t) plane: u is a quadratic polynomial in t -> a parabola y^2 = r x there (h != 0) or a line (h = 0).
    # (u, v) plane: u L(v)^2 = N(v) with L linear -- a cubic curve unless beta = 1/2 or h = 0.
    vals = {a1: sympy.Rational(1, 5), a2: sympy.Rational(4, 5), a3: sympy.Rational(3, 10), b: sympy.Rational(2, 5)}
    num, den = sympy.fraction(sympy.together(_printed_6_7().subs(vals)))
    implicit = sympy.Poly(sympy.expand(u * den - num), u, v)
    assert implicit.total_degree() == 3 and sympy.factor_list(implicit.as_expr())[1][0][0].as_poly(u, v).total_degree() == 3
    at_half = sympy.Poly(sympy.expand(sympy.fraction(sympy.together(_printed_6_7().subs({**vals, b: sympy.Rational(1, 2)})))[1]), v)
    assert at_half.degree() <= 0  # beta = 1/2: the denominator is constant, u(v) is a true parabola
    curves = {"(u, v)": implicit.as_expr(), "(u, t)": sympy.expand(u - (1 - ALPHA).subs(vals))}
    coords = {"(u, v)": (u, v), "(u, t)": (u, t)}

    def is_parabola_in(plane):
        P = sympy.Poly(curves[plane], *coords[plane])
        if P.total_degree() != 2:
            return f"the curve has degree {P.total_degree()} in {plane}"
        x_, y_ = coords[plane]
        A, B, C = P.coeff_monomial(x_**2), P.coeff_monomial(x_ * y_), P.coeff_monomial(y_**2)
        return None if B**2 - 4 * A * C == 0 else f"B^2 - 4AC = {B**2 - 4 * A * C} in {plane}"

    return erratum(
        "the curve (6) is a parabola (y^2 = r x with y = v + p/(2h), x = u + p^2/(4gh))",
        "the curve is a parabola in the (t, u) coordinates, u = 1 - alpha(t), with v = M_beta(t) a Möbius function of t "
        "(a line if 2 alpha2 = alpha1 + alpha3); in the (u, v) domain it is the rational cubic u ((2beta-1)v - (beta-1))^2 = N(v), "
        "a parabola only for beta = 1/2",
        "alpha = (1/5, 4/5, 3/10), beta = 2/5: the implicit equation u L(v)^2 - N(v) = 0 is irreducible of total degree 3; at beta = 1/2 L is constant",
        printed_form="(u, v)", corrected_form="(u, t)", check=predicate(is_parabola_in),
    )


@claim(doc="yang", section="5", ref="Theorem 2 proof: completed square", statement="Eq. (9) can be rewritten (v + p/(2h))^2 = g (u + p^2/(4gh))/h; y = v + p/(2h), x = u + p^2/(4gh), r = g/h: y^2 = r x")
def theorem2_completed_square():
    g, h, p, q = sympy.symbols("g h p q", nonzero=True)
    eq9 = h * v**2 + p * v + q - g * u  # (9): g u = h v^2 + p v + q

    def same_curve_as_9(rewritten):
        # rewritten = 0 must be (9) divided by h
        return same_expr(eq9)(sympy.expand(h * rewritten))

    printed = (v + p / (2 * h)) ** 2 - g * (u + p**2 / (4 * g * h)) / h
    corrected = (v + p / (2 * h)) ** 2 - g * (u - q / g + p**2 / (4 * g * h)) / h
    return erratum(
        "(v + p/(2h))^2 = g (u + p^2/(4gh))/h, x = u + p^2/(4gh)",
        "(v + p/(2h))^2 = g (u - q/g + p^2/(4gh))/h, x = u - q/g + p^2/(4gh)",
        "completing the square in g u = h v^2 + p v + q (sympy, symbolic g, h, p, q): the printed form drops the -q/g term",
        printed_form=printed, corrected_form=corrected, check=predicate(same_curve_as_9),
    )


#: which coefficients each equation of section 4 defines (transcribed from the text; tests/test_ledger_rules.py
#: re-reads the seed text when it is available)
EQUATION_COEFFICIENTS = {"(2)": ("alpha",), "(3)": ("beta",), "(4)": ("alpha_1", "alpha_2", "beta_1", "beta_2"),
                         "(5)": ("alpha_1", "alpha_2", "alpha_3", "beta_1", "beta_2", "beta_3")}


@claim(doc="yang", section="5", ref="beta_3, beta_2, beta_1 in Eq. (4)", statement="let the coefficients beta_3, beta_2 and beta_1 in Eq. (4) be the same and denote them as beta")
def beta_cross_reference():
    def defines_three_betas(tag):
        have = EQUATION_COEFFICIENTS[tag]
        missing = [c for c in ("beta_1", "beta_2", "beta_3") if c not in have]
        return None if not missing else f"Eq. {tag} defines {', '.join(have)}: no {', '.join(missing)}"

    return erratum(
        "beta_3, beta_2 and beta_1 in Eq. (4)",
        "beta_3, beta_2 and beta_1 in Eq. (5) (the cubic transformation; (4) is the quadratic one with beta_1, beta_2 only)",
        "the coefficients named must be defined by the equation cited (transcribed equation contents)",
        printed_form="(4)", corrected_form="(5)", check=predicate(defines_three_betas), reference="text",
    )


@claim(doc="yang", section="5", ref="(10)-(13)", statement="u(0) = 1 - a1 = u0, u(1) = 1 - a3 = u1, u'(0) = 2 beta (a1 - a2)/(1 - beta) = k1, u'(1) = 2 (1 - beta)(a2 - a3)/beta = k2 (u' = du/dv)")
def eq10_13():
    uu, vv = 1 - ALPHA, M
    dudv = sympy.diff(uu, t) / sympy.diff(vv, t)
    assert sympy.simplify(uu.subs(t, 0) - (1 - a1)) == 0 and sympy.simplify(uu.subs(t, 1) - (1 - a3)) == 0
    assert sympy.simplify(dudv.subs(t, 0) - 2 * b * (a1 - a2) / (1 - b)) == 0
    assert sympy.simplify(dudv.subs(t, 1) - 2 * (1 - b) * (a2 - a3) / b) == 0
    assert vv.subs(t, 0) == 0 and sympy.simplify(vv.subs(t, 1)) == 1
    return verified("symbolic in alpha_k, beta; k1, k2 are du/dv in the domain normalized to v0 = 0, v1 = 1 (k = m (v1 - v0)/n)",
        compared="printed (10)-(13) (u0, u1, k1, k2) vs sympy: u = 1 - alpha(t) at t = 0, 1 and du/dv = u'(t)/v'(t) at t = 0, 1, simplified symbolically",
        reference='sympy',
    )


@claim(doc="yang", section="5", ref="(14), Type 1", statement="m0 = 0: alpha2 = alpha1 (14) and beta = 2(u1-u0)/(2(u1-u0)+k2) in (0,1) for monotonic curves")
def eq14():
    u0, u1, k2 = sympy.symbols("u0 u1 k2")
    beta = sympy.solve(sympy.Eq(2 * (1 - b) * (a1 - a3) / b, k2).subs({a1: 1 - u0, a3: 1 - u1}), b)[0]
    assert sympy.simplify(beta - 2 * (u1 - u0) / (2 * (u1 - u0) + k2)) == 0
    rng = random.Random(1)
    for _ in range(200):
        du = mpq(rng.randint(1, 50), 50) * rng.choice([1, -1])
        kk = mpq(rng.randint(1, 50), 20) * (1 if du > 0 else -1)  # monotone: k2 has the sign of u1 - u0
        bb = 2 * du / (2 * du + kk)
        assert 0 < bb < 1
    return verified("symbolic solve of (13) with alpha2 = alpha1; beta in (0, 1) whenever k2 and u1 - u0 have the same sign (200 exact monotone cases)",
        compared='printed (14) beta = 2(u1-u0)/(2(u1-u0)+k2) vs sympy solve of (13) with alpha2 = alpha1; beta in (0, 1) on 200 exact monotone rational cases',
        reference='sympy',
    )


@claim(doc="yang", section="5", ref="(15)", statement="From Eq. (12), beta = 2(a2 - a3)/(2(a2 - a3) + k2); substituting (15) into (13): 4 a2^2 - 4(a1 + a3) a2 + 4 a1 a3 + k1 k2 = 0")
def eq15():
    k1, k2 = sympy.symbols("k1 k2")
    beta15 = 2 * (a2 - a3) / (2 * (a2 - a3) + k2)
    assert sympy.simplify((2 * (1 - b) * (a2 - a3) / b).subs(b, beta15) - k2) == 0  # (15) solves (13)
    quad = sympy.numer(sympy.together((2 * b * (a1 - a2) / (1 - b)).subs(b, beta15) - k1))
    target = 4 * a2**2 - 4 * (a1 + a3) * a2 + 4 * a1 * a3 + k1 * k2
    assert sympy.expand(quad + target) == 0
    eqs = {"(12)": 2 * b * (a1 - a2) / (1 - b) - k1, "(13)": 2 * (1 - b) * (a2 - a3) / b - k2}

    def derivation(numbers):
        solved_from, substituted_into = numbers
        if sympy.simplify(eqs[solved_from].subs(b, beta15)) != 0:
            return f"(15) does not solve {solved_from}"
        q_ = sympy.numer(sympy.together(eqs[substituted_into].subs(b, beta15)))
        if sympy.expand(q_ + target) != 0 and sympy.expand(q_ - target) != 0:
            return f"substituting (15) into {substituted_into} does not give the quadratic"
        return None

    return erratum(
        "From Eq. (12) we have (15); substituting (15) into (13) gives the quadratic",
        "(15) solves (13) (u'(1) = k2); substituting (15) into (12) (u'(0) = k1) gives 4 a2^2 - 4(a1+a3) a2 + 4 a1 a3 + k1 k2 = 0",
        "symbolic: the formula (15) and the quadratic are right, the equation numbers (12)/(13) are swapped",
        printed_form=("(12)", "(13)"), corrected_form=("(13)", "(12)"), check=predicate(derivation),
    )


@claim(doc="yang", section="5", ref="(16), (17)", statement="alpha2 = ((a1 + a3) + sqrt(Delta))/2, Delta = (a1 - a3)^2 - k1 k2 = (u0-u1)^2 - m1 m0 (v0-v1)^2/(n1 n0); 0 < alpha2 < 1 always holds for a monotonic curve")
def eq16_17():
    k1, k2 = sympy.symbols("k1 k2")
    roots = sympy.solve(4 * a2**2 - 4 * (a1 + a3) * a2 + 4 * a1 * a3 + k1 * k2, a2)
    Delta = (a1 - a3) ** 2 - k1 * k2
    assert {sympy.simplify(r - (a1 + a3) / 2) for r in roots} == {sympy.sqrt(Delta) / 2, -sympy.sqrt(Delta) / 2} or all(
        sympy.simplify((2 * r - a1 - a3) ** 2 - Delta) == 0 for r in roots
    )
    m0, n0, m1, n1, u0, u1, v0, v1 = sympy.symbols("m0 n0 m1 n1 u0 u1 v0 v1")
    d17 = Delta.subs({a1: 1 - u0, a3: 1 - u1, k1: m0 * (v1 - v0) / n0, k2: m1 * (v1 - v0) / n1})
    assert sympy.simplify(d17 - ((u0 - u1) ** 2 - m1 * m0 * (v0 - v1) ** 2 / (n1 * n0))) == 0
    # both roots give alpha2 strictly between alpha1 and alpha3 and beta in (0, 1) for monotone data
    rng = random.Random(2)
    count = 0
    for _ in range(1000):
        p0 = (mpq(rng.randint(0, 40), 40), mpq(0))
        p1 = (mpq(rng.randint(0, 40), 40), mpq(1))
        if p0[0] == p1[0]:
            continue
        sg = 1 if p1[0] > p0[0] else -1
        d0 = (sg * mpq(rng.randint(1, 30), 10), mpq(rng.randint(1, 30), 10))
        d1 = (sg * mpq(rng.randint(1, 30), 10), mpq(rng.randint(1, 30), 10))
        for root in ("paper", "other"):
            a = s_parabola(p0, d0, p1, d1, root)
            kk1, kk2 = d0[0] / d0[1], d1[0] / d1[1]
            if (p1[0] - p0[0]) ** 2 - kk1 * kk2 < 0:
                assert a is None
                continue
            count += 1
            al = a.params["alpha"]
            assert 0 < al[1] < 1 and min(al[0], al[2]) <= al[1] <= max(al[0], al[2]) and 0 < a.beta < 1
    assert count > 100
    # independent of exactcagd: the printed (16) root itself on random exact monotone data in the normalized domain
    # (a1 = 1 - u0, a3 = 1 - u1, k1, k2 of the sign of u1 - u0), exact sqrt comparisons in sympy
    printed_count = 0
    for _ in range(150):
        aa1, aa3 = sympy.Rational(rng.randint(0, 40), 40), sympy.Rational(rng.randint(0, 40), 40)
        if aa1 == aa3:
            continue
        sg = 1 if aa1 > aa3 else -1  # u1 - u0 = a1 - a3
        kk1, kk2 = (sg * abs(aa1 - aa3) * sympy.Rational(rng.randint(1, 50), 40) for _ in range(2))
        delta = (aa1 - aa3) ** 2 - kk1 * kk2
        if delta < 0:
            continue
        for sign in (1, -1):  # printed '+' and the other root
            al2 = (aa1 + aa3 + sign * sympy.sqrt(delta)) / 2
            assert sympy.expand(4 * al2**2 - 4 * (aa1 + aa3) * al2 + 4 * aa1 * aa3 + kk1 * kk2) == 0
            bb = 2 * (al2 - aa3) / (2 * (al2 - aa3) + kk2)
            assert 0 < al2 < 1 and min(aa1, aa3) < al2 < max(aa1, aa3) and 0 < bb < 1
            printed_count += 1
    assert printed_count > 100
    return verified_range(
        f"{count} random monotone exact instances through s_parabola and {printed_count} exact evaluations of the printed (16), both roots",
        "the two roots are (a1 + a3 -+ sqrt(Delta))/2; (17) is (16)'s Delta in curve data (symbolic); for k1 k2 > 0 "
        "sqrt(Delta) < |a1 - a3|, so BOTH roots lie strictly between alpha1 and alpha3 (hence in (0,1)) and give beta in (0,1): "
        "the paper's '+' is a choice, not a necessity (exactcagd: root='paper' | 'other')",
        compared='printed (16) roots and (17) Delta vs sympy solve of the quadratic after (15) and substitution of the curve data; the printed root (and the other) evaluated with exact sympy sqrt on random monotone rational data: a root of the quadratic, strictly between alpha1 and alpha3, beta of (15) in (0, 1)',
        reference='sympy',
    )


def _sym_map(coeffs):
    num, den = coeffs
    num = [sympy.Rational(str(x)) if not hasattr(x, "free_symbols") else x for x in map(_sym, num)]
    den = [sympy.Rational(str(x)) if not hasattr(x, "free_symbols") else x for x in map(_sym, den)]
    bern = lambda cs: sum(c * sympy.binomial(len(cs) - 1, i) * t**i * (1 - t) ** (len(cs) - 1 - i) for i, c in enumerate(cs))
    return bern(num) / bern(den)


def _sym(x):
    return sympy.sympify(str(x))


def _zero(expr) -> bool:
    return sympy.radsimp(sympy.expand(expr)) == 0


def _assert_interpolates(a, p0, d0, p1, d1):
    """Independent check of Theorem 1's promise: end points and tangent directions (sympy)."""
    uu, vv = _sym_map(a.u_map), _sym_map(a.v_map)
    for tt, p, d in ((0, p0, d0), (1, p1, d1)):
        assert _zero(uu.subs(t, tt) - _sym(p[0])) and _zero(vv.subs(t, tt) - _sym(p[1]))
        du, dv = (sympy.diff(f, t).subs(t, tt) for f in (uu, vv))
        assert _zero(du * _sym(d[1]) - dv * _sym(d[0])), "tangent not parallel"
        assert sympy.radsimp(du * _sym(d[0]) + dv * _sym(d[1])) > 0, "tangent reversed"


@claim(doc="yang", section="5", ref="Theorem 1", statement="Types 1-4: m0 = 0 or m1 = 0 -> s-parabola; n0 = 0 or n1 = 0 -> t-parabola; X >= K -> s-parabola; X <= K -> t-parabola (X = (u0-u1)^2/(v0-v1)^2, K = m0 m1/(n0 n1)); every monotonic curve falls into one type")
def theorem1():
    rng = random.Random(3)
    count = checked = 0
    for _ in range(400):
        p0 = (mpq(rng.randint(0, 30), 30), mpq(rng.randint(0, 30), 30))
        p1 = (mpq(rng.randint(0, 30), 30), mpq(rng.randint(0, 30), 30))
        su = 1 if p1[0] >= p0[0] else -1
        sv = 1 if p1[1] >= p0[1] else -1
        if p0[0] == p1[0] or p0[1] == p1[1]:
            continue
        comps = [mpq(rng.randint(0, 6), 3) for _ in range(4)]
        zeros = [c == 0 for c in comps]
        if sum(zeros) > 1:  # the theorem assumes the unmentioned components non-zero
            continue
        d0 = (su * comps[0], sv * comps[1])
        d1 = (su * comps[2], sv * comps[3])
        a = parabola(p0, d0, p1, d1)
        assert a is not None
        if count % 24 == 0:  # sympy is slow on sqrt coefficients: every 24th case (~10)
            _assert_interpolates(a, p0, d0, p1, d1)
            checked += 1
        count += 1
        if zeros[0] or zeros[2]:
            assert a.kind == "s-parabola"
        elif zeros[1] or zeros[3]:
            assert a.kind == "t-parabola"
        else:
            X = (p0[0] - p1[0]) ** 2 / (p0[1] - p1[1]) ** 2
            K = d0[0] * d1[0] / (d0[1] * d1[1])
            assert a.kind == ("s-parabola" if X >= K else "t-parabola")
    # two zero components of different kinds (m0 = 0 and n1 = 0): no parabola exists (the algorithm cuts the curve)
    assert parabola((mpq(0), mpq(0)), (mpq(0), mpq(1)), (mpq(1), mpq(1)), (mpq(1), mpq(0))) is None
    return verified_range(
        f"{count} random monotone exact cases with at most one zero end-derivative component",
        f"{checked} of them: each parabola, evaluated in sympy from its Bernstein maps, has the given end points and end tangents parallel and "
        "equally directed to the given ones; "
        "X >= K and X <= K cover every case (Type 3 / Type 4); with both m0 = 0 and n1 = 0 (excluded by the theorem's "
        "assumption) no s- or t-parabola exists -- exactcagd cuts such a piece at its shoulder point",
        compared="Theorem 1's promise (same end points, same tangent directions) vs sympy evaluation and differentiation of the constructed curve",
        reference="sympy",
    )


@claim(doc="yang", section="5", ref="cubic form of C2", statement="C2 = sum w_i P_i B^3_i / sum w_i B^3_i with P0 = (1-a1, 0), P1 = ((a1 b - 2 b a2 + b + 1 - a1)/(b+1), (1-b)/(b+1)), P2 = ((b - 2 - 2 b a2 + 2 a2 + b a3)/(b-2), 2(b-1)/(b-2)), P3 = (1-a3, 1); w1 = (b-1)^2, w2 = (1-b^2)/3, w3 = b(2-b)/3, w4 = b^2")
def cubic_form():
    x = sympy.Symbol("x")
    P = [
        (1 - a1, 0),
        ((a1 * b - 2 * b * a2 + b + 1 - a1) / (b + 1), (1 - b) / (b + 1)),
        ((b - 2 - 2 * b * a2 + 2 * a2 + b * a3) / (b - 2), 2 * (b - 1) / (b - 2)),
        (1 - a3, 1),
    ]
    w = [(b - 1) ** 2, (1 - b**2) / 3, b * (2 - b) / 3, b**2]  # printed w1..w4 = w_0..w_3
    B = [sympy.binomial(3, i) * x**i * (1 - x) ** (3 - i) for i in range(4)]
    den = sum(w[i] * B[i] for i in range(4))
    cu = sum(w[i] * P[i][0] * B[i] for i in range(4)) / den
    cv = sum(w[i] * P[i][1] * B[i] for i in range(4)) / den
    assert sympy.simplify(cv - x) == 0  # parametrized by v itself
    assert sympy.simplify(cu - _printed_6_7().subs(v, x)) == 0
    def labels_match_formula(labels):
        used = ("w0", "w1", "w2", "w3")  # the indices of C2's printed formula
        return None if tuple(labels) == used else f"weights listed as {', '.join(labels)}; C2's formula uses {', '.join(used)}"

    return erratum(
        "C2(t) with weights labelled w1..w4",
        "weights w0..w3 = (b-1)^2, (1-b^2)/3, b(2-b)/3, b^2, and the parameter of this form is v itself (C2(v) = (u(v), v)); "
        "in the parameter t of the iso-line the same control points carry the weights b, (1+b)/3, (2-b)/3, 1-b (Möbius-equivalent)",
        "symbolic: v-coordinate of the printed form is x, u-coordinate equals (6)-(7) at v = x; the printed list "
        "numbers the weights w1..w4 while the formula above it uses w0..w3 (a typo, not the extraction)",
        printed_form=("w1", "w2", "w3", "w4"), corrected_form=("w0", "w1", "w2", "w3"), check=predicate(labels_match_formula),
        reference="text",
    )


def _image_degree(F, uu, vv, var):
    """Degree of the reduced rational curve F(uu(var), vv(var)) (sympy; max over the components)."""
    degs = []
    for comp in F:
        num, den = sympy.fraction(sympy.cancel(sympy.together(comp.subs({u: uu, v: vv}, simultaneous=True))))
        degs.append(max(sympy.degree(num, var), sympy.degree(den, var)))
    return max(degs)


@claim(doc="yang", section="6", ref="degree max(2m+n, m+2n)", statement="the approximate curve has degree max(2m + n, m + 2n), lower than 2m + 2n (conics) and (m + n) d (exact)")
def degree_claim():
    rng = random.Random(4)
    x = sympy.Symbol("x")
    # independent reference: the reduced degree of F(u(t), v(t)) by sympy substitution, for an s-parabola
    # (u quadratic, v Möbius: alpha = (1/5, 4/5, 3/10), beta = 2/5), a t-parabola (roles swapped) and a rational conic
    vals = {a1: sympy.Rational(1, 5), a2: sympy.Rational(4, 5), a3: sympy.Rational(3, 10), b: sympy.Rational(2, 5)}
    quad, mob = (1 - ALPHA).subs(vals), M.subs(vals)
    wq = 1 + x**2 - x  # conic weight (1, 1/2, 1) in Bernstein form: (1-x)^2 + x (1-x) + x^2
    conic_u = (sympy.Rational(1, 5) * (1 - x) ** 2 + sympy.Rational(1, 2) * x * (1 - x) + sympy.Rational(4, 5) * x**2) / wq
    conic_v = (x * (1 - x) + sympy.Rational(1, 3) * x**2) / wq

    for m, n in [(1, 2), (2, 1), (3, 3), (2, 3)]:
        S = BezierSurface([[[rng.randint(-3, 3) for _ in range(3)] for _ in range(n + 1)] for _ in range(m + 1)])
        F = S.to_sympy(u, v)
        assert _image_degree(F, quad, mob, t) == 2 * m + n
        assert _image_degree(F, mob, quad, t) == m + 2 * n
        assert _image_degree(F, conic_u, conic_v, x) == 2 * (m + n)
        p0, p1 = (mpq(1, 5), mpq(1, 10)), (mpq(4, 5), mpq(9, 10))
        sp_ = s_parabola(p0, (mpq(1, 2), mpq(1)), p1, (mpq(1, 4), mpq(1)))
        tp = parabola(p0, (mpq(1), mpq(1, 4)), p1, (mpq(1), mpq(1, 2)))
        assert tp.kind == "t-parabola"
        assert sp_.image_hom(S.homogeneous()).shape[0] - 1 == 2 * m + n
        assert tp.image_hom(S.homogeneous()).shape[0] - 1 == m + 2 * n
        # the s-parabola image is the s = 1/2 iso-line of the cubic reparameterization, whose t-degree is 2m + n
        assert cubic(S, ("1/3", "1/2", "2/3"), ("1/2", "1/2", "1/2")).degree[1] == 2 * m + n
        # a rational conic (quadratic u, v with one weight function) through the surface: degree 2(m + n)
        from exactcagd.reparam import substitute_curve

        w = [mpq(1), mpq(1, 2), mpq(1)]
        conic = ([mpq(1, 5) * w[0], mpq(1, 2) * w[1], mpq(4, 5) * w[2]], w), ([mpq(0), mpq(1) * w[1], mpq(1, 3) * w[2]], w)
        assert substitute_curve(S.homogeneous(), *conic).shape[0] - 1 == 2 * (m + n)
    return verified(
        "s-parabola images have degree 2m + n (u quadratic: 2m, v Möbius: n), t-parabolas m + 2n; a rational conic "
        "domain curve (section 1's alternative) gives 2(m + n); checked on 4 bidegrees",
        compared="printed degrees 2m + n / m + 2n / 2(m + n) vs the reduced degree (sympy cancel) of F(u(t), v(t)) after substituting an s-parabola, a t-parabola and a rational conic into a random integer surface of bidegree (m, n); the package's image nets have that many control points",
        reference='sympy',
    )


@claim(doc="yang", section="6", ref="Tables 2-4 degrees", statement="Degree: Exact 18, Polyline 6, Hyperbola 6, Parabola 9 (bicubic surface, cubic domain curve)", slow=True)
def table_degrees():
    S = analytic_surface(4, 4, "face")
    D = closed_domain_curve(8)
    r = {meth: approximate(S, D, "1e-1", meth, angle_tol=30) for meth in ("parabola", "hyperbola", "polyline")}
    assert (r["parabola"].degree, r["hyperbola"].degree, r["polyline"].degree) == (9, 6, 6)
    # exact image of a cubic piece: (m + n) d = 18 (degree of F(K(t)) by substitution; checked with sympy on a tiny patch)
    piece = D.to_bezier()[0][1]
    rng = random.Random(5)
    patch = BezierSurface([[[rng.randint(-5, 5) for _ in range(3)] for _ in range(4)] for _ in range(4)])
    tt = sympy.Symbol("t")
    K = piece.to_sympy(tt)
    F = patch.to_sympy(u, v)
    num, den = sympy.fraction(sympy.cancel(sympy.together(F[2].subs({u: K[0], v: K[1]}, simultaneous=True))))
    assert max(sympy.degree(num, tt), sympy.degree(den, tt)) == 18
    # the approximants' degrees by sympy substitution into the same bicubic patch (reduced): an s-parabola
    # (u quadratic, v Möbius) 9, a hyperbola of [15] (u linear, v Möbius) 6, a polyline segment (u, v linear) 6
    vals = {a1: sympy.Rational(1, 5), a2: sympy.Rational(4, 5), a3: sympy.Rational(3, 10), b: sympy.Rational(2, 5)}
    maps = {"parabola": ((1 - ALPHA).subs(vals), M.subs(vals)), "hyperbola": (sympy.Rational(1, 5) + 3 * t / 5, M.subs(vals)),
            "polyline": (sympy.Rational(1, 5) + 3 * t / 5, sympy.Rational(1, 10) + 4 * t / 5)}
    for meth, (uu, vv) in maps.items():
        assert _image_degree(F, uu, vv, t) == r[meth].degree, meth
    return verified("bicubic B-spline surface and cubic NURBS domain curve: parabola 9 = 2m+n, hyperbola 6 = polyline 6 = m+n, exact image of one piece 18 = (m+n) d (reduced rational function)",
        compared="printed degrees vs the reduced degree (sympy cancel) on a random bicubic patch of: F(K(t)) for a cubic piece of the domain curve (18), an s-parabola domain curve (9), a hyperbola of [15] (u linear, v Möbius: 6), a line segment (6); exactcagd's reported degrees of its three approximations equal these",
        reference='sympy',
    )


class _Radicals:
    """Numbers a + b sqrt(D) (several D) as sympy polynomials in symbols r_D with r_D^2 = D (exact zero tests)."""

    def __init__(self):
        self.symbols = {}

    def __call__(self, x):
        D = getattr(x, "D", None)
        if D is None:
            return sympy.Rational(str(x))
        if x.b == 0:
            return sympy.Rational(str(x.a))
        r = self.symbols.setdefault(int(D), sympy.Symbol(f"r{len(self.symbols)}", positive=True))
        return sympy.Rational(str(x.a)) + sympy.Rational(str(x.b)) * r

    def is_zero(self, expr) -> bool:
        """Zero iff every coefficient of the reduced form in the basis of radical products is 0.

        Valid when no product of distinct radicands is a square (asserted), so the basis is independent over Q.
        """
        import gmpy2

        Ds = list(self.symbols)
        for i in range(len(Ds)):
            for j in range(i + 1, len(Ds)):
                assert not gmpy2.is_square(Ds[i] * Ds[j]), "dependent radicals"
        rs = [self.symbols[D] for D in Ds]
        P = sympy.Poly(sympy.expand(expr), *rs) if rs else sympy.Poly(sympy.expand(expr), sympy.Symbol("_"))
        for D, r in zip(Ds, rs):
            P = P.rem(sympy.Poly(r**2 - D, *rs))
        return P.is_zero


def _end_tangents(seg, R):
    """End points and directions P_1 - P_0, P_n - P_(n-1) of a rational Bézier segment (weights checked > 0)."""
    H = seg.homogeneous()
    assert all(H[i, -1] > 0 for i in (0, 1, -2, -1))
    pt = lambda row: [R(x) / R(row[-1]) for x in row[:-1]]
    P0, P1, Pm, Pn = pt(H[0]), pt(H[1]), pt(H[-2]), pt(H[-1])
    return P0, [a - b_ for a, b_ in zip(P1, P0)], Pn, [a - b_ for a, b_ in zip(Pn, Pm)]


def _g1_joints(segments, closed):
    """Count the joints where consecutive segments meet with parallel, equally directed tangents (exact, sympy)."""
    ok = 0
    pairs = list(zip(segments, segments[1:])) + ([(segments[-1], segments[0])] if closed else [])
    for left, right in pairs:
        R = _Radicals()
        _, _, end, d_end = _end_tangents(left, R)
        start, d_start, _, _ = _end_tangents(right, R)
        clear = lambda e: sympy.numer(sympy.together(e))
        assert all(R.is_zero(clear(a - b_)) for a, b_ in zip(end, start)), "gap at a joint"
        cross = [d_end[1] * d_start[2] - d_end[2] * d_start[1], d_end[2] * d_start[0] - d_end[0] * d_start[2],
                 d_end[0] * d_start[1] - d_end[1] * d_start[0]]
        dot = sum(a * b_ for a, b_ in zip(d_end, d_start))
        # the tangents are parallel (exact); the sign of their dot product (+-|d_end||d_start|, far from 0) at 50 digits
        dot = dot.subs({r: sympy.sqrt(D) for D, r in R.symbols.items()})
        if all(R.is_zero(clear(c)) for c in cross) and sympy.N(dot, 50) > 0:
            ok += 1
    return ok


@claim(doc="yang", section="6", ref="Tables 2-4 continuity", slow=True, statement="Continuity: parabola G1; polyline and hyperbola 1 deg-G1; all curves lie completely on the surface (distance 0)")
def table_continuity():
    S = analytic_surface(4, 4, "face")
    D = closed_domain_curve(8)
    r = approximate(S, D, "1e-2")
    joints = _g1_joints(r.segments, r.closed)
    assert joints == len(r.segments)
    h = approximate(S, D, "1e-2", "hyperbola", angle_tol=10)
    assert h.max_joint_angle <= 10
    return verified("exact G1 at every joint of the parabola result: the end tangents P_1 - P_0, P_n - P_(n-1) of consecutive segments, computed in sympy from their control points, have cross product 0 and positive dot product; baselines meet their angle tolerance; segments are exact images X(u(t), v(t)) (tests check it at 2N+1 parameters)",
        compared="printed 'parabola G1' vs sympy: end tangents P_1 - P_0 and P_n - P_(n-1) of consecutive segments from their control points, cross product exactly 0 (radicals reduced symbolically) and dot product > 0 at 50 digits; the baselines' angles are the package's measured joint angle",
        reference='sympy',
    )


@claim(doc="yang", section="4.2", ref="hyperbola iso-lines", statement="a vertical/horizontal segment of the quadratic reparameterization's domain is a hyperbola in the original domain; an s-hyperbola has only three variables alpha1, alpha2, beta, so G1 (four constraints) is impossible in general")
def quadratic_iso_lines():
    A1, A2 = sympy.symbols("A1 A2")
    # s = 1/2 on (4): alpha(t) = A1 t + A2 (1 - t), u = 1 - alpha(t) (linear), v = M_beta(t)
    uu = 1 - (A1 * t + A2 * (1 - t))
    vv = M
    # implicit equation: eliminate t (u linear in t) -> a conic in (u, v)
    t_of_u = sympy.solve(sympy.Eq(u, uu), t)[0]
    conic = sympy.numer(sympy.together(v - vv.subs(t, t_of_u)))
    P = sympy.Poly(conic, u, v)
    assert P.total_degree() == 2
    # it contains a u v term and no u^2, v^2 terms: discriminant B^2 - 4AC = B^2 > 0 -> hyperbola (when not degenerate)
    assert P.coeff_monomial(u**2) == 0 and P.coeff_monomial(v**2) == 0 and sympy.simplify(P.coeff_monomial(u * v)) != 0
    # end slopes in the normalized domain: k(0) k(1) = (u1 - u0)^2 for every beta -> only data with Delta = 0 are reachable
    dudv = sympy.diff(uu, t) / sympy.diff(vv, t)
    prod = sympy.simplify(dudv.subs(t, 0) * dudv.subs(t, 1))
    assert sympy.simplify(prod - (uu.subs(t, 1) - uu.subs(t, 0)) ** 2) == 0
    return verified(
        "symbolic: the iso-line s = 1/2 of (4) satisfies a conic equation with only a u v quadratic term (a hyperbola, "
        "B^2 - 4AC > 0); its end slopes satisfy k(0) k(1) = (u1 - u0)^2 whatever beta, so end data with "
        "(u0 - u1)^2 != k1 k2 cannot be matched: G1 needs the cubic reparameterization",
        compared='printed 4.2 claim (iso-lines of (4) are hyperbolas; G1 impossible in general) vs sympy elimination of t: conic with only a u v quadratic term (B^2 - 4AC > 0), and the end-slope product k(0) k(1) = (u1 - u0)^2 for every beta',
        reference='sympy',
    )


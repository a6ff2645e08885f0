"""Lasser & Bonneau (000), sections I-III and V: Theorems 1 and 2, eqs. (5)-(7), (13)-(16).

Symbolic checks use sympy symbols as control points (route (a) of
``exactcagd.composition.lasser`` works on object arrays of sympy expressions) and compare
with the direct substitution ``F(u(t), v(t))``; range checks compare route (a), route (b)
and an independent sympy-Poly substitution on random exact instances.
"""

from __future__ import annotations

import itertools
import math
import random
from fractions import Fraction as Fr

import numpy as np
import sympy
from gmpy2 import mpq

from exactcagd import BezierCurve, BezierSurface
from exactcagd.composition import compose
from exactcagd.composition.lasser import compose_homogeneous_lasser, lasser_constant, polar_value, trace_theorem1
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, not_checkable, reconstructed, verified, verified_range

T, U, V = sympy.symbols("t u v")


# ----------------------------------------------------------------------------- shared helpers
def bern(n, i, x):
    return sympy.binomial(n, i) * x**i * (1 - x) ** (n - i)


def symbolic_inputs(l, m, N, rational=False, dims=1):
    """Symbolic homogeneous net (l+1, m+1, dims+1) and domain curve (N+1, 3)."""
    net = np.empty((l + 1, m + 1, dims + 1), dtype=object)
    for i in range(l + 1):
        for j in range(m + 1):
            w = sympy.Symbol(f"w{i}{j}") if rational else sympy.Integer(1)
            for k in range(dims):
                net[i, j, k] = w * sympy.Symbol(f"f{k}_{i}{j}")
            net[i, j, dims] = w
    curve = np.empty((N + 1, 3), dtype=object)
    for i in range(N + 1):
        b = sympy.Symbol(f"b{i}") if rational else sympy.Integer(1)
        curve[i] = [b * sympy.Symbol(f"u{i}"), b * sympy.Symbol(f"v{i}"), b]
    return net, curve


def direct_homogeneous(net, curve):
    """``W^(l+m) * (P, w)(X/W, Y/W)`` by substitution, monomial by monomial (a list of exprs).

    ``P`` is expanded in the power basis of (u, v); each monomial ``u^a v^b`` times
    ``W^(l+m)`` becomes ``X^a Y^b W^(l+m-a-b)`` -- the substitution with the denominators
    cleared, independent of any Bernstein-product formula.
    """
    l, m = net.shape[0] - 1, net.shape[1] - 1
    N = curve.shape[0] - 1
    X, Y, W = (sympy.expand(sum(curve[i, k] * bern(N, i, T) for i in range(N + 1))) for k in range(3))
    out = []
    for k in range(net.shape[2]):
        P = sympy.Poly(sympy.expand(sum(net[i, j, k] * bern(l, i, U) * bern(m, j, V) for i in range(l + 1) for j in range(m + 1))), U, V)
        total = sum(c * X**a * Y**b * W ** (l + m - a - b) for (a, b), c in P.terms())
        out.append(sympy.expand(total))
    return out


def bezier_expr(coeffs, n):
    return sympy.expand(sum(coeffs[R] * bern(n, R, T) for R in range(n + 1)))


def random_instance(rng, l, m, N, rational_surface, rational_curve, dim=3):
    def q(lo=0, hi=1, den=16):
        return Fr(rng.randint(lo * den, hi * den), den)

    net = [[[q(-2, 2) for _ in range(dim)] for _ in range(m + 1)] for _ in range(l + 1)]
    ws = [[Fr(rng.randint(1, 9), rng.randint(1, 4)) for _ in range(m + 1)] for _ in range(l + 1)] if rational_surface else None
    pts = [[q(), q()] for _ in range(N + 1)]
    wc = [Fr(rng.randint(1, 9), rng.randint(1, 4)) for _ in range(N + 1)] if rational_curve else None
    return BezierSurface(net, ws), BezierCurve(pts, wc)


def poly_reference(surface, curve):
    """Independent sympy-Poly substitution: homogeneous components of F(K(t)) times W^(l+m)."""
    l, m = surface.degree
    n = curve.degree
    q = lambda x: sympy.Rational(int(x.numerator), int(x.denominator))  # noqa: E731
    hc = curve.homogeneous()
    X, Y, W = (sympy.Poly(sum(q(hc[i, k]) * bern(n, i, T) for i in range(n + 1)), T, domain="QQ") for k in range(3))
    hs = surface.homogeneous()
    out = []
    for k in range(hs.shape[2]):
        P = sympy.Poly(sum(q(hs[i, j, k]) * bern(l, i, U) * bern(m, j, V) for i in range(l + 1) for j in range(m + 1)), U, V, domain="QQ")
        total = sympy.Poly(0, T, domain="QQ")
        for (a, b), c in P.terms():
            total += X**a * Y**b * W ** (l + m - a - b) * c
        out.append(total)
    return out


def hom_polys(hom):
    n = hom.shape[0] - 1
    q = lambda x: sympy.Rational(int(x.numerator), int(x.denominator))  # noqa: E731
    return [sympy.Poly(sum(q(hom[i, k]) * bern(n, i, T) for i in range(n + 1)), T, domain="QQ") for k in range(hom.shape[1])]


def check_instance(surface, curve) -> None:
    """Route (a) == route (b) == independent substitution (homogeneous, cross-multiplied)."""
    a = compose(surface, curve, method="lasser", shortcut=False)
    b = compose(surface, curve, shortcut=False)
    assert a == b, "routes (a) and (b) differ"
    ref = poly_reference(surface, curve)
    got = hom_polys(b.homogeneous())
    ref_w, got_w = ref[-1], got[-1]
    for r, g in zip(ref[:-1], got[:-1]):
        assert (r * got_w - g * ref_w).is_zero, "composition differs from substitution"
    l, m = surface.degree
    assert b.degree == curve.degree * (l + m)


# ----------------------------------------------------------------------------- Theorem 1
def _theorem1_symbolic(cases):
    for l, m, N in cases:
        net, curve = symbolic_inputs(l, m, N)
        coeffs = compose_homogeneous_lasser(net, curve)
        direct = direct_homogeneous(net[..., :1], curve)[0]
        assert sympy.expand(bezier_expr(coeffs[:, 0], (l + m) * N) - direct) == 0, (l, m, N)


def _trace1():
    net = np.array([[[0, 1], [0, 1]], [[1, 1], [2, 1]]], dtype=object)
    net = np.vectorize(mpq, otypes=[object])(net)
    curve = BezierCurve([["1/4", 0], [1, "1/2"]]).homogeneous()
    trace_theorem1(net, curve, 1)


@claim(doc="lasser", section="III", ref="Theorem 1, (5)-(7)", statement="F(K(t)) = sum_R B_R B^{rN}_R(t), B_R = sum_{|I|=R} C^{l,m}_R(N,I) F^{l,m}_{0,0}(u_I, v_I)", trace=_trace1)
def theorem1_symbolic():
    cases = [(1, 1, 1), (2, 1, 1), (1, 2, 1), (1, 1, 2), (2, 1, 2), (2, 2, 1)]
    _theorem1_symbolic(cases)
    return verified(f"symbolic control points F_ij, u_I, v_I; (l, m, N) in {cases}: formula == expand(F(u(t), v(t)))",
        compared='printed (5)-(7) (compose_homogeneous_lasser on symbolic control points) vs sympy expansion of the substitution F(u(t), v(t)) monomial by monomial (direct_homogeneous), equal as polynomials in t',
        reference='sympy',
    )


@claim(doc="lasser", section="III", ref="Theorem 1 (range)", statement="Theorem 1 for l, m, N <= 2 on random exact instances")
def theorem1_range_small():
    rng = random.Random(1)
    for l, m, N in itertools.product(range(3), range(3), range(1, 3)):
        if l + m:
            check_instance(*random_instance(rng, l, m, N, False, False))
    return verified_range("l, m <= 2, 1 <= N <= 2", "route (a) == route (b) == sympy-Poly substitution, stored degree N(l+m)",
        compared="Theorem-1 control points (route (a) by (6)-(7), also route (b)) vs an independent sympy-Poly substitution of K(t) into F's power form over QQ, compared cross-multiplied as polynomials in t",
        reference='sympy',
    )


@claim(doc="lasser", section="III", ref="Theorem 1 (range)", statement="Theorem 1 for l, m, N <= 4 on random exact instances", slow=True)
def theorem1_range():
    rng = random.Random(2)
    for l, m, N in itertools.product(range(5), range(5), range(1, 5)):
        if l + m:
            check_instance(*random_instance(rng, l, m, N, False, False))
    return verified_range("l, m <= 4, 1 <= N <= 4 (one random exact instance each)", "route (a) == route (b) == substitution",
        compared='Theorem-1 control points (routes (a) and (b)) vs sympy-Poly substitution of K(t) into F over QQ, as polynomials in t',
        reference='sympy',
    )


@claim(doc="lasser", section="III", ref="(7)", statement="sum over |I| = R of C^{l,m}_R(N, I) = 1 (the B_R are affine combinations)")
def constants_partition_of_unity():
    for l, m, N in itertools.product(range(5), range(5), range(1, 5)):
        r = l + m
        # generating function: sum_{I} prod C(N, I_Q) x^{|I|} = (1 + x)^{N r}
        gen = [1]
        for _ in range(r):
            gen = [sum(gen[k - i] * math.comb(N, i) for i in range(N + 1) if 0 <= k - i < len(gen)) for k in range(len(gen) + N)]
        assert all(gen[R] == math.comb(r * N, R) for R in range(r * N + 1))
    assert lasser_constant(2, 1, 2, (1, 2), (0,)) == Fr(2 * 1 * 1, 20)
    return verified_range("l, m <= 4, N <= 4", "Vandermonde: sum_{|I|=R} prod C(N, I_Q) = C(rN, R), so (7) sums to 1",
        compared='printed (7) constants prod C(N, I_Q) / C(rN, R) summed over |I| = R vs 1: the generating function (1 + x)^(N r) expanded by exact integer convolution (math.comb), coefficient by coefficient against C(rN, R); lasser_constant(2, 1, 2, (1, 2), (0,)) vs (7) evaluated by hand (2 * 1 * 1 / 20)',
        reference='exact',
    )


@claim(doc="lasser", section="III", ref="polar form recursion after (7)", statement="F^{i+a,j+b}_{i,j} = (1 - u_{I_u^u}) F^{...-1} + u_{I_u^u} F_{i+1,j}^{...}; v direction with v_{I_1^u}, ...")
def polar_recursion():
    for l, m in [(1, 1), (2, 1), (2, 2), (3, 1)]:
        f = np.empty((l + 1, m + 1, 1), dtype=object)
        for i in range(l + 1):
            for j in range(m + 1):
                f[i, j, 0] = sympy.Symbol(f"f{i}{j}")
        us = sympy.symbols(f"a0:{l}")
        vs = sympy.symbols(f"c0:{m}")
        value = polar_value(f, list(us), list(vs))[0]
        for perm in itertools.permutations(range(l)):  # symmetric in the u arguments
            assert sympy.expand(polar_value(f, [us[p] for p in perm], list(vs))[0] - value) == 0
        for x in list(us) + list(vs):  # multi-affine
            assert sympy.degree(sympy.expand(value), x) <= 1
        diag = sympy.expand(value.subs({**{x: U for x in us}, **{y: V for y in vs}}))
        surface = sum(f[i, j, 0] * bern(l, i, U) * bern(m, j, V) for i in range(l + 1) for j in range(m + 1))
        assert sympy.expand(diag - surface) == 0
        # v first, then u: the directions commute
        v_first = f
        for y in vs:
            v_first = (1 - y) * v_first[:, :-1] + y * v_first[:, 1:]
        for x in us:
            v_first = (1 - x) * v_first[:-1] + x * v_first[1:]
        assert sympy.expand(v_first[0, 0, 0] - value) == 0
    def u_step_index(label):
        # the alpha-th u step must use the alpha-th u argument: label(alpha) == alpha for alpha = 1..l
        return None if all(label(al) == al for al in (1, 2, 3)) else f"the u step uses argument {label(2)} at step 2 (the same index every step)"
    return reconstructed(
        "u-step uses u_{I_u^u}; v-step description lists v_{I_1^u}, ..., v_{I_beta^v}",
        "u-step uses u_{I^u_alpha} (the alpha-th u index), v-step v_{I^v_beta}; arguments v_{I^v_1}, ..., v_{I^v_beta}",
        "the recursion (l de Casteljau steps in u, m in v) gives a symmetric, multi-affine form whose diagonal is F(u, v); u and v steps commute (symbolic, (l, m) <= (3, 1)/(2, 2))",
        printed_form=lambda al: 'u', corrected_form=lambda al: al, check=L.predicate(u_step_index), reference='text',
    )


# ----------------------------------------------------------------------------- Theorem 2
@claim(doc="lasser", section="V", ref="Theorem 2, (13)-(16)", statement="rational F(K(t)) of degree rN with Omega_R, Omega_R B_R by (14), (15) and constants (16)")
def theorem2_symbolic():
    cases = [(1, 1, 1), (1, 1, 2), (2, 1, 1), (1, 0, 2)]
    for l, m, N in cases:
        net, curve = symbolic_inputs(l, m, N, rational=True)
        coeffs = compose_homogeneous_lasser(net, curve)
        direct = direct_homogeneous(net, curve)
        for k in range(net.shape[2]):
            assert sympy.expand(bezier_expr(coeffs[:, k], (l + m) * N) - direct[k]) == 0, (l, m, N, k)
    return verified(
        f"symbolic weights omega_ij, beta_I, points F_ij, u_I, v_I; (l, m, N) in {cases}: "
        "(Omega_R B_R, Omega_R) are the Bernstein coefficients of W^(l+m) (wF, w)(X/W, Y/W); the factor W^(l+m) "
        "cancels between numerator and denominator, so the degree is rN, not 2rN",
        compared='printed (13)-(16) (compose_homogeneous_lasser with symbolic weights) vs sympy expansion of W^(l+m) (wF, w)(X/W, Y/W) by monomial substitution, component by component',
        reference='sympy',
    )


@claim(doc="lasser", section="V", ref="Theorem 2 (range)", statement="Theorem 2 for l, m, N <= 2, all four polynomial/rational combinations")
def theorem2_range_small():
    rng = random.Random(3)
    for l, m, N in itertools.product(range(3), range(3), range(1, 3)):
        if l + m:
            for rs, rc in ((True, False), (False, True), (True, True)):
                check_instance(*random_instance(rng, l, m, N, rs, rc))
    return verified_range("l, m <= 2, 1 <= N <= 2, (rational F) x (rational K)", "route (a) == route (b) == substitution",
        compared='Theorem-2 homogeneous control points (routes (a) and (b)) vs sympy-Poly substitution of the rational K(t) into the rational F over QQ, cross-multiplied',
        reference='sympy',
    )


@claim(doc="lasser", section="V", ref="Theorem 2 (range)", statement="Theorem 2 for l, m, N <= 4", slow=True)
def theorem2_range():
    rng = random.Random(4)
    kinds = itertools.cycle(((True, False), (False, True), (True, True)))
    for l, m, N in itertools.product(range(5), range(5), range(1, 5)):
        if l + m:
            check_instance(*random_instance(rng, l, m, N, *next(kinds)))
    return verified_range(
        "l, m <= 4, 1 <= N <= 4 (one random exact instance each, cycling rational F / rational K / both)",
        "route (a) == route (b) == substitution",
        compared='Theorem-2 homogeneous control points (routes (a) and (b)) vs sympy-Poly substitution over QQ, cross-multiplied',
        reference='sympy',
    )


@claim(doc="lasser", section="V", ref="Remark 3", statement="special cases: K, F polynomial; K polynomial, F rational; and K polynomial, F rational")
def remark3():
    # beta = 1, omega = 1: (16) -> (7) and Theorem 2 -> Theorem 1
    net, curve = symbolic_inputs(2, 1, 2, rational=True)
    ones = {s: 1 for s in set().union(*[x.free_symbols for x in np.concatenate([net.reshape(-1), curve.reshape(-1)])]) if s.name[0] in "wb"}
    poly_net, poly_curve = symbolic_inputs(2, 1, 2)
    a = compose_homogeneous_lasser(net, curve)
    b = compose_homogeneous_lasser(poly_net, poly_curve)
    assert all(sympy.expand(x.subs(ones) - y) == 0 for x, y in zip(a.reshape(-1), b.reshape(-1)))
    # the two mixed cases give genuinely rational curves
    rng = random.Random(5)
    for rs, rc in ((True, False), (False, True)):
        surface, k = random_instance(rng, 2, 2, 2, rs, rc)
        image = compose(surface, k)
        assert image.is_rational and image.reduce().is_rational
    def covers_the_four_cases(cases):
        need = {("poly", "poly"), ("poly", "rat"), ("rat", "poly")}
        missing = need - set(cases)
        return None if not missing else f"the list misses (K, F) = {sorted(missing)}; it names {cases}"
    return erratum(
        "Special cases K(t), F(u,v) both polynomial, K polynomial and F rational, and K polynomial and F rational",
        "... K(t) polynomial and F rational, and K(t) rational and F polynomial",
        "the list repeats one case; with beta = omega = 1 Theorem 2 reduces to Theorem 1 (symbolic, (l, m, N) = (2, 1, 2)); "
        "both mixed cases give rational curves whose reduced weight is not constant (random exact instances)",
        printed_form=[('poly', 'poly'), ('poly', 'rat'), ('poly', 'rat')], corrected_form=[('poly', 'poly'), ('poly', 'rat'), ('rat', 'poly')], check=L.predicate(covers_the_four_cases), reference='text',
    )


@claim(doc="lasser", section="III", ref="footnote 1", statement="triangle patch of degree n: iso and general lines map to curves of degree n")
def footnote_triangles():
    for n in range(1, 5):
        coeffs = {(i, j): sympy.Symbol(f"c{i}{j}") for i in range(n + 1) for j in range(n + 1 - i)}
        f = sum(c * U**i * V**j for (i, j), c in coeffs.items())
        a0, a1, b0, b1 = sympy.symbols("a0 a1 b0 b1")
        line = sympy.Poly(sympy.expand(f.subs({U: a0 + a1 * T, V: b0 + b1 * T}, simultaneous=True)), T)
        assert line.degree() == n
    return verified("total degree n is preserved under an affine substitution (u, v) = (a0 + a1 t, b0 + b1 t); symbolic, n <= 4",
        compared='footnote 1 (degree n preserved on lines) vs sympy: Poly degree in t of a symbolic total-degree-n polynomial after the affine substitution (u, v) = (a0 + a1 t, b0 + b1 t)',
        reference='sympy',
    )


@claim(doc="lasser", section="I", ref="[Elb 92] Table 6.1", statement="Table 6.1 of [Elb 92] listing polynomial degrees of F(K(t)) is erroneous")
def elber_table():
    return not_checkable("the table of [Elb 92] is not part of the source; the correct degrees rN (Theorems 1, 2) are verified above")

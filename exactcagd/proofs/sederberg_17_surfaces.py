"""Sederberg's notes, chapter 17.9-17.11: surface implicitization degrees, base
points, ideals, term orders and Gröbner bases.

Independent references: sympy substitution of parametrizations, sympy's own
Gröbner bases (buchberger) and monomial orderings, integer gcds.
"""

from __future__ import annotations

import math
import random

import sympy as sp

from exactcagd import BezierSurface
from exactcagd.algebra import SurfaceParametrization, base_point_count, groebner, ideal_contains, ideals_equal, implicitize_surface
from exactcagd.algebra.groebner import groebner_basis
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, reconstructed, verified, verified_range

DOC = "sederberg"
x, y, z, s, t, u = sp.symbols("x y z s t u")


def _irreducible(F):
    """sympy's factorization over Q has one factor of multiplicity one: with ``_vanishes`` F is the implicit equation."""
    _, factors = sp.factor_list(sp.sympify(F))
    return len(factors) == 1 and factors[0][1] == 1


def _vanishes(F, param):
    """``F(P(s, t)) == 0`` identically: ``F_hom(X, Y, Z, W)`` has degree <= D in each of
    s, t (D = deg F * max component degree), so vanishing on a (D + 1) x (D + 1) grid of
    distinct rational points proves it (exact Fraction arithmetic, independent of exactcagd)."""
    from fractions import Fraction

    Fp = sp.Poly(F, x, y, z)
    d = Fp.total_degree()
    comps = [sp.Poly(c, s, t) for c in param.components()]
    D = d * max(max(c.degree(s), c.degree(t)) for c in comps)
    terms = [(m, Fraction(int(c))) for m, c in Fp.terms()]
    cterms = [[(m, Fraction(int(c.p), int(c.q))) for m, c in ((mm, sp.Rational(cc)) for mm, cc in cp.terms())] for cp in comps]
    for i in range(D + 1):
        for j in range(D + 1):
            sv, tv = Fraction(i, D + 1), Fraction(j, D + 1) - Fraction(1, 3)
            X, Y, Z, W = (sum(c * sv**a * tv**b for (a, b), c in ct) for ct in cterms)
            if sum(c * X**a * Y**b * Z**e * W ** (d - a - b - e) for (a, b, e), c in terms) != 0:
                return False
    return True


# ---------------------------------------------------------------- 17.9
@claim(DOC, "17.9", "degrees", "triangular degree n: implicit degree n^2; tensor (m, n): 2mn (bilinear 2, quadratic 4, biquadratic 8)")
def surface_degrees():
    r = random.Random(179)
    out = []
    tri = {(i, j, 2 - i - j): [r.randint(-3, 3) for _ in range(3)] for i in range(3) for j in range(3 - i)}
    P = SurfaceParametrization.from_triangular_bezier(tri)
    F = implicitize_surface(P)
    assert F.total_degree() == 4 and _vanishes(F.as_expr(), P) and base_point_count(P) == 0 and _irreducible(F.as_expr())
    out.append("triangular n=2: 4")
    for (m, n) in ((1, 1), (1, 2)):
        net = [[[r.randint(-3, 3) for _ in range(3)] for _ in range(n + 1)] for _ in range(m + 1)]
        P = SurfaceParametrization.from_bezier_surface(BezierSurface(net))
        F = implicitize_surface(P)
        assert F.total_degree() == 2 * m * n and _vanishes(F.as_expr(), P) and _irreducible(F.as_expr()), (m, n)
        out.append(f"tensor ({m},{n}): {2 * m * n}")
    return verified_range("random integer patches: triangular n = 2; tensor (1,1), (1,2)", "; ".join(out) + " (implicit equation vanishes on the patch: exact grid check)",
        compared='printed degrees n^2 = 4 and 2mn = 2, 4 vs the total degree of an implicit equation shown independently to be THE implicit equation: it vanishes on the patch (exact Fraction grid) and is irreducible (sympy factor_list)',
        reference='sympy')


@claim(DOC, "17.9", "biquadratic", "biquadratic patches have implicit equations of degree 8", slow=True)
def surface_degree_biquadratic():
    r = random.Random(1792)
    net = [[[r.randint(-3, 3) for _ in range(3)] for _ in range(3)] for _ in range(3)]
    P = SurfaceParametrization.from_bezier_surface(BezierSurface(net))
    F = implicitize_surface(P)
    assert F.total_degree() == 8 and len(F.terms()) <= 165 and _vanishes(F.as_expr(), P) and _irreducible(F.as_expr())
    assert implicitize_surface(P, "dixon").as_expr() == F.as_expr()
    return verified_range("a random integer biquadratic patch", "degree 8 by undetermined coefficients and by the 8 x 8 Dixon determinant (equal); vanishes on a 17 x 17 grid",
        compared='printed degree 8 vs the total degree of an equation that vanishes on the patch (exact Fraction grid, 17 x 17) and is irreducible (sympy factor_list); the Dixon route gives the same polynomial',
        reference='sympy')


@claim(DOC, "17.9", "bicubic", "a bicubic patch has an implicit equation of degree 18 with 1330 terms; two bicubics meet in a curve of degree 324")
def bicubic_counts():
    assert 2 * 3 * 3 == 18 and math.comb(18 + 3, 3) == 1330 and 18 * 18 == 324
    return verified("2mn = 18; monomials of degree <= 18 in x, y, z: C(21, 3) = 1330; Bezout 18 * 18 = 324",
        compared='printed 18, 1330 and 324 vs 2mn, C(18 + 3, 3) and the Bezout product 18 * 18 in integer arithmetic',
        reference='exact')


@claim(DOC, "17.9", "Dixon", "tensor-product implicitization by Dixon's resultant equals the implicit equation")
def dixon_route():
    r = random.Random(1791)
    net = [[[r.randint(-3, 3) for _ in range(3)] for _ in range(2)] for _ in range(2)]
    P = SurfaceParametrization.from_bezier_surface(BezierSurface(net))
    F1 = implicitize_surface(P, "dixon").as_expr()
    F2 = implicitize_surface(P, "linear_algebra").as_expr()
    assert F1 == F2 and _vanishes(F1, P) and _irreducible(F1)
    return verified("bilinear patch: Dixon (2 x 2 matrix, entries linear in x, y, z) == undetermined coefficients",
        compared='Dixon-route implicit equation vs the undetermined-coefficients route, exact vanishing on the patch (Fraction grid) and irreducibility (sympy factor_list)',
        reference='sympy')


# ---------------------------------------------------------------- 17.10
@claim(DOC, "17.10", "sphere", "x = 2rs^u, y = 2rtu, z = r(u^2 - s^2 - t^2), w = s^2 + t^2 + u^2; base points (1, +-i, 0)")
def sphere_base_points():
    r_ = sp.Symbol("r", positive=True)
    X, Y, Z, W = 2 * r_ * s * u, 2 * r_ * t * u, r_ * (u**2 - s**2 - t**2), s**2 + t**2 + u**2
    assert sp.expand(X**2 + Y**2 + Z**2 - r_**2 * W**2) == 0
    for bp in ((1, sp.I, 0), (1, -sp.I, 0)):
        assert all(sp.expand(c.subs({s: bp[0], t: bp[1], u: bp[2]})) == 0 for c in (X, Y, Z, W))
    P = SurfaceParametrization.from_polynomials(6 * s, 6 * t, 3 * (1 - s**2 - t**2), 1 + s**2 + t**2)
    assert base_point_count(P) == 2
    F = implicitize_surface(P)
    assert F.as_expr() == x**2 + y**2 + z**2 - 9 and F.total_degree() == 4 - 2
    def on_sphere(X_):
        return L.same_expr(0)(sp.expand(X_**2 + Y**2 + Z**2 - r_**2 * W**2))
    return reconstructed("x = 2rs^u", "x = 2rsu", "with x = 2rsu the parametrization satisfies x^2 + y^2 + z^2 = r^2 w^2; exactly two base points (1, +-i, 0); degree 4 - 2 = 2",
        printed_form=2 * r_ * s**u, corrected_form=2 * r_ * s * u, check=L.predicate(on_sphere),
    )


@claim(DOC, "17.10", "degree drop", "with r base points the implicit degree is n^2 - r")
def base_point_degree_drop():
    r = random.Random(1710)
    # quadratic triangular patches whose four components all vanish at (0, 0) (and (1, 0))
    found = []
    for k in (1, 2):
        comps = []
        for _ in range(4):
            a, b, c, d, e = (r.randint(-4, 4) for _ in range(5))
            if k == 2:
                d = -a  # q(1, 0) = a + d = 0
            comps.append(a * s**2 + b * s * t + c * t**2 + d * s + e * t)  # q(0, 0) = 0
        P = SurfaceParametrization.from_polynomials(*comps)
        nb = base_point_count(P)
        F = implicitize_surface(P)
        assert nb >= k and F.total_degree() == 4 - nb and _vanishes(F.as_expr(), P) and _irreducible(F.as_expr())
        common = sp.solve(comps, [s, t], dict=True)  # affine common zeros (sympy); none at infinity for these random quadratic parts
        assert len(common) == nb
        found.append((k, nb, F.total_degree()))
    return verified_range("random quadratic triangular patches with 1 and 2 imposed base points", f"(imposed, counted, degree) = {found}: degree = 4 - r",
        compared='printed degree n^2 - r vs the degree of an equation that vanishes on the patch (Fraction grid) and is irreducible (sympy factor_list), r = the common zeros of the four components found by sympy.solve',
        reference='sympy')


# ---------------------------------------------------------------- 17.11
@claim(DOC, "17.11.1", "integer ideals", "21 = 6*2 + 9, 3 = 2*6 - 9 in <6, 9>; <6, 9> = <12, 15> = <3>")
def integer_ideals():
    assert 6 * 2 + 9 * 1 == 21 and 2 * 6 - 9 == 3
    assert math.gcd(6, 9) == math.gcd(12, 15) == 3
    # generator-wise membership (the theorem of 17.11.1)
    assert all(v % 3 == 0 for v in (6, 9, 12, 15))
    return verified("gcd 3 generates both ideals",
        compared='printed combinations 21 = 6*2 + 9, 3 = 2*6 - 9 and <6, 9> = <12, 15> = <3> vs integer arithmetic and math.gcd',
        reference='exact')


@claim(DOC, "17.11.3", "term orders", "lex x>y>z, z>x>y, y>z>x and deglex orderings of 3x^2y^2z + 4xy^3z^2 + 5x^3z + 6y^2 + 7xz^3 + 8")
def term_orders():
    f = 3 * x**2 * y**2 * z + 4 * x * y**3 * z**2 + 5 * x**3 * z + 6 * y**2 + 7 * x * z**3 + 8

    def ordered(gens, order):
        P = sp.Poly(f, *gens)
        return [sp.Mul(c, *[g**e for g, e in zip(gens, m)]) for m, c in P.terms(order=order)]

    assert ordered((x, y, z), "lex") == [5 * x**3 * z, 3 * x**2 * y**2 * z, 4 * x * y**3 * z**2, 7 * x * z**3, 6 * y**2, 8]
    assert ordered((z, x, y), "lex") == [7 * z**3 * x, 4 * z**2 * x * y**3, 5 * z * x**3, 3 * z * x**2 * y**2, 6 * y**2, 8]
    assert ordered((y, z, x), "lex") == [4 * y**3 * z**2 * x, 3 * y**2 * z * x**2, 6 * y**2, 7 * z**3 * x, 5 * z * x**3, 8]
    assert ordered((x, y, z), "grlex") == [4 * x * y**3 * z**2, 3 * x**2 * y**2 * z, 5 * x**3 * z, 7 * x * z**3, 6 * y**2, 8]
    return verified("sympy monomial orders reproduce all four printed orderings",
        compared="printed four orderings of the example polynomial vs sympy's lex / grlex monomial orders with the printed variable orders",
        reference='sympy')


@claim(DOC, "17.11.4", "linear ideal", "<x+y+z-6, x-y-z, x-2y+z-3> = <x-3, y-1, z-2>")
def linear_ideal():
    assert ideals_equal([x + y + z - 6, x - y - z, x - 2 * y + z - 3], [x - 3, y - 1, z - 2], [x, y, z])
    G = sp.groebner([x + y + z - 6, x - y - z, x - 2 * y + z - 3], x, y, z, order="lex", method="buchberger")
    assert list(G.exprs) == [x - 3, y - 1, z - 2]
    return verified("reduced Gröbner bases agree (exactcagd and sympy buchberger)",
        compared="printed basis <x-3, y-1, z-2> vs sympy's reduced Groebner basis (buchberger, lex); exactcagd's ideals_equal agrees",
        reference='sympy')


@claim(DOC, "17.11.4", "univariate ideal", "<t^4 - 3t^3 + 4t^2 - t - 4, t^6 - 4t^3 + 3> = <t - 1>: t = 1 is the common zero")
def univariate_ideal():
    f, g = t**4 - 3 * t**3 + 4 * t**2 - t - 4, t**6 - 4 * t**3 + 3
    assert f.subs(t, 1) == -3 and sp.gcd(f, g) == 1
    assert [p.as_expr() for p in groebner([f, g], [t])] == [1]
    f1 = t**4 - 3 * t**3 + 4 * t**2 - t - 1
    assert sp.gcd(f1, g) == t - 1
    def generated_ideal(gen):
        basis = [p.as_expr() for p in groebner([f, g], [t])]
        return None if basis == [gen] else f"the Groebner basis of the printed pair is {basis}"
    return erratum(
        "<t^4 - 3t^3 + 4t^2 - t - 4, t^6 - 4t^3 + 3> = <t - 1>",
        "the printed ideal is <1> (gcd 1, empty variety: f(1) = -3); with constant -1, <t^4 - 3t^3 + 4t^2 - t - 1, t^6 - 4t^3 + 3> = <t - 1>",
        "Euclid's algorithm (sympy gcd) and the Gröbner basis [1]",
        printed_form=t - 1, corrected_form=sp.Integer(1), check=L.predicate(generated_ideal),
    )


@claim(DOC, "17.11.5", "special cases", "univariate: the Gröbner basis is the gcd; linear: an upper-triangular form")
def groebner_special_cases():
    r = random.Random(1711)
    for _ in range(4):
        common = sp.prod([t - r.randint(-3, 3) for _ in range(r.randint(0, 2))])
        f = sp.expand(common * sp.prod([t - r.randint(4, 9) for _ in range(2)]))
        g = sp.expand(common * sp.prod([t + r.randint(4, 9) for _ in range(2)]))
        G = groebner([f, g], [t])
        assert len(G) == 1 and sp.expand(G[0].as_expr() - sp.Poly(sp.gcd(f, g), t).monic().as_expr()) == 0
        A = sp.Matrix(3, 3, lambda i, j: r.randint(-4, 4))
        if A.det() == 0:
            continue
        b = sp.Matrix([r.randint(-5, 5) for _ in range(3)])
        eqs = list(A * sp.Matrix([x, y, z]) - b)
        sol = A.LUsolve(b)
        assert [p.as_expr() for p in groebner(eqs, [x, y, z])] == [x - sol[0], y - sol[1], z - sol[2]]
    return verified_range("4 random univariate pairs and 3x3 linear systems", "basis = monic gcd; basis = solved triangular system",
        compared='printed special cases vs sympy.gcd (monic) for univariate pairs and sympy LUsolve for 3x3 linear systems',
        reference='sympy')


@claim(DOC, "17.11.5", "engine", "Gröbner bases by Buchberger's algorithm (any term order)")
def groebner_engines_agree():
    polys = [x**2 + y**2 + z**2 - 1, x**2 - y + z, x - z**2]
    for order in ("lex", "grevlex", "grlex"):
        ours = [p.as_expr() for p in groebner(polys, [x, y, z], order)]
        ref = [sp.Poly(p, x, y, z).monic().as_expr() for p in sp.groebner(polys, x, y, z, order=order, method="buchberger").exprs]
        assert sorted(map(str, ours)) == sorted(map(str, ref))
        assert all(ideal_contains(p, polys, [x, y, z]) for p in ours)
    # engines agree on a harder lex problem (flint -> FGLM fallback path)
    assert [p.as_expr() for p in groebner_basis(polys, [x, y, z], "lex", "f5b")] == [p.as_expr() for p in groebner(polys, [x, y, z], "lex")]
    return verified("reduced bases equal sympy's Buchberger for lex, grevlex, grlex",
        compared="exactcagd's reduced Groebner bases vs sympy's Buchberger (lex, grevlex, grlex), each element in the ideal",
        reference='sympy')

"""Sederberg's notes, chapter 17 items without a row: 17.3.1 (17.1), (17.2), 17.3.2 (17.5) and its
two examples, the 17.3.3 example's equation references, 17.7 (17.16)-(17.18), 17.11.3-17.11.4
(17.24), (17.25).

Every check is sympy from first principles (root products, Sylvester resultants, null spaces,
Groebner bases); no exactcagd function is under test here.
"""

from __future__ import annotations

import random

import sympy as sp

from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified, verified_range

DOC = "sederberg"
t, T, U, x, y, z = sp.symbols("t T U x y z")


def _root_product(fr, gr):
    """R(f, g) = prod_i prod_j (f_i - g_j) for monic f, g with roots fr, gr (17.2)."""
    return sp.prod([a - b for a in fr for b in gr])


def _sylvester_resultant(f, g):
    """Determinant of the Sylvester matrix of f, g in t (sympy 1.14's ``resultant`` returns -3 for
    Res(t - 2, (t-1)(t-3)(t-5)) = 3, a sign slip when deg f < deg g and deg f * deg g is odd; the
    determinant is the definition)."""
    from sympy.polys.subresultants_qq_zz import sylvester

    return sp.expand(sylvester(sp.expand(f), sp.expand(g), t, 1).det(method="berkowitz"))


def _bracket_det(f, g):
    """(17.8): det [[(a2 b1), (a2 b0)], [(a2 b0), (a1 b0)]] with (a_i b_j) = a_i b_j - a_j b_i."""
    a = sp.Poly(f, t).all_coeffs()[::-1]
    b = sp.Poly(g, t).all_coeffs()[::-1]
    br = lambda i, j: a[i] * b[j] - a[j] * b[i]  # noqa: E731
    return sp.Matrix([[br(2, 1), br(2, 0)], [br(2, 0), br(1, 0)]]).det()


@claim(doc=DOC, section="17.3.1", ref="(17.1)",
       statement="for f = sum a_i t^i, g = sum b_i t^i the resultant R(f, g) = 0 iff f and g have a common root; integer coefficients give an integer resultant")
def resultant_vanishes_iff_common_root():
    rng = random.Random(171)
    hits = misses = 0
    for n in (1, 2, 3, 4):
        for _ in range(6):
            f = sp.expand(sum(rng.randint(-5, 5) * t**i for i in range(n)) + rng.randint(1, 3) * t**n)
            g = sp.expand(sum(rng.randint(-5, 5) * t**i for i in range(n)) + rng.randint(1, 3) * t**n)
            if rng.random() < 0.5:  # plant a common root
                r = sp.Rational(rng.randint(-4, 4), rng.randint(1, 3))
                f, g = sp.expand(f * (t - r)), sp.expand(g * (t - r))
            res = _sylvester_resultant(f, g)
            common = bool(sp.degree(sp.gcd(f, g), t) >= 1)  # a common (complex) root iff a non-constant gcd
            assert (res == 0) == common and res.is_integer
            hits, misses = hits + common, misses + (not common)
    assert hits and misses
    return verified_range("degrees 1..5, 24 random integer pairs (half with a planted common root)",
                          "the Sylvester determinant is zero exactly for the pairs with a non-constant gcd; always an integer",
                          compared="printed (17.1) claim vs the Sylvester determinant and the polynomial gcd (sympy)", reference="sympy")


@claim(doc=DOC, section="17.3.1", ref="(17.2)",
       statement="for f = prod (t - f_i), g = prod (t - g_j) the resultant is R(f, g) = prod_i prod_j (f_i - g_j)")
def resultant_root_product_formula():
    for m, n in ((1, 1), (1, 2), (1, 3), (2, 1), (2, 2), (2, 3), (3, 1), (3, 2)):
        fr = sp.symbols(f"f1:{m + 1}")
        gr = sp.symbols(f"g1:{n + 1}")
        f, g = sp.expand(sp.prod([t - a for a in fr])), sp.expand(sp.prod([t - b for b in gr]))
        assert sp.expand(_sylvester_resultant(f, g) - _root_product(fr, gr)) == 0
    return verified("symbolic roots, (m, n) in {1, 2, 3}^2 except (3, 3) (sympy): the Sylvester resultant of the monic factored forms equals the root-difference product",
                    compared="printed (17.2) product vs the determinant of the Sylvester matrix (sympy)", reference="sympy")


@claim(doc=DOC, section="17.3.2", ref="(17.5)",
       statement="[[a1, a0], [b1, b0]] (T, U) = 0 has a non-trivial solution iff a1 b0 - b1 a0 = 0; then t = T/U is the common root")
def homogeneous_linear_system():
    rng = random.Random(175)
    seen = {True: 0, False: 0}
    for _ in range(40):
        a1, a0, b1, b0 = (rng.randint(-3, 3) for _ in range(4))
        M = sp.Matrix([[a1, a0], [b1, b0]])
        if M == sp.zeros(2, 2) or (a1, a0) == (0, 0) or (b1, b0) == (0, 0):
            continue  # not two degree <= 1 polynomials
        null = M.nullspace()
        f, g = a1 * T + a0 * U, b1 * T + b0 * U
        # common root of the homogeneous forms (on the projective line, roots at infinity U = 0 included)
        common = [s for s in ((sp.Integer(1), sp.Integer(0)),) + tuple((sp.Rational(p, q), sp.Integer(1)) for p in range(-9, 10) for q in (1, 2, 3))
                  if f.subs({T: s[0], U: s[1]}) == 0 and g.subs({T: s[0], U: s[1]}) == 0]
        assert bool(null) == (a1 * b0 - b1 * a0 == 0)
        if null and null[0][1] != 0:
            root = null[0][0] / null[0][1]  # t = T/U
            assert (a1 * root + a0 == 0 or a1 == a0 == 0) and (b1 * root + b0 == 0)
        assert bool(common) == bool(null)
        seen[bool(null)] += 1
    assert seen[True] and seen[False]
    return verified("40 random integer systems (sympy null space): a non-trivial (T, U) exists exactly when the determinant vanishes, "
                    "and T/U is then the common root (U = 0: the common root at infinity)",
                    compared="printed (17.5) vs sympy null space and a direct search for the common root", reference="sympy")


@claim(doc=DOC, section="17.3.2", ref="examples",
       statement="Example: 2t + 1 and t + 3: R = 2*3 - 1*1 = 5, no common root; t - 2 and 3t - 6: R = 1*(-6) - 3*(-2) = 0, a common root")
def linear_examples():
    for f, g, printed_R, printed_common in ((2 * t + 1, t + 3, 5, False), (t - 2, 3 * t - 6, 0, True)):
        (a1, a0), (b1, b0) = sp.Poly(f, t).all_coeffs(), sp.Poly(g, t).all_coeffs()
        # independent: the roots -a0/a1, -b0/b1 and the root product a1 b1 (f_1 - g_1) of (17.2) scaled to the leading coefficients
        rf, rg = sp.solve(f, t)[0], sp.solve(g, t)[0]
        assert a1 * b0 - b1 * a0 == printed_R == sp.expand(a1 * b1 * (rf - rg))
        assert (rf == rg) == printed_common
    return verified("both examples: the printed values 5 and 0 equal a1 b0 - b1 a0 and a1 b1 (f_1 - g_1) from the roots; the roots "
                    "-1/2, -3 differ, 2 = 2 agree",
                    compared="printed example values vs the roots (sympy solve)", reference="sympy")


@claim(doc=DOC, section="17.3.3", ref="example references (17.9)",
       statement="Example: the resultant of t^2 - 7t + 12 and t^2 - 3t + 2, 12 by (17.3), 'this time we use (??)'; 'a resultant computed by (??) and one using (17.8) can differ by a sign'")
def quadratic_example_references():
    f, g = t**2 - 7 * t + 12, t**2 - 3 * t + 2
    formulas = {  # the document's numbered formulas that compute a resultant of two quadratics
        "(17.2)": lambda p, q: sp.LC(p, t) ** 2 * sp.LC(q, t) ** 2 * _root_product(sp.solve(p, t), sp.solve(q, t)),
        "(17.8)": _bracket_det,
    }

    def names_the_right_formulas(refs):
        used, other = refs
        if used not in formulas or other not in formulas:
            return f"{refs} names no numbered resultant formula"
        if formulas[used](f, g) != -12:  # (17.9) evaluates the bracket determinant to -12
            return f"{used} gives {formulas[used](f, g)} on the example, (17.9) shows -12"
        # the note: |{other}| = |(17.8)| when a2 = b2 = 1, and they can differ by a sign (random monic and non-monic pairs)
        rng = random.Random(1739)
        for lead in (1, 2):
            for _ in range(3):
                p = lead * t**2 + rng.randint(-5, 5) * t + rng.randint(-5, 5)
                q = lead * t**2 + rng.randint(-5, 5) * t + rng.randint(-5, 5)
                a, b = sp.expand(formulas[other](p, q)), sp.expand(_bracket_det(p, q))
                if lead == 1 and sp.simplify(sp.Abs(a) - sp.Abs(b)) != 0:
                    return f"{other} and (17.8) differ in absolute value for monic {p}, {q}"
        if other == "(17.8)":
            return "the note compares (17.8) with itself"
        return None

    return erratum("'this time we use (??)'; 'a resultant computed by (??) and ... (17.8) can differ by a sign'",
                   "'this time we use (17.8)'; 'a resultant computed by the root product (17.2) and ... (17.8)'",
                   "LaTeX's unresolved-reference marker (??) is printed twice; (17.9) evaluates the bracket determinant (17.8) to -12 "
                   "and the note compares the root product of (17.2)/(17.3) (value 12) with it",
                   printed_form=("(??)", "(??)"), corrected_form=("(17.8)", "(17.2)"),
                   check=L.predicate(names_the_right_formulas), reference="text")


@claim(doc=DOC, section="17.7", ref="(17.16)-(17.18)",
       statement="for a rational cubic, linear f = a2 x + b2 y + c2 w, g = a1 x + b1 y + c1 w exist with f(x(t), y(t), w(t)) / g(...) == t, i.e. t g - f == 0")
def linear_inversion_equation():
    rng = random.Random(1716)
    a1, b1, c1, a2, b2, c2 = unknowns = sp.symbols("a1 b1 c1 a2 b2 c2")
    for _ in range(4):
        xt, yt, wt = (sum(rng.randint(-5, 5) * t**i for i in range(4)) for _ in range(3))
        g = a1 * xt + b1 * yt + c1 * wt
        f = a2 * xt + b2 * yt + c2 * wt
        # (17.18): every coefficient of t g - f vanishes: 5 linear equations in 6 unknowns, a non-trivial solution
        eqs = sp.Poly(sp.expand(t * g - f), t).all_coeffs()
        A = sp.Matrix([[sp.diff(e, u) for u in unknowns] for e in eqs])
        sol = A.nullspace()
        assert sol
        sub = dict(zip(unknowns, sol[0]))
        gs, fs = sp.expand(g.subs(sub)), sp.expand(f.subs(sub))
        if gs == 0:
            continue
        assert sp.cancel(fs / gs - t) == 0  # (17.17)
        # the inversion formula recovers t from a point of the curve
        tv = sp.Rational(rng.randint(-9, 9), 7)
        P = [v.subs(t, tv) for v in (xt, yt, wt)]
        den = (sol[0][0] * P[0] + sol[0][1] * P[1] + sol[0][2] * P[2])
        if den != 0:
            assert (sol[0][3] * P[0] + sol[0][4] * P[1] + sol[0][5] * P[2]) / den == tv
    return verified("4 random integer rational cubics (sympy): the coefficients of t g - f give 5 equations in 6 unknowns, whose null space "
                    "yields f/g == t identically and recovers t at a curve point",
                    compared="printed (17.16)-(17.18) vs sympy null space and substitution", reference="sympy")


@claim(doc=DOC, section="17.11.4", ref="(17.24)",
       statement="<f_1, ..., f_s> = {p_1 f_1 + ... + p_s f_s}; any polynomial ideal can be defined using different generating sets")
def polynomial_ideal():
    gens = [x**2 + y**2 - 1, x - y]
    G = sp.groebner(gens, x, y, order="lex")
    # the reduced Groebner basis is another generating set: each side's generators lie in the other's ideal
    assert all(G.reduce(f)[1] == 0 for f in gens)
    assert all(sp.groebner(gens + [0], x, y, order="grevlex").reduce(h)[1] == 0 for h in G.exprs)
    assert list(G.exprs) != gens
    # a combination p1 f1 + p2 f2 is a member; 1 (a non-member: the variety is non-empty) is not
    member = sp.expand((3 * x * y + 2) * gens[0] + (x**3 - y) * gens[1])
    assert G.reduce(member)[1] == 0 and G.reduce(sp.Integer(1))[1] != 0
    assert sp.groebner([x + y, x - y], x, y, order="lex").exprs == sp.groebner([x, y], x, y, order="lex").exprs
    return verified("<x^2 + y^2 - 1, x - y> equals the ideal of its reduced lex Groebner basis (each generator reduces to 0 by the other set); "
                    "p1 f1 + p2 f2 is a member, 1 is not; <x + y, x - y> = <x, y>",
                    compared="printed (17.24) vs sympy Groebner bases", reference="sympy")


@claim(doc=DOC, section="17.11.4", ref="(17.25)",
       statement="V(f_1, ..., f_s) = {(a_1..a_n) in k^n | f_i(a_1..a_n) = 0, i = 0, ..., s}, the intersection of V(f_1) ... V(f_s)")
def variety_index_range():
    fs = {1: x**2 + y**2 - 1, 2: x - y, 3: x + y - z}  # generators f_1, f_2, f_3 (s = 3)

    def defines_the_variety(index_range):
        lo, hi = index_range
        missing = [i for i in range(lo, hi + 1) if i not in fs]
        if missing:
            return f"i = {lo}, ..., {hi} needs f_{missing[0]}, not among the generators f_1, ..., f_3"
        if set(range(lo, hi + 1)) != set(fs):
            return f"i = {lo}, ..., {hi} leaves out generators"
        V = sp.solve([fs[i] for i in range(lo, hi + 1)], [x, y, z], dict=True)
        # the intersection of the hypersurfaces: every point satisfies each f_i, and (17.25) finds the 2 real points
        if len(V) != 2 or any(sp.simplify(f.subs(p)) != 0 for p in V for f in fs.values()):
            return f"V = {V}"
        return None

    return erratum("i = 0, ..., s", "i = 1, ..., s",
                   "the generators are f_1, ..., f_s; an index from 0 names a polynomial f_0 that the definition does not have "
                   "(V(x^2 + y^2 - 1, x - y, x + y - z) computed by sympy solve: two points, on every V(f_i))",
                   printed_form=(0, 3), corrected_form=(1, 3), check=L.predicate(defines_the_variety), reference="text")

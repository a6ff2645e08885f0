"""Sederberg's notes, chapter 17.2-17.4: brute-force implicitization, resultants
(Bezout and Sylvester), common roots by linear equations and by Euclid's algorithm.

References are independent of the code under test: products of root differences
(17.2), sympy ``Matrix.det`` of the printed matrices, sympy polynomial division.
(sympy's own ``resultant`` is not used as a reference: it returns the wrong sign
when the first polynomial has the lower degree and both degrees are odd,
sympy issue #10666.)
"""

from __future__ import annotations

import itertools
import random

import sympy as sp

from exactcagd.algebra import (
    bezout_matrix,
    common_root_count,
    common_roots_linear,
    curve_from_polynomials,
    euclid_steps,
    implicitize,
    resultant,
    sylvester_matrix,
)
from exactcagd.algebra.resultants import bezout_sign, echelon_bareiss
from exactcagd.algebra.traces import trace_bezout
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, reconstructed, verified, verified_range

DOC = "sederberg"
x, y, t = sp.symbols("x y t")


def _root_product(f_roots, g_roots):
    out = sp.Integer(1)
    for a in f_roots:
        for b in g_roots:
            out *= a - b
    return out


def _sylvester_sympy(a, b):
    """Sylvester's matrix of sum a_i t^i, sum b_j t^j (coefficients low to high) written out in sympy; det = Res(f, g)."""
    m, n = len(a) - 1, len(b) - 1
    S = sp.zeros(m + n, m + n)
    for r in range(n):
        for k, c in enumerate(reversed(a)):
            S[r, r + k] = c
    for r in range(m):
        for k, c in enumerate(reversed(b)):
            S[n + r, r + k] = c
    return S


def _bez(f, g):
    """The notes' bracket matrix (a_i b_j) built with sympy from the formula of 17.3.4."""
    a = sp.Poly(f, t).all_coeffs()[::-1]
    b = sp.Poly(g, t).all_coeffs()[::-1]
    n = max(len(a), len(b)) - 1
    a += [0] * (n + 1 - len(a))
    b += [0] * (n + 1 - len(b))
    br = lambda i, j: a[i] * b[j] - a[j] * b[i]  # noqa: E731
    L = lambda i, j: sum(br(i + j + 1 - m, m) for m in range(min(i, j) + 1) if i + j + 1 - m <= n)  # noqa: E731
    return sp.Matrix(n, n, lambda r, c: L(n - 1 - r, n - 1 - c))


# ---------------------------------------------------------------- 17.2
@claim(DOC, "17.2", "line", "x = t + 2, y = 3t + 1: 3x - y - 5 = 0; t = x - 2 = (y - 1)/3")
def brute_force_line():
    X, Y = t + 2, 3 * t + 1
    assert sp.expand(3 * X - Y - 5) == 0
    assert sp.expand((X - 2) - t) == 0 and sp.expand((Y - 1) / 3 - t) == 0
    c = curve_from_polynomials(X, Y)
    assert implicitize(c).as_expr() == 3 * x - y - 5
    return verified("substitution (sympy) and implicitize()",
        compared='printed 3x - y - 5 = 0 and t = x - 2 = (y - 1)/3 vs sympy substitution of x = t + 2, y = 3t + 1',
        reference='sympy')


@claim(DOC, "17.2", "parabola", "x = t^2 + 1, y = t^2 + 2t - 2: x^2 - 2xy + y^2 - 10x + 6y + 13 = 0")
def brute_force_parabola():
    X, Y = t**2 + 1, t**2 + 2 * t - 2
    printed = x**2 - 2 * x * y + y**2 - 10 * x + 6 * y + 13
    assert sp.expand(printed.subs({x: X, y: Y})) == 0
    # the squaring step: (y - (x - 1) + 2)^2 = 4 (x - 1)
    assert sp.expand((y - (x - 1) + 2) ** 2 - 4 * (x - 1) - printed) == 0
    assert implicitize(curve_from_polynomials(X, Y)).as_expr() == printed
    return verified("vanishes on the parametrization; equals the squared form and implicitize()",
        compared='printed x^2 - 2xy + y^2 - 10x + 6y + 13 vs sympy substitution of the parametrization and expansion of the squared form (y - (x-1) + 2)^2 = 4(x-1)',
        reference='sympy')


@claim(DOC, "17.2", "inversion (5,-2)", "x = 5 gives t = +-2, y = -2 gives t = -2 or 0; so t = -2")
def brute_force_inversion_point():
    sx = set(sp.solve(t**2 + 1 - 5, t))
    sy = set(sp.solve(t**2 + 2 * t - 2 + 2, t))
    assert sx == {2, -2} and sy == {-2, 0} and sx & sy == {-2}
    return verified("root sets as printed; intersection {-2}",
        compared='printed root sets {+-2}, {-2, 0} and t = -2 vs sympy.solve of x(t) = 5, y(t) = -2',
        reference='sympy')


# ---------------------------------------------------------------- 17.3
@claim(DOC, "17.3.1", "(17.3)", "R(t^2-7t+12, t^2-3t+2) = 12; with g = t^2-5t+6 it is 0")
def resultant_root_product():
    assert _root_product([3, 4], [2, 1]) == 12 and _root_product([3, 4], [2, 3]) == 0
    f = t**2 - 7 * t + 12
    assert resultant(f, t**2 - 3 * t + 2, t) == 12
    assert resultant(f, t**2 - 5 * t + 6, t) == 0
    return verified("root-difference products; resultant() (Sylvester) agrees",
        compared='printed (17.3) values 12 and 0 vs the root-difference products (17.2) in exact integers',
        reference='exact')


@claim(DOC, "17.3.2", "(17.4)", "R(a1 t + a0, b1 t + b0) = a1 b0 - b1 a0; examples 5 and 0")
def resultant_linear():
    a0, a1, b0, b1 = sp.symbols("a0 a1 b0 b1")
    assert sp.expand(resultant(a1 * t + a0, b1 * t + b0, t) - (a1 * b0 - b1 * a0)) == 0
    assert sp.Matrix([[a1, a0], [b1, b0]]).det() == a1 * b0 - b1 * a0  # (17.5)
    assert resultant(2 * t + 1, t + 3, t) == 5 and resultant(t - 2, 3 * t - 6, t) == 0
    assert sp.Matrix([[2, 1], [1, 3]]).det() == 5 and sp.Matrix([[1, -2], [3, -6]]).det() == 0  # (17.5) of both examples
    return verified("symbolic resultant and the determinant of (17.5); both examples",
        compared='printed (17.4) a1 b0 - b1 a0 and the examples 5, 0 vs the sympy determinant of (17.5)',
        reference='sympy')


@claim(DOC, "17.3.2", "common root condition", "common root iff -a0/a1 = b0/b1")
def linear_common_root_sign():
    # f = t - 2, g = 3t - 6 share the root 2: -a0/a1 = 2 but b0/b1 = -2
    a0, a1, b0, b1 = -2, 1, -6, 3
    printed_holds = sp.Rational(-a0, a1) == sp.Rational(b0, b1)
    corrected_holds = sp.Rational(-a0, a1) == sp.Rational(-b0, b1)
    assert not printed_holds and corrected_holds
    def condition_holds(cond):
        # f = t - 2, g = 3t - 6 share the root t = 2: the condition must hold for them
        return None if cond(a0, a1, b0, b1) else "f = t - 2, g = 3t - 6 share t = 2 but the condition fails"
    return erratum("-a0/a1 = b0/b1", "-a0/a1 = -b0/b1", "sign lost; f = t - 2, g = 3t - 6 share t = 2 but violate the printed equality",
        printed_form=lambda a0_, a1_, b0_, b1_: sp.Rational(-a0_, a1_) == sp.Rational(b0_, b1_), corrected_form=lambda a0_, a1_, b0_, b1_: sp.Rational(-a0_, a1_) == sp.Rational(-b0_, b1_), check=L.predicate(condition_holds),
    )


@claim(DOC, "17.3.3", "(17.6), (17.7)", "h1 = a2 g - b2 f = (a2b1) t + (a2b0); h2 = (a2 t + a1) g - (b2 t + b1) f = (a2b0) t + (a1b0)")
def degree_two_auxiliary():
    a0, a1, a2, b0, b1, b2 = sp.symbols("a0 a1 a2 b0 b1 b2")
    f = a2 * t**2 + a1 * t + a0
    g = b2 * t**2 + b1 * t + b0
    br = lambda p, q: p * q.subs({a0: b0, a1: b1, a2: b2}, simultaneous=True) - 0  # noqa: E731,F841
    A = {0: a0, 1: a1, 2: a2}
    B = {0: b0, 1: b1, 2: b2}
    ab = lambda i, j: A[i] * B[j] - A[j] * B[i]  # noqa: E731
    assert sp.expand(a2 * g - b2 * f - (ab(2, 1) * t + ab(2, 0))) == 0
    assert sp.expand((a2 * t + a1) * g - (b2 * t + b1) * f - (ab(2, 0) * t + ab(1, 0))) == 0
    t2, t1, t0 = sp.symbols("T2 T1 T0")
    def h1_coefficients(form):
        ref = ab(2, 1) * t + ab(2, 0)
        return L.same_expr(sp.expand(a2 * g - b2 * f))(form)
    return reconstructed(
        "h1 = (2, 1)t + (2, 0)",
        "h1 = (a2b1) t + (a2b0)",
        "the extraction dropped the a/b letters in (17.6); both identities expand exactly (sympy)",
        printed_form=L.LOST, lost_reason='the letters of the brackets (a2b1), (a2b0) are lost: (2, 1)t + (2, 0)', corrected_form=ab(2, 1) * t + ab(2, 0), check=L.predicate(h1_coefficients),
    )


def _trace_quadratic():
    trace_bezout(t**2 - 7 * t + 12, t**2 - 3 * t + 2, t)


@claim(DOC, "17.3.3", "(17.8)-(17.9)", "Bezout matrix [[4,-10],[-10,22]] of t^2-7t+12, t^2-3t+2 has det -12 (sign differs from (17.3))", trace=_trace_quadratic)
def degree_two_example():
    M = _bez(t**2 - 7 * t + 12, t**2 - 3 * t + 2)
    assert M == sp.Matrix([[4, -10], [-10, 22]]) and M.det() == -12
    assert bezout_matrix([12, -7, 1], [2, -3, 1]) == [[4, -10], [-10, 22]]
    # the sign relation for every degree n: det(Bezout) = (-1)^(n(n-1)/2) Res
    r = random.Random(173)
    for n in range(1, 7):
        for _ in range(3):
            fr = [r.randint(-4, 4) for _ in range(n)]
            gr = [r.randint(-4, 4) for _ in range(n)]
            f = sp.expand(sp.prod([t - a for a in fr]))
            g = sp.expand(sp.prod([t - b for b in gr]))
            assert _bez(f, g).det() == bezout_sign(n) * _root_product(fr, gr)
    return verified("printed matrix and -12 reproduced; det(Bezout_n) = (-1)^(n(n-1)/2) prod(f_i - g_j), n = 1..6 random monic",
        compared='printed (17.8) matrix and det -12 vs the bracket matrix built in sympy from the formula of 17.3.4 and its sympy determinant; sign vs root products for n = 1..6',
        reference='sympy')


@claim(DOC, "17.3.4", "cubic Bezout", "h1, h2, h3 of the cubic case and R = det of the 3x3 bracket matrix")
def degree_three_auxiliary():
    a = sp.symbols("a0:4")
    b = sp.symbols("b0:4")
    f = sum(a[i] * t**i for i in range(4))
    g = sum(b[i] * t**i for i in range(4))
    ab = lambda i, j: a[i] * b[j] - a[j] * b[i]  # noqa: E731
    h1 = a[3] * g - b[3] * f
    h2 = (a[3] * t + a[2]) * g - (b[3] * t + b[2]) * f
    h3 = (a[3] * t**2 + a[2] * t + a[1]) * g - (b[3] * t**2 + b[2] * t + b[1]) * f
    assert sp.expand(h1 - (ab(3, 2) * t**2 + ab(3, 1) * t + ab(3, 0))) == 0
    assert sp.expand(h2 - (ab(3, 1) * t**2 + (ab(3, 0) + ab(2, 1)) * t + ab(2, 0))) == 0
    assert sp.expand(h3 - (ab(3, 0) * t**2 + ab(2, 0) * t + ab(1, 0))) == 0
    M = sp.Matrix([[ab(3, 2), ab(3, 1), ab(3, 0)], [ab(3, 1), ab(3, 0) + ab(2, 1), ab(2, 0)], [ab(3, 0), ab(2, 0), ab(1, 0)]])
    r = random.Random(1734)
    for _ in range(10):
        vals = {s_: r.randint(-6, 6) for s_ in a + b}
        vals[a[3]] = vals[a[3]] or 1
        vals[b[3]] = vals[b[3]] or -1
        S = sp.Matrix(sylvester_matrix([vals[v] for v in a], [vals[v] for v in b]))
        assert M.subs(vals).det() == -S.det()  # bezout_sign(3) = -1
    return verified("h1, h2, h3 expand as printed (symbolic); det(printed 3x3) = -det(Sylvester 6x6) on 10 random integer cubics",
        compared='printed h1, h2, h3 and the 3x3 bracket matrix vs sympy expansion of the defining combinations; det vs the sympy determinant of the Sylvester matrix',
        reference='sympy')


def _trace_cubics():
    trace_bezout(t**3 - 2 * t**2 + 3 * t + 1, 2 * t**3 + 3 * t**2 - t + 4, t)
    trace_bezout(t**3 - t**2 - 11 * t - 4, 2 * t**3 - 7 * t**2 - 5 * t + 4, t)


@claim(DOC, "17.3.4", "examples", "R = -1611 for t^3-2t^2+3t+1, 2t^3+3t^2-t+4; R = 0 for t^3-t^2-11t-4, 2t^3-7t^2-5t+4", trace=_trace_cubics)
def degree_three_examples():
    M1 = _bez(t**3 - 2 * t**2 + 3 * t + 1, 2 * t**3 + 3 * t**2 - t + 4)
    M2 = _bez(t**3 - t**2 - 11 * t - 4, 2 * t**3 - 7 * t**2 - 5 * t + 4)
    assert M1 == sp.Matrix([[7, -7, 2], [-7, -5, -11], [2, -11, 13]]) and M1.det() == -1611
    assert M2 == sp.Matrix([[-5, 17, 12], [17, -60, -32], [12, -32, -64]]) and M2.det() == 0
    assert resultant(t**3 - 2 * t**2 + 3 * t + 1, 2 * t**3 + 3 * t**2 - t + 4, t) == 1611
    return verified("both matrices and determinants as printed (the Sylvester resultant is +1611)",
        compared='printed 3x3 matrices and determinants -1611, 0 vs the bracket matrices built in sympy from 17.3.4 and their sympy determinants',
        reference='sympy')


@claim(DOC, "17.3.5", "Sylvester", "Sylvester's 2n x 2n resultant is equivalent to Bezout's n x n resultant")
def sylvester_vs_bezout():
    r = random.Random(1735)
    count = 0
    for m, n in itertools.product(range(1, 6), repeat=2):
        a = [r.randint(-5, 5) for _ in range(m)] + [r.choice([-2, 1, 3])]
        b = [r.randint(-5, 5) for _ in range(n)] + [r.choice([-1, 2, 5])]
        S = sp.Matrix(sylvester_matrix(a, b)).det()
        big, small = (a, b) if m >= n else (b, a)
        B = sp.Matrix(bezout_matrix(big, small)).det()
        sign = bezout_sign(max(m, n)) * ((-1) ** (m * n) if m < n else 1)
        assert B == sign * S
        # independent: Sylvester's matrix written out in sympy (its determinant is the root product (17.2), checked below)
        assert sp.Matrix(sylvester_matrix(a, b)) == _sylvester_sympy(a, b)
        assert B == sign * _sylvester_sympy(a, b).det()
        count += 1
    for m, n in itertools.product(range(1, 5), repeat=2):  # det of the sympy Sylvester matrix = prod (f_i - g_j) for monic f, g
        fr, gr = [r.randint(-4, 4) for _ in range(m)], [r.randint(-4, 4) for _ in range(n)]
        a = sp.Poly(sp.prod([t - c for c in fr]), t).all_coeffs()[::-1]
        b = sp.Poly(sp.prod([t - c for c in gr]), t).all_coeffs()[::-1]
        assert _sylvester_sympy(a, b).det() == _root_product(fr, gr)
    return verified_range("degrees 1..5 x 1..5, random integer coefficients", f"{count} pairs: det(hybrid Bezout) = +-det(Sylvester) with the stated sign",
        compared="printed equivalence of Sylvester and Bezout resultants vs the determinant of Sylvester's matrix written out in sympy (itself checked against root products (17.2))",
        reference='sympy')


# ---------------------------------------------------------------- 17.4
@claim(DOC, "17.4", "Cramer", "t = -|(-5 12),(17 -32)| / |(-5 17),(17 -60)| = 4")
def cramer_example():
    num = sp.Matrix([[-5, 12], [17, -32]]).det()
    den = sp.Matrix([[-5, 17], [17, -60]]).det()
    assert -num / den == 4
    out = common_roots_linear(t**3 - t**2 - 11 * t - 4, 2 * t**3 - 7 * t**2 - 5 * t + 4)
    assert out["root"] == 4 and out["count"] == 1
    assert (t**3 - t**2 - 11 * t - 4).subs(t, 4) == 0 and (2 * t**3 - 7 * t**2 - 5 * t + 4).subs(t, 4) == 0
    return verified("Cramer's rule gives 4, a common root of both cubics",
        compared='printed Cramer quotient t = 4 vs sympy determinants and substitution into both cubics',
        reference='sympy')


def _bareiss_sympy(M):
    """Integer-preserving elimination written out independently (sympy entries)."""
    M = sp.Matrix(M)
    n = M.rows
    prev = 1
    for k in range(n - 1):
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                M[i, j] = sp.cancel((M[k, k] * M[i, j] - M[i, k] * M[k, j]) / prev)
            M[i, k] = 0
        prev = M[k, k]
    return M


@claim(DOC, "17.4", "Gauss example 1", "integer-preserving elimination: [[7,-7,2],[0,-84,0],[0,0,-1611]]")
def gauss_example_1():
    E = _bareiss_sympy([[7, -7, 2], [-7, -5, -11], [2, -11, 13]])
    assert E == sp.Matrix([[7, -7, 2], [0, -84, -63], [0, 0, -1611]])
    ours, rank = echelon_bareiss([[7, -7, 2], [-7, -5, -11], [2, -11, 13]])
    assert [list(r) for r in ours] == [[7, -7, 2], [0, -84, -63], [0, 0, -1611]] and rank == 3
    def row_two(row):
        ref = list(E.row(1))
        return None if list(row) == ref else f"row 2 = {list(row)}, integer-preserving elimination (sympy) gives {ref}"
    return erratum(
        "row 2 = (0, -84, 0)",
        "row 2 = (0, -84, -63)",
        "7*(-11) - (-7)*2 = -63; the corner -1611 (the determinant) is right",
        printed_form=(0, -84, 0), corrected_form=(0, -84, -63), check=L.predicate(row_two),
    )


@claim(DOC, "17.4", "Gauss example 2", "[[-5,17,12],[0,11,-44],[0,0,0]]: TU = 4U^2, common root t = 4")
def gauss_example_2():
    E = _bareiss_sympy([[-5, 17, 12], [17, -60, -32], [12, -32, -64]])
    assert E == sp.Matrix([[-5, 17, 12], [0, 11, -44], [0, 0, 0]])
    return verified("elimination reproduced; 11 TU - 44 U^2 = 0 gives t = 4",
        compared='printed echelon form [[-5,17,12],[0,11,-44],[0,0,0]] vs integer-preserving elimination written out in sympy',
        reference='sympy')


@claim(DOC, "17.4", "Gauss example 3", "rank 1: two common roots, gcd -t^2 + 3t - 2, t = 1, 2")
def gauss_example_3():
    f, g = t**3 - 6 * t**2 + 11 * t - 6, t**3 - 7 * t**2 + 14 * t - 8
    M = _bez(f, g)
    assert M == sp.Matrix([[-1, 3, -2], [3, -9, 6], [-2, 6, -4]]) and M.rank() == 1
    out = common_roots_linear(f, g)
    assert out["count"] == 2 and sp.expand(out["gcd"] - (-t**2 + 3 * t - 2)) == 0
    assert sp.gcd(f, g) == t**2 - 3 * t + 2 and common_root_count(f, g) == 2
    return verified("matrix, rank 1 and the gcd from the echelon row as printed",
        compared='printed rank-1 matrix and gcd -t^2 + 3t - 2 vs the sympy bracket matrix, its rank and sympy.gcd',
        reference='sympy')


@claim(DOC, "17.4", "Euclid (integers)", "42/30 = 1 r 12, 30/12 = 2 r 6, 12/6 = 2: gcd 6")
def euclid_integers():
    assert divmod(42, 30) == (1, 12) and divmod(30, 12) == (2, 6) and divmod(12, 6) == (2, 0)
    return verified("three division steps",
        compared='printed division steps 42 = 1*30 + 12, 30 = 2*12 + 6, 12 = 2*6 vs Python integer divmod',
        reference='exact')


def _div(a, b):
    q, r = sp.div(sp.Poly(a, t, domain="QQ"), sp.Poly(b, t, domain="QQ"))
    return q.as_expr(), r.as_expr()


@claim(DOC, "17.4", "Euclid example 1", "steps 2-4: quotient (t-1)/7 rem (12t+9)/7; (196t-343)/48 rem 1253/16; (192t+144)/8771")
def euclid_example_1():
    f, g = t**3 - 2 * t**2 + 3 * t + 1, 2 * t**3 + 3 * t**2 - t + 4
    q1, r1 = _div(g, f)
    q2, r2 = _div(f, r1)
    q3, r3 = _div(r1, r2)
    q4, r4 = _div(r2, r3)
    assert q1 == 2 and sp.expand(r1 - (7 * t**2 - 7 * t + 2)) == 0
    assert sp.expand(q2 - (t - 1) / 7) == 0 and sp.expand(r2 - (12 * t + 9) / 7) == 0
    assert sp.expand(q3 - (196 * t - 343) / 48) == 0 and r3 == sp.Rational(179, 16)
    assert sp.expand(q4 - (192 * t + 144) / 1253) == 0 and r4 == 0
    steps, gcd = euclid_steps(g, f)
    assert gcd == sp.Rational(179, 16) and len(steps) == 4 and steps[2]["remainder"] == sp.Rational(179, 16)
    return erratum(
        "step 3 remainder 1253/16; step 4 quotient (192t + 144)/8771",
        "step 3 remainder 179/16; step 4 quotient (192t + 144)/1253",
        "1253 = 7 * 179: the printed remainder is 7 times too large (step 2's line also prints the divisor as dividend); "
        "the gcd is still a constant: no common root",
        printed_form=sp.Rational(1253, 16), corrected_form=sp.Rational(179, 16), check=L.same_value(r3),
    )


@claim(DOC, "17.4", "Euclid example 2", "quotient -5t - 12/25 rem (-11t+44)/25; then 125t + 75/11 rem 0; root 4")
def euclid_example_2():
    f, g = t**3 - t**2 - 11 * t - 4, 2 * t**3 - 7 * t**2 - 5 * t + 4
    q1, r1 = _div(g, f)
    q2, r2 = _div(f, r1)
    q3, r3 = _div(r1, r2)
    assert q1 == 2 and sp.expand(r1 - (-5 * t**2 + 17 * t + 12)) == 0
    assert sp.expand(r2 - (-11 * t + 44) / 25) == 0 and sp.expand(q2 - (-t / 5 - sp.Rational(12, 25))) == 0
    assert sp.expand(q3 - (125 * t + 75) / 11) == 0 and r3 == 0
    def quotients(qs):
        return None if sp.expand(qs[0] - q2) == 0 and sp.expand(qs[1] - q3) == 0 else f"sympy division gives {q2} and {q3}"
    return erratum(
        "quotients -5t - 12/25 and 125t + 75/11",
        "quotients -t/5 - 12/25 and (125t + 75)/11",
        "exact polynomial division (sympy); remainders and the common root t = 4 are right",
        printed_form=(-5 * t - sp.Rational(12, 25), 125 * t + sp.Rational(75, 11)), corrected_form=(-t / 5 - sp.Rational(12, 25), (125 * t + 75) / 11), check=L.predicate(quotients),
    )


@claim(DOC, "17.4", "Euclid example 3", "t^3-6t^2+11t-6 = 1*(t^3-7t^2+14t-8) + t^2-3t+2; then t-4 rem 0")
def euclid_example_3():
    f, g = t**3 - 6 * t**2 + 11 * t - 6, t**3 - 7 * t**2 + 14 * t - 8
    q1, r1 = _div(f, g)
    q2, r2 = _div(g, r1)
    assert q1 == 1 and sp.expand(r1 - (t**2 - 3 * t + 2)) == 0 and sp.expand(q2 - (t - 4)) == 0 and r2 == 0
    return verified("division steps as printed; common roots 1, 2",
        compared='printed quotients 1, t - 4 and remainders t^2 - 3t + 2, 0 vs sympy polynomial division over QQ',
        reference='sympy')

"""Sederberg's notes, chapter 18.5: tangent moving lines, envelopes, reciprocal
curves, Plücker's relation and the scaled hodograph.

Independent references: sympy differentiation and cross products of the
parametrizations written out from the Bernstein definition.
"""

from __future__ import annotations

import random

import sympy as sp

from exactcagd import BezierCurve
from exactcagd.algebra import cusp_parameters, double_points, scaled_hodograph, tangent_control_lines, tangent_moving_line
from exactcagd.algebra.dual import inflection_polynomial
from exactcagd.proofs import _ledger as L
from exactcagd.proofs.sederberg_19_genus import _parameter_pairs
from exactcagd.proofs._ledger import claim, reconstructed, verified, verified_range

DOC = "sederberg"
t = sp.Symbol("t")


def _bern(points):
    n = len(points) - 1
    return sum((sp.binomial(n, i) * (1 - t) ** (n - i) * t**i * sp.Matrix([sp.Rational(str(v)) for v in p]) for i, p in enumerate(points)), sp.zeros(3, 1))


def _hom(curve):
    return [tuple(r) for r in curve.homogeneous()]


def _rand_curve(r, m, rational=True):
    return BezierCurve([[r.randint(-8, 8), r.randint(-8, 8)] for _ in range(m + 1)], [r.randint(1, 4) for _ in range(m + 1)] if rational else None)


def _deg(vec):
    return max(sp.Poly(sp.expand(c), t).degree() for c in vec)


@claim(DOC, "18.5.1", "(18.88)-(18.92)", "P x P' has degree <= 2m - 2: the t^(2m-1) coefficient P_m x m P_m vanishes")
def tangent_degree():
    r = random.Random(1888)
    for m in range(2, 7):
        P = _bern(_hom(_rand_curve(r, m)))
        T = P.cross(P.diff(t))
        assert _deg(T) == 2 * m - 2
        assert tangent_moving_line(_rand_curve(r, m)).degree == 2 * m - 2
    return verified_range("m = 2..6, random rational curves", "deg(P x P') = 2m - 2 exactly (sympy); no cusps: no reduction",
        compared="printed degree 2m - 2 of P x P' vs the degree of the cross product computed in sympy from the Bernstein form",
        reference='sympy')


@claim(DOC, "18.5.1", "(18.93)-(18.95)", "P x P' = m [sum B_i^(m-1) P_i] x [sum B_i^(m-1) P_(i+1)]")
def tangent_control_line_formula():
    r = random.Random(1895)
    for m in (2, 3, 4):
        c = _rand_curve(r, m)
        P = _bern(_hom(c))
        hom = _hom(c)
        A, B = _bern(hom[:-1]), _bern(hom[1:])
        assert (P.cross(P.diff(t)) - m * A.cross(B)).applyfunc(sp.expand) == sp.zeros(3, 1)
        assert (P.cross(P.diff(t)) - _bern(tangent_control_lines(c))).applyfunc(sp.expand) == sp.zeros(3, 1)
    return verified_range("m = 2, 3, 4, random rational curves", "symbolic identity; tangent_control_lines() reproduces it",
        compared="printed (18.93)-(18.95) m [sum B P_i] x [sum B P_(i+1)] vs sympy P x P' expanded identically; exactcagd's tangent_control_lines reproduces it",
        reference='sympy')


@claim(DOC, "18.5.1", "(18.96)", "the envelope Point(L x L') lies on L and L is tangent to it there")
def envelope_property():
    r = random.Random(1896)
    L = _bern([(r.randint(-5, 5), r.randint(-5, 5), r.randint(-5, 5)) for _ in range(4)])
    E = L.cross(L.diff(t))
    assert sp.expand(L.dot(E)) == 0 and sp.expand(L.dot(E.diff(t))) == 0
    return verified("L . E = 0 and L . E' = 0 (the tangent of E lies in L), random cubic moving line",
        compared="printed envelope property vs sympy L . (L x L') = 0 and L . (L x L')' = 0 for a random cubic moving line",
        reference='sympy')


@claim(DOC, "18.5.2", "(18.97)", "(P x P') x (P x P')' has degree 4m - 6 and equals P up to a factor (3m - 6 base points)")
def reciprocal_of_reciprocal():
    r = random.Random(1897)
    for m in (3, 4):
        P = _bern(_hom(_rand_curve(r, m)))
        B = P.cross(P.diff(t))
        BB = B.cross(B.diff(t))
        det = sp.expand(P.dot(P.diff(t).cross(P.diff(t, 2))))
        assert (BB - det * P).applyfunc(sp.expand) == sp.zeros(3, 1)
        assert _deg(BB) == 4 * m - 6 and sp.Poly(det, t).degree() == 3 * m - 6
    return verified_range("m = 3, 4", "(A x A') x (A x A')' = det(A, A', A'') A identically; degrees 4m - 6 and 3m - 6",
        compared="printed (18.97) vs the sympy identity (A x A') x (A x A')' = det(A, A', A'') A and the sympy degrees 4m - 6, 3m - 6",
        reference='sympy')


@claim(DOC, "18.5.2", "(18.98)-(18.100)", "2 kappa + iota = 3m - 6 and delta + kappa = (m - 1)(m - 2)/2 for rational curves")
def plucker():
    rows = []
    # a cubic with a cusp (kappa = 1) and generic cubics / quartics (kappa = 0)
    cusp = BezierCurve([[0, 0], [1, 1], [0, 1], [1, 0]])
    r = random.Random(18100)
    for c in [cusp, _rand_curve(r, 3), _rand_curve(r, 4), _rand_curve(r, 5, rational=False)]:
        m = c.degree
        D = sp.Poly([int(v) for v in reversed(inflection_polynomial(c).coeffs())], t)
        kappa = len(cusp_parameters(c))
        # det(P, P', P'') is a form of degree 3m - 6: roots at t = oo count 3m - 6 - deg
        total = 3 * m - 6
        # each cusp is a double root of the determinant
        for tc in cusp_parameters(c):
            assert D.eval(sp.Rational(str(tc.value))) == 0 and D.diff(t).eval(sp.Rational(str(tc.value))) == 0
        iota = total - 2 * kappa
        assert 2 * kappa + iota == 3 * m - 6 and D.degree() <= total
        # independent (sympy): det(P, P', P'') from the Bernstein form; its double roots are the cusps (P x P' = 0 there),
        # its simple roots inflections (P x P' != 0); a root at t = oo of multiplicity 3m - 6 - deg
        P = _bern(_hom(c))
        T = P.cross(P.diff(t))
        _, factors = sp.sqf_list(sp.expand(P.dot(P.diff(t).cross(P.diff(t, 2)))), t)
        at_infinity = total - sum(sp.degree(f, t) * k for f, k in factors)
        for f, k in factors:
            assert k <= 2
            divides_all = all(sp.rem(sp.expand(e), f, t) == 0 for e in T)
            assert divides_all == (k == 2), (m, f, k)
        if at_infinity <= 1:  # ordinary there as well (the polynomial quintic has a triple root at t = oo: not an ordinary point)
            kappa_sympy = sum(sp.degree(f, t) for f, k in factors if k == 2)
            iota_sympy = sum(sp.degree(f, t) for f, k in factors if k == 1) + at_infinity
            assert kappa_sympy == kappa and 2 * kappa_sympy + iota_sympy == 3 * m - 6
        dp = double_points(c)
        assert sum(d.count for d in dp) == (m - 1) * (m - 2) // 2
        # independent: parameter pairs with P(s) ~ P(t), with multiplicity (sympy Groebner): 2 per node, 2 per cusp (on s = t)
        pairs, no_diagonal = _parameter_pairs(c)
        assert pairs == (m - 1) * (m - 2) and no_diagonal == (kappa == 0)
        rows.append((m, kappa, iota))
    return verified_range("a cuspidal cubic, random cubic, quartic, quintic", f"(m, kappa, iota) = {rows}; cusps are double roots of det(P,P',P''); double points + cusps = (m-1)(m-2)/2",
        compared="printed 2 kappa + iota = 3m - 6 vs the roots of det(P, P', P'') factored in sympy (double roots are cusps: P x P' vanishes there; simple roots are not); printed delta + kappa = (m-1)(m-2)/2 vs the parameter pairs with P(s) ~ P(t) counted with multiplicity (sympy Groebner basis; a cusp lies on s = t)",
        reference='sympy')


@claim(DOC, "18.5.2", "(18.101)-(18.103)", "B = k1 (A x A') implies A = k2 (B x B') with k2 = 1 / (k1^2 A x A' . A'')")
def reciprocal_factor():
    a = [sp.Function(f"a{i}")(t) for i in range(3)]
    k1 = sp.Function("k1")(t)
    A = sp.Matrix(a)
    B = k1 * A.cross(A.diff(t))
    k2 = 1 / (k1**2 * A.cross(A.diff(t)).dot(A.diff(t, 2)))
    assert (k2 * B.cross(B.diff(t)) - A).applyfunc(sp.simplify) == sp.zeros(3, 1)
    return verified("symbolic with arbitrary functions a_i(t), k1(t)",
        compared="printed (18.101)-(18.103) k2 = 1/(k1^2 A x A' . A'') vs sympy simplification with arbitrary functions a_i(t), k1(t)",
        reference='sympy')


@claim(DOC, "18.5.2", "table 18.1", "double point <-> double tangent; cusp <-> inflection point")
def reciprocal_correspondence():
    # crunode of figure 18.11 at t = +-1: the reciprocal curve B = P x P' has the same tangent line at t = +-1
    c = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 0]])
    P = _bern(_hom(c))
    B = P.cross(P.diff(t))
    TB = B.cross(B.diff(t))  # tangent line of B, proportional to P
    l1, l2 = TB.subs(t, 1), TB.subs(t, -1)
    assert l1.cross(l2) == sp.zeros(3, 1)
    # cusp of the cuspidal cubic at t = 1/2: inflection of the reciprocal curve there
    cc = BezierCurve([[0, 0], [1, 1], [0, 1], [1, 0]])
    P = _bern(_hom(cc))
    B = P.cross(P.diff(t))
    g = sp.gcd(sp.gcd(sp.expand(B[0]), sp.expand(B[1])), sp.expand(B[2]))
    B = (B / g).applyfunc(sp.cancel)
    detB = sp.expand(B.dot(B.diff(t).cross(B.diff(t, 2))))
    assert detB.subs(t, sp.Rational(1, 2)) == 0
    return verified("crunode t = +-1 -> one tangent line of the reciprocal at both; cusp t = 1/2 -> det(B, B', B'') = 0 there",
        compared="printed table 18.1 (double point <-> double tangent, cusp <-> inflection) vs sympy tangent lines of the reciprocal curve at the crunode t = +-1 and det(B, B', B'') at the cusp t = 1/2",
        reference='sympy')


@claim(DOC, "18.5.3", "(18.104)-(18.109)", "L_H[t] = sum L_Hi, P_H[t] = sum P_Hi with P_Hi = (b_i, -a_i): a scaled hodograph")
def scaled_hodograph_claim():
    r = random.Random(18104)
    for rational in (True, False):
        c = _rand_curve(r, 3, rational)
        H = scaled_hodograph(c)
        assert H.degree == 4
        P = _bern(_hom(c))
        x_t = P[0] / P[2]
        y_t = P[1] / P[2]
        d = sp.Matrix([sp.diff(x_t, t), sp.diff(y_t, t)])
        h = _bern([(p[0], p[1], 1) for p in H.control_points])[:2, 0]
        assert sp.simplify(d[0] * h[1] - d[1] * h[0]) == 0
        if not rational:
            assert (h - d).applyfunc(sp.expand) == sp.zeros(2, 1)
    def is_parallel_to_derivative(with_basis):
        c_ = _rand_curve(random.Random(18105), 3, False)
        H_ = scaled_hodograph(c_)
        P_ = _bern(_hom(c_))
        d_ = sp.Matrix([sp.diff(P_[0] / P_[2], t), sp.diff(P_[1] / P_[2], t)])
        pts = [sp.Matrix([sp.Rational(str(p[0])), sp.Rational(str(p[1]))]) for p in H_.control_points]
        nn = len(pts) - 1
        h_ = sum(((sp.binomial(nn, i) * t**i * (1 - t) ** (nn - i) if with_basis else 1) * pts[i] for i in range(nn + 1)), sp.zeros(2, 1))
        return None if (h_ - d_).applyfunc(sp.expand) == sp.zeros(2, 1) else "sum P_Hi without the Bernstein functions is a constant, not P'(t)"
    return reconstructed(
        "L_H[t] = sum L_Hi; P_H[t] = sum P_Hi",
        "L_H[t] = sum B_i^(2n-2)(t) L_Hi; P_H[t] = sum B_i^(2n-2)(t) P_Hi",
        "the Bernstein basis functions were lost; P_H is parallel to P' (random rational cubic) and equals P' for a polynomial cubic",
        printed_form=False, corrected_form=True, check=L.predicate(is_parallel_to_derivative),
    )

"""Sederberg's notes, chapter 18.1-18.4: homogeneous points and lines, pencils,
moving lines, mu-bases and implicitization with two moving lines.

Independent references: sympy vector algebra (``Matrix.cross``), sympy expansion of
the printed identities, sympy determinants.
"""

from __future__ import annotations

import random

import numpy as np
import sympy as sp
from gmpy2 import mpq

from exactcagd import BezierCurve
from exactcagd.algebra import double_point_cubic, double_points_quartic, implicitize, moving_line_matrix, mu_basis, zeroing_process
from exactcagd.algebra.moving_lines import MovingLine, _lines_of_degree, cross, homogeneous_control_points, moving_line_following
from exactcagd.algebra._poly import curve_power
from exactcagd.algebra.traces import trace_zeroing
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import predicate as _ledger_predicate
from exactcagd.proofs._ledger import claim, erratum, not_checkable, reconstructed, verified, verified_range

DOC = "sederberg"
x, y, t, k, tau = sp.symbols("x y t k tau")


def _V(p):
    return sp.Matrix([sp.Rational(str(v)) if not isinstance(v, sp.Basic) else v for v in p])


def _bern(points, var=t):
    n = len(points) - 1
    return sum((sp.binomial(n, i) * (1 - var) ** (n - i) * var**i * _V(p) for i, p in enumerate(points)), sp.zeros(3, 1))


def _rand_hom(r, n):
    return [(r.randint(-6, 6), r.randint(-6, 6), r.randint(1, 4)) for _ in range(n + 1)]


def _printed_product(P, Q):
    """(18.44) / (18.50) written out: L_k = sum_{i+j=k} C(m,i) C(n,j) P_i x Q_j / C(m+n,k) (sympy)."""
    m, n = len(P) - 1, len(Q) - 1
    return [sum((sp.binomial(m, i) * sp.binomial(n, k_ - i) * _V(P[i]).cross(_V(Q[k_ - i])) for i in range(max(0, k_ - n), min(m, k_) + 1)), sp.zeros(3, 1))
            / sp.binomial(m + n, k_) for k_ in range(m + n + 1)]


def _axial_identity_holds(P, M):
    """P(tau) x P(t) == (t - tau) sum_ij (1-tau)^(n-1-i) tau^i (1-t)^(n-1-j) t^j M_ij (18.56)-(18.58), sympy."""
    n = len(P) - 1
    left = [(1 - tau) ** (n - 1 - i) * tau**i for i in range(n)]
    right = [(1 - t) ** (n - 1 - j) * t**j for j in range(n)]
    rhs = (t - tau) * sum((left[i] * right[j] * _V(M[i][j]) for i in range(n) for j in range(n)), sp.zeros(3, 1))
    return (_bern(P, tau).cross(_bern(P, t)) - rhs).applyfunc(sp.expand) == sp.zeros(3, 1)


def _sym_line(line):
    """A MovingLine (power-basis coefficient triples) as a sympy vector in t."""
    return sum((t**i * _V(c) for i, c in enumerate(line.coeffs)), sp.zeros(3, 1))


def _as_sympy_rows(M):
    return [[tuple(int(v) if v.denominator == 1 else sp.Rational(int(v.numerator), int(v.denominator)) for v in e) for e in row] for row in M]


CUBIC = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 0]])  # figure 18.11
QUARTIC = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 2], [2, 0]])  # figure 18.12 (reconstructed)
QUARTIC_TRIPLE = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 2], [3, -2]])  # figure 18.13 (reconstructed)


QUINTIC = BezierCurve([[0, 0], [1, 3], [2, -1], [4, 2], [5, 5], [6, 0]], weights=[1, 2, 1, 3, 1, 1])  # a generic quintic


def _trace_cubic():
    trace_zeroing(CUBIC)


def _trace_quartic():
    trace_zeroing(QUARTIC)


def _trace_quintic():
    trace_zeroing(QUINTIC)


# ---------------------------------------------------------------- 18.1
@claim(DOC, "18.1.1", "(18.3), (18.6), (18.7)", "(a,b,c) x (d,e,f) = (bf - ec, dc - af, ae - db); L = P1 x P2; P = L1 x L2")
def cross_product_duality():
    a = sp.symbols("a0:3")
    b = sp.symbols("b0:3")
    printed = (a[1] * b[2] - b[1] * a[2], b[0] * a[2] - a[0] * b[2], a[0] * b[1] - b[0] * a[1])
    assert sp.Matrix(a).cross(sp.Matrix(b)) == sp.Matrix(printed) and tuple(cross(a, b)) == printed
    L = sp.Matrix(a).cross(sp.Matrix(b))
    assert sp.expand(L.dot(sp.Matrix(a))) == 0 and sp.expand(L.dot(sp.Matrix(b))) == 0
    return verified("definition equals the vector cross product; the result is incident with both inputs (line through points / point on lines)",
        compared='printed (18.3) components vs sympy Matrix.cross with symbolic vectors; incidence L . P1 = L . P2 = 0 by sympy expansion',
        reference='sympy')


@claim(DOC, "18.1.1", "dual point and line", "1/d is the distance of Point(a,b,c) to the origin; the line from the origin to it is perpendicular to Line(a,b,c)")
def dual_point_line():
    r = random.Random(181)
    for _ in range(5):
        al, be, ga = (r.choice([i for i in range(-7, 8) if i]) for _ in range(3))
        d2 = sp.Rational(ga**2, al**2 + be**2)  # squared distance of the line to the origin
        p2 = sp.Rational(al**2 + be**2, ga**2)  # squared distance of the point (al/ga, be/ga)
        assert d2 * p2 == 1
        assert sp.Matrix([al, be]).dot(sp.Matrix([-be, al])) == 0  # direction of the line ⟂ (al, be)
    return verified("squared distances multiply to 1; (a, b) is normal to the line (5 random triples)",
        compared='printed distance and perpendicularity claims vs exact squared distances and dot products (sympy rationals, 5 random triples)',
        reference='sympy')


# ---------------------------------------------------------------- 18.2
@claim(DOC, "18.2.1", "(18.19)-(18.20)", "parameter line: d0/d1 = |(a0,b0)| / |(a1,b1)|; L[t] turns counter-clockwise iff a0 b1 > a1 b0")
def pencil_parameter_line():
    a0, b0, a1, b1, tt = sp.symbols("a0 b0 a1 b1 tt")
    ang = sp.diff(sp.atan2(b0 + (b1 - b0) * tt, a0 + (a1 - a0) * tt), tt)
    num = sp.simplify(ang * ((a0 + (a1 - a0) * tt) ** 2 + (b0 + (b1 - b0) * tt) ** 2))
    assert sp.expand(num - (a0 * b1 - a1 * b0)) == 0
    # d0/d1: parameter line Q(t) = Q0 (1 - t) + Q1 t follows L iff L0.Q1 + L1.Q0 = 0 (L0.Q0 = L1.Q1 = 0)
    r = random.Random(1819)
    for _ in range(4):
        L0 = sp.Matrix([r.randint(-5, 5) for _ in range(3)])
        L1 = sp.Matrix([r.randint(-5, 5) for _ in range(3)])
        A = L0.cross(L1)
        if A[2] == 0 or L0[:2, 0] == sp.zeros(2, 1) or L1[:2, 0] == sp.zeros(2, 1):
            continue
        A = A / A[2]
        u0, u1 = sp.Matrix([-L0[1], L0[0], 0]), sp.Matrix([-L1[1], L1[0], 0])  # directions (unit up to |n|)
        # Q0 = A + d0 u0/|n0|, Q1 = A + d1 u1/|n1|: the condition is linear in (d0/|n0|, d1/|n1|)
        e0, e1 = sp.symbols("e0 e1")
        Q0, Q1 = A + e0 * u0, A + e1 * u1
        sol = sp.solve(L0.dot(Q1) + L1.dot(Q0), e0, dict=True)[0]
        ratio = sol[e0] / e1  # = (d0/|n0|) / (d1/|n1|)
        n0, n1 = L0[0] ** 2 + L0[1] ** 2, L1[0] ** 2 + L1[1] ** 2
        # |d0/d1| = |n0|/|n1| <=> (ratio * |n0| / |n1|)^2 = n0 / n1 ... i.e. ratio^2 = 1
        assert sp.simplify(ratio**2) == 1 and n0 > 0 and n1 > 0
    return verified("angular speed sign = a0 b1 - a1 b0 (symbolic); the parameter line condition gives |d0|/|n0| = |d1|/|n1| (random pencils)",
        compared='printed (18.19)-(18.20) vs the sympy derivative of atan2 (angular speed sign a0 b1 - a1 b0) and sympy.solve of the parameter-line condition for random pencils',
        reference='sympy')


@claim(DOC, "18.2.2", "(18.26)-(18.27)", "L0[t] x L1[t] is a rational quadratic with P0 = L00 x L10, P1 = (L00 x L11 + L01 x L10)/2, P2 = L01 x L11")
def two_pencils():
    L = {key: sp.Matrix(sp.symbols(f"l{key}_0:3")) for key in ("00", "01", "10", "11")}
    lhs = (L["00"] * (1 - t) + L["01"] * t).cross(L["10"] * (1 - t) + L["11"] * t)
    P0 = L["00"].cross(L["10"])
    P1 = (L["00"].cross(L["11"]) + L["01"].cross(L["10"])) / 2
    P2 = L["01"].cross(L["11"])
    rhs = P0 * (1 - t) ** 2 + P1 * 2 * (1 - t) * t + P2 * t**2
    assert (lhs - rhs).applyfunc(sp.expand) == sp.zeros(3, 1)
    return verified("symbolic identity",
        compared='printed (18.26)-(18.27) control points vs sympy expansion of L0[t] x L1[t] with symbolic lines',
        reference='sympy')


@claim(DOC, "18.2.2", "(18.28)-(18.31)", "L00(1-t) + L10 t = 0, L10(1-t) + L11 t = 0; implicit L00 L11 - L01 L10 = 0")
def two_pencils_implicit():
    r = random.Random(1828)
    Ls = {key: sp.Matrix([r.randint(-5, 5) for _ in range(3)]) for key in ("00", "01", "10", "11")}
    P = (Ls["00"] * (1 - t) + Ls["01"] * t).cross(Ls["10"] * (1 - t) + Ls["11"] * t)
    Lxy = {key: v.dot(sp.Matrix([x, y, 1])) for key, v in Ls.items()}
    F = Lxy["00"] * Lxy["11"] - Lxy["01"] * Lxy["10"]
    assert sp.expand(sp.numer(sp.together(F.subs({x: P[0] / P[2], y: P[1] / P[2]}, simultaneous=True)))) == 0
    # the printed first equation (L00, L10) does not contain the point P[t] in general
    bad = (Lxy["00"] * (1 - t) + Lxy["10"] * t).subs({x: P[0] / P[2], y: P[1] / P[2]}, simultaneous=True)
    assert sp.simplify(bad) != 0
    def contains_point(pair):
        la, lb = pair
        e = (Lxy[la] * (1 - t) + Lxy[lb] * t).subs({x: P[0] / P[2], y: P[1] / P[2]}, simultaneous=True)
        return None if sp.simplify(e) == 0 else f"L{la}(1-t) + L{lb} t does not vanish at P[t] (random pencils)"
    return erratum("L00 (1 - t) + L10 t = 0", "L00 (1 - t) + L01 t = 0", "consistent with (18.30); the implicit equation (18.31) vanishes on L0[t] x L1[t] (random pencils)",
        printed_form=('00', '10'), corrected_form=('00', '01'), check=L.predicate(contains_point),
    )


@claim(DOC, "18.2.3", "(18.33)-(18.35)", "P[k] x P[t] = (t - k) {1-k, k} [[2 P0xP1, P0xP2],[P0xP2, 2 P1xP2]] {1-t, t}; k = 0, 1 give the two pencils")
def quadratic_pencils():
    r = random.Random(1833)
    P = [sp.Matrix([r.randint(-5, 5), r.randint(-5, 5), r.randint(1, 4)]) for _ in range(3)]
    Pt = _bern(P, t)
    Pk = _bern(P, k)
    M = [[2 * P[0].cross(P[1]), P[0].cross(P[2])], [P[0].cross(P[2]), 2 * P[1].cross(P[2])]]
    rhs = (t - k) * ((1 - k) * (M[0][0] * (1 - t) + M[0][1] * t) + k * (M[1][0] * (1 - t) + M[1][1] * t))
    assert (Pk.cross(Pt) - rhs).applyfunc(sp.expand) == sp.zeros(3, 1)
    L0 = P[0].cross(2 * P[1] * (1 - t) + P[2] * t)
    L1 = P[2].cross(P[0] * (1 - t) + 2 * P[1] * t)
    assert (_bern(P, 0).cross(Pt) - t * L0).applyfunc(sp.expand) == sp.zeros(3, 1)
    assert (_bern(P, 1).cross(Pt) - (1 - t) * L1).applyfunc(sp.expand) == sp.zeros(3, 1)
    return verified("symbolic in t, k for a random rational quadratic",
        compared='printed (18.33)-(18.35) factorization vs sympy expansion of P[k] x P[t] for a random rational quadratic',
        reference='sympy')


@claim(DOC, "18.2.3", "(18.36)-(18.37)", "nomogram: P0Pa = (2w1/w2) P0P1, P2Pb = (2w1/w0) P2P1; t = |PaPq| / |PaP2|")
def nomogram():
    r = random.Random(1836)
    pts = [sp.Matrix([r.randint(-5, 5), r.randint(-5, 5)]) for _ in range(3)]
    w = [r.randint(1, 4) for _ in range(3)]
    Pa = pts[0] + sp.Rational(2 * w[1], w[2]) * (pts[1] - pts[0])
    for tv in (sp.Rational(1, 3), sp.Rational(3, 4)):
        B = [(1 - tv) ** 2, 2 * (1 - tv) * tv, tv**2]
        den = sum(B[i] * w[i] for i in range(3))
        Pp = sum((B[i] * w[i] * pts[i] for i in range(3)), sp.zeros(2, 1)) / den
        lam, mu = sp.symbols("lam mu")
        sol = sp.solve(list(pts[0] + lam * (Pp - pts[0]) - (Pa + mu * (pts[2] - Pa))), [lam, mu], dict=True)[0]
        assert sol[mu] == tv
    return verified("the line P0 P(t) meets Pa P2 at the affine parameter t (two parameters, random weights)",
        compared='printed (18.36)-(18.37) construction vs sympy.solve of the line intersection P0 P(t) with Pa P2 (affine parameter = t)',
        reference='sympy')


# ---------------------------------------------------------------- 18.3
@claim(DOC, "18.3.2", "(18.43)-(18.47)", "L_k = sum_{i+j=k} C(m,i) C(n,j) P_i x Q_j / C(m+n,k); the m = 1, n = 2 example")
def moving_line_of_two_points():
    r = random.Random(1844)
    for m, n in ((1, 2), (2, 2), (1, 3)):
        P, Q = _rand_hom(r, m), _rand_hom(r, n)
        L = moving_line_following(P, Q)
        assert [_V(l) for l in L] == _printed_product(P, Q)
        lhs = _bern(P).cross(_bern(Q))
        assert (lhs - _bern(L)).applyfunc(sp.expand) == sp.zeros(3, 1)
        if (m, n) == (1, 2):
            Pm, Qm = [sp.Matrix(p) for p in P], [sp.Matrix(q) for q in Q]
            printed = [Pm[0].cross(Qm[0]), (2 * Pm[0].cross(Qm[1]) + Pm[1].cross(Qm[0])) / 3, (Pm[0].cross(Qm[2]) + 2 * Pm[1].cross(Qm[1])) / 3, Pm[1].cross(Qm[2])]
            assert [sp.Matrix([sp.Rational(str(v)) for v in l]) for l in L] == printed
    return verified_range("(m, n) = (1, 2), (2, 2), (1, 3), random points", "sum B_k L_k == P[t] x Q[t] symbolically; (18.47) as printed",
        compared="printed (18.44) L_k written out in sympy vs exactcagd's moving_line_following and vs sympy P[t] x Q[t]; (18.47) entries as printed",
        reference='sympy')


@claim(DOC, "18.3.3", "(18.49)-(18.50)", "P_k = sum C(m,i) C(n,j) L0i x L1j / C(m+n,k) (dual of (18.44))")
def moving_point_of_two_lines():
    r = random.Random(1849)
    L0, L1 = _rand_hom(r, 1), _rand_hom(r, 2)
    P = moving_line_following(L0, L1)
    assert (_bern(L0).cross(_bern(L1)) - _bern(P)).applyfunc(sp.expand) == sp.zeros(3, 1)
    printed = _printed_product(L0, L1)  # (18.50) written out
    assert [_V(p) for p in P] == printed and (_bern(L0).cross(_bern(L1)) - _bern(printed)).applyfunc(sp.expand) == sp.zeros(3, 1)
    return verified("pencil x quadratic moving line = cubic curve with the printed control points",
        compared="printed (18.50) P_k written out in sympy vs sympy L0[t] x L1[t] (and exactcagd's moving_line_following)",
        reference='sympy')


@claim(DOC, "18.3.4", "base points", "deg(P x Q) = m + n - r, r = number of common parameters at which P and Q meet")
def base_points_of_moving_line():
    # a conic Q and a line P through the same point at the same parameter t = 1/2
    Q = [(2, 2, 1), (2, -4, 1), (2, 2, 1)]
    Q_half = [v.subs(t, sp.Rational(1, 2)) for v in _bern(Q)]
    assert Q_half[0] / Q_half[2] == 2 and Q_half[1] / Q_half[2] == -1
    P = [(0, -2, 1), (4, 0, 1)]  # P(1/2) = (2, -1)
    L = _bern(P).cross(_bern(Q))
    g = sp.gcd(sp.gcd(sp.expand(L[0]), sp.expand(L[1])), sp.expand(L[2]))
    assert sp.Poly(g, t).degree() == 1 and sp.Poly(g, t).root(0) == sp.Rational(1, 2)
    line = MovingLine.from_bernstein(moving_line_following(P, Q)).remove_base_points()[0]
    assert line.degree == 1 + 2 - 1
    return verified("a line and a conic through (2, -1) at the same t = 1/2: P x Q has the factor (t - 1/2), degree 3 - 1",
        compared='printed degree drop m + n - r vs the sympy gcd (t - 1/2) of the components of P[t] x Q[t] for a line and a conic meeting at t = 1/2',
        reference='sympy')


# ---------------------------------------------------------------- 18.4
@claim(DOC, "18.4.1", "(18.56)", "P[tau] x P[t] = (t - tau) {..} [[3P0xP1, 3P0xP2, P0xP3],[3P0xP2, P0xP3 + 9P1xP2, 3P1xP3],[P0xP3, 3P1xP3, 3P2xP3]] {..}")
def cubic_axial_identity():
    r = random.Random(1856)
    P = [sp.Matrix(p) for p in _rand_hom(r, 3)]
    X = lambda i, j: P[i].cross(P[j])  # noqa: E731
    M = [[3 * X(0, 1), 3 * X(0, 2), X(0, 3)], [3 * X(0, 2), X(0, 3) + 9 * X(1, 2), 3 * X(1, 3)], [X(0, 3), 3 * X(1, 3), 3 * X(2, 3)]]
    left = [(1 - tau) ** 2, (1 - tau) * tau, tau**2]
    right = [(1 - t) ** 2, (1 - t) * t, t**2]
    rhs = (t - tau) * sum((left[i] * right[j] * M[i][j] for i in range(3) for j in range(3)), sp.zeros(3, 1))
    assert (_bern(P, tau).cross(_bern(P, t)) - rhs).applyfunc(sp.expand) == sp.zeros(3, 1)
    return verified("symbolic in t, tau for a random rational cubic",
        compared='printed (18.56) matrix vs sympy expansion of P[tau] x P[t] for a random rational cubic',
        reference='sympy')


@claim(DOC, "18.4.1", "(18.57)-(18.58)", "L_ij = sum_{l+m=i+j+1} C(n,l) C(n,m) P_l x P_m")
def general_axial_identity():
    r = random.Random(1858)
    for n in (2, 3, 4, 5):
        P = _rand_hom(r, n)
        M = moving_line_matrix(P)
        Pm = [sp.Matrix(p) for p in P]
        left = [(1 - tau) ** (n - 1 - i) * tau**i for i in range(n)]
        right = [(1 - t) ** (n - 1 - j) * t**j for j in range(n)]
        rhs = (t - tau) * sum((left[i] * right[j] * _V(M[i][j]) for i in range(n) for j in range(n)), sp.zeros(3, 1))
        assert (_bern(P, tau).cross(_bern(P, t)) - rhs).applyfunc(sp.expand) == sp.zeros(3, 1)
        # the printed sum without the restriction l <= min(i, j) is identically zero (terms cancel in pairs)
        printed = sum((sp.binomial(n, l) * sp.binomial(n, 1 - l) * Pm[l].cross(Pm[1 - l]) for l in range(2)), sp.zeros(3, 1))
        assert printed == sp.zeros(3, 1) and _V(M[0][0]) != sp.zeros(3, 1)
    def factorization(restricted):
        n_ = 3
        P_ = _rand_hom(random.Random(18581), n_)
        Pm_ = [sp.Matrix(p) for p in P_]
        def Lij(i, j):
            return sum((sp.binomial(n_, l) * sp.binomial(n_, i + j + 1 - l) * Pm_[l].cross(Pm_[i + j + 1 - l])
                        for l in range(0, min(i, j) + 1 if restricted else i + j + 2) if 0 <= i + j + 1 - l <= n_ and l <= n_), sp.zeros(3, 1))
        left = [(1 - tau) ** (n_ - 1 - i) * tau**i for i in range(n_)]
        right = [(1 - t) ** (n_ - 1 - j) * t**j for j in range(n_)]
        rhs = (t - tau) * sum((left[i] * right[j] * Lij(i, j) for i in range(n_) for j in range(n_)), sp.zeros(3, 1))
        ok = (_bern(P_, tau).cross(_bern(P_, t)) - rhs).applyfunc(sp.expand) == sp.zeros(3, 1)
        return None if ok else "P(tau) x P(t) != (t - tau) sum L_ij (1-tau)^.. tau^i (1-t)^.. t^j (random cubic)"
    return reconstructed(
        "L_ij = sum_{l+m=i+j+1} C(n,l) C(n,m) P_l x P_m",
        "L_ij = sum_{l+m=i+j+1, l <= min(i,j)} C(n,l) C(n,m) P_l x P_m",
        "the unrestricted sum vanishes (P_l x P_m = -P_m x P_l); with l <= min(i, j) (as in 17.6) the factorization holds symbolically for n = 2..5",
        printed_form=False, corrected_form=True, check=L.predicate(factorization),
    )


@claim(DOC, "18.4.2", "(18.60)", "P3 x P[t] = (t-1)(t+1)(3t, 3, -9t) = (t-1)(t+1){(0,3,0)(1-t) + (3,3,-9)t}: crunode at (3, 0), t = +-1")
def cubic_double_point_pencil():
    P = homogeneous_control_points(CUBIC)
    lhs = _V(P[3]).cross(_bern(P))
    assert (lhs - (t - 1) * (t + 1) * sp.Matrix([3 * t, 3, -9 * t])).applyfunc(sp.expand) == sp.zeros(3, 1)
    assert (lhs - (t - 1) * (t + 1) * (sp.Matrix([0, 3, 0]) * (1 - t) + sp.Matrix([3, 3, -9]) * t)).applyfunc(sp.expand) == sp.zeros(3, 1)
    assert CUBIC.evaluate(1) == (3, 0) and CUBIC.evaluate(-1, extrapolate=True) == (3, 0)
    return verified("symbolic; P(1) = P(-1) = (3, 0)",
        compared='printed (18.60) factorization vs sympy expansion of P3 x P[t]; P(1) = P(-1) = (3, 0)',
        reference='sympy')


@claim(DOC, "18.4.3", "(18.61)-(18.66)", "matrix of quadratic moving lines; zeroing gives the pencil (0,3,0)(1-t) + (3,3,-9)t with axis -9(3,0,1): double point (3, 0)", trace=_trace_cubic)
def cubic_zeroing():
    P = homogeneous_control_points(CUBIC)
    M = _as_sympy_rows(moving_line_matrix(P))
    assert M == [[(-3, 0, 0), (-6, 3, 0), (0, 3, 0)], [(-6, 3, 0), (-9, 12, -9), (3, 9, -9)], [(0, 3, 0), (3, 9, -9), (6, 6, -18)]]
    printed_M = [[(-3, 0, 0), (-6, 3, 0), (0, 3, 0)], [(-6, 3, 0), (-9, 12, -9), (3, 9, -9)], [(0, 3, 0), (3, 9, -9), (6, 6, -18)]]
    assert _axial_identity_holds([(0, 0, 1), (0, 1, 1), (1, 2, 1), (3, 0, 1)], printed_M)  # (18.61) from the figure's points, sympy
    Z = zeroing_process(P)
    assert _as_sympy_rows(Z.steps[-1])[2] == [(0, 0, 0), (0, 3, 0), (3, 3, -9)]
    pencil = sp.Matrix([0, 3, 0]) * (1 - t) + sp.Matrix([3, 3, -9]) * t
    assert sp.expand(pencil.dot(_bern(P))) == 0
    assert sp.Matrix([0, 3, 0]).cross(sp.Matrix([3, 3, -9])) == sp.Matrix([-27, 0, -9])
    assert double_point_cubic(CUBIC) == (3, 0)
    return verified("(18.61) and (18.63) reproduced; the pencil follows the curve; axis (3, 0)",
        compared='printed (18.61) matrix vs the axial identity P(tau) x P(t) = (t - tau) sum ... expanded in sympy; the printed (18.63) pencil vs sympy L . P = 0 and its axis by sympy cross product',
        reference='sympy')


@claim(DOC, "18.4.4", "(18.67)", "4 x 4 matrix of cubic moving lines for the quartic of figure 18.12")
def quartic_matrix():
    printed = [
        [(-4, 0, 0), (-12, 6, 0), (-8, 12, 0), (0, 3, 0)],
        [(-12, 6, 0), (-32, 36, -24), (-16, 50, -48), (3, 9, -9)],
        [(-8, 12, 0), (-16, 50, -48), (4, 56, -104), (12, 6, -24)],
        [(0, 2, 0), (4, 8, -8), (12, 6, -24), (8, -4, -16)],
    ]
    M = _as_sympy_rows(moving_line_matrix(homogeneous_control_points(QUARTIC)))
    diffs = [(i, j) for i in range(4) for j in range(4) if M[i][j] != printed[i][j]]
    assert diffs == [(0, 3), (1, 3)] and M[0][3] == (0, 2, 0) and M[1][3] == (4, 8, -8)
    assert all(M[i][j] == M[j][i] for i in range(4) for j in range(4))
    P_ = homogeneous_control_points(QUARTIC)
    def axial_identity(mat):
        n_ = 4
        left = [(1 - tau) ** (n_ - 1 - i) * tau**i for i in range(n_)]
        right = [(1 - t) ** (n_ - 1 - j) * t**j for j in range(n_)]
        rhs = (t - tau) * sum((left[i] * right[j] * sp.Matrix(mat[i][j]) for i in range(n_) for j in range(n_)), sp.zeros(3, 1))
        diff = (_bern(P_, tau).cross(_bern(P_, t)) - rhs).applyfunc(sp.expand)
        return None if diff == sp.zeros(3, 1) else f"P(tau) x P(t) - (t - tau) sum L_ij ... = {list(diff)[:1]}..."
    return erratum(
        "entries (row 0, col 3) = (0, 3, 0) and (row 1, col 3) = (3, 9, -9)",
        "(0, 2, 0) and (4, 8, -8) (the matrix is symmetric; rows 3 are printed correctly)",
        "control points reconstructed from the printed entries: (0,0), (0,1), (1,2), (3,2), (2,0), weights 1; "
        "the printed (3, 9, -9) is the cubic example's entry",
        printed_form=printed, corrected_form=M, check=L.predicate(axial_identity),
    )


@claim(DOC, "18.4.4", "(18.68)-(18.69)", "zeroing leaves two quadratic moving lines [(0,2,0),(4,4,-8),(4,-2,-8)] and [(8,6,0),(28,4,-24),(20,-14,-40)]", trace=_trace_quartic)
def quartic_two_quadratics():
    P = homogeneous_control_points(QUARTIC)
    Pt = _bern(P)
    rows = [[(0, 2, 0), (4, 4, -8), (4, -2, -8)], [(8, 6, 0), (28, 4, -24), (20, -14, -40)]]
    basis = [(1 - t) ** 2, (1 - t) * t, t**2]
    for row in rows:
        L = sum((basis[j] * sp.Matrix(row[j]) for j in range(3)), sp.zeros(3, 1))
        assert sp.expand(L.dot(Pt)) == 0
    Z = zeroing_process(P)
    ours = _as_sympy_rows(Z.steps[-1])
    assert ours[2][1:] == rows[0]
    assert [tuple(3 * v for v in e) for e in ours[3][1:]] == rows[1]
    assert Z.degrees == (2, 2)
    return verified("both printed rows follow the curve; the zeroing process gives row 2 exactly and row 3 / 3",
        compared="printed (18.68)-(18.69) moving lines vs sympy L . P[t] = 0 for the reconstructed quartic; exactcagd's zeroing gives the same rows",
        reference='sympy')


@claim(DOC, "18.4.4", "(18.70)-(18.73)", "L_Q axial iff 32 tau^3 - 32 tau^2 - 8 tau = 0: tau = 0, (1 +- sqrt 2)/2; double points (2, 0), (1, +-sqrt 2)")
def quartic_double_points():
    rows = [[sp.Matrix(v) for v in r_] for r_ in ([(0, 2, 0), (4, 4, -8), (4, -2, -8)], [(8, 6, 0), (28, 4, -24), (20, -14, -40)])]
    LQ = [(1 - tau) * rows[0][j] + tau * rows[1][j] for j in range(3)]
    printed = [sp.Matrix([8 * tau, 4 * tau + 2, 0]), sp.Matrix([24 * tau + 4, 4, -16 * tau - 8]), sp.Matrix([16 * tau + 4, -12 * tau - 2, -32 * tau - 8])]
    assert all((a - b).applyfunc(sp.expand) == sp.zeros(3, 1) for a, b in zip(LQ, printed))
    triple = sp.expand(LQ[0].cross(LQ[1]).dot(LQ[2]))
    assert sp.expand(triple - 16 * (32 * tau**3 - 32 * tau**2 - 8 * tau)) == 0
    axis = LQ[0].cross(LQ[1])
    assert axis.subs(tau, 0) == -8 * sp.Matrix([2, 0, 1])
    for sgn in (1, -1):
        tv = (1 + sgn * sp.sqrt(2)) / 2
        ax = axis.subs(tau, tv).applyfunc(sp.simplify)
        factor = sp.simplify(ax[0])
        assert sp.simplify(factor - 8 * (-12 - sgn * 8 * sp.sqrt(2))) == 0
        assert (ax / factor).applyfunc(sp.simplify) == sp.Matrix([1, -sgn * sp.sqrt(2), 1])
    pts, n_complex = double_points_quartic(QUARTIC)
    assert n_complex == 0 and len(pts) == 3 and (str(pts[2][0]), str(pts[2][1])) == ("2", "0")
    for px, py in pts[:2]:
        assert str(px) == "1" and [int(c) for c in py.poly.coeffs()] == [-2, 0, 1]
    def axis_at_zero(factor_):
        return None if axis.subs(tau, 0) == factor_ * sp.Matrix([2, 0, 1]) else f"L_Q0 x L_Q1 at tau = 0 is {list(axis.subs(tau, 0))}"
    return erratum(
        "axes -1 (2, 0, 1) and (-12 -+ 8 sqrt 2)(1, -+sqrt 2, 1)",
        "-8 (2, 0, 1) and 8 (-12 -+ 8 sqrt 2)(1, -+sqrt 2, 1)",
        "the scale factors are 8x the printed ones (the points (2, 0), (1, +-sqrt 2) are right); the printed cubic is 1/16 of the triple product (same roots)",
        printed_form=-1, corrected_form=-8, check=L.predicate(axis_at_zero),
    )


@claim(DOC, "18.4.4", "(18.74)-(18.77)", "quartic with a triple point: (18.75) lines have L1 x L2 = 0; pencil (0,0,0),(2,3,0),(-4,0,12) with axis 12(3,-2,1)")
def quartic_triple_point():
    P = homogeneous_control_points(QUARTIC_TRIPLE)
    printed = [
        [(-4, 0, 0), (-12, 6, 0), (-8, 12, 0), (2, 3, 0)],
        [(-12, 6, 0), (-32, 36, -24), (-14, 51, -48), (12, 12, -12)],
        [(-8, 12, 0), (-14, 51, -48), (12, 60, -108), (24, 12, -48)],
        [(2, 3, 0), (12, 12, -12), (24, 12, -48), (16, 0, -48)],
    ]
    assert _as_sympy_rows(moving_line_matrix(P)) == printed
    Pt = _bern(P)
    basis = [(1 - t) ** 2, (1 - t) * t, t**2]
    lines = []
    for row in ([(2, 3, 0), (8, 6, -12), (8, 0, -24)], [(8, 12, 0), (30, 21, -48), (28, 0, -84)]):
        L = sum((basis[j] * sp.Matrix(row[j]) for j in range(3)), sp.zeros(3, 1))
        assert sp.expand(L.dot(Pt)) == 0
        lines.append(L)
    assert lines[0].cross(lines[1]).applyfunc(sp.expand) == sp.zeros(3, 1)
    printed_pencil = basis[1] * sp.Matrix([2, 3, 0]) + basis[2] * sp.Matrix([-4, 0, 12])
    pencil = basis[1] * sp.Matrix([-2, -3, 0]) + basis[2] * sp.Matrix([-4, 0, 12])  # row 2 - 4 row 1 of (18.75)
    assert sp.expand(printed_pencil.dot(Pt)) != 0 and sp.expand(pencil.dot(Pt)) == 0
    assert sp.Matrix([-2, -3, 0]).cross(sp.Matrix([-4, 0, 12])) == -12 * sp.Matrix([3, -2, 1])
    p, q = mu_basis(QUARTIC_TRIPLE)
    assert (p.degree, q.degree) == (1, 3) and p.axis() == (3, -2)
    def follows_curve(mid):
        pen = basis[1] * sp.Matrix(mid) + basis[2] * sp.Matrix([-4, 0, 12])
        val = sp.factor(sp.expand(pen.dot(Pt)))
        return None if val == 0 else f"L.P = {val}"
    return erratum(
        "pencil (0,0,0), (2,3,0), (-4,0,12); (2,3,0) x (-4,0,12) = 12 (3,-2,1)",
        "pencil (0,0,0), (-2,-3,0), (-4,0,12) (= row 2 - 4 row 1 of (18.75)); axis -12 (3,-2,1)",
        "the printed pencil does not follow the curve (L.P = 24 t^2 (t-1)^2 (t+1)^2); the corrected one does; the triple point (3, -2) is right. "
        "Control points (0,0),(0,1),(1,2),(3,2),(3,-2) reproduce (18.74); (18.75) lines follow the curve and L1 x L2 = 0; mu = 1",
        printed_form=(2, 3, 0), corrected_form=(-2, -3, 0), check=_ledger_predicate(follows_curve),
    )


@claim(DOC, "18.4.5", "(18.78)-(18.84)", "an n-parameter family of degree n-1 moving lines; zeroing leaves degrees (m, m) for n = 2m and (m+1, m) for n = 2m+1", trace=_trace_quintic)
def general_zeroing():
    r = random.Random(1878)
    for n in range(2, 9):
        P = [tuple(mpq(v) for v in p) for p in _rand_hom(r, n)]
        curve = BezierCurve.from_homogeneous(np.array(P, dtype=object))
        X, Y, W = curve_power(curve)
        assert len(_lines_of_degree(X, Y, W, n - 1)) == n
        Z = zeroing_process(P)
        m = n // 2
        assert Z.degrees == ((m, m) if n % 2 == 0 else (m + 1, m))
        for line in Z.lines:
            assert line.follows(X, Y, W)
        # independent (sympy): both lines follow the Bernstein form, are independent, and have the stated degrees
        Ls = [_sym_line(line) for line in Z.lines]
        assert all(sp.expand(L_.dot(_bern(P))) == 0 for L_ in Ls)
        assert Ls[0].cross(Ls[1]).applyfunc(sp.expand) != sp.zeros(3, 1)
        assert sorted(max(sp.Poly(c, t).degree() for c in L_) for L_ in Ls) == sorted((m, m) if n % 2 == 0 else (m + 1, m))
        # (18.82): after the first step every remaining row starts with a line through P0
        if n >= 3:
            for row in Z.steps[1][2:]:
                assert sum(a * b for a, b in zip(row[1], P[0])) == 0
    return verified_range("n = 2..8, random rational curves", "dimension n at degree n - 1; degrees of the final pair as stated; both follow the curve; (18.82)",
        compared='printed degrees (m, m), (m+1, m) vs the sympy degrees of the two final moving lines, which follow the Bernstein form (sympy L . P = 0) and are independent; n = 2..8',
        reference='sympy')


@claim(DOC, "18.4.6", "(18.85)-(18.87)", "the 2 x 2 resultant of the two quadratic moving lines is 512(y^4 + 4x^3 + 2xy^2 - 16x^2 - 6y^2 + 16x)", trace=_trace_quartic)
def quartic_moving_line_implicit():
    a = [2 * y, 4 * x + 4 * y - 8, 4 * x - 2 * y - 8]
    b = [8 * x + 6 * y, 28 * x + 4 * y - 24, 20 * x - 14 * y - 40]
    br = lambda i, j: sp.expand(a[i] * b[j] - a[j] * b[i])  # noqa: E731
    M = sp.Matrix([[br(0, 1), br(0, 2)], [br(0, 2), br(1, 2) + 0]])
    printed = sp.Matrix([[-32 * x**2 - 16 * y**2 + 64 * x, -32 * x**2 + 32 * x * y - 16 * y**2 + 64 * x - 32 * y], [-32 * x**2 + 32 * x * y - 16 * y**2 + 64 * x - 32 * y, -32 * x**2 + 64 * x * y - 48 * y**2 - 64 * y + 128]])
    assert (M - printed).applyfunc(sp.expand) == sp.zeros(2, 2)
    F = y**4 + 4 * x**3 + 2 * x * y**2 - 16 * x**2 - 6 * y**2 + 16 * x
    assert sp.expand(M.det() - 512 * F) == 0
    assert implicitize(QUARTIC, "moving_lines").as_expr() == sp.expand(F)
    def resultant_is_512F(mat):
        return L.same_expr(512 * F)(sp.expand(sp.Matrix(mat).det()))
    return reconstructed(
        "first line of (18.87): a product of 2 x 2 determinants",
        "the 2 x 2 matrix of brackets |a_i b_j| (Bezout in the basis (1-t)^2, (1-t)t, t^2)",
        "the extraction damaged the first line; the printed matrix and 512 F are exact (sympy); implicitize(moving_lines) = F",
        printed_form=L.LOST, lost_reason='the first line of (18.87) is damaged (a product of 2 x 2 determinants)', corrected_form=M, check=L.predicate(resultant_is_512F),
    )


@claim(DOC, "18.4.6", "speed", "the moving-line method is generally faster than the n x n Bezout determinant")
def moving_line_speed():
    return not_checkable("a timing claim; measured in benchmarks/bench_algebra.py (results/full/algebra.md), see there for the verdict on this machine")

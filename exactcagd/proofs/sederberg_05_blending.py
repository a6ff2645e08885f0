"""Ledger: Sederberg's notes, chapter 5 (blending functions; Timmer, Ball, Overhauser)."""

from __future__ import annotations

import random
from fractions import Fraction

import sympy as sp

from exactcagd.toolbox import blending as bl
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified, verified_range

t = bl.T
P = [sp.Matrix(sp.symbols(f"x{i} y{i}")) for i in range(4)]


def _curve(funcs, pts):
    out = sp.zeros(2, 1)
    for f, p in zip(funcs, pts):
        out += f * p
    return out


#: the printed bases (5.1, 5.2) and the Overhauser basis derived here from its defining end conditions (5.3)
TIMMER = [(1 - 2 * t) * (1 - t) ** 2, 4 * t * (1 - t) ** 2, 4 * t**2 * (1 - t), (2 * t - 1) * t**2]
BALL = [(1 - t) ** 2, 2 * t * (1 - t) ** 2, 2 * t**2 * (1 - t), t**2]
BERNSTEIN3 = [sp.binomial(3, i) * t**i * (1 - t) ** (3 - i) for i in range(4)]


def _overhauser_from_conditions():
    """The cubic blending functions with Q(0) = P1, Q(1) = P2, Q'(0) = (P2 - P0)/2, Q'(1) = (P3 - P1)/2 (sympy solve)."""
    a = sp.symbols("a0:4")
    q = sum(a[k] * t**k for k in range(4))
    out = []
    for i in range(4):
        e = [sp.Integer(int(i == j)) for j in range(4)]
        sol = sp.solve([q.subs(t, 0) - e[1], q.subs(t, 1) - e[2], q.diff(t).subs(t, 0) - (e[2] - e[0]) / 2,
                        q.diff(t).subs(t, 1) - (e[3] - e[1]) / 2], a)
        out.append(sp.expand(q.subs(sol)))
    return out


def _properties_sympy(f):
    """(partition of unity, non-negative on [0, 1], symmetric f_i(1 - t) = f_(n-i)(t)) by sympy, from first principles."""
    n = len(f) - 1
    unity = sp.cancel(sum(f)) == 1
    nonneg = all(sp.solveset(sp.cancel(x) < 0, t, sp.Interval(0, 1)) == sp.EmptySet for x in f)
    symmetric = all(sp.cancel(f[i].subs(t, 1 - t) - f[n - i]) == 0 for i in range(n + 1))
    return unity, nonneg, symmetric


@claim(doc="sederberg", section="5", ref="property 3 (symmetry)", statement="for a curve whose domain is [t0, t1], symmetry requires sum f_i(t) P_i = sum f_i(t1 + t2 - t) P_{n-i}")
def symmetry_on_interval():
    t0, t1 = sp.Integer(1), sp.Integer(3)
    s = (t - t0) / (t1 - t0)
    bern = [sp.binomial(3, i) * s**i * (1 - s) ** (3 - i) for i in range(4)]
    assert bl.symmetric(bern, domain=(1, 3))
    # the reflection of [t0, t1] onto itself is t0 + t1 - t
    assert all(sp.expand(bern[i] - bern[3 - i].subs(t, t0 + t1 - t)) == 0 for i in range(4))
    # with the printed "t1 + t2 - t" read as the next interval's end (t2 = 5 here) the identity fails
    assert any(sp.expand(bern[i] - bern[3 - i].subs(t, t1 + 5 - t)) != 0 for i in range(4))
    def reflection_symmetry(expr):
        return None if all(sp.expand(bern[i] - bern[3 - i].subs(t, expr)) == 0 for i in range(4)) else f"t -> {expr} does not map [1, 3] onto itself"
    return erratum(printed="f_i(t1 + t2 - t)", corrected="f_i(t0 + t1 - t)",
                   detail="the Bernstein basis on [1, 3] is symmetric under t -> t0 + t1 - t = 4 - t; "
                          "the domain [t0, t1] has no t2, and t -> t1 + t2 - t does not map it onto itself",
        printed_form=t1 + 5 - t, corrected_form=t0 + t1 - t, check=L.predicate(reflection_symmetry),
    )


@claim(doc="sederberg", section="5", ref="Example", statement="f = ((t-1)^2, 2t(1-t), 2t^2)/(t^2+1): coordinate system independent, convex hull, not symmetric, linearly independent, interpolates the end points")
def example_curve():
    f = [(t**2 - 2 * t + 1) / (t**2 + 1), (2 * t - 2 * t**2) / (t**2 + 1), 2 * t**2 / (t**2 + 1)]
    rep = bl.check_properties(f)
    assert (rep.partition_of_unity, rep.convex_hull, rep.symmetric, rep.linearly_independent, rep.endpoint_interpolation) == (True, True, False, True, True)
    assert _properties_sympy(f) == (True, True, False)  # independent of check_properties
    assert [x.subs(t, 0) for x in f] == [1, 0, 0] and [x.subs(t, 1) for x in f] == [0, 0, 1]
    assert sp.cancel(f[0].subs(t, 1 - t) - t**2 / (t**2 - 2 * t + 2)) == 0
    c = sp.symbols("c0:3")
    comb = sp.expand(c[0] * (t**2 - 2 * t + 1) + c[1] * (2 * t - 2 * t**2) + c[2] * 2 * t**2)
    coeffs = sp.Poly(comb, t).all_coeffs()
    assert coeffs == [c[0] - 2 * c[1] + 2 * c[2], -2 * c[0] + 2 * c[1], c[0]]
    assert sp.solve(coeffs, c, dict=True) == [{c[0]: 0, c[1]: 0, c[2]: 0}]
    return verified("each printed statement reproduced; f0(1 - t) = t^2/(t^2 - 2t + 2) != f2(t); the coefficient system has only the zero solution",
                    compared='each printed property vs sympy from first principles: sum f_i cancels to 1, solveset(f_i < 0) on [0,1] empty, f_0(1-t) != f_2(t), f(0) = (1,0,0), f(1) = (0,0,1), the coefficient system has only the zero solution (and exactcagd check_properties agrees)', reference='sympy')


@claim(doc="sederberg", section="5", ref="overview", statement="Timmer's PC, Ball's cubic and the Overhauser curve are coordinate system independent and symmetric, but only Ball's cubic obeys the convex hull property")
def three_curves_properties():
    bases = {"timmer": TIMMER, "ball": BALL, "overhauser": _overhauser_from_conditions()}
    out = {name: _properties_sympy(f) for name, f in bases.items()}
    assert out == {"timmer": (True, False, True), "ball": (True, True, True), "overhauser": (True, False, True)}
    for name, f in bases.items():  # the package agrees with the first-principles bases
        assert all(sp.expand(a - b) == 0 for a, b in zip(getattr(bl, f"{name}_basis")(), f))
    assert TIMMER[0].subs(t, sp.Rational(3, 4)) < 0 and bases["overhauser"][0].subs(t, sp.Rational(1, 2)) < 0
    return verified("exact property checks; witnesses: Timmer f0(3/4) = -1/32 < 0, Overhauser f0(1/2) = -1/16 < 0",
                    compared="printed property claims vs sympy on the printed Timmer and Ball bases and the Overhauser basis solved from its end conditions (5.3): partition of unity (cancel), f_i(1-t) = f_(3-i)(t), non-negativity on [0,1] by solveset; exactcagd's bases equal these", reference='sympy')


@claim(doc="sederberg", section="5.1", ref="Timmer basis", statement="f0 = (1-2t)(1-t)^2 = -2t^3 + 5t^2 - 4t + 1, f1 = 4t(1-t)^2, f2 = 4t^2(1-t), f3 = (2t-1)t^2; the curve passes through the midpoint of P1 - P2")
def timmer_basis():
    f = bl.timmer_basis()
    expanded = [-2 * t**3 + 5 * t**2 - 4 * t + 1, 4 * t**3 - 8 * t**2 + 4 * t, -4 * t**3 + 4 * t**2, 2 * t**3 - t**2]
    assert [sp.expand(x) for x in TIMMER] == expanded  # printed factored forms = printed expansion
    assert [sp.expand(x) for x in f] == expanded
    Q = _curve(f, P)
    assert (Q.subs(t, sp.Rational(1, 2)) - (P[1] + P[2]) / 2).applyfunc(sp.expand) == sp.zeros(2, 1)
    assert Q.subs(t, 0) == P[0] and Q.subs(t, 1) == P[3]
    # not tangent to P1 - P2 in general
    d = Q.diff(t).subs(t, sp.Rational(1, 2))
    cross = sp.expand(d[0] * (P[2][1] - P[1][1]) - d[1] * (P[2][0] - P[1][0]))
    assert cross != 0
    return verified("expansions, end interpolation and Q(1/2) = (P1 + P2)/2 symbolically; Q'(1/2) x (P2 - P1) is not identically 0, "
                    "so the curve is not tangent to P1 - P2 in general (as the notes remark)",
                    compared="printed factored f_i vs printed expansion (sympy expand), and vs exactcagd timmer_basis; Q(0), Q(1), Q(1/2) = (P1+P2)/2 and Q'(1/2) x (P2-P1) by sympy substitution/differentiation with symbolic points", reference='sympy')


@claim(doc="sederberg", section="5.1", ref="Example (Timmer -> Bézier)", statement="Q'(t) = (-6t^2+10t-4)Q0 + (12t^2-16t+4)Q1 + (-12t^2+8t)Q2 + (6t^2-2t)Q3, so Q'(t) = 4(Q1 - Q0) and Q'(1) = 4(Q3 - Q2)")
def timmer_derivative():
    f = bl.timmer_basis()
    assert [sp.expand(sp.diff(x, t)) for x in f] == [-6 * t**2 + 10 * t - 4, 12 * t**2 - 16 * t + 4, -12 * t**2 + 8 * t, 6 * t**2 - 2 * t]
    Q = _curve(f, P)
    assert (Q.diff(t).subs(t, 0) - 4 * (P[1] - P[0])).applyfunc(sp.expand) == sp.zeros(2, 1)
    assert (Q.diff(t).subs(t, 1) - 4 * (P[3] - P[2])).applyfunc(sp.expand) == sp.zeros(2, 1)
    assert (Q.diff(t) - 4 * (P[1] - P[0])).applyfunc(sp.expand) != sp.zeros(2, 1)
    Qd = Q.diff(t)
    def derivative_value(at):
        diff = (Qd.subs(t, at) if at != 't' else Qd) - 4 * (P[1] - P[0])
        return None if diff.applyfunc(sp.expand) == sp.zeros(2, 1) else f"Q'({at}) - 4(Q1 - Q0) = {list(diff.applyfunc(sp.expand))}"
    return erratum(printed="Q'(t) = 4(Q1 - Q0)", corrected="Q'(0) = 4(Q1 - Q0)",
                   detail="the derivative of the Timmer basis is as printed; at t = 0 it is 4(Q1 - Q0), at t = 1 it is 4(Q3 - Q2); "
                          "Q'(t) is not constant",
        printed_form='t', corrected_form=0, check=L.predicate(derivative_value),
    )


@claim(doc="sederberg", section="5.1", ref="Example (conversion)", statement="P0 = Q0, P3 = Q3, 3(P1 - P0) = 4(Q1 - Q0) -> Q1 = (P0 + 3P1)/4, Q2 = (P3 + 3P2)/4")
def timmer_conversion():
    Qs = [sp.Matrix(sp.symbols(f"qx{i} qy{i}")) for i in range(4)]
    bez = [Qs[0], (4 * Qs[1] - Qs[0]) / 3, (4 * Qs[2] - Qs[3]) / 3, Qs[3]]
    assert (_curve(BERNSTEIN3, bez) - _curve(TIMMER, Qs)).applyfunc(sp.expand) == sp.zeros(2, 1)
    rng = random.Random(51)
    for _ in range(5):
        pts = [[Fraction(rng.randint(-9, 9), rng.randint(1, 3)) for _ in range(2)] for _ in range(4)]
        tim = bl.bezier_to_timmer(pts)
        assert [tuple(r) for r in tim.tolist()][1] == tuple((Fraction(a) + 3 * Fraction(b)) / 4 for a, b in zip(pts[0], pts[1]))
        assert [tuple(r) for r in tim.tolist()][2] == tuple((Fraction(a) + 3 * Fraction(b)) / 4 for a, b in zip(pts[3], pts[2]))
    return verified("the printed relations hold (they express the Timmer points by the Bézier points); the asked-for inverse is "
                    "P1 = (4Q1 - Q0)/3, P2 = (4Q2 - Q3)/3, verified as a symbolic identity of the two cubics",
                    compared='printed relations vs a sympy identity: the Bezier cubic with P1 = (4Q1-Q0)/3, P2 = (4Q2-Q3)/3 equals the printed Timmer curve for symbolic Q_i; exactcagd bezier_to_timmer vs the printed Q1 = (P0+3P1)/4, Q2 = (P3+3P2)/4 on 5 random exact inputs', reference='sympy')


@claim(doc="sederberg", section="5.2", ref="Ball's cubic", statement="f = ((1-t)^2, 2t(1-t)^2, 2t^2(1-t), t^2); if P1 = P2 the curve is the quadratic Bézier P0 (1-t)^2 + P1 2t(1-t) + P3 t^2")
def ball_cubic():
    f = BALL
    assert all(sp.expand(a - b) == 0 for a, b in zip(bl.ball_basis(), f))
    assert sp.expand(sum(f)) == 1
    C = _curve(f, [P[0], P[1], P[1], P[3]])
    quad = P[0] * (1 - t) ** 2 + P[1] * 2 * t * (1 - t) + P[3] * t**2
    assert (C - quad).applyfunc(sp.expand) == sp.zeros(2, 1)
    # Bézier form, exact: P0, (P0 + 2P1)/3, (2P2 + P3)/3, P3
    M = bl.bernstein_matrix(f, 3)
    assert M.tolist() == [[1, Fraction(1, 3), 0, 0], [0, Fraction(2, 3), 0, 0], [0, 0, Fraction(2, 3), 0], [0, 0, Fraction(1, 3), 1]]
    bez = [P[0], (P[0] + 2 * P[1]) / 3, (2 * P[2] + P[3]) / 3, P[3]]  # the matrix's columns, as a sympy identity
    assert (_curve(BERNSTEIN3, bez) - _curve(f, P)).applyfunc(sp.expand) == sp.zeros(2, 1)
    return verified("partition of unity; P1 = P2 gives the quadratic; Bernstein matrix (exact) gives the Bézier points",
                    compared='printed Ball basis vs sympy: sum = 1, with P1 = P2 the curve expands to the printed quadratic; Bezier points P0, (P0+2P1)/3, (2P2+P3)/3, P3 verified as a sympy identity of the two cubics (exactcagd bernstein_matrix agrees)', reference='sympy')


@claim(doc="sederberg", section="5.3", ref="Overhauser", statement="a segment interpolates P1 and P2 with P'(0) = (P2 - P0)/2, P'(1) = (P3 - P1)/2; consecutive segments sharing three points are tangent")
def overhauser():
    f = bl.overhauser_basis()
    C = _curve(f, P)
    assert C.subs(t, 0) == P[1] and (C.subs(t, 1) - P[2]).applyfunc(sp.expand) == sp.zeros(2, 1)
    assert (C.diff(t).subs(t, 0) - (P[2] - P[0]) / 2).applyfunc(sp.expand) == sp.zeros(2, 1)
    assert (C.diff(t).subs(t, 1) - (P[3] - P[1]) / 2).applyfunc(sp.expand) == sp.zeros(2, 1)
    rng = random.Random(53)
    for _ in range(5):
        pts = [[rng.randint(-9, 9), rng.randint(-9, 9)] for _ in range(7)]
        segs = bl.overhauser_spline(pts)
        assert all(a.derivative().evaluate(1) == b.derivative().evaluate(0) for a, b in zip(segs[:-1], segs[1:]))
    return verified_range("symbolic for one segment; 5 random 7-point strings", "interpolation and end slopes symbolic; consecutive segments C^1 exactly",
                          compared='printed interpolation and end slopes vs sympy substitution/differentiation of the Overhauser segment with symbolic points; consecutive exactcagd segments compared by their exact end derivatives', reference='sympy')

"""Lasser & Bonneau (000), sections III-VI: Statements 1, 2, eqs. (8)-(12), (17), (18), and the
strategy for isoparametric trim curves (sections IV and VI)."""

from __future__ import annotations

import itertools
import math
import random
from fractions import Fraction as Fr

import numpy as np
import sympy

from exactcagd import BezierCurve, BezierSurface
from exactcagd.composition import compose
from exactcagd.composition.isoparametric import statement1_points
from exactcagd.composition.lasser import compose_homogeneous_lasser, lasser_constant, multi_indices, polar_value
from exactcagd.exact import bernstein as bz
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._reference import agrees_with_substitution, composition_degree
from exactcagd.proofs._ledger import claim, erratum, reconstructed, verified, verified_range
from exactcagd.proofs.lasser_composition import random_instance


def _iso_symbolic(l, m, rational=False):
    """Symbolic net and a symbolic v-line (N = 1) u0 -> u1 at v = s."""
    net = np.empty((l + 1, m + 1, 2), dtype=object)
    for i in range(l + 1):
        for j in range(m + 1):
            w = sympy.Symbol(f"w{i}{j}") if rational else sympy.Integer(1)
            net[i, j] = [w * sympy.Symbol(f"f{i}{j}"), w]
    u0, u1, s = sympy.symbols("u0 u1 s")
    curve = np.array([[u0, s, sympy.Integer(1)], [u1, s, sympy.Integer(1)]], dtype=object)
    return net, curve, (u0, u1, s)


def _comb(n, k):
    return math.comb(n, k) if 0 <= k <= n else 0


def _bern(n, i, x):
    return sympy.binomial(n, i) * x**i * (1 - x) ** (n - i)


def _F_a(net, u0, u1, s, a):
    """F_a = F^{l,m}_{0,0}(u_I^l, v*^m) with |I^u| = a (a ones among the l u-indices)."""
    l, m = net.shape[0] - 1, net.shape[1] - 1
    level = net
    for x in [u1] * a + [u0] * (l - a):
        level = (1 - x) * level[:-1] + x * level[1:]
    col = level[0]
    for _ in range(m):
        col = (1 - s) * col[:-1] + s * col[1:]
    return col[0]


@claim(doc="lasser", section="III", ref="(8)", statement="for N = 1, (5) becomes C^{l,m}_R(N, I) = 1 / C(l+m, R)")
def eq8():
    for l, m in itertools.product(range(5), range(5)):
        for R in range(l + m + 1):
            assert all(lasser_constant(l, m, 1, iu, iv) == Fr(1, bz.binomial(l + m, R)) for iu, iv in multi_indices(l, m, 1, R))
    def constants_become_8(tag):
        # (7) is the constant C^{l,m}_R(N, I); (5) is the curve F(K(t)); only a constant can 'become' 1/C(l+m, R)
        return None if tag == "(7)" else f"{tag} is the composed curve, not the constants that equal 1/C(l+m, R) for N = 1"
    return reconstructed("(5) becomes (8)", "(7) becomes (8)", "the constants are (7), not the curve (5); C(1, 0) = C(1, 1) = 1 gives 1/C(l+m, R); checked for l, m <= 4",
        printed_form='(5)', corrected_form='(7)', check=L.predicate(constants_become_8), reference='text',
    )


@claim(doc="lasser", section="III", ref="(4) simplifies to", statement="(4) simplifies to B_R = 1/C(l+m,R) sum_{|I|=R} F(u_I^l, v_I^m)")
def eq_after_8():
    net, curve, _ = _iso_symbolic(2, 2)
    general = compose_homogeneous_lasser(net, curve)
    for R in range(5):
        direct = sum((polar_value(net, [curve[i, 0] for i in iu], [curve[i, 1] for i in iv]) for iu, iv in multi_indices(2, 2, 1, R)), net[0, 0] * 0) / bz.binomial(4, R)
        assert all(sympy.expand(x - y) == 0 for x, y in zip(general[R], direct))
    def bezier_point_formula(tag):
        return None if tag == "(6)" else f"{tag} is not the Bezier-point formula whose N = 1 case is B_R = 1/C(l+m,R) sum F(u_I, v_I)"
    return reconstructed("(4) simplifies to", "(6) simplifies to", "it is the Bézier-point formula (6) that simplifies; checked symbolically for l = m = 2",
        printed_form='(4)', corrected_form='(6)', check=L.predicate(bezier_point_formula), reference='text',
    )


@claim(doc="lasser", section="III", ref="Statement 1 proof: sum equivalence", statement="sum_{|I|=R} F(u_I^l, v_I^m) = sum_a C(l,a) C(n,R-a) F_a for v0 = v1 = v*")
def counting_identity():
    for l, m in itertools.product(range(5), range(5)):
        for R in range(l + m + 1):
            counts = {}
            for iu, iv in multi_indices(l, m, 1, R):
                counts[sum(iu)] = counts.get(sum(iu), 0) + 1
            assert all(counts.get(a, 0) == bz.binomial(l, a) * bz.binomial(m, R - a) for a in range(l + 1))
    def counts(second_degree):
        # number of multi-indices with |I^u| = a, |I^v| = R - a, against C(l, a) C(second_degree(l, m), R - a)
        for l_, m_ in itertools.product(range(1, 4), range(1, 4)):
            for R in range(l_ + m_ + 1):
                c = {}
                for iu, iv in multi_indices(l_, m_, 1, R):
                    c[sum(iu)] = c.get(sum(iu), 0) + 1
                for a in range(l_ + 1):
                    if c.get(a, 0) != bz.binomial(l_, a) * bz.binomial(second_degree(l_, m_), R - a):
                        return f"l = {l_}, m = {m_}, R = {R}, a = {a}: {c.get(a, 0)} multi-indices"
        return None
    return reconstructed(
        "sum_a binom(l, a) binom(n, R - a) F_a",
        "sum_a binom(l, a) binom(m, R - a) F_a  (n is undefined here; the v-indices number m)",
        "counting the multi-indices with |I^u| = a, |I^v| = R - a for l, m <= 4",
        printed_form=lambda l_, m_: l_ + m_, corrected_form=lambda l_, m_: m_, check=L.predicate(counts), reference='enumeration',
    )


@claim(doc="lasser", section="III", ref="(9), (10)", statement="for an isoparametric line F(K(t)) = sum_R B_R B^{l+m}_R(t), B_R = sum_a C(l,a) C(m,R-a)/C(l+m,R) F_a")
def eq9_10():
    t = sympy.Symbol("t")
    for l, m in [(1, 1), (2, 1), (2, 2), (3, 2)]:
        net, curve, (u0, u1, s) = _iso_symbolic(l, m)
        general = compose_homogeneous_lasser(net, curve)[:, 0]
        F = [_F_a(net, u0, u1, s, a)[0] for a in range(l + 1)]
        formula = [sum(sympy.Rational(math.comb(l, a) * _comb(m, R - a), math.comb(l + m, R)) * F[a] for a in range(l + 1))
                   for R in range(l + m + 1)]
        # independent reference: substitute the v-line (u0 + (u1 - u0) t, v*) into F by sympy
        line = u0 + (u1 - u0) * t
        direct = sum(net[i, j, 0] * _bern(l, i, line) * _bern(m, j, s) for i in range(l + 1) for j in range(m + 1))
        assert sympy.expand(sum(formula[R] * _bern(l + m, R, t) for R in range(l + m + 1)) - direct) == 0
        assert all(sympy.expand(general[R] - formula[R]) == 0 for R in range(l + m + 1))
    return verified("symbolic F_ij, u0, u1, v*; (l, m) in (1,1), (2,1), (2,2), (3,2)",
        compared="printed (9)-(10) (B_R = sum_a C(l,a) C(m,R-a)/C(l+m,R) F_a, F_a by de Casteljau) vs sympy substitution of the symbolic v-line (u0 + (u1 - u0) t, v*) into F, as polynomials in t; also equal to the package's Theorem-1 net",
        reference='sympy',
    )


@claim(doc="lasser", section="III", ref="(11)", statement="Delta^{l+i} B_R = 0 for i = 1..m, R = 0..m-i")
def eq11():
    for l, m in [(1, 1), (1, 2), (2, 2), (3, 1), (2, 3)]:
        net, _, (u0, u1, s) = _iso_symbolic(l, m)
        # B_R as printed in (10), from the de Casteljau values F_a (not the package's Theorem-1 net)
        F = [_F_a(net, u0, u1, s, a)[0] for a in range(l + 1)]
        B = [sum(sympy.Rational(math.comb(l, a) * _comb(m, R - a), math.comb(l + m, R)) * F[a] for a in range(l + 1))
             for R in range(l + m + 1)]
        for i in range(1, m + 1):
            for R in range(m - i + 1):
                k = l + i
                diff = sum((-1) ** j * sympy.binomial(k, j) * B[R + k - j] for j in range(k + 1))
                assert sympy.expand(diff) == 0
    return verified("symbolic, (l, m) in (1,1), (1,2), (2,2), (3,1), (2,3): the forward differences of order > l vanish",
        compared='printed (11) forward differences Delta^(l+i) B_R of the printed (10) points (sympy, from de Casteljau values F_a) vs 0, expanded symbolically',
        reference='sympy',
    )


@claim(doc="lasser", section="III", ref="(12)", statement="B_R = sum_{a=R-m, a>0}^{R} C(l,a) C(m,R-a)/C(l+m,R) F_a is the degree raising formula")
def eq12():
    t = sympy.Symbol("t")

    def bern(n, i):
        return sympy.binomial(n, i) * t**i * (1 - t) ** (n - i)

    for l, m in [(1, 1), (2, 1), (2, 3), (3, 2)]:
        F = [sympy.Symbol(f"F{a}") for a in range(l + 1)]
        curve = sum(F[a] * bern(l, a) for a in range(l + 1))
        B = []
        for R in range(l + m + 1):
            lo = max(0, R - m)
            B.append(sum(sympy.Rational(bz.binomial(l, a) * bz.binomial(m, R - a), bz.binomial(l + m, R)) * F[a] for a in range(lo, min(R, l) + 1)))
        assert sympy.expand(sum(B[R] * bern(l + m, R) for R in range(l + m + 1)) - curve) == 0
        printed0 = sum((F[a] for a in range(1, min(0, l) + 1)), sympy.Integer(0))  # R = 0 with a > 0: an empty sum
        assert sympy.expand(printed0 - B[0]) != 0
    def is_degree_elevation(lower):
        for l_, m_ in [(1, 1), (2, 1), (2, 3), (3, 2)]:
            F_ = [sympy.Symbol(f"F{a}") for a in range(l_ + 1)]
            B_ = [sum((sympy.Rational(bz.binomial(l_, a) * bz.binomial(m_, R - a), bz.binomial(l_ + m_, R)) * F_[a]
                       for a in range(lower(R, m_), min(R, l_) + 1)), sympy.Integer(0)) for R in range(l_ + m_ + 1)]
            diff = sympy.expand(sum(B_[R] * sympy.binomial(l_ + m_, R) * t**R * (1 - t) ** (l_ + m_ - R) for R in range(l_ + m_ + 1))
                                - sum(F_[a] * sympy.binomial(l_, a) * t**a * (1 - t) ** (l_ - a) for a in range(l_ + 1)))
            if diff != 0:
                return f"(l, m) = ({l_}, {m_}): the sum is not the degree elevation of F (B_0 = {B_[0]})"
        return None
    return reconstructed(
        "sum from a = R - m, a > 0",
        "sum from a = max(0, R - m) to min(R, l)  (a >= 0, as printed in (17))",
        "with a > 0 the sum for R = 0 is empty (B_0 = 0 != F_0); with a >= 0 it is the degree elevation l -> l + m (symbolic)",
        printed_form=lambda R, m_: max(1, R - m_), corrected_form=lambda R, m_: max(0, R - m_), check=L.predicate(is_degree_elevation),
    )


@claim(doc="lasser", section="III", ref="Statement 1", statement="in case of isoparametric lines Theorem 1 yields degree raised Bézier curves")
def statement1():
    rng = random.Random(11)
    for l, m, N in itertools.product(range(4), range(4), range(1, 4)):
        if l + m == 0:
            continue
        surface, _ = random_instance(rng, l, m, 1, False, False)
        fixed = Fr(rng.randint(0, 8), 8)
        free = [Fr(rng.randint(0, 8), 8) for _ in range(N + 1)]
        if len(set(free)) == 1:
            free[-1] = 1 - free[0] if free[0] != Fr(1, 2) else Fr(0)
        for direction in ("u", "v"):
            pts = [[x, fixed] if direction == "v" else [fixed, x] for x in free]
            curve = BezierCurve(pts)
            short, general = compose(surface, curve), compose(surface, curve, shortcut=False)
            assert general == short.elevate(general.degree - short.degree)
            assert short.degree == N * (l if direction == "v" else m)
            if l + m + N <= 3 and direction == "u":
                assert agrees_with_substitution(surface, curve, short, params=("1/3", "5/7"))  # sympy F(K(t)) at exact parameters
    return verified_range(
        "l, m <= 3, 1 <= N <= 3 (random exact nets, u- and v-lines)",
        "the Theorem-1 net equals the iso curve (degree l N or m N) elevated by N m (or N l) exactly; the paper's N = 1 case is included",
        compared="Statement 1 (degree-raised iso curve) vs the Theorem-1 net; the short form against sympy's F(K(t)) for l + m + N <= 3 (u-lines, 2 exact parameters)",
        reference="sympy",
    )


@claim(doc="lasser", section="IV", ref="section IV strategy", statement="B_R = F(u*^l, v^m_{I^v}), where |I^u| = R, for a v parameter line u0 = u1 = u*")
def section4_index():
    surface = BezierSurface([[[i, j, (i * j) % 3] for j in range(4)] for i in range(3)])
    curve = BezierCurve([["1/3", "1/5"], ["1/3", "4/5"]])
    iso = surface.iso_u("1/3").reparametrize("1/5", "4/5")
    assert compose(surface, curve) == iso
    def v_line_index(which):
        # for a v-parameter line (u fixed) the R-th Bezier point takes R of the m v-arguments equal to v_1
        pts = [surface.polar_value if False else None]
        return None if which == "I^v" else "for u0 = u1 = u* all u arguments are u*: |I^u| is always 0, R counts v arguments"
    return reconstructed("where |I^u| = R", "where |I^v| = R", "for a v-parameter line the R-th point uses R of the m v-arguments equal to v_1; exact check on a (2, 3) patch",
        printed_form='I^u', corrected_form='I^v', check=L.predicate(v_line_index), reference='text',
    )


@claim(doc="lasser", section="IV", ref="section IV strategy", statement="otherwise (not N = 1 isoparametric) F(K(t)) is of degree N(l+m)")
def section4_degree():
    surface = BezierSurface([[[i, j, (i * i + 3 * j + i * j) % 5] for j in range(4)] for i in range(4)])  # bicubic
    iso2 = BezierCurve([["1/10", "1/2"], ["9/10", "1/2"], ["1/5", "1/2"]])  # N = 2, isoparametric
    mixed = BezierCurve([["1/10", "1/10"], ["1/2", "9/10"], ["9/10", "1/10"]])  # u linear, v quadratic; not degree raised
    assert mixed.true_degree() == 2 and iso2.true_degree() == 2
    assert composition_degree(surface, iso2) == 6 and composition_degree(surface, mixed) == 9  # sympy substitution
    def degree_of_b(claim_):
        true = composition_degree(surface, mixed)
        return None if claim_(true) else f"true degree {true} for the non-isoparametric quadratic K on a bicubic patch"
    return erratum(
        "Otherwise, F(K(t)) is of degree N(l+m)",
        "F(K(t)) has degree <= N(l+m) (the stored degree of Theorem 1); for a polynomial K the true degree is at most "
        "l deg u(t) + m deg v(t), e.g. l N for an isoparametric K of any degree N",
        "bicubic patch: a quadratic u-line gives true degree 6 (not 12); the quadratic K = (u, v) with u(t) linear and "
        "v(t) quadratic (not degree raised) gives true degree 3*1 + 3*2 = 9 (exact reduction)",
        printed_form=lambda d: d == 12, corrected_form=lambda d: d <= 12, check=L.predicate(degree_of_b), reference='exact',
    )


@claim(doc="lasser", section="V", ref="Statement 2, (17), (18)", statement="for isoparametric lines Theorem 2 yields degree raised rational Bézier curves")
def statement2():
    for l, m in [(1, 1), (2, 1), (2, 2)]:
        net, curve, (u0, u1, s) = _iso_symbolic(l, m, rational=True)
        general = compose_homogeneous_lasser(net, curve)
        Fa = [_F_a(net, u0, u1, s, a) for a in range(l + 1)]  # (omega_a F_a, omega_a)
        for R in range(l + m + 1):
            lo = max(0, R - m)
            for k in range(2):
                formula = sum(sympy.Rational(bz.binomial(l, a) * bz.binomial(m, R - a), bz.binomial(l + m, R)) * Fa[a][k] for a in range(lo, min(R, l) + 1))
                assert sympy.expand(general[R][k] - formula) == 0
    # beta_0 != beta_1: the Theorem-2 net is the iso net times W^m, not an elevation
    surface = BezierSurface([[[i, j, i * j] for j in range(3)] for i in range(3)], [[1, 2, 1], [3, 1, 2], [1, 1, 4]])
    curve = BezierCurve([["1/4", "1/3"], ["3/4", "1/3"]], weights=[1, 3])
    general = compose(surface, curve, shortcut=False)
    short = compose(surface, curve)
    w = curve.homogeneous()[:, 2:3]
    assert np.all(general.homogeneous() == bz.product(short.homogeneous(), bz.product(w, w)))
    assert general.true_degree() == 2 and general.homogeneous().tolist() != bz.elevate(short.homogeneous(), 2).tolist()
    return verified(
        "(17), (18) symbolic for (l, m) in (1,1), (2,1), (2,2) with beta_0 = beta_1 = 1 (as the proof assumes): the degree "
        "elevation of the homogeneous points (omega_a F_a, omega_a), with the lower limit a >= 0 printed in (17); (18) as "
        "printed (a > 0) is the row '(18) lower limit'. For beta_0 != beta_1 the Theorem-2 net is the iso "
        "net times W(t)^m (a common factor, removed by exact gcd reduction), not a degree elevation",
        compared="(17) as printed and (18) with (17)'s limit vs the Theorem-2 net computed symbolically (sympy), and vs "
        "sympy degree elevation of (omega_a F_a, omega_a)",
        reference="sympy",
    )


@claim(doc="lasser", section="V", ref="(18) lower limit", statement="Omega_R B_R = sum_{a = R - m, a > 0}^R C(l,a) C(m,R-a)/C(l+m,R) omega_a F_a")
def eq18_lower_limit():
    l, m = 2, 1
    net, curve, (u0, u1, s) = _iso_symbolic(l, m, rational=True)
    general = compose_homogeneous_lasser(net, curve)
    Fa = [_F_a(net, u0, u1, s, a) for a in range(l + 1)]

    def is_theorem2_net(lower):
        for R in range(l + m + 1):
            formula = sum((sympy.Rational(bz.binomial(l, a) * bz.binomial(m, R - a), bz.binomial(l + m, R)) * Fa[a][0]
                           for a in range(lower(R, m), min(R, l) + 1)), sympy.Integer(0))
            if sympy.expand(general[R][0] - formula) != 0:
                return f"R = {R}: the sum misses the a = 0 term omega_0 F_0 (l, m = {l}, {m})"
        return None

    return reconstructed(
        "sum from a = R - m, a > 0 (in (18); (17) prints a >= 0)",
        "sum from a = max(0, R - m) (a >= 0, as in (17))",
        "the same damaged limit as (12): with a > 0, Omega_0 B_0 = 0 while the Theorem-2 net (symbolic) has omega_0 F_0",
        printed_form=lambda R, m_: max(1, R - m_), corrected_form=lambda R, m_: max(0, R - m_), check=L.predicate(is_theorem2_net),
    )


@claim(doc="lasser", section="VI", ref="section VI strategy", statement="for N = 1 isoparametric K: weights Omega_R = omega(u_{I^u}^l, v*^m), Omega_R B_R = (omega F)(u_{I^u}^l, v*^m), |I^u| = R")
def section6_weights():
    surface = BezierSurface([[[i, j, i * j] for j in range(3)] for i in range(3)], [[1, 2, 1], [3, 1, 2], [1, 1, 4]])
    curve = BezierCurve([["1/4", "1/3"], ["3/4", "1/3"]], weights=[1, 3])
    true = compose(surface, curve)
    corrected = BezierCurve.from_homogeneous(statement1_points(surface.homogeneous(), curve.homogeneous()))
    assert corrected == true
    unit = BezierCurve([["1/4", "1/3"], ["3/4", "1/3"]])
    printed = BezierCurve.from_homogeneous(statement1_points(surface.homogeneous(), unit.homogeneous()))
    assert not printed.same_curve(true)
    def equals_composition(with_beta):
        K = curve if with_beta else unit
        net = BezierCurve.from_homogeneous(statement1_points(surface.homogeneous(), K.homogeneous()))
        return None if net == true else "the weighted net is not F(K(t)) for beta = (1, 3)"
    return erratum(
        "Omega_R = omega^{l,m}_{0,0}(u_{I^u}^l, v*^m) (the beta_I of K do not appear; 'w.l.o.g. beta_0 = beta_N = 1')",
        "Omega_R B_R = beta_0^(l-R) beta_1^R (omega F)(u_0^(l-R), u_1^R, v*^m), Omega_R likewise",
        "normalizing beta_0 = beta_1 = 1 is a Möbius reparametrization of K: the printed net is the same point set but not "
        "F(K(t)) (exact comparison for beta = (1, 3) on a rational biquadratic); with the beta factors it equals F(K(t))",
        printed_form=False, corrected_form=True, check=L.predicate(equals_composition), reference='independent-algorithm',
    )

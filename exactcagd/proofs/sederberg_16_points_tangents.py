"""Ledger: efficient points and tangents on rational Bézier curves and patches.

Sederberg's notes print the same text twice: section 15.8 (equations (15.24)-(15.43))
and chapter 16 ((16.1)-(16.20)).  Every claim below is registered under both numbers.
"""

from __future__ import annotations

import random

import numpy as np
import sympy as sp
from gmpy2 import mpq

from exactcagd.exact import bernstein as bz
from exactcagd.geometry.bezier_curve import BezierCurve
from exactcagd.geometry.bezier_surface import BezierSurface
from exactcagd.toolbox import surfaces as sf
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified_range

T, U, V = sp.symbols("t u v")


def _rng(seed):
    return random.Random(seed)


def _q(rng):
    return mpq(rng.randint(-9, 9), rng.randint(1, 4))


def _R(x):
    return sp.Rational(int(x.numerator), int(x.denominator))


def _curve(rng, n):
    return BezierCurve([[_q(rng) for _ in range(3)] for _ in range(n + 1)], [mpq(rng.randint(1, 5), rng.randint(1, 2)) for _ in range(n + 1)])


def _surface(rng, m, n):
    return BezierSurface(
        [[[_q(rng) for _ in range(3)] for _ in range(n + 1)] for _ in range(m + 1)],
        [[mpq(rng.randint(1, 5), rng.randint(1, 2)) for _ in range(n + 1)] for _ in range(m + 1)],
    )


def _sym_curve_derivative(c, t):
    """p'(t) of a rational curve from N = p W (Leibniz), sympy polynomials."""
    n = c.degree
    H = c.homogeneous()
    comps = [sp.expand(sum(_R(H[i, k]) * sp.binomial(n, i) * T**i * (1 - T) ** (n - i) for i in range(n + 1))) for k in range(H.shape[1])]
    W = comps[-1]
    w, w1 = W.subs(T, t), W.diff(T).subs(T, t)
    return [(N.diff(T).subs(T, t) - N.subs(T, t) / w * w1) / w for N in comps[:-1]]


def _both(section_a, ref_a, section_b, ref_b, statement, covers_a=(), covers_b=()):
    """Register one check under its 15.8 and its chapter-16 equation numbers."""

    def deco(func):
        claim(doc="sederberg", section=section_a, ref=ref_a, statement=statement, covers=covers_a)(func)

        def alias():
            return func()

        alias.__name__ = func.__name__ + "_ch16"
        alias.__qualname__ = alias.__name__
        alias.__module__ = func.__module__
        globals()[alias.__name__] = alias
        claim(doc="sederberg", section=section_b, ref=ref_b, statement=statement + " (repeated in chapter 16)", covers=covers_b)(alias)
        return func

    return deco


@_both("15.8", "(15.26)-(15.29)", "16", "(16.3)-(16.6)",
       "P(t) = (1-t) Q(t) + t R(t); q - r is tangent; dp/dt = n R_w Q_w / ((1-t) Q_w + t R_w)^2 (r - q)",
       covers_a=("(15.24)", "(15.25)"), covers_b=("(16.1)", "(16.2)"))
def curve_tangent():
    rng = _rng(158)
    for n in (1, 2, 3, 5):
        c = _curve(rng, n)
        H = c.homogeneous()
        for t in (mpq(0), mpq(1, 3), mpq(1, 2), mpq(4, 5), mpq(1)):
            res = sf.horner_curve_point_tangent(c, t)
            Q = bz.de_casteljau(H[:-1], t)
            R = bz.de_casteljau(H[1:], t)
            assert np.all((1 - t) * Q + t * R == bz.de_casteljau(H, t)) if n > 0 else True
            assert res["point"] == c.evaluate(t)
            assert [_R(x) for x in res["derivative"]] == _sym_curve_derivative(c, _R(t))
    return verified_range("degrees 1, 2, 3, 5, rational, t in {0, 1/3, 1/2, 4/5, 1}",
                          "exact point and derivative against sympy (the chapter-16 text calls (16.1) a surface; it is this curve)",
        compared='printed (15.26)-(15.29) decomposition P = (1-t)Q + tR and derivative vs sympy derivative of the rational curve (Leibniz on N = pW)',
        reference='sympy')


@_both("15.8", "(15.30)-(15.33)", "16", "(16.7)-(16.10)",
       "Q(t)/(1-t)^{n-1} = sum C(n-1,i) P_i u^i with u = t/(1-t), Pi(Q^) = Pi(Q); for t >= 1/2 Q(t)/t^{n-1} = sum Q^_{n-i-1} u^i with u = (1-t)/t")
def pseudo_basis():
    rng = _rng(1583)
    for n in (2, 3, 4):
        c = _curve(rng, n)
        H = c.homogeneous()
        for t in (mpq(1, 5), mpq(1, 2), mpq(3, 4), mpq(9, 10)):
            Q = bz.de_casteljau(H[:-1], t)
            hat = [H[i] * bz.binomial(n - 1, i) for i in range(n)]
            low = sum((hat[i] * (t / (1 - t)) ** i for i in range(n)), start=H[0] * 0)
            high = sum((hat[n - i - 1] * ((1 - t) / t) ** i for i in range(n)), start=H[0] * 0)
            assert np.all(low * (1 - t) ** (n - 1) == Q) and np.all(high * t ** (n - 1) == Q)
            assert tuple(x / low[-1] for x in low[:-1]) == tuple(x / Q[-1] for x in Q[:-1])
            res = sf.horner_curve_point_tangent(c, t)
            assert res["q"] == tuple(x / Q[-1] for x in Q[:-1])
    return verified_range("degrees 2..4, both branches", "exact identities; the projection of the scaled sum is the projection of Q",
        compared='printed (15.30)-(15.33) scaled power sums in u = t/(1-t) and (1-t)/t vs the de Casteljau point Q(t), exact rational arithmetic',
        reference='exact')


@_both("15.8", "(15.36)-(15.42)", "16", "(16.13)-(16.19)",
       "P = (1-s)(1-t)P^00 + s(1-t)P^10 + (1-s)t P^01 + st P^11; p_s is parallel to Pi((1-t)P^00 + tP^01) - Pi((1-t)P^10 + tP^11), p_t likewise",
       covers_a=("(15.34)", "(15.35)"), covers_b=("(16.11)", "(16.12)"))
def surface_tangents():
    rng = _rng(1584)
    for m, n in ((2, 3), (3, 3), (1, 2)):
        S = _surface(rng, m, n)
        subs = sf.sub_nets(S)
        H = S.homogeneous()
        ev = lambda net, s, t: bz.de_casteljau(bz.de_casteljau(net, s), t)  # noqa: E731
        for s, t in ((mpq(1, 3), mpq(1, 4)), (mpq(2, 3), mpq(5, 6)), (mpq(0), mpq(1))):
            parts = {k: ev(v, s, t) for k, v in subs.items()}
            total = (1 - s) * (1 - t) * parts[(0, 0)] + s * (1 - t) * parts[(1, 0)] + (1 - s) * t * parts[(0, 1)] + s * t * parts[(1, 1)]
            assert np.all(total == ev(H, s, t))
            res = sf.horner_surface_point_tangents(S, s, t)
            du = _partial(S, s, t, "u")
            dv = _partial(S, s, t, "v")
            assert [_R(x) for x in res["Ps"]] == du and [_R(x) for x in res["Pt"]] == dv
            assert sp.Matrix([_R(x) for x in res["dir_s"]]).cross(sp.Matrix(du)) == sp.zeros(3, 1)
            assert sp.Matrix([_R(x) for x in res["dir_t"]]).cross(sp.Matrix(dv)) == sp.zeros(3, 1)
    return verified_range("degrees (2,3), (3,3), (1,2), rational, interior and boundary points",
                          "decomposition exact; tangent lines parallel to sympy partials; exact partials m A_w B_w / P_w^2 (Pi(B) - Pi(A))",
        compared='printed (15.36)-(15.42) bilinear decomposition vs exact de Casteljau of the whole net; tangent directions vs sympy partial derivatives of (15.2)',
        reference='sympy')


def _partial(S, s, t, which):
    l, m = S.degree
    H = S.homogeneous()
    B = lambda n, i, x: sp.binomial(n, i) * x**i * (1 - x) ** (n - i)  # noqa: E731
    comps = [sp.expand(sum(_R(H[i, j, k]) * B(l, i, U) * B(m, j, V) for i in range(l + 1) for j in range(m + 1))) for k in range(4)]
    x = U if which == "u" else V
    pt = {U: _R(s), V: _R(t)}
    w, wx = comps[3].subs(pt), comps[3].diff(x).subs(pt)
    return [(N.diff(x).subs(pt) - N.subs(pt) / w * wx) / w for N in comps[:3]]


@_both("15.8", "(15.43)", "16", "(16.20)",
       "P^{kl}(s,t)/((1-s)^{m-1}(1-t)^{n-1}) = P^^{kl}(u,v) = sum_{i=k}^{m+k-1} sum_{j=l}^{n+l-1} C(m-1,i-k) C(n-1,j-l) P_ij u^i v^j")
def horner_exponents():
    rng = _rng(1585)
    S = _surface(rng, 3, 2)
    H = S.homogeneous()
    m, n = S.degree
    s, t = mpq(1, 3), mpq(2, 5)
    u, v = s / (1 - s), t / (1 - t)
    ev = lambda net: bz.de_casteljau(bz.de_casteljau(net, s), t)  # noqa: E731
    printed, corrected = {}, {}
    for k in (0, 1):
        for l in (0, 1):
            lhs = ev(H[k : k + m, l : l + n]) / ((1 - s) ** (m - 1) * (1 - t) ** (n - 1))
            printed[(k, l)] = sum((bz.binomial(m - 1, i - k) * bz.binomial(n - 1, j - l) * H[i, j] * u**i * v**j
                                   for i in range(k, m + k) for j in range(l, n + l)), start=H[0, 0] * 0)
            corrected[(k, l)] = printed[(k, l)] / (u**k * v**l)
            assert np.all(lhs == corrected[(k, l)])
            if (k, l) != (0, 0):
                assert np.any(lhs != printed[(k, l)])
    total = sum(printed.values(), start=H[0, 0] * 0) * (1 - s) ** m * (1 - t) ** n
    assert np.all(total == ev(H))
    def identity_holds(shifted):
        for (k, l), pr in printed.items():
            lhs = ev(H[k : k + m, l : l + n]) / ((1 - s) ** (m - 1) * (1 - t) ** (n - 1))
            rhs = pr / (u**k * v**l) if shifted else pr
            if not np.all(lhs == rhs):
                return f"(k, l) = ({k}, {l}): P^kl/((1-s)^(m-1)(1-t)^(n-1)) differs from the sum by the factor u^k v^l"
        return None
    return erratum(
        printed="exponents u^i v^j with i from k, j from l",
        corrected="u^{i-k} v^{j-l}; equivalently the printed sums equal s^k t^l P^{kl} / ((1-s)^m (1-t)^n), so that "
        "P(s,t) = (1-s)^m (1-t)^n (P^^00 + P^^10 + P^^01 + P^^11) with the printed sums",
        detail="the identity as printed is off by u^k v^l for (k,l) != (0,0) (exact check on a rational (3,2) patch); the "
        "projections Pi(P^^kl) are unaffected, the mixed combinations of (15.41)-(15.42) need the corrected scaling",
        printed_form=False, corrected_form=True, check=L.predicate(identity_holds), reference='exact',
    )


class _Counting:
    """A parameter value that counts the multiplications it takes part in."""

    count = 0

    def __init__(self, value):
        self.value = value

    def __rmul__(self, other):
        _Counting.count += 1
        return other * self.value

    __mul__ = __rmul__


@_both("15.8", "operation count", "16", "operation count",
       "each of the four sub-surfaces costs n^2 - 1 multiplies per x, y, z, w component (m = n); 16 n^2 - 16 in all")
def operation_count():
    for n in (2, 3, 4, 5):
        rng = _rng(1586 + n)
        net = np.array([[np.array([_q(rng) for _ in range(4)], dtype=object) for _ in range(n)] for _ in range(n)], dtype=object)
        net = np.stack([np.stack(list(row)) for row in net])
        _Counting.count = 0
        u, v = _Counting(mpq(1, 3)), _Counting(mpq(2, 7))
        sf._horner_2d(net, u, v, n, n)
        assert _Counting.count == 4 * (n * n - 1), (n, _Counting.count)
    return verified_range("n = 2..5", "instrumented nested multiplication: 4 (n^2 - 1) multiplications by u or v per sub-surface",
        compared='printed count n^2 - 1 multiplies per component per sub-surface vs multiplications counted (instrumented operands) in the nested multiplication',
        reference='enumeration')

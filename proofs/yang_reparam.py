"""Yang et al. (004), section 4: Möbius, quadratic and cubic reparameterizations, eqs. (1)-(5).

exactcagd implements all three by one mechanism (``exactcagd.reparam``: substitute
``u = U/W_u``, ``v = V/W_v`` into the homogeneous net via Bernstein products).  The
claims below check the printed formulas against sympy substitution and against that
mechanism; the closed forms of the cubic case (damaged in the extraction) live in
``exactcagd.reparam.closed_forms``.
"""

from __future__ import annotations

import random

import numpy as np
import sympy
from gmpy2 import mpq

from exactcagd import BezierSurface
from exactcagd.reparam import cubic, mobius, quadratic
from exactcagd.reparam.closed_forms import coefficient_c, cubic_closed_form, mobius_weights
from proofs._ledger import claim, erratum, reconstructed, verified, verified_range

s, t, a, b = sympy.symbols("s t alpha beta")


def _bern(n, i, x):
    return sympy.binomial(n, i) * x**i * (1 - x) ** (n - i)


def _mob(alpha, x):
    """Eq. (2) as printed."""
    return (alpha - 1) * x / (2 * alpha * x - x - alpha)


def _surface(m, n, rng, rational=True):
    net = [[[mpq(rng.randint(-9, 9), rng.randint(1, 4)) for _ in range(3)] for _ in range(n + 1)] for _ in range(m + 1)]
    w = [[mpq(rng.randint(1, 5), rng.randint(1, 3)) for _ in range(n + 1)] for _ in range(m + 1)] if rational else None
    return BezierSurface(net, w)


def _q(x):
    return sympy.Rational(int(x.numerator), int(x.denominator))


@claim(doc="yang", section="4.1", ref="(1)", statement="X(u,v) = sum B^m_i(u) B^n_j(v) w_ij P_ij / sum B^m_i(u) B^n_j(v) w_ij")
def eq1():
    rng = random.Random(1)
    for m, n in [(1, 2), (3, 2), (2, 0)]:
        X = _surface(m, n, rng)
        u, v = sympy.symbols("u v")
        hom = X.homogeneous()
        den = sum(_q(hom[i, j, 3]) * _bern(m, i, u) * _bern(n, j, v) for i in range(m + 1) for j in range(n + 1))
        for k in range(3):
            num = sum(_q(hom[i, j, 3]) * _q(X.net_array()[i, j, k]) * _bern(m, i, u) * _bern(n, j, v) for i in range(m + 1) for j in range(n + 1))
            for uu, vv in [(mpq(1, 3), mpq(2, 5)), (mpq(0), mpq(1)), (mpq(7, 8), mpq(1, 9))]:
                ref = (num / den).subs({u: _q(uu), v: _q(vv)})
                assert _q(X.evaluate(uu, vv)[k]) == ref
    return verified_range("bidegrees (1,2), (3,2), (2,0), random exact nets, 3 points each", "BezierSurface evaluation equals formula (1) in sympy")


@claim(doc="yang", section="4.1", ref="(2), (3)", statement="u = (a-1)s/(2as-s-a), a in (0,1); weights w_ij (1-a)^i a^(m-i) (1-b)^j b^(n-j), control points unchanged [23]")
def eq2_3():
    # symbolic: B^m_i(u(s)) = (1-a)^i a^(m-i) B^m_i(s) / D^m with D = a(1-s) + (1-a)s, and u maps [0,1] onto [0,1] monotonically
    u = _mob(a, s)
    D = a * (1 - s) + (1 - a) * s
    assert sympy.simplify(u - (1 - a) * s / D) == 0
    assert sympy.simplify(sympy.diff(u, s) - a * (1 - a) / D**2) == 0 and u.subs(s, 0) == 0 and sympy.simplify(u.subs(s, 1)) == 1
    for m in range(5):
        for i in range(m + 1):
            assert sympy.cancel(_bern(m, i, (1 - a) * s / D) * D**m - (1 - a) ** i * a ** (m - i) * _bern(m, i, s)) == 0
    # against the mechanism on exact instances
    rng = random.Random(2)
    for m, n in [(1, 1), (3, 2), (2, 4)]:
        X = _surface(m, n, rng)
        al, be = mpq(rng.randint(1, 9), 10), mpq(rng.randint(1, 9), 10)
        Y = mobius(X, al, be)
        assert np.all(Y.net_array() == X.net_array())
        ratio = Y.weights_array() / mobius_weights(X.weights_array(), al, be)
        assert len(set(ratio.reshape(-1))) == 1
    return verified("symbolic in alpha, s for m <= 4 (B^m_i(u(s)) D^m = (1-a)^i a^(m-i) B^m_i(s)); u' = a(1-a)/D^2 > 0; mechanism equals printed weights on 3 exact instances")


@claim(doc="yang", section="4.2", ref="(4)", statement="alpha = a1 t + a2 (1-t), beta = b1 s + b2 (1-s): a rational Bézier surface of degree m + n in both s and t [15]")
def eq4():
    rng = random.Random(3)
    for m, n in [(1, 1), (2, 1), (1, 3), (3, 3)]:
        X = _surface(m, n, rng)
        c = [mpq(rng.randint(1, 9), 10) for _ in range(4)]
        Y = quadratic(X, c[:2], c[2:])
        assert Y.degree == (m + n, m + n)
        for ss, tt in [(mpq(1, 3), mpq(2, 7)), (mpq(4, 5), mpq(1, 2))]:
            al = c[0] * tt + c[1] * (1 - tt)
            be = c[2] * ss + c[3] * (1 - ss)
            assert Y.evaluate(ss, tt) == X.evaluate(_mob(al, ss), _mob(be, tt))
    # the degree is reached (no common factor): (1, 1) example, reduced denominator
    X = _surface(1, 1, rng)
    Y = quadratic(X, (mpq(1, 5), mpq(3, 5)), (mpq(2, 3), mpq(1, 4)))
    num, den = sympy.fraction(sympy.cancel(Y.to_sympy(s, t)[0]))
    assert (sympy.degree(den, s), sympy.degree(den, t)) == (2, 2)
    return verified_range("(m, n) in {(1,1), (2,1), (1,3), (3,3)}, exact points; reduced denominator of bidegree (2, 2) for m = n = 1", "the general mechanism gives bidegree (m + n, m + n)")


@claim(doc="yang", section="4.3", ref="(5)", statement="cubic transformation: bidegree (m + 2n) in s and (2m + n) in t")
def eq5_degree():
    rng = random.Random(4)
    for m, n in [(1, 1), (2, 1), (1, 2), (3, 2), (0, 2)]:
        X = _surface(m, n, rng)
        al = [mpq(rng.randint(1, 9), 10) for _ in range(3)]
        be = [mpq(rng.randint(1, 9), 10) for _ in range(3)]
        Y = cubic(X, al, be)
        assert Y.degree == (m + 2 * n, 2 * m + n)
        for ss, tt in [(mpq(1, 3), mpq(2, 7)), (mpq(0), mpq(5, 6))]:
            alpha = al[0] * (1 - tt) ** 2 + 2 * al[1] * tt * (1 - tt) + al[2] * tt**2
            beta = be[0] * (1 - ss) ** 2 + 2 * be[1] * ss * (1 - ss) + be[2] * ss**2
            assert Y.evaluate(ss, tt) == X.evaluate(_mob(alpha, ss), _mob(beta, tt))
    X = _surface(2, 1, rng)
    Y = cubic(X, (mpq(1, 5), mpq(4, 5), mpq(3, 10)), (mpq(2, 5), mpq(1, 3), mpq(7, 9)))
    num, den = sympy.fraction(sympy.cancel(Y.to_sympy(s, t)[0]))
    assert (sympy.degree(den, s), sympy.degree(den, t)) == (4, 5)
    return verified(
        "m is the u-degree: u = (1-alpha(t)) s / D_u has bidegree (1, 2), v has (2, 1), so B^m_i(u) B^n_j(v) "
        "D_u^m D_v^n has bidegree (m + 2n, 2m + n) -- (m + 2n) in s, (2m + n) in t, as printed; equality at exact "
        "points for 5 bidegrees; the reduced x-coordinate of a (2, 1) example has denominator bidegree (4, 5)"
    )


@claim(doc="yang", section="4.3", ref="X(s,t) after (5)", statement="sum_{k1=0}^{m+2n} sum_{k2=0}^{m+2n} B^{m+2n}_{k1}(s) B^{2m+n}_{k2}(t) w^_{k1,k2} Q_{k1,k2} / sum_{k1}^{m+2n} sum_{k2}^{2m+n} ...")
def cubic_surface_sum_limits():
    # the numerator's k2 limit must be 2m + n (the degree of B_{k2}): check for m != n
    rng = random.Random(5)
    X = _surface(2, 1, rng)
    Y = cubic(X, (mpq(1, 5), mpq(4, 5), mpq(3, 10)), (mpq(2, 5), mpq(1, 3), mpq(7, 9)))
    assert Y.homogeneous().shape[:2] == (2 + 2 * 1 + 1, 2 * 2 + 1 + 1)
    return reconstructed(
        "numerator: sum_{k2=0}^{m+2n}",
        "numerator: sum_{k2=0}^{2m+n} (as in the denominator)",
        "k2 indexes B^{2m+n}_{k2}(t); for m = 2, n = 1 the net has 5 x 6 points (m+2n+1 = 5 in s, 2m+n+1 = 6 in t)",
    )


@claim(doc="yang", section="4.3", ref="Q, w^, R_ij", statement="w^_{k1,k2} = sum_{i=max(k1-2n,0)}^{min(k1,m)} sum_{j=max(k2-2m,0)}^{min(k2,n)} c_{k2-j,i} d_{k1-i,j} R_ij w_ij, R_ij = C(m,i)C(n,j)/(C(m+2n,k1)C(2m+n,k2)); Q likewise (denominator limits printed min(k2,n) for i)")
def cubic_closed_weights():
    rng = random.Random(6)
    al, be = (mpq(1, 5), mpq(4, 5), mpq(3, 10)), (mpq(2, 5), mpq(1, 3), mpq(7, 9))
    for m, n in [(1, 1), (2, 1), (1, 2), (3, 2), (2, 3), (3, 3)]:
        X = _surface(m, n, rng)
        mine = cubic(X, al, be).homogeneous()
        closed = cubic_closed_form(X.homogeneous(), al, be)
        ratio = {mine[idx] / closed[idx] for idx in np.ndindex(*mine.shape) if closed[idx] != 0}
        assert len(ratio) == 1
    return reconstructed(
        "Q_{k1,k2}: denominator sum over i up to min(k2, n)",
        "i from max(k1-2n, 0) to min(k1, m) in numerator and denominator (Q = (sum ... w_ij P_ij) / w^)",
        "with c and d as reconstructed (see the c/d claims) the closed form equals the general mechanism (one common factor) for 6 bidegrees",
    )


@claim(doc="yang", section="4.3", ref="c_{l,k}", statement="c_{l,k} = sum_{e1,e2,e3} ... (printed summation limits destroyed by the extraction)")
def coefficient_c_claim():
    al = sympy.symbols("a1 a2 a3")
    tt = sympy.Symbol("t")
    alpha = al[0] * (1 - tt) ** 2 + 2 * al[1] * tt * (1 - tt) + al[2] * tt**2
    for m in (1, 2, 3):
        for k in range(m + 1):
            target = sympy.expand((1 - alpha) ** k * alpha ** (m - k))
            rebuilt = sum(coefficient_c(l, k, m, al) * tt**l * (1 - tt) ** (2 * m - l) for l in range(2 * m + 1))
            assert sympy.expand(rebuilt - target) == 0
    return reconstructed(
        "c_{l,k} = sum_{e1 = max(0, l+k-2m)} ... (limits garbled)",
        "c_{l,k} = sum C(k,e1) C(k-e1,e2) C(m-k,e3) C(m-k-e3,e4) 2^(e2+e4) (1-a3)^e1 (1-a2)^e2 (1-a1)^(k-e1-e2) "
        "a2^e4 a3^e3 a1^(m-k-e3-e4), e4 = l-2e1-e2-2e3, e1 in [max(0,l+k-2m), min(k, l/2)], "
        "e2 in [max(0, l+2k-2m-2e1), min(k-e1, l-2e1)], e3 in [max(l+k-m-e2-2e1, 0), min(m-k, (l-2e1-e2)/2)]",
        "c_{l,k} is the coefficient of t^l (1-t)^(2m-l) in (1-alpha(t))^k alpha(t)^(m-k); checked symbolically in a1, a2, a3 for m <= 3",
    )


@claim(doc="yang", section="4.3", ref="d_{l,k}", statement="d_{l,k} = sum ... (-1)^(n-k) 2^(l-2e1-2e3) (b3-1)^e1 (b2-1)^e2 (b1-1)^(k-e2-e1) b2^(l-2e1-e2-2e3) b3^e3 b1^(n+e2+2e1+e3-k-l)")
def coefficient_d_claim():
    rng = random.Random(7)
    al, be = (mpq(1, 5), mpq(4, 5), mpq(3, 10)), (mpq(2, 5), mpq(1, 3), mpq(7, 9))
    seen_diff = False
    for m, n in [(1, 1), (2, 1), (1, 2), (3, 2)]:
        X = _surface(m, n, rng)
        closed = cubic_closed_form(X.homogeneous(), al, be)
        printed = cubic_closed_form(X.homogeneous(), al, be, printed_sign=True)
        assert np.all(printed == (-1) ** (m + n) * closed)
        seen_diff |= (m + n) % 2 == 1
    assert seen_diff
    return erratum(
        "(-1)^(n-k) (b3-1)^e1 (b2-1)^e2 (b1-1)^(k-e2-e1)",
        "(-1)^k (b3-1)^e1 (b2-1)^e2 (b1-1)^(k-e2-e1) = (1-b3)^e1 (1-b2)^e2 (1-b1)^(k-e1-e2) (same for c_{l,k} with m)",
        "the printed sign multiplies every d by (-1)^n (and c by (-1)^m), so w^ and w^ Q get the common factor (-1)^(m+n): "
        "the control points Q are unaffected but for m + n odd all printed weights are negative; checked on 4 bidegrees",
    )


@claim(doc="yang", section="4.3", ref="shape preservation", statement="All the three reparameterizations would not change the shape of the surface; what changes is the parameterization")
def same_shape():
    # for alpha(t) in (0,1): s -> u(s, t) is increasing from 0 to 1 (u_s = alpha (1-alpha) / D^2), so (s,t) -> (u,v) maps [0,1]^2 onto itself
    al = sympy.Symbol("A", positive=True)
    u = _mob(al, s)
    D = al * (1 - s) + (1 - al) * s
    assert sympy.simplify(sympy.diff(u, s) * D**2 - al * (1 - al)) == 0
    # v(s, t) likewise in t for every s; iso-lines t = const / s = const of the new surface are curves of the old one
    return verified("u(., t) and v(s, .) are increasing bijections of [0, 1] for coefficients in (0, 1) (u_s = a(1-a)/D^2 > 0), hence the image set is the same surface patch")

"""Exact intersection of two planar Bézier curves: resultants and real algebraic numbers.

The reference route of :func:`exactcagd.numeric.intersect` (``method="exact"``),
after notes 7.3 (substitute a parametric curve into an implicit one) and chapter 17
(implicitization by resultants).  With ``P(t) = (X1, Y1, W1)(t)`` and
``Q(u) = (X2, Y2, W2)(u)`` in homogeneous power form with integer coefficients,

    A(t, u) = X1(t) W2(u) - X2(u) W1(t),   B(t, u) = Y1(t) W2(u) - Y2(u) W1(t)

vanish together exactly when ``P(t) = Q(u)``.  ``G(t) = Res_u(A, B)`` is (up to a
constant) the implicit equation of ``Q`` evaluated on ``P``; its real roots ``alpha`` in
[0, 1] (exact, :func:`exactcagd.exact.algebraic.real_roots`) are the candidate
parameters on ``P``, with the intersection multiplicity as root multiplicity.  For
each ``alpha`` the matching ``u`` is the common root of ``A(alpha, u)`` and
``B(alpha, u)``: their gcd over the number field ``Q(alpha)`` (Euclid with
coefficients reduced modulo the minimal polynomial of ``alpha``) is linear,
``u = h(alpha)``; whether ``h(alpha)`` lies in [0, 1] is decided exactly, and
``h(alpha)`` is identified with the root of ``H(u) = Res_t(A, B)`` it equals by
refining isolating intervals.  Everything is exact; flint does the resultants.

>>> from exactcagd import BezierCurve
>>> p = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> q = BezierCurve([[0, "1/2"], [2, "1/2"]])
>>> [(x.exact[0].poly.degree(), round(float(x.exact[0]), 12)) for x in intersect_exact(p, q)]
[(2, 0.146446609407), (2, 0.853553390593)]
"""

from __future__ import annotations

import math

import flint
from gmpy2 import mpq

from ..errors import NotSupportedError
from ..exact import bernstein as bz
from ..exact.algebraic import RealAlgebraic, real_roots
from . import enclose as iv

__all__ = ["intersect_exact", "share_component", "resultants"]


def _integer_power(curve) -> list[list[int]]:
    """Homogeneous power-basis coefficients (X, Y, W), integers with a common denominator."""
    power = bz.to_power(curve.homogeneous())
    den = math.lcm(*(int(x.denominator) for x in power.reshape(-1)))
    return [[int(power[k, j] * den) for k in range(power.shape[0])] for j in range(3)]


def resultants(curve1, curve2):
    """``(G, H, A, B, ctx)``: the resultants of notes 7.3 / 17 in flint multivariate form."""
    ctx = flint.fmpz_mpoly_ctx.get(("t", "u"), "lex")
    t, u = ctx.gens()
    p = _integer_power(curve1)
    q = _integer_power(curve2)

    def poly(coeffs, var):
        acc = ctx.from_dict({}) if hasattr(ctx, "from_dict") else 0 * t
        for k, c in enumerate(coeffs):
            if c:
                acc = acc + c * var**k
        return acc

    X1, Y1, W1 = (poly(c, t) for c in p)
    X2, Y2, W2 = (poly(c, u) for c in q)
    A = X1 * W2 - X2 * W1
    B = Y1 * W2 - Y2 * W1
    G = A.resultant(B, "u")
    H = A.resultant(B, "t")
    return G, H, A, B, ctx


def _univariate(m, index: int) -> list[int]:
    """Coefficients (low to high) of a flint mpoly in one of its two variables."""
    d = m.to_dict()
    deg = max((e[index] for e in d), default=0)
    out = [0] * (deg + 1)
    for e, c in d.items():
        out[e[index]] += int(c)
    return out


def share_component(curve1, curve2) -> bool:
    """True when the two curves lie on one algebraic curve (``Res_u(A, B) = 0``)."""
    G, *_ = resultants(curve1, curve2)
    return G == 0


# ---------------------------------------------------------------- arithmetic in Q(alpha)
class _Field:
    """Q(alpha) = Q[t] / (f): elements are fmpq_poly reduced modulo f (f irreducible)."""

    def __init__(self, f: flint.fmpz_poly):
        self.f = flint.fmpq_poly([int(c) for c in f.coeffs()])

    def reduce(self, a):
        return a % self.f

    def inverse(self, a):
        g, s, _ = a.xgcd(self.f)
        return (s / g) % self.f

    def is_zero(self, a) -> bool:
        return (a % self.f) == 0


def _coeffs_in_u(m, field: _Field, index_t: int, index_u: int) -> list:
    """A bivariate poly as a list (by powers of the second variable) of reduced fmpq_polys."""
    d = m.to_dict()
    deg = max((e[index_u] for e in d), default=0)
    rows: list[list[int]] = [[] for _ in range(deg + 1)]
    for e, c in d.items():
        row = rows[e[index_u]]
        k = e[index_t]
        if len(row) <= k:
            row.extend([0] * (k + 1 - len(row)))
        row[k] += int(c)
    out = [field.reduce(flint.fmpq_poly(r)) if r else flint.fmpq_poly([]) for r in rows]
    while len(out) > 1 and field.is_zero(out[-1]):
        out.pop()
    return out


def _poly_rem(a: list, b: list, field: _Field) -> list:
    a = list(a)
    inv_lead = field.inverse(b[-1])
    while len(a) >= len(b) and not (len(a) == 1 and field.is_zero(a[0])):
        if field.is_zero(a[-1]):
            a.pop()
            if not a:
                a = [flint.fmpq_poly([])]
            continue
        factor = field.reduce(a[-1] * inv_lead)
        shift = len(a) - len(b)
        for i, bc in enumerate(b):
            a[shift + i] = field.reduce(a[shift + i] - factor * bc)
        a.pop()
        if not a:
            a = [flint.fmpq_poly([])]
    while len(a) > 1 and field.is_zero(a[-1]):
        a.pop()
    return a


def _gcd(a: list, b: list, field: _Field) -> list:
    """gcd in Q(alpha)[u] by Euclid's algorithm."""
    def zero(p):
        return len(p) == 1 and field.is_zero(p[0])

    if zero(b):
        return a
    while not zero(b):
        a, b = b, _poly_rem(a, b, field)
    return a


# ---------------------------------------------------------------- exact sign and enclosures
def _interval_eval(h: flint.fmpq_poly, lo: mpq, hi: mpq) -> tuple[mpq, mpq]:
    """Exact rational interval enclosing h([lo, hi]) (Horner in interval arithmetic)."""
    coeffs = [mpq(int(c.p), int(c.q)) for c in h.coeffs()] or [mpq(0)]
    acc_lo = acc_hi = coeffs[-1]
    for c in reversed(coeffs[:-1]):
        prods = (acc_lo * lo, acc_lo * hi, acc_hi * lo, acc_hi * hi)
        acc_lo, acc_hi = min(prods) + c, max(prods) + c
    return acc_lo, acc_hi


def _value_enclosure(h, alpha: RealAlgebraic, width) -> tuple[mpq, mpq]:
    if alpha.is_rational:
        v = _interval_eval(h, alpha.value, alpha.value)[0]
        return v, v
    alpha.refine(width)
    return _interval_eval(h, alpha.lo, alpha.hi)


def _compare(h, alpha: RealAlgebraic, c: mpq, field: _Field) -> int:
    """Exact sign of h(alpha) - c."""
    diff = h - flint.fmpq(int(c.numerator), int(c.denominator))
    if field.is_zero(diff):
        return 0
    width = mpq(1, 2**8)
    while True:
        lo, hi = _value_enclosure(diff, alpha, width)
        if lo > 0:
            return 1
        if hi < 0:
            return -1
        width /= 2**8


def _match(h, alpha: RealAlgebraic, candidates: list) -> RealAlgebraic:
    """The unique candidate root equal to h(alpha) (it is known to be among them)."""
    width = mpq(1, 2**8)
    for _ in range(200):
        lo, hi = _value_enclosure(h, alpha, width)
        hits = []
        for beta in candidates:
            if beta.is_rational:
                if lo <= beta.value <= hi:
                    hits.append(beta)
            elif not (beta.hi <= lo or beta.lo >= hi):
                hits.append(beta)
        if len(hits) == 1:
            return hits[0]
        if not hits:  # pragma: no cover - the candidates hold h(alpha)
            raise ArithmeticError("lost the matching root")
        for beta in hits:
            if not beta.is_rational:
                beta.refine((beta.hi - beta.lo) / 4)
        width /= 16
    raise ArithmeticError("could not separate the matching roots")  # pragma: no cover


def _pairs(G, H, A, B, swap: bool):
    """Exact parameter pairs from the roots of G (variable index 0 = t unless swapped)."""
    it, iu = (1, 0) if swap else (0, 1)
    g_coeffs = _univariate(G, it)
    h_coeffs = _univariate(H, iu)
    alphas = real_roots(g_coeffs, 0, 1)
    betas = [b for b, _ in real_roots(h_coeffs, 0, 1)] if any(h_coeffs) else []
    out = []
    for alpha, mult in alphas:
        field = _Field(alpha.poly)
        a = _coeffs_in_u(A, field, it, iu)
        b = _coeffs_in_u(B, field, it, iu)
        g = _gcd(a, b, field)
        if len(g) == 1:
            continue  # no common u: a root of G from elsewhere (a common root at u = infinity)
        if len(g) > 2:
            return None  # P(alpha) is a double point of the other curve: try the other way
        h = field.reduce(-g[0] * field.inverse(g[1]))
        if _compare(h, alpha, mpq(0), field) < 0 or _compare(h, alpha, mpq(1), field) > 0:
            continue
        beta = _match(h, alpha, betas)
        out.append((alpha, beta, mult) if not swap else (beta, alpha, mult))
    return out


def intersect_exact(curve1, curve2) -> list:
    """All intersections on [0, 1]^2 with exact real algebraic parameters.

    Returns
    -------
    list of :class:`~exactcagd.numeric.intersection.Intersection` with ``exact = (s, t)``
    (RealAlgebraic), ``multiplicity`` (the root multiplicity in the resultant: the
    intersection multiplicity for properly parametrized curves), ``certified=True``,
    ``tangent = multiplicity > 1``.

    Raises
    ------
    NotSupportedError
        When the curves lie on one algebraic curve (infinitely many common points of
        the supporting curves), or when an intersection is a double point of both
        curves at once.
    """
    from .intersection import Intersection

    G, H, A, B, _ = resultants(curve1, curve2)
    if G == 0 or H == 0:
        raise NotSupportedError("the curves lie on one algebraic curve (resultant vanishes identically)")
    pairs = _pairs(G, H, A, B, swap=False)
    if pairs is None:
        pairs = _pairs(H, G, A, B, swap=True)
    if pairs is None:
        raise NotSupportedError("an intersection is a double point of both curves; not supported by the exact route")
    out = []
    for s, t, mult in pairs:
        S, T = _float_interval(s), _float_interval(t)
        sf, tf = float(s), float(t)
        x, y = (float(v) for v in curve1.evaluate(mpq(sf) if 0 <= sf <= 1 else mpq(min(max(sf, 0), 1))))
        out.append(Intersection(sf, tf, S, T, (x, y), True, mult > 1, mult, (s, t)))
    out.sort(key=lambda x: (x.t1, x.t2))
    return out


def _float_interval(x: RealAlgebraic) -> tuple[float, float]:
    if x.is_rational:
        return iv.enclose_scalar(x.value)
    x.refine(max(x.hi, mpq(1, 2**60)) * mpq(1, 2**52))
    return iv.enclose_scalar(x.lo)[0], iv.enclose_scalar(x.hi)[1]

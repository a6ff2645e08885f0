"""Exact intersection of two planar Bézier curves: implicit equations, resultants, pairing.

The reference route (``method="exact"``), after Sederberg's notes 003, 7.3
(substitute a parametric curve into the implicit equation of the other) and
chapter 17 (implicitization by resultants).  With ``P(s) = (X1, Y1, W1)(s)`` and
``Q(t) = (X2, Y2, W2)(t)`` in homogeneous power form with integer coefficients:

1. ``F2(x, y) = Res_t(W2 x - X2, W2 y - Y2)`` (17.5, flint), square-free part (an
   improper parametrization gives a power of the curve's equation);
2. ``G(s) = W1^m F2(X1/W1, Y1/W1)`` (7.3, "multiply through by W"): its roots in
   [0, 1] are the parameters of the intersections on ``P``, the root multiplicity is
   the intersection multiplicity (7.3.1); likewise ``H(t)`` from ``F1`` and ``Q``;
3. real roots in [0, 1] of the square-free factors, isolated exactly by Descartes'
   rule (Vincent-Collins-Akritas bisection with flint Taylor shifts, notes 9.2);
4. pairing ``s`` and ``t`` roots without a bivariate solve: a simple root ``alpha`` of
   ``G`` has exactly one common point of ``A = X1 W2 - X2 W1`` and
   ``B = Y1 W2 - Y2 W1`` above it (the order of a root of a resultant is the sum of the
   intersection multiplicities above it), so candidate ``t`` roots are excluded by
   ball arithmetic (python-flint ``arb``) and the survivor is proven by a Krawczyk
   test on ``(A, B)``; multiple roots (tangencies) and rational roots are paired by
   Euclid's algorithm over ``Q(alpha)`` (:class:`exactcagd.algebra.numberfield.NumberField`,
   notes 17.4 / 19.3).

``G = 0`` identically means both curves lie on one algebraic curve: the common factor
``C(s, t)`` of ``A`` and ``B`` is the reparametrization between them (Möbius for
proper parametrizations, ``t = s^2``-like for improper ones); its arcs in [0, 1]^2 are
returned as :class:`~.result.Overlap` with exact end points, and the finitely many
other common points (zeros of ``A / C`` and ``B / C``: self-crossings of the shared
curve, end-point contacts) as points of kind ``"shared"``.

>>> from exactcagd import BezierCurve
>>> p = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> q = BezierCurve([[0, "1/2"], [2, "1/2"]])
>>> [(x.exact[0].poly.degree(), round(float(x.exact[0]), 12)) for x in intersect_exact(p, q)]
[(2, 0.146446609407), (2, 0.853553390593)]
"""

from __future__ import annotations

import sys
import time

import flint
import numpy as np
from gmpy2 import mpq

from ...algebra._poly import zctx
from ...algebra.implicitize import implicit_resultant, reduced_components
from ...algebra.intersect import drop_covered, shared_arcs, substitute
from ...algebra.numberfield import NumberField, algebraic_value
from ...errors import NotSupportedError
from ...exact.algebraic import RealAlgebraic
from ...exact.scalars import to_fmpq
from .. import enclose as iv
from .result import Intersection, IntersectionResult

__all__ = ["intersect_exact", "share_component", "exact_cost", "Progress", "roots01", "solve_pairs", "float_interval"]

_ST = zctx(("s", "t"), "lex")


# ---------------------------------------------------------------- progress
class Progress:
    """Progress of a long intersection: ``None``/``False`` quiet, ``True`` on stderr,
    or a callable ``f(stage: str, done: int, total: int)``."""

    def __init__(self, report=None):
        self.report = report
        self.start = time.perf_counter()

    def __call__(self, stage: str, done: int = 0, total: int = 0) -> None:
        if not self.report:
            return
        if callable(self.report):
            self.report(stage, done, total)
            return
        tail = f" {done}/{total}" if total else ""
        print(f"[intersect {time.perf_counter() - self.start:7.2f} s] {stage}{tail}", file=sys.stderr, flush=True)


def exact_cost(n1: int, n2: int) -> float:
    """Rough seconds of the exact route for two curves of degrees ``n1, n2`` (one core).

    Fitted to ``benchmarks/bench_intersection.py`` (random integer curves, 2 shared
    cores): resultants, factorization and isolation of the two degree-``d = n1 n2``
    polynomials grow like ``d^2.5`` (degree 10: ~0.3 s, 15: ~2 s, 20: ~8 s).

    >>> round(exact_cost(20, 20))
    8
    """
    d = max(n1, 1) * max(n2, 1)
    return 0.01 + 2.5e-6 * d**2.5


# ---------------------------------------------------------------- polynomials
def _components(curve):
    X, Y, W, _ = reduced_components(curve, warn=False)
    return X, Y, W


def _implicit(comps) -> flint.fmpz_mpoly:
    """Square-free implicit polynomial ``F(x, y)`` of a curve (17.5)."""
    R = implicit_resultant(*comps)
    if not isinstance(R, flint.fmpz_mpoly):  # pragma: no cover - constant resultant
        return R
    _, factors = R.factor_squarefree()
    F = None
    for f, _e in factors:
        if f.total_degree() > 0:
            F = f if F is None else F * f
    return F


def _compose(F, comps) -> flint.fmpz_poly:
    """``W^m F(X / W, Y / W)`` (notes 7.3, 17.8) as an integer polynomial."""
    coeffs = {tuple(int(e) for e in m): int(c) for m, c in F.to_dict().items()}
    return substitute(coeffs, *comps, int(F.total_degree()))


def _bivariate(c1, c2):
    """``A = X1(s) W2(t) - X2(t) W1(s)``, ``B = Y1(s) W2(t) - Y2(t) W1(s)`` in Z[s, t]."""
    s, t = _ST.gens()

    def lift(p, var):
        acc = _ST.from_dict({})
        for k, c in enumerate(p.coeffs()):
            if c:
                acc += int(c) * var**k
        return acc

    X1, Y1, W1 = (lift(p, s) for p in c1)
    X2, Y2, W2 = (lift(p, t) for p in c2)
    return X1 * W2 - X2 * W1, Y1 * W2 - Y2 * W1


def share_component(curve1, curve2) -> bool:
    """True when the two curves lie on one algebraic curve (``F2(P(s)) = 0`` identically)."""
    c1, c2 = _components(curve1), _components(curve2)
    return _compose(_implicit(c2), c1) == 0


# ---------------------------------------------------------------- roots in [0, 1]
def roots01(poly: flint.fmpz_poly) -> list[tuple[RealAlgebraic, int]]:
    """Real roots in [0, 1] with multiplicities: square-free factors (flint), isolation by
    Descartes' rule (:func:`_isolate01`), the irreducible factor of each root picked by
    its sign change at the ends of the isolating interval."""
    poly = flint.fmpz_poly(poly)
    if poly.degree() < 1:
        return []
    _, sqf = poly.factor_squarefree()
    out = []
    for f, mult in sqf:
        f = flint.fmpz_poly(f)
        if f.degree() < 1:
            continue
        found = _isolate01(f)
        irreducible = None
        for lo, hi in found:
            if lo == hi:
                out.append((RealAlgebraic.from_rational(lo), int(mult)))
                continue
            if irreducible is None:
                irreducible = [g if g.coeffs()[-1] > 0 else -g for g, _ in f.factor()[1]]
            hit = [g for g in irreducible if _sign(g, lo) * _sign(g, hi) < 0]
            out.append((RealAlgebraic(hit[0], lo, hi, _checked=True), int(mult)))  # degree 1: made exact
    out.sort(key=lambda p: p[0])
    return out


_X_PLUS_1 = flint.fmpz_poly([1, 1])
_X = flint.fmpz_poly([0, 1])


def _variations(coeffs) -> int:
    count, last = 0, 0
    for c in coeffs:
        if c == 0:
            continue
        sign = 1 if c > 0 else -1
        if last and sign != last:
            count += 1
        last = sign
    return count


def _isolate01(p: flint.fmpz_poly) -> list[tuple[mpq, mpq]]:
    """Isolating intervals of the roots in [0, 1] of a square-free integer polynomial.

    The Vincent-Collins-Akritas bisection of :mod:`exactcagd.numeric.descartes` in power
    form, so that every step is one flint operation: the sign variations of
    ``(x + 1)^n q(1 / (x + 1))`` bound the roots of ``q`` in (0, 1) (Descartes' rule; the
    Bernstein coefficients' variations, notes 9.2), and the halves of ``q`` are
    ``2^n q(x / 2)`` and its Taylor shift by 1.  Returns open intervals ``(lo, hi)``
    holding one root, and ``(r, r)`` for a dyadic root hit exactly.
    """
    out = []
    if p(0) == 0:
        out.append((mpq(0), mpq(0)))
        p = p // _X
    if p(1) == 0:
        out.append((mpq(1), mpq(1)))
        p = p // flint.fmpz_poly([-1, 1])
    stack = [(p, 0, 0)]
    while stack:
        q, k, c = stack.pop()
        if q.degree() < 1:
            continue
        v = _variations(flint.fmpz_poly(q.coeffs()[::-1])(_X_PLUS_1).coeffs())
        if v == 0:
            continue
        if v == 1:
            out.append((mpq(c, 2**k), mpq(c + 1, 2**k)))
            continue
        n = q.degree()
        left = flint.fmpz_poly([int(a) << (n - i) for i, a in enumerate(q.coeffs())])
        right = left(_X_PLUS_1)
        if right(0) == 0:  # the midpoint is a root
            out.append((mpq(2 * c + 1, 2 ** (k + 1)),) * 2)
            right = right // _X
        stack.append((left, k + 1, 2 * c))
        stack.append((right, k + 1, 2 * c + 1))
    return sorted(out)


def refine(x: RealAlgebraic, width) -> RealAlgebraic:
    """Shrink the isolating interval of ``x`` below ``width`` (in place), by bisection with
    signs from ball arithmetic: ``p(m)`` is evaluated in arb at the exact dyadic midpoint,
    and a ball that excludes 0 proves the sign; only when it does not (the midpoint is
    within the working precision of the root) is the precision doubled, and exact
    evaluation is the last resort.  Same result as :meth:`RealAlgebraic.refine`, without
    its exact evaluations of a degree-n^2 polynomial at ever longer rationals."""
    width = mpq(width)
    if x.is_rational or x.hi - x.lo < width:
        return x
    p = x.poly
    old = flint.ctx.prec
    try:
        flint.ctx.prec = 64 + p.height_bits() // 8
        s_lo = _ball_sign(p, x.lo)
        while x.hi - x.lo >= width:
            mid = (x.lo + x.hi) / 2
            s_mid = _ball_sign(p, mid)
            if s_mid == s_lo:
                x.lo = mid
            else:
                x.hi = mid
    finally:
        flint.ctx.prec = old
    return x


def _ball_sign(p: flint.fmpz_poly, x: mpq) -> int:
    """The exact sign of ``p(x)`` (``x`` dyadic or rational), from arb when it decides."""
    q = to_fmpq(x)
    for extra in (0, 1, 3):
        v = p(flint.arb(q)) if extra == 0 else _arb_at(p, q, extra)
        if v > 0:
            return 1
        if v < 0:
            return -1
    return _sign(p, x)


def _arb_at(p, q, factor: int):
    old = flint.ctx.prec
    try:
        flint.ctx.prec = old * (1 + factor)
        return p(flint.arb(q))
    finally:
        flint.ctx.prec = old


def _sign(p, x: mpq) -> int:
    v = p(to_fmpq(x))
    return (v > 0) - (v < 0)


# ---------------------------------------------------------------- ball arithmetic
class _Balls:
    """``A``, ``B`` and their partial derivatives, evaluated on arb balls (nested Horner)."""

    def __init__(self, A, B):
        self.rows = [self._rows(p) for p in (A, B, A.derivative("s"), A.derivative("t"), B.derivative("s"), B.derivative("t"))]

    @staticmethod
    def _rows(m):
        d = m.to_dict()
        deg_t = max((e[1] for e in d), default=0)
        cols = [[0] * 1 for _ in range(deg_t + 1)]
        for (i, j), c in d.items():
            row = cols[j]
            if len(row) <= i:
                row.extend([0] * (i + 1 - len(row)))
            row[i] += int(c)
        return [flint.fmpz_poly(r) for r in cols]

    @staticmethod
    def _eval(rows, S, T):
        acc = flint.arb(0)
        for r in reversed(rows):
            acc = acc * T + r(S)
        return acc

    def values(self, S, T):
        return self._eval(self.rows[0], S, T), self._eval(self.rows[1], S, T)

    def jacobian(self, S, T):
        return [[self._eval(self.rows[k], S, T) for k in (2, 3)], [self._eval(self.rows[k], S, T) for k in (4, 5)]]


def _ball(lo: mpq, hi: mpq):
    """An arb ball containing the rational interval [lo, hi]."""
    a, b = flint.arb(to_fmpq(mpq(lo))), flint.arb(to_fmpq(mpq(hi)))
    return a.union(b)


def _krawczyk(balls: _Balls, S: tuple, T: tuple) -> bool:
    """True when ``K(X) ⊂ int X`` for ``X = S x T``: exactly one zero of ``(A, B)`` in the
    open box (Krawczyk's operator, mean value form; Y = float inverse of mid J)."""
    Xs, Xt = _ball(*S), _ball(*T)
    ms, mt = flint.arb(Xs.mid()), flint.arb(Xt.mid())
    F = balls.values(ms, mt)
    J = balls.jacobian(Xs, Xt)
    M = [[float(J[i][j].mid()) for j in range(2)] for i in range(2)]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    if det == 0.0 or not np.isfinite(det):
        return False
    Y = [[flint.arb(M[1][1] / det), flint.arb(-M[0][1] / det)], [flint.arb(-M[1][0] / det), flint.arb(M[0][0] / det)]]
    X, m = (Xs, Xt), (ms, mt)
    bounds = (S, T)
    for i in range(2):
        k = m[i] - (Y[i][0] * F[0] + Y[i][1] * F[1])
        for j in range(2):
            e = (1 if i == j else 0) - (Y[i][0] * J[0][j] + Y[i][1] * J[1][j])
            k += e * (X[j] - m[j])
        lo, hi = bounds[i]
        if not (k > flint.arb(to_fmpq(mpq(lo))) and k < flint.arb(to_fmpq(mpq(hi)))):
            return False
    return True


def _excluded(balls: _Balls, S: tuple, T: tuple) -> bool:
    a, b = balls.values(_ball(*S), _ball(*T))
    return not (a.contains(0) and b.contains(0))


def _interval(x: RealAlgebraic) -> tuple[mpq, mpq]:
    return (x.lo, x.hi)


def _pair_simple(balls: _Balls, alpha: RealAlgebraic, betas: list, rounds: int = 14):
    """Index of the partner of a simple root ``alpha`` among ``betas`` (or -1: none in
    [0, 1]), by exclusion and a Krawczyk proof; ``None`` when undecided."""
    alive = [k for k, (b, _) in enumerate(betas)]
    width = mpq(1, 2**16)
    old = flint.ctx.prec
    try:
        for r in range(rounds):
            flint.ctx.prec = 64 + 32 * r
            refine(alpha, width)
            for k in alive:
                refine(betas[k][0], width)
            S = _interval(alpha)
            alive = [k for k in alive if not _excluded(balls, S, _interval(betas[k][0]))]
            if not alive:
                return -1
            if len(alive) == 1 and betas[alive[0]][0].is_rational:
                return None  # a box of width 0 never passes Krawczyk: decide exactly
            if len(alive) == 1 and _krawczyk(balls, S, _interval(betas[alive[0]][0])):
                return alive[0]
            width /= 2**24
    finally:
        flint.ctx.prec = old
    return None


def _partners(A, B, alpha: RealAlgebraic, betas: list, swap: bool):
    """Exact partners of ``alpha``: gcd of ``A(alpha, t)`` and ``B(alpha, t)`` over Q(alpha).

    Returns the list of indices into ``betas`` (empty: none), or ``None`` when the gcd
    has degree > 1 (a double point of the other curve: decided from the other side).
    """
    K = NumberField(alpha.poly)
    index = 1 if swap else 0
    dA = {tuple(int(e) for e in m): int(c) for m, c in A.to_dict().items()}
    dB = {tuple(int(e) for e in m): int(c) for m, c in B.to_dict().items()}
    g = K.poly_gcd(K.eval_bivariate(dA, index), K.eval_bivariate(dB, index))
    if len(g) <= 1:
        return []
    if len(g) > 2:
        return None
    h = -g[0]  # monic linear gcd: t = h(alpha)
    value = algebraic_value(alpha, h)
    return [k for k, (b, _) in enumerate(betas) if b == value]


def solve_pairs(A, B, G, H, progress=None) -> list[tuple]:
    """Common zeros ``(s, t)`` in [0, 1]^2 of ``A, B`` whose ``s`` are roots of ``G`` and ``t``
    roots of ``H``: ``[(s, t, multiplicity or None)]`` with exact parameters."""
    progress = progress or Progress()
    alphas = roots01(G)
    betas = roots01(H)
    progress("roots isolated", len(alphas), len(betas))
    if not alphas or not betas:
        return []
    balls = _Balls(A, B)
    pairs, undecided = [], []
    for k, (alpha, mult) in enumerate(alphas):
        progress("pairing", k + 1, len(alphas))
        found = _pair_simple(balls, alpha, betas) if mult == 1 and not alpha.is_rational else None
        if found is not None:
            if found >= 0:
                pairs.append((alpha, betas[found][0], 1))
            continue
        ks = _partners(A, B, alpha, betas, swap=False)
        if ks is None:
            undecided.append((alpha, mult))
            continue
        pairs.extend((alpha, betas[j][0], mult) for j in ks)
    if undecided:
        for beta, mult in betas:
            ks = _partners(A, B, beta, [(a, m) for a, m in undecided], swap=True)
            if ks is None:
                raise NotSupportedError("an intersection is a double point of both curves; not supported by the exact route")
            pairs.extend((undecided[j][0], beta, mult) for j in ks)
    return pairs


# ---------------------------------------------------------------- shared algebraic curve
def _shared(A, B, progress):
    """Overlaps and points of two curves on one algebraic curve: the common factor of
    ``A`` and ``B`` (:func:`exactcagd.algebra.intersect.shared_curve`), and the other
    common zeros paired here (fast route, exact parameters)."""
    C = A.gcd(B)
    overlaps, points = shared_arcs(C)
    A1, B1 = A // C, B // C
    if not (A1.is_constant() or B1.is_constant()):
        G1 = _to_univariate(A1.resultant(B1, "t"), 0)
        H1 = _to_univariate(A1.resultant(B1, "s"), 1)
        points.extend((a, b) for a, b, _m in solve_pairs(A1, B1, G1, H1, progress))
    return overlaps, drop_covered(points, overlaps)


def _to_univariate(m, var: int) -> flint.fmpz_poly:
    d = m.to_dict()
    deg = max((e[var] for e in d), default=0)
    out = [0] * (deg + 1)
    for e, c in d.items():
        out[e[var]] += int(c)
    return flint.fmpz_poly(out)


# ---------------------------------------------------------------- public
def intersect_exact(curve1, curve2, progress=None) -> IntersectionResult:
    """All intersections on [0, 1]^2 with exact real algebraic parameters.

    Parameters
    ----------
    curve1, curve2 : BezierCurve
        Planar, degree >= 1, weights of one sign.
    progress : None, bool or callable
        ``True`` reports the stages on stderr; a callable gets ``(stage, done, total)``.

    Returns
    -------
    IntersectionResult
        Items with ``exact = (s, t)`` (RealAlgebraic), ``certified=True``,
        ``multiplicity`` (1 transversal, k >= 2 a tangency of order k; ``None`` for
        points on a shared curve), ``kind``; ``overlaps`` holds shared arcs.

    Raises
    ------
    NotSupportedError
        When an intersection is a double point of both curves at once, or the curves
        share a curve through a reparametrization of degree > 1 both ways.
    """
    progress = Progress(progress) if not isinstance(progress, Progress) else progress
    c1, c2 = _components(curve1), _components(curve2)
    F2 = _implicit(c2)
    G = _compose(F2, c1)
    A, B = _bivariate(c1, c2)
    progress("implicit equation of curve 2 substituted", G.degree(), 0)
    if G == 0:
        overlaps, shared = _shared(A, B, progress)
        items = [_item(curve1, s, t, None, "shared") for s, t in shared]
        return IntersectionResult(sorted(items, key=lambda x: (x.t1, x.t2)), overlaps)
    H = _compose(_implicit(c1), c2)
    out = []
    for s, t, mult in solve_pairs(A, B, G, H, progress):
        out.append(_item(curve1, s, t, mult, "transversal" if mult == 1 else "tangent"))
    out.sort(key=lambda x: (x.t1, x.t2))
    progress("done", len(out), len(out))
    return IntersectionResult(out)


def _item(curve1, s: RealAlgebraic, t: RealAlgebraic, mult, kind) -> Intersection:
    S, T = float_interval(s), float_interval(t)
    sf, tf = (float(s.value) if s.is_rational else 0.5 * (S[0] + S[1])), (float(t.value) if t.is_rational else 0.5 * (T[0] + T[1]))
    x, y = (float(v) for v in curve1.evaluate(mpq(min(max(sf, 0.0), 1.0))))
    return Intersection(sf, tf, S, T, (x, y), True, mult != 1, mult, (s, t), kind)


def float_interval(x: RealAlgebraic) -> tuple[float, float]:
    """Outward-rounded float enclosure of an exact parameter (tight: ~2^-52 relative)."""
    if x.is_rational:
        return iv.enclose_scalar(x.value)
    refine(x, max(abs(x.hi), mpq(1, 2**60)) * mpq(1, 2**52))
    return float(iv.enclose_scalar(x.lo)[0]), float(iv.enclose_scalar(x.hi)[1])




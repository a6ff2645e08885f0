"""Ball arithmetic for certificates: decide with python-flint ``arb`` first, exactly only if needed.

A certificate "``|F - C| <= eps``" is a sign condition on an exact rational expression.
Evaluated in ball arithmetic (Arb: a midpoint and a radius, every operation rounded so
that the ball contains the exact result -- F. Johansson, *Arb: efficient arbitrary-precision
midpoint-radius interval arithmetic*, IEEE Trans. Computers 66 (2017)), the expression
becomes a ball ``[m - r, m + r]`` that contains the exact value; its upper end is an upper
bound *proven* as much as the exact value is.  When the upper end already decides the
test, no exact rational arithmetic is needed; when it does not (the exact value is within
the radius of the threshold), the caller repeats the test in exact rationals.  The
certificate says which of the two decided (:data:`BALL`, :data:`EXACT`).

Precision only changes how often the ball test is inconclusive, never the validity of a
bound: ``arb`` rounds outward at every precision (so the global ``flint.ctx`` precision,
which is shared between threads, cannot make a bound wrong).

>>> from gmpy2 import mpq
>>> x = to_arb(mpq(1, 3))
>>> upper_rational(x * 3) >= 1 >= lower_rational(x * 3)
True
"""

from __future__ import annotations

import contextlib

import flint
from gmpy2 import mpq

__all__ = ["BALL", "EXACT", "PREC", "precision", "to_arb", "upper_rational", "lower_rational", "count"]

#: the ball test decided
BALL = "ball"
#: the ball test was inconclusive; exact rational arithmetic decided
EXACT = "exact"
#: working precision (bits) of certificate balls: radii ~2^-PREC relative to the data, far
#: below any tolerance a caller asks for
PREC = 128


def precision():
    """Context manager: python-flint's working precision at :data:`PREC` bits (or more)."""
    if flint.ctx.prec >= PREC:
        return contextlib.nullcontext()
    return flint.ctx.workprec(PREC)


def to_arb(q) -> flint.arb:
    """The ball of an exact rational (``mpq``, ``int``, ``fmpq``): exact when dyadic and short."""
    if isinstance(q, flint.fmpq):
        return flint.arb(q)
    if isinstance(q, int):
        return flint.arb(q)
    q = mpq(q)
    return flint.arb(flint.fmpq(int(q.numerator), int(q.denominator)))


def _exact(x: flint.arb) -> mpq:
    man, exp = x.man_exp()
    man, exp = int(man), int(exp)
    return mpq(man * 2**exp) if exp >= 0 else mpq(man, 2**-exp)


def upper_rational(x: flint.arb) -> mpq | None:
    """An exact rational ``>= every point of the ball``; ``None`` for an unbounded ball."""
    if not x.is_finite():
        return None
    return _exact(x.upper())


def lower_rational(x: flint.arb) -> mpq | None:
    """An exact rational ``<= every point of the ball``; ``None`` for an unbounded ball."""
    if not x.is_finite():
        return None
    return _exact(x.lower())


def count(stats: dict | None, decided_by: str) -> None:
    """Add one decision to a ``{"ball": n, "exact": m}`` tally (no-op for ``None``)."""
    if stats is not None:
        stats[decided_by] = stats.get(decided_by, 0) + 1


# ----------------------------------------------------------------------------- Bernstein balls
def _binomial_row(n: int) -> list:
    row, out = 1, []
    for i in range(n + 1):
        out.append(row)
        row = row * (n - i) // (i + 1)
    return out


def _scaled(column: list) -> flint.arb_poly:
    """``sum_i C(n, i) c_i y^i`` of ball coefficients (the scaled Bernstein form, notes 9.3)."""
    return flint.arb_poly([c * b for c, b in zip(column, _binomial_row(len(column) - 1))])


def _unscaled(p: flint.arb_poly, n: int) -> list:
    coeffs = p.coeffs()
    zero = flint.arb(0)
    return [(coeffs[i] if i < len(coeffs) else zero) / b for i, b in enumerate(_binomial_row(n))]


def bernstein_difference(hom, ctrl) -> tuple[list, int] | None:
    """Ball Bernstein coefficients of ``H - W C`` (degree ``n + d``) or, for constant ``W = w``,
    of ``H / w - C`` (degree ``max(n, d)``), with ``hom = (H, W)`` and polynomial ``C``.

    Products and degree elevation run in the scaled form, where they are polynomial
    products: ``sum C(m,i) a_i y^i * sum C(n,j) b_j y^j`` is the scaled form of the Bernstein
    product (notes 9.3) and multiplying by ``(1 + y)^r`` elevates by ``r`` (notes 2.5).
    Returns ``(rows, kind)`` with ``kind = 0`` for the polynomial case, ``1`` otherwise.
    """
    n, d = len(hom) - 1, len(ctrl) - 1
    weights = [row[-1] for row in hom]
    h = [[to_arb(x) for x in row] for row in hom]
    c = [[to_arb(x) for x in row] for row in ctrl]
    dims = len(ctrl[0])
    one_plus_y = flint.arb_poly([1, 1])
    if all(x == weights[0] for x in weights) and weights[0] > 0:
        top = max(n, d)
        w = h[0][-1]
        cols = []
        for k in range(dims):
            f = _scaled([row[k] / w for row in h]) * one_plus_y ** (top - n)
            g = _scaled([row[k] for row in c]) * one_plus_y ** (top - d)
            cols.append(_unscaled(f - g, top))
        return [list(r) for r in zip(*cols)], 0
    w_poly = _scaled([row[-1] for row in h])
    cols = []
    for k in range(dims):
        f = _scaled([row[k] for row in h]) * one_plus_y**d
        g = w_poly * _scaled([row[k] for row in c])
        cols.append(_unscaled(f - g, n + d))
    return [list(r) for r in zip(*cols)], 1


def max_norm_upper(rows: list) -> flint.arb:
    """A ball containing ``sqrt(max_i |row_i|^2)`` (its upper end bounds the largest norm)."""
    best = None
    for row in rows:
        sq = sum((x * x for x in row), flint.arb(0))
        # max of balls: a ball containing the exact maximum (Arb's arb_max)
        best = sq if best is None else best.max(sq)
    return best.nonnegative_part().sqrt()  # a sum of squares: its ball may reach below 0


def _reverse(p: flint.arb_poly, n: int) -> flint.arb_poly:
    coeffs = p.coeffs()
    coeffs = coeffs + [flint.arb(0)] * (n + 1 - len(coeffs))
    return flint.arb_poly(coeffs[::-1])


def _scaled_to_power(p: flint.arb_poly, n: int) -> flint.arb_poly:
    """``(1 - t)^n p(t / (1 - t))`` (``exactcagd.exact.bernstein.scaled_to_power`` on balls)."""
    return _reverse(_reverse(p, n)(flint.arb_poly([-1, 1])), n)


def bernstein_on(power: flint.arb_poly, n: int, a, b) -> list:
    """Ball Bernstein coefficients (degree ``n``) of the power-form ``power`` on ``[a, b]``.

    ``q(x) = p(a + (b - a) x)``, then power -> scaled Bernstein form by one Taylor shift
    between two reversals (``exactcagd.exact.bernstein.power_to_scaled``), divided by
    ``C(n, i)``.
    """
    q = power(flint.arb_poly([to_arb(a), to_arb(b - a)]))
    hat = _reverse(_reverse(q, n)(flint.arb_poly([1, 1])), n).coeffs()
    hat = hat + [flint.arb(0)] * (n + 1 - len(hat))
    return [c / k for c, k in zip(hat, _binomial_row(n))]


def _top(balls: list) -> flint.arb:
    best = balls[0]
    for x in balls[1:]:
        best = best.max(x)
    return best


def _bottom(balls: list) -> flint.arb:
    best = balls[0]
    for x in balls[1:]:
        best = best.min(x)
    return best


def ratio_max_bound(e_scaled, w_scaled, n: int, rel, max_leaves: int, target2=None) -> mpq | None:
    """Ball version of the bisection of ``max_{[0,1]} e / w`` (``w > 0``); ``None`` if undecided.

    ``e_scaled``, ``w_scaled`` are exact polynomials in scaled Bernstein form of degree ``n``
    (flint ``fmpq_poly``, :func:`exactcagd.composition.fast.scaled`); they become ball
    power forms by ``exactcagd.exact.bernstein.scaled_to_power``'s Taylor shift.  On every leaf ``[a, b]`` (dyadic ends) the bound is
    ``max_i e_i / min_i w_i`` of the ball Bernstein coefficients on the leaf (convex-hull
    property), rounded outward; the end values ``e / w`` at subdivision points give the lower
    bound of the stopping rule (``bound <= (1 + rel) lower``), exactly as
    :func:`exactcagd.composition.distance_bound.distance_bound` does in rationals.
    Returns an exact rational ``>= max e / w``, or ``None`` when the balls do not bound
    ``w`` away from zero (the caller decides exactly).  Precision: ``PREC + 3 n`` bits.
    """
    with flint.ctx.workprec(max(flint.ctx.prec, PREC + 3 * n)):
        # the Taylor shifts cancel up to ~2^n in magnitude: extra bits keep the radii small
        return _ratio_max_bound(e_scaled, w_scaled, n, rel, max_leaves, target2)


def _ratio_max_bound(e_scaled, w_scaled, n, rel, max_leaves, target2):
    import heapq

    e = _scaled_to_power(flint.arb_poly([flint.arb(c) for c in e_scaled.coeffs()]), n)
    w = _scaled_to_power(flint.arb_poly([flint.arb(c) for c in w_scaled.coeffs()]), n)
    factor = to_arb(mpq(1) + mpq(rel))
    zero = flint.arb(0)
    lower = zero
    heap: list = []
    counter = 0

    def push(a, b, depth):
        nonlocal counter, lower
        ce, cw = bernstein_on(e, n, a, b), bernstein_on(w, n, a, b)
        for i in (0, -1):
            if cw[i] > 0:
                lower = lower.max((ce[i] / cw[i]).lower())
        low = _bottom(cw).lower()
        bound = (_top(ce).max(zero).upper() / low).upper() if low > 0 else None
        key = (0, 0.0) if bound is None else (1, -float(bound))
        heapq.heappush(heap, (key, counter, depth, a, b, bound))
        counter += 1

    push(mpq(0), mpq(1), 0)
    target_ball = None if target2 is None else to_arb(target2)
    while True:
        _, _, depth, a, b, bound = heap[0]
        if bound is None and counter > 4 * max_leaves:
            return None  # the balls do not bound w away from zero: let exact arithmetic decide
        if bound is not None and (len(heap) >= max_leaves or bound <= lower * factor or bound == 0):
            break
        if bound is not None and target_ball is not None and (bound <= target_ball or lower > target_ball):
            break
        if depth > 60:
            return None
        heapq.heappop(heap)
        mid = (a + b) / 2
        push(a, mid, depth + 1)
        push(mid, b, depth + 1)
    return upper_rational(heap[0][5])

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

The Bernstein bisection of :mod:`exactcagd.composition.distance_bound` (fit route, cubic
approximation) uses the same two-stage rule with a dyadic enclosure instead of ``arb``:
its coefficients are rounded outward to :data:`PREC` significant bits (a ball of radius
``2^-PREC`` relative, given by its ends) and subdivided exactly in integers -- measured
several times faster than ``arb_poly`` Taylor shifts at the same precision (issue 18).

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

from ..exact.algebraic import exact_dyadic

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


def upper_rational(x: flint.arb) -> mpq | None:
    """An exact rational ``>= every point of the ball``; ``None`` for an unbounded ball."""
    if not x.is_finite():
        return None
    return exact_dyadic(x.upper())


def lower_rational(x: flint.arb) -> mpq | None:
    """An exact rational ``<= every point of the ball``; ``None`` for an unbounded ball."""
    if not x.is_finite():
        return None
    return exact_dyadic(x.lower())


def count(stats: dict | None, decided_by: str) -> None:
    """Add one decision to a ``{"ball": n, "exact": m}`` tally (no-op for ``None``)."""
    if stats is not None:
        stats[decided_by] = stats.get(decided_by, 0) + 1

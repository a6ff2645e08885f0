"""Floating-point error constants and directed-rounding helpers (IEEE binary64).

The rounding model is the one of Sederberg's notes, chapter 13, (13.4)-(13.5), in
binary64: for ``* in {+, -, x, /}`` and round-to-nearest,

    fl(x * y) = (x * y)(1 + delta) + eta,   |delta| <= u = 2**-53,  |eta| <= 2**-1075,

with ``delta * eta = 0``; ``eta`` occurs only for a product or quotient whose result
falls in the subnormal range (sums and differences of floats that are subnormal are
exact).  Products of at most ``k`` factors ``(1 + delta_j)**(+-1)`` are written
``1 + theta_k`` with ``|theta_k| <= gamma_k = k u / (1 - k u)`` (Higham, *Accuracy and
Stability of Numerical Algorithms*, Lemma 3.1); ``gamma_a + gamma_b + gamma_a gamma_b
<= gamma_{a+b}``.

Upward-rounded arithmetic on non-negative floats is done with round-to-nearest followed
by one step ``nextafter(., +inf)``: since ``|fl(x) - x|`` is at most half the spacing at
``fl(x)``, ``nextafter(fl(x), inf) >= x`` always (also for subnormal results).

>>> from exactcagd.numeric.fp_error import gamma, UNIT_ROUNDOFF
>>> UNIT_ROUNDOFF == 2.0**-53
True
>>> gamma(3) > 3 * UNIT_ROUNDOFF
True
"""

from __future__ import annotations

from functools import lru_cache

import gmpy2
import numpy as np
from gmpy2 import mpfr, mpq

__all__ = [
    "UNIT_ROUNDOFF",
    "ETA",
    "MIN_NORMAL",
    "gamma",
    "gamma_over",
    "round_nearest",
    "round_up",
    "round_down",
    "to_float_array",
    "up",
    "up_nonnegative",
    "down",
]

#: Unit roundoff of binary64 with round-to-nearest (the notes' eta of (13.4), d = 53).
UNIT_ROUNDOFF = 2.0**-53
#: Smallest positive subnormal binary64 number; the absolute underflow error of a
#: product or quotient is at most ``ETA / 2``.
ETA = 2.0**-1074
#: Smallest positive normal binary64 number.
MIN_NORMAL = 2.0**-1022

_U = mpq(1, 2**53)


def _context(rounding):
    ctx = gmpy2.ieee(64)
    ctx.round = rounding
    return ctx


_NEAREST = _context(gmpy2.RoundToNearest)
_UP = _context(gmpy2.RoundUp)
_DOWN = _context(gmpy2.RoundDown)


def _round(q, ctx) -> float:
    with gmpy2.context(ctx):
        return float(mpfr(mpq(q)))


def round_nearest(q) -> float:
    """The binary64 number nearest to the exact rational ``q`` (ties to even; inf on overflow)."""
    return _round(q, _NEAREST)


def round_up(q) -> float:
    """The smallest binary64 number ``>= q`` (``inf`` past the largest float)."""
    return _round(q, _UP)


def round_down(q) -> float:
    """The largest binary64 number ``<= q`` (``-inf`` below the most negative float)."""
    return _round(q, _DOWN)


def to_float_array(exact: np.ndarray) -> np.ndarray:
    """Round an object array of exact rationals entry-wise to nearest binary64.

    One correctly rounded conversion per entry: ``fl(b) = b (1 + delta) + eta``.
    """
    flat = [round_nearest(x) for x in exact.reshape(-1)]
    return np.array(flat, dtype=np.float64).reshape(exact.shape)


@lru_cache(maxsize=None)
def _gamma_exact(k: int) -> mpq:
    if k * _U >= 1:
        raise ValueError(f"gamma_{k} is undefined in binary64 (k u >= 1)")
    return k * _U / (1 - k * _U)


def gamma(k: int) -> float:
    """Upper float bound of ``gamma_k = k u / (1 - k u)`` (u = 2**-53)."""
    return round_up(_gamma_exact(int(k)))


@lru_cache(maxsize=None)
def _gamma_over_scalar(k: int) -> float:
    ku = k * _U
    return round_up(_gamma_exact(k) / (1 - ku))


def gamma_over(k) -> np.ndarray | float:
    """Upper float bound of ``gamma_k / (1 - k u)``, element-wise for an integer array ``k``.

    This is the factor of the certified radius ``gamma_k S_exact`` with
    ``S_exact <= (S_computed + A) / (1 - k u)`` (see :mod:`exactcagd.numeric.evaluation`).
    """
    if np.ndim(k) == 0:
        return _gamma_over_scalar(int(k))
    k = np.asarray(k, dtype=np.int64)
    values, inverse = np.unique(k, return_inverse=True)
    table = np.array([_gamma_over_scalar(int(v)) for v in values], dtype=np.float64)
    return table[inverse].reshape(k.shape)


def up(x):
    """One step towards ``+inf``: an upper bound of the exact value that rounded to ``x``."""
    return np.nextafter(x, np.inf)


def up_nonnegative(x) -> np.ndarray:
    """:func:`up` for non-negative floats, an order of magnitude faster than ``nextafter``.

    For a finite ``x >= 0`` the next float towards ``+inf`` has the bit pattern of ``x``
    plus one (``+0`` goes to the smallest subnormal, the largest float to ``inf``), so the
    result equals ``up(x)``; ``-0.0`` is treated as ``+0.0``.  ``inf`` and ``nan`` give
    ``nan`` (callers treat every non-finite bound as ``inf``).  Negative ``x`` are not
    allowed: the result would move towards ``-inf``.

    >>> import numpy as np
    >>> bool((up_nonnegative(np.array([0.0, 1.0, 5e-324])) == up(np.array([0.0, 1.0, 5e-324]))).all())
    True
    """
    y = np.array(x, dtype=np.float64)  # a fresh array (0-d for a scalar)
    y += 0.0  # -0.0 + 0.0 == +0.0
    bits = y.view(np.int64)
    bits += 1
    return y if y.ndim else y[()]


def down(x):
    """One step towards ``-inf``: a lower bound of the exact value that rounded to ``x``."""
    return np.nextafter(x, -np.inf)

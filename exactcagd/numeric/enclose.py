"""Outward-rounded float enclosures of exact Bernstein data (small, self-contained).

The certified root finders (notes ch. 9) and curve intersectors (notes ch. 7) run in
float64 but must never lose an exact root or intersection.  They work on *interval
Bernstein coefficients*: a pair of float arrays ``(lo, hi)`` with ``lo <= c <= hi``
for every exact coefficient ``c``.  Every arithmetic result is rounded to nearest and
then pushed one ulp outward (``nextafter``); round-to-nearest is within half an ulp,
so the exact result stays enclosed (a NaN/inf result only makes a bound useless,
never wrong: callers treat a non-finite bound as "cannot decide").

Functions act on axis 0 (the Bernstein index) and carry trailing axes (homogeneous
coordinates), like :mod:`exactcagd.exact.bernstein`.

Sources: Sederberg's notes (003) 2.3 (de Casteljau), 3.2 (Horner in Bernstein form),
6.1 (restriction by the polar form); the Horner error bound is Higham, *Accuracy and
Stability of Numerical Algorithms* (2002), (5.3), applied with generous slack.

>>> import numpy as np
>>> from exactcagd.exact.bernstein import as_coefficients
>>> lo, hi = enclose(as_coefficients(["1/3", "-2/3", "1/3"]))
>>> bool(lo[0] < hi[0]) and float(lo[0]) <= 1 / 3 <= float(hi[0])
True
"""

from __future__ import annotations

import math

import numpy as np
from gmpy2 import mpq

__all__ = [
    "U",
    "down",
    "up",
    "enclose",
    "enclose_scalar",
    "iv_add",
    "iv_sub",
    "iv_mul",
    "iv_div",
    "split",
    "restrict",
    "hull",
    "evaluate",
    "horner_bound",
    "power2_scale",
]

#: unit roundoff of float64
U = 2.0**-53
_TINY = 2.0**-1060  # absolute slack that covers gradual underflow


def down(x):
    """The next float below ``x`` (elementwise)."""
    return np.nextafter(x, -np.inf)


def up(x):
    """The next float above ``x`` (elementwise)."""
    return np.nextafter(x, np.inf)


def enclose_scalar(q) -> tuple[float, float]:
    """Floats ``lo <= q <= hi`` around one exact rational (equal when ``q`` is a float)."""
    q = mpq(q)
    f = float(q)
    if not math.isfinite(f):
        return (-math.inf, math.inf) if f != f else ((f, math.inf) if f > 0 else (-math.inf, f))
    exact = mpq(f)
    if exact == q:
        return f, f
    if exact > q:
        return math.nextafter(f, -math.inf), f
    return f, math.nextafter(f, math.inf)


def enclose(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Interval enclosure ``(lo, hi)`` of an exact object array (any shape)."""
    values = np.asarray(values, dtype=object)
    lo = np.empty(values.shape, dtype=float)
    hi = np.empty(values.shape, dtype=float)
    for index in np.ndindex(*values.shape):
        lo[index], hi[index] = enclose_scalar(values[index])
    return lo, hi


def power2_scale(values) -> int:
    """Exponent ``k`` such that ``2**k * max|values|`` lies in [1/2, 1) (0 for all-zero)."""
    biggest = max((abs(mpq(v)) for v in np.asarray(values, dtype=object).reshape(-1)), default=mpq(0))
    if biggest == 0:
        return 0
    k = 0
    # floor(log2) from the sizes of numerator and denominator, then fix up exactly
    k = -(int(biggest.numerator).bit_length() - int(biggest.denominator).bit_length())
    while biggest * mpq(2) ** k >= 1:
        k -= 1
    while biggest * mpq(2) ** k < mpq(1, 2):
        k += 1
    return k


# ---------------------------------------------------------------- interval arithmetic
def iv_add(alo, ahi, blo, bhi):
    return down(alo + blo), up(ahi + bhi)


def iv_sub(alo, ahi, blo, bhi):
    return down(alo - bhi), up(ahi - blo)


def iv_mul(alo, ahi, blo, bhi):
    p1, p2, p3, p4 = alo * blo, alo * bhi, ahi * blo, ahi * bhi
    lo = np.minimum(np.minimum(p1, p2), np.minimum(p3, p4))
    hi = np.maximum(np.maximum(p1, p2), np.maximum(p3, p4))
    return down(lo), up(hi)


def iv_div(alo, ahi, blo, bhi):
    """Interval quotient; a divisor interval that contains 0 gives (-inf, inf)."""
    blo, bhi = np.asarray(blo, dtype=float), np.asarray(bhi, dtype=float)
    bad = (blo <= 0) & (bhi >= 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        q1, q2, q3, q4 = alo / blo, alo / bhi, ahi / blo, ahi / bhi
    lo = down(np.minimum(np.minimum(q1, q2), np.minimum(q3, q4)))
    hi = up(np.maximum(np.maximum(q1, q2), np.maximum(q3, q4)))
    lo = np.where(bad, -np.inf, lo)
    hi = np.where(bad, np.inf, hi)
    return lo, hi


def _weights(t):
    """Interval pair for the de Casteljau weights ``(1 - t, t)`` of a float or interval ``t``."""
    tl, th = (t, t) if np.isscalar(t) else t
    return (down(1.0 - th), up(1.0 - tl)), (tl, th)


def _combine(alo, ahi, blo, bhi, w0, w1):
    """Enclosure of ``w0 * a + w1 * b`` (interval weights; non-negative weights are fast)."""
    (sl, sh), (tl, th) = w0, w1
    if sl >= 0 and tl >= 0:
        lo = down(down(np.minimum(sl * alo, sh * alo)) + down(np.minimum(tl * blo, th * blo)))
        hi = up(up(np.maximum(sl * ahi, sh * ahi)) + up(np.maximum(tl * bhi, th * bhi)))
        return lo, hi
    plo, phi = iv_mul(alo, ahi, sl, sh)
    qlo, qhi = iv_mul(blo, bhi, tl, th)
    return iv_add(plo, phi, qlo, qhi)


def split(lo: np.ndarray, hi: np.ndarray, t):
    """de Casteljau subdivision of interval coefficients at ``t`` (notes 2.3).

    ``t`` is a float or an interval ``(t_lo, t_hi)``; the result encloses the exact
    pieces on [0, t] and [t, 1] for every exact ``t`` in the interval.
    Returns ``((left_lo, left_hi), (right_lo, right_hi))``.
    """
    w0, w1 = _weights(t)
    n = lo.shape[0] - 1
    left_lo, left_hi = np.empty_like(lo), np.empty_like(hi)
    right_lo, right_hi = np.empty_like(lo), np.empty_like(hi)
    left_lo[0], left_hi[0] = lo[0], hi[0]
    right_lo[n], right_hi[n] = lo[n], hi[n]
    a_lo, a_hi = lo, hi
    for r in range(1, n + 1):
        a_lo, a_hi = _combine(a_lo[:-1], a_hi[:-1], a_lo[1:], a_hi[1:], w0, w1)
        left_lo[r], left_hi[r] = a_lo[0], a_hi[0]
        right_lo[n - r], right_hi[n - r] = a_lo[-1], a_hi[-1]
    return (left_lo, left_hi), (right_lo, right_hi)


def restrict(lo: np.ndarray, hi: np.ndarray, a, b):
    """Interval coefficients of ``p`` restricted to [a, b] and reparametrized to [0, 1].

    ``a``, ``b`` are floats or intervals with ``0 <= a < b <= 1``: split at ``a``, then
    the right piece at ``(b - a) / (1 - a)`` (an interval).  For ``[a, b]`` outside
    [0, 1] (extrapolation, used by the Krawczyk test near the ends) the same two
    splits are done with general interval weights.
    """
    al, ah = (a, a) if np.isscalar(a) else a
    bl, bh = (b, b) if np.isscalar(b) else b
    if al == 0 and ah == 0:
        right = (lo, hi)
    else:
        _, right = split(lo, hi, (al, ah))
    if bl == 1 and bh == 1:
        return right
    # u = (b - a) / (1 - a)
    nlo, nhi = iv_sub(np.float64(bl), np.float64(bh), np.float64(al), np.float64(ah))
    dlo, dhi = iv_sub(np.float64(1.0), np.float64(1.0), np.float64(al), np.float64(ah))
    ulo, uhi = iv_div(nlo, nhi, dlo, dhi)
    left, _ = split(right[0], right[1], (float(ulo), float(uhi)))
    return left


def hull(lo: np.ndarray, hi: np.ndarray):
    """Range enclosure of the polynomial over its whole domain (convex hull property)."""
    return lo.min(axis=0), hi.max(axis=0)


def evaluate(lo: np.ndarray, hi: np.ndarray, t):
    """Interval value at ``t`` (float or interval) by interval de Casteljau."""
    w0, w1 = _weights(t)
    a_lo, a_hi = lo, hi
    while a_lo.shape[0] > 1:
        a_lo, a_hi = _combine(a_lo[:-1], a_hi[:-1], a_lo[1:], a_hi[1:], w0, w1)
    return a_lo[0], a_hi[0]


def horner_bound(mid: np.ndarray, rad: np.ndarray, t: float):
    """Value and rigorous error bound of a Bernstein polynomial at a float ``t`` in [0, 1].

    Horner's rule in Bernstein form (notes 3.2): for ``t <= 1/2``,
    ``p(t) = (1-t)^n sum C(n,i) c_i s^i`` with ``s = t/(1-t)`` (mirror form above 1/2),
    run on the midpoints ``mid`` of interval coefficients of radius ``rad``.  The
    rounding error is at most ``gamma_{6n+8}`` times the same Horner sum of ``|c_i|``
    (Higham (5.3) with the perturbations of ``s``, the binomials and ``(1-t)^n``
    folded in); a generous ``(8n + 16) u`` is used, plus ``max rad``.
    O(n) per component instead of de Casteljau's O(n^2).

    Returns ``(value, bound)`` arrays over the trailing axes; the exact value lies in
    ``[value - bound, value + bound]``.
    """
    n = mid.shape[0] - 1
    if n == 0:
        return mid[0].copy(), np.asarray(rad[0], dtype=float) + _TINY
    binom = _binomials(n).reshape((n + 1,) + (1,) * (mid.ndim - 1))
    if t <= 0.5:
        s, scale, coeffs = t / (1.0 - t), (1.0 - t) ** n, (binom * mid)[::-1]
    else:
        s, scale, coeffs = (1.0 - t) / t, t**n, binom * mid
    value = coeffs[0].copy()
    absval = np.abs(coeffs[0])
    for k in range(1, n + 1):
        value = value * s + coeffs[k]
        absval = absval * s + np.abs(coeffs[k])
    value = value * scale
    absval = absval * scale
    bound = up(up((8 * n + 16) * U * absval) * (1 + 8 * U) + rad.max(axis=0) * (1 + 4 * U)) + _TINY
    return value, bound


_BINOMIALS: dict[int, np.ndarray] = {}


def _binomials(n: int) -> np.ndarray:
    if n not in _BINOMIALS:
        _BINOMIALS[n] = np.array([float(math.comb(n, i)) for i in range(n + 1)])
    return _BINOMIALS[n]


def midrad(lo: np.ndarray, hi: np.ndarray):
    """Midpoint and radius (rounded up) of interval arrays: ``[mid - rad, mid + rad] ⊇ [lo, hi]``."""
    mid = 0.5 * lo + 0.5 * hi
    rad = up(np.maximum(up(hi - mid), up(mid - lo)))
    return mid, rad

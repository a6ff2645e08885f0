"""Random exact inputs for reference records, and the hard cases kernels get wrong.

Every generator takes a :class:`random.Random` seeded from ``(kind, family, seed,
index)`` only (see :func:`record_rng`), so a record is a pure function of its
identity and the bytes of a suite never depend on the executor.

Hard families (the names used in record ids):

``random``
    small random rationals (denominators up to 16), the ordinary case.
``endpoints``
    parameters at 0 and 1, one ulp inside them (``2^-1074``, ``1 - 2^-53``) and
    rationals closer to the ends than any double (``1 - 2^-54``).
``weights_wide``
    rational objects whose weights are powers of ten spanning ``10^-8 .. 10^8``.
``extreme_coefficients``
    coordinates scaled by ``2^960`` (near overflow) or ``2^-1060`` (subnormal range).
``high_degree``
    degree 20 to 40.
``tangency`` / ``higher_contact``
    contact of order 2 (tangent) or 3-4 between two curves, or roots of
    multiplicity 2-4.
``clustered``
    two roots / intersections closer than ``2^-40``.
``shared_algebraic``
    two curves on one algebraic curve (a sub-arc, possibly reversed).
``nurbs``
    (compose only) a B-spline / NURBS surface instead of a Bézier patch: the image
    is cut where the domain curve crosses knot lines (algebraic parameters).

>>> rng = record_rng("roots", "random", 0, 0)
>>> isinstance(rational(rng), type(rational(rng)))
True
"""

from __future__ import annotations

import random

import numpy as np
from gmpy2 import mpq

from ..exact.bernstein import elevate, from_power
from ..geometry.bezier_curve import BezierCurve

__all__ = [
    "SCALE_EXPONENTS",
    "bezier_curve",
    "clamped_knots",
    "end_params",
    "points",
    "polynomial_with_roots",
    "rational",
    "record_rng",
    "weights",
]

#: Exponents of the scale factors of the ``extreme_coefficients`` family.
SCALE_EXPONENTS = (960, -1060)


def record_rng(kind: str, family: str, seed: int, index: int) -> random.Random:
    """The random source of one record (string seeds hash the same in every process)."""
    return random.Random(f"exactcagd-refdata:{kind}:{family}:{seed}:{index}")


def rational(rng: random.Random, lo: int = 0, hi: int = 1, den: int = 16) -> mpq:
    """A random rational in ``[lo, hi]`` with denominator at most ``den``."""
    d = rng.randint(1, den)
    return mpq(rng.randint(lo * d, hi * d), d)


def points(rng: random.Random, count: int, dim: int, lo: int = -2, hi: int = 2) -> list:
    """``count`` random points of dimension ``dim``."""
    return [[rational(rng, lo, hi) for _ in range(dim)] for _ in range(count)]


def weights(rng: random.Random, count: int, wide: bool = False) -> list:
    """Positive weights: ``[1, 3]`` with small denominators, or powers of ten in ``10^-8 .. 10^8``."""
    if wide:
        return [mpq(10) ** rng.randint(-8, 8) for _ in range(count)]
    return [rational(rng, 1, 3) for _ in range(count)]


def end_params(rng: random.Random, count: int) -> list:
    """Parameters at, one ulp inside, and closer than any double to the ends of [0, 1]."""
    special = [mpq(0), mpq(1), mpq(1, 2**1074), mpq(1, 2**53), 1 - mpq(1, 2**53), 1 - mpq(1, 2**54), mpq(1, 3 * 2**60)]
    return [special[rng.randrange(len(special))] for _ in range(count)]


def bezier_curve(rng: random.Random, degree: int, dim: int, rational_curve: bool, wide: bool = False, scale=None) -> BezierCurve:
    """A random Bézier curve (weights only when ``rational_curve`` or ``wide``)."""
    pts = points(rng, degree + 1, dim)
    if scale is not None:
        pts = [[x * scale for x in p] for p in pts]
    w = weights(rng, degree + 1, wide) if (rational_curve or wide) else None
    return BezierCurve(pts, w)


def clamped_knots(rng: random.Random, degree: int, n_points: int) -> list:
    """A clamped knot vector on [0, 1] for ``n_points`` control points.

    Interior knots are drawn from eighths (so they repeat, up to multiplicity ``degree``);
    a draw that would exceed the degree is replaced by a fresh odd multiple of 1/1024.
    """
    interior: list = []
    for _ in range(n_points - degree - 1):
        k = mpq(rng.randint(1, 7), 8)
        if interior.count(k) >= degree:
            k = mpq(2 * rng.randint(0, 511) + 1, 1024)
            while k in interior:
                k = mpq(2 * rng.randint(0, 511) + 1, 1024)
        interior.append(k)
    return [mpq(0)] * (degree + 1) + sorted(interior) + [mpq(1)] * (degree + 1)


def polynomial_with_roots(roots_with_mult: list, extra_degree: int, rng: random.Random) -> np.ndarray:
    """Bernstein coefficients on [0, 1] of ``prod (t - r)^m`` times a random factor of ``extra_degree``.

    The random factor has integer power coefficients in ``[-9, 9]``; its own roots are
    whatever they are (the answer isolates all roots exactly).
    """
    power = [mpq(rng.choice([-1, 1]) * rng.randint(1, 9))] + [mpq(rng.randint(-9, 9)) for _ in range(extra_degree)]
    if extra_degree:
        power[-1] = power[-1] or mpq(1)
    for r, m in roots_with_mult:
        for _ in range(m):
            power = [(power[k - 1] if k else 0) - r * (power[k] if k < len(power) else 0) for k in range(len(power) + 1)]
    coeffs = from_power(np.array(power, dtype=object))
    return coeffs


def elevated_to(c: np.ndarray, degree: int) -> np.ndarray:
    """Bernstein coefficients elevated to ``degree`` (no-op when already there)."""
    return c if c.shape[0] - 1 >= degree else elevate(c, degree - (c.shape[0] - 1))

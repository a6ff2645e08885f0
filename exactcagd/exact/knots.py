"""Exact B-spline algorithms on coefficient arrays (axis 0 = control-point index).

Knot vectors follow the standard convention: ``len(knots) = n_points + p + 1``,
clamped means the first and last knots have multiplicity ``p + 1``.  (Sederberg's
notes 6.2 drop the two outermost knots; :func:`from_notes_knots` converts.)

Sources: notes (003) 6.3 (Bézier extraction), 6.7 (knot insertion, Boehm),
6.8 (de Boor); Yang et al. (004) section 3 (NURBS -> rational Bézier patches).

>>> from exactcagd.exact.knots import check_knots
>>> check_knots([0, 0, 0, 1, 2, 2, 2], 4, 2)
(mpq(0,1), mpq(0,1), mpq(0,1), mpq(1,1), mpq(2,1), mpq(2,1), mpq(2,1))
"""

from __future__ import annotations

import bisect
import collections

import numpy as np

from .. import limits
from ..errors import DomainError, KnotError
from .scalars import to_count, to_rational

__all__ = [
    "check_knots",
    "from_notes_knots",
    "find_span",
    "de_boor",
    "insert_knot",
    "extract_bezier",
    "multiplicity",
    "domain",
    "blossom_de_boor",
    "span_index",
    "span_bezier",
]


def check_knots(knots, n_points: int, degree: int, clamped: bool = True, what: str = "knots") -> tuple:
    """Validate a knot vector; return it as a tuple of ``mpq``.

    Raises :class:`KnotError` for a wrong length, a decreasing vector, an empty
    domain, interior multiplicity above ``degree``, or (``clamped=True``) end
    multiplicities other than ``degree + 1``.  Every message starts with ``what``
    (e.g. ``"knots_v"``) and states the degree and point count it was checked for.
    """
    if degree < 0:
        raise KnotError(f"{what}: degree must be >= 0, got {degree}")
    limits.check("max_degree", degree, f"{what}: degree {degree}")
    if hasattr(knots, "__len__") and len(knots) != n_points + degree + 1:  # before converting them all
        raise KnotError(f"{what} ({len(knots)} knots, {n_points} control points, degree {degree}): "
                        f"{n_points} control points of degree {degree} need {n_points + degree + 1} knots")
    ks = tuple(to_rational(k, where=f"{what}[{i}]") for i, k in enumerate(knots))
    ctx = f"{what} ({len(ks)} knots, {n_points} control points, degree {degree})"
    expected = n_points + degree + 1
    if len(ks) != expected:
        raise KnotError(f"{ctx}: {n_points} control points of degree {degree} need {expected} knots")
    for i in range(len(ks) - 1):
        if ks[i] > ks[i + 1]:
            raise KnotError(f"{ctx}: the knot vector decreases at index {i}: {ks[i]} > {ks[i + 1]}")
    if ks[degree] == ks[-degree - 1]:
        raise KnotError(f"{ctx}: empty parameter domain [{ks[degree]}, {ks[-degree - 1]}]")
    if clamped:
        if len(set(ks[: degree + 1])) != 1 or len(set(ks[-degree - 1 :])) != 1:
            raise KnotError(f"{ctx}: not clamped: the first and last {degree + 1} knots must be equal")
        if ks[degree + 1] == ks[0] or ks[-degree - 2] == ks[-1]:
            raise KnotError(f"{ctx}: an end knot has multiplicity above degree + 1 = {degree + 1}")
    lo, hi = ks[degree], ks[-degree - 1]
    counts = collections.Counter(ks)  # one pass: the set-times-count loop was quadratic in the knot count
    for value, count in counts.items():
        # only knots inside the domain limit continuity; unclamped vectors may repeat an end
        if lo < value < hi and count > degree:
            raise KnotError(f"{ctx}: interior knot {value} has multiplicity {count} above the degree {degree}")
    return ks


def from_notes_knots(knots) -> tuple:
    """Convert a knot vector in the notes' convention (6.2) to the standard one.

    The notes list ``n + p - 1`` knots for ``n`` control points; the standard form
    repeats the first and last knot once more.
    """
    ks = tuple(to_rational(k) for k in knots)
    return (ks[0],) + ks + (ks[-1],)


def multiplicity(knots: tuple, value) -> int:
    """How many times ``value`` occurs in the (sorted) knot vector."""
    return bisect.bisect_right(knots, value) - bisect.bisect_left(knots, value)


def domain(knots: tuple, degree: int) -> tuple:
    """Parameter domain ``[knots[p], knots[-p-1]]``."""
    return knots[degree], knots[len(knots) - degree - 1]


def find_span(knots: tuple, degree: int, t) -> int:
    """Index ``k`` with ``knots[k] <= t < knots[k+1]`` inside the domain (the last
    non-empty span for the right end).  Raises :class:`DomainError` outside."""
    lo, hi = domain(knots, degree)
    if not (lo <= t <= hi):
        raise DomainError(f"parameter {t} outside the spline domain [{lo}, {hi}]")
    if t == hi:
        return bisect.bisect_left(knots, hi) - 1
    return bisect.bisect_right(knots, t) - 1


def de_boor(points: np.ndarray, knots: tuple, degree: int, t):
    """Evaluate the spline at ``t`` by de Boor's algorithm (notes 6.8), exactly."""
    t = to_rational(t, where="t")
    p = degree
    k = find_span(knots, p, t)
    d = [points[j + k - p].copy() if isinstance(points[j + k - p], np.ndarray) else points[j + k - p] for j in range(p + 1)]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = j + k - p
            denom = knots[i + p + 1 - r] - knots[i]
            alpha = (t - knots[i]) / denom
            d[j] = (1 - alpha) * d[j - 1] + alpha * d[j]
    return d[p]


def insert_knot(points: np.ndarray, knots: tuple, degree: int, t, times: int = 1) -> tuple[np.ndarray, tuple]:
    """Insert ``t`` ``times`` times by Boehm's algorithm (notes 6.7).

    Returns the new control array and knot vector; the spline is unchanged.
    Raises :class:`KnotError` if the multiplicity would exceed ``degree``
    (``degree + 1`` at the domain ends is already full), :class:`InputError` if
    ``times`` is not a non-negative integer (``times = 0`` returns the input).
    """
    times = to_count(times, where="knot insertion: times")
    t = to_rational(t, where="inserted knot")
    p = degree
    lo, hi = domain(knots, p)
    if not (lo < t < hi):
        raise DomainError(f"inserted knot {t} must lie inside the open domain ({lo}, {hi})")
    if multiplicity(knots, t) + times > p:
        raise KnotError(f"inserting {t} {times} time(s) would exceed multiplicity {p}")
    for _ in range(times):
        k = find_span(knots, p, t)
        new = [None] * (points.shape[0] + 1)
        for i in range(points.shape[0] + 1):
            if i <= k - p:
                new[i] = points[i]
            elif i >= k + 1:
                new[i] = points[i - 1]
            else:
                alpha = (t - knots[i]) / (knots[i + p] - knots[i])
                new[i] = (1 - alpha) * points[i - 1] + alpha * points[i]
        points = np.stack(new) if isinstance(new[0], np.ndarray) else np.array(new, dtype=object)
        knots = knots[: k + 1] + (t,) + knots[k + 1 :]
    return points, knots


def extract_bezier(points: np.ndarray, knots: tuple, degree: int) -> list[tuple[tuple, np.ndarray]]:
    """Bézier extraction (notes 6.3; Yang et al. section 3): raise every interior knot
    to multiplicity ``degree``; return ``[((a, b), bezier_coefficients), ...]`` for the
    non-empty knot spans in order.  Requires a clamped knot vector."""
    p = degree
    lo, hi = domain(knots, p)
    for value in sorted(set(k for k in knots if lo < k < hi)):
        need = p - multiplicity(knots, value)
        if need > 0:
            points, knots = insert_knot(points, knots, p, value, need)
    # after the insertions every non-empty span [knots[k], knots[k+1]] is a Bezier piece
    # whose coefficients are its local control points P_{k-p} .. P_k (degree 0 included)
    return [
        ((knots[k], knots[k + 1]), points[k - p : k + 1].copy())
        for k in range(p, len(knots) - p - 1)
        if knots[k] < knots[k + 1]
    ]


def blossom_de_boor(points: np.ndarray, knots: tuple, degree: int, k: int, args) -> object:
    """Polar form of the spline piece on knot span ``k`` at ``args`` (notes 6.1, 6.8).

    de Boor's algorithm with parameter ``args[r-1]`` at level ``r``; with all
    arguments equal to ``t`` it is ordinary de Boor evaluation.
    """
    p = degree
    d = [points[j + k - p] for j in range(p + 1)]
    for r in range(1, p + 1):
        u = args[r - 1]
        for j in range(p, r - 1, -1):
            i = j + k - p
            alpha = (u - knots[i]) / (knots[i + p + 1 - r] - knots[i])
            d[j] = (1 - alpha) * d[j - 1] + alpha * d[j]
    return d[p]


def span_index(knots: tuple, degree: int, piece: int) -> int:
    """Knot index ``k`` (``knots[k] < knots[k+1]``) of the ``piece``-th non-empty span."""
    lo, hi = domain(knots, degree)
    count = -1
    for k in range(degree, len(knots) - degree - 1):
        if knots[k] < knots[k + 1]:
            count += 1
            if count == piece:
                return k
    raise DomainError(f"the spline has no span number {piece}")


def span_bezier(points: np.ndarray, knots: tuple, degree: int, piece: int) -> tuple[tuple, np.ndarray]:
    """Bézier coefficients of one span, by blossoming: ``b_i = f(a^{p-i}, b^i)``.

    Touches only the ``p + 1`` control points of that span, so a caller that needs a
    few patches of a large spline never pays for the whole extraction.
    """
    k = span_index(knots, degree, piece)
    a, b = knots[k], knots[k + 1]
    coeffs = [blossom_de_boor(points, knots, degree, k, [a] * (degree - i) + [b] * i) for i in range(degree + 1)]
    return (a, b), np.stack(coeffs) if isinstance(coeffs[0], np.ndarray) else np.array(coeffs, dtype=object)

"""Intersections of two planar Bézier curves (polynomial or rational), certified.

Sources: Sederberg's notes (003), chapter 7: 7.5 Bézier subdivision
(:mod:`.subdivision`), 7.6 interval subdivision (:mod:`.interval_method`), 7.7 Bézier
clipping (:mod:`.clipping`); the exact route is implicitization + resultants (7.3,
chapter 17) in :mod:`.exact`.  Every route returns one result type
(:class:`~.result.IntersectionResult`: a list of :class:`~.result.Intersection` with
``overlaps``).

How the float methods stay right
--------------------------------
A region of parameter space is discarded only when a rigorous test proves it holds no
intersection; what is left is certified by the Krawczyk operator (:mod:`.certify`).
What float arithmetic cannot resolve -- a tangency (singular Jacobian), a cluster, a
shared curve, or a search that exceeds its work bound (``max_work`` steps) -- is handed
to the exact route (``fallback="exact"``, the default), which answers with exact
parameters, the exact multiplicity (a tangency of order k comes back as one point of
multiplicity k) and shared arcs as ``overlaps``.  ``fallback=None`` returns the
unresolved boxes instead (``certified=False``, ``kind="unresolved"``); they still hold
every intersection near them.

>>> from exactcagd import BezierCurve
>>> p = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> q = BezierCurve([[0, "1/2"], [2, "1/2"]])
>>> [round(x.t1, 9) for x in intersect(p, q)]
[0.146446609, 0.853553391]
>>> all(x.certified for x in intersect(p, q, method="clipping"))
True
"""

from __future__ import annotations

import numpy as np

from ...errors import InputError, LimitError
from ...exact.scalars import to_tolerance
from .certify import _certify, _endpoint_intersections
from .clipping import _clipping
from .curve_data import U, _Guard, _prepare
from .exact import Progress, exact_cost, intersect_exact, share_component
from .interval_method import _interval_method
from .result import KINDS, Intersection, IntersectionResult, Overlap
from .subdivision import _subdivision

__all__ = [
    "Intersection",
    "IntersectionResult",
    "Overlap",
    "KINDS",
    "intersect",
    "intersect_exact",
    "share_component",
    "exact_cost",
    "METHODS",
    "MAX_WORK",
    "default_work",
    "AUTO_EXACT_SECONDS",
    "Progress",
]

METHODS = ("subdivision", "interval", "clipping", "exact", "auto")
#: bounds of the float routes' default work bound (pairs of pieces examined); in between
#: it is ``WORK_PER_SECOND / n`` times the exact route's estimated cost (:func:`exact_cost`,
#: ``n`` the larger degree): one step costs about ``n / 4000`` s (measured: 0.5 ms at
#: degree 3-10, 2 ms for the interval method at degree 20), so a float route spends at
#: most about the exact route's time before handing over to it (random degree-10 pairs
#: need 20-700 steps, degree 15 up to 5000)
MIN_WORK, MAX_WORK, WORK_PER_SECOND = 200, 5_000, 4_000

#: ``method="auto"`` takes the exact route while its estimated cost is below this (seconds):
#: measured (benchmarks/results/bench_intersection.md) the exact route answers random
#: pairs up to degree ~12 and every hard fixture faster than clipping, clipping is
#: ahead from degree ~15 (degree 20: ~1 s against ~4-8 s)
AUTO_EXACT_SECONDS = 0.5


def default_work(n1: int, n2: int) -> int:
    """The float routes' work bound for curves of degrees ``n1, n2``.

    >>> default_work(3, 3), default_work(20, 20)
    (200, 1602)
    """
    n = max(n1, n2, 1)
    return int(min(MAX_WORK, max(MIN_WORK, WORK_PER_SECOND * exact_cost(n1, n2) / n)))


_ROUTES = {"subdivision": _subdivision, "interval": _interval_method, "clipping": _clipping}


def intersect(curve1, curve2, method: str = "subdivision", tol: float = 1e-12, *, fallback: str | None = "exact",
              max_work: int | None = None, progress=None, overlaps: str = "return") -> IntersectionResult:
    """All intersections of two planar Bézier curves (polynomial or rational) on [0, 1]^2.

    Parameters
    ----------
    curve1, curve2 : BezierCurve
        Planar (dimension 2), degree >= 1; rational curves need weights of one sign.
    method : {"subdivision", "interval", "clipping", "exact", "auto"}
        Bézier subdivision (notes 7.5), interval subdivision (7.6), Bézier clipping
        (7.7), the exact algebraic route (7.3 / 17: exact real algebraic parameters),
        or ``"auto"``: the fastest route that certifies every answer: the exact route
        while it is cheap (:data:`AUTO_EXACT_SECONDS`), else clipping with the exact
        route on what clipping cannot certify.
    tol : float
        Parameter tolerance of the float methods (stopping width); the reported
        enclosures are the proven ones, often tighter.
    fallback : {"exact", None}
        What happens to boxes a float route cannot certify (tangencies, clusters,
        shared curves, work bound reached): ``"exact"`` answers them by the exact route
        while that stays within :mod:`exactcagd.limits` (``max_implicit_degree``: beyond
        it the boxes come back uncertified, as with ``None``; raise the limit with
        ``limits.raised(...)`` to have them answered); ``None`` returns them uncertified.
    max_work : int or None
        Work bound of the float routes (pairs of pieces examined) before the fallback;
        ``None``: :func:`default_work` of the degrees (200-5000).
    progress : None, bool or callable
        Progress of the exact route (``True``: stderr; callable ``(stage, done, total)``).
    overlaps : {"return", "raise"}
        Shared arcs come back in ``result.overlaps``; ``"raise"`` raises
        :class:`~exactcagd.algebra.intersect.OverlapError` instead (points only).

    Returns
    -------
    IntersectionResult
        Sorted by ``t1``.  Every exact intersection lies in the box of some item
        (proven); ``overlaps`` lists the shared arcs with exact end parameters.

    Raises
    ------
    InputError, DimensionError, DegreeError, WeightError
        Bad curves or arguments.
    OverlapError
        ``overlaps="raise"`` and the curves share an arc.

    Examples
    --------
    >>> from exactcagd import BezierCurve
    >>> a = BezierCurve([[0, 0], [1, 1]])
    >>> b = BezierCurve([[0, 1], [1, 0]])
    >>> x = intersect(a, b, method="interval")[0]
    >>> x.certified, x.t1_interval[0] <= 0.5 <= x.t1_interval[1]
    (True, True)
    >>> r = intersect(BezierCurve([[0, 0], [1, 1]]), BezierCurve([["1/2", "1/2"], [2, 2]]))
    >>> [(str(o.t1_interval[0]), str(o.t1_interval[1])) for o in r.overlaps]
    [('1/2', '1')]
    """
    if method not in METHODS:
        raise InputError(f"unknown intersection method {method!r}; expected one of {METHODS}")
    if fallback not in ("exact", None):
        raise InputError(f"fallback must be 'exact' or None, got {fallback!r}")
    if overlaps not in ("return", "raise"):
        raise InputError(f"overlaps must be 'return' or 'raise', got {overlaps!r}")
    if max_work is not None and (isinstance(max_work, bool) or not isinstance(max_work, int) or max_work < 1):
        raise InputError(f"max_work must be a positive integer, got {max_work!r}")
    tol = to_tolerance(tol, "tol")
    c1, c2 = _prepare(curve1, curve2)
    if method == "auto" and exact_cost(curve1.degree, curve2.degree) <= AUTO_EXACT_SECONDS:
        method = "exact"
    if method == "exact":
        result = intersect_exact(curve1, curve2, progress)
    else:
        route = _ROUTES["clipping" if method == "auto" else method]
        if not (_finite(c1) and _finite(c2)):
            # weights or coordinates beyond the float range (weight 10^5000): no float
            # enclosure says anything there
            if fallback == "exact":
                result = intersect_exact(curve1, curve2, progress)
                if overlaps == "raise":
                    result.points()
                return result
        budget = _Guard(max_work or default_work(curve1.degree, curve2.degree))
        rects = route(c1, c2, max(tol, 64 * U), budget)
        result = None
        if budget.budget < 0 and fallback == "exact":
            result = _exact_within_limits(curve1, curve2, progress)
        if result is None:
            items = _certify(c1, c2, rects, max(tol, 64 * U), _endpoint_intersections(curve1, curve2))
            if fallback == "exact" and any(not x.certified for x in items):
                result = _exact_within_limits(curve1, curve2, progress)
            if result is None:
                result = IntersectionResult(items)
    if overlaps == "raise":
        result.points()
    return result


def _exact_within_limits(curve1, curve2, progress) -> IntersectionResult | None:
    """The exact route's answer, or ``None`` when it refuses by a limit of
    :mod:`exactcagd.limits` (checked from the degrees before its work): the float route's
    uncertified boxes then stand, as with ``fallback=None``."""
    try:
        return intersect_exact(curve1, curve2, progress)
    except LimitError:
        return None


def _finite(curve) -> bool:
    """The float enclosure of a curve is finite and its weights stay away from 0."""
    return bool(np.all(np.isfinite(curve.lo)) and np.all(np.isfinite(curve.hi)) and (not curve.rational or np.all(curve.lo[:, 2] > 0)))

"""The one result type of every intersection route: points, overlaps, and how sure we are.

Every route (:mod:`.subdivision`, :mod:`.interval_method`, :mod:`.clipping`,
:mod:`.exact`) returns an :class:`IntersectionResult`: a list of :class:`Intersection`
(one per intersection point, sorted by ``t1``) that also carries ``overlaps``, the
arcs the two curves share (:class:`Overlap`, exact end parameters).  Two curves on one
algebraic curve share an arc, or only finitely many points (end-point contacts,
self-crossings of the shared curve); both are answers, not errors (Sederberg's notes
003, 7.3: a vanishing resultant means a common component).  Asking for the points
alone (:meth:`IntersectionResult.points`) when there are infinitely many raises
:class:`~exactcagd.algebra.intersect.OverlapError`.

>>> r = IntersectionResult([], overlaps=[])
>>> r.points()
[]
"""

from __future__ import annotations

from dataclasses import dataclass

from gmpy2 import mpq

from ...algebra.intersect import Overlap  # one home: the exact shared-curve algebra

__all__ = ["Intersection", "IntersectionResult", "Overlap", "KINDS"]

#: What a returned point is: a proven simple crossing, a tangency (multiplicity >= 2),
#: a point where the curves lie on one algebraic curve (multiplicity undefined),
#: or a box the float route could not resolve (only when the exact fallback is off).
KINDS = ("transversal", "tangent", "shared", "unresolved")


@dataclass(frozen=True)
class Intersection:
    """One intersection (or one unresolved cluster) of two planar curves.

    Attributes
    ----------
    t1, t2 : float
        Parameter estimates on ``curve1`` and ``curve2``.
    t1_interval, t2_interval : (float, float)
        Enclosures: the exact intersection parameters lie inside (proven).
    point : (float, float)
        ``curve1(t1)`` in float.
    certified : bool
        The box holds exactly one intersection (proven; by a Krawczyk test for float
        routes, by exact algebra when ``exact`` is set).
    tangent : bool
        The point is (or, when not certified, may be) a tangency or a cluster.
    multiplicity : int or None
        Intersection multiplicity when known exactly: 1 for a transversal crossing,
        ``k >= 2`` for a tangency of order ``k`` (notes 7.3.1: the multiplicity of the
        root of the resultant); ``None`` when not known (unresolved, or ``kind =
        "shared"``, where the curves coincide as algebraic curves).
    exact : tuple or None
        ``(RealAlgebraic, RealAlgebraic)`` exact parameters, when known.
    kind : str
        One of :data:`KINDS`.
    """

    t1: float
    t2: float
    t1_interval: tuple[float, float]
    t2_interval: tuple[float, float]
    point: tuple[float, float]
    certified: bool
    tangent: bool = False
    multiplicity: int | None = None
    exact: tuple | None = None
    kind: str = "transversal"

    def contains(self, s, t) -> bool:
        """True when exact parameters ``(s, t)`` (rationals or RealAlgebraic) lie in the box."""
        (a, b), (c, d) = self.t1_interval, self.t2_interval
        return bool(mpq(a) <= s) and bool(s <= mpq(b)) and bool(mpq(c) <= t) and bool(t <= mpq(d))


class IntersectionResult(list):
    """List of :class:`Intersection` (sorted by ``t1``) with the shared arcs in ``overlaps``."""

    def __init__(self, items=(), overlaps=()):
        super().__init__(items)
        self.overlaps = list(overlaps)

    def points(self) -> list:
        """The intersection points; raises ``OverlapError`` when the curves share an arc."""
        if self.overlaps:
            from ...algebra.intersect import OverlapError

            arcs = ", ".join(f"t1 in [{a}, {b}]" for (a, b) in (o.t1_interval for o in self.overlaps))
            raise OverlapError(f"the curves share an arc ({arcs}): infinitely many intersection points")
        return list(self)

    def plot(self, ax=None, **style):
        """Draw the intersection points, numbered (matplotlib; see :func:`exactcagd.plotting.plot`)."""
        from ...plotting import plot

        return plot(self, ax=ax, **style)

    def __repr__(self) -> str:
        extra = f", overlaps={self.overlaps!r}" if self.overlaps else ""
        return f"IntersectionResult({list.__repr__(self)}{extra})"

"""FFD of a curve that leaves the deformation region: "points outside of the rectangle are
not moved" (Sederberg's notes (003) ch. 14, after (14.3)).

The curve is split, exactly, where it crosses the region's boundary lines (roots of
``X - x_min W`` etc. in local coordinates (14.1): real algebraic numbers, rational where
they are rational).  Stretches inside the region are images under the FFD -- sub-arcs of
the composition ``X(K(t))`` (Theorems 1, 2 of Lasser & Bonneau, with the map's polynomial
extension as the carrier) -- and stretches outside are the curve itself.

Whether the deformed and undeformed stretches meet at a crossing depends on the lattice
("continuity control" by freezing rows of control points, Figure 14.5); :attr:`PartialFFD.joints`
reports, exactly, whether each crossing is closed (G0): the minimal polynomial of the
crossing parameter divides the numerators of ``deformed - original``.

>>> from exactcagd import BezierCurve
>>> from exactcagd.composition.ffd import identity_lattice
>>> lattice = identity_lattice(2, 2)
>>> result = ffd_keep_outside(lattice, BezierCurve([["-1/2", "1/2"], ["3/2", "1/2"]]))
>>> [p.moved for p in result.pieces], [str(p.interval[0]) for p in result.pieces]
([False, True, False], ['0', '1/4', '3/4'])
>>> result.joints                     # the identity lattice: nothing tears
[True, True]
"""

from __future__ import annotations

from dataclasses import dataclass

from gmpy2 import mpq

from ..errors import InputError
from ..exact import bernstein as bz
import flint

from ..exact.algebraic import integer_poly
from ..exact.scalars import rational_str
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from .core import compose
from .splines import _line_roots, rational_between

__all__ = ["FFDPiece", "PartialFFD", "ffd_keep_outside"]


@dataclass
class FFDPiece:
    """A stretch ``interval`` (exact ends) of the input curve's parameter; ``curve`` is its
    carrier over the whole parameter range [0, 1]: the deformed composition when ``moved``,
    else the input curve."""

    curve: BezierCurve
    interval: tuple
    moved: bool

    def to_dict(self) -> dict:
        return {"curve": self.curve.to_dict(), "interval": [_exact_text(t) for t in self.interval], "moved": self.moved}


@dataclass
class PartialFFD:
    """Result of :func:`ffd_keep_outside`: ``pieces`` in parameter order and, for each
    crossing between a moved and an unmoved piece, whether the two meet (exact)."""

    pieces: list
    joints: list

    def evaluate(self, t) -> tuple:
        """Exact point at a rational parameter ``t`` in [0, 1]."""
        from ..exact.scalars import to_rational

        t = to_rational(t, where="t")
        for piece in self.pieces:
            lo, hi = piece.interval
            if not (t < lo) and not (hi < t):
                return piece.curve.evaluate(t)
        raise InputError(f"t = {t} is outside [0, 1]")

    def to_dict(self) -> dict:
        return {"pieces": [p.to_dict() for p in self.pieces], "joints_closed": list(self.joints)}


def _exact_text(t):
    return rational_str(t) if isinstance(t, type(mpq(0))) else t.to_dict()


def _crossings(local: BezierCurve) -> list:
    """Parameters in (0, 1) where the local curve meets ``u = 0, 1`` or ``v = 0, 1`` (sorted, distinct)."""
    hom = local.homogeneous()
    found = []
    for axis in (0, 1):
        for line in (mpq(0), mpq(1)):
            found += [r for r in _line_roots(hom, axis, line) if not any(r == f for f in found)]
    return sorted(found)


def _inside(local: BezierCurve, t: mpq) -> bool:
    u, v = local.evaluate(t)
    return 0 <= u <= 1 and 0 <= v <= 1


def _meets(deformed: BezierCurve, original: BezierCurve, t) -> bool:
    """Do the two curves pass through the same point at the exact parameter ``t``?"""
    if isinstance(t, type(mpq(0))):
        return tuple(deformed.evaluate(t)) == tuple(original.evaluate(t))
    a, b = deformed.homogeneous(), original.homogeneous()
    n = max(a.shape[0], b.shape[0]) - 1
    a, b = bz.elevate(a, n - a.shape[0] + 1), bz.elevate(b, n - b.shape[0] + 1)
    for k in range(a.shape[1] - 1):
        numerator = bz.to_power(bz.product(a[:, k], b[:, -1]) - bz.product(b[:, k], a[:, -1]))
        if all(c == 0 for c in numerator):
            continue  # the two curves agree identically in this coordinate
        poly = integer_poly(list(numerator))
        if flint.fmpq_poly(poly) % flint.fmpq_poly(t.poly) != 0:
            return False
    return True


def ffd_keep_outside(lattice: BezierSurface, curve: BezierCurve, region=None, **compose_options) -> PartialFFD:
    """FFD of a Bézier curve that may leave the region; outside stretches are not moved (ch. 14).

    Parameters
    ----------
    lattice, region
        As for :func:`exactcagd.composition.ffd` (the lattice must be planar: an
        undeformed stretch lives in the plane).
    curve : BezierCurve
        Planar, polynomial or rational.
    compose_options
        ``shortcut``, ``reduce``, ``method`` of :func:`exactcagd.composition.compose`.
    """
    from .ffd import to_local

    if lattice.dimension != 2:
        raise InputError("keeping outside points unmoved needs a planar lattice (dimension 2)")
    local = to_local(curve, region)
    cuts = [mpq(0)] + _crossings(local) + [mpq(1)]
    status = [_inside(local, rational_between(a, b)) for a, b in zip(cuts[:-1], cuts[1:])]
    deformed = compose(lattice, local, allow_outside=True, **compose_options) if any(status) else None
    pieces: list[FFDPiece] = []
    for (a, b), moved in zip(zip(cuts[:-1], cuts[1:]), status):
        if pieces and pieces[-1].moved == moved:  # merge stretches that only touch the boundary
            pieces[-1] = FFDPiece(pieces[-1].curve, (pieces[-1].interval[0], b), moved)
        else:
            pieces.append(FFDPiece(deformed if moved else curve, (a, b), moved))
    joints = [_meets(deformed, curve, right.interval[0]) for right in pieces[1:]]
    return PartialFFD(pieces, joints)


"""Free-form deformation of planar curves: Lasser & Bonneau (000) section VII, notes (003) ch. 14.

A 2-D FFD is a (rational) tensor-product Bézier map ``X(s, t) = sum B^l_i(s) B^m_j(t) P_ij``
(notes (14.2)) applied to the local coordinates ``s = (x - x_min)/(x_max - x_min)``,
``t = (y - y_min)/(y_max - y_min)`` of the deformation region (14.1).  A curve drawn in the
region is deformed *exactly* by composition (Theorems 1, 2): a Bézier curve of degree
``N`` becomes a curve of degree ``N (l + m)``; a horizontal/vertical line (isoparametric)
becomes a curve of degree ``l`` or ``m`` (Statement 1, notes 14.0.1); B-spline curves are
deformed piece by piece (:func:`exactcagd.composition.compose_spline`).

The region map (14.1) is affine, so it is applied exactly to the (homogeneous) control
points.  The notes' rule "points outside the region are not moved" is ``outside="keep"``
(:mod:`exactcagd.composition.ffd_partial`: exact split at the region boundary); by default
a curve that leaves the region raises :class:`~exactcagd.errors.DomainError`.

>>> from exactcagd import BezierCurve
>>> lattice = identity_lattice(2, 3)                       # (14.3): FFD = identity
>>> line = BezierCurve([["1/10", "1/5"], ["9/10", "7/10"]])
>>> ffd(lattice, line).reduce() == line
True
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..errors import DimensionError, DomainError, InputError, NotSupportedError
from ..exact.scalars import to_rational
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve
from .core import compose
from .splines import compose_spline

__all__ = ["ffd", "identity_lattice", "to_local"]


def identity_lattice(l: int, m: int, region=None, dimension: int = 2) -> BezierSurface:
    """The undisplaced lattice (14.3): ``P_ij = (x_min + i/l (x_max - x_min), y_min + j/m (...))``.

    With all weights 1 the FFD is the identity (linear precision of Bernstein polynomials).
    ``dimension=3`` appends ``z = 0`` (the paper's ``F_ij = (i/5, j/5, 0)``).
    """
    (x0, y0), (x1, y1) = _region(region)
    net = [[[x0 + mpq(i, l) * (x1 - x0) if l else x0, y0 + mpq(j, m) * (y1 - y0) if m else y0] + [mpq(0)] * (dimension - 2) for j in range(m + 1)] for i in range(l + 1)]
    return BezierSurface(net)


def _region(region):
    if region is None:
        return (mpq(0), mpq(0)), (mpq(1), mpq(1))
    (x0, y0), (x1, y1) = ((to_rational(a, where="region"), to_rational(b, where="region")) for a, b in region)
    if not (x0 < x1 and y0 < y1):
        raise DomainError(f"the deformation region needs x_min < x_max and y_min < y_max, got {region}")
    return (x0, y0), (x1, y1)


def to_local(curve, region=None):
    """The curve in the region's local coordinates (14.1) (exact affine map of the control points)."""
    (x0, y0), (x1, y1) = _region(region)
    if curve.dimension != 2:
        raise DimensionError(f"FFD deforms planar curves; got dimension {curve.dimension}")
    if (x0, y0, x1, y1) == (0, 0, 1, 1):
        return curve
    pts = curve.points_array()
    pts[:, 0] = (pts[:, 0] - x0) / (x1 - x0)
    pts[:, 1] = (pts[:, 1] - y0) / (y1 - y0)
    if isinstance(curve, BezierCurve):
        return BezierCurve._trusted(pts, None if not curve.is_rational else np.array(curve.weights, dtype=object))
    return BSplineCurve(pts, curve.knots, curve.weights)


def ffd(lattice: BezierSurface, shape, region=None, *, shortcut: bool = True, reduce: bool = False, method: str = "fast", outside: str = "raise"):
    """Deform planar curves exactly by the (rational) Bézier FFD ``lattice``.

    Parameters
    ----------
    lattice : BezierSurface
        The displaced control lattice (dimension 2, or 3 as in the paper's figure 9).
    shape : BezierCurve, BSplineCurve, or a list/tuple of them
        Planar curves inside ``region``.  A line segment is ``BezierCurve([p, q])``.
    region : ((x_min, y_min), (x_max, y_max)), optional
        The deformation region (default the unit square).
    shortcut, reduce, method
        As for :func:`exactcagd.composition.compose` (horizontal/vertical lines map to
        degree ``l`` / ``m`` with ``shortcut``).
    outside : {"raise", "keep"}
        A curve leaving the region: ``"raise"`` a ``DomainError`` (default), or ``"keep"``
        the notes' rule (ch. 14) -- outside points are not moved; a Bézier curve then gives a
        :class:`~exactcagd.composition.ffd_partial.PartialFFD` split exactly at the region
        boundary (:func:`~exactcagd.composition.ffd_partial.ffd_keep_outside`).

    Returns
    -------
    BezierCurve (for a Bézier curve), SplineComposition (for a B-spline), PartialFFD
    (``outside="keep"``), or a list of these.
    """
    if outside not in ("raise", "keep"):
        raise InputError(f"outside: expected 'raise' or 'keep', got {outside!r}")
    if not isinstance(lattice, BezierSurface):
        raise InputError(f"lattice: expected a BezierSurface, got {type(lattice).__name__}")
    if isinstance(shape, (list, tuple)):
        return [ffd(lattice, s, region, shortcut=shortcut, reduce=reduce, method=method, outside=outside) for s in shape]
    if not isinstance(shape, (BezierCurve, BSplineCurve)):
        raise InputError(f"shape: expected a BezierCurve or BSplineCurve, got {type(shape).__name__}")
    if outside == "keep":
        if not isinstance(shape, BezierCurve):
            raise NotSupportedError("outside='keep' takes Bézier curves; split a B-spline with .to_bezier() first")
        from .ffd_partial import ffd_keep_outside

        return ffd_keep_outside(lattice, shape, region, shortcut=shortcut, reduce=reduce, method=method)
    local = to_local(shape, region)
    if isinstance(local, BezierCurve):
        return compose(lattice, local, method, shortcut=shortcut, reduce=reduce)
    return compose_spline(lattice, local, method, shortcut=shortcut, reduce=reduce)

"""Input checks shared by the composition routes (one place for every message).

Both routes work on exact homogeneous arrays:

* the surface net ``H`` of shape ``(l + 1, m + 1, d + 1)`` holding ``(w_ij F_ij, w_ij)``
  (Lasser & Bonneau (000) eq. (4)); a polynomial surface has ``w_ij = 1``;
* the domain curve ``(X, Y, W)`` of shape ``(N + 1, 3)`` holding ``(beta_I u_I, beta_I v_I,
  beta_I)`` (eq. (3)); a polynomial curve has ``beta_I = 1``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import limits
from ..errors import DimensionError, InputError, NotSupportedError, WeightError
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from .domain import check_inside, check_weight_function

__all__ = ["Prepared", "prepare", "wrap_result"]


@dataclass
class Prepared:
    """Checked exact input of a composition."""

    net: np.ndarray  # homogeneous surface net (l+1, m+1, d+1)
    curve: np.ndarray  # homogeneous domain curve (N+1, 3)
    rational: bool  # is the result rational (either input rational)?
    check_result_weight: bool  # must the composed weight function be checked for zeros?
    degree: tuple  # (l, m, N)


def _check_types(surface, curve) -> None:
    if not isinstance(surface, BezierSurface):
        if type(surface).__name__ == "BSplineSurface":
            raise NotSupportedError("compose() takes one Bézier patch; use compose_spline() for B-spline/NURBS surfaces")
        raise InputError(f"surface: expected a BezierSurface, got {type(surface).__name__}")
    if not isinstance(curve, BezierCurve):
        if type(curve).__name__ == "BSplineCurve":
            raise NotSupportedError("compose() takes one Bézier domain curve; use compose_spline() for B-spline/NURBS curves")
        raise InputError(f"curve: expected a BezierCurve, got {type(curve).__name__}")
    if curve.dimension != 2:
        raise DimensionError(f"the domain curve must be planar (dimension 2, points (u, v)); got dimension {curve.dimension}")


def prepare(surface, curve, allow_outside: bool = False, box=((0, 1), (0, 1))) -> Prepared:
    """Validate ``surface`` and ``curve``; return their exact homogeneous arrays.

    Raises
    ------
    InputError, NotSupportedError
        Wrong object types.
    DimensionError
        The domain curve is not planar.
    WeightError
        The curve's weight function vanishes on [0, 1].
    DomainError
        The curve leaves ``box`` (default [0, 1]^2) and ``allow_outside`` is false.
    """
    _check_types(surface, curve)
    l, m = surface.degree
    limits.check("max_degree", curve.degree * (l + m), f"composition: degree N (l + m) of F(K(t)) for N = {curve.degree}, (l, m) = ({l}, {m})")
    hom = curve.homogeneous()
    if curve.is_rational and not all(w > 0 for w in hom[:, 2]):
        if check_weight_function(hom[:, 2], "weight function of the domain curve") < 0:
            hom = -hom
    if not allow_outside:
        check_inside(hom, box)
    net = surface.homogeneous()
    surface_positive = all(w > 0 for w in net[..., -1].reshape(-1))
    l, m = surface.degree
    return Prepared(
        net=net,
        curve=hom,
        rational=surface.is_rational or curve.is_rational,
        check_result_weight=surface.is_rational and (allow_outside or not surface_positive),
        degree=(l, m, curve.degree),
    )


def wrap_result(hom: np.ndarray, prep: Prepared, what: str = "composition") -> BezierCurve:
    """Exact homogeneous result -> :class:`BezierCurve` (polynomial when both inputs are).

    Raises :class:`WeightError` when the composed weight function has a zero on [0, 1]
    (the curve runs through a pole of the surface) or when one Bernstein weight of the
    result is exactly zero (a control point at infinity, which a BezierCurve cannot store;
    :func:`compose_homogeneous` returns the exact homogeneous coefficients instead).
    """
    if not prep.rational:
        return BezierCurve._trusted(hom[:, :-1].copy(), None)
    w = hom[:, -1]
    if prep.check_result_weight:
        if check_weight_function(w, f"weight function of the {what}") < 0:
            hom = -hom
            w = hom[:, -1]
    zeros = [r for r, x in enumerate(w) if x == 0]
    if zeros:
        raise WeightError(
            f"the exact {what} has Bernstein weight Omega_{zeros[0]} = 0 (a control point at infinity) although "
            "its weight function has no zero on [0, 1]; BezierCurve cannot store it. Use compose_homogeneous() "
            "for the exact homogeneous coefficients"
        )
    return BezierCurve.from_homogeneous(hom)

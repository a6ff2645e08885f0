"""``compose``: the exact Bézier representation of a trim curve ``F(K(t))``.

Source: Lasser & Bonneau (000), Theorems 1 (polynomial) and 2 (rational), Remark 3 (the
mixed cases), Statements 1, 2 and the strategy of sections IV and VI (isoparametric
curves).  Two routes compute the same exact coefficients:

* ``method="lasser"``: the printed formula, a sum of polar values times the constants
  (7)/(16) (:mod:`exactcagd.composition.lasser`; teaching and verification, slow);
* ``method="fast"`` (default): polynomial arithmetic on scaled Bernstein forms in
  python-flint (:mod:`exactcagd.composition.fast`).

>>> from exactcagd import BezierCurve, BezierSurface
>>> F = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])   # z = u v
>>> K = BezierCurve([[0, 1], [1, 0]])                                    # u + v = 1
>>> image = compose(F, K)
>>> image.degree, image.evaluate("1/2")
(2, (mpq(1,2), mpq(1,2), mpq(1,4)))
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from ..geometry.bezier_curve import BezierCurve
from ._inputs import prepare, wrap_result
from .fast import compose_homogeneous_fast
from .isoparametric import compose_isoparametric_homogeneous
from .lasser import compose_homogeneous_lasser

__all__ = ["compose", "compose_homogeneous", "compose_prepared"]

_METHODS = ("fast", "lasser")


def _route(method: str, net, curve, strategy: str, enumeration: str) -> np.ndarray:
    if method == "fast":
        return compose_homogeneous_fast(net, curve, strategy)
    if method == "lasser":
        return compose_homogeneous_lasser(net, curve, enumeration)
    raise InputError(f"unknown method {method!r}; expected one of {_METHODS}")


def compose_homogeneous(surface, curve, method: str = "fast", *, allow_outside: bool = False, strategy: str = "flint", enumeration: str = "multisets") -> np.ndarray:
    """Exact homogeneous Bernstein coefficients ``(Omega_R B_R, Omega_R)`` of ``F(K(t))``.

    Always of degree ``N (l + m)`` (no isoparametric shortcut, no reduction); the last
    column is the weight (all ones when both inputs are polynomial).  Use this when a
    Bernstein weight of the result is zero (which :class:`BezierCurve` cannot store).
    """
    prep = prepare(surface, curve, allow_outside)
    return _route(method, prep.net, prep.curve, strategy, enumeration)


def compose(surface, curve, method: str = "fast", *, reduce: bool = False, shortcut: bool = True, allow_outside: bool = False, strategy: str = "flint", enumeration: str = "multisets") -> BezierCurve:
    """Exact Bézier curve ``F(K(t))`` of a planar domain curve on a tensor-product surface.

    Parameters
    ----------
    surface : BezierSurface
        Degree ``(l, m)``, polynomial or rational, any dimension ``d``.
    curve : BezierCurve
        Planar (``dimension == 2``, points ``(u, v)``) of degree ``N``, polynomial or rational,
        lying in ``[0, 1]^2`` (checked exactly).
    method : {"fast", "lasser"}
        Route (b) (default) or route (a) (the paper's sum over multi-indices).
    reduce : bool
        Return the curve in its true (lowest) degree (exact degree reduction / gcd).
    shortcut : bool
        Isoparametric domain curves (``v`` or ``u`` constant) are composed as the iso-curve
        of degree ``l`` (or ``m``) with the 1-D reparametrization: degree ``l N`` (``m N``),
        sections IV and VI.  With ``shortcut=False`` the general formula is used (degree
        ``N (l + m)``, a degree-raised representation; Statements 1, 2).
    allow_outside : bool
        Compose even if ``K`` leaves ``[0, 1]^2`` (the surface's polynomial extension).
    strategy : {"flint", "bernstein"}
        Arithmetic of the fast route.
    enumeration : {"multisets", "ordered"}
        Summation of the lasser route.

    Returns
    -------
    BezierCurve
        Stored degree ``N (l + m)`` (``l N`` / ``m N`` for isoparametric curves with
        ``shortcut``), rational whenever an input is rational, exact control points and
        weights, dimension ``d``.

    Raises
    ------
    DimensionError
        ``curve`` is not planar.
    DomainError
        ``curve`` leaves ``[0, 1]^2`` and ``allow_outside`` is false.
    WeightError
        A weight function vanishes on [0, 1] (the curve's, or the composed one when the
        surface has non-positive weights), or a Bernstein weight of the result is 0.
    """
    if method not in _METHODS:
        raise InputError(f"unknown method {method!r}; expected one of {_METHODS}")
    prep = prepare(surface, curve, allow_outside)
    return compose_prepared(prep, method, shortcut=shortcut, reduce=reduce, strategy=strategy, enumeration=enumeration)


def compose_prepared(prep, method: str = "fast", *, shortcut: bool = True, reduce: bool = False, strategy: str = "flint", enumeration: str = "multisets") -> BezierCurve:
    """:func:`compose` on checked input (:func:`exactcagd.composition._inputs.prepare`)."""
    hom = None
    if shortcut:
        hom = compose_isoparametric_homogeneous(prep.net, prep.curve, method, strategy=strategy, enumeration=enumeration)
    if hom is None:
        hom = _route(method, prep.net, prep.curve, strategy, enumeration)
    result = wrap_result(hom, prep)
    return result.reduce() if reduce else result

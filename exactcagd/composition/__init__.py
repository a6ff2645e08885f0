"""Exact composition ``F(K(t))`` of planar domain curves with tensor-product surfaces.

Lasser & Bonneau, *Bézier Representation of Trim Curves* (000): Theorems 1, 2 (exact Bézier
form of trim curves), Statements 1, 2 (isoparametric curves), Remark 1 (splines),
section VII (free-form deformation), section VIII (cubic G1 approximation).

Public API
----------
compose(surface, curve, method="fast")          exact BezierCurve of F(K(t))
compose_homogeneous(surface, curve)            its exact homogeneous coefficients
compose_spline(surface, curve)                 B-spline/NURBS surfaces and curves (Remark 1)
crossed_patches(surface, curve)                patch indices a domain curve crosses
ffd(lattice, shape)                            free-form deformation of planar curves (VII)
approximate_cubic(surface, curve, tol)         G1 cubic spline with a certified distance (VIII)

>>> from exactcagd import BezierCurve, BezierSurface
>>> from exactcagd.composition import compose
>>> F = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
>>> compose(F, BezierCurve([[0, 0], [1, 1]])).degree
2
"""

from .core import compose, compose_homogeneous
from .cubic_approx import CubicApproximation, approximate_cubic
from .ffd import ffd
from .splines import SplineComposition, compose_spline, crossed_patches

__all__ = [
    "compose",
    "compose_homogeneous",
    "compose_spline",
    "crossed_patches",
    "SplineComposition",
    "ffd",
    "approximate_cubic",
    "CubicApproximation",
]

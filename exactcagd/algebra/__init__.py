"""Algebraic geometry for CAGD, exactly (Sederberg's notes, chapters 17-19).

Resultants and common roots (17.3-17.4), implicitization and inversion of
rational planar curves (17.5-17.7, 18.4), curve intersection (17.8, 7.3.1),
surfaces and base points (17.9-17.10), Gröbner bases (17.11), moving lines and
mu-bases (18), tangent moving lines and reciprocal curves (18.5), double points,
singular points, genus, discriminants and parametrization (19).

Public entry points (stable signatures)::

    resultant(f, g, var, method="flint")          # or "sylvester", "bezout": same value
    implicitize(curve, method="resultant")        # or "bezier", "moving_lines"
    inversion(curve)                              # t = f(x, y) / g(x, y)
    groebner(polys, gens, order="lex")            # or "grevlex", "grlex"
    intersect(curve1, curve2)                     # exact (t1, t2, multiplicity, point)

Derivation traces: :func:`trace_bezout` (Bezout matrix construction, 17.3-17.5) and
:func:`trace_zeroing` (moving-line zeroing process, (18.78)-(18.87)) print every
intermediate exact object.

Conventions
-----------
* Implicit equations are sympy ``Poly`` in ``x, y`` over ZZ, primitive, with positive
  leading coefficient in graded reverse lexicographic order (``x > y``).
* Irrational results are :class:`~exactcagd.exact.algebraic.RealAlgebraic`.
* Degenerate input: constant curve -> :class:`~exactcagd.errors.DegreeError`;
  common factor of ``X, Y, W`` -> :class:`BasePointWarning` (factor removed;
  ``strict=True``: :class:`BasePointError`);
  improper parametrization -> :class:`ImproperParametrizationWarning` from
  implicitization (``strict=True``: :class:`ImproperParametrizationError`) (the reduced equation is returned, the index is in
  :func:`implicit_equation`) and :class:`ImproperParametrizationError` from
  inversion / double points.

>>> from exactcagd import BezierCurve
>>> from exactcagd.algebra import implicitize, inversion
>>> c = BezierCurve([[1, 0], [5, 0], [5, 2], [4, 3]])
>>> implicitize(c).as_expr()
x**3 + 3*x**2*y - 3*x**2 + 3*x*y**2 - 30*x*y + 3*x + y**3 - 3*y**2 + 27*y - 1
>>> inversion(c)
2*y/(x + y - 1)
"""

from ._diagnostics import (
    AlgebraWarning,
    BasePointError,
    BasePointWarning,
    ImproperParametrizationError,
    ImproperParametrizationWarning,
)
from ._poly import curve_from_polynomials
from .double_points import DoublePoint, double_point_cubic, double_points, double_points_quartic
from .dual import (
    cusp_parameters,
    envelope,
    inflection_parameters,
    reciprocal,
    scaled_hodograph,
    tangent_control_lines,
    tangent_moving_line,
)
from .groebner import eliminate, groebner, groebner_basis, ideal_contains, ideals_equal, normal_form, quotient_dimension
from .implicitize import ImplicitEquation, implicit_equation, implicitize, l_matrix
from .intersect import CurveIntersection, OverlapError, implicit_intersections, intersect, intersection_polynomial
from .inversion import InversionFormula, inversion, inversion_bezier, inversion_cramer, inversion_linear_algebra, inversion_moving_line
from .moving_lines import MovingLine, axial_moving_line, moving_line_matrix, mu_basis, zeroing_process
from .parametrize import (
    circle_through_points,
    conic_through_points,
    parametrize_conic,
    parametrize_rational_cubic,
    parametrize_unicursal,
    undetermined_coefficients,
)
from .resultants import (
    bezout_matrix,
    bezout_matrix_bernstein,
    common_root_count,
    common_roots_linear,
    discriminant,
    euclid_steps,
    gcd_subresultant,
    resultant,
    sylvester_matrix,
)
from .singularities import SingularPoint, curve_discriminant, genus, line_section, singular_points
from .solve import common_points, solve_bivariate
from .surfaces import SurfaceParametrization, base_point_count, implicitize_surface
from .traces import trace_bezout, trace_zeroing

__all__ = [
    # stable entry points
    "resultant",
    "implicitize",
    "inversion",
    "groebner",
    "intersect",
    # resultants (17.3, 17.4, 19.4)
    "sylvester_matrix",
    "bezout_matrix",
    "bezout_matrix_bernstein",
    "discriminant",
    "common_roots_linear",
    "euclid_steps",
    "gcd_subresultant",
    "common_root_count",
    # implicitization / inversion (17.5-17.7)
    "implicit_equation",
    "ImplicitEquation",
    "l_matrix",
    "InversionFormula",
    "inversion_linear_algebra",
    "inversion_cramer",
    "inversion_bezier",
    "inversion_moving_line",
    "curve_from_polynomials",
    # intersection (17.8, 19.3)
    "CurveIntersection",
    "OverlapError",
    "intersection_polynomial",
    "implicit_intersections",
    "common_points",
    "solve_bivariate",
    # surfaces (17.9, 17.10)
    "SurfaceParametrization",
    "implicitize_surface",
    "base_point_count",
    # Gröbner bases (17.11)
    "groebner_basis",
    "normal_form",
    "ideal_contains",
    "ideals_equal",
    "eliminate",
    "quotient_dimension",
    # moving lines (18)
    "MovingLine",
    "moving_line_matrix",
    "zeroing_process",
    "mu_basis",
    "axial_moving_line",
    "tangent_moving_line",
    "tangent_control_lines",
    "envelope",
    "reciprocal",
    "scaled_hodograph",
    "cusp_parameters",
    "inflection_parameters",
    # chapter 19
    "DoublePoint",
    "double_points",
    "double_point_cubic",
    "double_points_quartic",
    "SingularPoint",
    "singular_points",
    "line_section",
    "genus",
    "curve_discriminant",
    "parametrize_unicursal",
    "parametrize_conic",
    "parametrize_rational_cubic",
    "undetermined_coefficients",
    "conic_through_points",
    "circle_through_points",
    # derivation traces (teaching mode, ``exactcagd verify --trace``)
    "trace_bezout",
    "trace_zeroing",
    # diagnostics
    "AlgebraWarning",
    "BasePointError",
    "BasePointWarning",
    "ImproperParametrizationWarning",
    "ImproperParametrizationError",
]

"""Chapter 5 of Sederberg's notes: properties of blending functions; Timmer's parametric
cubic, Ball's (rational) cubic and Overhauser (Catmull-Rom) curves, with exact conversion
to Bézier form.

Source: Sederberg, CAGD notes (003), chapter 5 (properties 1-6 and the example curve),
5.1 Timmer's PC, 5.2 Ball's cubic, 5.3 Overhauser curves.

Blending functions are sympy rational functions of one symbol; every property is decided
exactly (polynomial identities, exact real-root isolation for signs, rank over Q).  One
mechanism converts any polynomial basis to Bézier form: write each blending function in
the Bernstein basis (:func:`bernstein_matrix`); the Bézier control points are then
``M^T Q`` for the basis' control points ``Q``.

>>> from exactcagd.toolbox.blending import overhauser_to_bezier
>>> overhauser_to_bezier([[0, 0], [1, 0], [2, 1], [3, 1]]).control_points
((mpq(1,1), mpq(0,1)), (mpq(4,3), mpq(1,6)), (mpq(5,3), mpq(5,6)), (mpq(2,1), mpq(1,1)))
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy
from gmpy2 import mpq

from .. import limits
from ..errors import DegreeError, DimensionError, InputError
from ..exact import bernstein as bz
from ..exact.scalars import to_count, to_rational, to_rational_array
from ..geometry.bezier_curve import BezierCurve
from . import _exact as ex

__all__ = [
    "T",
    "BlendingReport",
    "check_properties",
    "partition_of_unity",
    "nonnegative",
    "symmetric",
    "linearly_independent",
    "endpoint_interpolation",
    "bernstein_basis",
    "timmer_basis",
    "ball_basis",
    "overhauser_basis",
    "hermite_basis",
    "bernstein_matrix",
    "basis_to_bezier",
    "timmer_to_bezier",
    "bezier_to_timmer",
    "ball_to_bezier",
    "overhauser_to_bezier",
    "overhauser_spline",
]

#: The parameter symbol used by the basis constructors.
T = sympy.Symbol("t")


def _rq(x):
    return sympy.Rational(int(x.numerator), int(x.denominator))


def _num_den(f, t):
    """Numerator and denominator of ``f`` as power-coefficient lists of mpq."""
    f = sympy.together(sympy.sympify(f))
    num, den = sympy.fraction(sympy.cancel(f))
    def coeffs(p):
        poly = sympy.Poly(p, t)
        if any(not c.is_Rational for c in poly.all_coeffs()):
            raise InputError(f"blending function {f} must have rational coefficients")
        return [to_rational(c) for c in reversed(poly.all_coeffs())]
    return coeffs(num), coeffs(den)


# ---------------------------------------------------------------- properties
def partition_of_unity(funcs, t=T) -> bool:
    """Property 1 (coordinate system independence): ``sum f_i == 1`` identically."""
    return sympy.cancel(sympy.together(sum(funcs) - 1)) == 0


def nonnegative(funcs, t=T, domain=(0, 1)) -> bool:
    """``f_i(t) >= 0`` on ``domain`` for every ``i`` (exact: signs between the real roots)."""
    lo, hi = (to_rational(x) for x in domain)
    for f in funcs:
        num, den = _num_den(f, t)
        if -1 in ex.sign_on_interval(num, den, lo, hi):
            return False
    return True


def symmetric(funcs, t=T, domain=(0, 1)) -> bool:
    """Property 3: ``f_i(t) = f_{n-i}(t0 + t1 - t)`` for all ``i`` (notes chapter 5).

    (The notes print ``t1 + t2 - t`` for the domain ``[t0, t1]``; the reflection of
    ``[t0, t1]`` is ``t0 + t1 - t``.)
    """
    lo, hi = (_rq(to_rational(x)) for x in domain)
    n = len(funcs) - 1
    return all(sympy.cancel(sympy.together(funcs[i] - funcs[n - i].subs(t, lo + hi - t))) == 0 for i in range(n + 1))


def linearly_independent(funcs, t=T) -> bool:
    """Property 5: no non-trivial ``sum c_i f_i == 0`` (rank over Q of the numerators over a common denominator)."""
    common = sympy.together(sum(sympy.Symbol(f"_c{i}") * f for i, f in enumerate(funcs)))
    _, den = sympy.fraction(common)
    rows = []
    for f in funcs:
        p = sympy.cancel(sympy.together(f * den))
        rows.append([to_rational(c) for c in reversed(sympy.Poly(p, t).all_coeffs())])
    width = max(len(r) for r in rows)
    rows = [r + [mpq(0)] * (width - len(r)) for r in rows]
    return ex.rank(rows) == len(funcs)


def endpoint_interpolation(funcs, t=T, domain=(0, 1)) -> bool:
    """Property 6: ``f_0(t0) = 1``, others 0; ``f_n(t1) = 1``, others 0."""
    lo, hi = (_rq(to_rational(x)) for x in domain)
    n = len(funcs) - 1
    start = [sympy.simplify(f.subs(t, lo)) for f in funcs]
    end = [sympy.simplify(f.subs(t, hi)) for f in funcs]
    return start == [1] + [0] * n and end == [0] * n + [1]


@dataclass
class BlendingReport:
    """Outcome of :func:`check_properties` (property numbers of the notes, chapter 5).

    ``variation_diminishing`` is always ``None``: the notes do not attempt it and no
    exact decision procedure is offered here.
    """

    partition_of_unity: bool
    convex_hull: bool
    symmetric: bool
    linearly_independent: bool
    endpoint_interpolation: bool
    variation_diminishing: None = None


def check_properties(funcs, t=T, domain=(0, 1)) -> BlendingReport:
    """All decidable properties of chapter 5 for a list of blending functions.

    Convex hull property = partition of unity and non-negativity on the domain (property 2).
    """
    funcs = [sympy.sympify(f) for f in funcs]
    if not funcs:
        raise InputError("no blending functions")
    pu = partition_of_unity(funcs, t)
    return BlendingReport(
        partition_of_unity=pu,
        convex_hull=pu and nonnegative(funcs, t, domain),
        symmetric=symmetric(funcs, t, domain),
        linearly_independent=linearly_independent(funcs, t),
        endpoint_interpolation=endpoint_interpolation(funcs, t, domain),
    )


# ---------------------------------------------------------------- named bases
def bernstein_basis(n: int, t=T) -> list:
    n = to_count(n, where="bernstein_basis: n")
    limits.check("max_degree", n, "bernstein_basis: n")
    return [sympy.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]


def timmer_basis(t=T) -> list:
    """Timmer's parametric cubic (notes 5.1): ``(1-2t)(1-t)^2, 4t(1-t)^2, 4t^2(1-t), (2t-1)t^2``."""
    return [(1 - 2 * t) * (1 - t) ** 2, 4 * t * (1 - t) ** 2, 4 * t**2 * (1 - t), (2 * t - 1) * t**2]


def ball_basis(t=T) -> list:
    """Ball's cubic (notes 5.2, non-rational case): ``(1-t)^2, 2t(1-t)^2, 2t^2(1-t), t^2``."""
    return [(1 - t) ** 2, 2 * t * (1 - t) ** 2, 2 * t**2 * (1 - t), t**2]


def overhauser_basis(t=T) -> list:
    """Overhauser / Catmull-Rom segment (notes 5.3)."""
    h = sympy.Rational(1, 2)
    return [-h * t + t**2 - h * t**3, 1 - 5 * h * t**2 + 3 * h * t**3, h * t + 2 * t**2 - 3 * h * t**3, -h * t**2 + h * t**3]


def hermite_basis(t=T) -> list:
    """Cubic Hermite functions for ``P(0), P(1), P'(0), P'(1)`` (notes 10.7)."""
    return [2 * t**3 - 3 * t**2 + 1, -2 * t**3 + 3 * t**2, t**3 - 2 * t**2 + t, t**3 - t**2]


# ---------------------------------------------------------------- conversion to Bézier form
def bernstein_matrix(funcs, degree: int | None = None, t=T) -> np.ndarray:
    """``M`` with ``f_i = sum_j M[i, j] B^n_j`` (exact; the functions must be polynomials)."""
    rows = []
    for f in funcs:
        poly = sympy.Poly(sympy.expand(f), t)
        if any(not c.is_Rational for c in poly.all_coeffs()):
            raise InputError(f"{f} is not a polynomial with rational coefficients")
        rows.append([to_rational(c) for c in reversed(poly.all_coeffs())])
    n = max(len(r) for r in rows) - 1 if degree is None else degree
    out = np.empty((len(funcs), n + 1), dtype=object)
    for i, r in enumerate(rows):
        if len(r) - 1 > n:
            raise DegreeError(f"blending function {funcs[i]} has degree {len(r) - 1} > {n}")
        out[i] = bz.from_power(np.array(r, dtype=object), n)
    return out


def basis_to_bezier(funcs, control_points, weights=None, degree: int | None = None) -> BezierCurve:
    """The Bézier form of ``sum f_i Q_i`` (or ``sum f_i w_i Q_i / sum f_i w_i``), exact."""
    Q = to_rational_array(control_points, where="control_points")
    if Q.ndim != 2 or Q.shape[0] != len(funcs):
        raise DimensionError(f"need {len(funcs)} control points (one per blending function)")
    M = bernstein_matrix(funcs, degree)
    if weights is None:
        return BezierCurve._trusted(M.T.dot(Q), None)
    w = to_rational_array(weights, where="weights")
    hom = np.concatenate([Q * w[:, None], w[:, None]], axis=1)
    return BezierCurve.from_homogeneous(M.T.dot(hom))


def timmer_to_bezier(control_points) -> BezierCurve:
    """Timmer PC -> cubic Bézier: ``P0 = Q0``, ``P1 = (4 Q1 - Q0)/3``, ``P2 = (4 Q2 - Q3)/3``, ``P3 = Q3``."""
    return basis_to_bezier(timmer_basis(), control_points)


def bezier_to_timmer(control_points) -> np.ndarray:
    """Cubic Bézier -> Timmer control points: ``Q1 = (P0 + 3 P1)/4``, ``Q2 = (P3 + 3 P2)/4`` (notes 5.1)."""
    M = bernstein_matrix(timmer_basis(), 3)
    P = to_rational_array(control_points, where="control_points")
    return ex.solve(M.T.tolist(), P.tolist(), "Timmer conversion")


def ball_to_bezier(control_points, weights=None) -> BezierCurve:
    """Ball's (rational) cubic -> cubic Bézier: ``P0, (P0 + 2 P1)/3, (2 P2 + P3)/3, P3`` in
    homogeneous form (so weights are carried: the rational Ball cubic)."""
    return basis_to_bezier(ball_basis(), control_points, weights, degree=3)


def overhauser_to_bezier(control_points) -> BezierCurve:
    """One Overhauser segment -> cubic Bézier: ``P1, P1 + (P2 - P0)/6, P2 - (P3 - P1)/6, P2``."""
    return basis_to_bezier(overhauser_basis(), control_points)


def overhauser_spline(points) -> list[BezierCurve]:
    """The Overhauser (Catmull-Rom) curve through ``points[1:-1]``: one cubic Bézier per
    consecutive four points (segment ``i`` interpolates ``points[i+1]``, ``points[i+2]``);
    consecutive segments are C^1 (tangent ``(P_{i+1} - P_{i-1})/2`` at every interior point)."""
    pts = to_rational_array(points, where="points")
    if pts.ndim != 2 or pts.shape[0] < 4:
        raise InputError("an Overhauser curve needs at least four points")
    return [overhauser_to_bezier(pts[i:i + 4]) for i in range(pts.shape[0] - 3)]

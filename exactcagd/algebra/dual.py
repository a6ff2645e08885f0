"""Tangent moving lines, envelopes, reciprocal curves and the scaled hodograph (notes 18.5).

For a curve ``P[t] = (X, Y, W)`` of degree ``m``:

* the tangent moving line ``Line(P x P')`` (18.88) has degree ``<= 2m - 2`` (the
  ``t^(2m-1)`` coefficient ``P_m x m P_m`` vanishes, (18.89)-(18.92)); each cusp
  (``P' ~ P``) is a base point, so after removing the gcd its degree is
  ``2m - 2 - kappa``;
* its control lines in Bernstein form are
  ``m [sum B_i^(m-1) P_i] x [sum B_i^(m-1) P_(i+1)]`` (18.95);
* the envelope of a moving line is ``Point(L x L')`` (18.96), and the reciprocal
  (dual) curve of ``P`` is ``Point(P x P')``; applying the construction twice gives
  back ``P`` up to the factor ``k2 = 1 / (k1^2 det(A, A', A''))`` (18.101)-(18.103);
* the scaled hodograph (18.104)-(18.108): with control lines ``(a_i, b_i, c_i)`` of the
  tangent moving line, the polynomial curve with control points ``(b_i, -a_i)``
  is parallel to ``P'``; for polynomial curves it is the (degree-elevated)
  hodograph itself.

>>> from exactcagd import BezierCurve
>>> cusp = BezierCurve([[0, 0], [1, 1], [0, 1], [1, 0]])
>>> tangent_moving_line(cusp).degree, [str(r) for r in cusp_parameters(cusp)]
(3, ['1/2'])
"""

from __future__ import annotations

import flint
import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError
from ..exact.algebraic import real_roots
from ._poly import curve_power
from .moving_lines import MovingLine, moving_line_following

__all__ = [
    "cross_polys",
    "tangent_moving_line",
    "tangent_control_lines",
    "envelope",
    "reciprocal",
    "scaled_hodograph",
    "cusp_parameters",
    "inflection_polynomial",
    "inflection_parameters",
]


def cross_polys(a, b) -> tuple:
    """Cross product (18.3) of triples of polynomials."""
    return (a[1] * b[2] - b[1] * a[2], b[0] * a[2] - a[0] * b[2], a[0] * b[1] - b[0] * a[1])


def _triple_to_line(tr) -> MovingLine:
    tr = [flint.fmpq_poly(list(p.coeffs())) if isinstance(p, flint.fmpz_poly) else p for p in tr]
    d = max(max(p.degree(), 0) for p in tr)
    coeffs = []
    for k in range(d + 1):
        coeffs.append(tuple(mpq(int(p[k].p), int(p[k].q)) if k <= p.degree() else mpq(0) for p in tr))
    return MovingLine(coeffs)


def _deriv(tr):
    return tuple(p.derivative() for p in tr)


def _gcd3(tr):
    g = flint.fmpz_poly([])
    for p in tr:
        if p != 0:
            g = p if g == 0 else g.gcd(p)
    return g


def tangent_moving_line(curve, reduce: bool = True) -> MovingLine:
    """``Line(P x P')`` (18.88) in power form; with ``reduce`` the gcd (cusps) divided out."""
    P = curve_power(curve)
    T = cross_polys(P, _deriv(P))
    if reduce:
        g = _gcd3(T)
        if g != 0 and g.degree() > 0:
            T = tuple(p // g for p in T)
    if all(p == 0 for p in T):
        raise DegreeError("the curve is a straight line or a point: its tangent line is constant")
    return _triple_to_line(T)


def tangent_control_lines(curve) -> list[tuple]:
    """Control lines of the tangent moving line of degree ``2m - 2`` by (18.95)."""
    hom = [tuple(r) for r in curve.homogeneous()]
    if curve.dimension != 2:
        raise DegreeError("tangent moving lines need a planar curve")
    m = len(hom) - 1
    if m < 1:
        raise DegreeError("a point has no tangent")
    lines = moving_line_following(hom[:-1], hom[1:])
    return [tuple(m * v for v in line) for line in lines]


def envelope(line: MovingLine) -> tuple:
    """``Point(L x L')`` (18.96): the envelope as homogeneous power-form polynomials
    ``(X, Y, W)`` (``fmpq_poly``)."""
    L = line.component_polys()
    return cross_polys(L, _deriv(L))


def reciprocal(curve) -> tuple:
    """The reciprocal (dual) curve ``Point(P x P')`` as homogeneous power-form
    polynomials (``fmpz_poly``), cusps (base points) removed (18.5.2)."""
    P = curve_power(curve)
    T = cross_polys(P, _deriv(P))
    g = _gcd3(T)
    if g != 0 and g.degree() > 0:
        T = tuple(p // g for p in T)
    return T


def scaled_hodograph(curve):
    """Polynomial curve of degree ``2m - 2`` parallel to ``P'`` (18.104)-(18.108)."""
    from ..geometry.bezier_curve import BezierCurve

    lines = tangent_control_lines(curve)
    pts = np.array([[line[1], -line[0]] for line in lines], dtype=object)
    return BezierCurve._trusted(pts, None)


def cusp_parameters(curve) -> list:
    """Real parameters of the cusps: real roots of ``gcd(P x P')`` (18.5.2)."""
    P = curve_power(curve)
    g = _gcd3(cross_polys(P, _deriv(P)))
    if g == 0 or g.degree() < 1:
        return []
    return [r for r, _ in real_roots([int(c) for c in g.coeffs()])]


def inflection_polynomial(curve) -> flint.fmpz_poly:
    """``det(P, P', P'')`` (degree ``<= 3m - 6``): zero at inflections (and doubly at cusps)."""
    P = curve_power(curve)
    d1 = _deriv(P)
    d2 = _deriv(d1)
    c = cross_polys(P, d1)
    return c[0] * d2[0] + c[1] * d2[1] + c[2] * d2[2]


def inflection_parameters(curve) -> list:
    """Real parameters of the inflection points: roots of ``det(P, P', P'')`` after the
    cusp factors (which divide it twice) are removed."""
    D = inflection_polynomial(curve)
    if D == 0:
        return []
    P = curve_power(curve)
    g = _gcd3(cross_polys(P, _deriv(P)))
    if g != 0 and g.degree() > 0:
        while D.degree() >= g.degree() and D % g == 0:
            D = D // g
    if D.degree() < 1:
        return []
    return [r for r, _ in real_roots([int(c) for c in D.coeffs()])]

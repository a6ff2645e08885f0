"""Curvature from control points, exact (Sederberg's notes (003) 15.9).

* curves: (15.44) ``k = (n-1)/n w0 w2 / w1^2 h / a^2`` at the start of a rational Bézier curve;
* tensor-product rational patches: Gaussian and mean curvature at a corner from the
  control net, (15.54)-(15.57);
* triangular rational patches: (15.59) and the reconstructed (15.60);
* implicit surfaces ``f = 0``: (15.61)-(15.62).

Gaussian curvature at a rational point of a rational surface is rational; the mean
curvature is ``X / sqrt(Y)`` with rational ``X, Y``.  Results therefore carry ``K``
exactly, ``H`` as its exact square plus sign, and offer ``H`` and the principal
curvatures as :class:`~exactcagd.exact.algebraic.RealAlgebraic` numbers.

Sign convention: ``H = (L G - 2 M F + N E) / (2 (E G - F^2))`` with ``L = r_uu . n`` and
``n = r_u x r_v / |r_u x r_v|`` (15.47)-(15.49).  The implicit formula (15.61) is the mean
curvature for the normal ``n = -grad f / |grad f|`` (a sphere ``|x|^2 - R^2`` gets
``H = +1/R``).

>>> from exactcagd import BezierSurface
>>> from exactcagd.toolbox.curvature import corner_curvature
>>> s = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])   # z = u v
>>> corner_curvature(s).gaussian
mpq(-1,1)
"""

from __future__ import annotations

import dataclasses

import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DimensionError, DomainError, InputError
from ..exact.algebraic import RealAlgebraic, real_roots
from ..exact.scalars import to_rational
from ..geometry._validate import instance_of
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from .surfaces import _oriented, _to_corner, cross, dot
from .triangular import TriangularBezier

__all__ = [
    "signed_sqrt",
    "CurveCurvature",
    "curve_start_curvature",
    "curve_curvature",
    "SurfaceCurvature",
    "corner_curvature",
    "surface_curvature",
    "triangular_corner_curvature",
    "implicit_curvature",
    "curvature_from_fundamental_forms",
]


def signed_sqrt(sign: int, square) -> RealAlgebraic:
    """The real number ``sign * sqrt(square)`` as a :class:`RealAlgebraic` (``square >= 0``)."""
    q = to_rational(square)
    if q < 0:
        raise DomainError("square of a real number cannot be negative")
    if q == 0 or sign == 0:
        return RealAlgebraic.from_rational(0)
    roots = [r for r, _ in real_roots([-q, 0, 1])]
    return roots[-1] if sign > 0 else roots[0]


# ---------------------------------------------------------------------------- curves (15.44)
@dataclasses.dataclass
class CurveCurvature:
    """Curvature ``k`` of a curve at a point: ``k^2`` exact; ``signed`` for planar curves."""

    squared: object
    sign: int

    @property
    def value(self) -> RealAlgebraic:
        """``k`` (signed for planar curves, ``>= 0`` otherwise) as an exact algebraic number."""
        return signed_sqrt(self.sign, self.squared)


def curve_start_curvature(curve: BezierCurve) -> CurveCurvature:
    """Curvature at ``t = 0`` from the control polygon, (15.44): ``k = (n-1)/n w0 w2/w1^2 h/a^2``.

    ``a = |P1 - P0|``, ``h`` the distance of ``P2`` from the line ``P0 P1``; so
    ``k^2 = ((n-1)/n w0 w2/w1^2)^2 |a x (P2 - P0)|^2 / |a|^6``.  In the plane the sign is that
    of ``a x (P2 - P0)`` (counter-clockwise turning positive).
    """
    n = curve.degree
    if n < 1:
        raise DegreeError("a point has no curvature")
    P, w = curve.points_array(), curve.weights_array()
    a = P[1] - P[0]
    aa = dot(a, a)
    if aa == 0:
        raise DomainError("P1 = P0: the curvature formula (15.44) needs a non-degenerate first leg")
    if n == 1:
        return CurveCurvature(mpq(0), 0)
    b = P[2] - P[0]
    factor = mpq(n - 1, n) * w[0] * w[2] / (w[1] * w[1])
    if curve.dimension == 2:
        c = a[0] * b[1] - a[1] * b[0]
        sq = factor * factor * c * c / (aa * aa * aa)
        s = (c > 0) - (c < 0)
        s = s if factor > 0 else -s
        return CurveCurvature(sq, s)
    if curve.dimension == 3:
        c = cross(a, b)
        cc = dot(c, c)
    else:  # |a|^2 |b|^2 - (a.b)^2 in any dimension
        cc = aa * dot(b, b) - dot(a, b) ** 2
    sq = factor * factor * cc / (aa * aa * aa)
    return CurveCurvature(sq, 1 if sq != 0 else 0)


def curve_curvature(curve: BezierCurve, t) -> CurveCurvature:
    """Curvature at any ``t`` in [0, 1]: subdivide so ``t`` is an end, then (15.44)."""
    instance_of(curve, BezierCurve, "curve_curvature: curve")
    t = to_rational(t, where="t")
    if not 0 <= t <= 1:
        raise DomainError("t outside [0, 1]")
    if t < 1:
        return curve_start_curvature(curve.reparametrize(t, 1))
    rev = curve_start_curvature(curve.reparametrize(1, 0))
    return CurveCurvature(rev.squared, -rev.sign if curve.dimension == 2 else rev.sign)


# ---------------------------------------------------------------------------- surfaces
@dataclasses.dataclass
class SurfaceCurvature:
    """Gaussian curvature (exact rational) and mean curvature (exact square and sign)."""

    gaussian: object
    mean_squared: object
    mean_sign: int

    @property
    def mean(self) -> RealAlgebraic:
        return signed_sqrt(self.mean_sign, self.mean_squared)

    def principal(self) -> tuple[RealAlgebraic, RealAlgebraic]:
        """Principal curvatures ``k_{1,2} = H -+ sqrt(H^2 - K)`` (Remark 3), increasing, exact.

        They are roots of ``(k^2 + K)^2 - 4 H^2 k^2`` (rational coefficients); the roots of
        ``k^2 - 2 H k + K`` are picked by the signs of ``H`` and ``K``.
        """
        K, H2, s = self.gaussian, self.mean_squared, self.mean_sign
        zero = RealAlgebraic.from_rational(0)
        if H2 - K < 0:  # pragma: no cover - impossible for real surfaces
            raise ArithmeticError("H^2 < K")
        if s == 0 and K == 0:
            return zero, zero
        roots = [r for r, _ in real_roots([K * K, 0, 2 * K - 4 * H2, 0, 1])]
        pos = sorted(r for r in roots if r > 0)
        neg = sorted(r for r in roots if r < 0)
        if s == 0:  # k = -+ sqrt(-K)
            return neg[0], pos[-1]
        if s > 0:
            big = pos[-1]  # H + sqrt(H^2 - K) > 0
            small = zero if K == 0 else (pos[0] if K > 0 else neg[-1])
            return small, big
        low = neg[0]  # H - sqrt(H^2 - K) < 0
        other = zero if K == 0 else (neg[-1] if K > 0 else pos[0])
        return low, other


def curvature_from_fundamental_forms(E, F, G, Ls, Ms, Ns, normal_sq) -> SurfaceCurvature:
    """``K``, ``H`` from ``E, F, G`` and the unnormalized ``Ls = r_uu . N`` etc. with ``|N|^2 = normal_sq``.

    ``K = (Ls Ns - Ms^2) / (|N|^2 (EG - F^2))``, ``H = (Ls G - 2 Ms F + Ns E) / (2 |N| (EG - F^2))``.
    """
    det = E * G - F * F
    if det == 0 or normal_sq == 0:
        raise DomainError("degenerate point: r_u and r_v are parallel")
    K = (Ls * Ns - Ms * Ms) / (normal_sq * det)
    X = Ls * G - 2 * Ms * F + Ns * E
    H2 = X * X / (4 * normal_sq * det * det)
    sign = (X > 0) - (X < 0)
    return SurfaceCurvature(K, H2, sign if det > 0 else -sign)


def corner_curvature(surface: BezierSurface, corner=(0, 0)) -> SurfaceCurvature:
    """Gaussian and mean curvature at a corner of a rational patch from its control net (15.54)-(15.55).

    With ``a = P10 - P00``, ``b = P01 - P00``, ``N = a x b`` and ``h_ij`` the signed distances
    ``(P_ij - P00) . N / |N|`` (15.50)::

        K = (w00/(w10 w01))^2 ((n-1)/n (m-1)/m w20 w02 h20 h02 - w11^2 h11^2) / |a x b|^2
        H = w00/(w10^2 w01^2) ((n-1)/n w01^2 |b|^2 w20 h20 - 2 w10 w01 (a.b) w11 h11
                               + (m-1)/m w10^2 |a|^2 w02 h02) / (2 |a x b|^2)

    (degrees ``n`` in u, ``m`` in v, as in (15.45)).  Other corners reflect the net; the
    sign of ``H`` refers to the normal ``r_u x r_v`` of the original parametrization.
    """
    if surface.dimension != 3:
        raise DimensionError("surface curvature needs a surface in 3-D")
    net, w, su, sv = _oriented(surface, corner)
    n, m = surface.degree
    if n < 1 or m < 1:
        raise DegreeError("a curve-like patch (degree 0 in one direction) has no surface curvature")
    P00 = net[0, 0]
    a, b = net[1, 0] - P00, net[0, 1] - P00
    N = cross(a, b)
    NN = dot(N, N)
    if NN == 0:
        raise DomainError("degenerate corner: P10 - P00 and P01 - P00 are parallel")
    H20 = dot(net[2, 0] - P00, N) if n >= 2 else mpq(0)  # = h20 |N|
    H02 = dot(net[0, 2] - P00, N) if m >= 2 else mpq(0)
    H11 = dot(net[1, 1] - P00, N)
    w00, w10, w01 = w[0, 0], w[1, 0], w[0, 1]
    w20 = w[2, 0] if n >= 2 else mpq(0)
    w02 = w[0, 2] if m >= 2 else mpq(0)
    w11 = w[1, 1]
    fn, fm = mpq(n - 1, n), mpq(m - 1, m)
    K = (w00 / (w10 * w01)) ** 2 * (fn * fm * w20 * w02 * H20 * H02 - w11 * w11 * H11 * H11) / (NN * NN)
    X = w00 / (w10 * w10 * w01 * w01) * (
        fn * w01 * w01 * dot(b, b) * w20 * H20 - 2 * w10 * w01 * dot(a, b) * w11 * H11 + fm * w10 * w10 * dot(a, a) * w02 * H02
    )
    # H = X / (2 |N|^2 |N|)  (the h's carry one factor 1/|N|)
    H2 = X * X / (4 * NN * NN * NN)
    sign = (X > 0) - (X < 0)
    orientation = su * sv  # reflecting one parameter flips r_u x r_v
    return SurfaceCurvature(K, H2, sign * orientation)


def surface_curvature(surface: BezierSurface, u, v) -> SurfaceCurvature:
    """Curvatures at any ``(u, v)``: subdivide the patch so the point is a corner (15.9.1 Remark 2)."""
    sub, hu, hv = _to_corner(surface, u, v)
    res = corner_curvature(sub)
    orient = (1 if hu > 0 else -1) * (1 if hv > 0 else -1)
    return SurfaceCurvature(res.gaussian, res.mean_squared, res.mean_sign * orient)


def triangular_corner_curvature(patch: TriangularBezier) -> SurfaceCurvature:
    """Curvatures at the corner ``(u, v) = (0, 0)`` (control point ``P_00n``) of a triangular patch.

    (15.59): ``K = ((n-1)/n)^2 (w00n/(w10 w01))^2 (w20 w02 h20 h02 - w11^2 h11^2) / |a x b|^2``;
    (15.60), reconstructed: ``H = (n-1)/n w00n/(w10^2 w01^2) (w01^2 |b|^2 w20 h20
    - 2 w10 w01 (a.b) w11 h11 + w10^2 |a|^2 w02 h02) / (2 |a x b|^2)``, with ``a = P_{10(n-1)} - P_{00n}``,
    ``b = P_{01(n-1)} - P_{00n}``, ``wij = w_{ij(n-i-j)}``.
    """
    if patch.dimension != 3:
        raise DimensionError("surface curvature needs a surface in 3-D")
    n = patch.degree
    if n < 1:
        raise DegreeError("degree 0 patch")
    P = lambda i, j: np.array(patch.point(i, j, n - i - j), dtype=object)  # noqa: E731
    W = lambda i, j: patch.weight(i, j, n - i - j)  # noqa: E731
    P00 = P(0, 0)
    a, b = P(1, 0) - P00, P(0, 1) - P00
    N = cross(a, b)
    NN = dot(N, N)
    if NN == 0:
        raise DomainError("degenerate corner")
    if n == 1:
        return SurfaceCurvature(mpq(0), mpq(0), 0)
    H20, H02, H11 = dot(P(2, 0) - P00, N), dot(P(0, 2) - P00, N), dot(P(1, 1) - P00, N)
    w00, w10, w01, w20, w02, w11 = W(0, 0), W(1, 0), W(0, 1), W(2, 0), W(0, 2), W(1, 1)
    f = mpq(n - 1, n)
    K = f * f * (w00 / (w10 * w01)) ** 2 * (w20 * w02 * H20 * H02 - w11 * w11 * H11 * H11) / (NN * NN)
    X = f * w00 / (w10 * w10 * w01 * w01) * (
        w01 * w01 * dot(b, b) * w20 * H20 - 2 * w10 * w01 * dot(a, b) * w11 * H11 + w10 * w10 * dot(a, a) * w02 * H02
    )
    H2 = X * X / (4 * NN * NN * NN)
    return SurfaceCurvature(K, H2, (X > 0) - (X < 0))


def implicit_curvature(gradient, hessian) -> SurfaceCurvature:
    """Curvatures of an implicit surface ``f = 0`` at a point from ``grad f`` and the Hessian (15.61)-(15.62).

    ``K = (grad f) adj(Hess f) (grad f)^T / |grad f|^4`` (the twelve terms of (15.62)) and
    ``H = (|grad f|^2 tr Hess f - grad f Hess f grad f^T) / (2 |grad f|^3)`` (15.61).
    ``gradient`` and ``hessian`` are exact numbers (3 and 3x3); see
    :func:`implicit_derivatives` for a sympy polynomial.
    """
    g = [to_rational(x, where="gradient") for x in gradient]
    Hm = [[to_rational(x, where="hessian") for x in row] for row in hessian]
    if len(g) != 3 or len(Hm) != 3 or any(len(r) != 3 for r in Hm):
        raise InputError("need a 3-vector gradient and a 3x3 Hessian")
    fx, fy, fz = g
    (fxx, fxy, fxz), (_, fyy, fyz), (_, _, fzz) = Hm
    if Hm[1][0] != fxy or Hm[2][0] != fxz or Hm[2][1] != fyz:
        raise InputError("the Hessian must be symmetric")
    lam2 = fx * fx + fy * fy + fz * fz
    if lam2 == 0:
        raise DomainError("singular point: grad f = 0")
    K = (
        -2 * fx * fy * fxy * fzz + fyy * fxx * fz**2 - 2 * fy * fz * fyz * fxx + fzz * fyy * fx**2
        - 2 * fz * fx * fxz * fyy + fxx * fzz * fy**2 - fx**2 * fyz**2 - fy**2 * fxz**2 - fz**2 * fxy**2
        + 2 * fx * fy * fxz * fyz + 2 * fy * fz * fxy * fxz + 2 * fx * fz * fxy * fyz
    ) / (lam2 * lam2)
    X = (
        fzz * (fy**2 + fx**2) - 2 * fx * fy * fxy + fxx * (fy**2 + fz**2) - 2 * fy * fz * fyz
        + fyy * (fx**2 + fz**2) - 2 * fz * fx * fxz
    )
    H2 = X * X / (4 * lam2**3)
    return SurfaceCurvature(K, H2, (X > 0) - (X < 0))


def implicit_derivatives(f, point, symbols=None) -> tuple[list, list]:
    """Exact gradient and Hessian of a sympy polynomial ``f(x, y, z)`` at a rational point."""
    import sympy

    x, y, z = symbols if symbols is not None else sympy.symbols("x y z")
    pt = [sympy.Rational(str(to_rational(c))) for c in point]
    sub = dict(zip((x, y, z), pt))
    if sympy.simplify(f.subs(sub)) != 0:
        raise DomainError("the point does not lie on f = 0")
    vars_ = (x, y, z)
    grad = [to_rational(sympy.diff(f, s).subs(sub)) for s in vars_]
    hess = [[to_rational(sympy.diff(f, s, t).subs(sub)) for t in vars_] for s in vars_]
    return grad, hess


__all__.append("implicit_derivatives")

"""Tensor-product surfaces beyond the foundation (Sederberg's notes (003) ch. 15, 16), exact.

* :func:`corner_derivatives`, :func:`tangents_at`, :func:`normal_at` -- 15.3: first and
  second partial derivatives at a corner of a rational patch straight from the
  control net, and at any point by subdividing it to a corner;
* :func:`curve_second_derivative_bound`, :func:`surface_second_derivative_bounds`,
  :func:`curve_sampling_number`, :func:`surface_sampling_numbers`,
  :func:`chord_bound_holds` -- 15.4: tessellation with the flatness bounds of
  second differences, exact (squared norms) and with certified ceilings;
* :func:`patch_continuity_order`, :func:`control_curve_continuity_order` -- 15.5: the
  exact order ``C^r`` across a common boundary of two patches;
* :func:`horner_curve_point_tangent`, :func:`horner_surface_point_tangents` -- 15.8 and
  chapter 16: point and tangents from the four sub-nets ``P^{kl}`` by Horner's rule
  in the pseudo-basis ``u = s / (1 - s)``.

Norms of vectors with rational entries are irrational; bounds are therefore returned
squared (exact rationals), and every decision taken from them (a ceiling, a
comparison with the tolerance) is made with certified rational interval bounds.

>>> from exactcagd import BezierSurface
>>> from exactcagd.toolbox.surfaces import corner_derivatives
>>> s = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
>>> corner_derivatives(s)["Puv"]
(mpq(0,1), mpq(0,1), mpq(1,1))
"""

from __future__ import annotations

import dataclasses
from math import comb

import gmpy2
import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DimensionError, DomainError, InputError
from ..exact import bernstein as bz
from ..exact.scalars import to_rational
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface

__all__ = [
    "corner_derivatives",
    "tangents_at",
    "normal_at",
    "cross",
    "dot",
    "curve_second_derivative_bound",
    "surface_second_derivative_bounds",
    "curve_sampling_number",
    "surface_sampling_numbers",
    "SurfaceSampling",
    "chord_bound_holds",
    "patch_continuity_order",
    "control_curve_continuity_order",
    "horner_curve_point_tangent",
    "horner_surface_point_tangents",
    "sub_nets",
    "sqrt_bounds",
    "certified_ceil",
]


def dot(a, b):
    return sum((x * y for x, y in zip(a, b)), start=mpq(0))


def cross(a, b) -> tuple:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


# ---------------------------------------------------------------------------- 15.3 tangents and normals
def _oriented(surface: BezierSurface, corner) -> tuple[np.ndarray, np.ndarray, int, int]:
    cu, cv = corner
    if (cu, cv) not in ((0, 0), (1, 0), (0, 1), (1, 1)):
        raise InputError(f"corner must be one of (0,0), (1,0), (0,1), (1,1); got {corner!r}")
    net, w = surface.net_array(), surface.weights_array()
    su, sv = (-1 if cu else 1), (-1 if cv else 1)
    return net[::su, ::sv], w[::su, ::sv], su, sv


def corner_derivatives(surface: BezierSurface, corner=(0, 0), u_range=(0, 1), v_range=(0, 1)) -> dict:
    """Exact point and partial derivatives up to order 2 at a corner (notes 15.3).

    For a rational patch of degree ``(m, n)`` over ``[s0, s1] x [t0, t1]``, at ``(s0, t0)``::

        P_s  = m/(s1-s0) w10/w00 (P10 - P00)
        P_ss = (m(m-1) w20/w00 (P20 - P00) - 2m w10/w00 (m w10 - w00)/w00 (P10 - P00)) / (s1-s0)^2
        P_st = m n / (w00^2 (s1-s0)(t1-t0)) (w00 w11 ^P11 - w10 w01 ^P10 - w10 w01 ^P01)

    (``^Pij = Pij - P00``; the notes print ``n`` for the s-degree in ``P_ss``: see the
    ledger), and symmetrically in ``t``.  Other corners reflect the net; the results are
    derivatives with respect to the patch's own parameters ``(u, v)``.

    Returns ``{"P", "Pu", "Pv", "Puu", "Puv", "Pvv"}`` (tuples of ``mpq``).
    """
    net, w, su, sv = _oriented(surface, corner)
    m, n = surface.degree
    (u0, u1), (v0, v1) = [(to_rational(a), to_rational(b)) for a, b in (u_range, v_range)]
    hu, hv = u1 - u0, v1 - v0
    if hu == 0 or hv == 0:
        raise DomainError("degenerate parameter ranges")
    P00, w00 = net[0, 0], w[0, 0]
    zero = P00 * 0

    def first(k, idx, h):
        if k == 0:
            return zero
        return (net[idx] - P00) * (k * w[idx] / w00 / h)

    def second(k, i1, i2, h):
        if k < 2:
            part = zero
        else:
            part = (net[i2] - P00) * (k * (k - 1) * w[i2] / w00)
        if k >= 1:
            part = part - (net[i1] - P00) * (2 * k * w[i1] / w00 * (k * w[i1] - w00) / w00)
        return part / (h * h)

    Pu = first(m, (1, 0), hu) if m else zero
    Pv = first(n, (0, 1), hv) if n else zero
    Puu = second(m, (1, 0), (2, 0), hu) if m else zero
    Pvv = second(n, (0, 1), (0, 2), hv) if n else zero
    if m and n:
        Puv = (
            (net[1, 1] - P00) * (w00 * w[1, 1]) - (net[1, 0] - P00) * (w[1, 0] * w[0, 1]) - (net[0, 1] - P00) * (w[1, 0] * w[0, 1])
        ) * (mpq(m * n) / (w00 * w00 * hu * hv))
    else:
        Puv = zero
    return {
        "P": tuple(P00),
        "Pu": tuple(Pu * su),
        "Pv": tuple(Pv * sv),
        "Puu": tuple(Puu),
        "Puv": tuple(Puv * (su * sv)),
        "Pvv": tuple(Pvv),
    }


def _to_corner(surface: BezierSurface, u, v) -> tuple[BezierSurface, mpq, mpq]:
    """The patch reparametrized so that ``(u, v)`` is its corner (0, 0): returns it and the scales."""
    u, v = to_rational(u, where="u"), to_rational(v, where="v")
    if not (0 <= u <= 1 and 0 <= v <= 1):
        raise DomainError(f"({u}, {v}) outside the unit square")
    bu = 1 if u < 1 else 0
    bv = 1 if v < 1 else 0
    return surface.reparametrize((u, bu), (v, bv)), mpq(bu) - u, mpq(bv) - v


def tangents_at(surface: BezierSurface, u, v) -> tuple[tuple, tuple]:
    """Exact ``(F_u, F_v)`` at any ``(u, v)``: subdivide to a corner, then (15.3)."""
    sub, hu, hv = _to_corner(surface, u, v)
    d = corner_derivatives(sub)
    return tuple(x / hu for x in d["Pu"]), tuple(x / hv for x in d["Pv"])


def normal_at(surface: BezierSurface, u, v) -> tuple:
    """Exact (unnormalized) normal ``F_u x F_v`` at ``(u, v)`` (notes 15.3); zero at a degenerate point."""
    if surface.dimension != 3:
        raise DimensionError("normals need a surface in 3-D")
    fu, fv = tangents_at(surface, u, v)
    return cross(fu, fv)


# ---------------------------------------------------------------------------- 15.4 tessellation
def sqrt_bounds(q, bits: int = 64) -> tuple[mpq, mpq]:
    """Rational ``lo <= sqrt(q) <= hi`` with ``hi - lo <= 2^-bits`` (relative to 1), exact isqrt."""
    q = to_rational(q)
    if q < 0:
        raise DomainError("square root of a negative number")
    scale = gmpy2.mpz(2) ** bits
    num = q.numerator * q.denominator * scale * scale
    r = gmpy2.isqrt(num)
    lo = mpq(r, q.denominator * scale)
    hi = lo if r * r == num else mpq(r + 1, q.denominator * scale)
    return lo, hi


class _Pos:
    """Interval ``[lo, hi]`` of non-negative rationals for monotone certified arithmetic."""

    __slots__ = ("lo", "hi")

    def __init__(self, lo, hi=None):
        self.lo, self.hi = mpq(lo), mpq(lo if hi is None else hi)

    def __add__(self, o):
        o = o if isinstance(o, _Pos) else _Pos(o)
        return _Pos(self.lo + o.lo, self.hi + o.hi)

    __radd__ = __add__

    def __mul__(self, o):
        o = o if isinstance(o, _Pos) else _Pos(o)
        return _Pos(self.lo * o.lo, self.hi * o.hi)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = o if isinstance(o, _Pos) else _Pos(o)
        if o.lo <= 0:
            raise ZeroDivisionError("interval divisor touches zero")
        return _Pos(self.lo / o.hi, self.hi / o.lo)

    def sqrt(self, bits):
        return _Pos(sqrt_bounds(self.lo, bits)[0], sqrt_bounds(self.hi, bits)[1])


def certified_ceil(expression, sympy_expr=None) -> int:
    """``ceil(x)`` for ``x = expression(bits)`` given as a monotone interval evaluator.

    ``expression(bits)`` returns a :class:`_Pos` enclosure that tightens as ``bits`` grows.
    When the enclosure keeps straddling an integer (``x`` is an integer), the optional
    ``sympy_expr`` decides exactly.
    """
    for bits in (64, 128, 256, 512, 1024):
        box = expression(bits)
        lo_c = int(gmpy2.ceil(box.lo))
        hi_c = int(gmpy2.ceil(box.hi))
        if lo_c == hi_c and box.lo != lo_c:
            return lo_c
        if lo_c == hi_c and box.lo == box.hi:
            return lo_c
    if sympy_expr is not None:
        import sympy

        return int(sympy.ceiling(sympy_expr))
    raise ArithmeticError("could not certify the ceiling (value is an integer?)")


def _max_sq_norm(vectors) -> mpq:
    return max((dot(v, v) for v in vectors), default=mpq(0))


def curve_second_derivative_bound(curve: BezierCurve) -> mpq:
    """Square of the bound ``n (n-1) max ||P_{i+2} - 2 P_{i+1} + P_i||`` on ``max ||r''||`` (15.4.1).

    Polynomial curves only (notes 15.4, Remark 2).
    """
    if curve.is_rational:
        raise DegreeError("the second-difference bound holds for polynomial curves (notes 15.4 Remark 2)")
    p = curve.points_array()
    n = curve.degree
    if n < 2:
        return mpq(0)
    diffs = [p[i + 2] - 2 * p[i + 1] + p[i] for i in range(n - 1)]
    return (n * (n - 1)) ** 2 * _max_sq_norm(diffs)


def surface_second_derivative_bounds(surface: BezierSurface) -> tuple[mpq, mpq, mpq]:
    """Squares ``(M1^2, M2^2, M3^2)`` of the bounds (15.6) on ``||r_ss||, ||r_st||, ||r_tt||``.

    Axis 0 of the net is ``s`` (degree ``m``), axis 1 is ``t`` (degree ``n``).
    """
    if surface.is_rational:
        raise DegreeError("the second-difference bounds (15.6) are for polynomial patches")
    P = surface.net_array()
    m, n = surface.degree
    ss = [P[i + 2, j] - 2 * P[i + 1, j] + P[i, j] for i in range(m - 1) for j in range(n + 1)]
    st = [P[i + 1, j + 1] - P[i + 1, j] - P[i, j + 1] + P[i, j] for i in range(m) for j in range(n)]
    tt = [P[i, j + 2] - 2 * P[i, j + 1] + P[i, j] for i in range(m + 1) for j in range(n - 1)]
    return (
        (m * (m - 1)) ** 2 * _max_sq_norm(ss),
        (m * n) ** 2 * _max_sq_norm(st),
        (n * (n - 1)) ** 2 * _max_sq_norm(tt),
    )


def curve_sampling_number(curve: BezierCurve, eps) -> int:
    """``n_t = ceil(1 / delta)`` with ``delta = sqrt(8 eps / M)`` (15.4.1; 1 when ``M = 0``)."""
    eps = to_rational(eps, where="eps")
    if eps <= 0:
        raise DomainError("tolerance must be positive")
    M2 = curve_second_derivative_bound(curve)
    if M2 == 0:
        return 1
    # 1/delta = sqrt(M / (8 eps)) = (M^2)^(1/4) / sqrt(8 eps)
    def box(bits):
        return (_Pos(M2).sqrt(bits) / (8 * eps)).sqrt(bits)

    return max(1, certified_ceil(box))


@dataclasses.dataclass
class SurfaceSampling:
    """Result of :func:`surface_sampling_numbers` (notes 15.4.2)."""

    n_s: int
    n_t: int
    case: int
    M_squared: tuple
    #: exact check that (1/8)(M1 ds^2 + 2 M2 ds dt + M3 dt^2) <= eps for ds = 1/n_s, dt = 1/n_t
    bound_holds: bool


def surface_sampling_numbers(surface: BezierSurface, eps, k=None) -> SurfaceSampling:
    """Sampling numbers ``(n_s, n_t)`` of notes 15.4.2 for a polynomial patch.

    Case 1 (``M1 = 0``): ``delta_s = 1``, ``delta_t = (sqrt(M2^2 + 8 M3 eps) - M2) / M3``;
    Case 2 (``M3 = 0``): symmetric; Case 3: ``delta_s = k delta_t``,
    ``delta_t = sqrt(8 eps / (M1 k^2 + 2 M2 k + M3))`` with default ``k = sqrt(M3 / M1)``.
    (When also the other bound vanishes, the inequality is linear: ``delta = 4 eps / M2``.)
    All ceilings are certified; ``bound_holds`` re-checks the final sampling exactly.
    """
    eps = to_rational(eps, where="eps")
    if eps <= 0:
        raise DomainError("tolerance must be positive")
    R1, R2, R3 = surface_second_derivative_bounds(surface)
    M = lambda R, bits: _Pos(R).sqrt(bits)  # noqa: E731
    one = lambda bits: _Pos(1)  # noqa: E731
    if R1 == 0 and R3 == 0:
        case = 0
        inv_s = one
        inv_t = one if R2 == 0 else (lambda bits: M(R2, bits) / (4 * eps))
    elif R1 == 0:
        case = 1
        inv_s = one

        def inv_t(bits):  # 1/delta_t = M3 / (sqrt(M2^2 + 8 M3 eps) - M2) = (sqrt(M2^2 + 8 M3 eps) + M2) / (8 eps)
            m2, m3 = M(R2, bits), M(R3, bits)
            return ((m2 * m2 + 8 * eps * m3).sqrt(bits) + m2) / (8 * eps)

    elif R3 == 0:
        case = 2
        inv_t = one

        def inv_s(bits):
            m2, m1 = M(R2, bits), M(R1, bits)
            return ((m2 * m2 + 8 * eps * m1).sqrt(bits) + m2) / (8 * eps)

    else:
        case = 3
        kk = None if k is None else to_rational(k, where="k")
        if kk is not None and kk <= 0:
            raise DomainError("k must be positive")

        def kbox(bits):
            return _Pos(kk) if kk is not None else (M(R3, bits) / M(R1, bits)).sqrt(bits)

        def inv_t(bits):  # 1/delta_t = sqrt((M1 k^2 + 2 M2 k + M3) / (8 eps))
            kb = kbox(bits)
            return ((M(R1, bits) * kb * kb + 2 * M(R2, bits) * kb + M(R3, bits)) / (8 * eps)).sqrt(bits)

        def inv_s(bits):  # delta_s = k delta_t
            return inv_t(bits) / kbox(bits)

    n_s = max(1, certified_ceil(inv_s))
    n_t = max(1, certified_ceil(inv_t))
    holds = _bound_holds(R1, R2, R3, mpq(1, n_s), mpq(1, n_t), eps)
    return SurfaceSampling(n_s, n_t, case, (R1, R2, R3), holds)


def _bound_holds(R1, R2, R3, ds, dt, eps) -> bool:
    """Certified ``M1 ds^2 + 2 M2 ds dt + M3 dt^2 <= 8 eps`` (``M_i = sqrt(R_i)``)."""
    for bits in (64, 128, 256, 512):
        lo = sum((sqrt_bounds(R, bits)[0] * c for R, c in ((R1, ds * ds), (R2, 2 * ds * dt), (R3, dt * dt))), start=mpq(0))
        hi = sum((sqrt_bounds(R, bits)[1] * c for R, c in ((R1, ds * ds), (R2, 2 * ds * dt), (R3, dt * dt))), start=mpq(0))
        if hi <= 8 * eps:
            return True
        if lo > 8 * eps:
            return False
    import sympy

    expr = sum(sympy.sqrt(sympy.Rational(str(R))) * sympy.Rational(str(c)) for R, c in ((R1, ds * ds), (R2, 2 * ds * dt), (R3, dt * dt)))
    return bool(expr <= 8 * sympy.Rational(str(eps)))


def _nonnegative_on_unit(power) -> bool:
    """Exact test ``g(t) >= 0`` on [0, 1] for a polynomial with rational power coefficients.

    The sign just right of 0 is the sign of the lowest non-zero coefficient; it flips at
    every root of odd multiplicity in (0, 1) (roots by exact factorization and isolation).
    """
    from ..exact.algebraic import real_roots

    nonzero = [c for c in power if c != 0]
    if not nonzero:
        return True
    sign = 1 if nonzero[0] > 0 else -1
    if sign < 0:
        return False
    for root, mult in real_roots(list(power), 0, 1):
        if root > 0 and root < 1 and mult % 2 == 1:
            sign = -sign
            if sign < 0:
                return False
    return True


def chord_bound_holds(curve: BezierCurve, a=0, b=1) -> bool:
    """Exact check of the chord bound of 15.4.1 on ``[a, b]``.

    ``max ||r(t) - L(t)|| <= (1/8) M (b - a)^2`` with ``L`` the chord from ``r(a)`` to ``r(b)``
    (same parametrization) and ``M`` the second-difference bound of the whole curve:
    decided as ``(M (b-a)^2 / 8)^2 - ||r - L||^2 >= 0`` on the interval, exactly.
    """
    if curve.is_rational:
        raise DegreeError("polynomial curves only")
    a, b = to_rational(a), to_rational(b)
    if not 0 <= a < b <= 1:
        raise DomainError("need 0 <= a < b <= 1")
    piece = bz.restrict(curve.points_array(), a, b)
    n = piece.shape[0] - 1
    line = np.stack([piece[0] * (1 - mpq(i, n)) + piece[-1] * mpq(i, n) for i in range(n + 1)]) if n else piece
    diff = piece - line
    sq = None
    for k in range(diff.shape[1]):
        term = bz.product(diff[:, k : k + 1], diff[:, k : k + 1])
        sq = term if sq is None else sq + term
    power = list(bz.to_power(sq[:, 0]))
    bound_sq = curve_second_derivative_bound(curve) * (b - a) ** 4 / 64
    power[0] = bound_sq - power[0]
    power = [power[0]] + [-c for c in power[1:]]
    return _nonnegative_on_unit(power)


# ---------------------------------------------------------------------------- 15.5 C^n patches
def _cross_boundary_power(hom: np.ndarray, axis: int, at_end: bool, h) -> np.ndarray:
    """Power coefficients in ``y`` (global distance from the junction) along ``axis``."""
    lo, hi = (1, 1 + 1 / h) if at_end else (0, 1 / h)
    return bz.along(axis, bz.restrict, hom, lo, hi)


def patch_continuity_order(first: BezierSurface, second: BezierSurface, direction: str = "u", h_first=1, h_second=1, max_order=None) -> int:
    """Exact order ``r`` of ``C^r`` continuity of two patches across a common boundary (notes 15.5).

    ``direction="u"``: ``first`` at ``u = 1`` meets ``second`` at ``u = 0`` (parameter spans
    ``h_first``, ``h_second`` in ``u``); ``"v"`` likewise.  With ``y`` the global parameter
    across the boundary, ``F1 = N1/W1`` and ``F2 = N2/W2`` agree to order ``r`` along the whole
    boundary iff ``N1 W2 - N2 W1`` vanishes to order ``r + 1`` in ``y`` identically in the
    other parameter.  Returns ``-1`` when the boundaries differ.
    """
    if direction not in ("u", "v"):
        raise InputError("direction must be 'u' or 'v'")
    if first.dimension != second.dimension:
        raise DimensionError("patches of different dimension")
    axis = 0 if direction == "u" else 1
    other = 1 - axis
    h1, h2 = to_rational(h_first, where="h_first"), to_rational(h_second, where="h_second")
    if h1 <= 0 or h2 <= 0:
        raise DomainError("spans must be positive")
    A, B = first.homogeneous(), second.homogeneous()
    dA, dB = first.degree[other], second.degree[other]
    top = max(dA, dB)
    A = bz.along(other, bz.elevate, A, top - dA)
    B = bz.along(other, bz.elevate, B, top - dB)
    a = bz.along(axis, bz.to_power, _cross_boundary_power(A, axis, True, h1))
    b = bz.along(axis, bz.to_power, _cross_boundary_power(B, axis, False, h2))
    a, b = np.moveaxis(a, axis, 0), np.moveaxis(b, axis, 0)  # (power in y, Bernstein in other, coords)
    limit = max(first.degree[axis], second.degree[axis]) if max_order is None else int(max_order)
    for k in range(limit + 1):
        acc = None
        for i in range(k + 1):
            if i >= a.shape[0] or k - i >= b.shape[0]:
                continue
            na, wa = a[i][:, :-1], a[i][:, -1:]
            nb, wb = b[k - i][:, :-1], b[k - i][:, -1:]
            term = bz.product(na, wb) - bz.product(nb, wa)
            acc = term if acc is None else acc + term
        if acc is not None and np.any(acc != 0):
            return k - 1
    return limit


def control_curve_continuity_order(first: BezierSurface, second: BezierSurface, direction: str = "u", h_first=1, h_second=1) -> int:
    """The notes' criterion (15.5): the minimum continuity order over pairs of adjacent control curves.

    For polynomial patches this equals :func:`patch_continuity_order`; for rational
    patches it is computed on the homogeneous control curves (a sufficient condition).
    """
    from .bspline_extras import continuity_order

    axis = 0 if direction == "u" else 1
    A, B = np.moveaxis(first.homogeneous(), axis, 0), np.moveaxis(second.homogeneous(), axis, 0)
    if A.shape[1] != B.shape[1]:
        raise DegreeError("control-curve criterion needs equal degrees along the boundary")
    rational = first.is_rational or second.is_rational
    orders = []
    for j in range(A.shape[1]):
        ca = BezierCurve._trusted(A[:, j] if rational else A[:, j, :-1], None)
        cb = BezierCurve._trusted(B[:, j] if rational else B[:, j, :-1], None)
        orders.append(continuity_order(ca, cb, h_first, h_second))
    return min(orders)


# ---------------------------------------------------------------------------- 15.8 / 16 points and tangents
def _pseudo_horner(coeffs, x):
    """``sum_i coeffs[i] x^i`` by nested multiplication (15.31)."""
    acc = coeffs[-1]
    for c in coeffs[-2::-1]:
        acc = acc * x + c
    return acc


def _proj(P):
    return tuple(c / P[-1] for c in P[:-1])


def horner_curve_point_tangent(curve: BezierCurve, t) -> dict:
    """Point and tangent of a rational Bézier curve by the Q/R construction (15.24)-(15.33).

    ``P(t) = (1 - t) Q(t) + t R(t)``; ``Q`` and ``R`` are evaluated in the pseudo-basis
    ``u = t/(1-t)`` (``t <= 1/2``) or ``u = (1-t)/t`` (``t > 1/2``) with binomially scaled
    coefficients ``^Q_i = C(n-1, i) P_i`` and nested multiplication; ``Pi(^Q) = Pi(Q)``.

    Returns ``{"point", "q", "r", "derivative"}`` where ``r - q`` is parallel to the
    tangent and ``derivative = n R_w Q_w / P_w^2 (r - q)`` (15.29), all exact.
    """
    t = to_rational(t, where="t")
    if not 0 <= t <= 1:
        raise DomainError("t outside [0, 1]")
    H = curve.homogeneous()
    n = curve.degree
    if n < 1:
        raise DegreeError("a degree-0 curve has no tangent")
    Qc = [H[i] * comb(n - 1, i) for i in range(n)]
    Rc = [H[i + 1] * comb(n - 1, i) for i in range(n)]
    if t <= mpq(1, 2):
        u, scale = t / (1 - t), (1 - t) ** (n - 1)
        Qh, Rh = _pseudo_horner(Qc, u), _pseudo_horner(Rc, u)
    else:
        u, scale = (1 - t) / t, t ** (n - 1)
        Qh, Rh = _pseudo_horner(Qc[::-1], u), _pseudo_horner(Rc[::-1], u)
    Q, R = Qh * scale, Rh * scale  # the true Q(t), R(t) (only needed for the magnitude)
    q, r = _proj(Qh), _proj(Rh)
    Pw = (1 - t) * Q[-1] + t * R[-1]
    point = _proj((1 - t) * Q + t * R)
    factor = n * R[-1] * Q[-1] / (Pw * Pw)
    return {"point": point, "q": q, "r": r, "derivative": tuple(factor * (b - a) for a, b in zip(q, r))}


def sub_nets(surface: BezierSurface) -> dict:
    """The four homogeneous sub-nets ``P^{kl}`` of (15.37)-(15.40): ``P^{kl}_{ij} = P_{i+k, j+l}``."""
    H = surface.homogeneous()
    m, n = surface.degree
    return {(k, l): H[k : k + m, l : l + n] for k in (0, 1) for l in (0, 1)}


def _horner_2d(net: np.ndarray, u, v, m: int, n: int):
    """``sum_ij C(m-1,i) C(n-1,j) P^{kl}_ij u^i v^j`` by nested multiplication, rows in ``u`` then ``v``.

    This is ``P^{kl}(s,t) / ((1-s)^{m-1} (1-t)^{n-1})`` with the exponents counted from the
    sub-net's own first index; the notes' (15.43) counts them from ``k`` and ``l``, which
    multiplies the sum by ``u^k v^l`` (see the ledger).
    """
    rows = []
    for j in range(n):
        coeffs = [net[i, j] * (comb(m - 1, i) * comb(n - 1, j)) for i in range(m)]
        rows.append(_pseudo_horner(coeffs, u))
    return _pseudo_horner(rows, v)


def horner_surface_point_tangents(surface: BezierSurface, s, t) -> dict:
    """Point and tangent directions of a rational patch from the four sub-nets (15.34)-(15.43).

    ``P = (1-s)(1-t) P^00 + s(1-t) P^10 + (1-s) t P^01 + s t P^11``; ``p_s`` is parallel to
    ``Pi(B) - Pi(A)`` with ``A = (1-t) P^00 + t P^01``, ``B = (1-t) P^10 + t P^11`` (15.41), and
    ``p_t`` to ``Pi(D) - Pi(C)``, ``C = (1-s) P^00 + s P^10``, ``D = (1-s) P^01 + s P^11`` (15.42).
    Each ``P^{kl}`` is evaluated by Horner's rule in ``u = s/(1-s)``, ``v = t/(1-t)`` (the net is
    mirrored for parameters beyond 1/2, as (15.33) does for curves).

    Returns ``{"point", "dir_s", "dir_t", "Ps", "Pt"}``; ``dir_*`` are the printed tangent lines
    ``Pi(B) - Pi(A)`` and ``Pi(D) - Pi(C)``, ``Ps = m A_w B_w / P_w^2 (Pi(B) - Pi(A))`` and
    ``Pt = n C_w D_w / P_w^2 (Pi(D) - Pi(C))`` the exact partial derivatives (the surface
    analogue of (15.29)).
    """
    s, t = to_rational(s, where="s"), to_rational(t, where="t")
    if not (0 <= s <= 1 and 0 <= t <= 1):
        raise DomainError("(s, t) outside the unit square")
    m, n = surface.degree
    if m < 1 or n < 1:
        raise DegreeError("need degree >= 1 in both directions")
    H = surface.homogeneous()
    flip_s, flip_t = s > mpq(1, 2), t > mpq(1, 2)
    if flip_s:
        H = H[::-1]
    if flip_t:
        H = H[:, ::-1]
    ss, tt = (1 - s if flip_s else s), (1 - t if flip_t else t)
    u, v = ss / (1 - ss), tt / (1 - tt)
    c = {(k, l): _horner_2d(H[k : k + m, l : l + n], u, v, m, n) for k in (0, 1) for l in (0, 1)}
    base = (1 - ss) ** (m - 1) * (1 - tt) ** (n - 1)
    A = (c[(0, 0)] + v * c[(0, 1)]) * (base * (1 - tt))
    B = (c[(1, 0)] + v * c[(1, 1)]) * (base * (1 - tt))
    C = (c[(0, 0)] + u * c[(1, 0)]) * (base * (1 - ss))
    D = (c[(0, 1)] + u * c[(1, 1)]) * (base * (1 - ss))
    P = (1 - ss) * A + ss * B
    Pw = P[-1]
    a, b, cc, d = _proj(A), _proj(B), _proj(C), _proj(D)
    Ps = tuple(m * A[-1] * B[-1] / (Pw * Pw) * (y - x) for x, y in zip(a, b))
    Pt = tuple(n * C[-1] * D[-1] / (Pw * Pw) * (y - x) for x, y in zip(cc, d))
    if flip_s:
        Ps, (a, b) = tuple(-x for x in Ps), (b, a)
        cc, d = cc, d
    if flip_t:
        Pt, (cc, d) = tuple(-x for x in Pt), (d, cc)
    return {
        "point": _proj(P),
        "dir_s": tuple(y - x for x, y in zip(a, b)),
        "dir_t": tuple(y - x for x, y in zip(cc, d)),
        "Ps": Ps,
        "Pt": Pt,
    }

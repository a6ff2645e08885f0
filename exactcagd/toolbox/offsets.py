"""Offset curves, exactly: Sederberg's notes (003) chapter 8.

The offset of a planar curve ``P(t) = (x(t), y(t))`` (8.1) with radius ``rho`` is (8.2)::

    Omega(rho, P)(t) = P(t) + rho (y'(t), -x'(t)) / sqrt(x'(t)^2 + y'(t)^2)

(``rho > 0``: on the right when walking along increasing ``t``).  The square root makes
offsets non-rational in general; what exactcagd carries exactly:

* :func:`offset_point`: one offset point at a rational ``t``, in ``Q(sqrt(|P'(t)|^2))``
  (a rational point when the speed is rational), any polynomial or rational curve;
* :func:`pythagorean_hodograph`: ``sigma(t)`` with ``x'^2 + y'^2 = sigma^2`` when the curve
  is a Pythagorean-hodograph (PH) curve (Farouki; notes ch. 8, last paragraph), else ``None``;
* :func:`offset_curve`: the exact rational Bézier offset of a polynomial PH curve of
  degree ``n`` (degree ``2n - 1``);
* :func:`parabola_offset`: the exact rational offset of a parabola (a quadratic Bézier
  curve) -- the notes' "non-obvious exception" -- by rationally parametrizing the conic
  ``w^2 = |P'(t)|^2``; it has degree 6 (the notes print "degree eight": true only as an
  elevated form; ``proofs/sederberg_08_offsets.py``);
* :func:`offset_cusps`: the exact parameters where the radius of curvature equals
  ``|rho|`` on the offset side, i.e. the cusps of the offset (Figure 8.2), as real
  algebraic numbers.

>>> from exactcagd import BezierCurve
>>> ph = BezierCurve([[0, 0], ["1/3", 0], ["2/3", "1/3"], ["2/3", 1]])   # P' = (1 - t^2, 2t)
>>> [int(c) for c in pythagorean_hodograph(ph)]                      # sigma = 1 + t^2
[1, 0, 1]
>>> offset_curve(ph, "1/4").degree
5
"""

from __future__ import annotations

import flint
import numpy as np
from gmpy2 import mpq

from ..algebra.numberfield import algebraic_sign
from ..errors import DegreeError, DimensionError, DomainError, InputError, NotSupportedError
from ..exact import bernstein as bz
from ..exact.algebraic import real_roots
from ..exact.quadratic import sqrt_rational
from ..exact.scalars import from_fmpq as _q
from ..exact.scalars import to_fmpq as _fq
from ..exact.scalars import to_rational
from ..geometry.bezier_curve import BezierCurve

__all__ = ["offset_point", "pythagorean_hodograph", "offset_curve", "parabola_offset", "offset_cusps"]


# ----------------------------------------------------------------------------- helpers
def _planar(curve) -> BezierCurve:
    if not isinstance(curve, BezierCurve):
        raise InputError(f"expected a BezierCurve, got {type(curve).__name__}")
    if curve.dimension != 2:
        raise DimensionError(f"offsets are planar: the curve has dimension {curve.dimension}")
    return curve


def _polynomial(curve) -> BezierCurve:
    _planar(curve)
    if curve.is_rational:
        raise NotSupportedError("this construction needs a polynomial curve (weights all equal)")
    return curve


def _power_polys(curve: BezierCurve) -> list:
    """``[x(t), y(t)]`` as ``fmpq_poly`` (power basis, notes 3.3)."""
    a = bz.to_power(curve.points_array())
    return [flint.fmpq_poly([_fq(c) for c in a[:, k]]) for k in range(2)]


def _tangent(curve: BezierCurve, t) -> tuple:
    """A positive multiple of ``P'(t)``: ``H' w - H w'`` from the homogeneous form."""
    hom = curve.homogeneous()
    H, w = hom[:, :2], hom[:, 2:]
    value = bz.de_casteljau(H, t), bz.de_casteljau(w, t)[0]
    dH, dw = bz.de_casteljau(bz.derivative(H), t), bz.de_casteljau(bz.derivative(w), t)[0]
    return tuple(dH[k] * value[1] - value[0][k] * dw for k in range(2))


# ----------------------------------------------------------------------------- points
def offset_point(curve, rho, t) -> tuple:
    """The offset point ``Omega(rho, P)(t)`` (8.2), exactly.

    Coordinates are rationals when ``|P'(t)|`` is rational, otherwise numbers of
    ``Q(sqrt(|P'(t)|^2))`` (:class:`~exactcagd.exact.quadratic.QuadraticNumber`).

    Raises
    ------
    DomainError
        ``P'(t) = 0``: the normal, hence the offset point, is undefined.

    >>> from exactcagd import BezierCurve
    >>> offset_point(BezierCurve([[0, 0], [1, 0]]), 2, "1/2")      # right of a rightward line
    (mpq(1,2), mpq(-2,1))
    """
    curve = _planar(curve)
    rho, t = to_rational(rho, where="rho"), to_rational(t, where="t")
    dx, dy = _tangent(curve, t)
    speed2 = dx * dx + dy * dy
    if speed2 == 0:
        raise DomainError(f"P'({t}) = 0: the offset is undefined at a stationary point")
    speed = sqrt_rational(speed2)
    x, y = curve.evaluate(t)
    return (x + rho * dy / speed, y - rho * dx / speed)


# ----------------------------------------------------------------------------- PH curves
def pythagorean_hodograph(curve) -> list | None:
    """``sigma`` (power coefficients, lowest first, exact) with ``x'^2 + y'^2 = sigma^2``.

    ``sigma`` is normalized positive at ``t = 1/2``; ``None`` when the curve is not a
    Pythagorean-hodograph curve (the sum is not the square of a rational polynomial).
    """
    x, y = _power_polys(_polynomial(curve))
    s = x.derivative() ** 2 + y.derivative() ** 2
    if s == 0:
        raise DegreeError("the curve is a single point")
    num, den = s.numer(), s.denom()  # s = num / den, num in Z[t]
    content = num.content() if hasattr(num, "content") else flint.fmpz(1)
    primitive = num / content if content != 1 else num
    root = _fmpz_poly_sqrt(flint.fmpz_poly([int(c) for c in primitive.coeffs()]))
    scale2 = mpq(int(content), int(den))
    scale = sqrt_rational(scale2)
    if root is None or not isinstance(scale, type(mpq(0))):
        return None
    sigma = [scale * mpq(int(c)) for c in root.coeffs()]
    half = sum(c * mpq(1, 2) ** k for k, c in enumerate(sigma))
    if half < 0:
        sigma = [-c for c in sigma]
    return sigma


def _fmpz_poly_sqrt(p):
    try:
        root = p.sqrt()
    except Exception:  # noqa: BLE001 - python-flint raises its own DomainError for non-squares
        return None
    return root if root is not None and root * root == p else None


def offset_curve(curve, rho) -> BezierCurve:
    """Exact rational offset of a polynomial Pythagorean-hodograph curve (notes ch. 8).

    With ``x'^2 + y'^2 = sigma^2``: ``Omega = (x sigma + rho y', y sigma - rho x') / sigma``,
    a rational Bézier curve of degree ``2n - 1``.

    Raises
    ------
    NotSupportedError
        The curve is not PH (its offset is not a rational curve in ``t``; for a parabola
        use :func:`parabola_offset`).
    DomainError
        ``sigma`` vanishes in [0, 1] (a stationary point, where the offset is undefined).
    """
    curve = _polynomial(curve)
    rho = to_rational(rho, where="rho")
    sigma = pythagorean_hodograph(curve)
    if sigma is None:
        raise NotSupportedError("not a Pythagorean-hodograph curve: x'^2 + y'^2 is not a perfect square")
    S = flint.fmpq_poly([_fq(c) for c in sigma])
    stationary = real_roots(sigma, 0, 1) if len(sigma) > 1 else []
    if stationary:
        raise DomainError(f"P' vanishes at t = {stationary[0][0]} in [0, 1]: the offset is undefined there")
    x, y = _power_polys(curve)
    r = _fq(rho)
    X, Y = x * S + r * y.derivative(), y * S - r * x.derivative()
    degree = 2 * curve.degree - 1
    return _rational_bezier([X, Y, S], degree)


def _rational_bezier(hom_polys: list, degree: int, interval=(0, 1)) -> BezierCurve:
    """Rational Bézier curve of the homogeneous power-basis polynomials on ``interval``."""
    a, b = (to_rational(v) for v in interval)
    shift = flint.fmpq_poly([_fq(a), _fq(b - a)])  # the parameter as a + (b - a) s
    columns = []
    for p in hom_polys:
        p = p(shift)
        coeffs = [_q(c) for c in p.coeffs()] or [mpq(0)]
        columns.append(bz.from_power(np.array(coeffs + [mpq(0)] * (degree + 1 - len(coeffs)), dtype=object), degree))
    hom = np.stack(columns, axis=1)
    if hom[0, -1] != 0:
        hom = hom / hom[0, -1]  # the same curve, first weight 1
    return BezierCurve.from_homogeneous(hom)


# ----------------------------------------------------------------------------- parabola
def parabola_offset(curve, rho) -> BezierCurve:
    """Exact rational offset of a parabola (quadratic Bézier curve), degree 6.

    Derivation (recorded in ``proofs/sederberg_08_offsets.py``): with ``P(t) = A + B t + C t^2``
    the speed satisfies ``w^2 = q(t) = |B + 2 C t|^2``.  Lines ``w - w_0 = k t`` through the
    rational point ``(0, w_0)``, ``w_0 = |P'(0)|``, meet the conic again at
    ``t = N_t(k) / D(k)`` with ``D = c - k^2``, ``c = |2C|^2``, ``N_t = 2 w_0 k - q'(0)``, and
    ``w = (w_0 D + k N_t) / D``.  Substituting into (8.2) gives a rational curve in ``k``
    of degree 6 (denominator ``D^2 (w_0 D + k N_t)``), restricted to the ``k``-interval
    that corresponds to ``t`` in [0, 1].

    Requires ``|P'(0)|`` and ``|P'(1)|`` rational (rational lengths of the two control
    polygon legs) so that the Bézier form on ``t`` in [0, 1] has rational ends.

    Raises
    ------
    NotSupportedError
        A leg of the control polygon has irrational length.
    DegreeError
        The curve is not a true parabola (degree < 2 or collinear control points).
    """
    curve = _polynomial(curve)
    if curve.degree != 2:
        raise DegreeError(f"a parabola is a quadratic Bézier curve, got degree {curve.degree}")
    rho = to_rational(rho, where="rho")
    x, y = _power_polys(curve)
    A = [_q(p[0]) for p in (x, y)]
    B = [_q(p[1]) for p in (x, y)]
    C = [_q(p[2]) for p in (x, y)]
    if B[0] * C[1] - B[1] * C[0] == 0:
        raise DegreeError("collinear control points: the curve is a line, not a parabola")
    w0, w1 = sqrt_rational(B[0] ** 2 + B[1] ** 2), sqrt_rational(sum((B[i] + 2 * C[i]) ** 2 for i in range(2)))
    if not (isinstance(w0, type(mpq(0))) and isinstance(w1, type(mpq(0)))):
        raise NotSupportedError("|P'(0)| and |P'(1)| must be rational (control polygon legs of rational length)")
    c = 4 * (C[0] ** 2 + C[1] ** 2)
    q1 = 4 * (B[0] * C[0] + B[1] * C[1])  # q'(0)
    k = flint.fmpq_poly([0, 1])
    F = _fq
    D = F(c) - k * k
    Nt = F(2 * w0) * k - F(q1)
    Nw = F(w0) * D + k * Nt
    # numerators over D^2 of P(t(k)) and over D of P'(t(k))
    px, py = (F(A[i]) * D * D + F(B[i]) * Nt * D + F(C[i]) * Nt * Nt for i in range(2))
    dx, dy = (F(B[i]) * D + F(2 * C[i]) * Nt for i in range(2))
    X = px * Nw + F(rho) * D * D * dy
    Y = py * Nw - F(rho) * D * D * dx
    W = D * D * Nw
    k0, k1 = q1 / (2 * w0), w1 - w0  # k = (w - w0) / t at t = 0 (limit) and t = 1
    return _rational_bezier([X, Y, W], 6, (k0, k1))


# ----------------------------------------------------------------------------- cusps
def offset_cusps(curve, rho) -> list:
    """Parameters ``t`` in [0, 1] where the offset has a cusp (Figure 8.2), exactly.

    The offset's derivative is ``Omega' = P' (1 + rho kappa)`` with the signed curvature
    ``kappa = (x' y'' - y' x'') / |P'|^3`` (positive turning left), so cusps are the roots
    of ``rho^2 (x' y'' - y' x'')^2 = |P'|^6`` with ``rho (x' y'' - y' x'') < 0``: where the
    radius of curvature equals ``|rho|`` and the offset lies on the concave side.

    Returns
    -------
    list of :class:`RealAlgebraic` (increasing).

    >>> from exactcagd import BezierCurve
    >>> parabola = BezierCurve([[-1, 1], [0, -1], [1, 1]])    # (2t-1, (2t-1)^2), min radius 1/2
    >>> [str(t) for t in offset_cusps(parabola, -4)]          # radius 4 at t = (2 -+ sqrt 3)/4
    ['root of 16*t^2 - 16*t + 1 in (0, 1/2)', 'root of 16*t^2 - 16*t + 1 in (1/2, 1)']
    """
    curve = _polynomial(curve)
    rho = to_rational(rho, where="rho")
    if rho == 0:
        raise InputError("rho must be non-zero")
    x, y = _power_polys(curve)
    dx, dy = x.derivative(), y.derivative()
    cross = dx * dy.derivative() - dy * dx.derivative()
    speed2 = dx * dx + dy * dy
    r = _fq(rho)
    equation = r * r * cross * cross - speed2 ** 3
    if equation == 0:
        raise DomainError("the radius of curvature equals |rho| everywhere (a circle of radius |rho|)")
    out = []
    for t, _mult in real_roots([_q(c) for c in equation.coeffs()], 0, 1):
        if algebraic_sign(t, r * cross) < 0:
            out.append(t)
    return out


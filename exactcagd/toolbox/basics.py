"""Chapter 1 of Sederberg's notes, exact: vectors, rotation about an axis, lines, conics.

Source: Sederberg, *Computer Aided Geometric Design* course notes (003), chapter 1:
1.2 vector algebra (1.1)-(1.4), 1.3 rotation about an arbitrary axis (1.5)-(1.9) and
its matrix form (1.27), 1.5 lines (1.34)-(1.38) and distance to a line, 1.6 conic
sections (1.39) and their parametric form.

Everything is exact.  Lengths, distances and angles are irrational in general; they
are returned exactly as :class:`~exactcagd.exact.quadratic.QuadraticNumber`
(``a + b sqrt(D)``) or ``mpq`` when rational (:func:`length`), while the squared
quantities stay rational (:func:`length_squared`, :func:`distance_squared_to_line`).
Rotations are exact whenever ``cos`` and ``sin`` are given exactly: rational pairs come
from Pythagorean triples or from ``t = tan(theta/2)`` (:func:`cos_sin_from_tan_half`);
every rational rotation matrix is the one of a rational quaternion
(:func:`rotation_from_quaternion`).

>>> from exactcagd.toolbox.basics import rotate_about_axis
>>> rotate_about_axis([5, 7, 3], base=[1, 1, 1], direction=[2, 1, 2], cos=0, sin=1)
(mpq(5,3), mpq(13,3), mpq(23,3))
"""

from __future__ import annotations

import itertools

from dataclasses import dataclass

import numpy as np
from gmpy2 import mpq

from ..errors import DimensionError, DomainError, InputError, NotSupportedError
from ..exact.quadratic import QuadraticNumber, sqrt_rational
from ..exact.scalars import to_rational
from . import _exact as ex

__all__ = [
    "vec",
    "dot",
    "cross",
    "length_squared",
    "length",
    "relative",
    "cos_angle",
    "angle",
    "project",
    "triangle_area_squared",
    "triangle_area",
    "heron_area_squared",
    "cos_sin_from_tan_half",
    "cos_sin_from_triple",
    "rotate_about_axis",
    "rotation_matrix",
    "rotation_from_quaternion",
    "rotate_about_axis_sympy",
    "Line",
    "line_through",
    "line_point_normal",
    "line_parametric",
    "affine_point",
    "rational_line_implicit",
    "signed_distance",
    "distance_squared_to_line",
    "distance_to_line",
    "distance_squared_point_line",
    "Conic",
    "classify_conic",
    "classify_parametric_conic",
    "implicitize_conic",
    "parametrize_conic",
]

_MPQ = type(mpq(0))


# ---------------------------------------------------------------- vectors (1.2)
def vec(p, what: str = "vector") -> tuple:
    """A point/vector as a tuple of exact rationals."""
    if isinstance(p, (str, bytes)) or not hasattr(p, "__len__"):
        raise InputError(f"{what}: expected a sequence of numbers, got {p!r}")
    return tuple(to_rational(x, where=f"{what}[{i}]") for i, x in enumerate(p))


def _same_dim(u, v, what="vectors"):
    if len(u) != len(v):
        raise DimensionError(f"{what}: dimensions {len(u)} and {len(v)} differ")


def dot(u, v):
    """Dot product (1.2): ``x1 x2 + y1 y2 + z1 z2`` (any dimension, exact)."""
    u, v = vec(u, "u"), vec(v, "v")
    _same_dim(u, v)
    return sum((a * b for a, b in zip(u, v)), mpq(0))


def cross(u, v) -> tuple:
    """Cross product (1.3) of two 3-vectors: ``(y1 z2 - y2 z1, x2 z1 - x1 z2, x1 y2 - x2 y1)``."""
    u, v = vec(u, "u"), vec(v, "v")
    if len(u) != 3 or len(v) != 3:
        raise DimensionError("cross product needs two 3-vectors")
    (x1, y1, z1), (x2, y2, z2) = u, v
    return (y1 * z2 - y2 * z1, x2 * z1 - x1 * z2, x1 * y2 - x2 * y1)


def length_squared(v):
    """``|v|^2`` (rational)."""
    return dot(v, v)


def length(v):
    """``|v|`` exactly: ``mpq`` when rational, else a :class:`QuadraticNumber` ``b sqrt(D)``."""
    return sqrt_rational(length_squared(v))


def relative(p_to, p_from) -> tuple:
    """Relative position vector ``P_{2/1} = P_2 - P_1`` (notes 1.1): ``relative(P2, P1)``."""
    a, b = vec(p_to, "p_to"), vec(p_from, "p_from")
    _same_dim(a, b)
    return tuple(x - y for x, y in zip(a, b))


def cos_angle(u, v):
    """``cos theta = u.v / (|u| |v|)`` (1.1), exact in ``Q(sqrt(|u|^2 |v|^2))``.

    >>> cos_angle([1, 2, 4], [3, -4, 2])        # notes 1.2: 3 / (sqrt(21) sqrt(29))
    QuadraticNumber(1/203*sqrt(609))
    """
    nn = length_squared(u) * length_squared(v)
    if nn == 0:
        raise DomainError("the angle with a zero vector is undefined")
    root = sqrt_rational(nn)
    return dot(u, v) / root


def angle(u, v):
    """The angle as an exact sympy expression ``acos(...)`` (evaluate with ``.evalf()``)."""
    import sympy

    c = cos_angle(u, v)
    return sympy.acos(c.to_sympy() if isinstance(c, QuadraticNumber) else sympy.Rational(int(c.numerator), int(c.denominator)))


def project(p, q_) -> tuple:
    """Projection of ``P`` onto ``Q``: ``(P.Q / Q.Q) Q`` (notes 1.2, Figure 1.4)."""
    qq = length_squared(q_)
    if qq == 0:
        raise DomainError("cannot project onto the zero vector")
    s = dot(p, q_) / qq
    return tuple(s * x for x in vec(q_))


def triangle_area_squared(p1, p2, p3):
    """Squared area of a triangle in any dimension (rational).

    ``Area = |P_{2/1} x P_{3/1}| / 2`` (1.4); by Lagrange's identity
    ``|a x b|^2 = |a|^2 |b|^2 - (a.b)^2``, which works in every dimension.
    """
    a, b = relative(p2, p1), relative(p3, p1)
    return (length_squared(a) * length_squared(b) - dot(a, b) ** 2) / 4


def triangle_area(p1, p2, p3):
    """The area exactly (``mpq`` or :class:`QuadraticNumber`)."""
    return sqrt_rational(triangle_area_squared(p1, p2, p3))


def heron_area_squared(l1_sq, l2_sq, l3_sq):
    """Heron's formula (notes 1.1) in squared side lengths, so that it stays rational.

    ``16 Area^2 = 4 a^2 b^2 - (a^2 + b^2 - c^2)^2`` is Heron's
    ``s (s - l1)(s - l2)(s - l3)`` multiplied out.
    """
    a, b, c = (to_rational(x, where="squared side length") for x in (l1_sq, l2_sq, l3_sq))
    if min(a, b, c) < 0:
        raise InputError("squared side lengths must be non-negative")
    value = (4 * a * b - (a + b - c) ** 2) / 16
    if value < 0:
        raise DomainError("these side lengths violate the triangle inequality")
    return value


# ---------------------------------------------------------------- rotation (1.3)
def cos_sin_from_tan_half(t) -> tuple:
    """Rational ``(cos theta, sin theta)`` from ``t = tan(theta / 2)``:
    ``((1 - t^2) / (1 + t^2), 2 t / (1 + t^2))``.

    >>> cos_sin_from_tan_half("1/2")
    (mpq(3,5), mpq(4,5))
    """
    t = to_rational(t, where="tan(theta/2)")
    return (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)


def cos_sin_from_triple(a, b, c) -> tuple:
    """``(a / c, b / c)`` for a Pythagorean triple ``a^2 + b^2 = c^2`` (checked)."""
    a, b, c = (to_rational(x) for x in (a, b, c))
    if a * a + b * b != c * c or c == 0:
        raise InputError(f"({a}, {b}, {c}) is not a Pythagorean triple")
    return a / c, b / c


def _exact_scalar(x, what):
    if isinstance(x, QuadraticNumber):
        return x
    return to_rational(x, where=what)


def _check_cos_sin(c, s):
    if c * c + s * s != 1:
        raise InputError(f"cos^2 + sin^2 = {c * c + s * s} != 1: (cos, sin) is not a rotation")


def rotate_about_axis(point, base, direction, cos, sin) -> tuple:
    """Rotate ``point`` by the angle with the given exact ``cos``/``sin`` about the axis through
    ``base`` with ``direction`` (notes 1.3, (1.5)-(1.9)).

    ``C = B + [(P - B).n] n``, ``u = P - C``, ``v = n x u``, ``r = u cos + v sin``, ``P' = C + r``.
    ``direction`` need not be a unit vector: with ``d`` the direction,
    ``C = B + ((P - B).d / d.d) d`` is rational and ``v = (d x u) / |d|`` lies in
    ``Q(sqrt(d.d))``; so the result is rational when ``|d|`` is, and otherwise exact
    :class:`QuadraticNumber` coordinates.  ``cos`` and ``sin`` may be rationals or
    :class:`QuadraticNumber` (``cos^2 + sin^2 = 1`` is checked exactly).
    """
    p, b, d = vec(point, "point"), vec(base, "base"), vec(direction, "direction")
    if not (len(p) == len(b) == len(d) == 3):
        raise DimensionError("rotation about an axis needs 3-D point, base and direction")
    c, s = _exact_scalar(cos, "cos"), _exact_scalar(sin, "sin")
    _check_cos_sin(c, s)
    dd = length_squared(d)
    if dd == 0:
        raise DomainError("the axis direction is the zero vector")
    k = dot(relative(p, b), d) / dd
    center = tuple(bi + k * di for bi, di in zip(b, d))           # (1.6)
    u = relative(p, center)                                       # (1.7)
    inv_len = 1 / sqrt_rational(dd)
    v = tuple(x * inv_len for x in cross(d, u))                    # (1.8)
    out = tuple(ci + ui * c + vi * s for ci, ui, vi in zip(center, u, v))  # (1.5), (1.9)
    return tuple(_simplify(x) for x in out)


def _simplify(x):
    if isinstance(x, QuadraticNumber) and x.is_rational:
        return x.rational
    return x


def rotation_matrix(base, direction, cos, sin) -> np.ndarray:
    """The 4x4 matrix (1.27) of the rotation about the axis ``base + s direction``.

    ``direction`` is normalized exactly (entries in ``Q(sqrt(d.d))`` if needed).
    """
    b, d = vec(base, "base"), vec(direction, "direction")
    if len(b) != 3 or len(d) != 3:
        raise DimensionError("rotation_matrix needs 3-D base and direction")
    c, s = _exact_scalar(cos, "cos"), _exact_scalar(sin, "sin")
    _check_cos_sin(c, s)
    dd = length_squared(d)
    if dd == 0:
        raise DomainError("the axis direction is the zero vector")
    inv = 1 / sqrt_rational(dd)
    nx, ny, nz = (x * inv for x in d)
    bn = sum((bi * ni for bi, ni in zip(b, (nx, ny, nz))), mpq(0))
    bx, by, bz = b
    one_c = 1 - c
    m = [
        [nx * nx + (ny * ny + nz * nz) * c, nx * ny * one_c - nz * s, nx * nz * one_c + ny * s,
         (bx - bn * nx) * one_c + (nz * by - ny * bz) * s],
        [nx * ny * one_c + nz * s, ny * ny + (nx * nx + nz * nz) * c, ny * nz * one_c - nx * s,
         (by - bn * ny) * one_c + (nx * bz - nz * bx) * s],
        [nx * nz * one_c - ny * s, ny * nz * one_c + nx * s, nz * nz + (nx * nx + ny * ny) * c,
         (bz - bn * nz) * one_c + (ny * bx - nx * by) * s],
        [mpq(0), mpq(0), mpq(0), mpq(1)],
    ]
    out = np.empty((4, 4), dtype=object)
    for i in range(4):
        for j in range(4):
            out[i, j] = _simplify(m[i][j])
    return out


def rotation_from_quaternion(a, b, c, d) -> tuple[np.ndarray, tuple, tuple]:
    """Rational 3x3 rotation matrix of the quaternion ``a + b i + c j + d k`` (Euler-Rodrigues).

    Returns ``(R, axis, (cos, sin_times_axis_length))`` where the rotation is about
    ``axis = (b, c, d)`` by the angle with ``cos = (a^2 - |v|^2) / (a^2 + |v|^2)`` and
    ``sin = 2 a |v| / (a^2 + |v|^2)``.  Every rational rotation arises this way, so this
    is the general exact rotation; ``|v|`` itself may be irrational.
    """
    a, b, c, d = (to_rational(x, where="quaternion") for x in (a, b, c, d))
    n = a * a + b * b + c * c + d * d
    if n == 0:
        raise DomainError("the zero quaternion is not a rotation")
    R = np.array(
        [
            [a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
            [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
            [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d],
        ],
        dtype=object,
    ) / n
    v2 = b * b + c * c + d * d
    return R, (b, c, d), ((a * a - v2) / n, 2 * a / n)


def rotate_about_axis_sympy(point, base, direction, theta):
    """Rotation for an arbitrary (sympy) angle ``theta``: exact symbolic coordinates (1.5)-(1.9)."""
    import sympy

    p, b, d = (sympy.Matrix([sympy.nsimplify(x) for x in v]) for v in (point, base, direction))
    n = d / sympy.sqrt(d.dot(d))
    center = b + (p - b).dot(n) * n
    u = p - center
    v = n.cross(u)
    return tuple(sympy.simplify(x) for x in center + u * sympy.cos(theta) + v * sympy.sin(theta))


# ---------------------------------------------------------------- lines (1.5)
@dataclass(frozen=True)
class Line:
    """Implicit line ``a x + b y + c = 0`` (notes 1.5.2) with exact coefficients."""

    a: _MPQ
    b: _MPQ
    c: _MPQ

    def __post_init__(self):
        if self.a == 0 and self.b == 0:
            raise DomainError("a = b = 0 is not a line")

    def __call__(self, point):
        x, y = vec(point, "point")
        return self.a * x + self.b * y + self.c

    @property
    def normal(self) -> tuple:
        """The normal vector ``(a, b)`` (1.38)."""
        return (self.a, self.b)

    def normalized(self) -> tuple:
        """Coefficients divided by ``sqrt(a^2 + b^2)`` (exact; ``QuadraticNumber`` if irrational)."""
        r = sqrt_rational(self.a**2 + self.b**2)
        return tuple(_simplify(x / r) for x in (self.a, self.b, self.c))

    def same_line(self, other: "Line") -> bool:
        """Proportional coefficients."""
        u, v = (self.a, self.b, self.c), (other.a, other.b, other.c)
        return all(u[i] * v[j] == u[j] * v[i] for i in range(3) for j in range(3))


def line_through(p1, p2) -> Line:
    """Line through two points (Cartesian ``(x, y)`` or homogeneous ``(X, Y, W)``), notes 1.5.2:

    ``(Y1 W2 - Y2 W1) X + (X2 W1 - X1 W2) Y + (X1 Y2 - X2 Y1) W = 0``.
    """
    h1, h2 = (_homog2(p, f"p{i}") for i, p in enumerate((p1, p2), 1))
    (X1, Y1, W1), (X2, Y2, W2) = h1, h2
    a, b, c = Y1 * W2 - Y2 * W1, X2 * W1 - X1 * W2, X1 * Y2 - X2 * Y1
    if a == 0 and b == 0:
        raise DomainError("the two points coincide (or both lie at infinity)")
    return Line(a, b, c)


def _homog2(p, what):
    p = vec(p, what)
    if len(p) == 2:
        return (p[0], p[1], mpq(1))
    if len(p) == 3:
        return p
    raise DimensionError(f"{what}: expected (x, y) or (X, Y, W)")


def line_point_normal(point, normal) -> Line:
    """``f(x, y) = a x + b y - (a x0 + b y0)`` (1.38)."""
    x0, y0 = vec(point, "point")
    a, b = vec(normal, "normal")
    return Line(a, b, -(a * x0 + b * y0))


def line_parametric(p0, p1, t0=0, t1=1) -> tuple:
    """``P(t) = A0 + A1 t`` (1.34) of the line with ``P(t0) = P0``, ``P(t1) = P1`` (1.35).

    Returns ``(A0, A1)``.
    """
    p0, p1 = vec(p0, "p0"), vec(p1, "p1")
    t0, t1 = to_rational(t0), to_rational(t1)
    if t0 == t1:
        raise DomainError("t0 == t1")
    a1 = tuple((y - x) / (t1 - t0) for x, y in zip(p0, p1))
    a0 = tuple(x - t0 * d for x, d in zip(p0, a1))
    return a0, a1


def affine_point(p_alpha, alpha, p_beta, beta, gamma) -> tuple:
    """``P(gamma) = ((beta - gamma) P(alpha) + (gamma - alpha) P(beta)) / (beta - alpha)`` (notes 1.5.1)."""
    a, b, g = (to_rational(x) for x in (alpha, beta, gamma))
    if a == b:
        raise DomainError("alpha == beta")
    pa, pb = vec(p_alpha, "p_alpha"), vec(p_beta, "p_beta")
    return tuple(((b - g) * x + (g - a) * y) / (b - a) for x, y in zip(pa, pb))


def rational_line_implicit(a, b, d) -> Line:
    """Implicit line of ``x = (a0 + a1 t)/(d0 + d1 t)``, ``y = (b0 + b1 t)/(d0 + d1 t)`` (1.37).

    The homogeneous points at ``(T, U) = (0, 1)`` and ``(1, 0)`` span it.
    """
    a0, a1 = vec(a, "a")
    b0, b1 = vec(b, "b")
    d0, d1 = vec(d, "d")
    return line_through((a0, b0, d0), (a1, b1, d1))


def signed_distance(point, line: Line):
    """``f(x, y) / sqrt(a^2 + b^2)`` (notes 1.5.3), exact."""
    return _simplify(line(point) / sqrt_rational(line.a**2 + line.b**2))


def distance_squared_to_line(point, line: Line):
    """Squared distance ``f(x, y)^2 / (a^2 + b^2)`` (rational)."""
    return line(point) ** 2 / (line.a**2 + line.b**2)


def distance_to_line(point, line: Line):
    """Distance, exact (``mpq`` or ``QuadraticNumber``)."""
    return sqrt_rational(distance_squared_to_line(point, line))


def distance_squared_point_line(point, on_line, direction):
    """Squared distance from ``point`` to the line ``on_line + s direction`` in any dimension:
    ``|P - A|^2 - ((P - A).d)^2 / d.d`` (rational)."""
    w = relative(point, on_line)
    dd = length_squared(direction)
    if dd == 0:
        raise DomainError("the line direction is the zero vector")
    return length_squared(w) - dot(w, direction) ** 2 / dd


# ---------------------------------------------------------------- conics (1.6)
@dataclass(frozen=True)
class Conic:
    """``a x^2 + b x y + c y^2 + d x + e y + f = 0`` (1.39) with exact coefficients."""

    a: _MPQ
    b: _MPQ
    c: _MPQ
    d: _MPQ
    e: _MPQ
    f: _MPQ

    @classmethod
    def of(cls, coeffs) -> "Conic":
        vals = vec(coeffs, "conic coefficients")
        if len(vals) != 6:
            raise InputError("a conic has 6 coefficients (a, b, c, d, e, f)")
        if vals[0] == vals[1] == vals[2] == 0:
            raise DomainError("the quadratic part vanishes: not a conic")
        return cls(*vals)

    @property
    def coefficients(self) -> tuple:
        return (self.a, self.b, self.c, self.d, self.e, self.f)

    def __call__(self, point):
        p = vec(point, "point")
        X, Y, W = p if len(p) == 3 else (p[0], p[1], mpq(1))
        return (self.a * X * X + self.b * X * Y + self.c * Y * Y + self.d * X * W + self.e * Y * W + self.f * W * W)

    def matrix(self) -> np.ndarray:
        """Symmetric 3x3 matrix ``M`` with ``(X, Y, W) M (X, Y, W)^T`` = the form."""
        a, b, c, d, e, f = self.coefficients
        return np.array([[a, b / 2, d / 2], [b / 2, c, e / 2], [d / 2, e / 2, f]], dtype=object)

    @property
    def discriminant(self):
        """``b^2 - 4 a c`` (notes 1.6)."""
        return self.b**2 - 4 * self.a * self.c

    def same_conic(self, other: "Conic") -> bool:
        u, v = self.coefficients, other.coefficients
        return all(u[i] * v[j] == u[j] * v[i] for i in range(6) for j in range(6))


def _det3(m) -> object:
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def classify_conic(conic) -> str:
    """Type of a conic by the number of real points at infinity (notes 1.6).

    ``b^2 - 4 a c > 0``: hyperbola, ``= 0``: parabola, ``< 0``: ellipse.  Degenerate
    conics (``det M = 0``: line pairs) are reported as ``"degenerate ..."`` and an ellipse
    without real points (``(a + c) det M > 0``) as ``"imaginary ellipse"``.
    """
    conic = conic if isinstance(conic, Conic) else Conic.of(conic)
    disc = conic.discriminant
    kind = "hyperbola" if disc > 0 else ("parabola" if disc == 0 else "ellipse")
    det = _det3(conic.matrix())
    if det == 0:
        return f"degenerate {kind}"
    if kind == "ellipse" and (conic.a + conic.c) * det > 0:
        return "imaginary ellipse"
    return kind


def _power3(coeffs, what):
    vals = vec(coeffs, what)
    if len(vals) > 3:
        raise InputError(f"{what}: a conic's parametric components have degree <= 2")
    return list(vals) + [mpq(0)] * (3 - len(vals))


def classify_parametric_conic(x, y, w) -> str:
    """Type of the conic ``(X(t), Y(t), W(t))`` (power coefficients ``[c0, c1, c2]``) by
    ``d1^2 - 4 d0 d2`` of ``W = d0 + d1 t + d2 t^2`` (notes 1.6.1).

    The rule holds when ``W`` shares no root with ``X`` and ``Y`` (else the parametrization
    degenerates to a line; reported as ``"degenerate"``).
    """
    X, Y, W = _power3(x, "x"), _power3(y, "y"), _power3(w, "w")
    con = implicitize_conic(X, Y, W)
    if con is None:
        return "degenerate"
    d0, d1, d2 = W
    # discriminant of the binary form W(T, U) = d2 T^2 + d1 T U + d0 U^2 (t = T/U), so a
    # root at t = infinity (d2 = 0) is counted too
    disc = d1 * d1 - 4 * d0 * d2
    return "hyperbola" if disc > 0 else ("parabola" if disc == 0 else "ellipse")


def implicitize_conic(x, y, w) -> Conic | None:
    """Implicit equation of the rational quadratic ``(X(t) : Y(t) : W(t))`` (power coefficients).

    Undetermined coefficients: ``a X^2 + b X Y + ... + f W^2 = 0`` identically in ``t`` is a
    5 x 6 homogeneous linear system; its one-dimensional nullspace is the conic.  Returns
    ``None`` when the parametrization is degenerate (a line or a point: nullspace > 1).
    """
    X, Y, W = _power3(x, "x"), _power3(y, "y"), _power3(w, "w")
    monos = [ex.pmul(X, X), ex.pmul(X, Y), ex.pmul(Y, Y), ex.pmul(X, W), ex.pmul(Y, W), ex.pmul(W, W)]
    rows = [[m[k] if k < len(m) else mpq(0) for m in monos] for k in range(5)]
    basis = ex.nullspace(rows)
    if len(basis) != 1:
        return None
    v = basis[0]
    den = 1
    for x_ in v:
        den = den * int(x_.denominator) // _gcd(den, int(x_.denominator))
    v = [x_ * den for x_ in v]
    g = 0
    for x_ in v:
        g = _gcd(g, abs(int(x_)))
    v = [x_ / g for x_ in v]
    first = next(x_ for x_ in v if x_ != 0)
    if first < 0:
        v = [-x_ for x_ in v]
    return Conic(*v)


def _gcd(a: int, b: int) -> int:
    while b:
        a, b = b, a % b
    return a


#: Largest number of candidates the Holzer-bound search may try before giving up honestly.
HOLZER_SEARCH_LIMIT = 4_000_000


def _rational_point(conic: Conic):
    """A rational point ``(X, Y, W)`` of the conic, or ``None`` when it provably has none.

    The form is diagonalised over Q (:func:`_diagonalise`), and the diagonal equation is
    decided by Legendre's theorem and solved by a search within Holzer's bound
    (:func:`_legendre_solution`).  (sympy 1.14's ``diop_ternary_quadratic`` is not used: it
    returns non-solutions, e.g. ``(8, 3, 0)`` for ``-3x^2 + 2xy + 2y^2 + 2xw - 3yw + 2w^2``,
    and ``None`` for some variable orders of conics that have points, e.g. ``(-8, -6, -4)``.)

    >>> _rational_point(Conic.of([-3, 2, 2, 2, -3, 2])) is not None
    True
    >>> _rational_point(Conic.of([1, 0, 1, 0, 0, -3])) is None  # x^2 + y^2 = 3
    True
    """
    M = [[mpq(v) for v in row] for row in conic.matrix()]
    diagonal, basis = _diagonalise(M)
    for d, v in zip(diagonal, basis):
        if d == 0:  # a null vector of the form: a (singular) point
            return _primitive(v)
    solution = _legendre_solution(*diagonal)
    if solution is None:
        return None
    point = [sum((x * v[k] for x, v in zip(solution, basis)), mpq(0)) for k in range(3)]
    point = _primitive(point)
    if conic(point) != 0:  # cannot happen: the congruence is exact
        raise ArithmeticError(f"internal error: {point} is not on {conic}")
    return point


def _primitive(v) -> tuple:
    """A nonzero rational vector scaled to coprime integers (as ``mpq``)."""
    den = 1
    for x in v:
        den = den * int(mpq(x).denominator) // _gcd(den, int(mpq(x).denominator))
    ints = [int(mpq(x) * den) for x in v]
    g = 0
    for x in ints:
        g = _gcd(g, abs(x))
    return tuple(mpq(x // g) for x in ints)


def _diagonalise(M) -> tuple[list, list]:
    """``d, V`` with ``V_i^T M V_j = d_i [i == j]`` for the symmetric rational matrix ``M``
    (symmetric Gaussian elimination, i.e. Lagrange's completion of squares; exact).

    >>> d, V = _diagonalise([[mpq(0), mpq(1), mpq(0)], [mpq(1), mpq(0), mpq(0)], [mpq(0), mpq(0), mpq(3)]])
    >>> [str(x) for x in d], [[str(x) for x in v] for v in V]
    (['3', '2', '-1/2'], [['0', '0', '1'], ['1', '1', '0'], ['-1/2', '1/2', '0']])
    """
    n = len(M)

    def form(u, v):
        return sum((u[i] * M[i][j] * v[j] for i in range(n) for j in range(n)), mpq(0))

    rest = [[mpq(int(i == j)) for j in range(n)] for i in range(n)]
    diagonal, basis = [], []
    while rest:
        k = next((i for i, v in enumerate(rest) if form(v, v) != 0), None)
        if k is None:  # every B(v, v) = 0: B(u + w, u + w) = 2 B(u, w) != 0 for a pair, if any
            pair = next(((i, j) for i in range(len(rest)) for j in range(i + 1, len(rest)) if form(rest[i], rest[j]) != 0), None)
            if pair is None:  # the rest spans the radical
                diagonal += [mpq(0)] * len(rest)
                basis += rest
                break
            i, j = pair
            rest[i] = [x + y for x, y in zip(rest[i], rest[j])]
            k = i
        v = rest.pop(k)
        vv = form(v, v)
        rest = [[x - form(w, v) / vv * y for x, y in zip(w, v)] for w in rest]
        diagonal.append(vv)
        basis.append(v)
    return diagonal, basis


def _squarefree_split(n: int) -> tuple[int, int]:
    """``(q, r)`` with ``n = q^2 r`` and ``r`` squarefree (sympy's ``factorint``)."""
    import sympy

    q, r = 1, 1 if n > 0 else -1
    for p, e in sympy.factorint(abs(n)).items():
        q *= p ** (e // 2)
        r *= p ** (e % 2)
    return q, r


def _legendre_solution(a, b, c):
    """A nonzero rational solution of ``a x^2 + b y^2 + c z^2 = 0`` (``a, b, c`` nonzero
    rationals), or ``None`` when there is none.

    The equation is first brought to squarefree, pairwise coprime integer coefficients
    (each step rescales variables).  Then Legendre's theorem (Ireland & Rosen, *A Classical
    Introduction to Modern Number Theory*, ch. 17.3, Thm. 1) decides: a solution exists iff
    the coefficients do not all have one sign and ``-bc``, ``-ca``, ``-ab`` are squares modulo
    ``|a|``, ``|b|``, ``|c|``.  Holzer's theorem (Mordell, *Diophantine Equations*, ch. 7,
    Thm. 5; Cremona & Rusin, Math. Comp. 72 (2003) eq. (1)) bounds a solution by
    ``|x| <= sqrt|bc|, |y| <= sqrt|ca|, |z| <= sqrt|ab|``, so the search below is
    complete.  :class:`NotSupportedError` if that search exceeds
    :data:`HOLZER_SEARCH_LIMIT` candidates (never a false "no solution").

    >>> _legendre_solution(mpq(1), mpq(1), mpq(-2)) is not None, _legendre_solution(mpq(1), mpq(1), mpq(-3))
    (True, None)
    """
    import gmpy2
    import sympy

    coeffs = [mpq(a), mpq(b), mpq(c)]
    den = 1
    for x in coeffs:
        den = den * int(x.denominator) // _gcd(den, int(x.denominator))
    k = [int(x * den) for x in coeffs]
    scale = [mpq(1)] * 3  # original variable i = scale[i] * new variable i
    while True:
        g = _gcd(_gcd(abs(k[0]), abs(k[1])), abs(k[2]))
        k = [x // g for x in k]
        for i in range(3):
            q, k[i] = _squarefree_split(k[i])
            scale[i] /= q  # k q^2 y^2 = k (q y)^2
        pair = next(((i, j) for i, j in ((0, 1), (0, 2), (1, 2)) if _gcd(abs(k[i]), abs(k[j])) > 1), None)
        if pair is None:
            break
        i, j = pair
        l = 3 - i - j
        g = _gcd(abs(k[i]), abs(k[j]))
        # times g: (k_i/g)(g y_i)^2 + (k_j/g)(g y_j)^2 + (g k_l) y_l^2 = 0; |k_0 k_1 k_2| shrinks
        k[i], k[j], k[l] = k[i] // g, k[j] // g, k[l] * g
        scale[i] /= g
        scale[j] /= g
    if all(x > 0 for x in k) or all(x < 0 for x in k):
        return None
    for i in range(3):
        j, l = (i + 1) % 3, (i + 2) % 3
        for p in sympy.factorint(abs(k[i])):
            if p != 2 and gmpy2.legendre(-k[j] * k[l], p) != 1:
                return None
    # Holzer search: loop over the two smallest bounds, solve for the third variable
    bounds = [gmpy2.isqrt(abs(k[(i + 1) % 3] * k[(i + 2) % 3])) for i in range(3)]
    order = sorted(range(3), key=lambda i: bounds[i])
    i, j, l = order
    if (bounds[i] + 1) * (2 * bounds[j] + 1) > HOLZER_SEARCH_LIMIT:
        raise NotSupportedError(f"conic coefficients too large for the rational-point search (Holzer bounds {list(map(int, bounds))})")
    for u in range(bounds[i] + 1):  # (x, y, z) and (-x, -y, -z): u >= 0 suffices
        for v in range(-bounds[j], bounds[j] + 1):
            if u == 0 and v == 0:
                continue
            num = -(k[i] * u * u + k[j] * v * v)
            if num % k[l]:
                continue
            w2 = num // k[l]
            if w2 >= 0 and gmpy2.is_square(w2):
                y = [0, 0, 0]
                y[i], y[j], y[l] = u, v, int(gmpy2.isqrt(w2))
                return [s * x for s, x in zip(scale, y)]
    raise ArithmeticError(f"internal error: Legendre's conditions hold for {k} but no solution within Holzer's bound")


def parametrize_conic(conic, point=None) -> tuple[list, list, list]:
    """Rational parametrization of a non-degenerate conic through a rational point (notes 1.6.1).

    The lines through the point ``P`` (a pencil, parametrized by ``t``) meet the conic in
    one more point, a rational function of ``t`` of degree 2.  ``point`` is Cartesian ``(x, y)`` or
    homogeneous ``(X, Y, W)`` and must lie on the conic; if omitted a rational point is
    found by Legendre's theorem and Holzer's bound (:func:`_rational_point`).  A conic without
    rational points (e.g. ``x^2 + y^2 = 3``) has no parametrization over Q:
    :class:`NotSupportedError`.

    Returns the power coefficients ``(X, Y, W)`` (each ``[c0, c1, c2]``) of the homogeneous
    parametrization ``(X(t) : Y(t) : W(t))``.
    """
    conic = conic if isinstance(conic, Conic) else Conic.of(conic)
    if classify_conic(conic).startswith(("degenerate", "imaginary")):
        raise DomainError(f"cannot parametrize a {classify_conic(conic)}")
    if point is None:
        point = _rational_point(conic)
        if point is None:
            raise NotSupportedError("the conic has no rational point: no parametrization over Q exists")
    P = _homog2(point, "point")
    if conic(P) != 0:
        raise DomainError(f"point {P} is not on the conic")
    M = conic.matrix()
    # Lines through P and the points D(t) = E1 + t E2 of a line not through P (the line at
    # infinity W = 0 unless P lies on it, then X = 0 or Y = 0):
    # conic(s P + D) = 2 s (P M D) + conic(D) = 0, so the second point is
    # -conic(D) P + 2 (P M D) D, quadratic in t.
    one, zero = mpq(1), mpq(0)
    if P[2] != 0:
        E1, E2 = (one, zero, zero), (zero, one, zero)
    elif P[0] != 0:
        E1, E2 = (zero, one, zero), (zero, zero, one)
    else:
        E1, E2 = (one, zero, zero), (zero, zero, one)

    def form(u, v):
        return sum((u[i] * M[i][j] * v[j] for i in range(3) for j in range(3)), mpq(0))

    q_d = [form(E1, E1), 2 * form(E1, E2), form(E2, E2)]
    pmd = [form(P, E1), form(P, E2)]
    comps = []
    for k in range(3):
        lin = [E1[k], E2[k]]
        comps.append(ex.padd(ex.pscale(q_d, -P[k]), ex.pscale(ex.pmul(pmd, lin), 2)))
    X, Y, W = comps
    pad = lambda p: (list(p) + [mpq(0)] * 3)[:3]  # noqa: E731
    return pad(X), pad(Y), pad(W)

"""Rational Bézier curves whose coefficients lie in a real quadratic field Q(sqrt(D)).

The G1 parabolas of Yang et al. (004), section 5, have ``alpha_2`` and ``beta`` in
``Q(sqrt(Delta))`` (eq. (16)); so do the control points of their images on the
surface.  :class:`FieldBezierCurve` carries such a curve exactly in homogeneous form
``(w P, w)`` (entries ``mpq`` or :class:`~exactcagd.exact.quadratic.QuadraticNumber`).
It is a subclass of :class:`~exactcagd.geometry.bezier_curve.BezierCurve` (so
``isinstance(seg, BezierCurve)`` holds for every segment returned by
:func:`~exactcagd.curves_on_surfaces.approximate`): the generic operations (evaluate,
subdivide, elevate, blossom, ...) run unchanged on field entries; what needs ``Q``
only (``reduce``, ``true_degree``) raises :class:`~exactcagd.errors.NotSupportedError`.
The homogeneous form is primary; the affine control points are computed on first use
(one field division each).  :func:`make_curve` returns a plain ``BezierCurve``
whenever every coefficient is rational.

>>> from gmpy2 import mpq
>>> from exactcagd.exact.quadratic import sqrt_rational
>>> r = sqrt_rational(2)
>>> c = FieldBezierCurve([[0, 0, 1], [r, 1, 1], [1, 1, 1]])   # homogeneous rows (x, y, w)
>>> c.degree, c.dimension, c.radicand
(2, 2, 2)
>>> c.evaluate("1/2")
(QuadraticNumber(1/4 + 1/2*sqrt(2)), mpq(3,4))
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..errors import DomainError, InputError, NotSupportedError
from ..exact import bernstein as bz
from ..exact.quadratic import QuadraticNumber, field_of
from ..exact.scalars import to_rational
from ..geometry.bezier_curve import BezierCurve

__all__ = ["FieldBezierCurve", "make_curve", "is_rational_array"]


def _clean(x):
    if isinstance(x, QuadraticNumber):
        return x.a if x.b == 0 else x
    if isinstance(x, int):
        return mpq(x)
    return x


def is_rational_array(a: np.ndarray) -> bool:
    return all(not isinstance(x, QuadraticNumber) or x.b == 0 for x in a.reshape(-1))


def make_curve(hom: np.ndarray):
    """``BezierCurve`` if every homogeneous coefficient is rational, else :class:`FieldBezierCurve`."""
    hom = np.vectorize(_clean, otypes=[object])(np.asarray(hom, dtype=object))
    if is_rational_array(hom):
        return BezierCurve.from_homogeneous(hom)
    return FieldBezierCurve(hom)


class FieldBezierCurve(BezierCurve):
    """A rational Bézier curve with homogeneous coefficients in ``Q(sqrt(D))``.

    Parameters
    ----------
    hom : array-like ``(n + 1, d + 1)``
        Rows ``(w_i P_i, w_i)``; entries ``int``/``mpq``/``QuadraticNumber`` of one field.
    """

    __slots__ = ("_hom", "_D", "_affine")

    def __init__(self, hom):
        a = np.array(hom, dtype=object)
        if a.ndim != 2 or a.shape[1] < 2 or a.shape[0] < 1:
            raise InputError(f"homogeneous coefficients need shape (n + 1, d + 1), got {a.shape}")
        a = np.vectorize(_clean, otypes=[object])(a)
        if any(x == 0 for x in a[:, -1]):
            raise InputError("a homogeneous control point has weight zero")
        self._D = field_of(a.reshape(-1))
        self._hom = a
        self._weights = a[:, -1].copy()
        self._affine = None

    def __reduce__(self):
        # pickle by the defining data: the default slot-by-slot state would include the
        # base class's ``_points`` slot, which this class replaces by a read-only cache
        return (type(self), (self._hom,))

    # ------------------------------------------------------------------ BezierCurve plumbing
    @property
    def _points(self) -> np.ndarray:
        """Affine control points ``H_i / w_i`` (field divisions, computed once)."""
        if self._affine is None:
            h = self._hom
            self._affine = np.vectorize(_clean, otypes=[object])(h[:, :-1] / h[:, -1:])
        return self._affine

    @classmethod
    def _trusted(cls, points, weights):
        w = np.asarray(weights, dtype=object)
        return cls(np.concatenate([np.asarray(points, dtype=object) * w[:, None], w[:, None]], axis=1))

    @classmethod
    def from_homogeneous(cls, hom, rational: bool = True):
        return cls(hom)

    def _wrap(self, array: np.ndarray):
        return make_curve(array)

    def derivative(self):
        """The derivative curve (quotient rule, exact in the field)."""
        return make_curve(BezierCurve.derivative(self).homogeneous())

    def true_degree(self) -> int:
        raise NotSupportedError("true_degree needs rational coefficients (gcd over Q); this curve lies over Q(sqrt(D))")

    def reduce(self):
        raise NotSupportedError("reduce needs rational coefficients (gcd over Q); this curve lies over Q(sqrt(D))")

    # ------------------------------------------------------------------ properties
    @property
    def degree(self) -> int:
        return self._hom.shape[0] - 1

    @property
    def dimension(self) -> int:
        return self._hom.shape[1] - 1

    @property
    def radicand(self) -> int | None:
        """``D`` of the field ``Q(sqrt(D))`` of the coefficients (``None``: all rational)."""
        return self._D

    @property
    def is_rational(self) -> bool:
        """Always True: a field curve carries weights (mirrors ``BezierCurve.is_rational``)."""
        return True

    def homogeneous(self) -> np.ndarray:
        return self._hom.copy()

    @property
    def weights(self) -> tuple:
        return tuple(self._hom[:, -1])

    @property
    def control_points(self) -> tuple:
        return tuple(tuple(p) for p in self._points)

    # ------------------------------------------------------------------ evaluation
    def evaluate(self, t, extrapolate: bool = False) -> tuple:
        """Exact point at a rational ``t`` (entries in the field)."""
        t = to_rational(t, where="t")
        if not extrapolate and not (0 <= t <= 1):
            raise DomainError(f"t = {t} lies outside [0, 1]")
        h = bz.de_casteljau(self._hom, t)
        if h[-1] == 0:
            raise DomainError(f"the curve has a pole at t = {t}")
        return tuple(_clean(x / h[-1]) for x in h[:-1])

    __call__ = evaluate

    def end_direction(self, end: int) -> tuple:
        """Exact positive multiple of the derivative at ``t = 0`` (``end=0``) or ``t = 1``.

        ``w_0 H_1 - w_1 H_0`` resp. ``w_(n-1) H_n - w_n H_(n-1)`` (``H = w P``), which is
        ``w^2 / n`` times ``P'`` -- no division in the field.
        """
        return _end_derivative(self._hom, end)

    def evaluate_float(self, ts) -> np.ndarray:
        """Float points at many parameters (de Casteljau in float64; for plots and heuristics)."""
        h = np.vectorize(float, otypes=[float])(self._hom)
        return _float_eval(h, ts)

    # ------------------------------------------------------------------ operations
    def elevate(self, r: int = 1) -> "FieldBezierCurve":
        return FieldBezierCurve(bz.elevate(self._hom, int(r)))

    def reparametrize(self, a, b) -> "FieldBezierCurve":
        return FieldBezierCurve(bz.restrict(self._hom, a, b))

    def reversed(self) -> "FieldBezierCurve":
        return FieldBezierCurve(self._hom[::-1].copy())

    def conjugate(self) -> "FieldBezierCurve":
        """The Galois conjugate curve (``sqrt(D) -> -sqrt(D)`` in every coefficient)."""
        conj = np.vectorize(lambda x: x.conjugate() if isinstance(x, QuadraticNumber) else x, otypes=[object])
        return FieldBezierCurve(conj(self._hom))

    def same_curve(self, other) -> bool:
        """Same rational functions of ``t`` (cross-multiplied, exact)."""
        a = self._hom
        b = other.homogeneous()
        if a.shape[1] != b.shape[1]:
            return False
        left = bz.product(a[:, :-1], b[:, -1:])
        right = bz.product(b[:, :-1], a[:, -1:])
        n = max(left.shape[0], right.shape[0])
        left = bz.elevate(left, n - left.shape[0])
        right = bz.elevate(right, n - right.shape[0])
        return all((x - y) == 0 for x, y in zip(left.reshape(-1), right.reshape(-1)))

    def to_bezier_curve(self) -> BezierCurve:
        """The same curve as a plain ``BezierCurve`` (only when every coefficient is rational)."""
        if self._D is not None:
            raise InputError(f"coefficients lie in Q(sqrt({self._D})), not in Q")
        return BezierCurve.from_homogeneous(self._hom)

    # ------------------------------------------------------------------ conversion
    def to_float(self) -> tuple[np.ndarray, np.ndarray]:
        h = np.vectorize(float, otypes=[float])(self._hom)
        return h[:, :-1] / h[:, -1:], h[:, -1].copy()

    def to_sympy(self, t=None):
        """Column ``Matrix`` of rational functions of ``t`` with ``sqrt(D)`` kept symbolic."""
        import sympy

        t = sympy.Symbol("t") if t is None else t
        n = self.degree
        basis = [sympy.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]
        sym = [[_sym(x) for x in row] for row in self._hom]
        comps = [sympy.expand(sum(sym[i][k] * basis[i] for i in range(n + 1))) for k in range(self._hom.shape[1])]
        return sympy.Matrix([c / comps[-1] for c in comps[:-1]])

    def to_dict(self) -> dict:
        return {
            "degree": self.degree,
            "radicand": self._D,
            "homogeneous": [[_to_text(x) for x in row] for row in self._hom],
        }

    def __repr__(self) -> str:
        field = "Q" if self._D is None else f"Q(sqrt({self._D}))"
        return f"<FieldBezierCurve degree={self.degree} dimension={self.dimension} field={field}>"


def _sym(x):
    from ..exact.scalars import to_sympy

    return x.to_sympy() if isinstance(x, QuadraticNumber) else to_sympy(mpq(x))


def _to_text(x) -> str:
    from ..exact.scalars import rational_str

    if isinstance(x, QuadraticNumber):
        return str(x)
    return rational_str(mpq(x))


def _end_derivative(hom: np.ndarray, end: int) -> tuple:
    """A positive multiple of the derivative at ``t = 0`` / ``t = 1``, without division.

    ``P'(1) = n w_(n-1) / w_n (P_n - P_(n-1)) = n / w_n^2 (w_(n-1) H_n - w_n H_(n-1))``
    with ``H = w P``: the direction is ``w_(n-1) H_n - w_n H_(n-1)`` up to ``n / w_n^2 > 0``
    (and ``w_1 H_0 - ...`` mirrored at ``t = 0``: ``w_0 H_1 - w_1 H_0``).
    """
    n = hom.shape[0] - 1
    if n == 0:
        return tuple(mpq(0) for _ in range(hom.shape[1] - 1))
    if end == 0:
        a, b = hom[0], hom[1]
        vec = [a[-1] * b[k] - b[-1] * a[k] for k in range(hom.shape[1] - 1)]
    else:
        a, b = hom[n], hom[n - 1]
        vec = [b[-1] * a[k] - a[-1] * b[k] for k in range(hom.shape[1] - 1)]
    return tuple(_clean(x) for x in vec)


def _float_eval(h: np.ndarray, ts) -> np.ndarray:
    ts = np.asarray(ts, dtype=float)
    n = h.shape[0] - 1
    s = 1.0 - ts
    level = np.broadcast_to(h, (len(ts),) + h.shape).copy()
    for _ in range(n):
        level = s[:, None, None] * level[:, :-1] + ts[:, None, None] * level[:, 1:]
    pts = level[:, 0, :]
    return pts[:, :-1] / pts[:, -1:]

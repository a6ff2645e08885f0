"""Exact polynomial and rational Bézier curves in any dimension.

Source: Sederberg's notes (003), chapter 2 (Bézier curves, de Casteljau, subdivision,
elevation, hodograph, rational curves 2.9) and 6.1 (polar form).

A rational curve ``P(t) = sum w_i P_i B_i(t) / sum w_i B_i(t)`` is carried in
homogeneous form ``(w_i P_i, w_i)``; every operation acts on that form exactly.

>>> from exactcagd import BezierCurve
>>> c = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> c.evaluate("1/2")
(mpq(1,1), mpq(1,1))
>>> c.degree, c.dimension, c.is_rational
(2, 2, False)
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DomainError, InputError, WeightError
from ..exact import bernstein as bz
from ..exact.scalars import from_fmpq, rational_str, to_count, to_float, to_fmpq, to_rational, to_sympy
from ._validate import check_stored_degree, dehomogenize, exchange_fields, homogeneous, point_array, unit_parameter, weight_array

__all__ = ["BezierCurve"]


class BezierCurve:
    """A Bézier curve with exact rational control points and optional weights.

    Parameters
    ----------
    control_points : sequence of points
        ``n + 1`` points, each a sequence of ``d >= 1`` numbers (converted by
        :func:`exactcagd.exact.scalars.to_rational`).
    weights : sequence of numbers, optional
        ``n + 1`` positive weights; ``None`` means a polynomial curve.

    Examples
    --------
    >>> quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    >>> x, y = quarter.evaluate("1/2")
    >>> x**2 + y**2
    mpq(1,1)
    """

    __slots__ = ("_points", "_weights")

    def __init__(self, control_points, weights=None):
        points = point_array(control_points, 1, "control_points", bezier=True)
        self._points = points
        self._weights = weight_array(weights, (points.shape[0],), "weights")

    # ------------------------------------------------------------------ construction
    @classmethod
    def _trusted(cls, points: np.ndarray, weights: np.ndarray | None) -> "BezierCurve":
        """Build from exact arrays without re-validation (internal use)."""
        curve = object.__new__(cls)
        curve._points = points
        curve._weights = weights
        return curve

    @classmethod
    def from_homogeneous(cls, hom, rational: bool = True) -> "BezierCurve":
        """Curve from homogeneous control points ``(w P, w)`` (last coordinate = weight).

        Weights must be non-zero; they may be negative here (the result of an exact
        construction), which :meth:`__init__` would reject.
        """
        if not isinstance(hom, np.ndarray):  # user data: checked like control points
            hom = point_array(hom, 1, "homogeneous control points", bezier=True)
        hom = np.asarray(hom, dtype=object)
        if hom.ndim != 2 or hom.shape[1] < 2:
            raise InputError(f"homogeneous control points: expected shape (n + 1, d + 1) with d >= 1, got {hom.shape}")
        points, weights = dehomogenize(hom)
        if not rational and all(w == weights[0] for w in weights):
            return cls._trusted(points, None)
        return cls._trusted(points, weights)

    def homogeneous(self) -> np.ndarray:
        """Homogeneous control points ``(w_i P_i, w_i)``, shape ``(n + 1, d + 1)``."""
        return homogeneous(self._points, self._weights)

    def _apply(self, func, *args) -> np.ndarray:
        """Apply a Bernstein operation to the right array (points, or homogeneous)."""
        return func(self._points if self._weights is None else self.homogeneous(), *args)

    def _wrap(self, array: np.ndarray) -> "BezierCurve":
        if self._weights is None:
            return BezierCurve._trusted(array, None)
        return BezierCurve.from_homogeneous(array)

    # ------------------------------------------------------------------ properties
    @property
    def degree(self) -> int:
        """Stored degree ``n`` (number of control points minus one)."""
        return self._points.shape[0] - 1

    @property
    def dimension(self) -> int:
        """Dimension ``d`` of the space the curve lies in."""
        return self._points.shape[1]

    @property
    def is_rational(self) -> bool:
        """True when the curve carries weights."""
        return self._weights is not None

    @property
    def control_points(self) -> tuple:
        """Control points as a tuple of tuples of ``mpq``."""
        return tuple(tuple(p) for p in self._points)

    @property
    def weights(self) -> tuple | None:
        """Weights as a tuple of ``mpq``, or ``None`` for a polynomial curve."""
        return None if self._weights is None else tuple(self._weights)

    def points_array(self) -> np.ndarray:
        """A copy of the control points as an exact object array ``(n + 1, d)``."""
        return self._points.copy()

    def weights_array(self) -> np.ndarray:
        """A copy of the weights (all ones for a polynomial curve)."""
        if self._weights is None:
            return np.array([mpq(1)] * (self.degree + 1), dtype=object)
        return self._weights.copy()

    # ------------------------------------------------------------------ evaluation
    def evaluate(self, t, extrapolate: bool = False) -> tuple:
        """Exact point at ``t`` by de Casteljau's algorithm (notes 2.3).

        ``t`` must lie in [0, 1] unless ``extrapolate=True``.
        """
        t = unit_parameter(t, "t", allow_outside=extrapolate)
        if self._weights is None:
            return tuple(bz.de_casteljau(self._points, t))
        hom = bz.de_casteljau(self.homogeneous(), t)
        if hom[-1] == 0:
            raise DomainError(f"the rational curve has a pole at t = {t} (weight function is zero)")
        return tuple(x / hom[-1] for x in hom[:-1])

    __call__ = evaluate

    def evaluate_horner(self, t, extrapolate: bool = False) -> tuple:
        """Exact point at ``t`` by Horner's rule in Bernstein form (notes 3.2)."""
        t = unit_parameter(t, "t", allow_outside=extrapolate)
        hom = bz.horner_bernstein(self.homogeneous(), t)
        if hom[-1] == 0:
            raise DomainError(f"the rational curve has a pole at t = {t}")
        return tuple(x / hom[-1] for x in hom[:-1])

    def blossom(self, params) -> tuple:
        """Polar form (blossom) of the curve at ``n`` parameters (notes 6.1).

        For a rational curve the blossom of the homogeneous curve is projected,
        i.e. the result is the point ``f_wP / f_w``.
        """
        hom = bz.blossom(self.homogeneous(), params)
        if hom[-1] == 0:
            raise DomainError("the homogeneous blossom has weight zero at these parameters")
        return tuple(x / hom[-1] for x in hom[:-1])

    # ------------------------------------------------------------------ operations
    def subdivide(self, t) -> tuple["BezierCurve", "BezierCurve"]:
        """Split at ``t`` in [0, 1] into the pieces on [0, t] and [t, 1] (notes 2.3)."""
        t = unit_parameter(t, "subdivision parameter")
        left, right = self._apply(bz.subdivide, t)
        return self._wrap(left), self._wrap(right)

    def elevate(self, r: int = 1) -> "BezierCurve":
        """Degree elevation by ``r`` (notes 2.5); the curve is unchanged."""
        r = to_count(r, where="elevation amount", error=DegreeError)
        return self._wrap(self._apply(bz.elevate, r))

    def reparametrize(self, a, b) -> "BezierCurve":
        """The curve restricted (or extended, or reversed) to [a, b], reparametrized to [0, 1].

        Uses the polar form ``Q_i = f(a^{n-i}, b^i)`` (notes 6.1).  For a rational
        curve, extending past a pole of the weight function raises :class:`WeightError`.
        """
        a, b = to_rational(a, where="a"), to_rational(b, where="b")
        if a == b:
            raise DomainError("reparametrize needs a != b")
        return self._wrap(self._apply(bz.restrict, a, b))

    def reversed(self) -> "BezierCurve":
        """The same curve traversed from ``t = 1`` to ``t = 0``."""
        return BezierCurve._trusted(self._points[::-1].copy(), None if self._weights is None else self._weights[::-1].copy())

    def derivative(self) -> "BezierCurve":
        """The derivative curve ``P'(t)`` as an exact Bézier curve.

        Polynomial: the hodograph of degree ``n - 1`` (notes 2.7).  Rational: the quotient
        rule ``(N' W - N W') / W^2``, a rational curve of degree ``2n`` with weights
        the Bernstein coefficients of ``W^2`` (exact products, notes 9.3).
        """
        if self._weights is None:
            return BezierCurve._trusted(bz.derivative(self._points), None)
        hom = self.homogeneous()
        num, w = hom[:, :-1], hom[:, -1:]
        d_num, d_w = bz.derivative(num), bz.derivative(w)
        top = bz.product(d_num, w) - bz.product(num, d_w) if self.degree > 0 else num * 0
        if self.degree > 0:
            top = bz.elevate(top, 1)
        bottom = bz.product(w, w)
        if self.degree == 0:
            bottom = w * w
        return BezierCurve.from_homogeneous(np.concatenate([top, bottom], axis=1))

    # ------------------------------------------------------------------ exact degree
    def true_degree(self) -> int:
        """The exact lowest degree of the curve (after cancelling common factors).

        For a polynomial curve: the highest non-vanishing power-basis coefficient.
        For a rational curve: the maximum degree of the homogeneous components after
        dividing out their common polynomial factor (python-flint gcd).
        """
        if self._weights is None:
            return bz.true_degree(self._points)
        return max(_poly_degree(p) for p in self._reduced_homogeneous_power())

    def reduce(self) -> "BezierCurve":
        """The same curve in Bézier form of its true degree (exact; never approximate).

        A rational curve whose reduced weight function is constant comes back as a
        polynomial curve.  The reduced weights are positive as a function on [0, 1];
        their Bernstein coefficients are what the exact division gives.  If one of them
        is exactly 0 (possible: ``(1-t)^2 + t^2`` has Bernstein weights ``1, 0, 1``),
        :class:`WeightError` is raised; :meth:`true_degree` still gives the degree.
        """
        if self._weights is None:
            return BezierCurve._trusted(bz.reduce_degree(self._points), None)
        comps = self._reduced_homogeneous_power()
        d = max(_poly_degree(p) for p in comps)
        power = np.array([[_coeff(p, k) for p in comps] for k in range(d + 1)], dtype=object)
        hom = bz.from_power(power, d)
        w_poly = comps[-1]
        if _poly_degree(w_poly) == 0:
            return BezierCurve._trusted(hom[:, :-1] / hom[0, -1], None)
        zeros = [k for k, w in enumerate(hom[:, -1]) if w == 0]
        if zeros:
            raise WeightError(
                f"the curve has true degree {d}, but in that degree its Bernstein weight {zeros[0]} is exactly 0 "
                "(a control point at infinity), which a BezierCurve cannot store; true_degree() still "
                f"reports {d}; keep the stored degree-{self.degree} form"
            )
        return BezierCurve.from_homogeneous(hom)

    def _reduced_homogeneous_power(self) -> list:
        import flint

        power = bz.to_power(self.homogeneous())
        comps = [flint.fmpq_poly([to_fmpq(x) for x in power[:, j]]) for j in range(power.shape[1])]
        g = comps[0]
        for p in comps[1:]:
            g = g.gcd(p)
        if g.degree() > 0:
            comps = [p // g for p in comps]
            # keep the weight function positive on [0, 1]: it cannot vanish there
            if _eval_fmpq(comps[-1], 0) < 0:
                comps = [-p for p in comps]
        return comps

    # ------------------------------------------------------------------ comparison
    def __eq__(self, other) -> bool:
        """Same stored representation (degree, points, weights), exactly."""
        if not isinstance(other, BezierCurve):
            return NotImplemented
        return (
            self._points.shape == other._points.shape
            and bool(np.all(self._points == other._points))
            and (self._weights is None) == (other._weights is None)
            and (self._weights is None or bool(np.all(self._weights == other._weights)))
        )

    def __hash__(self):
        return hash((self.control_points, self.weights))

    def same_curve(self, other: "BezierCurve") -> bool:
        """True when both define the same parametric curve (same rational functions of t)."""
        if self.dimension != other.dimension:
            return False
        n = max(self.degree, other.degree)
        a = bz.to_power(bz.elevate(self.homogeneous(), n - self.degree))
        b = bz.to_power(bz.elevate(other.homogeneous(), n - other.degree))
        # N_a / W_a == N_b / W_b  <=>  N_a W_b == N_b W_a
        left = bz.product(bz.from_power(a[:, :-1]), bz.from_power(b[:, -1:]))
        right = bz.product(bz.from_power(b[:, :-1]), bz.from_power(a[:, -1:]))
        return bool(np.all(left == right))

    # ------------------------------------------------------------------ conversion
    def to_sympy(self, t=None):
        """The curve as a sympy column ``Matrix`` of (rational) functions of ``t``."""
        import sympy

        t = sympy.Symbol("t") if t is None else t
        if not isinstance(t, sympy.Expr):  # a number: exact, through to_rational
            t = to_sympy(to_rational(t, where="t"))
        n = self.degree
        basis = [sympy.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]
        hom = self.homogeneous()
        comps = [sum(to_sympy(hom[i, j]) * basis[i] for i in range(n + 1)) for j in range(hom.shape[1])]
        w = comps[-1]
        if self._weights is None:
            return sympy.Matrix([sympy.expand(c) for c in comps[:-1]])
        return sympy.Matrix([sympy.expand(c) / sympy.expand(w) for c in comps[:-1]])

    def to_float(self) -> tuple[np.ndarray, np.ndarray | None]:
        """Control points (and weights) rounded to float64 (for plotting and numerics).

        Correctly rounded; magnitudes beyond the float range become ``inf`` (the rule of
        :func:`exactcagd.exact.scalars.to_float`).
        """
        pts = np.array([[to_float(x) for x in p] for p in self._points], dtype=float)
        w = None if self._weights is None else np.array([to_float(x) for x in self._weights], dtype=float)
        return pts, w

    def to_dict(self) -> dict:
        """Exact exchange form: rationals as ``"p/q"`` strings."""
        out = {"degree": self.degree, "control_points": [[rational_str(x) for x in p] for p in self._points]}
        if self._weights is not None:
            out["weights"] = [rational_str(w) for w in self._weights]
        return out

    @classmethod
    def from_dict(cls, data: dict) -> "BezierCurve":
        """The curve written by :meth:`to_dict` (exact: ints and ``"p/q"`` strings).

        ``"degree"`` is optional and, when present, must match the control points.

        >>> c = BezierCurve([[0, 0], [1, 2], [2, 0]], weights=[1, "1/3", 2])
        >>> BezierCurve.from_dict(c.to_dict()) == c
        True
        """
        data = exchange_fields(data, ("control_points",), ("degree", "weights"), "BezierCurve")
        curve = cls(data["control_points"], data.get("weights"))
        check_stored_degree(data, curve.degree, "BezierCurve")
        return curve

    def __repr__(self) -> str:
        from ._display import points_preview

        kind = "rational " if self.is_rational else ""
        return f"<{kind}BezierCurve degree={self.degree} dimension={self.dimension} points={points_preview(self.control_points)}>"

    def _repr_latex_(self) -> str:
        """Jupyter shows the curve typeset: ``P(t) =`` its sympy form."""
        from ._display import latex

        return latex(self, "P(t)")

    def plot(self, ax=None, **style):
        """Draw the curve and its control polygon (matplotlib; see :func:`exactcagd.plotting.plot`)."""
        from ._display import plot

        return plot(self, ax=ax, **style)


def _poly_degree(p) -> int:
    return max(p.degree(), 0)


def _coeff(p, k: int):
    coeffs = p.coeffs()
    if k >= len(coeffs):
        return mpq(0)
    return from_fmpq(coeffs[k])


def _eval_fmpq(p, x) -> object:
    return from_fmpq(p(to_fmpq(x)))


def _check_dimension(curve: BezierCurve, d: int, what: str) -> None:
    if curve.dimension != d:
        raise InputError(f"{what}: expected a curve of dimension {d}, got {curve.dimension}")

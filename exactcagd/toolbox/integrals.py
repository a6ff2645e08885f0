"""Chapter 20 of Sederberg's notes: polynomial approximation of rational curves (hybrid
curves), planar areas and integrals over Bézier curves, and the error bounds of 20.3.

Source: Sederberg, CAGD notes (003), chapter 20: hybrid curves (20.1)-(20.9), 20.2
integrals over plane Bézier curves (20.10)-(20.18), 20.3 error bounds (20.19)-(20.30),
20.4 the recursive algorithm and the semicircle example.

For polynomial curves every integral here is a polynomial in ``t`` and is computed
exactly with one mechanism -- Bernstein products and the Bernstein integral (notes 9.3,
2.15).  The notes' closed forms with the coefficients ``D_ij`` and ``D_ijk`` (20.11)-(20.12)
are provided as well, with the corrected coefficients (the printed ones lack the factors
``1 / C(2n, i+j)`` and ``1 / C(3n, i+j+k)``).  For rational curves the integrals are
transcendental in general (logarithms, arctangents); :func:`rational_integral` returns an
exact rational approximation with a rigorous rational error bound, from hybrid-curve
polynomial approximations of the pieces of a uniform subdivision (notes 20.4).

>>> from exactcagd import BezierCurve
>>> from exactcagd.toolbox.integrals import area_under
>>> area_under(BezierCurve([[0, 0], [1, 2], [2, 0]]))       # int_0^2 y dx of the parabola
mpq(4,3)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from gmpy2 import mpq

from .. import limits
from ..errors import DegreeError, DimensionError, DomainError, InputError
from ..exact import bernstein as bz
from ..exact.quadratic import sqrt_rational
from ..exact.scalars import to_count
from ..geometry._validate import instance_of
from ..geometry.bezier_curve import BezierCurve

__all__ = [
    "area_under",
    "sector_area",
    "first_moments",
    "volume_over_pi",
    "enclosed_area",
    "d2_coefficients",
    "d3_coefficients",
    "area_under_by_formula",
    "sector_area_by_formula",
    "first_moments_by_formula",
    "Hybrid",
    "hybrid_curve",
    "max_bernstein",
    "PolynomialApproximation",
    "polynomial_approximation",
    "derivative_bounds",
    "value_bounds",
    "integration_error_bounds",
    "rational_integral",
]

_KINDS = ("area", "sector", "Ix", "Iy", "volume")


def _planar_poly(curve: BezierCurve, what: str):
    instance_of(curve, BezierCurve, f"{what}: curve")
    if curve.dimension != 2:
        raise DimensionError(f"{what}: planar curves only")
    if curve.is_rational:
        raise InputError(f"{what}: polynomial curves only (use rational_integral for rational curves)")
    P = curve.points_array()
    return P[:, 0], P[:, 1]


def _int(*factors):
    """Exact int_0^1 of a product of Bernstein polynomials (coefficient arrays)."""
    acc = factors[0]
    for f in factors[1:]:
        acc = bz.product(acc, f)
    return bz.integral(acc)


# ---------------------------------------------------------------- 20.2 exact integrals
def area_under(curve: BezierCurve):
    """``int_{x0}^{xn} y dx = int_0^1 y(t) x'(t) dt`` (20.13), exact (signed)."""
    x, y = _planar_poly(curve, "area_under")
    if curve.degree == 0:
        return mpq(0)
    return _int(y, bz.derivative(x))


def sector_area(curve: BezierCurve):
    """Directed area of the sector from the origin (20.14): ``1/2 int_0^1 P ^ P' dt``, exact."""
    x, y = _planar_poly(curve, "sector_area")
    if curve.degree == 0:
        return mpq(0)
    return (_int(x, bz.derivative(y)) - _int(y, bz.derivative(x))) / 2


def first_moments(curve: BezierCurve) -> tuple:
    """``(I_x, I_y) = (int 1/2 y^2 dx, int x y dx)`` (20.16)-(20.17), exact."""
    x, y = _planar_poly(curve, "first_moments")
    if curve.degree == 0:
        return mpq(0), mpq(0)
    dx = bz.derivative(x)
    return _int(y, y, dx) / 2, _int(x, y, dx)


def volume_over_pi(curve: BezierCurve):
    """``Volume / pi = int y^2 dx = 2 I_x`` (20.18): the solid of revolution about the x axis."""
    return 2 * first_moments(curve)[0]


def enclosed_area(curves) -> object:
    """Signed area enclosed by a closed chain of polynomial Bézier curves (Green's theorem:
    the sum of the directed sector areas), exact; counter-clockwise is positive."""
    curves = list(curves)
    if not curves:
        raise InputError("no curves")
    for a, b in zip(curves, curves[1:] + curves[:1]):
        if a.control_points[-1] != b.control_points[0]:
            raise DomainError("the curves do not form a closed chain")
    return sum((sector_area(c) for c in curves), mpq(0))


# ---------------------------------------------------------------- the notes' closed forms
def d2_coefficients(n: int) -> np.ndarray:
    """``D_ij = C_{i,j-1} - C_{i,j}`` with ``C_ij = int B^n_i B^(n-1)_j`` (20.11), corrected:

    ``D_00 = -1/(2n)``, ``D_nn = 1/(2n)``, otherwise
    ``D_ij = (j - i) / ((i + j)(2n - i - j)) C(n,i) C(n,j) / C(2n, i+j)``.
    """
    if to_count(n, where="n", error=DegreeError) < 1:
        raise DegreeError("n >= 1")
    limits.check("max_control_points", (n + 1) ** 2, f"d2_coefficients: (n + 1)^2 entries for n = {n}")
    D = np.empty((n + 1, n + 1), dtype=object)
    for i in range(n + 1):
        for j in range(n + 1):
            if (i, j) == (0, 0):
                D[i, j] = mpq(-1, 2 * n)
            elif (i, j) == (n, n):
                D[i, j] = mpq(1, 2 * n)
            else:
                D[i, j] = mpq((j - i) * bz.binomial(n, i) * bz.binomial(n, j), (i + j) * (2 * n - i - j) * bz.binomial(2 * n, i + j))
    return D


def d3_coefficients(n: int) -> np.ndarray:
    """``D_ijk = C_{i,j,k-1} - C_{i,j,k}`` (20.12), corrected with ``1 / C(3n, i+j+k)``."""
    if to_count(n, where="n", error=DegreeError) < 1:
        raise DegreeError("n >= 1")
    limits.check("max_control_points", (n + 1) ** 3, f"d3_coefficients: (n + 1)^3 entries for n = {n}")
    D = np.empty((n + 1, n + 1, n + 1), dtype=object)
    for i in range(n + 1):
        for j in range(n + 1):
            for k in range(n + 1):
                s = i + j + k
                if s == 0:
                    D[i, j, k] = mpq(-1, 3 * n)
                elif s == 3 * n:
                    D[i, j, k] = mpq(1, 3 * n)
                else:
                    D[i, j, k] = mpq((2 * k - i - j) * bz.binomial(n, i) * bz.binomial(n, j) * bz.binomial(n, k),
                                     s * (3 * n - s) * bz.binomial(3 * n, s))
    return D


def area_under_by_formula(curve: BezierCurve):
    """(20.13): ``n sum_ij D_ij y_i x_j`` (with the corrected ``D``)."""
    x, y = _planar_poly(curve, "area_under_by_formula")
    n = curve.degree
    D = d2_coefficients(n)
    return n * sum((D[i, j] * y[i] * x[j] for i in range(n + 1) for j in range(n + 1)), mpq(0))


def sector_area_by_formula(curve: BezierCurve):
    """(20.14): ``n sum_{i<j} D_ij (P_i ^ P_j)``."""
    x, y = _planar_poly(curve, "sector_area_by_formula")
    n = curve.degree
    D = d2_coefficients(n)
    return n * sum((D[i, j] * (x[i] * y[j] - y[i] * x[j]) for i in range(n + 1) for j in range(i + 1, n + 1)), mpq(0))


def first_moments_by_formula(curve: BezierCurve) -> tuple:
    """(20.16)-(20.17): ``I_x = n/2 sum D_ijk y_i y_j x_k``, ``I_y = n sum D_ijk x_i y_j x_k``."""
    x, y = _planar_poly(curve, "first_moments_by_formula")
    n = curve.degree
    D = d3_coefficients(n)
    r = range(n + 1)
    ix = n * sum((D[i, j, k] * y[i] * y[j] * x[k] for i in r for j in r for k in r), mpq(0)) / 2
    iy = n * sum((D[i, j, k] * x[i] * y[j] * x[k] for i in r for j in r for k in r), mpq(0))
    return ix, iy


# ---------------------------------------------------------------- 20.1 hybrid curves
@dataclass
class Hybrid:
    """``H(t) = sum_{i != m} B^n_i(t) P_i + B^n_m(t) M(t)`` (20.2) with the moving control point
    ``M(t)`` a rational Bézier curve with the weights of the original curve (20.3)."""

    points: list          # P_0..P_n (entry m is None)
    m: int
    moving: BezierCurve   # M(t)

    @property
    def degree(self) -> int:
        return len(self.points) - 1

    def evaluate(self, t) -> tuple:
        n, m = self.degree, self.m
        Mt = self.moving.evaluate(t)
        pts = np.array([list(Mt) if i == m else list(p) for i, p in enumerate(self.points)], dtype=object)
        return tuple(bz.de_casteljau(pts, t))


def hybrid_curve(curve: BezierCurve, n: int, m: int | None = None) -> Hybrid:
    """The hybrid representation of a rational curve of degree ``r`` (notes 20.1, [SK91]).

    ``P_0 = R_0``, ``P_i = R_0 + sum_{j=1}^{min(r,i)} C(r,j) C(n,i-j) w_j [R_j - P_{i-j}] / (w_0 C(n,i))``
    for ``i < m`` (20.4); the mirror formula (20.5) from the other end; and
    ``M_i = R_i + sum_{j != i} C(r,j) C(n,i+m-j) w_j [R_j - P_{i+m-j}] / (w_i C(n,m) C(r,i))`` (20.6).
    They express ``sum_{i,j} C(n,i) C(r,j) w_j (R_j - P_i) B^{n+r}_{i+j} = 0`` coefficient by
    coefficient.  ``m`` defaults to ``n // 2``; ``0 < m < n``.
    """
    if not isinstance(curve, BezierCurve):
        raise InputError("hybrid_curve needs a BezierCurve")
    r = curve.degree
    n = to_count(n, where="n", error=DegreeError)
    limits.check("max_degree", n + r, f"hybrid_curve: degree n + r = {n} + {r}")
    m = n // 2 if m is None else to_count(m, where="m", error=DegreeError)
    if not (0 < m < n):
        raise DegreeError(f"need 0 < m < n (got n = {n}, m = {m})")
    w = curve.weights_array()
    R = curve.points_array()
    C = bz.binomial
    P = [None] * (n + 1)
    P[0] = R[0]
    for i in range(1, m):
        acc = R[0] * 0
        for j in range(1, min(r, i) + 1):
            acc = acc + C(r, j) * C(n, i - j) * w[j] * (R[j] - P[i - j])
        P[i] = R[0] + acc / (w[0] * C(n, i))
    P[n] = R[r]
    for i in range(n + r - 1, m + r, -1):
        acc = R[0] * 0
        for j in range(max(0, i - n), r):
            acc = acc + C(r, j) * C(n, i - j) * w[j] * (R[j] - P[i - j])
        P[i - r] = R[r] + acc / (w[r] * C(n, i - r))
    M = []
    for i in range(r + 1):
        acc = R[0] * 0
        for j in range(max(0, i + m - n), min(i + m, r) + 1):
            if j != i:
                acc = acc + C(r, j) * C(n, i + m - j) * w[j] * (R[j] - P[i + m - j])
        M.append(R[i] + acc / (w[i] * C(n, m) * C(r, i)))
    moving = BezierCurve.from_homogeneous(np.concatenate([np.array(M, dtype=object) * w[:, None], w[:, None]], axis=1))
    P[m] = None
    return Hybrid([None if p is None else tuple(p) for p in P], m, moving)


def max_bernstein(n: int, m: int):
    """``max_{[0,1]} B^n_m = C(n,m) (m/n)^m ((n-m)/n)^(n-m)`` (at ``t = m/n``); for ``m = n/2`` it is
    ``C(n, n/2) / 2^n`` as in (20.7)."""
    n, m = to_count(n, where="n", error=DegreeError), to_count(m, where="m", error=DegreeError)
    limits.check("max_degree", n, "max_bernstein: n")
    if not (0 <= m <= n):
        raise DegreeError("need 0 <= m <= n")
    if n == 0:  # B^0_0 = 1
        return mpq(1)
    return bz.binomial(n, m) * mpq(m, n) ** m * mpq(n - m, n) ** (n - m)


@dataclass
class PolynomialApproximation:
    """Result of :func:`polynomial_approximation`: the polynomial curve ``P`` (the hybrid curve
    with ``M(t)`` frozen at the box centre), the half-box sizes ``delta`` and the bounds
    ``|x_P - x_H| <= B_xPH``, ... (20.8)-(20.9) (one per coordinate), and ``|P - H|^2 <= bound_sq`` (20.7)."""

    curve: BezierCurve
    hybrid: Hybrid
    delta: tuple
    coordinate_bounds: tuple
    bound_sq: object

    @property
    def bound(self):
        """``||Delta|| max B^n_m`` exactly (``mpq`` or ``QuadraticNumber``)."""
        return sqrt_rational(self.bound_sq)


def polynomial_approximation(curve: BezierCurve, n: int, m: int | None = None) -> PolynomialApproximation:
    """Polynomial approximation of a rational curve: replace ``M(t)`` by the centre of the
    min-max box of its control points (notes 20.1).  Positive weights keep ``M(t)`` in that
    box, so ``|P(t) - R(t)| <= ||Delta|| max B^n_m`` ((20.7) with ``C(n, n/2)/2^n`` for ``m = n/2``)."""
    if curve.is_rational and any(w <= 0 for w in curve.weights):
        raise DomainError("the box bound needs positive weights")
    hyb = hybrid_curve(curve, n, m)
    Mpts = hyb.moving.points_array()
    lo = [min(Mpts[:, k]) for k in range(Mpts.shape[1])]
    hi = [max(Mpts[:, k]) for k in range(Mpts.shape[1])]
    centre = tuple((a + b) / 2 for a, b in zip(lo, hi))
    delta = tuple((b - a) / 2 for a, b in zip(lo, hi))
    pts = [centre if p is None else p for p in hyb.points]
    bmax = max_bernstein(n, hyb.m)
    coord = tuple(d * bmax for d in delta)
    return PolynomialApproximation(BezierCurve(pts), hyb, delta, coord, sum((d * d for d in delta), mpq(0)) * bmax * bmax)


# ---------------------------------------------------------------- 20.3 bounds
def derivative_bounds(curve: BezierCurve) -> tuple:
    """(20.19)-(20.22): ``|x'| <= n max|Delta x_i|`` (polynomial), and Floater's
    ``|x'_R| <= r (max w / min w)^2 max|Delta X_i|`` (rational, positive weights)."""
    P = curve.points_array()
    n = curve.degree
    if n == 0:
        return tuple(mpq(0) for _ in range(curve.dimension))
    diffs = P[1:] - P[:-1]
    base = [n * max(abs(v) for v in diffs[:, k]) for k in range(curve.dimension)]
    if not curve.is_rational:
        return tuple(base)
    w = curve.weights
    if min(w) <= 0:
        raise DomainError("Floater's bound needs positive weights")
    f = (max(w) / min(w)) ** 2
    return tuple(b * f for b in base)


def value_bounds(curve: BezierCurve) -> tuple:
    """(20.23)-(20.26): ``|x| <= max|x_i|`` (convex hull; positive weights for rational curves)."""
    if curve.is_rational and min(curve.weights) <= 0:
        raise DomainError("the bound needs positive weights")
    P = curve.points_array()
    return tuple(max(abs(v) for v in P[:, k]) for k in range(curve.dimension))


def integration_error_bounds(curve: BezierCurve, approx: PolynomialApproximation) -> dict:
    """The bounds (20.27)-(20.30) for replacing the rational curve ``R`` by its polynomial
    approximation ``P`` in

    * ``"area"``: ``int y dx`` (20.27: ``B_xPH B_y'R + B_yPH B_x'P``),
    * ``"wedge"``: ``int R ^ R'`` (20.28; twice the sector area),
    * ``"y2dx"``: ``int y^2 dx`` (20.29; ``2 I_x`` = volume / pi),
    * ``"xydx"``: ``int x y dx`` (20.30; ``I_y``).
    """
    if curve.dimension != 2:
        raise DimensionError("planar curves only")
    bxph, byph = approx.coordinate_bounds
    bxdR, bydR = derivative_bounds(curve)
    bxdP, bydP = derivative_bounds(approx.curve)
    bxR, byR = value_bounds(curve)
    bxP, byP = value_bounds(approx.curve)
    return {
        "area": bxph * bydR + byph * bxdP,
        "wedge": bxph * (bydR + bydP) + byph * (bxdR + bxdP),
        "y2dx": 2 * bxph * bydR * byR + byph * bxdP * (byR + byP),
        "xydx": bxph * (bxdR * byR + bydR * bxR + bxdP * byP) + byph * bxdP * bxR,
    }


def _poly_integral(curve: BezierCurve, kind: str):
    if kind == "area":
        return area_under(curve)
    if kind == "sector":
        return sector_area(curve)
    ix, iy = first_moments(curve)
    return {"Ix": ix, "Iy": iy, "volume": 2 * ix}[kind]


def _bound_for(kind: str, bounds: dict):
    return {"area": bounds["area"], "sector": bounds["wedge"] / 2, "Ix": bounds["y2dx"] / 2,
            "Iy": bounds["xydx"], "volume": bounds["y2dx"]}[kind]


def rational_integral(curve: BezierCurve, kind: str = "area", tol="1/1000", n: int = 6, max_pieces: int = 4096) -> tuple:
    """Certified integral of a planar rational Bézier curve (notes 20.4).

    ``kind``: ``"area"`` (``int y dx``), ``"sector"`` (directed sector area), ``"Ix"``
    (``int y^2/2 dx``), ``"Iy"`` (``int x y dx``), ``"volume"`` (volume of revolution about the
    x axis divided by ``pi``).  The curve is split uniformly into ``2^k`` pieces (``k``
    increasing) until the sum of the piecewise bounds (20.27)-(20.30) is ``<= tol``; each
    piece is replaced by its degree-``n`` polynomial approximation and integrated exactly.
    Returns ``(value, bound)``: exact rationals with ``|true - value| <= bound``.
    A polynomial curve is integrated exactly (bound 0).
    """
    if kind not in _KINDS:
        raise InputError(f"kind must be one of {_KINDS}")
    if curve.dimension != 2:
        raise DimensionError("planar curves only")
    from ..exact.scalars import to_rational

    tol = to_rational(tol, where="tol")
    if tol <= 0:
        raise DomainError("tol must be positive")
    if not curve.is_rational:
        return _poly_integral(curve, kind), mpq(0)
    pieces = 1
    while pieces <= max_pieces:
        value, bound = mpq(0), mpq(0)
        for i in range(pieces):
            piece = curve.reparametrize(mpq(i, pieces), mpq(i + 1, pieces))
            approx = polynomial_approximation(piece, n)
            value += _poly_integral(approx.curve, kind)
            bound += _bound_for(kind, integration_error_bounds(piece, approx))
        if bound <= tol:
            return value, bound
        pieces *= 2
    raise DomainError(f"tolerance {tol} not reached with {max_pieces} pieces")

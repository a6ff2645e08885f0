"""Chapter 10 of Sederberg's notes: polynomial interpolation, error bounds, Chebyshev nodes,
interpolating points and normals -- exact.

Source: Sederberg, CAGD notes (003), 10.1 undetermined coefficients, 10.2 Lagrange,
10.3 Newton (divided differences), 10.4 Neville (Aitken's lemma), 10.6 error bounds
(10.1)-(10.6), 10.7 points and normals (Hermite).

Interpolants are :class:`PolynomialCurve` objects (power basis in the global parameter,
exact rational coefficients), convertible to Bézier form over any interval.  Chebyshev
nodes ``cos((2i+1) pi / (2n+2))`` are irrational; they are carried exactly as
:class:`~exactcagd.exact.algebraic.RealAlgebraic` roots of ``T_{n+1}``, and the
interpolant of a *polynomial* at them is exact and rational (the remainder modulo the
node polynomial).  For other functions the float nodes and an exact error bound are
offered.

>>> from exactcagd.toolbox.interpolation import neville
>>> neville([0, 1, 3, 4], [[0, 0], [3, 3], [5, 3], [7, 0]], 2)[-1][0]      # notes 10.4
(mpq(25,6), mpq(4,1))
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, DimensionError, DomainError, InputError
from ..exact import bernstein as bz
from ..exact.algebraic import RealAlgebraic, real_roots
from ..exact.scalars import to_rational, to_rational_array
from ..geometry.bezier_curve import BezierCurve
from . import _exact as ex

__all__ = [
    "PolynomialCurve",
    "undetermined_coefficients",
    "lagrange_basis",
    "lagrange_interpolate",
    "divided_differences",
    "NewtonPolynomial",
    "newton_interpolate",
    "extend_divided_differences",
    "neville",
    "node_polynomial",
    "node_polynomial_max",
    "interpolation_error_bound",
    "linear_error_bound",
    "segments_needed",
    "second_derivative_bounds",
    "bezier_segments_for_tolerance",
    "bisection_depth",
    "polyline_max_deviation_squared",
    "chebyshev_polynomial",
    "chebyshev_nodes",
    "chebyshev_nodes_float",
    "chebyshev_node_polynomial",
    "chebyshev_node_polynomial_max",
    "chebyshev_interpolant",
    "chebyshev_error_bound",
    "hermite_cubic",
    "interpolate_conditions",
    "interpolate_points_normals",
]


# ---------------------------------------------------------------- data
def _params(params, what="params") -> list:
    ts = [to_rational(t, where=what) for t in params]
    if len(set(ts)) != len(ts):
        raise InputError(f"{what}: interpolation parameters must be distinct")
    if not ts:
        raise InputError(f"{what}: empty")
    return ts


def _values(values, n, what="values") -> tuple[np.ndarray, bool]:
    arr = to_rational_array(values, where=what)
    scalar = arr.ndim == 1
    if scalar:
        arr = arr.reshape(-1, 1)
    if arr.ndim != 2 or arr.shape[0] != n:
        raise DimensionError(f"{what}: need {n} values (scalars or points), got shape {arr.shape}")
    return arr, scalar


@dataclass
class PolynomialCurve:
    """``P(t) = sum_k a_k t^k`` with exact coefficients ``a_k`` (rows of ``coefficients``).

    ``scalar`` curves (one coordinate) evaluate to numbers, others to tuples.
    """

    coefficients: np.ndarray
    scalar: bool = False

    @property
    def degree(self) -> int:
        return self.coefficients.shape[0] - 1

    def evaluate(self, t):
        t = to_rational(t, where="t")
        acc = self.coefficients[-1].copy()
        for row in self.coefficients[-2::-1]:
            acc = acc * t + row
        return acc[0] if self.scalar else tuple(acc)

    __call__ = evaluate

    def derivative(self) -> "PolynomialCurve":
        c = self.coefficients
        if c.shape[0] == 1:
            return PolynomialCurve(c * 0, self.scalar)
        return PolynomialCurve(np.array([k * c[k] for k in range(1, c.shape[0])], dtype=object), self.scalar)

    def to_bezier(self, a=0, b=1) -> BezierCurve:
        """The Bézier form of ``P`` over ``[a, b]`` (reparametrized to [0, 1])."""
        bern = bz.from_power(self.coefficients)
        return BezierCurve._trusted(bz.restrict(bern, a, b), None)

    def to_sympy(self, t=None):
        import sympy

        t = sympy.Symbol("t") if t is None else t
        comps = [sum(sympy.Rational(int(c.numerator), int(c.denominator)) * t**k for k, c in enumerate(self.coefficients[:, j]))
                 for j in range(self.coefficients.shape[1])]
        return comps[0] if self.scalar else sympy.Matrix(comps)

    def __eq__(self, other) -> bool:
        if not isinstance(other, PolynomialCurve):
            return NotImplemented
        a, b = _trim_rows(self.coefficients), _trim_rows(other.coefficients)
        return a.shape == b.shape and bool(np.all(a == b))


def _trim_rows(c):
    k = c.shape[0]
    while k > 1 and all(x == 0 for x in c[k - 1]):
        k -= 1
    return c[:k]


# ---------------------------------------------------------------- 10.1 undetermined coefficients
def undetermined_coefficients(params, values, basis: str = "power", interval=(0, 1)):
    """Solve the interpolation conditions ``P(t_i) = P_i`` as a linear system (notes 10.1).

    ``basis="power"``: returns a :class:`PolynomialCurve`; ``basis="bernstein"``: the
    Bernstein coefficients over ``interval`` as a :class:`BezierCurve` (the notes'
    direct solve for the Bézier control points).
    """
    ts = _params(params)
    V, scalar = _values(values, len(ts))
    n = len(ts) - 1
    if basis == "power":
        A = [[t**k for k in range(n + 1)] for t in ts]
        return PolynomialCurve(ex.solve(A, V.tolist(), "undetermined coefficients"), scalar)
    if basis == "bernstein":
        a, b = (to_rational(x) for x in interval)
        if a == b:
            raise DomainError("empty interval")
        us = [(t - a) / (b - a) for t in ts]
        A = [[bz.binomial(n, i) * u**i * (1 - u) ** (n - i) for i in range(n + 1)] for u in us]
        return BezierCurve._trusted(ex.solve(A, V.tolist(), "undetermined coefficients (Bernstein)"), None)
    raise InputError(f"basis must be 'power' or 'bernstein', got {basis!r}")


# ---------------------------------------------------------------- 10.2 Lagrange
def lagrange_basis(params) -> list[PolynomialCurve]:
    """``L_i(t) = prod_{j != i} (t - t_j) / (t_i - t_j)`` (notes 10.2) as scalar curves."""
    ts = _params(params)
    out = []
    for i, ti in enumerate(ts):
        p = [mpq(1)]
        den = mpq(1)
        for j, tj in enumerate(ts):
            if j != i:
                p = ex.pmul(p, [-tj, mpq(1)])
                den *= ti - tj
        out.append(PolynomialCurve(np.array([[c / den] for c in p], dtype=object), True))
    return out


def lagrange_interpolate(params, values) -> PolynomialCurve:
    """``P(t) = sum_i P_i L_i(t)``."""
    ts = _params(params)
    V, scalar = _values(values, len(ts))
    L = lagrange_basis(ts)
    coeffs = sum((L[i].coefficients * V[i][None, :] for i in range(len(ts))), start=np.zeros((len(ts), V.shape[1]), dtype=object) * mpq(0))
    return PolynomialCurve(coeffs, scalar)


# ---------------------------------------------------------------- 10.3 Newton
def divided_differences(params, values) -> list[list]:
    """Divided-difference table (notes 10.3): column ``k`` holds ``f_{i,...,i+k}``.

    ``f_i = y_i``; ``f_{i..k} = (f_{i+1..k} - f_{i..k-1}) / (t_k - t_i)``.  Entries are
    numbers or tuples (points).
    """
    ts = _params(params)
    V, scalar = _values(values, len(ts))
    col = [V[i] for i in range(len(ts))]
    table = [col]
    for k in range(1, len(ts)):
        prev = table[-1]
        table.append([(prev[i + 1] - prev[i]) / (ts[i + k] - ts[i]) for i in range(len(ts) - k)])
    return [[(c[0] if scalar else tuple(c)) for c in column] for column in table]


@dataclass
class NewtonPolynomial:
    """``p(t) = a_0 + a_1 (t - t_0) + ... + a_n (t - t_0)...(t - t_{n-1})`` (notes 10.3)."""

    nodes: list
    coefficients: list
    scalar: bool

    def evaluate(self, t):
        """Nested multiplication, O(n)."""
        t = to_rational(t, where="t")
        acc = np.array(self.coefficients[-1], dtype=object).reshape(-1)
        for a, node in zip(reversed(self.coefficients[:-1]), reversed(self.nodes[: len(self.coefficients) - 1])):
            acc = acc * (t - node) + np.array(a, dtype=object).reshape(-1)
        return acc[0] if self.scalar else tuple(acc)

    __call__ = evaluate

    def to_power(self) -> PolynomialCurve:
        d = len(np.array(self.coefficients[0], dtype=object).reshape(-1))
        total = np.zeros((len(self.coefficients), d), dtype=object) * mpq(0)
        basis = [mpq(1)]
        for k, a in enumerate(self.coefficients):
            a = np.array(a, dtype=object).reshape(-1)
            for j, c in enumerate(basis):
                total[j] = total[j] + c * a
            if k < len(self.nodes) - 1:
                basis = ex.pmul(basis, [-self.nodes[k], mpq(1)])
        return PolynomialCurve(total, self.scalar)


def newton_interpolate(params, values) -> NewtonPolynomial:
    """Newton form with ``a_k = f_{0,...,k}`` (the top diagonal of the table)."""
    ts = _params(params)
    table = divided_differences(ts, values)
    scalar = not isinstance(table[0][0], tuple)
    return NewtonPolynomial(ts, [column[0] for column in table], scalar)


def extend_divided_differences(params, values, t_new) -> dict:
    """Evaluate at ``t_new`` directly from the table (notes 10.3, second example).

    A new row ``t_new | c_n ... c_1 c_0 | f_{...}`` is appended, using that the last
    column (order ``n``) is constant; solving each divided-difference equation for the
    unknown gives ``c_0``, ``c_1``, ..., and finally ``P(t_new) = c_{n-1}``.
    Returns ``{"c": [c_0, c_1, ...], "value": P(t_new)}`` (``c`` from the highest order down).
    """
    ts = _params(params)
    tn = to_rational(t_new)
    table = divided_differences(ts, values)
    n = len(ts) - 1
    as_arr = lambda v: np.array(v, dtype=object).reshape(-1)  # noqa: E731
    scalar = not isinstance(table[0][0], tuple)
    # entry of order k in the new row uses nodes t_{n-k+1}, ..., t_n, t_new
    if n == 0:
        return {"c": [], "value": table[0][0]}
    new = {n: as_arr(table[n][0])}
    cs = []
    for k in range(n - 1, -1, -1):
        # new[k] = f[t_{n-k+1}, ..., t_n, t_new] (order k).  The order-(k+1) entry satisfies
        # new[k+1] = (new[k] - f[t_{n-k}, ..., t_n]) / (t_new - t_{n-k}); solve for new[k].
        left = as_arr(table[k][-1])
        new[k] = left + new[k + 1] * (tn - ts[n - k])
        cs.append(new[k][0] if scalar else tuple(new[k]))
    return {"c": cs, "value": cs[-1]}


# ---------------------------------------------------------------- 10.4 Neville
def neville(params, values, tau) -> list[list]:
    """Neville's scheme (notes 10.4) at ``tau``: all levels ``p_{i..i+k}(tau)``; the last
    level holds ``p(tau)``.

    Aitken's lemma: ``p_{i..k} = ((t_k - tau) p_{i..k-1} - (t_i - tau) p_{i+1..k}) / (t_k - t_i)``.
    """
    ts = _params(params)
    V, scalar = _values(values, len(ts))
    tau = to_rational(tau, where="tau")
    level = [V[i] for i in range(len(ts))]
    levels = [level]
    for k in range(1, len(ts)):
        level = [((ts[i + k] - tau) * level[i] - (ts[i] - tau) * level[i + 1]) / (ts[i + k] - ts[i]) for i in range(len(level) - 1)]
        levels.append(level)
    return [[(v[0] if scalar else tuple(v)) for v in lev] for lev in levels]


# ---------------------------------------------------------------- 10.6 error bounds
def node_polynomial(nodes) -> list:
    """Power coefficients of ``omega(x) = (x - x_0)(x - x_1)...(x - x_n)``."""
    p = [mpq(1)]
    for x in (to_rational(v) for v in nodes):
        p = ex.pmul(p, [-x, mpq(1)])
    return p


def node_polynomial_max(nodes, a, b) -> RealAlgebraic:
    """Exact ``max_{a <= x <= b} |omega(x)|`` (a real algebraic number)."""
    p = node_polynomial(nodes)
    hi, _ = ex.poly_max(p, a, b)
    lo, _ = ex.poly_min(p, a, b)
    neg = ex.negate(lo)
    return hi if hi >= neg else neg


def interpolation_error_bound(derivative_bound, nodes, x):
    """(10.1): ``|f(x) - p(x)| <= M / (n + 1)! |prod (x - x_i)|`` with ``M >= |f^(n+1)|``."""
    M = to_rational(derivative_bound, where="derivative bound")
    nodes = [to_rational(v) for v in nodes]
    x = to_rational(x)
    w = mpq(1)
    for xi in nodes:
        w *= x - xi
    return M / math.factorial(len(nodes)) * abs(w)


def linear_error_bound(second_derivative_bound, delta):
    """``|f - p_1| <= L delta^2 / 8`` (notes 10.6, with ``L >= |f''|``)."""
    L, d = to_rational(second_derivative_bound), to_rational(delta)
    return L * d * d / 8


def _ceil_root(x, k: int) -> int:
    """Smallest integer ``m >= 0`` with ``m^k >= x`` (exact, ``x`` rational)."""
    x = to_rational(x)
    if x <= 0:
        return 0
    m = max(0, int(math.floor(float(x) ** (1.0 / k))) - 2)
    while mpq(m) ** k < x:
        m += 1
    while m > 0 and mpq(m - 1) ** k >= x:
        m -= 1
    return m


def segments_needed(second_derivative_bound, eps, length) -> int:
    """Smallest ``m`` with ``m >= sqrt(L / (8 eps)) (x_1 - x_0)`` (notes 10.6), exactly."""
    L, e, ln = (to_rational(v) for v in (second_derivative_bound, eps, length))
    if e <= 0:
        raise DomainError("the tolerance must be positive")
    return max(1, _ceil_root(L * ln * ln / (8 * e), 2))


def second_derivative_bounds(curve: BezierCurve) -> tuple:
    """(10.2)-(10.3): ``L_k = n (n - 1) max_i |P_{i+2,k} - 2 P_{i+1,k} + P_{i,k}|`` per coordinate."""
    if curve.is_rational:
        raise InputError("second_derivative_bounds needs a polynomial curve")
    n = curve.degree
    P = curve.points_array()
    if n < 2:
        return tuple(mpq(0) for _ in range(curve.dimension))
    second = P[2:] - 2 * P[1:-1] + P[:-2]
    return tuple(n * (n - 1) * max(abs(x) for x in second[:, k]) for k in range(curve.dimension))


def bezier_segments_for_tolerance(curve: BezierCurve, eps) -> int:
    """Smallest ``m`` with ``m >= sqrt(sqrt(L_x^2 + L_y^2) / (8 eps))`` (notes 10.6): ``m^4 >= |L|^2 / (64 eps^2)``."""
    e = to_rational(eps)
    if e <= 0:
        raise DomainError("the tolerance must be positive")
    L2 = sum((L * L for L in second_derivative_bounds(curve)), mpq(0))
    return max(1, _ceil_root(L2 / (64 * e * e), 4))


def bisection_depth(curve: BezierCurve, eps) -> int:
    """(10.4): ``r = ceil(log2 sqrt(sqrt(L_x^2 + L_y^2) / (8 eps)))``: smallest ``r`` with ``(2^r)^4 >= |L|^2 / (64 eps^2)``."""
    e = to_rational(eps)
    if e <= 0:
        raise DomainError("the tolerance must be positive")
    L2 = sum((L * L for L in second_derivative_bounds(curve)), mpq(0))
    target = L2 / (64 * e * e)
    r = 0
    while mpq(2) ** (4 * r) < target:
        r += 1
    return r


def polyline_max_deviation_squared(curve: BezierCurve, m: int) -> RealAlgebraic:
    """Exact ``max_t |P(t) - L(t)|^2`` where ``L`` interpolates ``P`` linearly at ``t = i/m``.

    (This is the deviation in the parametric sense that the bounds of notes 10.6 control.)
    """
    if curve.is_rational:
        raise InputError("polyline deviation needs a polynomial curve")
    if m < 1:
        raise InputError("m must be >= 1")
    best = None
    for i in range(m):
        a, b = mpq(i, m), mpq(i + 1, m)
        piece = bz.restrict(curve.points_array(), a, b)  # on s in [0, 1]
        chord = bz.elevate(np.stack([piece[0], piece[-1]]), curve.degree - 1) if curve.degree > 1 else piece
        D = bz.to_power(piece - chord)
        total = [mpq(0)]
        for k in range(D.shape[1]):
            total = ex.padd(total, ex.pmul(list(D[:, k]), list(D[:, k])))
        value, _ = ex.poly_max(total, 0, 1)
        if best is None or value > best:
            best = value
    return best


# ---------------------------------------------------------------- 10.6.1 Chebyshev
def chebyshev_polynomial(k: int) -> list:
    """Power coefficients of ``T_k`` (``T_0 = 1``, ``T_1 = s``, ``T_{k+1} = 2 s T_k - T_{k-1}``)."""
    if k < 0:
        raise InputError("k must be >= 0")
    a, b = [mpq(1)], [mpq(0), mpq(1)]
    if k == 0:
        return a
    for _ in range(k - 1):
        a, b = b, ex.padd(ex.pscale([mpq(0)] + b, 2), ex.pscale(a, -1))
    return b


def _affine_compose(p, a, b) -> list:
    """Coefficients of ``p((2x - a - b) / (b - a))`` in ``x``."""
    lin = [-(a + b) / (b - a), 2 / (b - a)]
    out = [mpq(0)]
    power = [mpq(1)]
    for c in p:
        out = ex.padd(out, ex.pscale(power, c))
        power = ex.pmul(power, lin)
    return out


def chebyshev_node_polynomial(n: int, a=-1, b=1) -> list:
    """Monic ``omega(x) = prod (x - x_i)`` over the ``n + 1`` Chebyshev nodes of ``[a, b]``:
    ``((b - a)/2)^(n+1) 2^-n T_{n+1}((2x - a - b)/(b - a))``, exact rational coefficients."""
    a, b = to_rational(a), to_rational(b)
    if a >= b:
        raise DomainError("need a < b")
    T = chebyshev_polynomial(n + 1)
    scale = ((b - a) / 2) ** (n + 1) / mpq(2) ** n
    return [c * scale for c in _affine_compose(T, a, b)]


def chebyshev_nodes(n: int, a=-1, b=1) -> list[RealAlgebraic]:
    """The ``n + 1`` Chebyshev points ``(a + b)/2 + (b - a)/2 cos((2i + 1) pi / (2n + 2))``, ``i = 0..n``
    (notes (10.6), which prints ``i = 0..n-1``), exactly, in increasing order."""
    roots = real_roots(chebyshev_node_polynomial(n, a, b))
    if len(roots) != n + 1 or any(m != 1 for _, m in roots):  # pragma: no cover - T_{n+1} has n+1 simple roots
        raise AssertionError("Chebyshev root isolation failed")
    return [r for r, _ in roots]


def chebyshev_nodes_float(n: int, a=-1.0, b=1.0) -> list[float]:
    """The same nodes in floating point (cos is irrational: these are approximations)."""
    a, b = float(a), float(b)
    return sorted((a + b) / 2 + (b - a) / 2 * math.cos((2 * i + 1) * math.pi / (2 * n + 2)) for i in range(n + 1))


def chebyshev_node_polynomial_max(n: int, a=-1, b=1):
    """``max |omega| = 2 ((b - a)/4)^(n+1)`` over ``[a, b]`` (exact; the notes print exponent ``n``)."""
    a, b = to_rational(a), to_rational(b)
    return 2 * ((b - a) / 4) ** (n + 1)


def chebyshev_interpolant(f_coeffs, n: int, a=-1, b=1) -> PolynomialCurve:
    """The degree-``<= n`` interpolant of the polynomial ``f`` at the ``n + 1`` Chebyshev nodes.

    Interpolating at the roots of ``omega`` is the remainder of ``f`` modulo ``omega``:
    exact, with rational coefficients, although the nodes are irrational.
    """
    import flint

    f = [to_rational(c) for c in f_coeffs]
    w = chebyshev_node_polynomial(n, a, b)
    fq = flint.fmpq_poly([flint.fmpq(int(c.numerator), int(c.denominator)) for c in f])
    wq = flint.fmpq_poly([flint.fmpq(int(c.numerator), int(c.denominator)) for c in w])
    r = fq % wq
    coeffs = [mpq(int(c.p), int(c.q)) for c in r.coeffs()] or [mpq(0)]
    coeffs += [mpq(0)] * (n + 1 - len(coeffs))
    return PolynomialCurve(np.array([[c] for c in coeffs], dtype=object), True)


def chebyshev_error_bound(derivative_bound, n: int, a=-1, b=1):
    """(10.5) with Chebyshev nodes: ``|f - p| <= M / (n + 1)! * 2 ((b - a)/4)^(n+1)``, exact."""
    M = to_rational(derivative_bound)
    return M / math.factorial(n + 1) * chebyshev_node_polynomial_max(n, a, b)


# ---------------------------------------------------------------- 10.7 points and normals
def hermite_cubic(p0, p1, d0, d1) -> BezierCurve:
    """The cubic Hermite curve (notes 10.7) in Bézier form: ``P0, P0 + d0/3, P1 - d1/3, P1``."""
    P0, P1, D0, D1 = (to_rational_array(v, where="hermite data") for v in (p0, p1, d0, d1))
    return BezierCurve._trusted(np.stack([P0, P0 + D0 / 3, P1 - D1 / 3, P1]), None)


def interpolate_conditions(degree: int, conditions, dimension: int | None = None) -> tuple[PolynomialCurve, list]:
    """Undetermined coefficients with derivative and normal conditions (notes 10.7).

    ``conditions``: tuples ``(t, k, value)`` meaning ``P^(k)(t) = value`` (a point or
    vector), or ``(t, "normal", n)`` meaning ``P'(t) . n = 0``.  Returns the particular
    solution (free coefficients 0) and a basis of the homogeneous solutions (curves
    satisfying the conditions with zero right sides); an empty basis means the conditions
    determine the curve.  Inconsistent conditions raise :class:`InputError`.
    """
    if degree < 0:
        raise DegreeError("degree must be >= 0")
    conds = []
    for c in conditions:
        if len(c) != 3:
            raise InputError(f"condition {c!r}: expected (t, order, value) or (t, 'normal', n)")
        t, kind, value = c
        conds.append((to_rational(t), kind, [to_rational(v) for v in value]))
    dims = {len(v) for _, _, v in conds}
    if dimension is not None:
        dims.add(dimension)
    if len(dims) != 1:
        raise DimensionError("conditions of different dimensions")
    d = dims.pop()
    m = degree + 1
    rows, rhs = [], []

    def deriv_row(t, k):
        # coefficient of a_j in P^(k)(t)
        return [(math.perm(j, k) * t ** (j - k) if j >= k else 0) for j in range(m)]

    for t, kind, value in conds:
        if kind == "normal":
            r = deriv_row(t, 1)
            row = [mpq(0)] * (m * d)
            for j in range(m):
                for c in range(d):
                    row[j * d + c] = r[j] * value[c]
            rows.append(row)
            rhs.append(mpq(0))
        else:
            k = int(kind)
            r = deriv_row(t, k)
            for c in range(d):
                row = [mpq(0)] * (m * d)
                for j in range(m):
                    row[j * d + c] = mpq(r[j])
                rows.append(row)
                rhs.append(value[c])
    x, null = ex.solve_general(rows, rhs)
    shape = lambda v: PolynomialCurve(np.array(v, dtype=object).reshape(m, d))  # noqa: E731
    return shape(x), [shape(v) for v in null]


def interpolate_points_normals(params, points, normals, degree: int) -> tuple[PolynomialCurve, list]:
    """Curves of the given degree through ``points`` at ``params`` with the given normals there
    (``P(t_i) = P_i``, ``P'(t_i) . n_i = 0``); returns the family as in :func:`interpolate_conditions`.

    Normals fix tangent *directions* only, so the family keeps one free tangent length per
    point unless the degree is too low to leave any freedom.
    """
    ts = _params(params)
    conds = [(t, 0, p) for t, p in zip(ts, points)] + [(t, "normal", n) for t, n in zip(ts, normals)]
    return interpolate_conditions(degree, conds)

"""Chapter 4 of Sederberg's notes: forward differencing, exact and in floating point.

Source: Sederberg, CAGD notes (003), chapter 4 (difference tables, ``R_right = R + R_down``,
initial differences of power-basis polynomials) and 4.1 (choosing delta for gap-free
rasterization).

A degree-``n`` polynomial sampled at evenly spaced parameters ``t_i = t0 + i delta`` has a
constant ``n``-th difference, so after ``n + 1`` evaluations every further value costs
``n`` additions.  In exact rational arithmetic the scheme is exact forever.  In floating
point the additions accumulate rounding errors that grow like ``k^n``;
:func:`forward_difference_float` returns the float values together with a rigorous
running error bound (computed in rationals from the float values alone) and
:func:`float_error_report` compares both with the exact values.

>>> from exactcagd.toolbox.forward_diff import extend
>>> extend([1, 3, 2, 5, 4], 3)                       # notes chapter 4: -24, -117, -328
[mpq(-24,1), mpq(-117,1), mpq(-328,1)]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from gmpy2 import mpq

from .. import limits
from ..errors import DegreeError, DomainError, InputError
from ..exact import bernstein as bz
from ..exact.scalars import to_count, to_rational
from ..geometry.bezier_curve import BezierCurve
from . import _exact as ex

__all__ = [
    "difference_table",
    "extend",
    "initial_differences",
    "power_initial_differences",
    "forward_difference",
    "forward_difference_float",
    "FloatRun",
    "float_error_report",
    "solve_missing",
    "rasterization_steps",
    "rasterize",
    "pixels_connected",
]

#: unit roundoff of binary64, round to nearest
_U = mpq(1, 2**53)


def _values(values, what="values") -> list:
    if isinstance(values, (str, bytes, bytearray)) or not hasattr(values, "__iter__"):
        raise InputError(f"{what}: expected a sequence of numbers, got {type(values).__name__}")
    out = [to_rational(v, where=what) if v is not None else None for v in values]
    if not out:
        raise InputError(f"{what}: empty")
    return out


def difference_table(values) -> list[list]:
    """Rows ``[f(t_i)...], [Delta_1(t_i)...], ...`` down to a single entry (notes chapter 4)."""
    rows = [_values(values)]
    while len(rows[-1]) > 1:
        prev = rows[-1]
        rows.append([b - a for a, b in zip(prev[:-1], prev[1:])])
    return rows


def initial_differences(values, degree: int | None = None) -> list:
    """``[f(t_0), Delta_1(t_0), ..., Delta_n(t_0)]`` from ``n + 1`` evenly spaced values."""
    vals = _values(values)
    n = len(vals) - 1 if degree is None else degree
    if len(vals) < n + 1:
        raise InputError(f"a degree-{n} polynomial needs {n + 1} values to start, got {len(vals)}")
    table = difference_table(vals)
    for row in table[n + 1:]:
        if any(x != 0 for x in row):
            raise DegreeError(f"the values are not those of a polynomial of degree <= {n}")
    return [table[j][0] for j in range(n + 1)]


def _run(diffs: list, count: int) -> list:
    """Generate ``count`` further values from the current column ``[f, D1, ..., Dn]``."""
    d = list(diffs)
    out = []
    for _ in range(count):
        for j in range(len(d) - 1):
            d[j] = d[j] + d[j + 1]
        out.append(d[0])
    return out


def extend(values, count: int, degree: int | None = None) -> list:
    """The next ``count`` values of the polynomial through ``values`` (evenly spaced).

    Fill the difference table with ``R_right = R + R_down`` (notes chapter 4).
    """
    count = to_count(count, where="count")
    limits.check("max_control_points", count, "extend: count")
    vals = _values(values)
    if any(v is None for v in vals):
        raise InputError("values: unknown values (None) cannot be extended; see solve_missing")
    n = len(vals) - 1 if degree is None else to_count(degree, where="degree", error=DegreeError)
    table = difference_table(vals)
    for row in table[n + 1:]:
        if any(x != 0 for x in row):
            raise DegreeError(f"the values are not those of a polynomial of degree <= {n}")
    # the anti-diagonal f(t_m), Delta_1(t_{m-1}), ..., Delta_n(t_{m-n}); each new value fills
    # it from the bottom up: Delta_j(t_{m-j+1}) = Delta_j(t_{m-j}) + Delta_{j+1}(t_{m-j})
    diag = [table[j][-1] for j in range(n + 1)]
    out = []
    for _ in range(count):
        for j in range(n - 1, -1, -1):
            diag[j] = diag[j] + diag[j + 1]
        out.append(diag[0])
    return out


def power_initial_differences(a, t0, delta) -> list:
    """Closed-form ``Delta_j(t0) = sum_k (-1)^(j-k) C(j,k) f(t0 + k delta)`` for power coefficients ``a``.

    For ``t0 = 0`` and a cubic this is the notes' ``Delta_1 = a1 d + a2 d^2 + a3 d^3``,
    ``Delta_2 = 2 a2 d^2 + 6 a3 d^3``, ``Delta_3 = 6 a3 d^3``.
    """
    a = [to_rational(x) for x in a]
    t0, delta = to_rational(t0), to_rational(delta)
    n = len(a) - 1
    f = [ex.peval(a, t0 + k * delta) for k in range(n + 1)]
    return [sum((((-1) ** (j - k)) * bz.binomial(j, k) * f[k] for k in range(j + 1)), mpq(0)) for j in range(n + 1)]


def _evaluator(poly, basis):
    if isinstance(poly, BezierCurve):
        if poly.is_rational:
            raise InputError("forward differencing applies to polynomials; for a rational curve difference the homogeneous components")
        pts = poly.points_array()
        return lambda t: np.array(bz.de_casteljau(pts, t), dtype=object), poly.degree
    c = bz.as_coefficients(poly, "polynomial")
    n = c.shape[0] - 1
    limits.check("max_degree", n, "polynomial: degree")
    if basis == "bernstein":
        return lambda t: bz.de_casteljau(c, t), n
    if basis == "power":
        return lambda t: ex.peval(list(c), t), n
    raise InputError(f"basis must be 'power' or 'bernstein', got {basis!r}")


def forward_difference(poly, t0, delta, count: int, basis: str = "power") -> list:
    """Exact values at ``t0, t0 + delta, ..., t0 + (count - 1) delta``.

    ``poly``: power coefficients (``basis="power"``), Bernstein coefficients on [0, 1]
    (``basis="bernstein"``) or a polynomial :class:`BezierCurve` (points; then each
    value is a point).  Only ``n + 1`` evaluations, then additions.
    """
    f, n = _evaluator(poly, basis)
    t0, delta = to_rational(t0), to_rational(delta)
    count = to_count(count, where="count")
    limits.check("max_control_points", count, "forward_difference: count")
    start = [f(t0 + k * delta) for k in range(n + 1)]
    table = [start]
    while len(table[-1]) > 1:
        prev = table[-1]
        table.append([b - a for a, b in zip(prev[:-1], prev[1:])])
    column = [row[0] for row in table]
    out = [column[0]] + _run(column, max(count - 1, 0))
    return out[:count]


@dataclass
class FloatRun:
    """Float forward differencing with a rigorous running error bound.

    ``values[i]`` is the float result at ``t0 + i delta``; ``bounds[i]`` an exact rational
    ``B_i >= |values[i] - f(t0 + i delta)|``, propagated from ``|fl(a + b) - (a + b)|
    <= u |fl(a + b)| / (1 - u)`` (``u = 2^-53``) through every addition, starting from the
    rounding errors of the exact initial differences.
    """

    values: list
    bounds: list


def forward_difference_float(poly, t0, delta, count: int, basis: str = "power") -> FloatRun:
    """Forward differencing in binary64 (scalar polynomials), with a certified error bound."""
    f, n = _evaluator(poly, basis)
    t0, delta = to_rational(t0), to_rational(delta)
    start = [f(t0 + k * delta) for k in range(n + 1)]
    if isinstance(start[0], np.ndarray):
        raise InputError("forward_difference_float works on scalar polynomials (difference each coordinate)")
    column = initial_differences(start, n)
    d = [float(x) for x in column]  # correctly rounded from the exact values
    e = [abs(mpq(*x.as_integer_ratio()) - c) for x, c in zip(d, column)]
    values, bounds = [d[0]], [e[0]]
    rel = _U / (1 - _U)
    for _ in range(count - 1):
        for j in range(n):
            d[j] = d[j] + d[j + 1]
            e[j] = e[j] + e[j + 1] + rel * abs(mpq(*d[j].as_integer_ratio()))
        values.append(d[0])
        bounds.append(e[0])
    if not all(math.isfinite(v) for v in values):
        raise DomainError("float overflow during forward differencing")
    return FloatRun(values[:count], bounds[:count])


def float_error_report(poly, t0, delta, count: int, basis: str = "power") -> dict:
    """Exact comparison of float forward differencing with exact evaluation.

    Returns ``{"max_error", "max_bound", "max_error_at", "errors", "bounds"}``; all
    rationals (the float values are converted exactly).  ``errors[i] <= bounds[i]`` always.
    """
    exact = forward_difference(poly, t0, delta, count, basis)
    run = forward_difference_float(poly, t0, delta, count, basis)
    errors = [abs(mpq(*v.as_integer_ratio()) - x) for v, x in zip(run.values, exact)]
    k = max(range(len(errors)), key=lambda i: errors[i]) if errors else 0
    return {"max_error": max(errors, default=mpq(0)), "max_error_at": k, "max_bound": max(run.bounds, default=mpq(0)),
            "errors": errors, "bounds": run.bounds}


def solve_missing(values, degree: int) -> list:
    """Fill the ``None`` entries of evenly spaced samples of a degree-``degree`` polynomial.

    Every window of ``degree + 2`` consecutive samples has ``Delta_{degree+1} = 0`` (notes
    chapter 4, example ``f(4) = 8``); the linear equations are solved exactly and must
    determine the unknowns uniquely.
    """
    vals = _values(values)
    unknown = [i for i, v in enumerate(vals) if v is None]
    m = degree + 2
    if len(vals) < m:
        raise InputError(f"need at least {m} samples for degree {degree}")
    rows, rhs = [], []
    for s in range(len(vals) - m + 1):
        coeffs = [((-1) ** (m - 1 - k)) * bz.binomial(m - 1, k) for k in range(m)]
        row = [mpq(0)] * len(unknown)
        const = mpq(0)
        for k, c in enumerate(coeffs):
            i = s + k
            if vals[i] is None:
                row[unknown.index(i)] += c
            else:
                const += c * vals[i]
        rows.append(row)
        rhs.append(-const)
    if not unknown:
        if any(r != 0 for r in rhs):
            raise DegreeError(f"the samples are not those of a polynomial of degree <= {degree}")
        return vals
    x, null = ex.solve_general(rows, rhs)
    if null:
        raise InputError("the missing values are not determined uniquely")
    if any(sum((a * b for a, b in zip(r, x)), mpq(0)) != c for r, c in zip(rows, rhs)):  # pragma: no cover
        raise DegreeError("inconsistent samples")
    out = list(vals)
    for i, v in zip(unknown, x):
        out[i] = v
    return out


# ---------------------------------------------------------------- 4.1 choosing delta
def rasterization_steps(curve: BezierCurve) -> int:
    """Number of steps ``ceil(n d)`` with ``d = max_i max(|x_i - x_{i-1}|, |y_i - y_{i-1}|)``
    (notes 4.1, with absolute values): ``n d`` bounds ``|x'|`` and ``|y'|`` (hodograph), so
    consecutive samples at ``delta = 1 / ceil(n d)`` differ by at most one pixel per axis."""
    if curve.is_rational or curve.dimension != 2:
        raise InputError("rasterization_steps needs a planar polynomial curve (pixel coordinates)")
    P = curve.control_points
    n = curve.degree
    d = max((max(abs(b[0] - a[0]), abs(b[1] - a[1])) for a, b in zip(P[:-1], P[1:])), default=mpq(0))
    return max(1, int(math.ceil(n * d)))


def _round_half_up(x) -> int:
    return int(math.floor(x + mpq(1, 2)))


def rasterize(curve: BezierCurve, steps: int | None = None) -> list:
    """Pixels ``round(P(i / steps))``, exact (forward differencing of the coordinates), ``i = 0..steps``."""
    steps = rasterization_steps(curve) if steps is None else to_count(steps, where="steps")
    if steps < 1:
        raise InputError(f"steps must be a positive integer, got {steps}")
    pts = forward_difference(curve, 0, mpq(1, steps), steps + 1)
    return [(_round_half_up(p[0]), _round_half_up(p[1])) for p in pts]


def pixels_connected(pixels) -> bool:
    """No gaps: consecutive pixels are equal or 8-neighbours."""
    return all(abs(a[0] - b[0]) <= 1 and abs(a[1] - b[1]) <= 1 for a, b in zip(pixels[:-1], pixels[1:]))

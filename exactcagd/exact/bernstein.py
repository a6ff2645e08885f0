"""Exact Bernstein-polynomial arithmetic.

A Bernstein polynomial of degree ``n`` is stored as a numpy object array ``c`` whose
axis 0 holds the ``n + 1`` Bernstein coefficients; any trailing axes are carried along
(so the same functions act on scalars, on control points and on homogeneous points).
Entries are exact rationals (``gmpy2.mpq``) or anything closed under ``+ - *``.
Tensor-product (bivariate) arrays use axes 0 and 1; :func:`along` applies any
univariate operation along a chosen axis.

Sources: Sederberg's CAGD notes (003), sections 2.2-2.7 (de Casteljau, subdivision,
degree elevation, hodograph), 3.2-3.3 (Horner in Bernstein form, basis conversion),
6.1 (polar form), 9.3 (products), 2.15 (integrals).

>>> from exactcagd.exact.bernstein import as_coefficients, de_casteljau
>>> c = as_coefficients([0, 1, 0])         # 2 t (1 - t)
>>> de_casteljau(c, "1/2")
mpq(1,2)
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from gmpy2 import bincoef, mpq, mpz

from .. import limits
from ..errors import DegreeError, InputError
from .scalars import from_fmpq, to_fmpq, to_rational, to_rational_array

__all__ = [
    "as_coefficients",
    "binomial",
    "de_casteljau",
    "de_casteljau_triangle",
    "horner_bernstein",
    "subdivide",
    "elevate",
    "reduce_degree",
    "true_degree",
    "derivative",
    "product",
    "antiderivative",
    "integral",
    "to_power",
    "from_power",
    "scaled_to_power",
    "power_to_scaled",
    "blossom",
    "restrict",
    "along",
    "product_tensor",
]


@lru_cache(maxsize=None)
def binomial(n: int, k: int) -> int:
    """Binomial coefficient C(n, k) as a Python int (0 outside ``0 <= k <= n``)."""
    if k < 0 or k > n:
        return 0
    return int(bincoef(n, k))


def as_coefficients(values, where: str = "coefficients") -> np.ndarray:
    """Convert user coefficients to an exact object array (axis 0 = Bernstein index)."""
    array = to_rational_array(values, where=where)
    if array.ndim == 0 or array.shape[0] == 0:
        raise InputError(f"{where}: need at least one Bernstein coefficient")
    return array


def _param(t):
    return to_rational(t, where="parameter")


def de_casteljau_triangle(c: np.ndarray, t) -> list[np.ndarray]:
    """All levels of the de Casteljau algorithm at ``t`` (notes 2.3).

    Level ``r`` holds ``n + 1 - r`` points; the last level is the value ``c(t)``.
    """
    t = _param(t)
    s = 1 - t
    levels = [c]
    while levels[-1].shape[0] > 1:
        prev = levels[-1]
        levels.append(s * prev[:-1] + t * prev[1:])
    return levels


def de_casteljau(c: np.ndarray, t):
    """Evaluate the Bernstein polynomial at ``t`` by de Casteljau's algorithm (notes 2.3)."""
    return de_casteljau_triangle(c, t)[-1][0]


def horner_bernstein(c: np.ndarray, t):
    """Evaluate by Horner's rule in Bernstein form (notes 3.2).

    For ``t <= 1/2``: ``p(t) = (1-t)^n sum_i C(n,i) c_i s^i`` with ``s = t/(1-t)``;
    for ``t > 1/2`` the mirror form in ``(1-t)/t`` is used, so the ratio never exceeds 1.
    """
    t = _param(t)
    n = c.shape[0] - 1
    if t == 1:
        return c[-1]
    if t <= mpq(1, 2):
        s, scale, coeffs = t / (1 - t), (1 - t) ** n, c[::-1]
        index = range(n, -1, -1)
    else:
        s, scale, coeffs = (1 - t) / t, t**n, c
        index = range(0, n + 1)
    acc = None
    for k, i in enumerate(index):
        term = binomial(n, i) * coeffs[k]
        acc = term if acc is None else acc * s + term
    return acc * scale


def subdivide(c: np.ndarray, t) -> tuple[np.ndarray, np.ndarray]:
    """Split at ``t``: coefficients of the pieces on [0, t] and [t, 1] (notes 2.3).

    Each piece is reparametrized to [0, 1].
    """
    levels = de_casteljau_triangle(c, t)
    left = np.stack([level[0] for level in levels])
    right = np.stack([level[-1] for level in reversed(levels)])
    return left, right


def elevate(c: np.ndarray, r: int = 1) -> np.ndarray:
    """Degree elevation by ``r`` (notes 2.5): same polynomial, degree ``n + r``.

    Uses the closed form ``c'_k = sum_i C(n,i) C(r,k-i) / C(n+r,k) c_i``.
    """
    if r < 0:
        raise DegreeError(f"elevation by a negative amount ({r}); use reduce_degree")
    limits.check("max_degree", c.shape[0] - 1 + r, f"degree elevation by r = {r} of degree {c.shape[0] - 1}")
    if r == 0:
        return c.copy()
    n = c.shape[0] - 1
    out = np.empty((n + r + 1,) + c.shape[1:], dtype=object)
    for k in range(n + r + 1):
        lo, hi = max(0, k - r), min(n, k)
        acc = sum((binomial(n, i) * binomial(r, k - i) * c[i] for i in range(lo, hi + 1)), start=c[0] * 0)
        out[k] = acc * mpq(1, binomial(n + r, k))
    return _zeros_to_mpq(out)


def _zeros_to_mpq(a: np.ndarray) -> np.ndarray:
    """Replace stray Python ints (from empty sums) with mpq so types stay uniform.

    Other exact entry types (e.g. :class:`exactcagd.exact.quadratic.QuadraticNumber`,
    sympy expressions) are left as they are: the module works on anything closed
    under ``+ - *``.
    """
    flat = a.reshape(-1)
    for i, x in enumerate(flat):
        if isinstance(x, (int, _MPZ)) and not isinstance(x, bool):
            flat[i] = mpq(x)
    return a


_MPZ = type(mpz(0))
_MPQ = type(mpq(0))


def to_power(c: np.ndarray) -> np.ndarray:
    """Bernstein -> power basis: ``p(t) = sum_k a_k t^k`` (notes 3.3).

    ``a_k = C(n,k) sum_{i<=k} (-1)^(k-i) C(k,i) c_i``; rational columns go through
    python-flint (:func:`_to_power_flint`), other exact entries through this sum.
    """
    n = c.shape[0] - 1
    out = np.empty_like(c)
    for index in np.ndindex(*c.shape[1:]) if c.ndim > 1 else [()]:
        column = c[(slice(None),) + index]
        if n > 2 and all(isinstance(x, (_MPQ, _MPZ, int)) and not isinstance(x, bool) for x in column):
            out[(slice(None),) + index] = _to_power_flint(column)
            continue
        for k in range(n + 1):
            acc = sum(((-1) ** (k - i) * binomial(k, i) * column[i] for i in range(k + 1)), start=mpq(0) * column[0])
            out[(k,) + index] = binomial(n, k) * acc
    return _zeros_to_mpq(out)


def _to_power_flint(column) -> list:
    """Power coefficients of one rational Bernstein column through :func:`scaled_to_power`."""
    import flint

    n = len(column) - 1
    power = scaled_to_power(flint.fmpq_poly([to_fmpq(c) * binomial(n, i) for i, c in enumerate(column)]), n)
    coeffs = power.coeffs()
    return [from_fmpq(coeffs[k]) if k < len(coeffs) else mpq(0) for k in range(n + 1)]


def _reverse(p, n: int):
    """``t^n p(1/t)`` of a flint polynomial of degree ``<= n`` (same flint type: fmpq_poly, fmpz_poly)."""
    c = p.coeffs()
    return type(p)((c + [0] * (n + 1 - len(c)))[::-1])


def scaled_to_power(p, n: int):
    """Scaled Bernstein form -> power form, for flint ``fmpq_poly`` (notes 3.3).

    ``p`` holds ``b_i = C(n,i) c_i`` as the coefficient of ``t^i``; the result is
    ``(1 - t)^n p(t / (1 - t)) = sum_i c_i B_i^n(t)``.  With ``R(y) = y^n p(1/y)``,
    ``t^-n (1 - t)^n p(t / (1 - t)) = R(1/t - 1)``: one Taylor shift between two
    reversals, instead of ``O(n^2)`` rational operations.  An ``fmpz_poly`` stays integral.
    """
    return _reverse(_reverse(p, n)(type(p)([-1, 1])), n)


def power_to_scaled(p, n: int):
    """Power form -> scaled Bernstein form of degree ``n`` (the inverse of :func:`scaled_to_power`)."""
    import flint

    return _reverse(_reverse(p, n)(flint.fmpq_poly([1, 1])), n)


def from_power(a, degree: int | None = None) -> np.ndarray:
    """Power -> Bernstein basis of degree ``degree`` (default: ``len(a) - 1``) (notes 3.3).

    ``c_i = sum_{k<=i} C(i,k) / C(n,k) a_k``.
    """
    a = a if isinstance(a, np.ndarray) else as_coefficients(a, "power coefficients")
    n = a.shape[0] - 1 if degree is None else degree
    if n < a.shape[0] - 1:
        nonzero = [k for k in range(n + 1, a.shape[0]) if np.any(a[k] != 0)]
        if nonzero:
            raise DegreeError(f"power coefficients have degree {max(nonzero)} > requested {n}")
        a = a[: n + 1]
    out = np.empty((n + 1,) + a.shape[1:], dtype=object)
    for i in range(n + 1):
        acc = mpq(0) * a[0]
        for k in range(min(i, a.shape[0] - 1) + 1):
            acc = acc + mpq(binomial(i, k), binomial(n, k)) * a[k]
        out[i] = acc
    return _zeros_to_mpq(out)


def true_degree(c: np.ndarray) -> int:
    """Exact degree of the polynomial (all trailing components together).

    The zero polynomial has degree 0 by convention here.
    """
    a = to_power(c)
    for k in range(a.shape[0] - 1, 0, -1):
        if np.any(a[k] != 0):
            return k
    return 0


def reduce_degree(c: np.ndarray, degree: int | None = None) -> np.ndarray:
    """Exact degree reduction: the same polynomial in Bernstein form of lower degree.

    Parameters
    ----------
    degree : int, optional
        Target degree; default the true degree.  Raises :class:`DegreeError` when the
        polynomial is not of degree <= ``degree`` (no approximation is ever made).
    """
    d = true_degree(c)
    target = d if degree is None else degree
    if target < d:
        raise DegreeError(f"polynomial has exact degree {d}; cannot reduce exactly to {target}")
    if target > c.shape[0] - 1:
        return elevate(c, target - (c.shape[0] - 1))
    return from_power(to_power(c)[: target + 1], target)


def derivative(c: np.ndarray) -> np.ndarray:
    """Hodograph: Bernstein coefficients of ``p'(t)``, degree ``n - 1`` (notes 2.7).

    A constant (degree 0) gives the degree-0 zero polynomial.
    """
    n = c.shape[0] - 1
    if n == 0:
        return c * 0
    return n * (c[1:] - c[:-1])


def product(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Product of two Bernstein polynomials, degree ``m + n`` (notes 9.3).

    ``(sum_i a_i B^m_i)(sum_j b_j B^n_j) = sum_k c_k B^{m+n}_k`` with
    ``c_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j``.  Trailing axes broadcast,
    so a scalar polynomial times homogeneous points works.  Long scalar products
    go through python-flint's ``fmpq_poly`` on the scaled coefficients
    ``C(m,i) a_i`` (a plain convolution).
    """
    m, n = a.shape[0] - 1, b.shape[0] - 1
    limits.check("max_degree", m + n, f"Bernstein product of degrees {m} and {n}")
    scaled_a = np.array([binomial(m, i) for i in range(m + 1)], dtype=object).reshape((m + 1,) + (1,) * (a.ndim - 1)) * a
    scaled_b = np.array([binomial(n, j) for j in range(n + 1)], dtype=object).reshape((n + 1,) + (1,) * (b.ndim - 1)) * b
    conv = _convolve(scaled_a, scaled_b)
    denom = np.array([mpq(1, binomial(m + n, k)) for k in range(m + n + 1)], dtype=object)
    return _zeros_to_mpq(conv * denom.reshape((m + n + 1,) + (1,) * (conv.ndim - 1)))


def _convolve(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Exact convolution along axis 0, broadcasting trailing axes."""
    trailing = np.broadcast_shapes(a.shape[1:], b.shape[1:])
    a = np.broadcast_to(a, (a.shape[0],) + trailing)
    b = np.broadcast_to(b, (b.shape[0],) + trailing)
    out = np.empty((a.shape[0] + b.shape[0] - 1,) + trailing, dtype=object)
    for index in np.ndindex(*trailing) if trailing else [()]:
        col_a = a[(slice(None),) + index]
        col_b = b[(slice(None),) + index]
        out[(slice(None),) + index] = _convolve_scalar(list(col_a), list(col_b))
    return out


def _convolve_scalar(a: list, b: list) -> list:
    if min(len(a), len(b)) > 8:
        try:
            return _convolve_flint(a, b)
        except TypeError:
            pass  # entries are not rationals (e.g. sympy symbols): plain loop below
    out = [mpq(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x == 0:
            continue
        for j, y in enumerate(b):
            out[i + j] = out[i + j] + x * y
    return out


def _convolve_flint(a: list, b: list) -> list:
    import flint

    if not all(isinstance(x, _MPQ) for x in a) or not all(isinstance(x, _MPQ) for x in b):
        raise TypeError("non-rational entry")
    pa = flint.fmpq_poly([to_fmpq(x) for x in a])
    pb = flint.fmpq_poly([to_fmpq(x) for x in b])
    result = [from_fmpq(q) for q in (pa * pb).coeffs()]
    return result + [mpq(0)] * (len(a) + len(b) - 1 - len(result))


def antiderivative(c: np.ndarray) -> np.ndarray:
    """Bernstein coefficients (degree ``n + 1``) of ``P(t) = int_0^t p`` (notes 2.15).

    ``P_0 = 0``, ``P_k = (c_0 + ... + c_{k-1}) / (n + 1)``.
    """
    n = c.shape[0] - 1
    out = np.empty((n + 2,) + c.shape[1:], dtype=object)
    out[0] = c[0] * 0
    running = c[0] * 0
    for k in range(1, n + 2):
        running = running + c[k - 1]
        out[k] = running * mpq(1, n + 1)
    return _zeros_to_mpq(out)


def integral(c: np.ndarray):
    """Exact ``int_0^1 p(t) dt = (c_0 + ... + c_n) / (n + 1)`` (notes 2.15)."""
    return antiderivative(c)[-1]


def blossom(c: np.ndarray, params) -> object:
    """Polar form ``f(t_1, ..., t_n)`` (notes 6.1): de Casteljau with one parameter per level.

    Symmetric, multi-affine, and ``f(t, ..., t) = p(t)``.
    """
    n = c.shape[0] - 1
    if isinstance(params, (str, bytes, bytearray)) or not hasattr(params, "__len__"):
        raise InputError(f"blossom: expected a sequence of {n} parameters, got {type(params).__name__}")
    if len(params) != n:
        raise InputError(f"blossom of a degree-{n} polynomial needs {n} arguments, got {len(params)}")
    params = [_param(t) for t in params]
    if len(params) != n:
        raise InputError(f"blossom of a degree-{n} polynomial needs {n} arguments, got {len(params)}")
    level = c
    for t in params:
        level = (1 - t) * level[:-1] + t * level[1:]
    return level[0]


def restrict(c: np.ndarray, a, b) -> np.ndarray:
    """Coefficients of ``q(s) = p(a + s (b - a))`` on [0, 1] (notes 6.1).

    ``q_i = f(a^{n-i}, b^i)`` in polar form; works for any ``a, b`` (restriction,
    extension or reversal).
    """
    a, b = _param(a), _param(b)
    n = c.shape[0] - 1
    out = np.empty_like(c)
    level_b = c
    for i in range(n + 1):
        level = level_b
        for _ in range(n - i):
            level = (1 - a) * level[:-1] + a * level[1:]
        out[i] = level[0]
        if i < n:
            level_b = (1 - b) * level_b[:-1] + b * level_b[1:]
    return out


def along(axis: int, func, array: np.ndarray, *args, **kwargs):
    """Apply a univariate Bernstein operation along ``axis`` of a tensor-product array.

    ``func`` acts on axis 0; results that are arrays get the axis moved back,
    tuples of arrays are handled element-wise, scalars are returned as they are.
    """
    moved = np.moveaxis(array, axis, 0)
    result = func(moved, *args, **kwargs)

    def back(x):
        return np.moveaxis(x, 0, axis) if isinstance(x, np.ndarray) and x.ndim == array.ndim else x

    if isinstance(result, tuple):
        return tuple(back(x) for x in result)
    return back(result)


def _binomial_column(n: int, ndim: int, axis: int) -> np.ndarray:
    shape = [1] * ndim
    shape[axis] = n + 1
    return np.array([binomial(n, i) for i in range(n + 1)], dtype=object).reshape(shape)


def product_tensor(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Product of two tensor-product Bernstein polynomials (axes 0 and 1).

    Degrees add in each direction: ``(l1, m1) x (l2, m2) -> (l1 + l2, m1 + m2)``;
    the univariate formula of notes 9.3 applied in both directions at once.
    Trailing axes broadcast.
    """
    (l1, m1), (l2, m2) = (a.shape[0] - 1, a.shape[1] - 1), (b.shape[0] - 1, b.shape[1] - 1)
    sa = a * _binomial_column(l1, a.ndim, 0) * _binomial_column(m1, a.ndim, 1)
    sb = b * _binomial_column(l2, b.ndim, 0) * _binomial_column(m2, b.ndim, 1)
    trailing = np.broadcast_shapes(a.shape[2:], b.shape[2:])
    out = np.empty((l1 + l2 + 1, m1 + m2 + 1) + trailing, dtype=object)
    out[...] = mpq(0)
    for i in range(l1 + 1):
        for j in range(m1 + 1):
            out[i : i + l2 + 1, j : j + m2 + 1] += sa[i, j] * sb
    inv = np.array([[mpq(1, binomial(l1 + l2, k) * binomial(m1 + m2, q)) for q in range(m1 + m2 + 1)] for k in range(l1 + l2 + 1)], dtype=object)
    return out * inv.reshape(inv.shape + (1,) * len(trailing))

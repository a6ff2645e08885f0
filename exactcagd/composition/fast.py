"""Route (b): the composition ``F(K(t))`` by exact polynomial arithmetic (the fast route).

Derivation (Lasser & Bonneau (000) Theorems 1, 2; Remark 3).  Write the domain curve in
homogeneous form ``K = (X/W, Y/W)`` with Bernstein polynomials ``X, Y, W`` of degree ``N``
(``W = 1`` for a polynomial curve) and the surface as ``F = P/w`` with the homogeneous net
``H_ij = (w_ij F_ij, w_ij)``.  Since ``B^l_i(X/W) = C(l,i) X^i (W - X)^(l-i) / W^l``,

    W^(l+m) * (P, w)(X/W, Y/W) = sum_ij H_ij  b_i(t) c_j(t),
    b_i = C(l,i) X^i (W - X)^(l-i),   c_j = C(m,j) Y^j (W - Y)^(m-j),

a homogeneous curve of degree exactly ``N(l + m)`` in ``t``: the factor ``W^(l+m)`` cancels
between numerator and denominator (which is why the degree does not double for a
rational ``K``).  Every term is a product of ``l + m`` Bernstein polynomials of degree ``N``.

Arithmetic: a Bernstein polynomial ``sum c_i B^n_i`` is carried as the ordinary
polynomial ``sum C(n,i) c_i x^i`` ("scaled Bernstein form" = the homogeneous form
``sum c_i C(n,i) t^i (1-t)^(n-i)`` dehomogenized by ``x = t/(1-t)``).  Products of
Bernstein polynomials are then plain polynomial products (notes 9.3) and sums of equal
degree are plain sums, so the whole formula runs in python-flint ``fmpz_poly``
arithmetic (over common denominators, all coordinates packed into one integer per
control point: :func:`_flint_route`); one division by ``C(R, r)`` at the end gives the
Bernstein coefficients.  No power-basis conversion is made.  ``strategy="bernstein"`` evaluates the same
formula as a homogeneous de Casteljau scheme with :func:`exactcagd.exact.bernstein.product`
(kept for comparison; see ``benchmarks/bench_compose.py``).

>>> import numpy as np
>>> from exactcagd.exact.scalars import to_rational_array
>>> net = to_rational_array([[[0, 1], [0, 1]], [[1, 1], [1, 1]]])    # F(u, v) = u (homogeneous)
>>> curve = to_rational_array([[0, 0, 1], [1, 1, 1]])                 # K(t) = (t, t)
>>> [str(x) for x in compose_homogeneous_fast(net, curve)[:, 0]]     # t, as degree 2
['0', '1/2', '1']
"""

from __future__ import annotations

import math
from functools import lru_cache

import flint
import numpy as np
from gmpy2 import mpq, mpz

from ..errors import InputError
from ..exact import bernstein as bz
from ..exact.scalars import to_fmpq as _fmpq
from ..exact.scalars import to_rational

__all__ = ["compose_homogeneous_fast", "scaled", "unscaled"]

_MPQ = type(mpq(0))


def scaled(c) -> flint.fmpq_poly:
    """Scaled Bernstein form of a 1-D coefficient sequence: ``sum C(n,i) c_i x^i``."""
    binomials = _binomials(len(c) - 1)
    return flint.fmpq_poly([flint.fmpq(int(x.numerator) * binomials[i], int(x.denominator)) if type(x) is _MPQ else _fmpq(x) * binomials[i]
                            for i, x in enumerate(c)])


def unscaled(p: flint.fmpq_poly, n: int) -> list:
    """Bernstein coefficients (``mpq``) of degree ``n`` from the scaled form ``p``."""
    # p = numer / den with an integer numerator: b_i = numer_i / (den C(n, i)), one
    # canonicalizing mpq constructor per coefficient (no fmpq -> p, q attribute round trip)
    den = int(p.denom())
    coeffs = p.numer().coeffs()
    binomials = _binomials(n)
    out = [mpq(int(a), den * b) for a, b in zip(coeffs, binomials)]
    if len(out) < n + 1:
        out += [mpq(0)] * (n + 1 - len(out))
    return out


@lru_cache(maxsize=256)
def _binomials(n: int) -> tuple:
    return tuple(bz.binomial(n, i) for i in range(n + 1))


def _basis(one: flint.fmpz_poly, zero: flint.fmpz_poly, degree: int) -> list:
    """``[one^i zero^(k-i) for i = 0..k]`` (``k = degree``; the binomials ``C(k, i)`` are
    applied to the packed net instead, see :func:`_flint_route`)."""
    pow_one, pow_zero = [flint.fmpz_poly([1])], [flint.fmpz_poly([1])]
    for _ in range(degree):
        pow_one.append(pow_one[-1] * one)
        pow_zero.append(pow_zero[-1] * zero)
    return [pow_one[i] * pow_zero[degree - i] for i in range(degree + 1)]


def _integers(values: list) -> tuple[list, object]:
    """``(a, D)`` with ``values[i] == a[i] / D``: integer numerators (``mpz``) over the least
    common denominator ``D``."""
    values = [v if type(v) is _MPQ else to_rational(v) for v in values]
    den = math.lcm(*[v.denominator for v in values])
    if den == 1:
        return [v.numerator for v in values], 1
    den = mpz(den)
    return [v.numerator * (den // v.denominator) for v in values], den


def _digit_bits(h: list, norm_x, norm_y, norm_w, l: int, m: int) -> int:
    """Digit width ``B`` of the packing in :func:`_flint_route`: every packed coordinate
    satisfies ``|A_k,r| < 2^(B-1)``.

    ``|A_k,r| <= ||A_k||_1 <= max|h| (||x||_1 + ||w - x||_1)^l (||y||_1 + ||w - y||_1)^m``
    (``||p||_1`` the sum of the absolute coefficients; ``||p q||_1 <= ||p||_1 ||q||_1`` and
    ``sum_i C(l,i) a^i b^(l-i) = (a + b)^l``), and ``||w - x||_1 <= ||w||_1 + ||x||_1``; ``B``
    is the bit length of the bound plus one.  The bound is attained (a one-point curve at
    ``(0, 0)``), so no smaller width is safe in general (``tests/test_composition_packed.py``).

    >>> _digit_bits([3, -4], 0, 0, 1, 2, 2)   # |A| <= 4 < 2^3
    4
    """
    bound = max(abs(v) for v in h) * (2 * norm_x + norm_w) ** l * (2 * norm_y + norm_w) ** m
    return int(bound).bit_length() + 1


def _packed_sum(b: list, c: list, h: list, count: int, bits: int) -> flint.fmpz_poly:
    """``T = sum_j c_j sum_i b_i P_ij`` with ``P_ij = C(l,i) C(m,j) sum_k h_ijk 2^(bits k)``
    (``h`` flat in the order ``i, j, k``, ``count`` values ``k`` per ``(i, j)``)."""
    l, m = len(b) - 1, len(c) - 1
    bl, bm = _binomials(l), _binomials(m)
    total = flint.fmpz_poly()
    for j in range(m + 1):
        g = flint.fmpz_poly()
        for i in range(l + 1):
            start = (i * (m + 1) + j) * count
            packed = h[start + count - 1]
            for k in range(start + count - 2, start - 1, -1):
                packed = (packed << bits) + h[k]
            if packed:
                g += b[i] * int(packed * (bl[i] * bm[j]))
        if not g.is_zero():
            total += g * c[j]
    return total


def _balanced_digits(total: flint.fmpz_poly, bits: int, count: int, length: int) -> list:
    """The ``count`` balanced base-``2^bits`` digits of every coefficient of ``total``
    (coefficient ``r`` is ``sum_k a_k,r 2^(bits k)`` with ``|a_k,r| < 2^(bits-1)``), as
    ``count`` lists of ``length`` flint integers (``a_k,0 .. a_k,length-1``).

    Coefficient-wise in flint: with ``off = 2^(bits-1) (1 + 2^bits + ... )`` added to every
    coefficient, digit ``k`` of ``T + off`` is ``a_k,r + 2^(bits-1)``, in ``[0, 2^bits)``.

    >>> _balanced_digits(flint.fmpz_poly([-3 + 5 * 2**4]), 4, 2, 1)
    [[-3], [5]]
    """
    ones = flint.fmpz_poly([1] * length)
    full = 1 << bits
    half = full >> 1
    shifted = total + ones * sum(half << (bits * k) for k in range(count))
    half_poly = ones * half
    out = []
    for k in range(count):
        digits = ((shifted // (1 << (bits * k))) if k else shifted) % full - half_poly
        coeffs = digits.coeffs()
        out.append(coeffs + [flint.fmpz(0)] * (length - len(coeffs)))
    return out


def _flint_route(net: np.ndarray, curve: np.ndarray) -> np.ndarray:
    """The formula of the module docstring in integer arithmetic, all coordinates at once.

    Every coordinate ``k`` of the result is ``A_k = sum_ij C(l,i) C(m,j) h_ijk b_i c_j``
    with the integer scaled forms ``b_i = x^i (w - x)^(l-i)``, ``c_j = y^j (w - y)^(m-j)``
    of the curve (common denominator ``d`` of the curve, ``D`` of the net: the true
    coordinate is ``A_k / (D d^(l+m))``, the formula being homogeneous of degree ``l + m``
    in ``(x, y, w)``).  Instead of one polynomial sum per coordinate (three times the
    python-flint calls), the coordinates are packed into the integers
    ``P_ij = C(l,i) C(m,j) sum_k h_ijk 2^(B k)`` (Kronecker substitution in the values):
    ``T = sum_j c_j sum_i b_i P_ij`` then has the coefficients ``T_r = sum_k A_k,r 2^(B k)``,
    and ``A_k,r`` is the k-th balanced base-``2^B`` digit of ``T_r`` since
    ``|A_k,r| < 2^(B-1)`` (:func:`_digit_bits`).  One ``mpq`` per output coefficient
    remains: the Bernstein coefficient ``A_k,r / (D d^(l+m) C(R, r))``.
    """
    l, m = net.shape[0] - 1, net.shape[1] - 1
    n = curve.shape[0] - 1
    out_degree = n * (l + m)
    dims = net.shape[2]
    rows = net.tolist()  # nested lists: item access without numpy indexing
    result = np.empty((out_degree + 1, dims), dtype=object)
    computed = dims
    if all(p[-1] == 1 for row in rows for p in row) and all(x == 1 for x in curve[:, 2].tolist()):
        # polynomial surface and curve: the weight sum_ij B_i(X, W - X) B_j(Y, W - Y) = W^(l+m) = 1
        computed = dims - 1
        result[:, -1] = mpq(1)
    # the curve: integer scaled Bernstein forms x, y, w over one common denominator d
    values, d = _integers(curve.ravel().tolist())
    binomials = _binomials(n)
    cols = [[values[3 * i + k] * binomials[i] for i in range(n + 1)] for k in range(3)]
    x, y, w = (flint.fmpz_poly([int(v) for v in col]) for col in cols)
    norm_x, norm_y, norm_w = (sum(abs(v) for v in col) for col in cols)
    # the net: integers over one common denominator D
    h, den = _integers([p[k] for row in rows for p in row for k in range(computed)])
    bits = _digit_bits(h, norm_x, norm_y, norm_w, l, m)
    total = _packed_sum(_basis(x, w - x, l), _basis(y, w - y, m), h, computed, bits)
    scale = den * d ** (l + m)
    denominators = [scale * bc for bc in _binomials(out_degree)]
    for k, digits in enumerate(_balanced_digits(total, bits, computed, out_degree + 1)):
        result[:, k] = [mpq(int(a), q) for a, q in zip(digits, denominators)]
    return result


def _bernstein_route(net: np.ndarray, curve: np.ndarray) -> np.ndarray:
    """Homogeneous de Casteljau in u, then in v, with Bernstein products (notes 9.3)."""
    x, y, w = curve[:, 0:1], curve[:, 1:2], curve[:, 2:3]
    u1, u0, v1, v0 = x, w - x, y, w - y
    # u direction: level arrays hold polynomials (axis 1) for every (i, j, coordinate)
    level = [[net[i, j][None, :] for j in range(net.shape[1])] for i in range(net.shape[0])]
    while len(level) > 1:
        level = [[bz.product(u0, level[i][j]) + bz.product(u1, level[i + 1][j]) for j in range(len(level[i]))] for i in range(len(level) - 1)]
    row = level[0]
    while len(row) > 1:
        row = [bz.product(v0, row[j]) + bz.product(v1, row[j + 1]) for j in range(len(row) - 1)]
    return bz._zeros_to_mpq(np.array(row[0], dtype=object))


def compose_homogeneous_fast(net: np.ndarray, curve: np.ndarray, strategy: str = "flint") -> np.ndarray:
    """Exact homogeneous Bernstein coefficients of ``F(K(t))``, degree ``N(l + m)``.

    Parameters
    ----------
    net : object array ``(l + 1, m + 1, D)``
        Homogeneous surface net (any trailing coordinates; the last one is usually the weight).
    curve : object array ``(N + 1, 3)``
        Homogeneous domain curve ``(X, Y, W)``.
    strategy : {"flint", "bernstein"}
        ``"flint"``: scaled Bernstein forms in python-flint (default, fastest);
        ``"bernstein"``: de Casteljau with :func:`exactcagd.exact.bernstein.product`
        (works on any object entries, e.g. sympy expressions).

    Returns
    -------
    object array ``(N(l + m) + 1, D)`` of ``mpq``.
    """
    if strategy == "flint":
        return _flint_route(net, curve)
    if strategy == "bernstein":
        return _bernstein_route(net, curve)
    raise InputError(f"unknown strategy {strategy!r}; expected 'flint' or 'bernstein'")

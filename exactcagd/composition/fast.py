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

__all__ = ["ScaledBernstein", "compose_homogeneous_fast", "compose_scaled", "scaled", "scaled_halves", "unscaled"]

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

    >>> _balanced_digits(flint.fmpz_poly([-3 + 5 * 2**4]), 4, 2, 1)
    [[-3], [5]]
    """
    out = []
    for digits in _balanced_digit_polys(total, bits, count, length):
        coeffs = digits.coeffs()
        out.append(coeffs + [flint.fmpz(0)] * (length - len(coeffs)))
    return out


def _balanced_digit_polys(total: flint.fmpz_poly, bits: int, count: int, length: int) -> list:
    """:func:`_balanced_digits` as ``count`` integer polynomials (digit ``k`` of coefficient ``r``
    is the coefficient ``r`` of polynomial ``k``).

    Coefficient-wise in flint: with ``off = 2^(bits-1) (1 + 2^bits + ... )`` added to every
    coefficient, digit ``k`` of ``T + off`` is ``a_k,r + 2^(bits-1)``, in ``[0, 2^bits)``.

    >>> _balanced_digit_polys(flint.fmpz_poly([-3 + 5 * 2**4, 1]), 4, 2, 2)
    [x + (-3), 5]
    """
    ones = flint.fmpz_poly([1] * length)
    full = 1 << bits
    half = full >> 1
    shifted = total + ones * sum(half << (bits * k) for k in range(count))
    half_poly = ones * half
    return [((shifted // (1 << (bits * k))) if k else shifted) % full - half_poly for k in range(count)]


def _flint_route(net: np.ndarray, curve: np.ndarray) -> np.ndarray:
    """The formula of the module docstring in integer arithmetic (:func:`compose_scaled`),
    read as ``mpq`` Bernstein coefficients."""
    return compose_scaled(net, curve).homogeneous()


def compose_scaled(net: np.ndarray, curve: np.ndarray) -> "ScaledBernstein":
    """``F(K(t))`` as integer scaled Bernstein forms over one denominator (no ``mpq``).

    Every coordinate ``k`` of the result is ``A_k = sum_ij C(l,i) C(m,j) h_ijk b_i c_j``
    with the integer scaled forms ``b_i = x^i (w - x)^(l-i)``, ``c_j = y^j (w - y)^(m-j)``
    of the curve (common denominator ``d`` of the curve, ``D`` of the net: the true
    coordinate is ``A_k / (D d^(l+m))``, the formula being homogeneous of degree ``l + m``
    in ``(x, y, w)``).  Instead of one polynomial sum per coordinate (three times the
    python-flint calls), the coordinates are packed into the integers
    ``P_ij = C(l,i) C(m,j) sum_k h_ijk 2^(B k)`` (Kronecker substitution in the values):
    ``T = sum_j c_j sum_i b_i P_ij`` then has the coefficients ``T_r = sum_k A_k,r 2^(B k)``,
    and ``A_k,r`` is the k-th balanced base-``2^B`` digit of ``T_r`` since
    ``|A_k,r| < 2^(B-1)`` (:func:`_digit_bits`).  The Bernstein coefficient is
    ``A_k,r / (D d^(l+m) C(R, r))`` (:class:`ScaledBernstein`); a polynomial surface and
    curve give the weight ``1`` without computing it.

    Parameters and the curve's meaning as in :func:`compose_homogeneous_fast`.

    >>> from exactcagd.exact.scalars import to_rational_array
    >>> net = to_rational_array([[[0, 1], [0, 1]], [[1, 1], [1, 1]]])    # F(u, v) = u
    >>> image = compose_scaled(net, to_rational_array([[0, 0, 1], [1, 1, 1]]))
    >>> image.columns, int(image.denominator), image.weight is None  # 0 B_0 + 1/2 B_1 + B_2: 2 x (1/2) = 1
    ([x^2 + x], 1, True)
    """
    l, m = net.shape[0] - 1, net.shape[1] - 1
    n = curve.shape[0] - 1
    out_degree = n * (l + m)
    dims = net.shape[2]
    rows = net.tolist()  # nested lists: item access without numpy indexing
    computed = dims
    if all(p[-1] == 1 for row in rows for p in row) and all(x == 1 for x in curve[:, 2].tolist()):
        # polynomial surface and curve: the weight sum_ij B_i(X, W - X) B_j(Y, W - Y) = W^(l+m) = 1
        computed = dims - 1
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
    polys = _balanced_digit_polys(total, bits, computed, out_degree + 1)
    if computed == dims:
        return ScaledBernstein(polys[:-1], polys[-1], den * d ** (l + m), out_degree)
    return ScaledBernstein(polys, None, den * d ** (l + m), out_degree)


class ScaledBernstein:
    """A homogeneous Bézier curve ``(W F, W)`` of degree ``R`` held as integer polynomials.

    Column ``k`` is an integer polynomial ``A_k`` such that ``A_k / denominator`` is the
    scaled Bernstein form ``sum_r C(R, r) b_r x^r`` of the coordinate (module docstring), so
    its Bernstein coefficients are ``b_r = A_k,r / (denominator C(R, r))``.  This is what the
    fast route computes (:func:`compose_scaled`); consumers that multiply Bernstein
    polynomials (the fit route's certificate, :mod:`.distance_bound`) use it directly, and
    ``mpq`` coefficients are made only on request (:meth:`homogeneous`, :meth:`row`).

    Attributes
    ----------
    columns : list of ``flint.fmpz_poly``
        The coordinates ``W F_k`` (all but the weight).
    weight : ``flint.fmpz_poly`` or None
        The weight ``W``; ``None`` when it is the constant 1 (a polynomial curve).
    denominator : int
        Common positive denominator.
    degree : int

    >>> h = ScaledBernstein.from_homogeneous(np.array([[mpq(1, 2), 1], [mpq(0), 1], [mpq(1), 1]], dtype=object))
    >>> h.columns, int(h.denominator), h.weight is None  # (1/2) C(2,0) + 0 + 1 C(2,2) x^2, over 2
    ([2*x^2 + 1], 2, True)
    >>> [str(x) for x in h.homogeneous()[:, 0]]
    ['1/2', '0', '1']
    """

    __slots__ = ("columns", "weight", "denominator", "degree", "_hom")

    def __init__(self, columns: list, weight, denominator, degree: int):
        self.columns = columns
        self.weight = weight
        self.denominator = denominator
        self.degree = degree
        self._hom = None

    @classmethod
    def from_homogeneous(cls, hom: np.ndarray) -> "ScaledBernstein":
        """From homogeneous Bernstein coefficients ``(W F, W)`` (object array of rationals, at
        least one row); a weight column of ones becomes ``weight = None``."""
        rows = hom.tolist()
        degree, dims = len(rows) - 1, len(rows[0])
        unit = all(row[-1] == 1 for row in rows)
        computed = dims - 1 if unit else dims
        values, den = _integers([row[k] for k in range(computed) for row in rows])  # column-major
        binomials = _binomials(degree)
        polys = [flint.fmpz_poly([int(values[k * (degree + 1) + r] * binomials[r]) for r in range(degree + 1)])
                 for k in range(computed)]
        if unit:
            return cls(polys, None, den, degree)
        return cls(polys[:-1], polys[-1], den, degree)

    def weight_poly(self) -> flint.fmpz_poly:
        """The weight's integer scaled form over :attr:`denominator` (``denominator (1 + x)^R``
        for the unit weight)."""
        if self.weight is None:
            return _ones(self.degree) * int(self.denominator)
        return self.weight

    def constant_weight(self):
        """``(a, c)`` with every Bernstein coefficient of the weight ``a / c`` when they are all
        equal (``c = denominator``), else ``None``: ``W = a (1 + x)^R / c`` in scaled form."""
        if self.weight is None:
            return self.denominator, self.denominator
        first = self.weight[0]
        return (first, self.denominator) if self.weight == _ones(self.degree) * first else None

    def homogeneous(self) -> np.ndarray:
        """The ``mpq`` Bernstein coefficients ``(W F, W)``, shape ``(R + 1, k + 1)`` (cached;
        one canonical ``mpq`` per coefficient)."""
        if self._hom is None:
            n = self.degree
            cols = self.columns if self.weight is None else self.columns + [self.weight]
            out = np.empty((n + 1, len(self.columns) + 1), dtype=object)
            denominators = [self.denominator * bc for bc in _binomials(n)]
            for k, poly in enumerate(cols):
                coeffs = poly.coeffs()
                out[:, k] = [mpq(int(a), q) for a, q in zip(coeffs, denominators)] + [mpq(0)] * (n + 1 - len(coeffs))
            if self.weight is None:
                out[:, -1] = mpq(1)
            self._hom = out
        return self._hom

    def row(self, r: int) -> list:
        """Homogeneous row ``r`` as ``mpq`` (``r = 0`` or ``-1``: the end points' ``(W F, W)``)."""
        if self._hom is not None:
            return list(self._hom[r])
        r = r % (self.degree + 1)
        q = self.denominator * _binomials(self.degree)[r]
        out = [mpq(int(p[r]), q) for p in self.columns]
        return out + [mpq(1) if self.weight is None else mpq(int(self.weight[r]), q)]

    def halves(self) -> tuple["ScaledBernstein", "ScaledBernstein"]:
        """The curve on ``[0, 1/2]`` and on ``[1/2, 1]``, each reparametrized to [0, 1] (de
        Casteljau at ``1/2``, notes 2.3), in integers.

        In scaled form (``x = t / (1 - t)``) the left half of ``A`` is
        ``sum_r A_r x^r (2 + x)^(R - r) / 2^R = rev(rev(A)(1 + 2x)) / 2^R`` and the right half
        ``A(1 + 2x) / 2^R`` (``rev`` the reversal at degree ``R``, which reverses the Bernstein
        coefficients): two Taylor-type substitutions per column, no rational arithmetic.

        >>> h = ScaledBernstein.from_homogeneous(np.array([[mpq(0), 1], [mpq(1), 1]], dtype=object))
        >>> [[str(x) for x in half.homogeneous()[:, 0]] for half in h.halves()]
        [['0', '1/2'], ['1/2', '1']]
        """
        n = self.degree
        den = self.denominator << n
        cols = self.columns if self.weight is None else self.columns + [self.weight]
        pairs = [scaled_halves(p.coeffs(), n) for p in cols]
        left = [flint.fmpz_poly(a) for a, _ in pairs]
        right = [flint.fmpz_poly(b) for _, b in pairs]
        if self.weight is None:
            return ScaledBernstein(left, None, den, n), ScaledBernstein(right, None, den, n)
        return ScaledBernstein(left[:-1], left[-1], den, n), ScaledBernstein(right[:-1], right[-1], den, n)

    def floats(self) -> np.ndarray:
        """Binary64 Bernstein coefficients ``(W F, W)``, each correctly rounded (Python's
        integer true division), shape ``(R + 1, k + 1)``."""
        n = self.degree
        out = np.ones((n + 1, len(self.columns) + 1))
        denominators = [int(self.denominator * bc) for bc in _binomials(n)]
        for k, poly in enumerate(self.columns if self.weight is None else self.columns + [self.weight]):
            coeffs = poly.coeffs()
            out[:, k] = [int(a) / q for a, q in zip(coeffs, denominators)] + [0.0] * (n + 1 - len(coeffs))
        return out


_SUBSTITUTION = flint.fmpz_poly([1, 2])


def scaled_halves(s: list, n: int) -> tuple[list, list]:
    """``2^n`` times the scaled Bernstein coefficients of both halves (``[0, 1/2]``, ``[1/2, 1]``)
    of the degree-``n`` scaled form with coefficients ``s`` (flint or Python integers, at most
    ``n + 1``), as two lists of ``n + 1`` flint integers.

    With ``x = t / (1 - t)`` the right half is ``s(1 + 2x)`` and the left half its mirror
    image ``rev(rev(s)(1 + 2x))`` (``rev`` reverses the ``n + 1`` coefficients, which reverses
    the Bernstein coefficients): de Casteljau at ``1/2`` (notes 2.3) as two Taylor-type
    substitutions, no rational arithmetic.

    >>> scaled_halves([0, 2, 2], 2)   # 2t: Bernstein (0, 1, 2); halves t, 1 + t: (0, 1/2, 1), (1, 3/2, 2)
    ([0, 4, 4], [4, 12, 8])
    """
    pad = [flint.fmpz(0)] * (n + 1)
    s = list(s) + pad[len(s):]
    right = flint.fmpz_poly(s)(_SUBSTITUTION).coeffs()
    mirrored = flint.fmpz_poly(s[::-1])(_SUBSTITUTION).coeffs()
    return (mirrored + pad[len(mirrored):])[::-1], right + pad[len(right):]


@lru_cache(maxsize=256)
def _ones(n: int) -> flint.fmpz_poly:
    """``(1 + x)^n``: the scaled Bernstein form of the constant 1 at degree ``n``."""
    return flint.fmpz_poly(list(_binomials(n)))


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

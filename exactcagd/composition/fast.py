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
degree are plain sums, so the whole formula runs in python-flint ``fmpq_poly``
arithmetic; one division by ``C(n, R)`` at the end gives the Bernstein coefficients.
No power-basis conversion is made.  ``strategy="bernstein"`` evaluates the same
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

from functools import lru_cache

import flint
import numpy as np
from gmpy2 import mpq

from ..errors import InputError
from ..exact import bernstein as bz
from ..exact.scalars import to_fmpq as _fmpq

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


def _basis(one: flint.fmpq_poly, zero: flint.fmpq_poly, degree: int) -> list:
    """``[C(k,i) one^i zero^(k-i) for i = 0..k]`` in scaled form (``k = degree``)."""
    pow_one, pow_zero = [flint.fmpq_poly([1])], [flint.fmpq_poly([1])]
    for _ in range(degree):
        pow_one.append(pow_one[-1] * one)
        pow_zero.append(pow_zero[-1] * zero)
    return [pow_one[i] * pow_zero[degree - i] * bz.binomial(degree, i) for i in range(degree + 1)]


def _flint_route(net: np.ndarray, curve: np.ndarray) -> np.ndarray:
    l, m = net.shape[0] - 1, net.shape[1] - 1
    n = curve.shape[0] - 1
    x, y, w = (scaled(curve[:, k]) for k in range(3))
    b = _basis(x, w - x, l)
    c = _basis(y, w - y, m)
    out_degree = n * (l + m)
    dims = net.shape[2]
    result = np.empty((out_degree + 1, dims), dtype=object)
    computed = dims
    if all(x == 1 for x in net[:, :, -1].ravel().tolist()) and all(x == 1 for x in curve[:, 2].tolist()):
        # polynomial surface and curve: the weight sum_ij B_i(X, W - X) B_j(Y, W - Y) = W^(l+m) = 1
        computed = dims - 1
        result[:, -1] = mpq(1)
    rows = net.tolist()  # nested lists: item access without numpy indexing
    fmpq, mpq_type = flint.fmpq, _MPQ
    for k in range(computed):
        total = flint.fmpq_poly([])
        for j in range(m + 1):
            g = flint.fmpq_poly([])
            for i in range(l + 1):
                h = rows[i][j][k]
                if h:
                    g += b[i] * (fmpq(int(h.numerator), int(h.denominator)) if type(h) is mpq_type else _fmpq(h))
            if not g.is_zero():
                total += g * c[j]
        result[:, k] = unscaled(total, out_degree)
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

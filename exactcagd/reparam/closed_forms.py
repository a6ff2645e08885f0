"""The closed forms printed in Yang et al. (004), section 4, as functions.

They are *not* used by :mod:`exactcagd.reparam` (which has one general mechanism);
they exist so that ``proofs/yang_reparam.py`` and the tests can check the printed
formulas against it.  The extraction of the paper damaged the summation limits of
``c_{l,k}`` and ``d_{l,k}``; the versions here are reconstructed from the
derivation (multinomial expansion of ``(1 - alpha(t))^k alpha(t)^(m-k)``):

    c_{l,k} = sum_{e1, e2, e3} C(k, e1) C(k - e1, e2) C(m - k, e3) C(m - k - e3, e4)
              2^(e2 + e4) (1 - a3)^e1 (1 - a2)^e2 (1 - a1)^(k - e1 - e2)
              a2^e4 a3^e3 a1^(m - k - e3 - e4),        e4 = l - 2 e1 - e2 - 2 e3,

the coefficient of ``t^l (1 - t)^(2m - l)`` in ``(1 - alpha(t))^k alpha(t)^(m-k)``;
``d_{l,k}`` is the same with ``(n, beta)``.  The printed ``d`` carries the factor
``(-1)^(n-k) (b3 - 1)^e1 (b2 - 1)^e2 (b1 - 1)^(k-e1-e2)``; the correct sign is
``(-1)^k`` (erratum, recorded in the ledger), :func:`coefficient_d` has
``printed_sign=True`` to reproduce the printed one.

>>> from gmpy2 import mpq
>>> # (1 - alpha)^1 alpha^0 with alpha = B^2 (a1, a2, a3): coefficients C(2,l)(1 - a_{l+1})
>>> [coefficient_c(l, 1, 1, (mpq(1, 5), mpq(4, 5), mpq(3, 10))) for l in range(3)]
[mpq(4,5), mpq(2,5), mpq(7,10)]
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..exact.bernstein import binomial

__all__ = ["mobius_weights", "coefficient_c", "coefficient_d", "cubic_closed_form"]


def mobius_weights(weights: np.ndarray, alpha, beta) -> np.ndarray:
    """Printed weights after eqs. (2), (3): ``w_ij (1 - a)^i a^(m-i) (1 - b)^j b^(n-j)`` [23]."""
    m, n = weights.shape[0] - 1, weights.shape[1] - 1
    out = np.empty_like(weights)
    for i in range(m + 1):
        for j in range(n + 1):
            out[i, j] = weights[i, j] * (1 - alpha) ** i * alpha ** (m - i) * (1 - beta) ** j * beta ** (n - j)
    return out


def _coefficient(l: int, k: int, deg: int, coeffs, printed_sign: bool = False):
    a1, a2, a3 = coeffs
    total = mpq(0)
    for e1 in range(max(0, l + k - 2 * deg), min(k, l // 2) + 1):
        for e2 in range(max(0, l + 2 * k - 2 * deg - 2 * e1), min(k - e1, l - 2 * e1) + 1):
            for e3 in range(max(l + k - deg - e2 - 2 * e1, 0), min(deg - k, (l - 2 * e1 - e2) // 2) + 1):
                e4 = l - 2 * e1 - e2 - 2 * e3
                rest = deg - k - e3 - e4
                if e4 < 0 or rest < 0:
                    continue
                comb = binomial(k, e1) * binomial(k - e1, e2) * binomial(deg - k, e3) * binomial(deg - k - e3, e4)
                if printed_sign:
                    ones = (-1) ** (deg - k) * (a3 - 1) ** e1 * (a2 - 1) ** e2 * (a1 - 1) ** (k - e1 - e2)
                else:
                    ones = (1 - a3) ** e1 * (1 - a2) ** e2 * (1 - a1) ** (k - e1 - e2)
                total += comb * 2 ** (e2 + e4) * ones * a2**e4 * a3**e3 * a1**rest
    return total


def coefficient_c(l: int, k: int, m: int, alphas, printed_sign: bool = False):
    """``c_{l,k}``: coefficient of ``t^l (1-t)^(2m-l)`` in ``(1 - alpha(t))^k alpha(t)^(m-k)``."""
    return _coefficient(l, k, m, alphas, printed_sign)


def coefficient_d(l: int, k: int, n: int, betas, printed_sign: bool = False):
    """``d_{l,k}``: coefficient of ``s^l (1-s)^(2n-l)`` in ``(1 - beta(s))^k beta(s)^(n-k)``.

    ``printed_sign=True`` uses the printed factor ``(-1)^(n-k) (b - 1)^...`` (wrong for odd ``n``).
    """
    return _coefficient(l, k, n, betas, printed_sign)


def cubic_closed_form(hom: np.ndarray, alphas, betas, printed_sign: bool = False) -> np.ndarray:
    """Homogeneous net ``(w^ Q, w^)`` of the cubic reparameterization by the printed sums.

    ``w^_{k1,k2} = sum_{i,j} c_{k2-j,i} d_{k1-i,j} R_ij w_ij`` with
    ``R_ij = C(m,i) C(n,j) / (C(m+2n,k1) C(2m+n,k2))``, ``i`` from ``max(k1-2n, 0)`` to
    ``min(k1, m)``, ``j`` from ``max(k2-2m, 0)`` to ``min(k2, n)``; ``w^ Q`` likewise
    with ``w_ij P_ij``.  Shape ``(m + 2n + 1, 2m + n + 1, d + 1)``.
    """
    m, n = hom.shape[0] - 1, hom.shape[1] - 1
    c = {(l, i): coefficient_c(l, i, m, alphas, printed_sign) for l in range(2 * m + 1) for i in range(m + 1)}
    d = {(l, j): coefficient_d(l, j, n, betas, printed_sign) for l in range(2 * n + 1) for j in range(n + 1)}
    out = np.empty((m + 2 * n + 1, 2 * m + n + 1, hom.shape[2]), dtype=object)
    for k1 in range(m + 2 * n + 1):
        for k2 in range(2 * m + n + 1):
            acc = hom[0, 0] * 0
            for i in range(max(k1 - 2 * n, 0), min(k1, m) + 1):
                for j in range(max(k2 - 2 * m, 0), min(k2, n) + 1):
                    R = mpq(binomial(m, i) * binomial(n, j), binomial(m + 2 * n, k1) * binomial(2 * m + n, k2))
                    acc = acc + c[(k2 - j, i)] * d[(k1 - i, j)] * R * hom[i, j]
            out[k1, k2] = acc
    return out

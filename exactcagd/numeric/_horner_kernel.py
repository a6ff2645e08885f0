"""Compiled kernel of Bernstein-Horner evaluation with its certified radius (optional numba).

Blocks of parameters go through, one coefficient at a time, what the numpy path of
:class:`exactcagd.numeric.evaluation._HornerBernstein` does with whole arrays: the same
float operations in the same order (notes 3.2, Horner's rule in Bernstein form; the
radius of :mod:`exactcagd.numeric.evaluation`, notes 13 (13.4)-(13.8)), so the values and
radii are bit-for-bit those of the numpy path (tested).  Fusing the value pass, the pass
on ``|c|`` and the radius formula into one loop removes the temporary arrays that make
the numpy path several times slower than a compiled evaluator.

numba compiles with ``fastmath=False``: no reassociation and no contraction of ``a * b + c``
into a fused multiply-add, so every operation is one correctly rounded binary64 operation
as the error analysis counts it.  Without numba, :data:`AVAILABLE` is ``False`` and the
caller keeps the numpy path (the tested fallback).

>>> from exactcagd.numeric import _horner_kernel
>>> isinstance(_horner_kernel.AVAILABLE, bool)
True
"""

from __future__ import annotations

import importlib.util
import math
import os

import numpy as np

__all__ = ["AVAILABLE", "horner_curve", "project"]

#: numba installed (and not switched off by ``EXACTCAGD_NO_NUMBA``); it is imported, and the
#: kernels compiled (or loaded from numba's cache), at their first call, not at import time
#: (importing numba costs ~0.15 s)
AVAILABLE = not os.environ.get("EXACTCAGD_NO_NUMBA") and importlib.util.find_spec("numba") is not None


#: parameters per block: the block's work arrays stay in L1 and every inner loop runs over
#: the block's parameters (no branches, so the compiler vectorizes it), as numpy's does
BLOCK = 512


def _horner_curve(c, c_abs_sum, t, g, eta, min_normal, values, radii, bound):
    """Values (and radii) of ``sum_k c_k B_k`` at every ``t``; ``c`` is ``(n + 1, D)``.

    ``c`` holds the binomial-scaled coefficients ``C(n, k) b_k``, ``c_abs_sum[j]`` the sum
    of ``|c_k,j|`` over ``k`` (numpy's ``np.sum``); ``g = gamma_over(6n + 1)`` and
    ``eta = 2^-1074`` as in the numpy path.  ``t <= 1/2``: ``(1-t)^n sum_k c_k s^k``,
    ``s = t/(1-t)``, Horner from ``c_n``; ``t > 1/2``: ``t^n sum_k c_k r^(n-k)``,
    ``r = (1-t)/t``, Horner from ``c_0``.  Each upward rounding of the radius is the bit
    increment of :func:`exactcagd.numeric.fp_error.up_nonnegative` (``x + 0.0`` first).
    """
    n = c.shape[0] - 1
    dim = c.shape[1]
    count = t.shape[0]
    a_factor = (2 * n + 2) * eta
    tiny_factor = 2 * n * eta
    x = np.empty(BLOCK)
    x_abs = np.empty(BLOCK)
    scale = np.empty(BLOCK)
    a = np.empty(BLOCK)
    low = np.empty(BLOCK, dtype=np.bool_)
    tiny = np.empty(BLOCK, dtype=np.bool_)
    h = np.empty(BLOCK)
    h_abs = np.empty(BLOCK)
    r = np.empty(BLOCK)
    r_bits = r.view(np.int64)
    for start in range(0, count, BLOCK):
        m = min(BLOCK, count - start)
        for i in range(m):
            tp = t[start + i]
            q = 1.0 - tp
            is_low = tp <= 0.5
            base = q if is_low else tp
            xi = (tp if is_low else q) / base
            s = 1.0
            if n >= 1:
                s = base
                for _ in range(n - 1):
                    s = s * base
            x[i] = xi
            x_abs[i] = abs(xi)
            scale[i] = s
            low[i] = is_low
            # a_factor is subnormal: multiplying it by 1.0 (every t in [0, 1]) gives it back
            # exactly, and skipping that product avoids the CPU's slow subnormal path
            a[i] = a_factor if abs(s) <= 1.0 else a_factor * abs(s)
            tiny[i] = xi != 0.0 and abs(xi) <= min_normal
        for j in range(dim):
            first_low, first_high = c[n, j], c[0, j]
            for i in range(m):
                h[i] = first_low if low[i] else first_high
                h_abs[i] = abs(h[i])
            for k in range(1, n + 1):
                next_low, next_high = c[n - k, j], c[k, j]
                for i in range(m):
                    coefficient = next_low if low[i] else next_high
                    h[i] = h[i] * x[i] + coefficient
                    h_abs[i] = h_abs[i] * x_abs[i] + abs(coefficient)
            for i in range(m):
                values[start + i, j] = h[i] * scale[i]
            if not bound:
                continue
            tiny_j = c_abs_sum[j] * tiny_factor
            for i in range(m):  # up(S^ + A)
                r[i] = (h_abs[i] * scale[i] + (a[i] + tiny_j * abs(scale[i]) if tiny[i] else a[i])) + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):  # up(g * .)
                r[i] = g * r[i] + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):  # up(. + A)
                r[i] = r[i] + (a[i] + tiny_j * abs(scale[i]) if tiny[i] else a[i]) + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):
                v = values[start + i, j]
                radii[start + i, j] = r[i] if math.isfinite(v) and math.isfinite(r[i]) else np.inf


def _project(hom, rad, u_quotient, eta, values, radii):
    """``values = X / W`` with certified radii from the homogeneous ``hom`` and ``rad``.

    The operations of :func:`exactcagd.numeric.evaluation._project` in the same order, in
    blocks of parameters with one pass per operation (``up`` is the bit increment after
    ``+ 0.0``, ``down`` the bit decrement where its result is used)::

        |X^/W^ - X/W| <= (e_X + (|X^| + e_X) e_W / (|W^| - e_W)) / |W^| + u |X^/W^| + eta
    """
    count, dim = values.shape
    abs_w = np.empty(BLOCK)
    err_w = np.empty(BLOCK)
    low = np.empty(BLOCK)
    low_bits = low.view(np.int64)
    valid = np.empty(BLOCK, dtype=np.bool_)
    q = np.empty(BLOCK)
    r = np.empty(BLOCK)
    r_bits = r.view(np.int64)
    d = np.empty(BLOCK)
    d_bits = d.view(np.int64)
    for start in range(0, count, BLOCK):
        m = min(BLOCK, count - start)
        for i in range(m):
            abs_w[i] = abs(hom[start + i, dim])
            err_w[i] = rad[start + i, dim]
            low[i] = abs_w[i] - err_w[i]
        for i in range(m):
            # down(x) = nextafter(x, -inf) is only read where it is > 0, i.e. for x > 0
            # (+inf included): there it is the bit decrement; elsewhere mark it invalid
            if low[i] > 0:
                low_bits[i] -= 1
            else:
                low[i] = -1.0
        for i in range(m):
            valid[i] = low[i] > 0
        for j in range(dim):
            for i in range(m):
                x = hom[start + i, j]
                q[i] = x / hom[start + i, dim]
                values[start + i, j] = q[i]
                r[i] = abs(x) + rad[start + i, j] + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):  # x_bound = up(up(|x| + e_x) e_w)
                r[i] = r[i] * err_w[i] + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):
                r[i] = r[i] / (low[i] if valid[i] else 1.0) + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):  # term = up(e_x + up(x_bound / low))
                r[i] = rad[start + i, j] + r[i] + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):  # d = up(term / |w|)
                r[i] = r[i] / (abs_w[i] if valid[i] else 1.0) + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):
                d[i] = abs(q[i]) * u_quotient + 0.0
            for i in range(m):
                d_bits[i] += 1
            for i in range(m):
                d[i] = d[i] + eta + 0.0
            for i in range(m):
                d_bits[i] += 1
            for i in range(m):
                r[i] = r[i] + d[i] + 0.0
            for i in range(m):
                r_bits[i] += 1
            for i in range(m):
                ri = r[i] if valid[i] else np.inf
                radii[start + i, j] = ri if math.isfinite(q[i]) and math.isfinite(ri) else np.inf


_COMPILED: dict = {}


def _compiled(func):
    kernel = _COMPILED.get(func.__name__)
    if kernel is None:
        import numba

        # error_model="numpy": a division by zero gives inf/nan as in numpy, never an exception
        kernel = numba.njit(cache=True, nogil=True, fastmath=False, error_model="numpy")(func)
        _COMPILED[func.__name__] = kernel
    return kernel


def horner_curve(c, c_abs_sum, t, g, eta, min_normal, values, radii, bound) -> None:
    """The compiled :func:`_horner_curve` (numba; compiled at the first call)."""
    _compiled(_horner_curve)(c, c_abs_sum, t, g, eta, min_normal, values, radii, bound)


def project(hom, rad, u_quotient, eta, values, radii) -> None:
    """The compiled :func:`_project` (numba; compiled at the first call)."""
    _compiled(_project)(hom, rad, u_quotient, eta, values, radii)

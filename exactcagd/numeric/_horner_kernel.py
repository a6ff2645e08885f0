"""Compiled kernel of Bernstein-Horner evaluation with its certified radius (optional numba).

Blocks of parameters go through what the numpy path of
:class:`exactcagd.numeric.evaluation._HornerBernstein` (and, for rational curves,
:func:`exactcagd.numeric.evaluation._project`) does with whole arrays: the same float
operations in the same order (notes 3.2, Horner's rule in Bernstein form; the radius of
:mod:`exactcagd.numeric.evaluation`, notes 13 (13.4)-(13.8)), so the values and radii are
bit-for-bit those of the numpy path (tested).  What makes it faster is only where the
intermediate results live:

* every per-parameter quantity (ratio, scale, running sums, radius) stays in a work
  array of :data:`BLOCK` parameters (in L1 cache), and every inner loop runs over the
  block's parameters without branches, so the compiler vectorizes it;
* Horner's steps are sequential, so one pass over the block takes up to 4 of them, on
  the values and on ``|c|`` (the radius' ``S^``) together: the running sums stay in
  registers between the steps instead of going to memory after each one;
* a rational curve's weight is evaluated first in each block and every coordinate is
  divided by it (with the radius of the quotient) while still in the block: the
  homogeneous values never go to a ``(P, D + 1)`` array.

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

__all__ = ["AVAILABLE", "horner_curve"]

#: numba installed (and not switched off by ``EXACTCAGD_NO_NUMBA``); it is imported, and the
#: kernels compiled (or loaded from numba's cache), at their first call, not at import time
#: (importing numba costs ~0.15 s)
AVAILABLE = not os.environ.get("EXACTCAGD_NO_NUMBA") and importlib.util.find_spec("numba") is not None


#: parameters per block: the block's work arrays stay in L1 and every inner loop runs over
#: the block's parameters (no branches, so the compiler vectorizes it), as numpy's does
BLOCK = 512


def _up(x):
    """``nextafter(x + 0.0, inf)`` for ``x >= 0`` (or ``nan``): the bit increment of
    :func:`exactcagd.numeric.fp_error.up_nonnegative`, on one float."""
    return np.int64(np.float64(x + 0.0).view(np.int64) + 1).view(np.float64)


def _down_positive(x):
    """``nextafter(x, -inf)`` where ``x > 0`` (``+inf`` included: the bit decrement), ``-1``
    elsewhere, where :func:`exactcagd.numeric.evaluation._project` never reads it."""
    return np.int64(np.float64(x).view(np.int64) - 1).view(np.float64) if x > 0 else -1.0


def _horner_curve(c, c_abs_sum, t, g, eta, min_normal, u_quotient, rational, values, radii, bound):
    """Values (and radii) of the curve ``sum_k c_k B_k`` at every ``t`` into ``(P, d)`` arrays.

    ``c`` is ``(n + 1, D)``: the binomial-scaled coefficients ``C(n, k) b_k``; for a
    ``rational`` curve its last column is the weight and ``d = D - 1`` coordinates
    ``X_j / W`` are stored, else ``d = D``.  ``c_abs_sum[j]`` is the sum of ``|c_k,j|``
    over ``k`` (numpy's ``np.sum``); ``g = gamma_over(6n + 1)``, ``eta = 2^-1074``,
    ``u_quotient >= u / (1 - u)`` as in the numpy path.  With ``bound`` false only
    ``values`` is written (``radii`` may be any float array).

    Returns ``False``, before any other work, if some ``t`` is not in [0, 1] (or is NaN):
    the caller's validation then says which.
    """
    outside = 0
    for i in range(t.shape[0]):  # one vectorized pass, no early exit
        outside += 0 if 0.0 <= t[i] <= 1.0 else 1
    if outside:
        return False
    n = c.shape[0] - 1
    a_factor = (2 * n + 2) * eta
    tiny_factor = 2 * n * eta
    first_steps = (n - 1) % 4 + 1 if n >= 1 else 0  # steps of the first pass: 1..4
    x = np.empty(BLOCK)
    base = np.empty(BLOCK)
    scale = np.empty(BLOCK)
    a = np.empty(BLOCK)
    a_j = np.empty(BLOCK)
    low = np.empty(BLOCK, dtype=np.bool_)
    w = np.empty(BLOCK)
    e_w = np.empty(BLOCK)
    w_low = np.empty(BLOCK)
    count = t.shape[0]
    dim = values.shape[1]
    h = np.empty((dim, BLOCK))  # values of the block, one row per coordinate
    e = np.empty((dim, BLOCK))  # their radii
    for start in range(0, count, BLOCK):
        m = min(BLOCK, count - start)
        any_tiny = False
        for i in range(m):
            tp = t[start + i]
            q = 1.0 - tp
            is_low = tp <= 0.5
            b = q if is_low else tp
            xi = (tp if is_low else q) / b
            x[i] = xi
            base[i] = b
            low[i] = is_low
            any_tiny |= xi != 0.0 and abs(xi) <= min_normal
        for i in range(m):
            scale[i] = base[i] if n >= 1 else 1.0
        for _ in range(n - 1):  # (1-t)^n or t^n by n - 1 repeated products
            for i in range(m):
                scale[i] = scale[i] * base[i]
        for i in range(m):
            s = abs(scale[i])
            # a_factor is subnormal: multiplying it by 1.0 (every t in [0, 1]) gives it back
            # exactly, and skipping that product avoids the CPU's slow subnormal path
            a[i] = a_factor if s <= 1.0 else a_factor * s
        if rational:
            _coordinate(c, c_abs_sum, dim, n, first_steps, x, low, scale, a, a_j, any_tiny, tiny_factor, min_normal,
                        g, bound, w, e_w, m)
            if bound:
                for i in range(m):
                    w_low[i] = _down_positive(abs(w[i]) - e_w[i])
        for j in range(dim):
            _coordinate(c, c_abs_sum, j, n, first_steps, x, low, scale, a, a_j, any_tiny, tiny_factor, min_normal,
                        g, bound, h[j], e[j], m)
            if rational:
                _divide(h[j], e[j], w, e_w, w_low, u_quotient, eta, bound, m)
        _store(values, h, start, m)
        if bound:
            _store(radii, e, start, m)
    return True


def _coordinate(c, c_abs_sum, j, n, first_steps, x, low, scale, a, a_j, any_tiny, tiny_factor, min_normal, g, bound,
                value, radius, m):
    """Column ``j`` of ``c`` on the block: ``value = h * scale`` and (if ``bound``) its radius.

    The first pass starts the recurrence and takes its first 1-4 steps, every further pass
    4 steps (same operations as one step per pass).  ``radius`` is ``inf`` where the value
    or the bound is not finite.
    """
    _first_pass(c, j, n, first_steps, x, low, value, radius, m)
    for k in range(first_steps + 1, n + 1, 4):
        _four_steps(c, j, n, k, x, low, value, radius, m)
    if not bound:
        for i in range(m):
            value[i] = value[i] * scale[i]
        return
    for i in range(m):
        a_j[i] = a[i]
    if any_tiny:  # s^ subnormal: its absolute error moves p (module docstring of evaluation)
        tiny_j = c_abs_sum[j] * tiny_factor
        for i in range(m):
            if x[i] != 0.0 and abs(x[i]) <= min_normal:
                a_j[i] = a[i] + tiny_j * abs(scale[i])
    for i in range(m):
        v = value[i] * scale[i]
        r = _up(g * _up(radius[i] * scale[i] + a_j[i]))  # up(g * up(S^ + A))
        r = _up(r + a_j[i])  # up(. + A)
        value[i] = v
        radius[i] = r if math.isfinite(v) and math.isfinite(r) else np.inf


def _step(v, u, xi, is_low, e, f):
    """One Horner step on the value ``v`` and on ``|c|`` (``u``): ``v x + d, u x + |d|``,
    ``d = e`` on the low half (``t <= 1/2``), ``f`` on the high half."""
    d = e if is_low else f
    return v * xi + d, u * xi + abs(d)


def _first_pass(c, j, n, steps, x, low, h, h_abs, m):
    """``h = c_first`` and the first ``steps`` (0-4) Horner steps, with the pass on ``|c|``."""
    e0, f0 = c[n, j], c[0, j]  # e*: coefficients of the low half (t <= 1/2), f*: the high half
    e1, f1 = c[max(n - 1, 0), j], c[min(1, n), j]
    e2, f2 = c[max(n - 2, 0), j], c[min(2, n), j]
    e3, f3 = c[max(n - 3, 0), j], c[min(3, n), j]
    e4, f4 = c[max(n - 4, 0), j], c[min(4, n), j]
    # the tests of steps are loop-invariant: the compiler unswitches them out of the loop
    for i in range(m):
        is_low = low[i]
        xi = x[i]
        v = e0 if is_low else f0
        u = abs(v)
        if steps >= 1:
            v, u = _step(v, u, xi, is_low, e1, f1)
        if steps >= 2:
            v, u = _step(v, u, xi, is_low, e2, f2)
        if steps >= 3:
            v, u = _step(v, u, xi, is_low, e3, f3)
        if steps >= 4:
            v, u = _step(v, u, xi, is_low, e4, f4)
        h[i] = v
        h_abs[i] = u


def _four_steps(c, j, n, k, x, low, h, h_abs, m):
    """Horner steps ``k .. k + 3``: coefficients ``c_(n-k) ..`` (low half), ``c_k ..`` (high)."""
    e1, f1 = c[n - k, j], c[k, j]
    e2, f2 = c[n - k - 1, j], c[k + 1, j]
    e3, f3 = c[n - k - 2, j], c[k + 2, j]
    e4, f4 = c[n - k - 3, j], c[k + 3, j]
    for i in range(m):
        is_low = low[i]
        xi = x[i]
        v, u = _step(h[i], h_abs[i], xi, is_low, e1, f1)
        v, u = _step(v, u, xi, is_low, e2, f2)
        v, u = _step(v, u, xi, is_low, e3, f3)
        h[i], h_abs[i] = _step(v, u, xi, is_low, e4, f4)


def _store(out, block, start, m):
    """``out[start + i, j] = block[j, i]`` for the block's ``m`` parameters (``out`` is C-ordered).

    With 1, 2 or 3 coordinates the row length is a constant of the loop, so the compiler
    interleaves whole vectors of coordinates (one loop per coordinate writes with a
    stride of ``d`` floats, one float at a time).
    """
    dim = out.shape[1]
    flat = out.reshape(-1)
    if dim == 1:
        for i in range(m):
            flat[start + i] = block[0, i]
    elif dim == 2:
        for i in range(m):
            flat[2 * (start + i)] = block[0, i]
            flat[2 * (start + i) + 1] = block[1, i]
    elif dim == 3:
        for i in range(m):
            flat[3 * (start + i)] = block[0, i]
            flat[3 * (start + i) + 1] = block[1, i]
            flat[3 * (start + i) + 2] = block[2, i]
    else:
        for i in range(m):
            for j in range(dim):
                out[start + i, j] = block[j, i]


def _divide(x, e_x, w, e_w, w_low, u_quotient, eta, bound, m):
    """``x = x / w`` and ``e_x`` its certified radius, in place, as numpy's ``_project``::

        |X^/W^ - X/W| <= (e_X + (|X^| + e_X) e_W / (|W^| - e_W)) / |W^| + u |X^/W^| + eta

    ``w_low = down(|W^| - e_W)`` (``<= 0``: the weight's enclosure may contain 0, radius
    ``inf``); ``up`` is the bit increment after ``+ 0.0``.
    """
    if not bound:
        for i in range(m):
            x[i] = x[i] / w[i]
        return
    for i in range(m):
        xi = x[i]
        ei = e_x[i]
        valid = w_low[i] > 0
        q = xi / w[i]
        x_bound = _up(_up(abs(xi) + ei) * e_w[i])  # up(up(|x| + e_x) e_w)
        term = _up(ei + _up(x_bound / (w_low[i] if valid else 1.0)))  # up(e_x + up(x_bound / low))
        d = _up(term / (abs(w[i]) if valid else 1.0))  # up(term / |w|)
        r = _up(d + _up(_up(abs(q) * u_quotient) + eta))
        r = r if valid else np.inf
        x[i] = q
        e_x[i] = r if math.isfinite(q) and math.isfinite(r) else np.inf


_COMPILED: dict = {}
#: helpers of the kernel: compiled before it and put in their place in this module's
#: namespace, where numba resolves the kernel's calls (LLVM inlines them)
_HELPERS = ("_up", "_down_positive", "_step", "_coordinate", "_first_pass", "_four_steps", "_divide", "_store")


def _compiled(func):
    kernel = _COMPILED.get(func.__name__)
    if kernel is None:
        import numba

        # error_model="numpy": a division by zero gives inf/nan as in numpy, never an exception
        options = {"nogil": True, "fastmath": False, "error_model": "numpy"}
        namespace = globals()
        for name in _HELPERS:
            if not isinstance(namespace[name], numba.core.dispatcher.Dispatcher):
                namespace[name] = numba.njit(**options)(namespace[name])
        kernel = numba.njit(cache=True, **options)(func)
        _COMPILED[func.__name__] = kernel
    return kernel


def horner_curve(c, c_abs_sum, t, g, eta, min_normal, u_quotient, rational, values, radii, bound) -> bool:
    """The compiled :func:`_horner_curve` (numba; compiled at the first call)."""
    return _compiled(_horner_curve)(c, c_abs_sum, t, g, eta, min_normal, u_quotient, rational, values, radii, bound)

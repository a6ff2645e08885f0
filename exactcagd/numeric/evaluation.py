"""Float evaluation of Bézier curves and surfaces with certified error bounds.

``evaluate(curve, ts)`` returns float64 points and, for every parameter and every
coordinate, a radius with ``|exact - value| <= radius``, where *exact* is the value of
the exact rational curve at the exact binary value of the float parameter.  The
evaluation is numpy-vectorized over all parameters at once (the loops run over the
degree, never over the parameters).

Three algorithms (Sederberg's notes, chapters 2.3 and 3), and the default ``"auto"``:
``"horner"`` on parameters in [0, 1] only (:class:`DomainError` outside, as de
Casteljau), run by a compiled loop (:mod:`exactcagd.numeric._horner_kernel`, numba) when
numba is installed -- the same operations, bit-for-bit the same values and radii:

``"decasteljau"``  repeated affine maps ``fl(fl(fl(1-t) a) + fl(t b))`` (notes 2.3, 12.16);
                   parameters must lie in [0, 1] (else :class:`DomainError`): outside
                   the unit interval the affine map extrapolates and the error grows
                   (notes 12.2.3); use ``"horner"`` or ``"power"`` there.
``"horner"``       Horner's rule in Bernstein form (notes 3.2): for ``t <= 1/2``
                   ``p(t) = (1-t)^n sum_k C(n,k) b_k s^k`` with ``s = t/(1-t)``, for
                   ``t > 1/2`` the mirror form in ``r = (1-t)/t`` scaled by ``t^n``;
                   ``|s|, |r| <= 1`` for every real ``t``, so any finite ``t`` is allowed.
``"power"``        exact conversion to the power basis (notes 3.3, ``bernstein.to_power``),
                   then Horner's rule (notes 3.1); any finite ``t`` is allowed.

Error bounds (notes 13, (13.4)-(13.8), in Higham's ``gamma_k`` notation; see
:mod:`exactcagd.numeric.fp_error` for the rounding model ``fl(x*y) = xy(1+delta)+eta``)
--------------------------------------------------------------------------------
Every algorithm computes ``p(t) = sum_i b_i phi_i(t)`` as a sum of terms, each term the
exact term times at most ``k`` rounding factors ``(1 + delta)^(+-1)``, so

    |computed - p(t)| <= gamma_k * S(t) + A,    S(t) = sum_i |b_i| |phi_i(t)|,

where ``A`` bounds the absolute underflow errors ``eta``.  The *same* algorithm run on
``|b_i|`` (and on the absolute values of its parameter quantities) computes ``S^`` with
only non-negative terms, so ``S^ >= (1 - u)^k S - A``, i.e. ``S <= (S^ + A)/(1 - k u)``.
The returned radius is

    radius = gamma_k / (1 - k u) * (S^ + A) + A,

every operation of this formula rounded upward (``nextafter`` after round-to-nearest);
``gamma_k/(1-ku)`` is rounded upward from its exact rational value.  ``A`` itself is
computed in round-to-nearest with a factor 2 of slack.  Counting the factors ``k``:

* de Casteljau: converting ``b_i`` to float (1 factor); each of the ``n`` levels
  multiplies by ``fl(1-t)`` (rounded: 1), rounds the product (1) and the sum (1) on the
  ``(1-t)`` branch, the product (1) and the sum on the ``t`` branch: at most 3 per level,
  ``k = 3n + 1``; for ``t`` in [1/2, 1] (or whenever ``fl(1-t)`` is exact, tested by
  ``1 - (1 - t) == t``) ``k = 2n + 1``.  ``A = (n + 1) 2^-1074``: the products of a level
  contribute ``2 * 2^-1075`` per node, weighted by Bernstein values that sum to 1.
* Horner (Bernstein): conversion of ``C(n,k) b_k`` (1), ``s^ = fl(t / fl(1-t))`` (2 per
  power of ``s``: ``2k``), ``k`` products and ``k + 1`` sums in the Horner recurrence,
  ``(1-t)^n`` by ``n - 1`` repeated multiplications of ``fl(1-t)`` (``2n - 1``), the
  final product (1): ``k = 6n + 1``.  ``A = (2n + 2) 2^-1074 max(1, |scale|)`` (``|s| <= 1``);
  if ``s^`` is subnormal (``|t| < 2^-1021``) it carries an absolute error ``2^-1075``
  which moves ``p`` by at most ``n 2^-1075 sum_k |C(n,k) b_k| |scale|``; twice that is
  added to ``A``.
* power basis: conversion (1), ``k`` products and ``k`` or ``k + 1`` sums for the term
  ``a_k t^k``: ``k = 2n + 1``; ``A = (2n + 1) 2^-1074 max(1, |t|)^n``.

The factor 2 in ``2^-1074 = 2 * 2^-1075`` absorbs the ``(1 + u)^{O(n)}`` growth of the
propagated underflow errors and the roundings in computing ``A`` (``n < 10^6``).  Surfaces are evaluated in two stages (rows
in ``v``, then the column in ``u``); with ``gamma_a + gamma_b + gamma_a gamma_b <=
gamma_{a+b}`` the same formula holds with ``k = k_u + k_v``,
``S = sum_ij |b_ij| |phi_i(u)| |phi_j(v)|`` and ``A = L_u A_v + A_u`` (``L_u >= 2 sum_i
|phi_i(u)|``).

Rational curves: the homogeneous numerator ``X`` and weight ``W`` are evaluated with
radii ``e_X, e_W``; with ``|W^| > e_W``,

    |X^/W^ - X/W| <= (e_X + |X/W| e_W) / |W^|,   |X/W| <= (|X^| + e_X) / (|W^| - e_W),

plus the rounding of the quotient ``u |X^/W^| + 2^-1075``.  If the enclosure
``[W^ - e_W, W^ + e_W]`` contains 0 the radius is ``inf``.  A radius is also ``inf``
wherever the float computation overflowed.

>>> from exactcagd import BezierCurve
>>> from exactcagd.numeric.evaluation import evaluate
>>> values, radii = evaluate(BezierCurve([[0, 0], [1, 2], [2, 0]]), [0.0, 0.5, 1.0])
>>> values.tolist()
[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]
>>> bool((radii < 1e-14).all())
True
"""

from __future__ import annotations

import math
import threading
from functools import lru_cache

import numpy as np
from gmpy2 import mpq

from ..errors import DomainError, InexactInputError, InputError
from ..exact import bernstein as bz
from ..exact.scalars import short_repr, to_rational
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from . import _horner_kernel
from .fp_error import ETA, MIN_NORMAL, down, gamma_over, round_nearest, round_up, to_float_array
from .fp_error import up_nonnegative

__all__ = ["evaluate", "evaluate_surface", "METHODS"]

METHODS = ("auto", "decasteljau", "horner", "power")
#: run the default method through the compiled kernel when numba is installed (tests
#: switch it off to check the numpy fallback against it) ...
KERNEL = True
#: ... for at least this many parameters per call: below it the numpy path is as fast, and
#: a short script does not pay numba's import and cache load (~0.5 s) for a few points
KERNEL_MIN_POINTS = 4096


def _use_kernel(count: int) -> bool:
    return KERNEL and count >= KERNEL_MIN_POINTS and _horner_kernel.AVAILABLE

#: upper bound of u / (1 - u), the relative rounding error of one correctly rounded quotient
_U_QUOTIENT = round_up(mpq(1, 2**53) / (1 - mpq(1, 2**53)))
#: parameters per chunk are chosen so that the work arrays hold about this many floats
#: (2 MB: large enough that numpy's per-call overhead is small -- measured faster than
#: L2-sized chunks --, at least ``_MIN_CHUNK`` parameters so the inner loops stay long)
_CHUNK_FLOATS = 1 << 18
_MIN_CHUNK = 512


# ---------------------------------------------------------------------------- methods
# Layout: coefficient arrays have the Bernstein index on axis 0 and the parameter axis
# LAST (length 1 when the coefficients do not depend on the parameter), so numpy's inner
# loops run along the parameters; ``t`` is the 1-d array of parameters.  For curves the
# coefficients ``c`` and ``|c|`` are also stacked as a *pair* of shape ``(n+1, 2, D, 1)``:
# one pass of a method over the pair yields the values (row 0) and the sum ``S^`` of the
# error bound (row 1), every float operation the same as in two separate passes.


class _Scratch(threading.local):
    """Per-thread working memory, kept between calls."""

    buffer = np.empty(0)


_SCRATCH = _Scratch()
#: largest working memory (floats) kept per thread; larger requests are allocated afresh
_SCRATCH_LIMIT = 1 << 20


def _scratch(*shapes: tuple[int, ...]) -> list[np.ndarray]:
    """Uninitialized float64 arrays of the given shapes, in memory reused across calls.

    Allocating and first touching megabytes of fresh memory for every chunk costs page
    faults that can exceed the arithmetic of de Casteljau's algorithm itself.  The arrays
    are views of one per-thread buffer: they are valid until the next call of this
    function in the same thread, so no caller may return them.
    """
    sizes = [math.prod(shape) for shape in shapes]
    total = sum(sizes)
    if total > _SCRATCH_LIMIT:
        buffer = np.empty(total)
    else:
        buffer = _SCRATCH.buffer
        if buffer.size < total:
            buffer = _SCRATCH.buffer = np.empty(total)
    offsets = np.cumsum([0] + sizes)
    return [buffer[offsets[i] : offsets[i + 1]].reshape(shape) for i, shape in enumerate(shapes)]


def _select(c: np.ndarray, index) -> np.ndarray:
    """The coefficients belonging to the parameters ``index`` (all of them if shared)."""
    return c if c.shape[-1] == 1 else c[..., index]


def _index(mask: np.ndarray):
    """Positions of ``mask``: a slice when they are contiguous, ``None`` when there are none."""
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return None
    if idx[-1] - idx[0] + 1 == idx.size:
        return slice(int(idx[0]), int(idx[-1]) + 1)
    return idx


def _store(out: np.ndarray, index, rows: np.ndarray) -> None:
    """``out[index, j] = rows[j]`` for every coordinate ``j`` (``out`` is ``(P, D)``).

    One 1-d assignment per coordinate: this transposes and scatters in one pass, faster
    than ``out[index] = rows.T`` for an index array.
    """
    for j, row in enumerate(rows):
        out[index, j] = row


def _with_abs(x: np.ndarray) -> np.ndarray:
    """``x`` and ``|x|`` stacked to shape ``(2, 1, P)``, the multiplier of a pair pass."""
    return np.stack([x, np.abs(x)])[:, None]


class _DeCasteljau:
    """De Casteljau's algorithm (notes 2.3) on float coefficients, vectorized, in place."""

    name = "decasteljau"

    @staticmethod
    def work(coefficients: int, dim: int) -> int:
        """Floats of working memory per parameter (the whole triangle's current level)."""
        return coefficients * dim

    @staticmethod
    def check(t: np.ndarray, where: str) -> None:
        if t.size == 0 or (t.min() >= 0 and t.max() <= 1):  # two reductions, no temporaries
            return
        bad = (t < 0) | (t > 1)
        if bad.any():
            first = float(t[bad][0])
            raise DomainError(
                f"{where}: de Casteljau evaluation needs parameters in [0, 1]; got {first!r}"
                f" ({int(bad.sum())} outside). Use method='horner' or 'power' to extrapolate."
            )

    @staticmethod
    def coefficients(exact: np.ndarray, axis: int) -> np.ndarray:
        return exact

    @classmethod
    def run(cls, c: np.ndarray, t: np.ndarray, absolute: bool) -> np.ndarray:
        return cls._triangle(c, t, absolute).copy()

    @staticmethod
    def _triangle(c: np.ndarray, t: np.ndarray, absolute: bool) -> np.ndarray:
        """Like :meth:`run`, but the result lives in the scratch memory (see :func:`_scratch`)."""
        s = 1.0 - t
        shape = c.shape[:-1] + t.shape
        level, buf = _scratch(shape, (shape[0] - 1,) + shape[1:])
        np.copyto(level, np.abs(c) if absolute else c)
        for m in range(c.shape[0] - 1, 0, -1):
            # level[i] <- fl(fl(s * level[i]) + fl(t * level[i+1])), i < m
            np.multiply(level[1 : m + 1], t, out=buf[:m])
            np.multiply(level[:m], s, out=level[:m])
            np.add(level[:m], buf[:m], out=level[:m])
        return level[0]

    @classmethod
    def curve(cls, c, c_abs, pair, t, values, radii) -> None:
        """Store the values (and radii, unless ``None``) at ``t`` in the ``(P, D)`` outputs.

        ``s, t >= 0``, so the pass over the pair ``[c, |c|]`` gives the values and ``S^``.
        """
        if radii is None:
            _store(values, slice(None), cls._triangle(c, t, False))
            return
        n = c.shape[0] - 1
        v, s_hat = cls._triangle(pair, t, False)
        _store(values, slice(None), v)
        _store(radii, slice(None), _finish(v, _radius(cls.factor(n, t), s_hat, cls.underflow(n, t, c_abs))))

    @staticmethod
    def count(n: int, t: np.ndarray) -> np.ndarray:
        exact_complement = (1.0 - (1.0 - t)) == t  # Sterbenz: fl(1-t) exact <=> this
        return np.where(exact_complement, 2 * n + 1, 3 * n + 1)

    @staticmethod
    def factor(n: int, t: np.ndarray) -> np.ndarray:
        """``gamma_over(count(n, t))``, choosing between the two possible counts directly."""
        exact_complement = (1.0 - (1.0 - t)) == t
        return np.where(exact_complement, gamma_over(2 * n + 1), gamma_over(3 * n + 1))

    @staticmethod
    def underflow(n: int, t: np.ndarray, c_abs: np.ndarray) -> float:
        return (n + 1) * ETA

    @staticmethod
    def spread(n: int, t: np.ndarray) -> float:
        return 2.0


class _HornerBernstein:
    """Horner's rule in Bernstein form (notes 3.2), ratio ``|s| <= 1`` on both halves.

    The parameters ``t <= 1/2`` and ``t > 1/2`` are evaluated as two separate groups
    (gathered by index), each with its fixed coefficient order.
    """

    name = "horner"

    @staticmethod
    def work(coefficients: int, dim: int) -> int:
        """Floats per parameter: one running value per coordinate plus ratio and scale."""
        return dim + 4

    @staticmethod
    def check(t: np.ndarray, where: str) -> None:
        return None

    @staticmethod
    def coefficients(exact: np.ndarray, axis: int) -> np.ndarray:
        n = exact.shape[axis] - 1
        shape = [1] * exact.ndim
        shape[axis] = n + 1
        binom = np.array([bz.binomial(n, i) for i in range(n + 1)], dtype=object).reshape(shape)
        return exact * binom

    @staticmethod
    def _parts(t: np.ndarray):
        low = t <= 0.5
        q = 1.0 - t
        with np.errstate(divide="ignore", invalid="ignore"):
            x = np.where(low, t / np.where(low, q, 1.0), q / np.where(low, 1.0, t))
        base = np.where(low, q, t)
        return low, x, base

    @staticmethod
    def _halves(t: np.ndarray):
        """``(index, low)`` for the halves ``t <= 1/2`` (``low``) and ``t > 1/2`` that are not empty."""
        low = t <= 0.5
        for index, is_low in ((_index(low), True), (_index(~low), False)):
            if index is not None:
                yield index, is_low

    @staticmethod
    def _ratio(t: np.ndarray, low: bool):
        """Ratio and base: ``t/(1-t)`` and ``1-t`` on the low half, ``(1-t)/t`` and ``t`` above."""
        q = 1.0 - t
        return (t / q, q) if low else (q / t, t)

    @staticmethod
    def _order(n: int, low: bool) -> range:
        # low: sum_k c_k s^k, Horner from c_n down; high: sum_k c_k r^(n-k), from c_0 up
        return range(n, -1, -1) if low else range(n + 1)

    @staticmethod
    def _scale(base: np.ndarray, n: int) -> np.ndarray:
        scale = np.ones_like(base)
        if n >= 1:
            scale = base.copy()
            for _ in range(n - 1):
                scale *= base
        return scale

    @staticmethod
    def _horner(c: np.ndarray, x: np.ndarray, order) -> np.ndarray:
        order = list(order)
        if len(order) == 1:
            return np.array(np.broadcast_to(c[order[0]], np.broadcast_shapes(c.shape[1:], x.shape)))
        h = np.multiply(c[order[0]], x)
        np.add(h, c[order[1]], out=h)
        for i in order[2:]:
            np.multiply(h, x, out=h)
            np.add(h, c[i], out=h)
        return h

    @classmethod
    def run(cls, c: np.ndarray, t: np.ndarray, absolute: bool) -> np.ndarray:
        n = c.shape[0] - 1
        out = np.empty(np.broadcast_shapes(c.shape[1:], t.shape))
        for index, low in cls._halves(t):
            x, base = cls._ratio(t[index], low)
            ci = _select(c, index)
            if absolute:
                ci, x, base = np.abs(ci), np.abs(x), np.abs(base)
            h = cls._horner(ci, x, cls._order(n, low))
            h *= cls._scale(base, n)
            out[..., index] = h
        return out

    @classmethod
    def curve(cls, c, c_abs, pair, t, values, radii) -> None:
        """Store the values (and radii, unless ``None``) at ``t`` in the ``(P, D)`` outputs."""
        n = c.shape[0] - 1
        g = gamma_over(cls.count(n, t))
        for index, low in cls._halves(t):
            x, base = cls._ratio(t[index], low)
            scale = cls._scale(base, n)  # base = max(|t|, |1-t|) > 0: |scale| = scale
            if radii is None:
                h = cls._horner(c, x, cls._order(n, low))
                h *= scale
                _store(values, index, h)
                continue
            h = cls._horner(pair, _with_abs(x), cls._order(n, low))
            h *= scale
            v, s_hat = h
            a = cls._underflow(n, x, scale, c_abs)
            _store(values, index, v)
            _store(radii, index, _finish(v, _radius(g, s_hat, a)))

    @staticmethod
    def count(n: int, t: np.ndarray) -> int:
        return 6 * n + 1

    @staticmethod
    def _underflow(n: int, x: np.ndarray, scale: np.ndarray, c_abs: np.ndarray) -> np.ndarray:
        # round-to-nearest here: the factor 2 in ETA = 2 * 2^-1075 absorbs these roundings
        scale = np.abs(scale)
        a = ((2 * n + 2) * ETA) * np.maximum(1.0, scale)
        tiny = (x != 0) & (np.abs(x) <= MIN_NORMAL)
        if tiny.any():
            total = np.sum(c_abs, axis=0)
            a = a + np.where(tiny, total * (2 * n * ETA) * scale, 0.0)
        return a

    @classmethod
    def underflow(cls, n: int, t: np.ndarray, c_abs: np.ndarray) -> np.ndarray:
        _, x, base = cls._parts(t)
        return cls._underflow(n, x, cls._scale(base, n), c_abs)

    @staticmethod
    def spread(n: int, t: np.ndarray) -> np.ndarray:
        # 2 sum_i |B_i(t)| = 2 (|1 - t| + |t|)^n, with a factor 2 for the roundings
        w = np.abs(1.0 - t) + np.abs(t)
        out = np.full(np.shape(t), 4.0)
        for _ in range(n):
            out = out * w
        return out


class _Default(_HornerBernstein):
    """The default: Horner's rule in Bernstein form on parameters in [0, 1] only.

    The same float operations and radius as ``"horner"`` (so the same certificate), run
    by the compiled kernel :mod:`exactcagd.numeric._horner_kernel` when numba is installed
    (bit-for-bit the numpy path's results, which stays the fallback), and refusing
    parameters outside [0, 1] like de Casteljau's algorithm: there the default evaluates,
    extrapolation needs an explicit ``method="horner"`` or ``"power"``.
    """

    name = "auto"
    check = _DeCasteljau.check

    @classmethod
    def compiled(cls, curve: BezierCurve, t: np.ndarray, bound: bool):
        """The whole evaluation by the kernel: values ``(P, d)`` (and radii), divided by the
        weight block by block if the curve is rational; ``None`` if some ``t`` is not in
        [0, 1] (NaN included), found before any other work.
        """
        c, c_abs_sum, g = _kernel_arguments(curve)
        dim = c.shape[1] - 1 if curve.is_rational else c.shape[1]
        # one allocation for both outputs (see evaluate)
        values, radii = np.empty((2, t.size, dim)) if bound else (np.empty((t.size, dim)),) * 2
        if not _horner_kernel.horner_curve(c, c_abs_sum, t, g, ETA, MIN_NORMAL, _U_QUOTIENT, curve.is_rational,
                                           values, radii, bound):
            return None
        return (values, radii) if bound else values


class _PowerHorner:
    """Exact conversion to the power basis (notes 3.3), then Horner's rule (notes 3.1)."""

    name = "power"

    @staticmethod
    def work(coefficients: int, dim: int) -> int:
        return dim + 1

    @staticmethod
    def check(t: np.ndarray, where: str) -> None:
        return None

    @staticmethod
    def coefficients(exact: np.ndarray, axis: int) -> np.ndarray:
        return bz.along(axis, bz.to_power, exact)

    @staticmethod
    def run(c: np.ndarray, t: np.ndarray, absolute: bool) -> np.ndarray:
        if absolute:
            c, t = np.abs(c), np.abs(t)
        n = c.shape[0] - 1
        return _HornerBernstein._horner(c, t, range(n, -1, -1))

    @classmethod
    def curve(cls, c, c_abs, pair, t, values, radii) -> None:
        """Store the values (and radii, unless ``None``); the pair pass runs on ``t`` and ``|t|``."""
        if radii is None:
            _store(values, slice(None), cls.run(c, t, False))
            return
        n = c.shape[0] - 1
        v, s_hat = _HornerBernstein._horner(pair, _with_abs(t), range(n, -1, -1))
        _store(values, slice(None), v)
        _store(radii, slice(None), _finish(v, _radius(gamma_over(cls.count(n, t)), s_hat, cls.underflow(n, t, c_abs))))

    @staticmethod
    def count(n: int, t: np.ndarray) -> int:
        return 2 * n + 1

    @staticmethod
    def _growth(n: int, t: np.ndarray) -> np.ndarray:
        # max(1, |t|)^n in round-to-nearest; the factor 2 in ETA absorbs the (1 + u)^n
        g = np.maximum(1.0, np.abs(t))
        out = np.ones_like(g)
        for _ in range(n):
            out = out * g
        return out

    @classmethod
    def underflow(cls, n: int, t: np.ndarray, c_abs: np.ndarray) -> np.ndarray:
        return ((2 * n + 1) * ETA) * cls._growth(n, t)

    @classmethod
    def spread(cls, n: int, t: np.ndarray) -> np.ndarray:
        return (4.0 * (n + 1)) * cls._growth(n, t)


_METHODS = {m.name: m for m in (_Default, _DeCasteljau, _HornerBernstein, _PowerHorner)}


def _method(method):
    try:
        return _METHODS[method]
    except (KeyError, TypeError):
        raise InputError(f"unknown evaluation method {method!r}; expected one of {METHODS}") from None


# ---------------------------------------------------------------------------- inputs
def _parameters(ts, where: str) -> np.ndarray:
    """Float64 parameters, each equal to the given number exactly (never rounded here)."""
    try:
        arr = np.asarray(ts)
    except ValueError:  # ragged nesting such as [0, [[]]]
        raise InputError(f"{where}: expected a 1-d sequence of parameters, got {short_repr(ts)}") from None
    if arr.ndim > 1:
        raise InputError(f"{where}: expected a 1-d sequence of parameters, got shape {arr.shape}")
    arr = np.atleast_1d(arr)
    kind = arr.dtype.kind
    if kind == "f":
        out = arr.astype(np.float64)
        if arr.dtype.itemsize > 8 and not np.all((out == arr) | np.isnan(arr)):
            raise InexactInputError(f"{where}: extended-precision parameters are not binary64 numbers")
    elif kind in "iu" or kind == "O" or kind == "U":
        out = np.array([_one_parameter(x, where) for x in arr.tolist()], dtype=np.float64)
    else:
        raise InputError(f"{where}: parameters of dtype {arr.dtype} are not numbers")
    bad = ~np.isfinite(out)
    if bad.any():
        raise InexactInputError(f"{where}: parameter {float(out[bad][0])!r} is not a finite number")
    return out


def _one_parameter(x, where: str) -> float:
    if isinstance(x, bool):
        raise InputError(f"{where}: booleans are not parameters ({x!r})")
    if isinstance(x, float):
        return x
    if isinstance(x, np.floating):
        return float(x)
    q = to_rational(x, where=where, policy="exact")
    f = round_nearest(q)
    if not math.isfinite(f) or mpq(*f.as_integer_ratio()) != q:
        raise InexactInputError(
            f"{where}: parameter {short_repr(x)} is not exactly a binary64 number; evaluate it exactly "
            "(BezierCurve.evaluate) or round it to a float explicitly"
        )
    return f


# ---------------------------------------------------------------------------- coefficients
def _frozen(*arrays: np.ndarray) -> tuple[np.ndarray, ...]:
    """The arrays made read-only: they are cached and shared between calls."""
    for a in arrays:
        a.flags.writeable = False
    return arrays


@lru_cache(maxsize=64)
def _curve_coefficients(curve: BezierCurve, method: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Float coefficients ``c``, ``|c|`` and the pair ``[c, |c|]`` (axis 1), read-only."""
    exact = curve.points_array() if not curve.is_rational else curve.homogeneous()
    c = to_float_array(_METHODS[method].coefficients(exact, 0))
    c_abs = np.abs(c)
    return _frozen(c, c_abs, np.stack([c, c_abs], axis=1))


@lru_cache(maxsize=64)
def _kernel_arguments(curve: BezierCurve) -> tuple[np.ndarray, np.ndarray, float]:
    """The kernel's ``(c, sum_k |c_k|, gamma_over(6n + 1))``, read-only; one cache lookup per call.

    Keyed by the curve's hash like :func:`_curve_coefficients` (not by identity: a curve
    built on an array its maker still owns can change in place, and its hash with it).
    """
    c, c_abs, _ = _curve_coefficients(curve, _Default.name)
    return (c, *_frozen(np.sum(c_abs, axis=0)), gamma_over(_Default.count(c.shape[0] - 1, None)))


def _is_float_vector(ts) -> bool:
    """``ts`` is a 1-d contiguous, writable float64 ndarray: the kernel reads it as it is."""
    return (type(ts) is np.ndarray and ts.dtype == np.float64 and ts.ndim == 1 and ts.flags.c_contiguous
            and ts.flags.writeable)


@lru_cache(maxsize=16)
def _surface_coefficients(surface: BezierSurface, method: str) -> tuple[np.ndarray, np.ndarray]:
    exact = surface.net_array() if not surface.is_rational else surface.homogeneous()
    m = _METHODS[method]
    c = to_float_array(m.coefficients(m.coefficients(exact, 0), 1))
    return _frozen(c, np.abs(c))


# ---------------------------------------------------------------------------- kernels
def _radius(g, s_hat: np.ndarray, a) -> np.ndarray:
    """``g (S^ + A) + A`` rounded upward, ``g = gamma_over(k)`` (``gamma_k / (1 - k u)``)."""
    return up_nonnegative(up_nonnegative(g * up_nonnegative(s_hat + a)) + a)


def _finish(values: np.ndarray, radii: np.ndarray) -> np.ndarray:
    return np.where(np.isfinite(values) & np.isfinite(radii), radii, np.inf)


def _surface_chunk(m, c, c_abs, u, v, bound):
    """Two stages: rows in ``v`` (shape ``(l+1, D, P)``), then the column in ``u``."""
    l, mm = c.shape[0] - 1, c.shape[1] - 1
    c1 = np.moveaxis(c, 1, 0)[..., None]  # (m+1, l+1, D, 1)
    rows = m.run(c1, v, False)  # (l+1, D, P)
    values = m.run(rows, u, False)  # (D, P)
    if not bound:
        return values, None
    a1_in = np.moveaxis(c_abs, 1, 0)[..., None]
    s_rows = m.run(a1_in, v, True)
    a1 = m.underflow(mm, v, a1_in)
    t_hat = m.run(s_rows, u, True)
    a2 = m.underflow(l, u, np.maximum(np.abs(rows), s_rows))
    a1_max = np.max(np.broadcast_to(a1, s_rows.shape), axis=0)
    a = up_nonnegative(up_nonnegative(a1_max * m.spread(l, u)) + a2)
    k = m.count(mm, v) + m.count(l, u)
    return values, _finish(values, _radius(gamma_over(k), t_hat, a))


def _project(hom: np.ndarray, rad: np.ndarray | None):
    """Divide the homogeneous values by the weight and bound the quotient rigorously."""
    x, w = hom[:, :-1], hom[:, -1:]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        q = x / w
        if rad is None:
            return q, None
        ex, ew = rad[:, :-1], rad[:, -1:]
        aw = np.abs(w)
        low = down(aw - ew)
        valid = low > 0
        x_bound = up_nonnegative(up_nonnegative(np.abs(x) + ex) * ew)
        term = up_nonnegative(ex + up_nonnegative(x_bound / np.where(valid, low, 1.0)))
        d = up_nonnegative(term / np.where(valid, aw, 1.0))
        r = up_nonnegative(d + up_nonnegative(up_nonnegative(np.abs(q) * _U_QUOTIENT) + ETA))
        r = np.where(valid, r, np.inf)
    return q, _finish(q, r)


def _chunks(count: int, per_parameter: int):
    size = max(_MIN_CHUNK, _CHUNK_FLOATS // max(per_parameter, 1))
    for start in range(0, count, size):
        yield slice(start, min(start + size, count))


# ---------------------------------------------------------------------------- public
def evaluate(curve, ts, method: str = "auto", bound: bool = True):
    """Evaluate a Bézier curve at many float parameters with certified error radii.

    Parameters
    ----------
    curve : BezierCurve
        Polynomial or rational, any dimension ``d``, any degree ``n``.
    ts : sequence of float or 1-d ndarray
        Parameters; each is taken as its exact binary64 value.  Integers and exact
        rationals are accepted only if they are binary64 numbers exactly
        (:class:`InexactInputError` otherwise, and for NaN/inf).
    method : {"auto", "decasteljau", "horner", "power"}
        Algorithm (see the module docstring).  ``"auto"`` (default) is ``"horner"``
        restricted to ``ts`` in [0, 1], compiled when numba is installed;
        ``"auto"`` and ``"decasteljau"`` need ``ts`` in [0, 1] (:class:`DomainError`);
        the others accept any finite parameter.  Horner is O(n) per point against de
        Casteljau's O(n^2), with errors of the same size
        (``benchmarks/results/peers_evaluate.md``); ``"power"`` loses accuracy as the
        degree grows.
    bound : bool
        With ``False`` only the values are returned (no second pass).

    Returns
    -------
    values : ndarray, shape ``(len(ts), d)``
    radii : ndarray, shape ``(len(ts), d)`` (only when ``bound``)
        ``|exact_j(t_i) - values[i, j]| <= radii[i, j]`` for every ``i, j``; ``inf`` where
        no bound could be certified (overflow, or a weight enclosure containing 0).

    Examples
    --------
    >>> from exactcagd import BezierCurve
    >>> quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    >>> p, r = evaluate(quarter, [0.25], method="horner")
    >>> bool(abs(p[0, 0] ** 2 + p[0, 1] ** 2 - 1) < 1e-15 and r.max() < 1e-14)
    True
    """
    if not isinstance(curve, BezierCurve):
        raise InputError(f"evaluate needs a BezierCurve, got {type(curve).__name__}")
    m = _method(method)
    if m is _Default and _is_float_vector(ts) and _use_kernel(ts.size):
        # the kernel checks 0 <= t <= 1 itself (no copy of ts); if it refuses a
        # parameter, the validation below names it
        result = _Default.compiled(curve, ts, bound)
        if result is not None:
            return result
    t = _parameters(ts, "ts")
    m.check(t, "ts")
    if m is _Default and _use_kernel(t.size):
        return _Default.compiled(curve, t, bound)  # t passed the kernel's own check
    c, c_abs, pair = (a[..., None] for a in _curve_coefficients(curve, m.name))
    dim = c.shape[1]
    # one allocation for both outputs: two fresh arrays of this size each cost their page
    # faults again on every call (measured 7 ms against 1.1 ms for 10^5 points in 3-D)
    values, radii = np.empty((2, t.size, dim)) if bound else (np.empty((t.size, dim)), None)
    for sl in _chunks(t.size, m.work(c.shape[0], 2 * dim if bound else dim)):
        with np.errstate(all="ignore"):  # overflow shows up as an infinite radius
            m.curve(c, c_abs, pair, t[sl], values[sl], radii[sl] if bound else None)
    if curve.is_rational:
        values, radii = _project(values, radii)
    return (values, radii) if bound else values


def evaluate_surface(surface, us, vs, method: str = "auto", bound: bool = True):
    """Evaluate a tensor-product Bézier surface at parameter pairs ``(us[i], vs[i])``.

    Rows in ``v`` are evaluated first, then the column in ``u`` (notes 15.2); the radius
    is certified as explained in the module docstring (``k = k_u + k_v``).

    Parameters
    ----------
    surface : BezierSurface
    us, vs : 1-d sequences of floats of equal length
    method, bound : as in :func:`evaluate`

    Returns
    -------
    values, radii : ndarrays of shape ``(len(us), d)``

    Examples
    --------
    >>> from exactcagd import BezierSurface
    >>> s = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    >>> p, r = evaluate_surface(s, [0.5], [0.5])
    >>> p.tolist(), bool(r.max() < 1e-15)
    ([[0.5, 0.5, 0.25]], True)
    """
    if not isinstance(surface, BezierSurface):
        raise InputError(f"evaluate_surface needs a BezierSurface, got {type(surface).__name__}")
    m = _method(method)
    u = _parameters(us, "us")
    v = _parameters(vs, "vs")
    if u.shape != v.shape:
        raise InputError(f"us and vs must have the same length, got {u.size} and {v.size}")
    m.check(u, "us")
    m.check(v, "vs")
    c, c_abs = _surface_coefficients(surface, m.name)
    dim = c.shape[2]
    values = np.empty((u.size, dim))
    radii = np.empty((u.size, dim)) if bound else None
    for sl in _chunks(u.size, c.size):
        with np.errstate(all="ignore"):  # overflow shows up as an infinite radius
            val, r = _surface_chunk(m, c, c_abs, u[sl], v[sl], bound)
        values[sl] = val.T
        if bound:
            radii[sl] = r.T
    if surface.is_rational:
        values, radii = _project(values, radii)
    return (values, radii) if bound else values

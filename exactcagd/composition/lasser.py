"""Route (a): the composition formula of Lasser & Bonneau (000), Theorems 1 and 2.

Theorem 1 (eqs. (5)-(7)), polynomial case::

    F(K(t)) = sum_{R=0}^{rN} B_R B^{rN}_R(t),   r = l + m,
    B_R = sum_{|I| = R} C^{l,m}_R(N, I) F^{l,m}_{0,0}(u^l_{I^u}, v^m_{I^v}),
    C^{l,m}_R(N, I) = prod_{Q=1}^{l} C(N, I^u_Q) prod_{Q=1}^{m} C(N, I^v_Q) / C(rN, R),

summed over all multi-indices ``I = (I^u_1..I^u_l, I^v_1..I^v_m)`` in ``{0..N}^(l+m)``
with ``|I| = R``; ``F^{l,m}_{0,0}(u_{I^u}, v_{I^v})`` is the polar form (blossom) of the
surface at the u-coordinates ``u_{I^u_1}, ..., u_{I^u_l}`` and v-coordinates
``v_{I^v_1}, ..., v_{I^v_m}`` of the curve's control points ``K_I = (u_I, v_I)``,
computed by the de Casteljau recursion printed after (7) (one level per argument).

Theorem 2 (eqs. (13)-(16)), rational case: the same sum applied to the homogeneous net
``(w F, w)`` (the polar forms ``omega^{l,m}_{0,0}`` and ``omega F``), with constants

    B^{l,m}_R(N, I) = prod_Q beta_{I^u_Q} C(N, I^u_Q) prod_Q beta_{I^v_Q} C(N, I^v_Q) / C(rN, R).

This module is the *teaching / verification* route: it evaluates the formula as printed.
``enumeration="ordered"`` sums over all ``(N+1)^(l+m)`` ordered multi-indices (literally
(6)/(15)); the default ``"multisets"`` uses the symmetry of the polar form to sum over
multisets, each weighted by its number of orderings ``l!/prod(k!)`` -- the same sum,
``C(N+l, l) C(N+m, m)`` polar values instead of ``(N+1)^(l+m)``.
The entries may be any objects closed under ``+ - *`` (e.g. sympy symbols).

>>> from exactcagd.exact.scalars import to_rational_array
>>> net = to_rational_array([[[0, 1], [0, 1]], [[1, 1], [1, 1]]])    # F(u, v) = u
>>> curve = to_rational_array([[0, 0, 1], [1, 1, 1]])                 # K(t) = (t, t)
>>> [str(x) for x in compose_homogeneous_lasser(net, curve)[:, 0]]
['0', '1/2', '1']
"""

from __future__ import annotations

import itertools
from collections import Counter
from math import factorial, prod

import numpy as np
from gmpy2 import mpq

from ..errors import InputError
from ..exact import bernstein as bz

__all__ = [
    "compose_homogeneous_lasser",
    "lasser_constant",
    "polar_value",
    "multi_indices",
    "trace_theorem1",
]


def multi_indices(l: int, m: int, N: int, R: int):
    """All ordered multi-indices ``(I^u, I^v)`` in ``{0..N}^l x {0..N}^m`` with ``|I| = R``."""
    for iu in itertools.product(range(N + 1), repeat=l):
        su = sum(iu)
        if su > R:
            continue
        for iv in itertools.product(range(N + 1), repeat=m):
            if su + sum(iv) == R:
                yield iu, iv


def lasser_constant(l: int, m: int, N: int, iu, iv, betas=None):
    """The constant ``C^{l,m}_R(N, I)`` of (7), or ``B^{l,m}_R(N, I)`` of (16) with ``betas``.

    >>> lasser_constant(1, 1, 2, (1,), (2,))          # C(2,1) C(2,2) / C(4,3)
    mpq(1,2)
    """
    R = sum(iu) + sum(iv)
    value = mpq(prod(bz.binomial(N, i) for i in itertools.chain(iu, iv)), bz.binomial((l + m) * N, R))
    if betas is not None:
        value = value * prod((betas[i] for i in itertools.chain(iu, iv)), start=mpq(1))
    return value


def _blossom_axis0(array: np.ndarray, params) -> np.ndarray:
    """Polar form along axis 0 (de Casteljau, one level per argument; notes 6.1)."""
    level = array
    for t in params:
        level = (1 - t) * level[:-1] + t * level[1:]
    return level[0]


def polar_value(net: np.ndarray, u_args, v_args) -> np.ndarray:
    """``F^{l,m}_{0,0}(u_args, v_args)``: the polar form of a tensor-product net.

    ``l`` de Casteljau steps in u (axis 0) with the values ``u_args``, then ``m`` in v
    (axis 1) with ``v_args`` -- the recursion printed after (7) of (000); the two
    directions commute.  Works on homogeneous nets (then it is ``omega F`` and ``omega``).
    """
    l, m = net.shape[0] - 1, net.shape[1] - 1
    if len(u_args) != l or len(v_args) != m:
        raise InputError(f"polar form of degree ({l}, {m}) needs {l} u- and {m} v-arguments")
    return _blossom_axis0(_blossom_axis0(net, u_args), v_args)


def _symbolic(*arrays) -> bool:
    """Do the arrays hold sympy expressions (then constants must be sympy Rationals)?"""
    return any(type(x).__module__.startswith("sympy") for a in arrays for x in a.reshape(-1))


def _constant_type(symbolic: bool):
    if not symbolic:
        return lambda q: q
    from ..exact.scalars import to_sympy

    return to_sympy


def _cartesian(curve: np.ndarray):
    """Control points ``u_I, v_I`` and weights ``beta_I`` of a homogeneous domain curve."""
    w = curve[:, 2]
    return [x / b for x, b in zip(curve[:, 0], w)], [y / b for y, b in zip(curve[:, 1], w)], list(w)


def _ordered(net, us, vs, betas, l, m, N, out, cast):
    for iu in itertools.product(range(N + 1), repeat=l):
        column = _blossom_axis0(net, [us[i] for i in iu])
        for iv in itertools.product(range(N + 1), repeat=m):
            R = sum(iu) + sum(iv)
            const = lasser_constant(l, m, N, iu, iv) * prod((betas[i] for i in itertools.chain(iu, iv)), start=1)
            out[R] = out[R] + cast(const) * _blossom_axis0(column, [vs[i] for i in iv])


def _orderings(ms) -> int:
    return factorial(len(ms)) // prod(factorial(k) for k in Counter(ms).values())


def _multisets(net, us, vs, betas, l, m, N, out, cast):
    r = l + m
    vsets = []
    for jv in itertools.combinations_with_replacement(range(N + 1), m):
        weight = cast(mpq(_orderings(jv) * prod(bz.binomial(N, i) for i in jv))) * prod((betas[i] for i in jv), start=1)
        vsets.append((sum(jv), weight, [vs[i] for i in jv]))
    for ju in itertools.combinations_with_replacement(range(N + 1), l):
        wu = cast(mpq(_orderings(ju) * prod(bz.binomial(N, i) for i in ju))) * prod((betas[i] for i in ju), start=1)
        column = _blossom_axis0(net, [us[i] for i in ju])
        for sv, wv, vargs in vsets:
            R = sum(ju) + sv
            out[R] = out[R] + (wu * wv * cast(mpq(1, bz.binomial(r * N, R)))) * _blossom_axis0(column, vargs)


def compose_homogeneous_lasser(net: np.ndarray, curve: np.ndarray, enumeration: str = "multisets") -> np.ndarray:
    """Homogeneous Bézier points ``(Omega_R B_R, Omega_R)`` of ``F(K(t))`` by (6)/(7), (14)-(16).

    Parameters
    ----------
    net : object array ``(l + 1, m + 1, D)``, homogeneous surface net
    curve : object array ``(N + 1, 3)``, homogeneous domain curve ``(beta u, beta v, beta)``
    enumeration : {"multisets", "ordered"}
        ``"ordered"`` is the literal sum over all multi-indices of (6).

    Returns
    -------
    object array ``(N(l + m) + 1, D)``
    """
    l, m = net.shape[0] - 1, net.shape[1] - 1
    N = curve.shape[0] - 1
    us, vs, betas = _cartesian(curve)
    out = np.empty(((l + m) * N + 1,) + net.shape[2:], dtype=object)
    for R in range(out.shape[0]):
        out[R] = net[0, 0] * 0
    cast = _constant_type(_symbolic(net, curve))
    if enumeration == "ordered":
        _ordered(net, us, vs, betas, l, m, N, out, cast)
    elif enumeration == "multisets":
        _multisets(net, us, vs, betas, l, m, N, out, cast)
    else:
        raise InputError(f"unknown enumeration {enumeration!r}; expected 'multisets' or 'ordered'")
    return out


def trace_theorem1(net: np.ndarray, curve: np.ndarray, R: int, out=print) -> None:
    """Print the terms of (6) for one ``R``: multi-index, constant (7)/(16), polar value.

    Teaching mode for a small example (the sum runs over ordered multi-indices).
    """
    l, m = net.shape[0] - 1, net.shape[1] - 1
    N = curve.shape[0] - 1
    us, vs, betas = _cartesian(curve)
    total = net[0, 0] * 0
    out(f"Theorem 1/2, R = {R}: l = {l}, m = {m}, N = {N}, rN = {(l + m) * N}")
    for iu, iv in multi_indices(l, m, N, R):
        const = lasser_constant(l, m, N, iu, iv, betas)
        value = polar_value(net, [us[i] for i in iu], [vs[i] for i in iv])
        total = total + const * value
        out(f"  I^u = {iu}, I^v = {iv}: C = {const}, polar value = {[str(x) for x in value]}")
    out(f"  sum = {[str(x) for x in total]}")

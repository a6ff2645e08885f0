"""Certified upper bound of the distance between an exact curve and a cubic (section VIII).

For an exact curve ``F = N/W`` (Bézier, degree ``n``, parameter ``t`` in [0, 1]), a cubic
Bézier curve ``X`` with exact rational control points and an exact polynomial
reparametrization ``phi`` with ``phi(0) = 0``, ``phi(1) = 1`` and Bernstein coefficients in
[0, 1] (so ``phi`` maps [0, 1] *onto* [0, 1]),

    E(t) = |N(t) - W(t) X(phi(t))|^2 / W(t)^2 = |F(t) - X(phi(t))|^2

is a rational function whose numerator and denominator are computed exactly in
Bernstein form (products, notes 9.3; composition ``X o phi`` by route (b)).  Then

    H(F, X) <= sup_t |F(t) - X(phi(t))| = sqrt(max E),

a bound on the Hausdorff distance of the two curve segments (every ``F(t)`` is within it of
``X(phi(t))`` on ``X``, and every ``X(s)`` is ``X(phi(t))`` for some ``t``).  ``max E`` is bounded
by the convex-hull property: on every sub-interval, (max Bernstein coefficient of the
numerator) / (min Bernstein coefficient of ``W^2``), refined by bisection of [0, 1]
until the bound is within a factor ``1 + rel`` of the values at the subdivision points.
The bisection runs first in ball arithmetic (python-flint ``arb``, outward rounded,
:mod:`exactcagd.composition.ball`), and again in exact arithmetic (python-flint
``fmpq_poly``) only when the balls do not certify ``target``: the Bernstein coefficients of a
polynomial on ``[a, b]`` come from its power form by two exact compositions with linear
polynomials.  To keep the numbers short, the Bernstein coefficients on [0, 1] are first
rounded *outward* to 64-bit dyadic rationals (numerator up, ``W^2`` down): a polynomial
with larger Bernstein coefficients is pointwise larger on [0, 1], so every bound of the
rounded pair bounds the exact ratio.  The final square root is rounded upwards.

>>> from exactcagd import BezierCurve
>>> F = BezierCurve([[0, 0], [1, 1], [2, 0]])
>>> X = F.elevate(1)
>>> distance_bound(F, X)
mpq(0,1)
"""

from __future__ import annotations

import heapq

import flint
import numpy as np
from gmpy2 import isqrt, mpq

from ..errors import InputError, WeightError
from ..exact import bernstein as bz
from ..exact.scalars import from_fmpq, to_rational_array
from ..geometry.bezier_curve import BezierCurve
from . import ball
from .fast import _fmpq, compose_homogeneous_fast, scaled, unscaled

__all__ = ["distance_bound", "compose_with_reparametrization", "sqrt_upper", "bernstein_on"]


def sqrt_upper(q: mpq, bits: int = 64) -> mpq:
    """A rational ``r >= sqrt(q)`` (``q >= 0``), exceeding it by about ``2^-bits`` relatively."""
    if q <= 0:
        return mpq(0)
    e = (int(q.numerator.bit_length()) - int(q.denominator.bit_length())) // 2
    shift = bits - e
    scaled_q = q * (mpq(4) ** shift)  # sqrt(q) = sqrt(scaled_q) / 2^shift
    n = scaled_q.numerator * scaled_q.denominator
    root = isqrt(n)
    if root * root < n:
        root += 1
    return mpq(root, scaled_q.denominator) / (mpq(2) ** shift)


def compose_with_reparametrization(cubic: BezierCurve, phi) -> np.ndarray:
    """Exact homogeneous Bernstein coefficients of ``X(phi(t))`` (degree ``3 deg(phi)``)."""
    phi = to_rational_array(phi, where="phi")
    k = phi.shape[0] - 1
    curve = np.empty((k + 1, 3), dtype=object)
    curve[:, 0] = phi
    curve[:, 1] = mpq(0)
    curve[:, 2] = mpq(1)
    net = cubic.homogeneous()[:, None, :]
    return compose_homogeneous_fast(net, curve)


def _round(q: mpq, up: bool) -> mpq:
    """Dyadic rational with 64 significant bits next to ``q``, rounded up (or down)."""
    if q == 0:
        return mpq(0)
    e = int(abs(q.numerator).bit_length()) - int(q.denominator.bit_length())
    scale = mpq(2) ** (64 - e)
    scaled_q = q * scale
    n = scaled_q.numerator // scaled_q.denominator  # floor
    if up and n * scaled_q.denominator != scaled_q.numerator:
        n += 1
    return mpq(n) / scale


def bernstein_on(power: flint.fmpq_poly, n: int, a, b) -> list:
    """Bernstein coefficients (degree ``n``) of the power-form polynomial on ``[a, b]``."""
    return [from_fmpq(c) for c in _bernstein_on_fmpq(power, n, a, b)]


def _bernstein_on_fmpq(power: flint.fmpq_poly, n: int, a, b) -> list:
    """:func:`bernstein_on` as flint ``fmpq`` (the bisection reads only a few of them as ``mpq``)."""
    q = power(flint.fmpq_poly([_fmpq(a), _fmpq(b - a)]))
    hat = bz.power_to_scaled(q, n).coeffs()
    hat = hat + [flint.fmpq(0)] * (n + 1 - len(hat))
    return [c / bz.binomial(n, i) for i, c in enumerate(hat)]


def _squared_error(F: BezierCurve, cubic: BezierCurve, phi):
    """Scaled Bernstein forms of ``|N Xw - W X|^2`` and ``(W Xw)^2`` (``X o phi = X/Xw``), degree ``D``."""
    if cubic.is_rational:
        raise InputError("the approximating cubic must be polynomial")
    hom_f = F.homogeneous()
    xphi = compose_with_reparametrization(cubic, phi)
    n, k = hom_f.shape[0] - 1, xphi.shape[0] - 1
    fw, xw = scaled(hom_f[:, -1]), scaled(xphi[:, -1])
    err = flint.fmpq_poly([])
    for c in range(hom_f.shape[1] - 1):
        diff = scaled(hom_f[:, c]) * xw - fw * scaled(xphi[:, c])
        err += diff * diff
    D = 2 * (n + k)
    w2 = fw * fw * xw * xw
    return err, w2, D


def _leaf_bound(e: list, w2: list):
    """Upper bound of ``e / w2`` on the leaf (``mpq``), or ``None`` when ``w2`` is not yet bounded below.

    ``e`` and ``w2`` are Bernstein coefficients as flint ``fmpq`` (from
    :func:`_bernstein_on_fmpq`): ``e / w2 <= max e / min w2``.
    """
    low = min(w2)
    if low <= 0:
        return None
    return max(from_fmpq(max(e)), mpq(0)) / from_fmpq(low)


def distance_bound(F: BezierCurve, cubic: BezierCurve, phi=None, rel: float = 0.02, max_leaves: int = 400, target=None,
                   stats: dict | None = None) -> mpq:
    """Certified ``r >= sup_t |F(t) - X(phi(t))|`` (hence ``>=`` the Hausdorff distance).

    Parameters
    ----------
    F : BezierCurve
        Exact curve (polynomial or rational with a weight function positive on [0, 1]).
    cubic : BezierCurve
        Polynomial approximating curve of the same dimension.
    phi : sequence of rationals, optional
        Bernstein coefficients of the reparametrization (default: identity ``[0, 1]``);
        must start with 0, end with 1 and lie in [0, 1].
    rel : float
        Stop refining when the bound of ``max E`` is within ``(1 + rel)`` of the largest
        value of ``E`` seen at subdivision points.
    max_leaves : int
        Work limit (the bound stays valid, only less tight).
    target : rational, optional
        Stop as soon as the bound is ``<= target`` or a value above ``target`` is found
        (an acceptance test needs no more; the bound is then less tight).
    stats : dict, optional
        Tally ``{"ball": n, "exact": m}`` of which arithmetic decided: the bisection runs in
        ball arithmetic first (:func:`exactcagd.composition.ball.ratio_max_bound`), in exact
        rationals only when the balls do not reach ``target`` (or ``W`` is not bounded away
        from zero in balls).

    Raises
    ------
    WeightError
        The weight function of ``F`` is not bounded away from zero on [0, 1].
    """
    phi = [mpq(0), mpq(1)] if phi is None else list(to_rational_array(phi, where="phi"))
    if phi[0] != 0 or phi[-1] != 1 or any(not (0 <= x <= 1) for x in phi):
        raise InputError("phi must have Bernstein coefficients in [0, 1] starting with 0 and ending with 1")
    if F.dimension != cubic.dimension:
        raise InputError(f"dimensions differ: {F.dimension} vs {cubic.dimension}")
    e_scaled, w_scaled, D = _squared_error(F, cubic, phi)
    target2 = None if target is None else mpq(to_rational_array([target])[0]) ** 2
    with ball.precision():
        quick = ball.ratio_max_bound(e_scaled, w_scaled, D, rel, max_leaves, target2)
    if quick is not None and (target2 is None or quick <= target2):
        ball.count(stats, ball.BALL)
        return sqrt_upper(quick)
    ball.count(stats, ball.EXACT)
    e_pow = bz.scaled_to_power(scaled([_round(x, True) for x in unscaled(e_scaled, D)]), D)
    w_pow = bz.scaled_to_power(scaled([_round(x, False) for x in unscaled(w_scaled, D)]), D)
    return _exact_bisection(e_pow, w_pow, D, rel, max_leaves, target2)


def _exact_bisection(e_pow, w_pow, D: int, rel, max_leaves: int, target2) -> mpq:
    """The bisection of :func:`distance_bound` in exact rationals (flint ``fmpq``)."""
    lower = mpq(0)
    heap: list = []
    counter = 0

    def push(a, b, depth):
        nonlocal counter, lower
        ce, cw = _bernstein_on_fmpq(e_pow, D, a, b), _bernstein_on_fmpq(w_pow, D, a, b)
        for i in (0, -1):  # end coefficients are the values E(a), W2(a), E(b), W2(b)
            if cw[i] > 0:
                lower = max(lower, from_fmpq(ce[i]) / from_fmpq(cw[i]))
        bound = _leaf_bound(ce, cw)
        key = (0, 0) if bound is None else (1, -bound)
        heapq.heappush(heap, (key, counter, depth, a, b, bound))
        counter += 1

    push(mpq(0), mpq(1), 0)
    while True:
        _, _, depth, a, b, bound = heap[0]
        if bound is not None and (len(heap) >= max_leaves or bound <= lower * mpq(1 + rel) or bound == 0):
            break
        if bound is not None and target2 is not None and (bound <= target2 or lower > target2):
            break
        if depth > 60:
            raise WeightError("the weight function of the curve is not bounded away from zero on [0, 1]")
        heapq.heappop(heap)
        mid = (a + b) / 2
        push(a, mid, depth + 1)
        push(mid, b, depth + 1)
    return sqrt_upper(heap[0][5])

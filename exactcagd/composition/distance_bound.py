"""Certified upper bound of the distance between an exact curve and a cubic (section VIII).

For an exact curve ``F = N/W`` (Bézier, degree ``n``, parameter ``t`` in [0, 1]), a cubic
Bézier curve ``X`` with exact rational control points and an exact polynomial
reparametrization ``phi`` with ``phi(0) = 0``, ``phi(1) = 1`` and Bernstein coefficients in
[0, 1] (so ``phi`` maps [0, 1] *onto* [0, 1]),

    E(t) = |N(t) - W(t) X(phi(t))|^2 / W(t)^2 = |F(t) - X(phi(t))|^2

is a rational function whose numerator and denominator are computed exactly in
Bernstein form (products, notes 9.3; composition ``X o phi`` by route (b)); for two
polynomial curves (constant weights) ``E = |F - X o phi|^2`` directly, of degree
``2 max(n, deg)`` instead of ``2 (n + deg)``.  Then

    H(F, X) <= sup_t |F(t) - X(phi(t))| = sqrt(max E),

a bound on the Hausdorff distance of the two curve segments (every ``F(t)`` is within it of
``X(phi(t))`` on ``X``, and every ``X(s)`` is ``X(phi(t))`` for some ``t``).  ``max E`` is bounded
by the convex-hull property: on every sub-interval, by the largest ratio of a Bernstein
coefficient of the numerator to the corresponding one of ``W^2`` (all of which must be
positive; :func:`_largest_ratio`), refined by bisection of [0, 1]
until the bound is within a factor ``1 + rel`` of the values at the subdivision points.
The Bernstein coefficients of a half interval come from those of the parent by de
Casteljau at ``1/2``, which times ``2^D`` is integral: in the scaled form
``s_i = C(D, i) b_i`` the halves are ``s(1 + 2x)`` and its mirror image
(:func:`~.fast.scaled_halves`), so the bisection is exact integer arithmetic (python-flint
``fmpz_poly`` Taylor shifts), two substitutions per column and split.  It runs first on the coefficients on [0, 1] rounded *outward* to
:data:`~exactcagd.composition.ball.PREC` significant bits (numerator up, ``W^2`` down: a
polynomial with larger Bernstein coefficients is pointwise larger on [0, 1], so every
bound of the rounded pair bounds the exact ratio; ``"ball"``), and on the exact
coefficients only when that does not prove ``target`` (``"exact"``).  The final square
root is rounded upwards.

>>> from exactcagd import BezierCurve
>>> F = BezierCurve([[0, 0], [1, 1], [2, 0]])
>>> X = F.elevate(1)
>>> distance_bound(F, X)
mpq(0,1)
"""

from __future__ import annotations

import heapq
import operator
from functools import lru_cache

import flint
import numpy as np
from gmpy2 import isqrt, mpq

from ..errors import InputError, WeightError
from ..exact import bernstein as bz
from ..exact.scalars import from_fmpq, to_rational_array
from ..geometry.bezier_curve import BezierCurve
from . import ball
from .fast import ScaledBernstein, _binomials, _fmpq, _ones, compose_homogeneous_fast, scaled_halves

__all__ = [
    "bernstein_on",
    "compose_with_reparametrization",
    "distance_bound",
    "homogeneous_distance_bound",
    "ratio_max_bound",
    "sqrt_upper",
]


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


def bernstein_on(power: flint.fmpq_poly, n: int, a, b) -> list:
    """Bernstein coefficients (degree ``n``) of the power-form polynomial on ``[a, b]``."""
    return [from_fmpq(c) for c in _bernstein_on_fmpq(power, n, a, b)]


def _bernstein_on_fmpq(power: flint.fmpq_poly, n: int, a, b) -> list:
    """:func:`bernstein_on` as flint ``fmpq`` (the bisection reads only a few of them as ``mpq``)."""
    q = power(flint.fmpq_poly([_fmpq(a), _fmpq(b - a)]))
    hat = bz.power_to_scaled(q, n).coeffs()
    hat = hat + [flint.fmpq(0)] * (n + 1 - len(hat))
    return [c / bz.binomial(n, i) for i, c in enumerate(hat)]


def _squared_error(hom_f, hom_x):
    """``(e, w2, D)``: scaled Bernstein forms (flint ``fmpq_poly``, degree ``D``) of the squared error.

    ``hom_f = (N, W)`` and ``hom_x = (X Xw, Xw)`` are homogeneous Bernstein coefficients
    (object arrays, or their integer form :class:`~.fast.ScaledBernstein`, e.g. straight from
    the composition).  In general ``e = |N Xw - W X|^2`` and ``w2 = (W Xw)^2``
    (``D = 2 (n + k)``).  When both weights are constant (two polynomial curves) the
    difference needs no common denominator: ``e = |N / W - X|^2`` with both elevated to
    ``m = max(n, k)`` and ``w2`` is the constant ``1`` (an ``fmpq``), ``D = 2 m`` -- the same
    function, of a lower degree.  The products run on the integer numerators (one
    denominator per curve); ``e`` and ``w2`` are canonical, so they do not depend on the
    input's form.
    """
    f = hom_f if isinstance(hom_f, ScaledBernstein) else ScaledBernstein.from_homogeneous(hom_f)
    x = hom_x if isinstance(hom_x, ScaledBernstein) else ScaledBernstein.from_homogeneous(hom_x)
    n, k = f.degree, x.degree
    const_f, const_x = f.constant_weight(), x.constant_weight()
    if const_f is not None and const_x is not None:
        # N_c / W = A_c / a_f in scaled form (W = a_f / den_f), the same for X; elevation to m
        # multiplies a scaled form by (1 + x)^(m - degree)
        m = max(n, k)
        a_f, a_x = int(const_f[0]), int(const_x[0])
        up_f, up_x = _ones(m - n) * a_x, _ones(m - k) * a_f
        err = flint.fmpz_poly()
        for col_f, col_x in zip(f.columns, x.columns):
            diff = col_f * up_f - col_x * up_x
            err += diff * diff
        return flint.fmpq_poly(err, (a_f * a_x) ** 2), flint.fmpq(1), 2 * m
    fw, xw = f.weight_poly(), x.weight_poly()
    err = flint.fmpz_poly()
    for col_f, col_x in zip(f.columns, x.columns):
        diff = col_f * xw - fw * col_x
        err += diff * diff
    den = int(f.denominator * x.denominator) ** 2
    w = fw * xw
    return flint.fmpq_poly(err, den), flint.fmpq_poly(w * w, den), 2 * (n + k)


# ----------------------------------------------------------------------------- integer bisection
def _integer_column(p: flint.fmpq_poly, n: int, bits: int | None, up: bool) -> tuple[list, flint.fmpq]:
    """``(c, s)``: integers ``c_i`` with ``c_i s`` the Bernstein coefficients (degree ``n``) of the
    scaled form ``p``, exactly (``bits=None``), or rounded outward to ``bits`` significant bits
    of the largest one (``up``: every ``c_i s >= b_i``, else ``<=``): a dyadic enclosure.

    ``p = numer / den`` with an integer numerator; ``b_i = numer_i / (den C(n, i))``, over
    the common denominator ``den L`` (``L = lcm_i C(n, i)``) ``b_i = numer_i (L / C(n, i)) / (den L)``.
    """
    numer = p.numer().coeffs()
    lcm, cofactors = _binomial_cofactors(n)
    column = [a * c for a, c in zip(numer, cofactors)]
    column += [flint.fmpz(0)] * (n + 1 - len(column))
    scale = flint.fmpq(1, p.denom() * lcm)
    if bits is None:
        return column, scale
    shift = max(max(column), -min(column)).bit_length() - bits
    if shift <= 0:
        return column, scale
    if up:  # ceiling of x / 2^shift is floor((x + 2^shift - 1) / 2^shift)
        below = (flint.fmpz(1) << shift) - 1
        column = [(x + below) >> shift for x in column]
    else:
        column = [x >> shift for x in column]
    return column, scale * (flint.fmpz(1) << shift)


@lru_cache(maxsize=64)
def _binomial_cofactors(n: int) -> tuple[int, tuple]:
    """``(L, (L / C(n, i))_i)`` with ``L = lcm_i C(n, i)`` (the cofactors as flint integers)."""
    from math import lcm

    big = lcm(*_binomials(n))
    return big, tuple(flint.fmpz(big // b) for b in _binomials(n))


def ratio_max_bound(e: flint.fmpq_poly, w2, n: int, rel, max_leaves: int, target2=None, bits: int | None = None):
    """An exact rational ``>= max_[0,1] e / w2`` by bisection, or ``None`` (``w2`` not bounded below).

    ``e`` and ``w2`` are scaled Bernstein forms of degree ``n`` (``w2`` may be a positive
    constant ``fmpq``).  On a leaf the bound is ``max_i e_i / w_i`` of its Bernstein
    coefficients (convex-hull property, :func:`_largest_ratio`); the leaf with the largest bound is halved (exact
    integer de Casteljau, :func:`~.fast.scaled_halves`) until the bound is within ``1 + rel`` of the
    largest end value ``e / w2`` seen, is ``<= target2``, an end value exceeds ``target2``, or
    ``max_leaves`` leaves exist.  ``bits``: round the coefficients on [0, 1] outward first
    (``e`` up, ``w2`` down: a pointwise larger ``e`` and smaller ``w2``, so every bound stays a
    bound) to keep the integers short -- the ball route; ``None``: exact.

    >>> import flint
    >>> e = flint.fmpq_poly([0, 4])   # 4 t (1 - t): Bernstein (0, 2, 0), scaled (0, 4, 0); max 1
    >>> ratio_max_bound(e, flint.fmpq(1), 2, 0.02, 400) <= mpq(102, 100)
    True
    """
    e_col, e_scale = _integer_column(e, n, bits, True)
    constant = isinstance(w2, flint.fmpq)
    if constant:
        if w2 <= 0:
            return None
        w_col, factor = None, e_scale / w2
    else:
        w_col, w_scale = _integer_column(w2, n, bits, False)
        factor = e_scale / w_scale
    return _bisection(e_col, w_col, n, factor, _one_plus(rel), max_leaves,
                      None if target2 is None else _fmpq(target2))


@lru_cache(maxsize=16)
def _one_plus(rel) -> flint.fmpq:
    """``1 + rel`` as an exact ``fmpq`` (``rel`` a float or rational)."""
    return _fmpq(mpq(1) + mpq(rel))


def _largest_ratio(e: list, w: list | None, w_low) -> flint.fmpq:
    """``max(0, max_i e_i / w_i)`` (all ``w_i > 0``; ``w = None``: every ``w_i = w_low``).

    It bounds ``sum e_i B_i / sum w_i B_i`` on the leaf (a weighted mean of the ratios, the
    weights ``w_i B_i >= 0``: the rational convex-hull property), and is never larger than
    ``max e / min w``; its excess over the true maximum shrinks like ``h^2`` with the leaf
    width ``h`` (``max e / min w``: like ``h``, through the variation of ``w`` on the leaf).
    Compared by cross-multiplication (exact integers).
    """
    if w is None:
        top = max(e)
        return flint.fmpq(top, w_low) if top > 0 else flint.fmpq(0)
    best_e, best_w = 0, 1
    for a, b in zip(e, w):
        if a * best_w > best_e * b:
            best_e, best_w = a, b
    return flint.fmpq(best_e, best_w)


def _bisection(e_col, w_col, n, factor, one_rel, max_leaves, target2):
    """:func:`ratio_max_bound` on integer columns: the true ``e_i / w_i`` of a leaf at depth ``k``
    is ``e_col_i / w_col_i * factor`` (``w_col = None``: ``w_i = 2^(n k)``, a constant ``w2``).

    A leaf keeps its coefficients in scaled Bernstein form ``s_i = C(n, i) b_i`` (lists of flint
    integers): ``e_i / w_i = s^e_i / s^w_i`` (the binomials cancel), the end values are
    ``s_0 = b_0``, ``s_n = b_n``, and a halving is the substitution ``x -> 1 + 2x``
    (:func:`~.fast.scaled_halves`) -- the same coefficients ``2^n`` times de Casteljau's at ``1/2``
    (notes 2.3's triangle edges, ``b'_i = 2^-i sum_j C(i, j) b_j``), at the cost of a Taylor
    shift instead of an ``(n + 1)``-square integer matrix product (measured 0.64x - 0.84x
    the time of the ``fmpz_mat`` bisection at n = 52-62, equal at n = 36)."""
    binomials = _binomials(n)
    lcm, cofactors = _binomial_cofactors(n)
    zero = flint.fmpq(0)
    lower = zero
    heap: list = []
    counter = 0

    def push(se, sw, depth):
        nonlocal counter, lower
        if sw is None:
            w_low = w_first = w_last = flint.fmpz(1) << (n * depth)
        else:
            w_low, w_first, w_last = min(sw), sw[0], sw[-1]
        for a, b in ((se[0], w_first), (se[-1], w_last)):  # end coefficients: values at the ends
            if b > 0:
                value = flint.fmpq(a, b) * factor
                lower = max(lower, value)
        if w_low > 0:
            if sw is None:  # max_i b_i = max_i s_i (L / C(n, i)) / L
                top = max(map(operator.mul, se, cofactors))
                bound = (flint.fmpq(top, lcm * w_low) if top > 0 else zero) * factor
            else:
                bound = _largest_ratio(se, sw, w_low) * factor
            key = (1, -bound)
        else:
            bound, key = None, (0, zero)
        heapq.heappush(heap, (key, counter, depth, se, sw, bound))
        counter += 1

    push([x * c for x, c in zip(e_col, binomials)], None if w_col is None else [x * c for x, c in zip(w_col, binomials)], 0)
    while True:
        _, _, depth, se, sw, bound = heap[0]
        if bound is not None and (len(heap) >= max_leaves or bound <= lower * one_rel or bound == 0):
            break
        if bound is not None and target2 is not None and (bound <= target2 or lower > target2):
            break
        if depth > 60:
            return None
        heapq.heappop(heap)
        left_e, right_e = scaled_halves(se, n)
        left_w, right_w = (None, None) if sw is None else scaled_halves(sw, n)
        push(left_e, left_w, depth + 1)
        push(right_e, right_w, depth + 1)
    return from_fmpq(heap[0][5])


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
        Tally ``{"ball": n, "exact": m}`` of which arithmetic decided (see
        :func:`homogeneous_distance_bound`).

    Raises
    ------
    WeightError
        The weight function of ``F`` is not bounded away from zero on [0, 1].
    """
    if cubic.is_rational:
        raise InputError("the approximating cubic must be polynomial")
    if phi is not None:
        phi = list(to_rational_array(phi, where="phi"))
        if phi[0] != 0 or phi[-1] != 1 or any(not (0 <= x <= 1) for x in phi):
            raise InputError("phi must have Bernstein coefficients in [0, 1] starting with 0 and ending with 1")
    if F.dimension != cubic.dimension:
        raise InputError(f"dimensions differ: {F.dimension} vs {cubic.dimension}")
    identity = phi is None or phi == [mpq(0), mpq(1)]
    hom_x = cubic.homogeneous() if identity else compose_with_reparametrization(cubic, phi)
    return homogeneous_distance_bound(F.homogeneous(), hom_x, rel, max_leaves, target, stats)


def homogeneous_distance_bound(hom_f: np.ndarray, hom_x: np.ndarray, rel: float = 0.02, max_leaves: int = 400,
                               target=None, stats: dict | None = None) -> mpq:
    """:func:`distance_bound` of two curves given by homogeneous Bernstein coefficients (no checks).

    ``hom_f = (W F, W)`` (``W > 0`` on [0, 1]) and ``hom_x = (Xw X, Xw)``, object arrays of
    rationals.  The bisection of ``max E`` (:func:`ratio_max_bound`) runs first on the
    coefficients of ``E``'s numerator and denominator rounded outward to
    :data:`~exactcagd.composition.ball.PREC` significant bits (``"ball"``: a dyadic enclosure of
    every coefficient, as an Arb ball's ends), and on the exact coefficients only when that
    does not prove ``target`` or does not bound ``W`` away from zero (``"exact"``).

    >>> from exactcagd import BezierCurve
    >>> F = BezierCurve([[0, 0], [1, 2], [2, 0]], weights=[1, 2, 1])
    >>> X = BezierCurve([[0, 0], [1, 1], [2, 0]])
    >>> stats = {}
    >>> r = homogeneous_distance_bound(F.homogeneous(), X.homogeneous(), target=1, stats=stats)
    >>> mpq(5, 6) <= r <= 1, stats      # |F(1/2) - X(1/2)| = |(1, 4/3) - (1, 1/2)| = 5/6
    (True, {'ball': 1})
    """
    e, w2, D = _squared_error(hom_f, hom_x)
    target2 = None if target is None else mpq(to_rational_array([target])[0]) ** 2
    quick = ratio_max_bound(e, w2, D, rel, max_leaves, target2, bits=ball.PREC)
    if quick is not None and (target2 is None or quick <= target2):
        ball.count(stats, ball.BALL)
        return sqrt_upper(quick)
    ball.count(stats, ball.EXACT)
    bound = ratio_max_bound(e, w2, D, rel, max_leaves, target2)
    if bound is None:
        raise WeightError("the weight function of the curve is not bounded away from zero on [0, 1]")
    return sqrt_upper(bound)

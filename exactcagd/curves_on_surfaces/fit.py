"""Fit then certify: compact polynomial curves within a certified distance of ``S(D(t))``.

The route of ``approximate(..., method="fit")``.  Unlike the other methods the result
does *not* lie on the surface; it is a C0 chain of polynomial Bézier curves ``C`` with a
proven bound of ``max_t |F(t) - C(t)|`` to the exact image ``F = S o D``, which bounds the
Hausdorff distance from above (every ``F(t)`` is within it of ``C(t)`` and conversely).

1. **Exact image.**  The domain curve is cut at its own knots and at knot-line crossings of
   the surface (:class:`~.domain.DomainCurve`; its monotonicity cuts are not needed here and
   are dropped), and every piece is composed exactly with its patch
   (:func:`exactcagd.composition.fast.compose_scaled`, degree ``N (l + m)``), kept as
   integer polynomials (:class:`~exactcagd.composition.fast.ScaledBernstein`): the
   certificate multiplies them as they are, the fit reads their floats, and only the end
   points become ``mpq``.
2. **Fit (binary64).**  Least squares of a degree-``d`` Bézier curve to ``F`` at
   Chebyshev-Lobatto parameters (parametric correspondence ``C(t) ~ F(t)``), end points
   interpolated; ``d = 3, 4, ...`` up to ``max_degree`` (and up to ``deg F`` for a polynomial
   ``F``, where ``d = deg F`` reproduces ``F``), the piece is bisected when no degree works.
   The sampled errors of four consecutive degrees come from one matrix product; the lowest
   degree whose sampled error is ``<= tol`` (and that certifies) is kept.
3. **Exact conversion.**  The interior float control points are converted to their exact
   binary values; the end points are the exact joint points ``S(joint)``, shared by the two
   neighbours, so the chain is C0 *exactly*.
4. **Certificate (ball first, then exact rationals).**  The squared error
   ``E = |F - C|^2`` (for ``F = H / W``: ``|H - W C|^2 / W^2``) is bounded by the
   convex-hull property of its Bernstein coefficients, refined by bisection where the
   bound on [0, 1] exceeds ``tol^2``
   (:func:`exactcagd.composition.distance_bound.homogeneous_distance_bound`): exact integer
   subdivision of the coefficients rounded outward to
   :data:`~exactcagd.composition.ball.PREC` bits (``"ball"``), or of the exact ones when that
   does not prove ``tol`` (``"exact"``; the result's ``certified_by`` counts both).  The
   square root is rounded upwards.  Samples only *select* candidates; the accepted bound
   is always such a proof.

Irrational knot-line crossings are carried by isolating intervals of width ``2^-64``
(:mod:`.domain`): the tiny image arcs between two pieces are covered by the joint bound of
the driver (``_gap_bound``), part of ``distance_bound``.

>>> from exactcagd import BezierCurve
>>> F = BezierCurve([[0, 0, 0], [1, 2, 0], [2, -1, 1], [3, 0, 0], [4, 1, 1]])
>>> pieces = fit_curve(F.homogeneous(), "1/100")
>>> all(bound <= mpq(1, 100) for _, _, bound in pieces)
True
"""

from __future__ import annotations

import time
from functools import lru_cache

import numpy as np
from gmpy2 import mpq

from ..composition import ball
from ..composition.cubic_approx import bernstein_basis_float
from ..composition.distance_bound import homogeneous_distance_bound, sqrt_upper
from ..composition.fast import ScaledBernstein, compose_scaled
from ..errors import ExactCAGDError, WeightError
from ..exact import bernstein as bz
from ..exact.scalars import to_float, to_rational
from ..geometry.bezier_curve import BezierCurve

__all__ = ["fit_curve", "certify", "certified_bound", "approximate_fit", "sample_parameters", "MAX_DEGREE"]

#: Highest degree tried before a piece is bisected (OpenCASCADE's default maximum).
MAX_DEGREE = 14
#: Number of Chebyshev-Lobatto fitting parameters.
NODES = 48
#: Smallest parameter width of a piece (relative to its domain piece) before giving up.
MIN_WIDTH = mpq(1, 2**40)
#: Degrees whose sampled errors are computed together (one matrix product).
_DEGREE_BLOCK = 4
#: Reasons of a domain joint that separate exact images (other cuts are not needed).
_KEEP = {"start", "end", "curve-knot", "u-knot-line", "v-knot-line"}


# ----------------------------------------------------------------------------- float side
def sample_parameters() -> tuple[np.ndarray, np.ndarray]:
    """``(fit, check)``: the Chebyshev-Lobatto fitting parameters and the midpoints between them.

    The sampled error at both sets only *selects* a degree; it is never the bound.
    """
    fit = (1.0 - np.cos(np.pi * np.arange(NODES) / (NODES - 1))) / 2
    fit[0], fit[-1] = 0.0, 1.0
    return fit, (fit[:-1] + fit[1:]) / 2


def _homogeneous_points(h: np.ndarray) -> np.ndarray:
    """Affine points of homogeneous float rows ``(w P, w)``."""
    return h[:, :-1] / h[:, -1:]


@lru_cache(maxsize=64)
def _basis(d: int, params: bytes) -> tuple[np.ndarray, np.ndarray]:
    """``(basis, pinv)``: the degree-``d`` Bernstein basis at the parameters (float64 bytes)
    and the pseudo-inverse of its interior columns, read-only.  The parameters are fixed, so
    this is computed once per degree instead of one ``lstsq`` (an SVD) per fit."""
    basis = bernstein_basis_float(d, np.frombuffer(params))
    pinv = np.linalg.pinv(basis[:, 1:-1]) if d >= 2 else np.zeros((0, basis.shape[0]))
    for a in (basis, pinv):
        a.flags.writeable = False
    return basis, pinv


def _least_squares(d: int, params: np.ndarray, target: np.ndarray, p0: np.ndarray, p1: np.ndarray) -> np.ndarray:
    """Control points of the degree-``d`` least-squares fit to ``target`` with fixed ends."""
    if d == 1:
        return np.vstack([p0, p1])
    basis, pinv = _basis(d, params.tobytes())
    rhs = target - np.outer(basis[:, 0], p0) - np.outer(basis[:, -1], p1)
    return np.vstack([p0, pinv @ rhs, p1])


# ----------------------------------------------------------------------------- certificate
def _max_norm_sq(rows) -> mpq:
    return max(sum(x * x for x in row) for row in rows)


def _hull_bound(hom: np.ndarray, ctrl: np.ndarray) -> mpq | None:
    """Convex-hull bound of ``max_t |F(t) - C(t)|`` (``None`` if a weight coefficient is <= 0)."""
    n, d = hom.shape[0] - 1, ctrl.shape[0] - 1
    h, w = hom[:, :-1], hom[:, -1]
    if all(x == w[0] for x in w) and w[0] > 0:  # polynomial F
        top = max(n, d)
        diff = bz.elevate(h / w[0], top - n) - bz.elevate(ctrl, top - d)
        return sqrt_upper(_max_norm_sq(diff))
    low = min(w)
    if low <= 0:
        return None
    num = bz.elevate(h, d) - bz.product(w.reshape(-1, 1), ctrl)
    return sqrt_upper(_max_norm_sq(num)) / low


def _homogeneous(ctrl: np.ndarray) -> np.ndarray:
    """``(C, 1)``: the polynomial control points with a unit weight column."""
    return np.concatenate([ctrl, np.full((ctrl.shape[0], 1), mpq(1), dtype=object)], axis=1)


def _control_form(ctrl: np.ndarray) -> ScaledBernstein:
    """The polynomial curve ``C`` (exact control points) as integer scaled forms."""
    return ScaledBernstein.from_homogeneous(_homogeneous(ctrl))


def certify(hom, ctrl: np.ndarray, target=None) -> tuple[mpq, str]:
    """``(r, decided_by)``: :func:`certified_bound` and which arithmetic proved it.

    ``hom``: the exact curve's homogeneous coefficients, an object array or its integer
    form (:class:`~exactcagd.composition.fast.ScaledBernstein`).

    With a ``target``: the bisection of the squared error
    (:func:`~exactcagd.composition.distance_bound.homogeneous_distance_bound`), on
    coefficients rounded outward first (``decided_by = "ball"``) and on the exact ones only
    when that does not prove ``target`` (``"exact"``); its first leaf is the convex-hull
    bound of the squared error on [0, 1], so no separate hull test is needed.  Without a
    target: the exact hull bound, or (weights not all positive) the bisection.
    """
    stats: dict = {}
    if target is None:
        hull = _hull_bound(hom.homogeneous() if isinstance(hom, ScaledBernstein) else hom, ctrl)
        if hull is not None:
            return hull, ball.EXACT
    bound = homogeneous_distance_bound(hom, _control_form(ctrl), target=target, stats=stats)
    return bound, (ball.EXACT if stats.get(ball.EXACT) else ball.BALL)


def certified_bound(hom: np.ndarray, ctrl: np.ndarray, target=None) -> mpq:
    """A rational ``r >= max_{t in [0, 1]} |F(t) - C(t)|``, proven in exact arithmetic.

    Parameters
    ----------
    hom : object array ``(n + 1, k + 1)``
        Homogeneous Bernstein coefficients ``(W F, W)`` of the exact curve.
    ctrl : object array ``(d + 1, k)``
        Exact (rational) control points of the polynomial curve ``C``.
    target : rational, optional
        When the convex-hull bound exceeds it, refine by exact bisection of the squared
        error (:func:`~exactcagd.composition.distance_bound.distance_bound`) until the
        bound is below ``target`` or a point above it is found.

    Notes
    -----
    Convex-hull property of the Bernstein basis: ``|sum_i D_i B_i(t)| <= max_i |D_i|``;
    for ``F = H / W``, ``F - C = (H - W C) / W`` and ``W(t) >= min_i W_i``.
    """
    bound = _hull_bound(hom, ctrl)
    if bound is not None and (target is None or bound <= target):
        return bound
    refined = homogeneous_distance_bound(hom, _homogeneous(ctrl), target=target)
    return refined if bound is None else min(bound, refined)


# ----------------------------------------------------------------------------- one piece
@lru_cache(maxsize=16)
def _samples() -> tuple:
    """``(fit, check, fit bytes, check bytes)``: :func:`sample_parameters`, computed once."""
    s_fit, s_check = sample_parameters()
    return s_fit, s_check, s_fit.tobytes(), s_check.tobytes()


@lru_cache(maxsize=16)
def _prediction_operator(lo: int, hi: int) -> np.ndarray:
    """Stacked linear maps, degrees ``lo..hi``: ``[T; p0; p1]`` (fit targets, fixed ends) to the
    values of the degree-``d`` least-squares fit (:func:`_least_squares`) at the fit and
    check parameters, ``(hi - lo + 1) * (2 NODES - 1)`` rows.  One product then gives the
    sampled residuals of every degree (selection only, never a bound)."""
    s_fit, _, fit_bytes, check_bytes = _samples()
    m = s_fit.size
    blocks = []
    for d in range(lo, hi + 1):
        fit_of = np.zeros((d + 1, m + 2))  # control points as a linear map of [T; p0; p1]
        fit_of[0, m], fit_of[d, m + 1] = 1.0, 1.0
        if d >= 2:
            basis, pinv = _basis(d, fit_bytes)
            fit_of[1:d, :m] = pinv
            fit_of[1:d, m] = -pinv @ basis[:, 0]
            fit_of[1:d, m + 1] = -pinv @ basis[:, -1]
        blocks.append(np.vstack([_basis(d, fit_bytes)[0], _basis(d, check_bytes)[0]]) @ fit_of)
    out = np.vstack(blocks)
    out.flags.writeable = False
    return out


def _sampled_error(d: int, fctrl: np.ndarray, target_fit: np.ndarray, target_check: np.ndarray) -> float:
    """Largest distance of the fit to ``F`` at the fit and check parameters (selection only)."""
    _, _, fit_bytes, check_bytes = _samples()
    return max(np.linalg.norm(_basis(d, b)[0].dot(fctrl) - t, axis=1).max()
               for b, t in ((fit_bytes, target_fit), (check_bytes, target_check)))


def _fit_piece(image: ScaledBernstein, p0, p1, tol: mpq, max_degree: int):
    """``(ctrl, bound, decided_by)`` of the lowest degree that certifies ``<= tol``, or ``None``.

    The sampled errors of ``_DEGREE_BLOCK`` consecutive degrees come from one product
    (:func:`_prediction_operator`); it differs from fitting each degree and measuring
    (:func:`_sampled_error`) by rounding only, so a degree clearly above ``tol`` there is
    skipped, one clearly below passes, and one within the rounding slack is re-measured:
    the selected degree is the one the degree-by-degree loop selects.
    """
    s_fit, _, fit_bytes, check_bytes = _samples()
    n = image.degree
    fl = image.floats()
    target_fit, target_check = (_homogeneous_points(_basis(n, b)[0] @ fl) for b in (fit_bytes, check_bytes))
    f0, f1 = np.array([float(x) for x in p0]), np.array([float(x) for x in p1])
    polynomial = image.constant_weight() is not None
    top = min(max_degree, n) if polynomial else max_degree
    tol_f = to_float(tol)
    rows = 2 * s_fit.size - 1
    data, targets = np.vstack([target_fit, f0, f1]), np.vstack([target_fit, target_check])
    # the two float evaluations differ by rounding only (~1e-16 cond |F|): skip what is clearly above
    slack = tol_f * 2**-20 + 2**-30 * float(np.abs(target_fit).max())
    skip_above, pass_below = tol_f + slack, tol_f - slack
    for lo in range(max(1, min(3, top)), top + 1, _DEGREE_BLOCK):
        hi = min(top, lo + _DEGREE_BLOCK - 1)
        residual = (_prediction_operator(lo, hi) @ data).reshape(hi - lo + 1, rows, -1) - targets
        quick = np.sqrt(np.einsum("ijk,ijk->ij", residual, residual).max(axis=1))
        for d, approx in zip(range(lo, hi + 1), quick):
            if approx > skip_above:
                continue
            try:
                found = _fit_degree(d, image, p0, p1, tol, (target_fit, target_check, f0, f1), approx < pass_below)
            except WeightError:
                return None
            if found is not None:
                return found
    return None


def _fit_degree(d: int, image: ScaledBernstein, p0, p1, tol: mpq, floats: tuple, clearly_below: bool = False):
    """``(ctrl, bound, decided_by)`` when degree ``d`` passes the sampled test and certifies,
    else ``None`` (:class:`~exactcagd.errors.WeightError` when ``W`` is not bounded away from
    zero).  ``clearly_below``: the stacked estimate is below ``tol`` by more than rounding,
    so the sampled test (re-measured otherwise) passes."""
    target_fit, target_check, f0, f1 = floats
    fctrl = _least_squares(d, _samples()[0], target_fit, f0, f1)
    if not clearly_below and not _sampled_error(d, fctrl, target_fit, target_check) <= to_float(tol):
        return None  # (rejects NaN; an inf tol passes)
    ctrl = np.empty(fctrl.shape, dtype=object)
    ctrl[1:-1] = [[mpq(*x.as_integer_ratio()) for x in row] for row in fctrl[1:-1].tolist()]  # exact binary values
    ctrl[0], ctrl[-1] = list(p0), list(p1)
    bound, decided_by = certify(image, ctrl, target=tol)
    return (ctrl, bound, decided_by) if bound <= tol else None


def fit_curve(hom, tol, p0=None, p1=None, max_degree: int = MAX_DEGREE, max_segments: int = 10000,
              stats: dict | None = None) -> list:
    """Fit-then-certify one exact Bézier curve ``F`` on ``[0, 1]``.

    Parameters
    ----------
    hom : object array ``(n + 1, k + 1)`` or :class:`~exactcagd.composition.fast.ScaledBernstein`
        Homogeneous coefficients ``(W F, W)`` (weights positive on [0, 1]).
    tol : positive rational
    p0, p1 : sequences of rationals, optional
        Exact end points to interpolate (default ``F(0)``, ``F(1)``).
    max_degree : int
        Highest fitting degree before a bisection at the parametric midpoint.
    stats : dict, optional
        Tally of which arithmetic proved each piece's bound (``{"ball": n, "exact": m}``).

    Returns
    -------
    list of ``((a, b), ctrl, bound)``
        In parameter order: sub-interval of [0, 1], exact control points (shared end points
        between neighbours) and the certified bound of ``max |F - C|`` on it.
    """
    tol = to_rational(tol, where="tol")
    if not isinstance(hom, ScaledBernstein):
        hom = ScaledBernstein.from_homogeneous(np.asarray(hom, dtype=object))
    p0 = _affine(hom.row(0)) if p0 is None else tuple(p0)
    p1 = _affine(hom.row(-1)) if p1 is None else tuple(p1)
    out: list = []
    stack = [(mpq(0), mpq(1), hom, p0, p1)]
    while stack:
        a, b, h, q0, q1 = stack.pop()
        found = _fit_piece(h, q0, q1, tol, max_degree)
        if found is not None:
            out.append(((a, b), found[0], found[1]))
            ball.count(stats, found[2])
            if len(out) > max_segments:
                raise ExactCAGDError(f"fit: more than max_segments = {max_segments} segments needed")
            continue
        if b - a < MIN_WIDTH:
            raise ExactCAGDError(f"fit: tolerance {to_float(tol):.3g} not reached on a piece narrower than 2^-40")
        left, right = h.halves()
        mid = _affine(left.row(-1))
        m = (a + b) / 2
        stack.append((m, b, right, mid, q1))
        stack.append((a, m, left, q0, mid))
    return out


def _affine(row) -> tuple:
    """The point of a homogeneous row ``(w P, w)``."""
    return tuple(x / row[-1] for x in row[:-1])


# ----------------------------------------------------------------------------- whole curve
def _surface_point(grid, key, point) -> tuple:
    """Exact ``S(u, v)`` from the patch ``key`` (de Casteljau in both directions)."""
    u, v = grid.to_local(key, point)
    h = bz.de_casteljau(bz.de_casteljau(grid.patch_hom(key), u), v)
    return tuple(h[:-1] / h[-1])


def _joint_image(grid, key, joint, domain_row, image_row) -> tuple:
    """Exact ``S(joint.point)``: the composed piece's end row ``image_row`` when the piece's
    domain end ``domain_row`` (homogeneous) is the joint's point itself (an exact joint; the
    composition is exact, so its end is ``S`` there), else :func:`_surface_point`."""
    w = domain_row[2]
    if joint.exact and (domain_row[0] / w, domain_row[1] / w) == tuple(joint.point):
        return _affine(image_row)
    return _surface_point(grid, key, joint.point)


def _dyadic_piece(hom: np.ndarray, a: mpq, b: mpq) -> np.ndarray:
    """``bz.restrict(hom, a, b)`` for a piece of the fit's bisection (``[a, b] = [k, k + 1] / 2^j``):
    ``j`` exact halvings in integers (:meth:`~exactcagd.composition.fast.ScaledBernstein.halves`),
    the same rational coefficients as the polar-form restriction at a fraction of its cost."""
    width = b - a
    depth = int(width.denominator).bit_length() - 1
    if width.numerator != 1 or width.denominator != 1 << depth:  # pragma: no cover - bisection pieces are dyadic
        return bz.restrict(hom, a, b)
    index = int(a / width)
    node = ScaledBernstein.from_homogeneous(hom)
    for level in range(depth - 1, -1, -1):  # the bits of k, most significant first: 0 left, 1 right
        node = node.halves()[(index >> level) & 1]
    return node.homogeneous()


def _pieces(joints):
    """Consecutive kept joints ``(ja, jb)``: each pair bounds one exact image piece."""
    kept = [j for j in joints if _KEEP.intersection(j.reasons)]
    pairs = list(zip(kept[:-1], kept[1:]))
    if any(ja.hi[0] != jb.lo[0] for ja, jb in pairs):  # pragma: no cover - curve knots are kept
        raise ExactCAGDError("internal: a fit piece spans two pieces of the domain curve")
    return pairs


def approximate_fit(grid, dcurve, joints, tol: mpq, max_degree: int, max_segments: int, start: float):
    """The ``method="fit"`` branch of :func:`~.driver.approximate` (see the module docstring)."""
    from .driver import CurveOnSurface, _angle_deg, _gap_bound

    t_split = time.perf_counter()
    segments, domains, patches, params, ends, bounds = [], [], [], [], [], []
    cache: dict = {}
    stats: dict = {}
    for ja, jb in _pieces(joints):
        k, ta = ja.hi
        _, tb = jb.lo
        key = grid.locate(*dcurve.point(k, (ta + tb) / 2))
        (ua, ub), (va, vb) = grid.spans(key)
        glob = dcurve.homs[k] if (ta, tb) == (0, 1) else dcurve.restricted(k, ta, tb)
        local = glob
        if (ua, ub, va, vb) != (0, 1, 0, 1):  # global (u, v) -> the patch's local [0, 1]^2
            local = glob.copy()
            local[:, 0] = (glob[:, 0] - ua * glob[:, 2]) / (ub - ua)
            local[:, 1] = (glob[:, 1] - va * glob[:, 2]) / (vb - va)
        image = compose_scaled(grid.patch_hom(key), local)
        for j, row in ((ja, 0), (jb, -1)):
            if id(j) not in cache:  # one exact point per joint, shared by both neighbours
                cache[id(j)] = _joint_image(grid, key, j, glob[row], image.row(row))
        p0, p1 = cache[id(ja)], cache[id(jb)]
        for (a, b), ctrl, bound in fit_curve(image, tol, p0, p1, max_degree, max_segments, stats):
            segments.append(ctrl)
            bounds.append(bound)
            patches.append(key)
            domains.append(BezierCurve.from_homogeneous(glob if (a, b) == (0, 1) else _dyadic_piece(glob, a, b)))
            params.append({"piece": k, "interval": [str(ta + (tb - ta) * a), str(ta + (tb - ta) * b)],
                           "fit_degree": ctrl.shape[0] - 1})
            span0, span1 = dcurve.spans[k]
            t0, t1 = ta + (tb - ta) * a, ta + (tb - ta) * b
            ends.append(((span0 + (span1 - span0) * t0, ja.exact or a > 0),
                         (span0 + (span1 - span0) * t1, jb.exact or b < 1)))
            if len(segments) > max_segments:
                raise ExactCAGDError(f"more than max_segments = {max_segments} segments needed")
    t_fit = time.perf_counter()
    degree = max(c.shape[0] - 1 for c in segments)
    # exact mpq control points built here (validated by construction): no re-validation
    nets = [bz.elevate(c, degree - (c.shape[0] - 1)) for c in segments]
    curves = [BezierCurve._trusted(net, None) for net in nets]
    bound = max(max(bounds), _gap_bound(grid, dcurve, joints))
    pairs = list(zip(nets[:-1], nets[1:])) + ([(nets[-1], nets[0])] if dcurve.closed and len(nets) > 1 else [])
    angles = [_angle_deg(a[-1] - a[-2], b[1] - b[0]) for a, b in pairs]  # end / start tangent directions
    t_end = time.perf_counter()
    return CurveOnSurface(
        segments=curves,
        domain_segments=domains,
        patches=patches,
        kinds=["fit"] * len(curves),
        distance_bound=bound,
        degree=degree,
        method="fit",
        tolerance=tol,
        continuity="C0",
        max_joint_angle=max(angles) if angles else 0.0,
        angle_tolerance=None,
        corners=[j.point for j in joints if j.corner],
        timings={"split": t_split - start, "distance": t_fit - t_split, "angle": 0.0, "images": 0.0,
                 "verify": t_end - t_fit, "total": t_end - start, "attempts": len(curves), "angle_rounds": 0},
        g1_verified=None,
        closed=dcurve.closed,
        params=params,
        ends=ends,
        certified_by=stats,
    )

"""G1 cubic spline approximation of a trim curve, Lasser & Bonneau (000) section VIII.

For a segment of the exact curve ``F(t) = sum B_R B^{rN}_R(t)`` the cubic
``X(t) = sum b_k B^3_k(t)`` (19) has fixed ends and end tangents (20)::

    b_0 = B_0,   b_1 = B_0 + lambda_1 (B_1 - B_0),
    b_3 = B_rN,  b_2 = B_rN + lambda_2 (B_{rN-1} - B_rN),

and ``lambda_1, lambda_2`` minimize (21)
``d = sum_l | D_l - lambda_1 (B_1 - B_0) B^3_1(t_l) - lambda_2 (B_{rN-1} - B_rN) B^3_2(t_l) |^2``
with ``D_l = P_l - B_0 (B^3_0 + B^3_1)(t_l) - B_rN (B^3_2 + B^3_3)(t_l)`` (22), a 2x2 linear
system.  Parameter correction (as in the paper: the points move on ``F``): ``t_l* `` solves
``<F(t*) - X(t_l), X'(t_l)> = 0`` (Newton steps with the exact derivative of ``F``), so the
error vectors ``d_l = F(t_l*) - X(t_l)`` become perpendicular to ``X``; then (21) is solved
again.  If the tolerance is not met, ``F`` is split (exactly, de Casteljau) at the point of
maximal error and both halves are approximated (G1 joints: the subdivided control polygons
are collinear at the split point, so ``b_2, b_3 = b'_0, b'_1`` are collinear exactly).

Floats are used inside the fit; the returned control points are exact rationals
(``lambda`` rounded to a short rational, the rest exact), and every segment carries a
*certified* upper bound of its Hausdorff distance to the exact curve
(:func:`exactcagd.composition.distance_bound.distance_bound`), which decides acceptance.
If the paper's degenerate case ``B_1 = B_0`` occurs, the first control point different
from ``B_0`` gives the tangent direction.

>>> from exactcagd import BezierCurve, BezierSurface
>>> F = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
>>> result = approximate_cubic(F, BezierCurve([[0, 0], [1, "1/2"], [0, 1]]), tol="1/100")
>>> result.tolerance_met, len(result.segments) >= 1
(True, True)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
from gmpy2 import mpq

from ..errors import InputError
from ..exact.scalars import rational_str, to_count, to_rational
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from .distance_bound import distance_bound

__all__ = ["approximate_cubic", "approximate_cubic_curve", "CubicApproximation", "CubicSegment", "fit_cubic", "bernstein_basis_float"]


# ----------------------------------------------------------------------------- float helpers
def bernstein_basis_float(n: int, t: np.ndarray) -> np.ndarray:
    """Binary64 values ``B_i^n(t_j)`` as a ``(len(t), n + 1)`` matrix, for least-squares fits.

    Float only (sampling and fitting, never a certificate); also used by the fit route of
    :mod:`exactcagd.curves_on_surfaces.fit`.
    """
    from math import comb

    t = np.asarray(t, dtype=float)[:, None]
    i = np.arange(n + 1)[None, :]
    coef = np.array([float(comb(n, k)) for k in range(n + 1)])[None, :]
    return coef * t**i * (1 - t) ** (n - i)


class _FloatCurve:
    """Float evaluation of an exact (rational) Bézier curve and its derivative."""

    def __init__(self, curve: BezierCurve):
        hom = curve.homogeneous()
        self.hom = np.vectorize(float, otypes=[float])(hom)
        self.n = hom.shape[0] - 1
        self.dhom = self.n * (self.hom[1:] - self.hom[:-1]) if self.n > 0 else np.zeros_like(self.hom)

    def __call__(self, t):
        h = bernstein_basis_float(self.n, t) @ self.hom
        return h[:, :-1] / h[:, -1:]

    def derivative(self, t):
        h = bernstein_basis_float(self.n, t) @ self.hom
        if self.n == 0:
            return np.zeros((len(np.atleast_1d(t)), self.hom.shape[1] - 1))
        dh = bernstein_basis_float(self.n - 1, t) @ self.dhom
        w, dw = h[:, -1:], dh[:, -1:]
        return (dh[:, :-1] * w - h[:, :-1] * dw) / w**2


def _cubic_float(b: np.ndarray, t: np.ndarray):
    m = bernstein_basis_float(3, t)
    d = bernstein_basis_float(2, t) @ (3 * (b[1:] - b[:-1]))
    return m @ b, d


# ----------------------------------------------------------------------------- results
@dataclass
class CubicSegment:
    """One cubic of the spline: ``curve`` approximates ``F`` on the parameter ``interval``."""

    curve: BezierCurve
    interval: tuple
    distance_bound: mpq
    sampled_error: float
    reparametrization: tuple
    lambdas: tuple

    def to_dict(self) -> dict:
        return {
            "curve": self.curve.to_dict(),
            "interval": [rational_str(x) for x in self.interval],
            "distance_bound": rational_str(self.distance_bound),
            "distance_bound_float": float(self.distance_bound),
            "sampled_error": self.sampled_error,
            "reparametrization": [rational_str(x) for x in self.reparametrization],
            "lambdas": [rational_str(x) for x in self.lambdas],
        }


@dataclass
class CubicApproximation:
    """A G1 cubic Bézier spline approximating ``F(K(t))`` with a certified distance.

    ``distance_bound`` (exact rational) is an upper bound of the Hausdorff distance between
    the exact curve and the spline (maximum over segments); ``tolerance_met`` says whether
    it is <= ``tolerance``.  ``sampled_error`` is the largest float-sampled error (a lower
    estimate of the parametric error, for comparison only).
    """

    segments: list
    tolerance: mpq
    distance_bound: mpq
    tolerance_met: bool
    sampled_error: float
    exact_curves: list = field(default_factory=list)

    @property
    def curves(self) -> list:
        return [s.curve for s in self.segments]

    def g1_joints(self) -> list:
        """Exact check at every joint: ``b_2, b_3 = b'_0, b'_1`` collinear, same direction."""
        out = []
        for left, right in zip(self.segments[:-1], self.segments[1:]):
            a, b = left.curve.points_array(), right.curve.points_array()
            u, v = a[3] - a[2], b[1] - b[0]
            same_point = bool(np.all(a[3] == b[0]))
            dot = sum(x * y for x, y in zip(u, v))
            uu, vv = sum(x * x for x in u), sum(x * x for x in v)
            collinear = dot * dot == uu * vv
            out.append(same_point and collinear and dot >= 0)
        return out

    def to_dict(self) -> dict:
        return {
            "tolerance": rational_str(self.tolerance),
            "distance_bound": rational_str(self.distance_bound),
            "distance_bound_float": float(self.distance_bound),
            "tolerance_met": self.tolerance_met,
            "sampled_error": self.sampled_error,
            "segments": [s.to_dict() for s in self.segments],
        }


# ----------------------------------------------------------------------------- one cubic
def _end_direction(points: np.ndarray, from_end: bool):
    seq = points[::-1] if from_end else points
    for p in seq[1:]:
        if np.any(p != seq[0]):
            return p - seq[0]
    return None


def _short_rational(x: float) -> mpq:
    f = Fraction(x).limit_denominator(2**24)
    return mpq(f.numerator, f.denominator)


def fit_cubic(F: BezierCurve, samples: int | None = None, iterations: int = 8, ends=(None, None)):
    """Fit one cubic to the exact curve ``F`` on [0, 1] by (20)-(22) with parameter correction.

    ``ends`` optionally prescribes ``(point, direction)`` (exact arrays) at the start and/or
    the end instead of ``F``'s own end point and end tangent (used at snapped joints of a
    spline, where both neighbours must share one exact point and direction).

    Returns ``(cubic, lambdas, t_star, t_cubic, errors)``: the exact cubic, the exact
    ``(lambda_1, lambda_2)``, the corrected parameters on ``F``, the fixed parameters on ``X``
    and the final error-vector lengths ``|d_l|`` (floats).
    """
    pts = F.points_array()
    b0, b3 = pts[0], pts[-1]
    t0dir, t1dir = _end_direction(pts, False), _end_direction(pts, True)
    if ends[0] is not None:
        b0, t0dir = ends[0]
    if ends[1] is not None:
        b3, t1dir = ends[1]
    n = F.degree
    L = samples or max(24, 2 * n + 2)
    t = np.linspace(0.0, 1.0, L + 1)
    tstar = t.copy()
    fF = _FloatCurve(F)
    fb0, fb3 = np.array([float(x) for x in b0]), np.array([float(x) for x in b3])
    d0 = np.zeros_like(fb0) if t0dir is None else np.array([float(x) for x in t0dir])
    d1 = np.zeros_like(fb0) if t1dir is None else np.array([float(x) for x in t1dir])
    basis = bernstein_basis_float(3, t)
    a1, a2 = d0[None, :] * basis[:, 1:2], d1[None, :] * basis[:, 2:3]
    lam = np.array([1.0 / 3.0, 1.0 / 3.0])
    for it in range(iterations + 1):
        P = fF(tstar)
        D = P - np.outer(basis[:, 0] + basis[:, 1], fb0) - np.outer(basis[:, 2] + basis[:, 3], fb3)
        G = np.array([[np.sum(a1 * a1), np.sum(a1 * a2)], [np.sum(a1 * a2), np.sum(a2 * a2)]])
        rhs = np.array([np.sum(D * a1), np.sum(D * a2)])
        lam = np.linalg.lstsq(G, rhs, rcond=None)[0] if np.any(G) else lam
        if it == iterations:
            break
        ctrl = np.array([fb0, fb0 + lam[0] * d0, fb3 + lam[1] * d1, fb3])
        X, dX = _cubic_float(ctrl, t)
        for _ in range(2):  # Newton on <F(t*) - X(t_l), X'(t_l)> = 0
            Fv, dF = fF(tstar), fF.derivative(tstar)
            g = np.sum((Fv - X) * dX, axis=1)
            dg = np.sum(dF * dX, axis=1)
            step = np.where(np.abs(dg) > 1e-300, g / np.where(dg == 0, 1, dg), 0.0)
            tstar = np.clip(tstar - step, 0.0, 1.0)
            tstar[0], tstar[-1] = 0.0, 1.0
    lam1, lam2 = (_short_rational(float(x)) for x in lam)
    zero = b0 * 0
    p1 = b0 + lam1 * (zero if t0dir is None else t0dir)
    p2 = b3 + lam2 * (zero if t1dir is None else t1dir)
    cubic = BezierCurve._trusted(np.array([b0, p1, p2, b3], dtype=object), None)
    ctrl = np.array([[float(x) for x in p] for p in (b0, p1, p2, b3)])
    X, _ = _cubic_float(ctrl, t)
    errors = np.linalg.norm(fF(tstar) - X, axis=1)
    return cubic, (lam1, lam2), tstar, t, errors


def _reparametrization(tstar: np.ndarray, t: np.ndarray, degree: int = 3) -> list:
    """Exact Bernstein coefficients of ``phi`` with ``phi(t*_l) ~ t_l``, ``phi(0)=0``, ``phi(1)=1``.

    Least squares for the interior coefficients; falls back to the identity when a
    coefficient leaves [0, 1] (then ``phi`` would not map [0, 1] into [0, 1]).
    """
    M = bernstein_basis_float(degree, tstar)
    rhs = t - M[:, -1]
    coef = np.linalg.lstsq(M[:, 1:-1], rhs, rcond=None)[0] if degree > 1 else np.array([])
    exact = [mpq(0)] + [_short_rational(float(c)) for c in coef] + [mpq(1)]
    if all(0 <= c <= 1 for c in exact):
        return exact
    return [mpq(0), mpq(1)]


def _split_parameter(tstar: np.ndarray, errors: np.ndarray) -> mpq:
    k = int(np.argmax(errors))
    x = float(np.clip(tstar[k], 0.1, 0.9))
    return mpq(Fraction(x).limit_denominator(1024).numerator, Fraction(x).limit_denominator(1024).denominator)


def _approximate_piece(F: BezierCurve, interval, tol: mpq, max_segments: int, options, out: list, ends=(None, None)) -> None:
    cubic, lams, tstar, t, errors = fit_cubic(F, options.get("samples"), options.get("iterations", 8), ends)
    phi = _reparametrization(tstar, t, options.get("reparam_degree", 3))
    bound = distance_bound(F, cubic, phi, target=tol)
    identity_bound = None
    if bound > tol and phi != [mpq(0), mpq(1)]:
        identity_bound = distance_bound(F, cubic, target=tol)
        if identity_bound < bound:
            bound, phi = identity_bound, [mpq(0), mpq(1)]
    if bound <= tol or options["splits_left"] <= 0:
        if options.get("tight", True):  # the acceptance test stopped early: tighten the report
            bound = min(bound, distance_bound(F, cubic, phi, rel=0.05, max_leaves=64))
        fphi = bernstein_basis_float(len(phi) - 1, np.linspace(0, 1, 201)) @ np.array([float(x) for x in phi])
        dense = np.linspace(0, 1, 201)
        ctrl = np.array([[float(x) for x in p] for p in cubic.points_array()])
        X, _ = _cubic_float(ctrl, fphi)
        sampled = float(np.max(np.linalg.norm(_FloatCurve(F)(dense) - X, axis=1)))
        out.append(CubicSegment(cubic, interval, bound, sampled, tuple(phi), lams))
        return
    options["splits_left"] -= 1
    s = _split_parameter(tstar, errors)
    left, right = F.subdivide(s)
    a, b = interval
    mid = a + s * (b - a)
    _approximate_piece(left, (a, mid), tol, max_segments, options, out, (ends[0], None))
    _approximate_piece(right, (mid, b), tol, max_segments, options, out, (None, ends[1]))


def approximate_cubic_curve(F: BezierCurve, tol, *, interval=(0, 1), max_segments: int = 64, samples: int | None = None, iterations: int = 8, reparam_degree: int = 3, ends=(None, None)) -> CubicApproximation:
    """G1 cubic spline approximation of an exact Bézier curve ``F`` (section VIII).

    Parameters
    ----------
    F : BezierCurve
        The exact curve (e.g. ``compose(surface, curve)``), polynomial or rational.
    tol : number
        Required certified distance (exact rational; floats are converted exactly).
    interval : (a, b)
        Global parameter interval that ``F``'s [0, 1] stands for (for reporting).
    max_segments : int
        Stop splitting at this many cubics (``tolerance_met`` then may be false).
    samples, iterations, reparam_degree
        ``L`` of (21) (default ``max(24, 2 rN + 2)``), parameter-correction rounds, degree of
        the reparametrization used for the certificate.
    ends : (start, end)
        Optional exact ``(point, direction)`` overriding ``F``'s end point and end tangent
        (see :func:`fit_cubic`); the certified bound still measures against ``F`` itself.
    """
    if not isinstance(F, BezierCurve):
        raise InputError(f"expected a BezierCurve, got {type(F).__name__}")
    tol = to_rational(tol, where="tol")
    if tol <= 0:
        raise InputError("tol must be positive")
    segments: list = []
    options = {"samples": samples, "iterations": iterations, "reparam_degree": reparam_degree, "splits_left": max_segments - 1}
    a, b = (to_rational(x) for x in interval)
    _approximate_piece(F, (a, b), tol, max_segments, options, segments, tuple(ends))
    bound = max(s.distance_bound for s in segments)
    return CubicApproximation(segments, tol, bound, bound <= tol, max(s.sampled_error for s in segments), [F])


def approximate_cubic(surface, curve, tol, *, max_segments: int = 64, samples: int | None = None, iterations: int = 8, reparam_degree: int = 3, method: str = "fast", snap_bits: int = 64) -> CubicApproximation:
    """G1 cubic Bézier spline approximation of the trim curve ``F(K(t))`` (section VIII).

    ``surface``/``curve`` as for :func:`exactcagd.composition.compose` (Bézier) or
    :func:`exactcagd.composition.compose_spline` (B-spline/NURBS).  Each exact piece of
    ``F(K(t))`` is approximated by :func:`approximate_cubic_curve`.

    A spline piece may end at an irrational parameter ``t*`` (a knot-line crossing); no
    cubic with rational control points passes through that exact point.  Such a joint is
    *snapped*: a dyadic ``tau`` with ``|tau - t*| <= 2^-snap_bits`` replaces ``t*`` for
    both neighbours, which share the exact point ``S(K(tau))`` and tangent direction taken
    from the patch that really contains ``tau`` (so G1 stays exact).  Each neighbour is
    fitted to its own patch's exact composition over the snapped interval, and the
    reported bound adds ``2^-snap_bits`` times a certified speed bound of the pieces'
    carrier curves (the exact curve between ``tau`` and ``t*`` moves at most that far),
    so the bound stays a certified Hausdorff bound.  Where the exact curve has a corner
    (a C0 knot line, Remark 1 bound 0) the joint is G0 with each side's own tangent.

    Returns
    -------
    CubicApproximation
        ``segments`` (exact cubics, global parameter intervals, certified bounds),
        ``distance_bound`` (certified Hausdorff bound of the whole spline), ``tolerance_met``.
    """
    from .core import compose
    from .splines import compose_spline

    options = {"max_segments": max_segments, "samples": samples, "iterations": iterations, "reparam_degree": reparam_degree}
    for name in ("max_segments", "iterations", "reparam_degree") + (("samples",) if samples is not None else ()):
        if to_count(options[name], where=name) < 1:
            raise InputError(f"{name} must be a positive integer, got {options[name]!r}")
    if isinstance(surface, BezierSurface) and isinstance(curve, BezierCurve):
        return approximate_cubic_curve(compose(surface, curve, method=method), tol, **options)
    tol = to_rational(tol, where="tol")
    if tol <= 0:
        raise InputError("tol must be positive")
    spline = compose_spline(surface, curve, method=method, continuity=False)
    pieces, gap = _snapped_pieces(spline.pieces, spline.joints, snap_bits)
    if gap >= tol:
        raise InputError(f"snap_bits={snap_bits} is too coarse for tol={rational_str(tol)} (snapping costs {float(gap):.3g})")
    parts = [approximate_cubic_curve(F, tol - gap, interval=interval, ends=ends, **options) for F, interval, ends in pieces]
    segments = [s for part in parts for s in part.segments]
    bound = max(s.distance_bound for s in segments) + gap
    return CubicApproximation(segments, tol, bound, bound <= tol, max(p.sampled_error for p in parts), [p.curve for p in spline.pieces])


# ----------------------------------------------------------------------------- snapped joints
def _snap(t, bits: int) -> mpq:
    """A dyadic rational within ``2^-bits`` of the exact parameter ``t`` (``t`` itself if rational)."""
    if isinstance(t, mpq):
        return t
    t.refine(mpq(1, 2**bits))
    return (t.lo + t.hi) / 2


def _speed_bound(curve: BezierCurve) -> mpq:
    """Certified ``M >= sup_{s in [0,1]} |C'(s)|`` from Bernstein coefficients.

    For ``C = P / w``: ``C' = (P' w - P w') / w^2``; the numerator's Bernstein coefficients
    bound it componentwise, ``min`` of the weight coefficients bounds ``w`` from below, and
    the 1-norm bounds the 2-norm.
    """
    from ..exact import bernstein as bz

    hom = curve.homogeneous()
    P, w = hom[:, :-1], hom[:, -1]
    if not curve.is_rational:
        numerator, wmin = bz.derivative(P), mpq(1)
    else:
        W = w.reshape(-1, 1)
        numerator = bz.product(bz.derivative(P), W) - bz.product(P, bz.derivative(W))
        wmin = min(w)
        if wmin <= 0:
            raise InputError("a piece of F(K(t)) has a non-positive weight coefficient; cannot bound its speed")
    return sum(max(abs(c) for c in numerator[:, k]) for k in range(numerator.shape[1])) / (wmin * wmin)


def _snapped_pieces(pieces, joints_info, bits: int):
    """``([(F, (tau0, tau1), ends)], gap)`` for :func:`approximate_cubic` (see its docstring).

    ``F`` is piece ``k``'s patch composition re-parametrized to the snapped global interval;
    ``ends`` prescribes the shared exact point (and, where the exact curve is at least C1
    by Remark 1, the shared direction) at snapped joints; ``gap`` bounds the Hausdorff
    distance between the snapped pieces and the exact curve.
    """
    smooth = {id(j.parameter): j.remark_bound is None or j.remark_bound >= 1 for j in joints_info}
    taus = [_snap(p.interval[0], bits) for p in pieces] + [_snap(pieces[-1].interval[1], bits)]
    locals_, gap = [], mpq(0)
    for k, piece in enumerate(pieces):
        a, b = piece.carrier
        s0, s1 = (taus[k] - a) / (b - a), (taus[k + 1] - a) / (b - a)
        F = piece.curve.reparametrize(s0, s1) if (s0, s1) != (0, 1) else piece.curve
        locals_.append(F)
        if not piece.exact:
            # the stretch between tau and t* lies in the carrier, where the exact curve is piece.curve
            gap = max(gap, mpq(1, 2**bits) * _speed_bound(piece.curve) / (b - a))
    joints = [None] * (len(pieces) + 1)
    for k in range(1, len(pieces)):
        t_exact = pieces[k].interval[0]
        if isinstance(t_exact, mpq):
            continue
        # the point and direction come from the piece whose exact interval holds tau
        owner, end = (k - 1, -1) if taus[k] < t_exact else (k, 0)
        pts = locals_[owner].points_array()  # affine control points: the end tangent is along the polygon
        direction = _end_direction(pts, end == -1)
        if end == -1:
            direction = -direction  # _end_direction(from_end=True) points backwards
        shared = smooth.get(id(t_exact), True)
        joints[k] = (pts[end], direction if shared else None)
    out = []
    for k, F in enumerate(locals_):
        start = end = None
        if joints[k] is not None:
            point, direction = joints[k]
            start = (point, direction if direction is not None else _end_direction(F.points_array(), False))
        if joints[k + 1] is not None:
            point, direction = joints[k + 1]
            end = (point, -direction if direction is not None else _end_direction(F.points_array(), True))
        out.append((F, (taus[k], taus[k + 1]), (start, end)))
    return out, gap


"""Certified upper bounds of the Hausdorff distance between two planar rational curves.

Box I of Yang et al. (004) (3-D tolerance -> 2-D tolerance) is missing from the
source text, and their H(C_1, C_2) comes from an iterative method [25] without a
guarantee.  exactcagd certifies instead (derivation and checks in
``proofs/yang_hausdorff.py``):

**Piece bound.**  Let ``A`` and ``B`` be rational Bézier pieces with positive weights,
with end points ``a_0, a_1`` and ``b_0, b_1`` and projected control points ``Q^A_k``,
``Q^B_k``.  For ``p`` on ``A`` let ``x`` be the point of the chord ``[b_0, b_1]`` nearest to
``p``; the projection of ``B`` onto the chord's line is connected and contains both
chord ends, so some ``y`` on ``B`` projects to ``x``, and ``|x - y|`` is at most the
half-width ``delta_B = max_k dist(Q^B_k, line(b_0, b_1))`` of the fat line around
the chord.  Since the distance to a segment is convex, its maximum over ``A``'s convex
hull is attained at a control point:

    h(A -> B) <= max_k dist(Q^A_k, [b_0, b_1]) + delta_B,

and symmetrically for ``h(B -> A)``.  (A closed chord ``b_0 = b_1`` uses
``max_k |Q^A_k - b_0|``.)

**Curve bound.**  Cut ``C_1`` at ``0 = t_0 < ... < t_N = 1`` and ``C_2`` at
``0 = tau_0 <= ... <= tau_N = 1``; the pieces cover both curves, so
``H(C_1, C_2) <= max_i max(h(A_i -> B_i), h(B_i -> A_i))`` for *any* pairing.  The
pairing only affects tightness: the ``tau_i`` are float foot points of
``C_1(t_i)`` on ``C_2`` (rounded to dyadic rationals, kept monotonic), and pieces
whose bound is too large are bisected adaptively.  Every distance comparison is
exact (rationals or ``Q(sqrt(Delta))``); square roots are bounded above by exact
integer square roots.  For rational pieces the same formula is first evaluated in ball
arithmetic (python-flint ``arb``, outward rounded; :func:`ball_piece_bound`), and exactly
only when the ball's upper end does not certify the piece.

>>> from gmpy2 import mpq
>>> from exactcagd import BezierCurve
>>> a = BezierCurve([[0, 0], [1, 1], [2, 0]]).homogeneous()
>>> b = BezierCurve([[0, 0], [2, 0]]).homogeneous()
>>> hb = hausdorff_bound(a, b, limit="3/5")       # true distance 1/2 (at the apex)
>>> hb is not None and mpq(1, 2) <= hb <= mpq(3, 5)
True
"""

from __future__ import annotations

import flint
import gmpy2
import numpy as np
from gmpy2 import mpq, mpz

from ..composition import ball
from ..exact import bernstein as bz
from ..exact.quadratic import QuadraticNumber
from ..exact.scalars import to_float, to_rational

__all__ = ["hausdorff_bound", "piece_bound", "directed_piece_bound", "ball_piece_bound", "ball_directed_bound", "sqrt_upper", "upper", "float_hausdorff"]


def upper(x) -> mpq:
    """A rational upper bound of an exact number (itself if rational)."""
    if isinstance(x, QuadraticNumber):
        return x.bounds(80)[1]
    return mpq(x)


def sqrt_upper(q, bits: int = 64) -> mpq:
    """Rational ``r >= sqrt(q)`` with ``r - sqrt(q) <= 2^-bits (1 + sqrt(q))`` (exact isqrt)."""
    q = upper(q)
    if q <= 0:
        return mpq(0)
    scale = mpz(2) ** bits
    num = q.numerator * scale * scale
    r = gmpy2.isqrt(num // q.denominator)
    while r * r * q.denominator < num:  # ceil
        r += 1
    return mpq(r, scale)


def _casteljau_split(cols: list, t) -> tuple[list, list]:
    """Left and right control values of scalar columns split at ``t`` (plain Python, exact)."""
    left, right = [], []
    s = 1 - t
    for col in cols:
        level = list(col)
        lo, hi = [level[0]], [level[-1]]
        while len(level) > 1:
            level = [s * x + t * y for x, y in zip(level[:-1], level[1:])]
            lo.append(level[0])
            hi.append(level[-1])
        left.append(lo)
        right.append(hi[::-1])
    return left, right


def restrict_fast(hom: np.ndarray, a, b) -> np.ndarray:
    """``bernstein.restrict`` for ``0 <= a < b <= 1`` by two de Casteljau splits (faster for
    the small arrays used here)."""
    cols = [list(hom[:, k]) for k in range(hom.shape[1])]
    if b != 1:
        cols, _ = _casteljau_split(cols, b)
    if a != 0:
        _, cols = _casteljau_split(cols, a / b)
    out = np.empty(hom.shape, dtype=object)
    for k, col in enumerate(cols):
        out[:, k] = col
    return out


def _points(hom: np.ndarray) -> list:
    return [tuple(row[k] / row[-1] for k in range(hom.shape[1] - 1)) for row in hom]


def _sq(v) -> object:
    return sum(x * x for x in v)


def _dist_segment_sq(p, a, b):
    e = [y - x for x, y in zip(a, b)]
    ee = _sq(e)
    ap = [y - x for x, y in zip(a, p)]
    if ee == 0:
        return _sq(ap)
    s = sum(x * y for x, y in zip(ap, e))
    if s <= 0:
        return _sq(ap)
    if s >= ee:
        return _sq([y - x for x, y in zip(b, p)])
    return _sq(ap) - s * s / ee


def _dist_line_sq(p, a, b):
    e = [y - x for x, y in zip(a, b)]
    ee = _sq(e)
    ap = [y - x for x, y in zip(a, p)]
    if ee == 0:
        return _sq(ap)
    s = sum(x * y for x, y in zip(ap, e))
    return _sq(ap) - s * s / ee


def _max(values):
    best = None
    for v in values:
        if best is None or v > best:
            best = v
    return best


def _one_sided(pa: list, pb: list):
    """``(max_k dist(Q^A_k, chord B)^2, delta_B^2)`` (exact)."""
    b0, b1 = pb[0], pb[-1]
    if all(x == y for x, y in zip(b0, b1)):
        return _max(_sq([y - x for x, y in zip(b0, q)]) for q in pa), mpq(0)
    a_part = _max(_dist_segment_sq(q, b0, b1) for q in pa)
    delta = _max(_dist_line_sq(q, b0, b1) for q in pb[1:-1]) if len(pb) > 2 else mpq(0)
    return a_part, delta


def piece_bound(hom_a: np.ndarray, hom_b: np.ndarray) -> mpq:
    """Rational upper bound of ``H(A, B)`` for two rational Bézier pieces (positive weights)."""
    pa, pb = _points(hom_a), _points(hom_b)
    return max(_directed_points_bound(pa, pb), _directed_points_bound(pb, pa))


def directed_piece_bound(hom_a: np.ndarray, hom_b: np.ndarray) -> mpq:
    """Rational upper bound of the one-sided distance ``h(A -> B) = max_{p in A} dist(p, B)``
    (the module's piece bound, one direction: ``max_k dist(Q^A_k, [b_0, b_1]) + delta_B``).

    >>> from exactcagd import BezierCurve
    >>> a = BezierCurve([[0, 1], [1, 1]]).homogeneous()
    >>> b = BezierCurve([[0, 0], [2, 0]]).homogeneous()
    >>> directed_piece_bound(a, b), directed_piece_bound(b, a) > 1
    (mpq(1,1), True)
    """
    return _directed_points_bound(_points(hom_a), _points(hom_b))


def _directed_points_bound(pa: list, pb: list) -> mpq:
    a_part, delta = _one_sided(pa, pb)
    return sqrt_upper(a_part) + sqrt_upper(delta)


# ---------------------------------------------------------------------- ball arithmetic
def _ball_rows(hom: np.ndarray) -> list | None:
    """Homogeneous coefficients as ``arb`` balls, ``None`` if any is not rational."""
    if not all(isinstance(x, (type(mpq(0)), int)) for x in hom.flat):
        return None
    return [[ball.to_arb(x) for x in row] for row in hom]


def _ball_split(rows: list, t: flint.arb) -> tuple[list, list]:
    """De Casteljau split of ball rows at ``t`` (every ball contains the exact value)."""
    s = 1 - t
    level = rows
    left, right = [rows[0]], [rows[-1]]
    while len(level) > 1:
        level = [[s * x + t * y for x, y in zip(r0, r1)] for r0, r1 in zip(level[:-1], level[1:])]
        left.append(level[0])
        right.append(level[-1])
    return left, right[::-1]


def _ball_restrict(rows: list, a, b) -> list:
    """:func:`restrict_fast` on ball rows (``0 <= a < b <= 1`` rational)."""
    if b != 1:
        rows, _ = _ball_split(rows, ball.to_arb(b))
    if a != 0:
        _, rows = _ball_split(rows, ball.to_arb(a) / ball.to_arb(b))
    return rows


def _ball_points(rows: list) -> list:
    return [[x / row[-1] for x in row[:-1]] for row in rows]


def _ball_sq(v) -> flint.arb:
    return sum((x * x for x in v), flint.arb(0))


def _ball_dist_segment_sq(p, a, b, ee) -> flint.arb | None:
    """A ball whose upper end bounds ``dist(p, [a, b])^2`` (``ee = |b - a|^2 > 0``).

    When the sign tests of :func:`_dist_segment_sq` are not decided by the balls, the
    largest candidate value of the cases the balls allow is used: the exact distance is one
    of them.
    """
    e = [y - x for x, y in zip(a, b)]
    ap = [y - x for x, y in zip(a, p)]
    s = sum((x * y for x, y in zip(ap, e)), flint.arb(0))
    if s <= 0:
        return _ball_sq(ap)
    if s >= ee:
        return _ball_sq([y - x for x, y in zip(b, p)])
    inner = _ball_sq(ap) - s * s / ee
    if s > 0 and s < ee:
        return inner
    # undecided: the exact distance is the candidate of a case the balls do not exclude
    best = inner
    if not s > 0:
        best = best.max(_ball_sq(ap))
    if not s < ee:
        best = best.max(_ball_sq([y - x for x, y in zip(b, p)]))
    return best


def _ball_one_sided(pa: list, pb: list):
    b0, b1 = pb[0], pb[-1]
    ee = _ball_sq([y - x for x, y in zip(b0, b1)])
    if not ee > 0:
        return None  # a closed or (in balls) degenerate chord: the exact route decides
    a_part = _ball_top(_ball_dist_segment_sq(q, b0, b1, ee) for q in pa)
    if len(pb) <= 2:
        return a_part, flint.arb(0)
    delta = _ball_top(_ball_sq([y - x for x, y in zip(b0, q)]) - _ball_dot(q, b0, b1) ** 2 / ee for q in pb[1:-1])
    return a_part, delta


def _ball_dot(q, b0, b1) -> flint.arb:
    return sum(((y - x) * (z - x) for x, y, z in zip(b0, q, b1)), flint.arb(0))


def _ball_top(values) -> flint.arb:
    best = None
    for v in values:
        best = v if best is None else best.max(v)
    return best


def ball_directed_bound(rows_a: list, rows_b: list) -> mpq | None:
    """:func:`directed_piece_bound` of two pieces given as ball rows; ``None`` when undecided
    (a degenerate chord in balls, or a ball reaching 0: see :func:`ball_piece_bound`)."""
    parts = _ball_one_sided(_ball_points(rows_a), _ball_points(rows_b))
    if parts is None:
        return None
    a_part, delta = parts
    value = a_part.nonnegative_part().sqrt() + delta.nonnegative_part().sqrt()
    if not value > 0:
        return None
    return ball.upper_rational(value)


def ball_piece_bound(rows_a: list, rows_b: list) -> mpq | None:
    """:func:`piece_bound` of two pieces given as ball rows; ``None`` when undecided.

    The same formula on balls containing the exact control points (python-flint ``arb``,
    :mod:`exactcagd.composition.ball`): the upper end of the result bounds the exact
    :func:`piece_bound`, hence ``H(A, B)``.  ``None`` also when the ball reaches 0: a square
    root of a ball around 0 costs ``sqrt(radius)``, and an exact zero bound (an iso-curve,
    reproduced exactly) should stay 0.
    """
    pa, pb = _ball_points(rows_a), _ball_points(rows_b)
    best = flint.arb(0)
    for x, y in ((pa, pb), (pb, pa)):
        parts = _ball_one_sided(x, y)
        if parts is None:
            return None
        a_part, delta = parts
        # squared distances are >= 0: their balls may reach below 0, sqrt takes the part >= 0
        best = best.max(a_part.nonnegative_part().sqrt() + delta.nonnegative_part().sqrt())
    if not best > 0:
        return None  # the exact bound may be 0 (e.g. an exact iso-curve): exact rationals give it exactly
    return ball.upper_rational(best)


# ---------------------------------------------------------------------- float helpers
def _float_hom(hom) -> np.ndarray:
    return np.vectorize(float, otypes=[float])(hom)


def _eval(hf: np.ndarray, ts) -> np.ndarray:
    ts = np.atleast_1d(np.asarray(ts, dtype=float))
    n = hf.shape[0] - 1
    s = 1.0 - ts
    level = np.broadcast_to(hf, (len(ts),) + hf.shape).copy()
    for _ in range(n):
        level = s[:, None, None] * level[:, :-1] + ts[:, None, None] * level[:, 1:]
    pts = level[:, 0, :]
    return pts[:, :-1] / pts[:, -1:]


def float_hausdorff(hom_a, hom_b, samples: int = 129) -> float:
    """Float estimate of ``H`` from dense samples (a heuristic, never a certificate)."""
    ts = np.linspace(0.0, 1.0, samples)
    pa, pb = _eval(_float_hom(hom_a), ts), _eval(_float_hom(hom_b), ts)
    d = np.sqrt(((pa[:, None, :] - pb[None, :, :]) ** 2).sum(-1))
    return float(max(_seg_dist(pa, pb).max(), _seg_dist(pb, pa).max())) if samples > 1 else float(d.min())


def _seg_dist(p: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Distance of each point of ``p`` to the polyline ``poly``."""
    a, b = poly[:-1], poly[1:]
    e = b - a
    ee = (e * e).sum(-1)
    ee[ee == 0] = 1e-300
    ap = p[:, None, :] - a[None, :, :]
    s = np.clip((ap * e[None]).sum(-1) / ee[None], 0, 1)
    foot = a[None] + s[..., None] * e[None]
    return np.sqrt(((p[:, None, :] - foot) ** 2).sum(-1)).min(1)


class _Footer:
    """Float foot points on ``B`` from a dense sample with parabolic refinement (a heuristic)."""

    def __init__(self, hf_b: np.ndarray, samples: int = 1025):
        self.ts = np.linspace(0.0, 1.0, samples)
        self.pts = _eval(hf_b, self.ts)
        self.h = 1.0 / (samples - 1)

    def __call__(self, point: np.ndarray, lo: float, hi: float) -> float:
        i0 = int(np.floor(lo / self.h))
        i1 = int(np.ceil(hi / self.h)) + 1
        d = ((self.pts[i0:i1] - point) ** 2).sum(-1)
        k = int(np.argmin(d))
        t = self.ts[i0 + k]
        if 0 < k < len(d) - 1:
            a, b, c = d[k - 1], d[k], d[k + 1]
            den = a - 2 * b + c
            if den > 0:
                t += 0.5 * self.h * (a - c) / den
        return float(min(max(t, lo), hi))


def _dyadic(x: float, lo: mpq, hi: mpq, bits: int = 40) -> mpq:
    q = mpq(int(round(x * 2**bits)), 2**bits)
    if not (lo < q < hi):
        q = (lo + hi) / 2
    return q


def hausdorff_bound(hom_a, hom_b, limit, pieces: int = 4, max_pieces: int = 512, stats: dict | None = None):
    """Certified rational upper bound ``<= limit`` of ``H(A, B)``, or ``None``.

    ``None`` means "not certified below ``limit``" (the caller subdivides); it is
    returned at once when the float estimate already exceeds ``limit``.  Each piece bound
    is evaluated in ball arithmetic first and in exact arithmetic only when the ball's
    upper end exceeds ``limit``; ``stats`` (a dict) counts which decided
    (``{"ball": n, "exact": m}``, :mod:`exactcagd.composition.ball`).
    """
    with ball.precision():
        bound = _hausdorff_bound(hom_a, hom_b, limit, pieces, max_pieces, stats)
        if bound is None:
            bound = _unpaired_bound(hom_a, hom_b, limit, pieces, max_pieces, stats)
        return bound


def _unpaired_bound(hom_a, hom_b, limit, pieces, max_pieces, stats):
    """``max(h(A -> B), h(B -> A))`` bounded one direction at a time, or ``None``.

    The paired route cuts both curves monotonically, so its bound tends to the Fréchet
    distance, which can exceed ``H`` by far (two arcs bulging to opposite sides: the foot
    point of ``A(t)`` on ``B`` jumps).  Here each direction is certified on its own:
    ``h(A_i -> B) <= h(A_i -> W)`` for *any* window ``W`` of ``B``, so every piece of ``A``
    only needs one window of ``B`` (no monotonicity, no covering of ``B``).
    """
    limit = to_rational(limit, where="limit")
    if float_hausdorff(hom_a, hom_b, 33) > to_float(limit) * (1 + 1e-9):
        return None
    first = _directed_bound(hom_a, hom_b, limit, pieces, max_pieces, stats)
    if first is None:
        return None
    second = _directed_bound(hom_b, hom_a, limit, pieces, max_pieces, stats)
    return None if second is None else max(first, second)


def _window(f: float, half: float) -> tuple:
    """Dyadic window ``[lo, hi]`` of ``[0, 1]`` around the float parameter ``f`` (``lo < hi``)."""
    scale = 2**40
    lo = max(0, int(np.floor((f - half) * scale)))
    hi = min(scale, int(np.ceil((f + half) * scale)))
    if hi <= lo:
        lo, hi = (hi - 1, hi) if hi > 0 else (0, 1)
    return mpq(lo, scale), mpq(hi, scale)


def _directed_bound(hom_a, hom_b, limit, pieces, max_pieces, stats):
    """Certified upper bound ``<= limit`` of ``h(A -> B)``, or ``None``.

    Each piece ``A_i`` tries windows of ``B`` around the float foot points of its two ends
    and midpoint (global nearest samples of ``B``), each wide enough for ``B`` to travel
    twice the chord of ``A_i``, and the window spanning all three feet; a piece that no
    window certifies is bisected (windows shrink with it, the bound tends to
    ``max dist(p, B)``).
    """
    hf_a, hf_b = _float_hom(hom_a), _float_hom(hom_b)
    foot = _Footer(hf_b)
    speeds = np.sqrt((np.diff(foot.pts, axis=0) ** 2).sum(-1)) / foot.h
    balls_a, balls_b = _ball_rows(hom_a), _ball_rows(hom_b)
    stack = [(mpq(i, pieces), mpq(i + 1, pieces)) for i in range(pieces)]
    count, best = len(stack), mpq(0)
    while stack:
        ta, tb = stack.pop()
        ends = _eval(hf_a, [float(ta), float((ta + tb) / 2), float(tb)])
        feet = [foot(p, 0.0, 1.0) for p in ends]
        chord = float(np.sqrt(((ends[2] - ends[0]) ** 2).sum()))
        windows = []
        for f in feet:
            speed = speeds[min(int(f / foot.h), len(speeds) - 1)]
            windows.append(_window(f, min(1.0, max(2 * chord / max(speed, 1e-300), 2.0**-30))))
        windows.append((min(w[0] for w in windows), max(w[1] for w in windows)))
        bound = _certify_window(hom_a, hom_b, balls_a, balls_b, (ta, tb), windows, limit, stats)
        if bound is not None:
            best = max(best, bound)
            continue
        if count >= max_pieces:
            return None
        tm = (ta + tb) / 2
        stack += [(ta, tm), (tm, tb)]
        count += 1
    return best


def _certify_window(hom_a, hom_b, balls_a, balls_b, piece, windows, limit, stats):
    """The first window's one-sided bound ``<= limit`` (balls first, then exact), or ``None``."""
    ta, tb = piece
    if balls_a is not None and balls_b is not None:
        rows_a = _ball_restrict(balls_a, ta, tb)
        for sa, sb in windows:
            quick = ball_directed_bound(rows_a, _ball_restrict(balls_b, sa, sb))
            if quick is not None and quick <= limit:
                ball.count(stats, ball.BALL)
                return quick
    piece_a = restrict_fast(hom_a, ta, tb)
    for sa, sb in windows:
        bound = directed_piece_bound(piece_a, restrict_fast(hom_b, sa, sb))
        if bound <= limit:
            ball.count(stats, ball.EXACT)
            return bound
    return None


def _hausdorff_bound(hom_a, hom_b, limit, pieces, max_pieces, stats):
    limit = to_rational(limit, where="limit")
    hf_a, hf_b = _float_hom(hom_a), _float_hom(hom_b)
    if float_hausdorff(hom_a, hom_b, 33) > to_float(limit) * (1 + 1e-9):
        return None
    foot = _Footer(hf_b)

    def hom_b_at(t):
        return bz.de_casteljau(hom_b, t)

    ts = [mpq(i, pieces) for i in range(pieces + 1)]
    taus = [mpq(0)]
    for t in ts[1:-1]:
        point = _eval(hf_a, [float(t)])[0]
        taus.append(_dyadic(foot(point, float(taus[-1]), 1.0), taus[-1], mpq(1)))
    taus.append(mpq(1))
    stack = list(zip(zip(ts[:-1], ts[1:]), zip(taus[:-1], taus[1:])))
    count = len(stack)
    best = mpq(0)
    balls_a, balls_b = _ball_rows(hom_a), _ball_rows(hom_b)
    while stack:
        (ta, tb), (sa, sb) = stack.pop()
        if balls_a is not None and balls_b is not None and sa < sb:
            quick = ball_piece_bound(_ball_restrict(balls_a, ta, tb), _ball_restrict(balls_b, sa, sb))
            if quick is not None and quick <= limit:
                best = max(best, quick)
                ball.count(stats, ball.BALL)
                continue
        piece_b = restrict_fast(hom_b, sa, sb) if sa < sb else np.array([hom_b_at(sa)] * 2, dtype=object)
        bound = piece_bound(restrict_fast(hom_a, ta, tb), piece_b)
        if bound <= limit:
            best = max(best, bound)
            ball.count(stats, ball.EXACT)
            continue
        if count >= max_pieces:
            return None
        tm = (ta + tb) / 2
        point = _eval(hf_a, [float(tm)])[0]
        sm = _dyadic(foot(point, float(sa), float(sb)), sa, sb) if sa < sb else sa
        stack.append(((ta, tm), (sa, sm)))
        stack.append(((tm, tb), (sm, sb)))
        count += 1
    return best

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
integer square roots.  For rational pieces the same formula is evaluated first for all
pieces of a bisection level at once in outward-rounded binary64 intervals
(:func:`float_piece_bounds`), then, for a piece the interval leaves undecided (the limit
inside it), in ball arithmetic (python-flint ``arb``; :func:`ball_piece_bound`), and
exactly only when the ball does not decide either.  An enclosure decides both ways: its
upper end below the limit certifies the piece, its lower end above the limit proves the
exact bound exceeds it (the piece is bisected), so the pieces accepted are those of the
exact formula.  The bound returned is the largest ball (else exact) piece bound of the
pieces that can attain it (:class:`Certified`).

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

__all__ = ["hausdorff_bound", "hausdorff_certificate", "Certified", "may_attain", "piece_bound", "directed_piece_bound", "ball_piece_bound", "ball_directed_bound", "sqrt_upper", "upper", "float_hausdorff"]


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
    value = _ball_piece_value(rows_a, rows_b)
    return None if value is None else ball.upper_rational(value)


def _ball_piece_value(rows_a: list, rows_b: list) -> flint.arb | None:
    """The ball of :func:`ball_piece_bound` (it contains the exact formula value), or ``None``."""
    pa, pb = _ball_points(rows_a), _ball_points(rows_b)
    best = flint.arb(0)
    for x, y in ((pa, pb), (pb, pa)):
        parts = _ball_one_sided(x, y)
        if parts is None:
            return None
        a_part, delta = parts
        # squared distances are >= 0: their balls may reach below 0, sqrt takes the part >= 0
        best = best.max(a_part.nonnegative_part().sqrt() + delta.nonnegative_part().sqrt())
    if not best > 0 or not best.is_finite():
        return None  # the exact bound may be 0 (e.g. an exact iso-curve): exact rationals give it exactly
    return best


# ---------------------------------------------------------------------- binary64 enclosures
# The piece bound of many pieces at once, in binary64 interval arithmetic.  An interval is
# an array ``X`` of shape ``(2, ...)`` holding ``(-lo, hi)``: both ends are then rounded
# outward by one ``nextafter(., +inf)`` (the rounding error of ``+ - * /`` and ``sqrt``
# is at most half the spacing at the result, Sederberg's notes (13.4)-(13.5), so the next
# float up bounds the exact result; ``-lo`` rounded up is ``lo`` rounded down).  Like an
# ``arb`` ball, the interval decides only when the threshold lies outside it; otherwise
# the ball route and then exact rationals decide.

#: Unit roundoff of binary64 (round to nearest).
_U = 2.0**-53
#: Absolute radius covering underflow (each product's error ``<= 2^-1075``, Sederberg (13.4)).
_FLOAT_ABS = 2.0**-1000
_FLOAT_MAX_DEGREE = 1000
_DYADIC_FLOAT = 2**53
_SIGNS = np.array([[1.0, -1.0], [-1.0, 1.0]])
_NEG = np.array([-1.0, 1.0])


def _up(x):
    return np.nextafter(x, np.inf)


def _col(sign, ndim):
    return sign.reshape(sign.shape + (1,) * ndim)


def _iadd(a, b):
    return _up(a + b)


def _isub(a, b):
    return _up(a + b[::-1])  # -lo = -lo_a + hi_b, hi = hi_a - lo_b


def _pair(neg_lo, hi):
    """``(-lo, hi)`` rounded outward."""
    out = np.empty((2,) + np.shape(hi))
    out[0] = neg_lo
    out[1] = hi
    return _up(out)


def _imul(a, b):
    # the four products lo_a lo_b, lo_a hi_b, hi_a lo_b, hi_a hi_b
    q = (a[:, None] * b[None, :]) * _col(_SIGNS, a.ndim - 1)
    q = q.reshape((4,) + q.shape[2:])
    return _pair(-q.min(axis=0), q.max(axis=0))


def _isqr(a):
    # |x| over the interval lies in [max(lo, -hi, 0), max(-lo, hi)]; square both, -lo first
    out = np.empty_like(a)
    np.maximum(np.maximum(-a[0], -a[1]), 0.0, out=out[0])
    np.maximum(a[0], a[1], out=out[1])
    out *= out
    np.negative(out[0], out=out[0])
    return _up(out)


def _idiv_pos(a, b):
    """``a / b`` for ``b`` with a positive lower end (the caller masks the other entries)."""
    ends = b * _col(_NEG, b.ndim - 1)  # lo_b, hi_b
    return _up((a[:, None] / ends[None, :]).max(axis=1))


def _isqrt(a):
    sign = _col(_NEG, a.ndim - 1)
    return _up(np.sqrt(np.maximum(a * sign, 0.0)) * sign)


def _icoords(a):
    """Sum over the last axis (two coordinates)."""
    return _up(a[..., 0] + a[..., 1])


def _float_net(hom, hf: np.ndarray | None = None) -> np.ndarray | None:
    """``(values, |values|)`` of a rational homogeneous array in binary64, ``None`` if an entry is
    not rational, the curve is not planar or of too high a degree, or a value is not finite."""
    if hom.shape[1] != 3 or hom.shape[0] - 1 > _FLOAT_MAX_DEGREE:
        return None
    if not all(isinstance(x, (type(mpq(0)), int)) for x in hom.flat):
        return None
    mid = _float_hom(hom) if hf is None else hf  # each entry within one ulp of the exact value
    if not np.isfinite(mid).all():
        return None
    return np.stack([mid, np.abs(mid)])


def _float_ends(values) -> np.ndarray | None:
    """Parameters as binary64 numbers with ``1 - t`` exact (dyadic, denominator ``<= 2^53``),
    or ``None`` if one is not."""
    for q in values:
        d = mpq(q).denominator
        if d > _DYADIC_FLOAT or d & (d - 1):
            return None
    return np.array([float(q) for q in values])


def _float_restrict(net: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Intervals of the control points of ``N`` restrictions ``[a_k, b_k]`` of a Bézier net.

    Restricted point ``i`` is the blossom ``b(a, .., a, b, .., b)`` (``n - i`` times ``a``):
    ``n`` de Casteljau levels, level ``r`` at ``a`` for ``r < n - i`` and at ``b`` otherwise,
    all of them at once.  With ``a, b`` binary64 numbers for which ``1 - a``, ``1 - b`` are
    exact, every level is ``fl(fl((1 - t) x) + fl(t y))`` with non-negative weights, so
    (Higham, Lemma 3.1, one more factor for the conversion of the input, within one ulp)
    ``|computed - exact| <= gamma_{2n+2} sum_j M_ij |x_j|``, where ``M_ij >= 0`` are the
    blossom weights; the same recursion on ``|x|`` computes that sum ``A`` up to a factor
    ``(1 + theta_2n)`` and the conversion's ``(1 - 2u)``.  For ``n <= 1000``,
    ``gamma_{2n+2} / ((1 - gamma_{2n}) (1 - 2u)) < 1.00001 (2n + 2) u``: the radius
    ``(4n + 4) u A`` holds it with a factor 2 to spare, which also covers the rounding of
    the radius itself.  Returns ``(-lo, hi)`` of shape ``(2, N, n + 1, 3)``.
    """
    n = net.shape[1] - 1
    N = len(a)
    i = np.arange(n + 1)
    level = np.broadcast_to(net[:, None, None], (2, N, n + 1, n + 1, net.shape[-1]))
    # parameter of level r for restricted point i: a while r < n - i, then b
    t = np.where(np.arange(n)[:, None, None] < n - i[None, None, :], a[None, :, None], b[None, :, None])
    t = t[:, None, :, :, None, None]
    s = 1.0 - t
    for r in range(n):
        level = s[r] * level[:, :, :, :-1] + t[r] * level[:, :, :, 1:]
    mid, size = level[0, :, :, 0], level[1, :, :, 0]
    rad = _up(size * ((4 * n + 4) * _U) + _FLOAT_ABS)
    return _pair(rad - mid, mid + rad)


def _float_points(net, a, b, count: int):
    """Intervals of the projected control points, shape ``(2, N, count, 2)`` (the last point
    repeated up to ``count``), and a mask of the pieces whose weights are positive."""
    hom = _float_restrict(net, a, b)
    if hom.shape[2] < count:
        hom = np.concatenate([hom, np.repeat(hom[:, :, -1:], count - hom.shape[2], axis=2)], axis=2)
    w = hom[..., 2:]
    ok = (w[0, ..., 0] < 0).all(axis=1)  # -lo < 0: lo > 0
    w = np.where(w[0] < 0, w, _col(_NEG, w.ndim - 1))
    return _idiv_pos(hom[..., :2], w), ok


def _float_directed(pa: np.ndarray, pb: np.ndarray):
    """Interval of ``max_k dist(Q^A_k, [b_0, b_1]) + delta_B`` for piece pairs at once (rows of
    ``pa``, ``pb``: intervals of shape ``(2, N, points, 2)``), and a mask of the rows where
    the chord is not degenerate in intervals.

    The distance to the chord's line is taken as ``|cross(q - b_0, e)| / |e|`` (``= |q - b_0|^2
    - ((q - b_0).e)^2 / |e|^2`` by Lagrange's identity, the exact code's form, with far less
    cancellation).
    """
    b0, b1 = pb[:, :, :1], pb[:, :, -1:]
    e = _isub(b1, b0)
    ee = _icoords(_isqr(e))
    ok = ee[0, :, 0] < 0
    ee = np.where(ee[0] < 0, ee, _col(_NEG, ee.ndim - 1))
    count = pa.shape[2]
    inner_b = pb.shape[2] > 2
    # A's points and B's inner points share the chord: one pass for the distances to its line
    q = np.concatenate([pa, pb[:, :, 1:-1]], axis=2) if inner_b else pa
    aq = _isub(q, b0)
    ap, bp = aq[:, :, :count], _isub(pa, b1)
    s = _icoords(_imul(ap, e))
    near = _icoords(_isqr(np.concatenate([ap, bp], axis=2)))
    near0, near1 = near[:, :, :count], near[:, :, count:]  # s <= 0: nearest b_0; s >= |e|^2: b_1
    cross = _imul(aq, e[..., ::-1])  # q_x e_y, q_y e_x
    line = _idiv_pos(_isqr(_isub(cross[..., :1], cross[..., 1:])[..., 0]), ee)
    inner = line[:, :, :count]
    s_lo, s_hi, ee_lo, ee_hi = -s[0], s[1], -ee[0], ee[1]
    # the exact value is one of the three cases; take the cases the intervals do not exclude
    m0, m1, m2 = s_lo <= 0, s_hi >= ee_lo, (s_hi > 0) & (s_lo < ee_hi)
    neg_lo = np.minimum(np.minimum(np.where(m0, near0[0], np.inf), np.where(m1, near1[0], np.inf)), np.where(m2, inner[0], np.inf))
    hi = np.maximum(np.maximum(np.where(m0, near0[1], -np.inf), np.where(m1, near1[1], -np.inf)), np.where(m2, inner[1], -np.inf))
    neg_lo, hi = neg_lo.min(axis=1), hi.max(axis=1)
    a_part = _pair(neg_lo, hi)
    if inner_b:
        d = line[:, :, count:]
        delta = _pair(d[0].min(axis=1), d[1].max(axis=1))
    else:
        delta = np.zeros_like(a_part)
    return _iadd(_isqrt(a_part), _isqrt(delta)), ok


def float_piece_bounds(net_a, net_b, ta, tb, sa, sb):
    """Intervals ``(lo, hi)`` containing the :func:`piece_bound` formula value of the pieces
    ``A[ta_k, tb_k]``, ``B[sa_k, sb_k]`` (``NaN`` where undecided), all pieces at once.

    The module's fat-line piece bound (Yang et al. (004) section 5, derivation in
    ``proofs/yang_hausdorff.py``) in outward-rounded binary64 intervals.  ``net_a``,
    ``net_b`` from :func:`_float_net`; parameters are binary64 numbers with ``1 - t``
    exact (dyadic, :func:`_float_ends`).

    >>> import numpy as np
    >>> from exactcagd import BezierCurve
    >>> a = BezierCurve([[0, 0], ["1/2", 0], [1, 0]]).homogeneous()
    >>> b = BezierCurve([[0, "3/1000"], [1, "3/1000"]]).homogeneous()   # H(A, B) = 3/1000
    >>> ends = np.array([0.0]), np.array([1.0])
    >>> lo, hi = float_piece_bounds(_float_net(a), _float_net(b), *ends, *ends)
    >>> bool(lo[0] <= 0.003 <= hi[0] and hi[0] - lo[0] < 1e-15)
    True
    """
    count = max(net_a.shape[1], net_b.shape[1])
    with np.errstate(all="ignore"):
        pa, ok_a = _float_points(net_a, ta, tb, count)
        pb, ok_b = _float_points(net_b, sa, sb, count)
        # both directions in one pass: rows A -> B, then B -> A
        value, ok = _float_directed(np.concatenate([pa, pb], axis=1), np.concatenate([pb, pa], axis=1))
        N = len(ta)
        lo = np.maximum(-value[0, :N], -value[0, N:])
        hi = np.maximum(value[1, :N], value[1, N:])
        good = ok_a & ok_b & ok[:N] & ok[N:] & np.isfinite(lo) & np.isfinite(hi)
    return np.where(good, lo, np.nan), np.where(good, hi, np.nan)


# ---------------------------------------------------------------------- float helpers
def _float_hom(hom) -> np.ndarray:
    return np.array([[float(x) for x in row] for row in hom], dtype=float).reshape(hom.shape)


def _eval(hf: np.ndarray, ts) -> np.ndarray:
    ts = np.atleast_1d(np.asarray(ts, dtype=float))
    n = hf.shape[0] - 1
    s = 1.0 - ts
    level = hf.T[:, :, None]  # (coordinate, control point, parameter): the parameters innermost
    for _ in range(n):
        level = s * level[:, :-1] + ts * level[:, 1:]
    pts = np.broadcast_to(level[:, 0], (hf.shape[1], len(ts)))
    return (pts[:-1] / pts[-1:]).T


def float_hausdorff(hom_a, hom_b, samples: int = 129) -> float:
    """Float estimate of ``H`` from dense samples (a heuristic, never a certificate)."""
    return _float_estimate(_float_hom(hom_a), _float_hom(hom_b), samples)


def _float_estimate(hf_a: np.ndarray, hf_b: np.ndarray, samples: int) -> float:
    ts = np.linspace(0.0, 1.0, samples)
    pa, pb = _eval(hf_a, ts), _eval(hf_b, ts)
    if samples <= 1:
        return float(np.sqrt(((pa[:, None, :] - pb[None, :, :]) ** 2).sum(-1)).min())
    both = _seg_dist(np.stack([pa, pb]), np.stack([pb, pa]))  # A -> B and B -> A in one pass
    return float(max(both[0].max(), both[1].max()))


def _seg_dist(p: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Distance of each planar point of ``p`` to the polyline ``poly`` (leading axes: a batch)."""
    ax, ay = poly[..., :-1, 0], poly[..., :-1, 1]
    ex, ey = poly[..., 1:, 0] - ax, poly[..., 1:, 1] - ay
    ee = ex * ex + ey * ey
    ee[ee == 0] = 1e-300
    ax, ay, ex, ey, ee = (x[..., None, :] for x in (ax, ay, ex, ey, ee))
    px, py = p[..., :, 0, None], p[..., :, 1, None]
    s = np.minimum(np.maximum(((px - ax) * ex + (py - ay) * ey) / ee, 0.0), 1.0)
    gx, gy = px - (ax + s * ex), py - (ay + s * ey)
    return np.sqrt((gx * gx + gy * gy).min(-1))  # sqrt is monotone and correctly rounded: min first


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

    def many(self, points: np.ndarray, los: np.ndarray, his: np.ndarray) -> np.ndarray:
        """``[self(p, lo, hi) for ...]`` in one pass (the same float operations, the same values)."""
        i0 = np.floor(los / self.h).astype(np.int64)
        i1 = np.minimum(np.ceil(his / self.h).astype(np.int64) + 1, len(self.ts))  # slice ends, clipped
        first, last = int(i0.min()), int(i1.max())  # only the samples some window holds
        dx = self.pts[None, first:last, 0] - points[:, 0, None]
        dy = self.pts[None, first:last, 1] - points[:, 1, None]
        d = dx * dx + dy * dy  # ((pts - point) ** 2).sum(-1), the same operations
        index = np.arange(first, last)
        inside = (index[None, :] >= i0[:, None]) & (index[None, :] < i1[:, None])
        k = np.argmin(np.where(inside, d, np.inf), axis=1)
        j = k + first
        t = self.ts[j].copy()
        rows = np.arange(len(j))
        interior = (j > i0) & (j < i1 - 1)
        a = d[rows, np.maximum(k - 1, 0)]
        b = d[rows, k]
        c = d[rows, np.minimum(k + 1, last - first - 1)]
        den = a - 2 * b + c
        step = interior & (den > 0)
        with np.errstate(all="ignore"):
            t[step] += 0.5 * self.h * (a[step] - c[step]) / den[step]
        return np.minimum(np.maximum(t, los), his)


def _dyadic(x: float, lo: mpq, hi: mpq, bits: int = 40) -> mpq:
    q = mpq(int(round(x * 2**bits)), 2**bits)
    if not (lo < q < hi):
        q = (lo + hi) / 2
    return q


class Certified:
    """A certified bound of ``H(A, B)`` known first as an interval: ``lower <= value() <= upper``.

    ``upper`` is itself a certified upper bound (``<= limit``); :meth:`value` is the bound
    the piece-by-piece route gives (each piece's ball bound, else its exact one), computed
    on first use for the pieces that can attain the maximum.  A caller that only needs the
    largest of many bounds refines only the candidates (:func:`exactcagd.curves_on_surfaces.driver`).
    """

    __slots__ = ("lower", "upper", "_refine", "_value")

    def __init__(self, lower: mpq, upper: mpq, refine=None):
        self.lower, self.upper, self._refine, self._value = lower, upper, refine, None
        if refine is None:
            self._value = upper

    def value(self) -> mpq:
        if self._value is None:
            self._value = self._refine()
            self._refine = None
        return self._value


def hausdorff_bound(hom_a, hom_b, limit, pieces: int = 4, max_pieces: int = 512, stats: dict | None = None):
    """Certified rational upper bound ``<= limit`` of ``H(A, B)``, or ``None``.

    ``None`` means "not certified below ``limit``" (the caller subdivides); it is
    returned at once when the float estimate already exceeds ``limit``.  Each piece bound
    is evaluated in ball arithmetic first and in exact arithmetic only when the ball's
    upper end exceeds ``limit``; ``stats`` (a dict) counts which decided
    (``{"ball": n, "exact": m}``, :mod:`exactcagd.composition.ball`).  "ball" counts every
    enclosure decision: binary64 intervals for all pieces of a bisection level at once
    (:func:`float_piece_bounds`), else an ``arb`` ball per piece.
    """
    cert = hausdorff_certificate(hom_a, hom_b, limit, pieces, max_pieces, stats)
    return None if cert is None else cert.value()


def hausdorff_certificate(hom_a, hom_b, limit, pieces: int = 4, max_pieces: int = 512, stats: dict | None = None):
    """:func:`hausdorff_bound` as a :class:`Certified` (its value computed on demand), or ``None``.

    >>> from exactcagd import BezierCurve
    >>> a = BezierCurve([[0, 0], ["1/2", "1/4"], [1, 0]]).homogeneous()   # apex height 1/8
    >>> b = BezierCurve([[0, 0], [1, 0]]).homogeneous()
    >>> c = hausdorff_certificate(a, b, "1/2")
    >>> bool(c.lower <= c.value() <= c.upper <= mpq(1, 2)), bool(c.value() >= mpq(1, 8))
    (True, True)
    """
    limit = to_rational(limit, where="limit")
    hf_a, hf_b = _float_hom(hom_a), _float_hom(hom_b)
    if _float_estimate(hf_a, hf_b, 33) > to_float(limit) * (1 + 1e-9):
        return None
    with ball.precision():
        cert = _hausdorff_bound(hom_a, hom_b, limit, pieces, max_pieces, stats, hf_a, hf_b)
        if cert is None:
            bound = _unpaired_bound(hom_a, hom_b, limit, pieces, max_pieces, stats)
            cert = None if bound is None else Certified(bound, bound)
        return cert


def _unpaired_bound(hom_a, hom_b, limit, pieces, max_pieces, stats):
    """``max(h(A -> B), h(B -> A))`` bounded one direction at a time, or ``None``.

    The paired route cuts both curves monotonically, so its bound tends to the Fréchet
    distance, which can exceed ``H`` by far (two arcs bulging to opposite sides: the foot
    point of ``A(t)`` on ``B`` jumps).  Here each direction is certified on its own:
    ``h(A_i -> B) <= h(A_i -> W)`` for *any* window ``W`` of ``B``, so every piece of ``A``
    only needs one window of ``B`` (no monotonicity, no covering of ``B``).
    """
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


def _float_limits(limit: mpq) -> tuple[float, float]:
    """Binary64 numbers ``lo <= limit <= hi`` (adjacent, or equal when ``limit`` is a float;
    ``(largest float, inf)`` past the float range)."""
    try:
        f = float(limit)
    except OverflowError:
        f = np.inf
    if f == np.inf:
        return float(np.finfo(float).max), np.inf
    lo = f if mpq(f) <= limit else float(np.nextafter(f, -np.inf))
    hi = f if mpq(f) >= limit else float(np.nextafter(f, np.inf))
    return lo, hi


class _PairedPieces:
    """The per-piece decision of the paired route: ball first, exact rationals if undecided."""

    def __init__(self, hom_a, hom_b, limit):
        self.hom_a, self.hom_b, self.limit = hom_a, hom_b, limit
        self._balls = None

    def balls(self):
        if self._balls is None:
            self._balls = (_ball_rows(self.hom_a), _ball_rows(self.hom_b))
        return self._balls

    def bound(self, piece, stats) -> mpq | None:
        """The piece's bound if it is ``<= limit``, else ``None`` (counted in ``stats``)."""
        (ta, tb), (sa, sb) = piece
        balls_a, balls_b = self.balls()
        if balls_a is not None and balls_b is not None and sa < sb:
            value = _ball_piece_value(_ball_restrict(balls_a, ta, tb), _ball_restrict(balls_b, sa, sb))
            if value is not None:
                quick = ball.upper_rational(value)
                if quick is not None and quick <= self.limit:
                    ball.count(stats, ball.BALL)
                    return quick
                if value.lower() > self.to_arb_limit():
                    return None  # the exact bound is >= the exact formula value > limit
        if sa < sb:
            piece_b = restrict_fast(self.hom_b, sa, sb)
        else:
            piece_b = np.array([bz.de_casteljau(self.hom_b, sa)] * 2, dtype=object)
        bound = piece_bound(restrict_fast(self.hom_a, ta, tb), piece_b)
        if bound <= self.limit:
            ball.count(stats, ball.EXACT)
            return bound
        return None

    def to_arb_limit(self):
        return ball.to_arb(self.limit)


def _hausdorff_bound(hom_a, hom_b, limit, pieces, max_pieces, stats, hf_a, hf_b):
    """The paired route, one bisection level at a time.

    All pieces of a level are first bounded in binary64 intervals (:func:`float_piece_bounds`);
    a piece whose interval lies below ``limit`` is accepted, one above is bisected, and the
    others are decided piece by piece (:class:`_PairedPieces`: ball, then exact).  The tree
    of pieces is the one of a piece-by-piece bisection (each piece's fate and its children
    depend on the piece alone), so the accepted pieces are the same; the returned bound is
    the largest of their ball/exact bounds, computed for the pieces that can attain it.
    """
    foot = _Footer(hf_b)
    ts = [mpq(i, pieces) for i in range(pieces + 1)]
    taus = [mpq(0)]
    for point in _eval(hf_a, [float(t) for t in ts[1:-1]]):
        taus.append(_dyadic(foot(point, float(taus[-1]), 1.0), taus[-1], mpq(1)))
    taus.append(mpq(1))
    level = list(zip(zip(ts[:-1], ts[1:]), zip(taus[:-1], taus[1:])))
    count = len(level)
    best = mpq(0)
    exact = _PairedPieces(hom_a, hom_b, limit)
    net_a, net_b = _float_net(hom_a, hf_a), _float_net(hom_b, hf_b)
    lim_lo, lim_hi = _float_limits(limit)
    accepted = []  # (lo, hi, piece) decided by binary64 intervals
    while level:
        lo, hi = _level_bounds(net_a, net_b, level)
        failed = []
        for k, piece in enumerate(level):
            if hi[k] <= lim_lo:
                accepted.append((lo[k], hi[k], piece))
                ball.count(stats, ball.BALL)
                continue
            if not lo[k] > lim_hi:  # undecided in binary64
                bound = exact.bound(piece, stats)
                if bound is not None:
                    best = max(best, bound)
                    continue
            if count >= max_pieces:
                return None
            failed.append(piece)
            count += 1
        level = _bisect(failed, hf_a, foot)
    if not accepted:
        return Certified(best, best)
    lower = max(mpq(max(x[0] for x in accepted)), best)
    upper = max(mpq(max(x[1] for x in accepted)), best)

    def refine():
        value = best
        with ball.precision():  # called later, outside the caller's precision context
            for lo_k, hi_k, piece in accepted:
                if may_attain(mpq(hi_k), lower):
                    bound = exact.bound(piece, None)
                    value = max(value, mpq(hi_k) if bound is None else bound)
        return value

    return Certified(lower, upper, refine)


def may_attain(upper: mpq, top: mpq) -> bool:
    """Whether a bound known to lie below ``upper`` may be the largest of bounds one of which
    is ``>= top`` (a margin of ``2^-20`` relative, ``2^-60`` absolute, far above the slack of
    the ball and exact bounds against the formula value, ``<= 2^-64 (1 + value)``)."""
    return upper >= top * (1 - mpq(1, 2**20)) - mpq(1, 2**60)



def _level_bounds(net_a, net_b, level):
    """:func:`float_piece_bounds` of the pieces of a level (``NaN`` where they do not apply)."""
    nan = np.full(len(level), np.nan)
    if net_a is None or net_b is None:
        return nan, nan
    usable = [k for k, (_, (sa, sb)) in enumerate(level) if sa < sb]
    if not usable:
        return nan, nan
    ends = [_float_ends([level[k][j][i] for k in usable]) for j in (0, 1) for i in (0, 1)]
    if any(x is None for x in ends):
        return nan, nan
    lo, hi = float_piece_bounds(net_a, net_b, *ends)
    out_lo, out_hi = nan.copy(), nan.copy()
    out_lo[usable], out_hi[usable] = lo, hi
    return out_lo, out_hi


def _bisect(failed, hf_a, foot):
    """Children of the failed pieces: ``A`` halved, ``B`` cut at the float foot point of ``A``'s
    midpoint (rounded to a dyadic, kept inside ``(sa, sb)``)."""
    if not failed:
        return []
    mids = [(ta + tb) / 2 for (ta, tb), _ in failed]
    points = _eval(hf_a, [float(t) for t in mids])
    open_ = [k for k, (_, (sa, sb)) in enumerate(failed) if sa < sb]
    feet = {}
    if open_:
        los = np.array([float(failed[k][1][0]) for k in open_])
        his = np.array([float(failed[k][1][1]) for k in open_])
        feet = dict(zip(open_, foot.many(points[open_], los, his)))
    out = []
    for k, ((ta, tb), (sa, sb)) in enumerate(failed):
        tm = mids[k]
        sm = _dyadic(float(feet[k]), sa, sb) if sa < sb else sa
        out.append(((ta, tm), (sa, sm)))
        out.append(((tm, tb), (sm, sb)))
    return out

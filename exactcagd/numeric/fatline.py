"""Fat lines and Bézier clipping on interval Bézier data (notes 7.7).

A *fat line* is the region between two parallel lines (7.7.1).  For a (rational,
positive-weight) curve ``Q`` and any line ``a x + b y + c = 0`` the signed values
``d_i = a x_i + b y_i + c`` of its control points bound ``Q`` between ``d_min`` and
``d_max`` (convex hull property, (7.6)-(7.7)).  The line need not be normalized
(``a^2 + b^2 = 1`` in (7.4) only makes ``d`` a Euclidean distance; any scale bounds
the same region), so ``a, b, c`` are plain floats and everything else is interval
arithmetic.

Clipping (7.7.2, 7.7.6): for ``P = sum w_i P_i B_i / sum w_i B_i`` the parameters where
``P`` lies beyond ``d_max`` are where ``sum w_i (a x_i + b y_i + c - d_max) B_i > 0``;
those below ``d_min`` where ``sum w_i (a x_i + b y_i + c - d_min) B_i < 0``.  (The
printed second condition reads ``+ d_min``; the sign is wrong — see the ledger,
proofs/sederberg_07_intersection.py.)  Each one-sided clip uses the chord rule of
7.7.8: the left clip value is the smallest t-intercept of the chords from ``E_0`` to
all the points ``E_i`` (those on the same side of the axis included: with only the
points across the axis the chord rule can overshoot the convex hull), the right clip
value the largest intercept of the chords from ``E_n``; both are rounded so that the
clip is never too big.

>>> import numpy as np
>>> e = np.array([-40.0, -56.0, -20.0, 96.0, 294.0])      # notes 7.7.8, L_min
>>> round(left_clip(-e), 4)                                  # clip where e < 0
0.1198
"""

from __future__ import annotations

import numpy as np

from . import enclose as iv

__all__ = ["left_clip", "right_clip", "fat_lines", "clip_range"]

_SHRINK = 1.0 - 16 * iv.U


def left_clip(g: np.ndarray) -> float | None:
    """Largest safe ``t0``: the explicit curve with coefficients ``>= g`` is ``> 0`` on [0, t0).

    ``g`` are lower bounds of the explicit Bézier curve ``(i/n, e_i)``.  Returns 0.0
    when ``g_0 <= 0`` (nothing to clip at the left), ``None`` when every ``g_i > 0``
    (the whole piece is clipped away).
    """
    n = len(g) - 1
    if not g[0] > 0:
        return 0.0
    if np.all(g > 0):
        return None
    # every chord from E_0 that goes down, also to points above the axis (the V_i of
    # 7.7.8 are formed with all E_i); chords to points below the axis only would
    # overshoot the hull crossing when an E_i above the axis is a hull vertex
    idx = np.nonzero(g[1:] < g[0])[0] + 1
    ts = (idx / n) * (g[0] / (g[0] - g[idx]))
    return min(float(np.min(ts)) * _SHRINK, 1.0)


def right_clip(g: np.ndarray) -> float | None:
    """Smallest safe ``t1``: the explicit curve with coefficients ``>= g`` is ``> 0`` on (t1, 1]."""
    t = left_clip(g[::-1])
    if t is None:
        return None
    return float(iv.up(1.0 - t)) if t > 0 else 1.0


def fat_lines(cart_lo: np.ndarray, cart_hi: np.ndarray):
    """The fat line parallel to ``Q_0 Q_n`` and the one perpendicular to it (7.7.1, 7.7.4).

    ``cart_lo/hi`` are interval Cartesian control points ``(n+1, 2)``.  Returns a list of
    ``(a, b, c, d_min, d_max)``: floats with ``d_min <= a x + b y + c <= d_max`` on the
    whole curve (empty when the curve's enclosure is not finite).
    """
    if not (np.all(np.isfinite(cart_lo)) and np.all(np.isfinite(cart_hi))):
        return []
    mid = 0.5 * (cart_lo + cart_hi)
    p0, pn = mid[0], mid[-1]
    dx, dy = pn[0] - p0[0], pn[1] - p0[1]
    if dx == 0.0 and dy == 0.0:  # closed piece: use the widest control point instead
        far = mid[np.argmax(np.abs(mid - p0).sum(axis=1))]
        dx, dy = far[0] - p0[0], far[1] - p0[1]
        if dx == 0.0 and dy == 0.0:
            dx, dy = 1.0, 0.0
    out = []
    for a, b in ((-dy, dx), (dx, dy)):
        c = -(a * p0[0] + b * p0[1])
        dlo, dhi = _line_values(cart_lo, cart_hi, a, b, c)
        out.append((a, b, c, float(dlo.min()), float(dhi.max())))
    return out


def _line_values(lo, hi, a, b, c):
    """Interval ``a x + b y + c`` for interval points (a, b, c exact floats)."""
    xl, xh = iv.iv_mul(lo[:, 0], hi[:, 0], a, a)
    yl, yh = iv.iv_mul(lo[:, 1], hi[:, 1], b, b)
    sl, sh = iv.iv_add(xl, xh, yl, yh)
    return iv.iv_add(sl, sh, c, c)


def _homogeneous_values(hom_lo, hom_hi, a, b, c, d):
    """Interval ``a X + b Y + (c - d) W`` for interval homogeneous points."""
    xl, xh = iv.iv_mul(hom_lo[:, 0], hom_hi[:, 0], a, a)
    yl, yh = iv.iv_mul(hom_lo[:, 1], hom_hi[:, 1], b, b)
    cd_lo, cd_hi = iv.iv_sub(np.float64(c), np.float64(c), np.float64(d), np.float64(d))
    wl, wh = iv.iv_mul(hom_lo[:, 2], hom_hi[:, 2], cd_lo, cd_hi)
    sl, sh = iv.iv_add(xl, xh, yl, yh)
    return iv.iv_add(sl, sh, wl, wh)


def clip_range(hom_lo: np.ndarray, hom_hi: np.ndarray, line) -> tuple[float, float] | None:
    """Parameter range of ``P`` (homogeneous interval coefficients) that can meet a fat line.

    Clips against each bounding line separately (7.7.6), which for polynomial curves
    gives the same range as the single explicit curve of 7.7.2.  Returns ``(t0, t1)``
    with ``0 <= t0 <= t1 <= 1`` or ``None`` when ``P`` misses the fat line.
    """
    a, b, c, dmin, dmax = line
    lo_max, _ = _homogeneous_values(hom_lo, hom_hi, a, b, c, dmax)  # > 0: beyond d_max
    _, hi_min = _homogeneous_values(hom_lo, hom_hi, a, b, c, dmin)  # < 0: below d_min
    t0, t1 = 0.0, 1.0
    for g in (lo_max, -hi_min):
        if not np.all(np.isfinite(g)):
            continue
        left = left_clip(g)
        right = right_clip(g)
        if left is None or right is None:
            return None
        t0, t1 = max(t0, left), min(t1, right)
    if t0 > t1:
        return None
    return t0, t1

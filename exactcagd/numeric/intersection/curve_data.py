"""Float interval data shared by the float routes: curve enclosures, pieces, fat-line clips.

The exact control points are enclosed in outward-rounded float intervals
(:mod:`exactcagd.numeric.enclose`); every piece of a curve carries interval
coefficients and an enclosure of its parameter range, so a region of parameter space
is discarded only when a rigorous test proves it holds no intersection (Sederberg's
notes 003, chapter 7).  :class:`_Guard` is the work bound every float route obeys:
when it runs out, what is left is handed to the exact route.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from gmpy2 import mpq

from ...errors import DegreeError, DimensionError, InputError, WeightError
from ...exact import bernstein as bz
from ...geometry.bezier_curve import BezierCurve
from .. import enclose as iv
from ..fatline import clip_range, fat_lines

U = iv.U


# =============================================================== curve data
class _Curve:
    """Float interval data of one exact planar curve (scaled exactly by powers of 2)."""

    def __init__(self, curve: BezierCurve, shift: int):
        hom = curve.homogeneous()
        w = hom[:, 2]
        if any(x <= 0 for x in w):
            if all(x < 0 for x in w):
                hom = -hom
            else:
                raise WeightError("curve intersection needs weights of one sign (the convex hull property)")
        wk = iv.power2_scale(hom[:, 2]) if curve.is_rational else 0  # W stays 1 for polynomials
        scale_xy, scale_w = mpq(2) ** (shift + wk), mpq(2) ** wk
        exact = np.empty_like(hom)
        exact[:, :2] = hom[:, :2] * scale_xy
        exact[:, 2] = hom[:, 2] * scale_w
        self.exact = exact
        self.rational = curve.is_rational
        self.n = curve.degree
        self.lo, self.hi = iv.enclose(exact)
        self.mid, self.rad = iv.midrad(self.lo, self.hi)
        self.scale = float(mpq(2) ** shift)
        # derivative data for the Krawczyk test
        if not self.rational:
            d = bz.derivative(exact[:, :2])
            self.dlo, self.dhi = iv.enclose(d)
        else:
            num, wt = exact[:, :2], exact[:, 2:3]
            d = bz.product(bz.derivative(num), wt) - bz.product(num, bz.derivative(wt))
            self.dlo, self.dhi = iv.enclose(d)
            self.w2lo, self.w2hi = iv.enclose(bz.product(wt, wt))

    # -------------------------------------------------------------- pieces
    def cart(self, lo, hi):
        """Interval Cartesian control points of interval homogeneous ones."""
        if not self.rational:
            return lo[:, :2], hi[:, :2]
        return iv.iv_div(lo[:, :2], hi[:, :2], lo[:, 2:3], hi[:, 2:3])

    def point(self, t: float):
        """Interval point at a float parameter (Horner in Bernstein form with error bound)."""
        value, bound = iv.horner_bound(self.mid, self.rad, t)
        lo, hi = iv.down(value - bound), iv.up(value + bound)
        if not self.rational:
            return lo[:2], hi[:2]
        return iv.iv_div(lo[:2], hi[:2], lo[2], hi[2])

    def point_float(self, t: float) -> tuple[float, float]:
        value, _ = iv.horner_bound(self.mid, self.rad, min(max(t, 0.0), 1.0))
        xy = value[:2] / value[2]
        return float(xy[0] / self.scale), float(xy[1] / self.scale)

    def range_derivative(self, a, b):
        """Interval enclosure of P'(s) for s in [a, b] (a < 0 or b > 1 allowed)."""
        dlo, dhi = iv.restrict(self.dlo, self.dhi, a, b)
        lo, hi = iv.hull(dlo, dhi)
        if not self.rational:
            return lo, hi
        wlo, whi = iv.hull(*iv.restrict(self.w2lo, self.w2hi, a, b))
        return iv.iv_div(lo, hi, wlo, whi)

    def value_at(self, s: float):
        """Interval point at a float parameter by interval de Casteljau (any real s)."""
        lo, hi = iv.evaluate(self.lo, self.hi, s)
        if not self.rational:
            return lo[:2], hi[:2]
        return iv.iv_div(lo[:2], hi[:2], lo[2], hi[2])


@dataclass
class _Piece:
    """A piece of a curve: interval coefficients and an enclosure of its parameter range."""

    lo: np.ndarray
    hi: np.ndarray
    a: tuple  # interval enclosing the exact left parameter
    b: tuple  # interval enclosing the exact right parameter

    @property
    def width(self) -> float:
        return self.b[1] - self.a[0]

    @property
    def span(self) -> tuple[float, float]:
        return self.a[0], self.b[1]

    def sub(self, u0: float, u1: float, curve: "_Curve") -> "_Piece":
        """A piece holding local [u0, u1]: float end parameters rounded outward, and the
        coefficients restricted from the whole curve (no error build-up, no widening
        of parameter enclosures from one clip to the next)."""
        A, B = self.a[0], self.b[1]
        width = B - A
        a = A if u0 <= 0.0 else max(A, float(iv.down(A + u0 * width - 4 * U * abs(A + u0 * width))))
        b = B if u1 >= 1.0 else min(B, float(iv.up(A + u1 * width + 4 * U * abs(A + u1 * width))))
        if b <= a:
            b = min(B, float(iv.up(a)))
        lo, hi = iv.restrict(curve.lo, curve.hi, a, b)
        return _Piece(lo, hi, (a, a), (b, b))


def _param(piece: _Piece, u: float) -> tuple:
    """Enclosure of the global parameter a + u (b - a) for exact local u."""
    if u == 0.0:
        return piece.a
    if u == 1.0:
        return piece.b
    wl, wh = iv.iv_sub(piece.b[0], piece.b[1], piece.a[0], piece.a[1])
    pl, ph = iv.iv_mul(wl, wh, u, u)
    lo, hi = iv.iv_add(pl, ph, piece.a[0], piece.a[1])
    return float(max(lo, 0.0)), float(min(hi, 1.0))


def _box(curve: _Curve, piece: _Piece):
    lo, hi = curve.cart(piece.lo, piece.hi)
    return lo.min(axis=0), hi.max(axis=0)


def _disjoint(b1, b2) -> bool:
    (l1, h1), (l2, h2) = b1, b2
    if not (np.all(np.isfinite(l1)) and np.all(np.isfinite(h1)) and np.all(np.isfinite(l2)) and np.all(np.isfinite(h2))):
        return False
    return bool(np.any(h1 < l2) or np.any(h2 < l1))


def _prepare(curve1, curve2) -> tuple[_Curve, _Curve]:
    for name, c in (("curve1", curve1), ("curve2", curve2)):
        if not isinstance(c, BezierCurve):
            raise InputError(f"{name} must be a BezierCurve, got {type(c).__name__}")
        if c.dimension != 2:
            raise DimensionError(f"{name}: curve intersection is planar; got dimension {c.dimension}")
        if c.degree < 1:
            raise DegreeError(f"{name}: a degree-0 curve is a point, not a curve")
    cart = []
    for c in (curve1, curve2):
        hom = c.homogeneous()
        for h in hom:
            if h[2] != 0:
                cart.extend([abs(h[0] / h[2]), abs(h[1] / h[2])])
    shift = iv.power2_scale(np.array(cart, dtype=object)) if cart else 0
    return _Curve(curve1, shift), _Curve(curve2, shift)


def _root_piece(curve: _Curve) -> _Piece:
    return _Piece(curve.lo, curve.hi, (0.0, 0.0), (1.0, 1.0))


_W_TANGENT = 2.0**-16  # pieces of possibly tangent pairs are not split below this width


def _directions(curve: _Curve, lo, hi):
    """Float directions of the control polygon legs (a proxy of the tangent cone)."""
    clo, chi = curve.cart(lo, hi)
    mid = 0.5 * (clo + chi)
    return np.diff(mid, axis=0)


def _possibly_tangent(c1: _Curve, p_lo, p_hi, c2: _Curve, q_lo, q_hi) -> bool:
    """Heuristic (it only decides when to stop splitting, never what to discard): the
    control-polygon leg directions of the two pieces are not all crossing one way."""
    d1, d2 = _directions(c1, p_lo, p_hi), _directions(c2, q_lo, q_hi)
    if not (np.all(np.isfinite(d1)) and np.all(np.isfinite(d2))):
        return True
    cross = d1[:, None, 0] * d2[None, :, 1] - d1[:, None, 1] * d2[None, :, 0]
    return not (np.all(cross > 0) or np.all(cross < 0))


def _fat_excluded(c1: _Curve, p: "_Piece", c2: _Curve, q: "_Piece") -> bool:
    """Rigorous: one piece misses a fat line of the other (7.7.1)."""
    return _clip(c1, p, c2, q) is None or _clip(c2, q, c1, p) is None


class _Guard:
    """Work bound of a float route: ``tick`` counts one examined pair of pieces and says
    whether the route may go on; a route that runs out returns what is pending (the
    public entry then hands the pair to the exact route)."""

    def __init__(self, budget: int):
        self.budget = budget

    def tick(self, pending: int = 0) -> bool:
        self.budget -= 1
        return self.budget >= 0


def _size(box) -> float:
    lo, hi = box
    return float(np.max(hi - lo)) if np.all(np.isfinite(lo)) and np.all(np.isfinite(hi)) else math.inf


def _halves(piece: _Piece):
    (llo, lhi), (rlo, rhi) = iv.split(piece.lo, piece.hi, 0.5)
    m = _param(piece, 0.5)
    return [_Piece(llo, lhi, piece.a, m), _Piece(rlo, rhi, m, piece.b)]


def _clip(target: _Curve, piece: _Piece, other: _Curve, against: _Piece):
    """Clip ``piece`` against both fat lines of ``against`` (7.7.4: the parallel and the
    perpendicular one; both are valid, so their ranges are intersected)."""
    clo, chi = other.cart(against.lo, against.hi)
    t0, t1 = 0.0, 1.0
    for line in fat_lines(clo, chi):
        r = clip_range(piece.lo, piece.hi, line)
        if r is None:
            return None
        t0, t1 = max(t0, r[0]), min(t1, r[1])
        if t0 > t1:
            return None
    return t0, t1



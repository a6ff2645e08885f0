"""Domain-curve preprocessing: Bézier pieces, split events and joints (Yang et al. (004), sections 3 and 5).

The planar domain curve ``D(t) = (u(t), v(t))`` (rational Bézier or NURBS) is cut

* at its own knots (Bézier extraction),
* where it crosses a knot line ``u = u_k`` or ``v = v_l`` of the surface (section 3),
* where ``u'(t)`` or ``v'(t)`` changes sign (section 5: monotonic segments),

so that every piece is monotonic in both coordinates and lies in one patch.  The
cut parameters are roots of exact polynomials (``N_u - u_k W`` and the numerators
``G = N' W - N W'`` of the derivative), found by
:func:`exactcagd.exact.algebraic.real_roots`; they are usually irrational.

**Joints.**  Consecutive approximating segments meet at a *joint*: an exact rational
point ``P`` with one exact rational direction shared by both segments (so G1 holds
by construction).  A rational cut ``t*`` gives ``P = D(t*)`` and the direction
``G(t*)``.  An irrational cut ``t*`` is *carried* by its isolating interval
``[t_lo, t_hi]`` refined to width ``2^-GAP_BITS``: the curve piece before ends at
``t_lo``, the next starts at ``t_hi``, the joint point is ``D(t_lo)`` with the
crossed knot coordinate replaced by the exact knot value (so both neighbours stay
in their patches), and the direction is ``G(t_lo)`` with the vanishing component
of a monotonicity cut set exactly to zero.  The tiny arc ``D([t_lo, t_hi])`` is
accounted for in the distance bound (:meth:`Joint.gap_piece`).

Stationary points (``D'(t) = 0``) at rational parameters get one-sided directions
from the first non-vanishing Taylor coefficient of ``G``; if the two sides disagree
(a cusp, or a corner at a knot of the domain spline) the joint is a *corner*.

>>> from exactcagd import BezierCurve
>>> dc = DomainCurve(BezierCurve([[0, 0], [1, 2], [2, 0]]))
>>> [str(e.t) for e in dc.events(0, [], [])]        # u' never vanishes; v' = 0 at t = 1/2
['1/2']
"""

from __future__ import annotations

from dataclasses import dataclass, field

import flint
import numpy as np
from gmpy2 import mpq

from ..errors import DomainError, InputError
from ..composition.fast import scaled
from ..exact import bernstein as bz
from ..exact.algebraic import RealAlgebraic, real_roots
from ..exact.scalars import from_fmpq
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bspline import BSplineCurve

__all__ = ["DomainCurve", "Event", "Joint", "GAP_BITS"]

#: Width exponent of the isolating interval that carries an irrational cut.
GAP_BITS = 64


_to_mpq = from_fmpq


def _coeffs(p: flint.fmpq_poly) -> list:
    return [_to_mpq(c) for c in p.coeffs()]


def _ev(p: flint.fmpq_poly, t: mpq) -> mpq:
    return _to_mpq(p(flint.fmpq(int(t.numerator), int(t.denominator))))


def positively_parallel(a, b) -> bool:
    """``a`` and ``b`` point the same way (exact, any dimension): every 2 x 2 minor
    ``a_i b_j - a_j b_i`` vanishes and ``a . b > 0``."""
    k = len(a)
    for i in range(k):
        for j in range(i + 1, k):
            if a[i] * b[j] - a[j] * b[i] != 0:
                return False
    return sum(x * y for x, y in zip(a, b)) > 0


@dataclass
class Event:
    """A cut inside one Bézier piece (merged over all reasons at the same parameter)."""

    t: RealAlgebraic
    u_line: mpq | None = None
    v_line: mpq | None = None
    mono_u: bool = False
    mono_v: bool = False
    stationary: bool = False


@dataclass
class Joint:
    """Where two segments meet (or where the curve starts/ends).

    ``lo = (piece, t)`` is where the curve before the joint stops and ``hi`` where
    the curve after it starts (equal for an exact joint).  ``point`` and the
    directions are global (u, v) coordinates, exact rationals.
    """

    lo: tuple
    hi: tuple
    point: tuple
    dir_in: tuple | None
    dir_out: tuple | None
    exact: bool = True
    corner: bool = False
    reasons: tuple = field(default_factory=tuple)

    @property
    def smooth(self) -> bool:
        return self.dir_in is not None and self.dir_out is not None and not self.corner


class DomainCurve:
    """The domain curve as exact rational Bézier pieces with global parameter spans."""

    def __init__(self, curve):
        if isinstance(curve, BSplineCurve):
            pieces = curve.to_bezier()
        elif isinstance(curve, BezierCurve):
            pieces = [((mpq(0), mpq(1)), curve)]
        else:
            raise InputError(f"domain curve must be a BezierCurve or BSplineCurve, got {type(curve).__name__}")
        if curve.dimension != 2:
            raise InputError(f"domain curve must be planar (dimension 2), got dimension {curve.dimension}")
        self.spans = [span for span, _ in pieces]
        self.curves = [c for _, c in pieces]
        self.homs = [c.homogeneous() for c in self.curves]
        self._poly_cache: list | None = None  # power forms, made on first use (:attr:`_polys`)
        # end points = end rows of the homogeneous form (endpoint interpolation; no evaluate() call)
        first, last = (tuple(h[:-1] / h[-1]) for h in (self.homs[0][0], self.homs[-1][-1]))
        self.closed = first == last

    # ------------------------------------------------------------------ polynomials
    @property
    def _polys(self) -> list:
        """Per piece the power forms ``nu, nv, w`` and ``gu, gv`` (:meth:`_make_polys`), built
        on first use: the fit route's joints of an open curve without knot-line crossings
        need none of them."""
        if self._poly_cache is None:
            self._poly_cache = [self._make_polys(h) for h in self.homs]
        return self._poly_cache

    @staticmethod
    def _make_polys(hom) -> dict:
        # Bernstein -> power form of each column straight from its scaled form (notes 3.3),
        # flint fmpq_poly throughout (the same polynomials as bz.to_power, no mpq round trip)
        n = hom.shape[0] - 1
        nu, nv, w = (bz.scaled_to_power(scaled(hom[:, k]), n) for k in range(3))
        gu = nu.derivative() * w - nu * w.derivative()
        gv = nv.derivative() * w - nv * w.derivative()
        return {"nu": nu, "nv": nv, "w": w, "gu": gu, "gv": gv}

    def is_iso_u(self, k: int) -> bool:
        """Piece ``k`` has constant ``u`` (an iso-parametric segment)."""
        return self._polys[k]["gu"] == 0

    def is_iso_v(self, k: int) -> bool:
        return self._polys[k]["gv"] == 0

    def point(self, k: int, t) -> tuple:
        """``D(t)`` on piece ``k``, exact: ``sum_i C(n, i) t^i (1 - t)^(n - i) (w_i P_i, w_i)``
        dehomogenized (Bernstein form, notes 2.1; end points are the end rows)."""
        t = mpq(t)
        if t == 0 or t == 1:  # end point interpolation: the homogeneous end row
            row = self.homs[k][0 if t == 0 else -1]
            return row[0] / row[2], row[1] / row[2]
        rows = self.homs[k].tolist()
        n = len(rows) - 1
        # t = a / (a + c): the factor (a + c)^-n of every basis value cancels in x / w, y / w
        a, c = t.numerator, t.denominator - t.numerator
        basis = [bz.binomial(n, i) * a**i * c ** (n - i) for i in range(n + 1)]
        x, y, w = (sum(b * row[j] for b, row in zip(basis, rows)) for j in range(3))
        return x / w, y / w

    def derivative_direction(self, k: int, t) -> tuple:
        """``G(t) = N'(t) W(t) - N(t) W'(t)``: a positive multiple of ``D'(t)``."""
        p = self._polys[k]
        t = mpq(t)
        return _ev(p["gu"], t), _ev(p["gv"], t)

    def taylor_directions(self, k: int, t) -> tuple[tuple, tuple]:
        """One-sided tangent directions ``(left, right)`` at a rational ``t`` of piece ``k``.

        The first non-zero Taylor coefficient ``g_r`` of ``G`` at ``t`` gives ``right = g_r``
        and ``left = (-1)^r g_r``.
        """
        p = self._polys[k]
        t = mpq(t)
        shift = flint.fmpq_poly([flint.fmpq(int(t.numerator), int(t.denominator)), 1])
        gu, gv = p["gu"](shift), p["gv"](shift)
        cu, cv = _coeffs(gu), _coeffs(gv)
        for r in range(max(len(cu), len(cv))):
            a = cu[r] if r < len(cu) else mpq(0)
            b = cv[r] if r < len(cv) else mpq(0)
            if a != 0 or b != 0:
                sign = -1 if r % 2 else 1
                return (sign * a, sign * b), (a, b)
        raise DomainError(f"the domain curve is constant on piece {k}")

    def restricted(self, k: int, ta, tb) -> np.ndarray:
        """Homogeneous coefficients of piece ``k`` on ``[ta, tb]`` (global coordinates)."""
        return bz.restrict(self.homs[k], ta, tb)

    # ------------------------------------------------------------------ events
    def events(self, k: int, u_lines, v_lines, domain=None, monotone: bool = True) -> list[Event]:
        """Sorted, merged cuts of piece ``k`` in the open interval ``(0, 1)``.

        ``u_lines``/``v_lines``: knot values of the surface; ``domain`` =
        ``((u0, u1), (v0, v1))`` raises :class:`DomainError` if the piece leaves it.
        ``monotone=False`` leaves out the monotonicity and stationary-point cuts (only the
        knot-line crossings are needed, e.g. by the fit route, which is C0 anyway).
        """
        hom = self.homs[k]
        pts = [(hom[i, 0] / hom[i, 2], hom[i, 1] / hom[i, 2]) for i in range(hom.shape[0])]
        found: list[tuple[RealAlgebraic, dict]] = []

        def add(roots, **flags):
            for r, mult in roots:
                if r == 0 or r == 1:
                    continue
                found.append((r, dict(flags, mult=mult)))

        for axis, lines, key in ((0, u_lines, "u_line"), (1, v_lines, "v_line")):
            lo = min(q[axis] for q in pts)
            hi = max(q[axis] for q in pts)
            for value in lines:
                # Bernstein coefficients w_i (q_i - value), w_i > 0, all >= 0 (or all <= 0) and not
                # all zero: num - value w has no root in (0, 1) (each B_i > 0 there)
                if not (lo < value < hi):
                    continue
                p = self._polys[k]  # power forms only where a knot line may be crossed
                num = p["nu"] if axis == 0 else p["nv"]
                poly = num - flint.fmpq(int(value.numerator), int(value.denominator)) * p["w"]
                if poly == 0:
                    continue  # the piece runs along this knot line
                roots = [(r, m) for r, m in real_roots(_coeffs(poly), 0, 1) if m % 2 == 1]
                add(roots, **{key: value})
        # G = N' W - N W' vanishes identically iff every control point is the same (the weights
        # are non-zero and the Bernstein polynomials independent): no power form needed
        if all(q == pts[0] for q in pts):
            raise DomainError(f"the domain curve is constant on its piece {k}")
        p = self._polys[k] if monotone else None
        for key, g in (("mono_u", p["gu"]), ("mono_v", p["gv"])) if monotone else ():
            if g != 0:
                add([(r, m) for r, m in real_roots(_coeffs(g), 0, 1) if m % 2 == 1], **{key: True})
        if monotone and p["gu"] != 0 and p["gv"] != 0 and (common := p["gu"].gcd(p["gv"])).degree() > 0:
            for r, _ in real_roots(_coeffs(common), 0, 1):
                if r == 0 or r == 1:
                    continue
                if not r.is_rational:
                    raise DomainError(
                        f"the domain curve has a singular point (D'(t) = 0) at the irrational parameter "
                        f"t = {float(r):.12g} of piece {k}; G1 approximation is undefined there"
                    )
                found.append((r, {"stationary": True, "mult": 1}))

        found.sort(key=lambda pair: pair[0])
        merged: list[Event] = []
        for r, flags in found:
            if merged and merged[-1].t == r:
                ev = merged[-1]
            else:
                ev = Event(r)
                merged.append(ev)
            if "u_line" in flags:
                ev.u_line = flags["u_line"]
            if "v_line" in flags:
                ev.v_line = flags["v_line"]
            ev.mono_u |= flags.get("mono_u", False)
            ev.mono_v |= flags.get("mono_v", False)
            ev.stationary |= flags.get("stationary", False)
        if domain is not None:
            (u0, u1), (v0, v1) = domain
            for ev in merged:
                if ev.u_line in (u0, u1) or ev.v_line in (v0, v1):
                    raise DomainError(
                        f"the domain curve leaves the surface domain at t ~ {float(ev.t):.12g} of piece {k}"
                    )
            cuts = [mpq(0)] + [ev.t.lo if ev.t.is_rational else (ev.t.lo + ev.t.hi) / 2 for ev in merged] + [mpq(1)]
            for a, b in zip(cuts[:-1], cuts[1:]):
                u, v = self.point(k, (a + b) / 2)
                if not (u0 <= u <= u1 and v0 <= v <= v1):
                    raise DomainError(f"the domain curve leaves the surface domain on piece {k} near t = {float((a + b) / 2):.6g}")
            for end in (0, 1):
                u, v = self.point(k, end)
                if not (u0 <= u <= u1 and v0 <= v <= v1):
                    raise DomainError(f"the domain curve point {float(u):.6g}, {float(v):.6g} lies outside the surface domain")
        return merged

    # ------------------------------------------------------------------ joints
    def joint_for_event(self, k: int, ev: Event) -> Joint:
        reasons = tuple(
            name
            for name, flag in (
                ("u-knot-line", ev.u_line is not None),
                ("v-knot-line", ev.v_line is not None),
                ("u-monotonic", ev.mono_u),
                ("v-monotonic", ev.mono_v),
                ("stationary", ev.stationary),
            )
            if flag
        )
        if ev.t.is_rational:
            t = ev.t.lo
            point = self.point(k, t)
            if ev.stationary:
                left, right = self.taylor_directions(k, t)
                if positively_parallel(left, right):
                    return Joint((k, t), (k, t), point, left, left, True, False, reasons)
                return Joint((k, t), (k, t), point, left, right, True, True, reasons + ("cusp",))
            d = self.derivative_direction(k, t)
            return Joint((k, t), (k, t), point, d, d, True, False, reasons)
        lo, hi = ev.t.interval(mpq(1, 2**GAP_BITS))
        u, v = self.point(k, lo)
        if ev.u_line is not None:
            u = ev.u_line
        if ev.v_line is not None:
            v = ev.v_line
        du, dv = self.derivative_direction(k, lo)
        if ev.mono_u:
            du = mpq(0)
        if ev.mono_v:
            dv = mpq(0)
        if du == 0 and dv == 0:  # pragma: no cover - excluded: irrational stationary points raise
            raise DomainError("degenerate direction at an irrational cut")
        return Joint((k, lo), (k, hi), (u, v), (du, dv), (du, dv), False, False, reasons + ("irrational",))

    def joints(self, u_lines, v_lines, domain=None, on_corner: str = "error", monotone: bool = True,
               end_directions: bool = True) -> list[Joint]:
        """All joints in order along the curve, start and end included (``monotone``: see :meth:`events`).

        ``end_directions=False``: the start and end joints of an *open* curve carry no
        directions (``None``), for a caller that uses only the cuts, points and corners (the
        fit route); every other joint, and a closed curve's ends (a possible corner), keep them.
        """
        joints: list[Joint] = []
        n = len(self.curves)
        directed = end_directions or self.closed
        for k in range(n):
            if k == 0:
                right = self.taylor_directions(0, 0)[1] if directed else None
                joints.append(Joint((0, mpq(0)), (0, mpq(0)), self.point(0, 0), None, right, True, False, ("start",)))
            for ev in self.events(k, u_lines, v_lines, domain, monotone):
                joints.append(self.joint_for_event(k, ev))
            if k + 1 < n:
                left, _ = self.taylor_directions(k, 1)
                _, right = self.taylor_directions(k + 1, 0)
                point = self.point(k, 1)
                if positively_parallel(left, right):
                    joints.append(Joint((k, mpq(1)), (k + 1, mpq(0)), point, left, left, True, False, ("curve-knot",)))
                else:
                    joints.append(Joint((k, mpq(1)), (k + 1, mpq(0)), point, left, right, True, True, ("curve-knot", "corner")))
        left = self.taylor_directions(n - 1, 1)[0] if directed else None
        joints.append(Joint((n - 1, mpq(1)), (n - 1, mpq(1)), self.point(n - 1, 1), left, None, True, False, ("end",)))
        if self.closed:
            start, end = joints[0], joints[-1]
            if positively_parallel(end.dir_in, start.dir_out):
                end.dir_in = start.dir_out
            else:
                start.corner = end.corner = True
        corners = [j for j in joints if j.corner]
        if corners and on_corner == "error":
            j = corners[0]
            raise DomainError(
                f"the domain curve has a tangent discontinuity ({', '.join(j.reasons)}) at "
                f"({float(j.point[0]):.6g}, {float(j.point[1]):.6g}); a G1 approximation cannot exist there "
                "(pass on_corner='split' to keep it as a G0 joint)"
            )
        return joints

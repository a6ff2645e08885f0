"""Trim curves on B-spline / NURBS surfaces: Remark 1 (and Remark 2) of Lasser & Bonneau (000).

Remark 1: split the domain curve at its own knots and where it crosses the knot lines
``u = kappa`` / ``v = kappa`` of the surface, then compose every piece with the Bézier patch
it lies in (Theorems 1, 2).  If ``K`` is ``C^a`` at ``t*`` and ``F`` is ``C^b`` at ``K(t*)``,
``F(K(t))`` is ``C^e`` there with ``e = min(a, b)`` (a lower bound; the measured order may
be higher).

What is exact
-------------
* Crossing parameters are the roots in (0, 1) of ``X(s) - kappa W(s)`` (resp. ``Y``), found by
  exact isolation (:func:`exactcagd.exact.algebraic.real_roots`); they are rational or
  :class:`~exactcagd.exact.algebraic.RealAlgebraic` (never rounded).
* A piece whose parameter interval has two rational ends is the exact Bézier curve of
  ``F(K(t))`` over that interval (``piece.exact`` is true): the domain segment is
  restricted to the interval by the polar form and composed with its patch.
* A piece with an irrational end cannot be a Bézier curve with rational control points.
  It is carried as ``(carrier curve, exact interval)``: the carrier is the exact
  composition of the domain segment over a slightly larger rational interval (rational
  ends kept; an irrational end replaced by the outer end of its isolating interval, refined
  to width 1/64 of the segment) with the patch's polynomial (rational) map *extended*
  beyond the patch.  On the exact parameter interval ``[t0, t1]`` (RealAlgebraic ends) the
  carrier equals ``F(K(t))`` exactly; on the small overhang it follows the patch's
  extension, not the surface (for a NURBS patch the extension may even have a pole there;
  the carrier is then shrunk until no Bernstein weight is zero).
* Patches are extracted only for the knot spans the curve crosses
  (``BSplineSurface.to_bezier_patches(u_spans, v_spans)``).
* Joint continuity: ``a`` (curve knots: ``p - multiplicity``), ``b`` (surface knot lines
  through ``K(t*)``: ``q - multiplicity``), the Remark-1 bound ``min(a, b)``, and the
  *measured* order: the multiplicity of ``t*`` as a root of ``P_L W_R - P_R W_L`` (global
  parameter), minus one -- exact also at irrational ``t*`` (powers of its minimal polynomial).

>>> from exactcagd import BSplineSurface, BezierCurve
>>> net = [[[i, j, (i * j) % 3] for j in range(3)] for i in range(3)]
>>> F = BSplineSurface(net, [0, 0, "1/2", 1, 1], [0, 0, 0, 1, 1, 1])    # u-knot 1/2
>>> result = compose_spline(F, BezierCurve([[0, 0], [1, 1]]))
>>> [(p.patch, str(p.interval[0]), str(p.interval[1])) for p in result.pieces]
[((0, 0), '0', '1/2'), ((1, 0), '1/2', '1')]
>>> result.joints[0].remark_bound, result.joints[0].measured
(0, 0)
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass, field

import flint
import numpy as np
from gmpy2 import mpq

from ..errors import DimensionError, DomainError, InputError, WeightError
from ..exact import bernstein as bz
from ..exact import knots as kn
from ..exact.algebraic import RealAlgebraic, integer_poly, real_roots_bernstein
from ..exact.scalars import from_fmpq, rational_str, to_rational
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface
from ._inputs import prepare
from .core import compose_prepared
from .domain import check_inside, check_weight_function
from .fast import _fmpq

__all__ = ["compose_spline", "crossed_patches", "SplineComposition", "ComposedPiece", "Joint", "split_domain_curve"]

_MPQ = type(mpq(0))


# ----------------------------------------------------------------------------- exact parameters
def _is_rational(x) -> bool:
    return isinstance(x, _MPQ) or (isinstance(x, RealAlgebraic) and x.is_rational)


def _as_mpq(x) -> mpq:
    return x if isinstance(x, _MPQ) else x.value


def _simplify(x):
    """RealAlgebraic that is rational -> mpq; otherwise unchanged."""
    return x.value if isinstance(x, RealAlgebraic) and x.is_rational else x


def _upper(x) -> mpq:
    return x if isinstance(x, _MPQ) else x.hi


def _lower(x) -> mpq:
    return x if isinstance(x, _MPQ) else x.lo


def rational_between(a, b) -> mpq:
    """A rational number strictly between the exact numbers ``a < b`` (refining intervals)."""
    while not _upper(a) < _lower(b):
        if isinstance(a, RealAlgebraic):
            a.refine((a.hi - a.lo) / 2)
        if isinstance(b, RealAlgebraic):
            b.refine((b.hi - b.lo) / 2)
    return (_upper(a) + _lower(b)) / 2


def affine_algebraic(r, offset, scale):
    """The exact number ``offset + scale * r`` (``scale > 0`` rational); RealAlgebraic stays exact."""
    offset, scale = mpq(offset), mpq(scale)
    if _is_rational(r):
        return offset + scale * _as_mpq(r)
    p = flint.fmpq_poly([flint.fmpq(int(c)) for c in r.poly.coeffs()])
    q = p(flint.fmpq_poly([-_fmpq(offset / scale), _fmpq(1 / scale)]))
    coeffs = [from_fmpq(c) for c in q.coeffs()]
    return RealAlgebraic(integer_poly(coeffs), offset + scale * r.lo, offset + scale * r.hi)


def _fmt(x) -> str:
    return rational_str(x) if isinstance(x, _MPQ) else str(x)


def _exact_dict(x):
    return {"rational": rational_str(x)} if isinstance(x, _MPQ) else x.to_dict()


# ----------------------------------------------------------------------------- result objects
@dataclass
class ComposedPiece:
    """One piece of ``F(K(t))``: lies in one patch and one Bézier segment of ``K``.

    Attributes
    ----------
    curve : BezierCurve
        The exact composition over the rational ``carrier`` interval (parameter ``s`` in
        [0, 1] maps to ``t = a + s (b - a)``).
    carrier : (mpq, mpq)
        Rational global parameter interval of ``curve``.
    interval : (t0, t1)
        Exact global parameter interval of the piece (``mpq`` or ``RealAlgebraic``).
    patch : (int, int)
        Index of the Bézier patch (as in ``BSplineSurface.to_bezier_patches``).
    patch_domain : ((u0, u1), (v0, v1))
    segment : int
        Index of the domain curve's Bézier segment.
    """

    curve: BezierCurve
    carrier: tuple
    interval: tuple
    patch: tuple
    patch_domain: tuple
    segment: int

    @property
    def exact(self) -> bool:
        """True when ``curve`` is exactly the piece (both interval ends rational)."""
        return _is_rational(self.interval[0]) and _is_rational(self.interval[1])

    def local_interval(self) -> tuple:
        """The piece's interval in the carrier curve's own parameter ``s`` (exact)."""
        a, b = self.carrier
        return tuple(_simplify(affine_algebraic(t, -a / (b - a), 1 / (b - a))) for t in self.interval)

    def contains(self, t) -> bool:
        t = to_rational(t)
        return not (t < self.interval[0]) and not (self.interval[1] < t)

    def evaluate(self, t) -> tuple:
        """Exact point at the global parameter ``t`` (rational, inside the carrier)."""
        a, b = self.carrier
        return self.curve.evaluate((to_rational(t) - a) / (b - a))

    def to_dict(self) -> dict:
        return {
            "curve": self.curve.to_dict(),
            "carrier": [rational_str(x) for x in self.carrier],
            "interval": [_exact_dict(x) for x in self.interval],
            "exact": self.exact,
            "patch": list(self.patch),
            "patch_domain": [[rational_str(x) for x in span] for span in self.patch_domain],
            "segment": self.segment,
        }


@dataclass
class Joint:
    """A joint between consecutive pieces at the global parameter ``parameter``.

    ``curve_continuity`` (a) and ``surface_continuity`` (b) are ``None`` for C-infinity;
    ``remark_bound = min(a, b)`` (Remark 1); ``measured`` is the exact order of contact
    of the two adjacent pieces (``None``: the same analytic curve).
    """

    parameter: object
    kinds: tuple
    curve_continuity: int | None
    surface_continuity: int | None
    remark_bound: int | None
    measured: int | None

    def to_dict(self) -> dict:
        return {
            "parameter": _exact_dict(self.parameter),
            "kinds": list(self.kinds),
            "curve_continuity": self.curve_continuity,
            "surface_continuity": self.surface_continuity,
            "remark_bound": self.remark_bound,
            "measured": self.measured,
        }


@dataclass
class SplineComposition:
    """Result of :func:`compose_spline`: pieces in parameter order and their joints."""

    pieces: list
    joints: list = field(default_factory=list)
    domain: tuple = (mpq(0), mpq(1))

    @property
    def patches(self) -> list:
        return [p.patch for p in self.pieces]

    def evaluate(self, t) -> tuple:
        """Exact point of ``F(K(t))`` at a rational global parameter ``t``."""
        t = to_rational(t)
        for piece in self.pieces:
            if piece.contains(t):
                return piece.evaluate(t)
        raise DomainError(f"parameter {t} outside the curve's domain [{self.domain[0]}, {self.domain[1]}]")

    def to_dict(self) -> dict:
        return {
            "domain": [rational_str(x) for x in self.domain],
            "pieces": [p.to_dict() for p in self.pieces],
            "joints": [j.to_dict() for j in self.joints],
        }

    def plot(self, ax=None, **style):
        """Draw the exact image curve, all pieces one legend entry (matplotlib; :func:`exactcagd.plotting.plot`)."""
        from ..plotting import plot

        return plot(self, ax=ax, **style)


# ----------------------------------------------------------------------------- splitting
@dataclass
class _Segment:
    index: int
    span: tuple  # global (a, b)
    hom: np.ndarray  # homogeneous (X, Y, W), positive weight function
    rational: bool
    breaks: list  # [(s, tags)] in (0, 1), sorted; tags: set of ("u"|"v", kappa)
    pieces: list  # [(s0, s1, (i, j))]


def _surface_info(surface):
    if isinstance(surface, BezierSurface):
        return ((mpq(0), mpq(1)), (mpq(0), mpq(1))), {}, {}, (0, 0)
    if isinstance(surface, BSplineSurface):
        bu, bv = surface.breakpoints()
        return (bu, bv), surface.knots_u, surface.knots_v, surface.degree
    raise InputError(f"surface: expected a BSplineSurface or BezierSurface, got {type(surface).__name__}")


def _curve_segments(curve):
    if isinstance(curve, BezierCurve):
        return [((mpq(0), mpq(1)), curve)], None
    if isinstance(curve, BSplineCurve):
        return curve.to_bezier(), curve
    raise InputError(f"curve: expected a BSplineCurve or BezierCurve, got {type(curve).__name__}")


def _line_roots(hom, axis: int, kappa) -> list:
    poly = hom[:, axis] - kappa * hom[:, 2]
    if all(x == 0 for x in poly):
        return []  # the segment runs along the knot line
    return [_simplify(r) for r, _ in real_roots_bernstein(poly, 0, 1) if r != 0 and r != 1]


def _span_index(breaks: tuple, x) -> int:
    return min(max(bisect.bisect_right(breaks, x) - 1, 0), len(breaks) - 2)


def split_domain_curve(surface, curve) -> list:
    """Split the domain curve at its knots and at the surface's knot lines (exact).

    Returns a list of ``_Segment`` records (internal) with exact break parameters and the
    patch index of every sub-interval; consecutive sub-intervals in the same patch are
    merged (the curve only touched a knot line there).
    """
    (bu, bv), _, _, _ = _surface_info(surface)
    segments, _ = _curve_segments(curve)
    if segments[0][1].dimension != 2:
        raise DimensionError(f"the domain curve must be planar (dimension 2); got dimension {segments[0][1].dimension}")
    box = ((bu[0], bu[-1]), (bv[0], bv[-1]))
    out = []
    for index, (span, bez) in enumerate(segments):
        hom = bez.homogeneous()
        if bez.is_rational and not all(w > 0 for w in hom[:, 2]):
            if check_weight_function(hom[:, 2], "weight function of the domain curve") < 0:
                hom = -hom
        check_inside(hom, box, what=f"domain curve (segment {index}, t in [{span[0]}, {span[1]}])")
        found: list = []
        for axis, breaks, name in ((0, bu, "u"), (1, bv, "v")):
            for kappa in breaks[1:-1]:
                for r in _line_roots(hom, axis, kappa):
                    for entry in found:
                        if entry[0] == r:
                            entry[1].add((name, kappa))
                            break
                    else:
                        found.append((r, {(name, kappa)}))
        found.sort(key=lambda e: e[0] if isinstance(e[0], RealAlgebraic) else RealAlgebraic.from_rational(e[0]))
        params = [mpq(0)] + [r for r, _ in found] + [mpq(1)]
        pieces = []
        for s0, s1 in zip(params[:-1], params[1:]):
            sample = rational_between(s0, s1)
            w = bz.de_casteljau(hom, sample)
            patch = (_span_index(bu, w[0] / w[2]), _span_index(bv, w[1] / w[2]))
            if pieces and pieces[-1][2] == patch:
                pieces[-1] = (pieces[-1][0], s1, patch)
            else:
                pieces.append((s0, s1, patch))
        kept = {id(p[0]) for p in pieces}
        breaks = [(r, tags) for r, tags in found if id(r) in kept]
        out.append(_Segment(index, span, hom, bez.is_rational, breaks, pieces))
    return out


def crossed_patches(surface, curve) -> set:
    """Indices ``(i, j)`` of the Bézier patches the domain curve passes through (exact)."""
    return {patch for seg in split_domain_curve(surface, curve) for _, _, patch in seg.pieces}


# ----------------------------------------------------------------------------- composing
def _local_hom(hom: np.ndarray, domain) -> np.ndarray:
    (u0, u1), (v0, v1) = domain
    out = hom.copy()
    out[:, 0] = (hom[:, 0] - u0 * hom[:, 2]) / (u1 - u0)
    out[:, 1] = (hom[:, 1] - v0 * hom[:, 2]) / (v1 - v0)
    return out


def _global(span, s):
    a, b = span
    return _simplify(affine_algebraic(s, a, b - a))


def _carrier_end(s, lower: bool, width) -> mpq:
    """Rational carrier end next to an exact break parameter ``s`` (outside ``[s0, s1]``)."""
    if _is_rational(s):
        return _as_mpq(s)
    s.refine(width)
    return max(s.lo, mpq(0)) if lower else min(s.hi, mpq(1))


def _compose_piece(seg, s0, s1, patch_index, patches, options) -> ComposedPiece:
    domain, patch = patches[patch_index]
    local = _local_hom(seg.hom, domain)
    exact = _is_rational(s0) and _is_rational(s1)
    width = mpq(1, 64)
    while True:
        c0, c1 = _carrier_end(s0, True, width), _carrier_end(s1, False, width)
        restricted = bz.restrict(local, c0, c1) if (c0, c1) != (0, 1) else local
        dom_curve = BezierCurve.from_homogeneous(restricted, rational=seg.rational)
        prep = prepare(patch, dom_curve, allow_outside=not exact)
        if not exact:
            # the carrier runs a little beyond the piece (outside the patch), where a NURBS patch's
            # extension may have poles; only the piece itself must avoid them (it does: it lies in
            # the patch, whose weights are positive)
            prep.check_result_weight = False
        try:
            image = compose_prepared(prep, **options)
            break
        except WeightError:
            if exact or width < mpq(1, 2**40):
                raise
            width /= 64  # a zero Bernstein weight in the carrier: shrink the carrier and retry
    a, b = seg.span
    carrier = (a + c0 * (b - a), a + c1 * (b - a))
    return ComposedPiece(image, carrier, (_global(seg.span, s0), _global(seg.span, s1)), patch_index, domain, seg.index)


def _power_in_global(piece: ComposedPiece) -> list:
    """Homogeneous components of a piece as fmpq_poly in the global parameter t."""
    a, b = piece.carrier
    hom = piece.curve.homogeneous()
    power = bz.to_power(hom)
    sub = flint.fmpq_poly([-_fmpq(a / (b - a)), _fmpq(1 / (b - a))])
    return [flint.fmpq_poly([_fmpq(x) for x in power[:, k]])(sub) for k in range(power.shape[1])]


def _root_multiplicity(poly: flint.fmpq_poly, t) -> int | None:
    """Multiplicity of the exact number ``t`` as a root of ``poly`` (None for the zero poly)."""
    if poly.is_zero():
        return None
    if _is_rational(t):
        factor = flint.fmpq_poly([-_fmpq(_as_mpq(t)), 1])
    else:
        factor = flint.fmpq_poly([flint.fmpq(int(c)) for c in t.poly.coeffs()])
    count = 0
    while (poly % factor).is_zero():
        poly = poly // factor
        count += 1
    return count


def _measured(left: ComposedPiece, right: ComposedPiece, t) -> int | None:
    pl, pr = _power_in_global(left), _power_in_global(right)
    wl, wr = pl[-1], pr[-1]
    orders = []
    for k in range(len(pl) - 1):
        mult = _root_multiplicity(pl[k] * wr - pr[k] * wl, t)
        if mult is not None:
            orders.append(mult - 1)
    return min(orders) if orders else None


def _min_opt(*values):
    finite = [v for v in values if v is not None]
    return min(finite) if finite else None


def _surface_continuity(tags, knots_u, knots_v, degree) -> int | None:
    values = []
    for name, kappa in tags:
        knots, p = (knots_u, degree[0]) if name == "u" else (knots_v, degree[1])
        values.append(p - kn.multiplicity(knots, kappa))
    return _min_opt(*values)


def _tags_at_point(point, bu, bv) -> set:
    u, v = point
    return {("u", k) for k in bu[1:-1] if k == u} | {("v", k) for k in bv[1:-1] if k == v}


def compose_spline(surface, curve, method: str = "fast", *, shortcut: bool = True, reduce: bool = False, continuity: bool = True) -> SplineComposition:
    """Exact ``F(K(t))`` for a B-spline/NURBS (or Bézier) surface and domain curve (Remark 1).

    Parameters
    ----------
    surface : BSplineSurface or BezierSurface
        Polynomial or rational (NURBS); a Bézier patch counts as one patch over [0, 1]^2.
    curve : BSplineCurve or BezierCurve
        Planar domain curve lying in the surface's parameter domain (checked exactly).
    method, shortcut, reduce
        Passed to :func:`exactcagd.composition.compose` for every piece.
    continuity : bool
        Compute the exact measured continuity at the joints (else ``measured = None``).

    Returns
    -------
    SplineComposition
        ``pieces`` in parameter order (see the module docstring for what is exact) and
        ``joints`` with the Remark-1 bound and the measured order.
    """
    (bu, bv), knots_u, knots_v, sdeg = _surface_info(surface)
    segments = split_domain_curve(surface, curve)
    _, spline = _curve_segments(curve)
    needed = {patch for seg in segments for _, _, patch in seg.pieces}
    if isinstance(surface, BezierSurface):
        patches = {(0, 0): (((mpq(0), mpq(1)), (mpq(0), mpq(1))), surface)}
    else:
        patches = surface.to_bezier_patches(pairs=needed)  # only the crossed patches
    options = {"method": method, "shortcut": shortcut, "reduce": reduce}
    pieces, joints = [], []
    for seg in segments:
        tags_of = {id(r): tags for r, tags in seg.breaks}
        for k, (s0, s1, patch) in enumerate(seg.pieces):
            piece = _compose_piece(seg, s0, s1, patch, patches, options)
            if pieces:
                left = pieces[-1]
                t = piece.interval[0]
                if k == 0:  # a knot of the domain curve
                    knot = seg.span[0]
                    a = spline.degree - kn.multiplicity(spline.knots, knot)
                    w = seg.hom[0]
                    tags = _tags_at_point((w[0] / w[2], w[1] / w[2]), bu, bv)
                    kinds = ("curve knot",) + tuple(f"{n} knot line {rational_str(x)}" for n, x in sorted(tags))
                else:
                    a = None
                    tags = tags_of.get(id(s0), set())
                    kinds = tuple(f"{n} knot line {rational_str(x)}" for n, x in sorted(tags))
                b = _surface_continuity(tags, knots_u, knots_v, sdeg)
                measured = _measured(left, piece, t) if continuity else None
                joints.append(Joint(t, kinds, a, b, _min_opt(a, b), measured))
            pieces.append(piece)
    domain = spline.domain if spline is not None else (mpq(0), mpq(1))
    return SplineComposition(pieces, joints, domain)

"""The full algorithm of Yang et al. (004), section 2: a G1 curve on a NURBS surface.

1. the surface is split into rational Bézier patches (lazily, :class:`SurfaceGrid`);
2. the domain curve is cut at its knots, at knot-line crossings and where ``u'`` or
   ``v'`` changes sign (:class:`DomainCurve`), giving monotonic pieces in one patch
   each, bounded by exact joints (shared point and tangent direction);
3. each piece is approximated (parabola: Theorem 1; or a baseline), the 3-D distance
   is certified (``L * H`` with the exact derivative bound ``L`` of the patch over the
   piece's box and the certified domain Hausdorff bound ``H``), and a piece that
   fails is cut at its parametric midpoint (the "shoulder point" ``C_1(0.5)``);
4. the images ``X(u(t), v(t))`` are computed exactly (iso-lines of the cubic /
   quadratic reparameterization, or images of segments) and raised to a common degree.

The baselines need the angle tolerance ``eps_T`` as well: after the distance pass,
every joint whose two image tangents make an angle above ``eps_T`` (exact test
against a rational bound of ``cos^2 eps_T``) has both neighbours cut, until none does.
"""

from __future__ import annotations

import bisect
import time
from dataclasses import dataclass, field

import mpmath
import numpy as np
from gmpy2 import mpq

from .. import limits
from ..errors import ExactCAGDError, InputError, NotSupportedError
from ..exact import bernstein as bz
from ..exact.scalars import rational_str, to_count, to_float, to_rational
from . import approximants as ap
from .domain import DomainCurve, Joint, positively_parallel
from .field_curve import _end_derivative, make_curve
from .hausdorff import hausdorff_certificate, may_attain, sqrt_upper
from .surface_grid import SurfaceGrid

__all__ = ["approximate", "CurveOnSurface", "METHODS"]

METHODS = ("parabola", "hyperbola", "polyline", "fit")

#: Smallest parameter width of a piece before the algorithm gives up.
MIN_WIDTH = mpq(1, 2**48)


@dataclass
class _Item:
    ja: Joint
    jb: Joint
    key: tuple | None = None
    approx: ap.Approximant | None = None
    bound: mpq | None = None
    tangents: tuple | None = None
    certificate: tuple | None = None  # (L, Certified, delta): bound = L (value + delta), refined on demand

    @property
    def piece(self) -> int:
        return self.ja.hi[0]

    @property
    def span(self) -> tuple:
        return self.ja.hi[1], self.jb.lo[1]


@dataclass
class CurveOnSurface:
    """Result of :func:`approximate`: a composite exact rational Bézier curve on the surface.

    Attributes
    ----------
    segments : list of ``BezierCurve`` / ``FieldBezierCurve``
        Exact images on the surface, in order, all of degree ``degree``.  A segment
        is a ``FieldBezierCurve`` when its coefficients lie in ``Q(sqrt(Delta))``.
    domain_segments : list
        The approximating domain curves in the surface's global ``(u, v)`` coordinates.
    patches : list of ``(i, j)``
        Patch (knot-span) index of each segment.
    kinds : list of str
        ``s-parabola`` / ``t-parabola`` / ``s-hyperbola`` / ``t-hyperbola`` / ``segment``.
    distance_bound : mpq
        Certified upper bound of the Hausdorff distance between the composite curve
        and the exact image ``S(D(t))`` (always ``<= tolerance``).
    continuity : str
        ``"G1"`` (checked exactly at every joint when ``verify``), ``"eps_T-G1"``
        for the baselines, with ``" (G0 at corners)"`` if the domain curve has corners.
    max_joint_angle : float
        Largest angle (degrees) between the two image tangents at a joint (float).
    ends : list of ``((t0, on0), (t1, on1))``
        Per segment: the global parameters of the domain curve ``D`` where the target
        piece starts and ends, and whether the segment interpolates ``D`` *exactly*
        there (joint point ``== D(t)`` and joint direction a positive multiple of
        ``D'(t)``).  ``False`` at joints carried by an isolating interval (irrational
        cuts), at stationary points, and at joints rounded by ``snap_bits``.
    certified_by : dict
        How many of the accepted distance certificates (Hausdorff piece bounds) were decided
        in enclosure arithmetic (``"ball"``: outward-rounded binary64 intervals for all pieces
        of a bisection level at once, else a python-flint ``arb`` ball per piece) and how many
        needed exact rationals (``"exact"``) because the enclosures were inconclusive
        (:mod:`exactcagd.composition.ball`, :func:`.hausdorff.float_piece_bounds`).
    """

    segments: list
    domain_segments: list
    patches: list
    kinds: list
    distance_bound: mpq
    degree: int
    method: str
    tolerance: mpq
    continuity: str
    max_joint_angle: float
    angle_tolerance: mpq | None
    corners: list
    timings: dict
    g1_verified: bool | None = None
    closed: bool = False
    params: list = field(default_factory=list)
    ends: list = field(default_factory=list)
    certified_by: dict = field(default_factory=dict)

    def __len__(self) -> int:
        return len(self.segments)

    def summary(self) -> dict:
        return {
            "method": self.method,
            "segments": len(self.segments),
            "degree": self.degree,
            "tolerance": to_float(self.tolerance),
            "distance_bound": float(self.distance_bound),
            "continuity": self.continuity,
            "max_joint_angle_deg": self.max_joint_angle,
            "seconds": self.timings.get("total"),
        }

    def to_dict(self) -> dict:
        """Exact exchange form (rationals as ``"p/q"``, field numbers as ``"a + b*sqrt(D)"``)."""
        return {
            "method": self.method,
            "tolerance": rational_str(self.tolerance),
            "distance_bound": rational_str(self.distance_bound),
            "degree": self.degree,
            "continuity": self.continuity,
            "closed": self.closed,
            "patches": [list(p) for p in self.patches],
            "kinds": list(self.kinds),
            "params": self.params,
            "segments": [s.to_dict() for s in self.segments],
            "domain_segments": [s.to_dict() for s in self.domain_segments],
            "corners": [[rational_str(x) for x in p] for p in self.corners],
            "timings": dict(self.timings),
        }

    def plot(self, ax=None, **style):
        """Draw the approximation, all segments one legend entry with the bound (matplotlib; see :func:`exactcagd.plotting.plot`)."""
        from ..plotting import plot

        return plot(self, ax=ax, **style)

    def __repr__(self) -> str:
        return (
            f"<CurveOnSurface method={self.method} segments={len(self.segments)} degree={self.degree} "
            f"bound={float(self.distance_bound):.3g} continuity={self.continuity}>"
        )


def _cos2_upper(angle_deg) -> mpq:
    """Rational ``C >= cos^2(angle)`` (outward-rounded, 80 digits)."""
    with mpmath.workdps(80):
        c = mpmath.cos(mpmath.mpf(angle_deg.numerator) / angle_deg.denominator * mpmath.pi / 180) ** 2
        num = int(mpmath.ceil(c * mpmath.mpf(10) ** 60))
    return min(mpq(num, 10**60), mpq(1))


class _Solver:
    def __init__(self, grid, dcurve, tol, method, root, max_segments, snap_bits):
        self.grid, self.dcurve, self.tol, self.method, self.root = grid, dcurve, tol, method, root
        self.snap_bits = snap_bits
        self.max_segments = max_segments
        self.attempts = 0
        self.certified_by: dict = {}  # piece bounds decided by ball / exact arithmetic

    # ------------------------------------------------------------------ local data
    def local_c1(self, item: _Item) -> np.ndarray:
        ta, tb = item.span
        hom = self.dcurve.restricted(item.piece, ta, tb)
        (ua, ub), (va, vb) = self.grid.spans(item.key)
        out = hom.copy()
        out[:, 0] = (hom[:, 0] - ua * hom[:, 2]) / (ub - ua)
        out[:, 1] = (hom[:, 1] - va * hom[:, 2]) / (vb - va)
        return out

    def build(self, item: _Item) -> ap.Approximant | None:
        g = self.grid
        p0, p1 = g.to_local(item.key, item.ja.point), g.to_local(item.key, item.jb.point)
        if self.method == "polyline":
            return ap.segment(p0, p1)
        d0 = g.direction_to_local(item.key, item.ja.dir_out)
        d1 = g.direction_to_local(item.key, item.jb.dir_in)
        if self.method == "parabola":
            return ap.parabola(p0, d0, p1, d1, self.root)
        ta, tb = item.span
        mid = g.to_local(item.key, self.dcurve.point(item.piece, (ta + tb) / 2))
        return ap.hyperbola(p0, p1, mid, d0, d1)

    # ------------------------------------------------------------------ one piece
    def try_item(self, item: _Item) -> bool:
        self.attempts += 1
        ta, tb = item.span
        if not ta < tb:
            raise ExactCAGDError(f"internal: empty piece [{ta}, {tb}] (overlapping cut intervals)")
        mid = self.dcurve.point(item.piece, (ta + tb) / 2)
        item.key = self.grid.locate(*mid)
        approx = self.build(item)
        if approx is None:
            return False
        c1 = self.local_c1(item)
        p0, p1 = self.grid.to_local(item.key, item.ja.point), self.grid.to_local(item.key, item.jb.point)
        ends = [p0, p1, (c1[0, 0] / c1[0, 2], c1[0, 1] / c1[0, 2]), (c1[-1, 0] / c1[-1, 2], c1[-1, 1] / c1[-1, 2])]
        us, vs = [e[0] for e in ends], [e[1] for e in ends]
        box_u, box_v = (min(us), max(us)), (min(vs), max(vs))
        if box_u[0] < 0 or box_u[1] > 1 or box_v[0] < 0 or box_v[1] > 1:
            raise NotSupportedError(
                "internal: a piece's box leaves its patch (an irrational cut lies within 2^-64 of a patch corner)"
            )
        L = sqrt_upper(self.grid.lipschitz_sq(item.key, box_u, box_v))
        if L == 0:
            item.approx, item.bound = approx, mpq(0)
            return True
        proxy, delta = approx.proxy()
        limit = self.tol / L - delta
        if limit <= 0:
            return False
        hb = hausdorff_certificate(c1, proxy.domain_hom(), limit, stats=self.certified_by)
        if hb is None:
            return False
        item.approx, item.bound, item.certificate = approx, L * (hb.upper + delta), (L, hb, delta)
        return True

    # ------------------------------------------------------------------ joint data
    def snap(self, joint: Joint) -> Joint:
        """Round a joint's point to the dyadic grid ``2^-snap_bits`` and its direction to
        ``snap_bits - 24`` bits, keeping knot-line coordinates, zero components, the span of
        each coordinate and numbers that are already simple (denominator ``<= 2^snap_bits``).  The approximants interpolate the rounded data; the
        certified bound accounts for it (the rounding only keeps the exact numbers small)."""
        if self.snap_bits is None:
            return joint
        b = self.snap_bits
        scale = mpq(2) ** b
        point = []
        for x, breaks in zip(joint.point, (self.grid.u_breaks, self.grid.v_breaks)):
            if x in breaks or x.denominator <= scale:  # knot values and simple numbers stay exact
                point.append(x)
                continue
            q = mpq(round(x * scale)) / scale
            i = bisect.bisect_right(breaks, x)
            lo, hi = breaks[max(i - 1, 0)], breaks[min(i, len(breaks) - 1)]
            point.append(q if lo < q < hi else x)
        joint.point = tuple(point)

        limit = 2 ** (b - 24)

        def rnd(d):
            if d is None:
                return None
            big = max(abs(x) for x in d)
            if big == 0 or all(abs(x.numerator) <= limit and x.denominator <= limit for x in d):
                return d
            return tuple(mpq(round(x / big * 2 ** (b - 24))) for x in d)

        same = joint.dir_in is joint.dir_out or joint.dir_in == joint.dir_out
        joint.dir_in = rnd(joint.dir_in)
        joint.dir_out = joint.dir_in if same else rnd(joint.dir_out)
        return joint

    def split(self, item: _Item) -> tuple[_Item, _Item]:
        ta, tb = item.span
        if tb - ta < MIN_WIDTH:
            raise ExactCAGDError(
                f"{self.method}: tolerance {to_float(self.tol):.3g} not reached before pieces became "
                f"narrower than 2^-48 in the parameter (piece {item.piece}, t ~ {float(ta):.12g})"
            )
        k = item.piece
        tm = (ta + tb) / 2
        d = self.dcurve.derivative_direction(k, tm)
        if d == (0, 0):  # pragma: no cover - stationary points are cut beforehand
            d = self.dcurve.taylor_directions(k, tm)[1]
        joint = self.snap(Joint((k, tm), (k, tm), self.dcurve.point(k, tm), d, d, True, False, ("shoulder",)))
        return _Item(item.ja, joint), _Item(joint, item.jb)

    def solve(self, item: _Item, out: list) -> None:
        stack = [item]
        while stack:
            it = stack.pop()
            if self.try_item(it):
                out.append(it)
                if len(out) > self.max_segments:
                    raise ExactCAGDError(f"more than max_segments = {self.max_segments} segments needed")
            else:
                left, right = self.split(it)
                stack.append(right)
                stack.append(left)

    # ------------------------------------------------------------------ joints
    def culprits(self, left: _Item, right: _Item, il: int, ir: int, eps: float) -> set:
        """Which neighbours of a joint with too large an angle to cut (baselines; a heuristic):
        the one whose image tangent deviates more from the exact curve's tangent ``J D``, or
        both if both deviate by more than ``eps / 2``."""
        joint = left.jb
        key = left.key
        exact = self.grid.tangent(key, self.grid.to_local(key, joint.point), self.grid.direction_to_local(key, joint.dir_in))
        dl = _angle_deg(self.image_tangent(left, 1), exact)
        dr = _angle_deg(self.image_tangent(right, 0), exact)
        if dl > eps / 2 and dr > eps / 2:
            return {il, ir}
        return {il} if dl >= dr else {ir}

    def image_tangent(self, item: _Item, end: int) -> tuple:
        """Exact image tangent ``J (domain derivative)`` of the approximant at an end (cached)."""
        if item.tangents is None:
            dom = item.approx.domain_hom()
            pair = []
            for e, joint in ((0, item.ja), (1, item.jb)):
                d = _end_derivative(dom, e)
                pair.append(self.grid.tangent(item.key, self.grid.to_local(item.key, joint.point), d))
            item.tangents = tuple(pair)
        return item.tangents[end]


def _text(value):
    if isinstance(value, (tuple, list)):
        return [_text(x) for x in value]
    if isinstance(value, type(mpq(0))):
        return rational_str(value)
    return str(value) if not isinstance(value, (str, int)) else value


def _angle_deg(a, b) -> float:
    fa = np.array([float(x) for x in a])
    fb = np.array([float(x) for x in b])
    den = np.linalg.norm(fa) * np.linalg.norm(fb)
    if den == 0:
        return 180.0
    return float(np.degrees(np.arccos(np.clip(fa @ fb / den, -1.0, 1.0))))


def _within_angle(a, b, cos2: mpq) -> bool:
    dot = sum(x * y for x, y in zip(a, b))
    if dot <= 0:
        return False
    return dot * dot >= cos2 * sum(x * x for x in a) * sum(y * y for y in b)


def approximate(
    surface,
    domain_curve,
    tol,
    method: str = "parabola",
    *,
    angle_tol=1,
    root: str = "paper",
    on_corner: str = "error",
    max_segments: int = 100000,
    verify: bool = True,
    snap_bits: int | None = 64,
    max_degree: int = 14,
) -> CurveOnSurface:
    """Approximate the image of a domain curve on a surface by an exact composite curve.

    Parameters
    ----------
    surface : BezierSurface or BSplineSurface (NURBS)
    domain_curve : planar BezierCurve or BSplineCurve inside the surface's domain
    tol : positive number
        ``eps_D``: bound on the Hausdorff distance to the exact image ``S(D(t))``.
    method : "parabola" (Yang et al. 2012, G1), "hyperbola" (ref. [15]), "polyline" (ref. [2]) or "fit"
        The first three lie exactly on the surface.  ``"fit"`` (fit then certify,
        :mod:`.fit`) is *not* on the surface: a least-squares polynomial fit (binary64,
        degree 3 .. ``max_degree``, bisection when no degree suffices) to the exact image
        ``F = S(D(t))``, converted exactly to rationals, with a proven rational bound of
        ``max_t |F(t) - C(t)|`` (Bernstein coefficients of the exact difference, convex-hull
        property; exact bisection when needed) as ``distance_bound``.  C0 at joints (shared
        exact end points); ``domain_segments`` are the pieces of ``D`` each segment follows,
        ``continuity`` is ``"C0"``.
    angle_tol : number (degrees)
        ``eps_T`` of the baselines (ignored by the parabola method, which is G1).
    root : "paper" | "other"
        Root of eq. (16) (both are valid for monotonic data).
    on_corner : "error" | "split"
        What to do where the domain curve itself has a tangent discontinuity.
    verify : bool
        Check G1 exactly at every joint (parabola method).
    max_degree : int
        Highest degree of a ``"fit"`` segment (ignored by the other methods).
    snap_bits : int or None
        Joints created at irrational cuts and at shoulder points get their point
        rounded to ``2^-snap_bits`` and their direction to ``snap_bits - 24`` bits
        (both neighbours use the rounded data, so G1 stays exact; the bound covers
        the rounding).  ``None`` keeps the exact curve data (much larger numbers).

    Returns
    -------
    CurveOnSurface

    Examples
    --------
    >>> from exactcagd import BezierSurface, BezierCurve
    >>> S = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    >>> D = BezierCurve([["1/10", "1/10"], ["1/2", "9/10"], ["9/10", "1/5"]])
    >>> r = approximate(S, D, "1/100")
    >>> r.degree, r.continuity, r.distance_bound <= mpq(1, 100)
    (3, 'G1', True)
    >>> f = approximate(S, D, "1/100", method="fit")     # compact, within 1/100, not on S
    >>> len(f.segments), f.continuity, f.distance_bound <= mpq(1, 100)
    (1, 'C0', True)
    """
    start = time.perf_counter()
    tol = to_rational(tol, where="tol")
    if tol <= 0:
        raise InputError(f"tolerance must be positive, got {tol}")
    if method not in METHODS:
        raise InputError(f"method must be one of {METHODS}, got {method!r}")
    if root not in ("paper", "other"):
        raise InputError(f"root must be 'paper' or 'other', got {root!r}")
    if on_corner not in ("error", "split"):
        raise InputError(f"on_corner must be 'error' or 'split', got {on_corner!r}")
    angle = to_rational(angle_tol, where="angle_tol")
    if method in ("hyperbola", "polyline") and not (0 < angle < 180):
        raise InputError(f"angle tolerance must lie in (0, 180) degrees, got {angle}")
    if snap_bits is not None:  # directions are rounded to snap_bits - 24 bits: at least one is needed
        if to_count(snap_bits, where="snap_bits") < 25:
            raise InputError(f"snap_bits must be None or an integer >= 25 (directions keep snap_bits - 24 bits), got {snap_bits!r}")
        limits.check("max_input_bits", snap_bits, "snap_bits (bits of the rounded joint data)")
    if to_count(max_segments, where="max_segments") < 1:
        raise InputError(f"max_segments must be a positive integer, got {max_segments!r}")
    grid = SurfaceGrid(surface)
    if grid.dimension < 2:
        raise InputError("the surface must lie in a space of dimension >= 2")
    dcurve = DomainCurve(domain_curve)
    if method == "fit":  # C0 result: corners of D need no special joint
        if to_count(max_degree, where="max_degree") < 1:
            raise InputError(f"max_degree must be a positive integer, got {max_degree!r}")
        from .fit import approximate_fit

        joints = dcurve.joints(grid.u_breaks, grid.v_breaks, grid.domain, "split", monotone=False, end_directions=False)
        return approximate_fit(grid, dcurve, joints, tol, max_degree, max_segments, start)
    joints = dcurve.joints(grid.u_breaks, grid.v_breaks, grid.domain, on_corner)
    for a, b in zip(joints[:-1], joints[1:]):
        if a.hi[0] == b.lo[0] and not a.hi[1] < b.lo[1]:
            raise ExactCAGDError("internal: cut intervals overlap; refine GAP_BITS")
    t_split = time.perf_counter()
    solver = _Solver(grid, dcurve, tol, method, root, max_segments, snap_bits)
    joints = [solver.snap(j) if not j.exact else j for j in joints]
    done: list[_Item] = []
    for ja, jb in zip(joints[:-1], joints[1:]):
        solver.solve(_Item(ja, jb), done)
    t_dist = time.perf_counter()

    cos2 = _cos2_upper(angle) if method != "parabola" else None
    rounds = 0
    while method != "parabola":
        bad = set()
        for idx in range(len(done) - 1 + (1 if dcurve.closed else 0)):
            left, right = done[idx], done[(idx + 1) % len(done)]
            if left.jb.corner:
                continue
            ta, tb = solver.image_tangent(left, 1), solver.image_tangent(right, 0)
            if not _within_angle(ta, tb, cos2):
                bad.update(solver.culprits(left, right, idx, (idx + 1) % len(done), float(angle)))
        if not bad:
            break
        rounds += 1
        new: list[_Item] = []
        for idx, it in enumerate(done):
            if idx in bad:
                for half in solver.split(it):
                    solver.solve(half, new)
            else:
                new.append(it)
        done = new
        if len(done) > max_segments:
            raise ExactCAGDError(f"more than max_segments = {max_segments} segments needed")
    t_angle = time.perf_counter()

    ends = [(_end_info(dcurve, it.ja, "hi"), _end_info(dcurve, it.jb, "lo")) for it in done]

    # images, exact
    m, n = grid.degree
    images, domains, kinds, params = [], [], [], []
    for it in done:
        images.append(it.approx.image_hom(grid.patch_hom(it.key)))
        kinds.append(it.approx.kind)
        params.append({k: _text(v) for k, v in it.approx.params.items() if not k.startswith("_")})
        dom = it.approx.domain_hom()
        (ua, ub), (va, vb) = grid.spans(it.key)
        glob = dom.copy()
        glob[:, 0] = ua * dom[:, 2] + (ub - ua) * dom[:, 0]
        glob[:, 1] = va * dom[:, 2] + (vb - va) * dom[:, 1]
        domains.append(make_curve(glob))
    degree = max(h.shape[0] - 1 for h in images)
    segments = [make_curve(bz.elevate(h, degree - (h.shape[0] - 1))) for h in images]
    t_img = time.perf_counter()

    bound = _largest_bound(done)
    bound = max(bound, _gap_bound(grid, dcurve, joints))
    angles = []
    g1 = None
    pairs = list(zip(done[:-1], done[1:])) + ([(done[-1], done[0])] if dcurve.closed and len(done) > 1 else [])
    if method == "parabola" and verify:
        g1 = True
    for il, (left, right) in enumerate(pairs):
        if left.jb.corner:
            continue
        a, b = solver.image_tangent(left, 1), solver.image_tangent(right, 0)
        angles.append(_angle_deg(a, b))
        if g1:
            g1 = _g1_exact(grid, left, right, segments[il], segments[(il + 1) % len(done)])
    corners = [j.point for j in joints if j.corner]
    if method == "parabola":
        continuity = "G1" if (g1 or not verify) else "G0 (surface not C1 at a joint)"
    else:
        continuity = "eps_T-G1"
    if corners:
        continuity += " (G0 at corners)"
    t_end = time.perf_counter()
    return CurveOnSurface(
        segments=segments,
        domain_segments=domains,
        patches=[it.key for it in done],
        kinds=kinds,
        distance_bound=bound,
        degree=degree,
        method=method,
        tolerance=tol,
        continuity=continuity,
        max_joint_angle=0.0 if g1 else (max(angles) if angles else 0.0),
        angle_tolerance=None if method == "parabola" else angle,
        corners=corners,
        timings={
            "split": t_split - start,
            "distance": t_dist - t_split,
            "angle": t_angle - t_dist,
            "images": t_img - t_angle,
            "verify": t_end - t_img,
            "total": t_end - start,
            "attempts": solver.attempts,
            "angle_rounds": rounds,
        },
        g1_verified=g1,
        closed=dcurve.closed,
        params=params,
        ends=ends,
        certified_by=solver.certified_by,
    )


def _largest_bound(done: list) -> mpq:
    """``max L (H + delta)`` over the pieces, with each ``H`` the value of its certificate:
    only the pieces whose upper bound may attain the maximum are refined."""
    lowers = [it.bound if it.certificate is None else it.certificate[0] * (it.certificate[1].lower + it.certificate[2]) for it in done]
    top = max(lowers)
    best = mpq(0)
    for it in done:
        if it.certificate is not None and may_attain(it.bound, top):
            L, hb, delta = it.certificate
            it.bound = L * (hb.value() + delta)
        best = max(best, it.bound)
    return best


def _end_info(dcurve: DomainCurve, joint: Joint, side: str) -> tuple:
    """``(global parameter, exact interpolation of D's point and tangent direction)``."""
    k, t = getattr(joint, side)
    a, b = dcurve.spans[k]
    direction = joint.dir_out if side == "hi" else joint.dir_in
    exact = (
        joint.exact
        and direction is not None
        and tuple(joint.point) == dcurve.point(k, t)
        and positively_parallel(direction, dcurve.derivative_direction(k, t))
    )
    return a + (b - a) * t, exact


def _g1_exact(grid: SurfaceGrid, left: _Item, right: _Item, seg_l, seg_r) -> bool:
    """Exact G1 test at a joint: both image tangents are positive multiples of ``J D``."""
    d_l = grid.direction_to_local(left.key, left.jb.dir_in)
    d_r = grid.direction_to_local(right.key, right.ja.dir_out)
    t_l = grid.tangent(left.key, grid.to_local(left.key, left.jb.point), d_l)
    t_r = grid.tangent(right.key, grid.to_local(right.key, right.ja.point), d_r)
    img_l = _end_derivative(seg_l.homogeneous(), 1)
    img_r = _end_derivative(seg_r.homogeneous(), 0)
    if all(x == 0 for x in t_l) or all(x == 0 for x in t_r):
        return False
    return positively_parallel(img_l, t_l) and positively_parallel(img_r, t_r) and positively_parallel(t_l, t_r)


def _gap_bound(grid: SurfaceGrid, dcurve: DomainCurve, joints) -> mpq:
    """3-D bound for the tiny arcs ``D([t_lo, t_hi])`` carried by irrational cuts."""
    best = mpq(0)
    for j in joints:
        if j.exact:
            continue
        k, lo = j.lo
        _, hi = j.hi
        hom = dcurve.restricted(k, lo, hi)
        pts = [(row[0] / row[2], row[1] / row[2]) for row in hom]
        far = max((p[0] - j.point[0]) ** 2 + (p[1] - j.point[1]) ** 2 for p in pts)
        us = [p[0] for p in pts] + [j.point[0]]
        vs = [p[1] for p in pts] + [j.point[1]]
        keys = grid.patches_near((min(us), max(us)), (min(vs), max(vs)))
        L2 = max(grid.global_lipschitz_sq(key) for key in keys)
        best = max(best, sqrt_upper(L2) * sqrt_upper(far))
    return best

"""The record kinds of ``exactcagd refdata``: what each record holds and how it is made.

A kind is a name, its families (``random`` plus the hard families of
:mod:`exactcagd.refdata.families` that apply to it) and, per family, a builder
``(rng, degrees) -> (input, answer)``.  Builders compute the answer with the exact
layers of exactcagd (de Casteljau and de Boor in rationals, Boehm insertion,
resultants, exact root isolation); every exact value is stored with its correctly
rounded float64 companion (:mod:`exactcagd.refdata.records`).

Conventions of every kind (also stated in its JSON Schema):

* control points: a list of points, each a list of coordinates; surfaces
  ``control_points[i][j]`` with ``i`` along ``u``; ``weights`` in the same layout,
  absent for polynomial objects;
* Bernstein / power coefficients and polynomial coefficients: lowest index first;
* implicit equations: ``[[i, j, "c"], ...]`` for the monomial ``c x^i y^j``
  (``c`` a decimal integer string), sorted by ``(i + j, i)``;
* algebraic numbers: ``{"poly", "interval", "f64"}``.

>>> rec = make_record("curve_eval", "random", seed=1, index=0, degrees=(2,))
>>> rec["id"], sorted(rec["answer"])[:2]
('curve_eval/random/0', ['first_derivatives', 'first_derivatives_f64'])
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, InputError
from ..exact.algebraic import RealAlgebraic, real_roots_bernstein
from ..exact.bernstein import de_casteljau, derivative, elevate, from_power, subdivide
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface
from . import families as fam
from .records import algebraic, with_f64

__all__ = ["KINDS", "MAX_DEGREE", "Kind", "kind_named", "make_record", "preload"]

#: Largest degree accepted from ``--degree``.
MAX_DEGREE = 40


@dataclass(frozen=True)
class Kind:
    """A record kind: ``builders[family](rng, degrees) -> (input, answer)``.

    ``degrees`` has at most ``len(default_degrees)`` entries (a shorter tuple repeats its
    last entry), each in ``1 .. max_degree``: the exact algorithms of the kind grow
    quickly with the degree (implicitization and intersection are resultants of degree
    ``n^2``; composition has degree ``n (l + m)``).
    """

    name: str
    description: str
    default_degrees: tuple
    builders: dict = field(default_factory=dict)
    max_degree: int = MAX_DEGREE

    @property
    def families(self) -> tuple:
        return tuple(self.builders)


# ----------------------------------------------------------------------------- encoders
def curve_dict(curve) -> dict:
    """A Bézier curve: degree, dimension, control points (+ weights), exact and float."""
    out = {"degree": curve.degree, "dimension": curve.dimension}
    with_f64(out, "control_points", curve.points_array())
    if curve.is_rational:
        with_f64(out, "weights", curve.weights_array())
    return out


def surface_dict(surface: BezierSurface) -> dict:
    out = {"degree": list(surface.degree), "dimension": surface.dimension}
    with_f64(out, "control_points", surface.net_array())
    if surface.is_rational:
        with_f64(out, "weights", surface.weights_array())
    return out


def bspline_curve_dict(curve: BSplineCurve) -> dict:
    out = {"degree": curve.degree, "dimension": curve.dimension}
    with_f64(out, "knots", list(curve.knots))
    with_f64(out, "control_points", [list(p) for p in curve.control_points])
    if curve.is_rational:
        with_f64(out, "weights", list(curve.weights))
    return out


def bspline_surface_dict(surface: BSplineSurface) -> dict:
    out = {"degree": list(surface.degree), "dimension": surface.dimension}
    with_f64(out, "knots_u", list(surface.knots_u))
    with_f64(out, "knots_v", list(surface.knots_v))
    with_f64(out, "control_points", [[list(p) for p in row] for row in surface.control_net])
    if surface.is_rational:
        with_f64(out, "weights", [list(r) for r in surface.weights])
    return out


def implicit_terms(mpoly) -> list:
    """``[[i, j, "c"], ...]`` from a flint ``fmpz_mpoly`` in ``x, y``, sorted by ``(i + j, i)``."""
    terms = [(int(m[0]), int(m[1]), int(c)) for m, c in mpoly.to_dict().items() if c != 0]
    terms.sort(key=lambda t: (t[0] + t[1], t[0]))
    return [[i, j, str(c)] for i, j, c in terms]


# ----------------------------------------------------------------------------- exact derivatives
def rational_jet(hom: np.ndarray, t, order: int = 2) -> list:
    """Point and derivatives up to ``order`` of the rational Bernstein curve ``hom`` (last column = weight).

    Quotient rule for ``P = X / w`` (Sederberg's notes 15.3):
    ``P' = (X' - w' P) / w`` and ``P'' = (X'' - 2 w' P' - w'' P) / w``.
    """
    h0 = de_casteljau(hom, t)
    d1 = derivative(hom)
    h1 = de_casteljau(d1, t)
    w = h0[-1]
    p = h0[:-1] / w
    jet = [p, (h1[:-1] - h1[-1] * p) / w]
    if order >= 2:
        h2 = de_casteljau(derivative(d1), t)
        jet.append((h2[:-1] - 2 * h1[-1] * jet[1] - h2[-1] * p) / w)
    return jet


def _tensor_eval(hom: np.ndarray, u, v):
    rows = np.array([de_casteljau(hom[i], v) for i in range(hom.shape[0])], dtype=object)
    return de_casteljau(rows, u)


def surface_point_normal(surface: BezierSurface, u, v) -> tuple:
    """Exact ``S(u, v)`` and the unnormalised normal ``S_u x S_v`` (quotient rule for rational patches)."""
    hom = surface.homogeneous()
    h = _tensor_eval(hom, u, v)
    hu = _tensor_eval(derivative(hom), u, v)
    hv = _tensor_eval(np.swapaxes(derivative(np.swapaxes(hom, 0, 1)), 0, 1), u, v)
    w = h[-1]
    p = h[:-1] / w
    su = (hu[:-1] - hu[-1] * p) / w
    sv = (hv[:-1] - hv[-1] * p) / w
    normal = [su[1] * sv[2] - su[2] * sv[1], su[2] * sv[0] - su[0] * sv[2], su[0] * sv[1] - su[1] * sv[0]]
    return list(p), normal


# ----------------------------------------------------------------------------- curve_eval
def _curve_for(rng, family: str, degree: int, dim: int, rational_curve: bool) -> BezierCurve:
    if family == "weights_wide":
        return fam.bezier_curve(rng, degree, dim, True, wide=True)
    if family == "extreme_coefficients":
        return fam.bezier_curve(rng, degree, dim, False, scale=mpq(2) ** rng.choice(fam.SCALE_EXPONENTS))
    if family == "high_degree":
        return fam.bezier_curve(rng, rng.randint(20, MAX_DEGREE), dim, rational_curve)
    return fam.bezier_curve(rng, degree, dim, rational_curve)


def _params(rng, family: str, count: int) -> list:
    if family == "endpoints":
        return fam.end_params(rng, count)
    return [fam.rational(rng, 0, 1, 64) for _ in range(count)]


def _curve_eval(family):
    def build(rng, degrees):
        dim = rng.choice((2, 3))
        curve = _curve_for(rng, family, degrees[0], dim, rational_curve=rng.random() < 0.5)
        params = _params(rng, family, 3)
        jets = [rational_jet(curve.homogeneous(), t) for t in params]
        inp = curve_dict(curve)
        with_f64(inp, "params", params)
        ans = {}
        with_f64(ans, "values", [j[0] for j in jets])
        with_f64(ans, "first_derivatives", [j[1] for j in jets])
        with_f64(ans, "second_derivatives", [j[2] for j in jets])
        return inp, ans

    return build


# ----------------------------------------------------------------------------- surface_eval
def _random_surface(rng, family: str, l: int, m: int) -> BezierSurface:
    scale = mpq(2) ** rng.choice(fam.SCALE_EXPONENTS) if family == "extreme_coefficients" else 1
    if family == "high_degree":
        l, m = rng.randint(20, MAX_DEGREE), rng.randint(1, 3)
    net = [[[x * scale for x in fam.points(rng, 1, 3)[0]] for _ in range(m + 1)] for _ in range(l + 1)]
    w = None
    if family == "weights_wide":
        w = [fam.weights(rng, m + 1, wide=True) for _ in range(l + 1)]
    elif family in ("random", "endpoints") and rng.random() < 0.5:
        w = [fam.weights(rng, m + 1) for _ in range(l + 1)]
    return BezierSurface(net, w)


def _surface_eval(family):
    def build(rng, degrees):
        l, m = (degrees + degrees[-1:])[:2]
        surface = _random_surface(rng, family, l, m)
        params = [list(pair) for pair in zip(_params(rng, family, 3), _params(rng, family, 3))]
        evaluated = [surface_point_normal(surface, u, v) for u, v in params]
        inp = surface_dict(surface)
        with_f64(inp, "params", params)
        ans = {}
        with_f64(ans, "values", [e[0] for e in evaluated])
        with_f64(ans, "normals", [e[1] for e in evaluated])
        return inp, ans

    return build


# ----------------------------------------------------------------------------- B-splines
def _random_bspline_curve(rng, family: str, degree: int) -> BSplineCurve:
    if family == "high_degree":
        degree = rng.randint(20, MAX_DEGREE)
    n_points = degree + 1 + rng.randint(1, 4)
    knots = fam.clamped_knots(rng, degree, n_points)
    wide = family == "weights_wide"
    w = fam.weights(rng, n_points, wide) if (wide or rng.random() < 0.5) else None
    pts = fam.points(rng, n_points, rng.choice((2, 3)))
    if family == "extreme_coefficients":
        scale = mpq(2) ** rng.choice(fam.SCALE_EXPONENTS)
        pts = [[x * scale for x in p] for p in pts]
    return BSplineCurve(pts, knots, w)


def _random_bspline_surface(rng, family: str, p: int, q: int) -> BSplineSurface:
    nu, nv = p + 1 + rng.randint(1, 2), q + 1 + rng.randint(1, 2)
    ku, kv = fam.clamped_knots(rng, p, nu), fam.clamped_knots(rng, q, nv)
    wide = family == "weights_wide"
    w = [fam.weights(rng, nv, wide) for _ in range(nu)] if (wide or rng.random() < 0.5) else None
    net = [fam.points(rng, nv, 3) for _ in range(nu)]
    return BSplineSurface(net, ku, kv, w)


def _knot_params(rng, family: str, knots, count: int) -> list:
    """Random parameters; for ``endpoints``: knots, and one ulp (2^-53) around knots and ends."""
    if family != "endpoints":
        return [fam.rational(rng, 0, 1, 64) for _ in range(count)]
    out = []
    for _ in range(count):
        k = knots[rng.randrange(len(knots))]
        delta = rng.choice((0, mpq(1, 2**53), -mpq(1, 2**53), mpq(1, 2**1074)))
        out.append(min(max(k + delta, mpq(0)), mpq(1)))
    return out


def _bspline_eval(family):
    def build(rng, degrees):
        if rng.random() < 0.5 or family in ("high_degree", "extreme_coefficients"):
            curve = _random_bspline_curve(rng, family, degrees[0])
            params = _knot_params(rng, family, curve.knots, 3)
            inp = {"object": "curve", **bspline_curve_dict(curve)}
            with_f64(inp, "params", params)
            values = [list(curve.evaluate(t)) for t in params]
        else:
            p, q = (degrees + degrees[-1:])[:2]
            surface = _random_bspline_surface(rng, family, p, q)
            params = [list(pair) for pair in zip(_knot_params(rng, family, surface.knots_u, 3), _knot_params(rng, family, surface.knots_v, 3))]
            inp = {"object": "surface", **bspline_surface_dict(surface)}
            with_f64(inp, "params", params)
            values = [list(surface.evaluate(u, v)) for u, v in params]
        return inp, with_f64({}, "values", values)

    return build


def _knot_insertion(family):
    def build(rng, degrees):
        curve = _random_bspline_curve(rng, family, degrees[0])
        if family == "endpoints":
            knot = _knot_params(rng, family, curve.knots, 1)[0]
        else:
            knot = fam.rational(rng, 0, 1, 64)
        room = curve.degree - sum(1 for k in curve.knots if k == knot)
        times = rng.randint(1, max(1, room)) if room > 0 else 0
        if times == 0:  # full multiplicity already (the ends): insert one ulp inside instead
            knot = knot + mpq(1, 2**53) if knot == 0 else knot - mpq(1, 2**53)
            times = 1
        refined = curve.insert_knot(knot, times)
        inp = bspline_curve_dict(curve)
        with_f64(inp, "knot", knot)
        inp["times"] = times
        ans = {}
        with_f64(ans, "knots", list(refined.knots))
        with_f64(ans, "control_points", [list(p) for p in refined.control_points])
        if refined.is_rational:
            with_f64(ans, "weights", list(refined.weights))
        return inp, ans

    return build


def _bezier_extraction(family):
    def build(rng, degrees):
        curve = _random_bspline_curve(rng, family, degrees[0])
        segments = []
        for (a, b), piece in curve.to_bezier():
            seg = with_f64({}, "interval", [a, b])
            seg.update({k: v for k, v in curve_dict(piece).items() if k not in ("degree", "dimension")})
            segments.append(seg)
        return bspline_curve_dict(curve), {"segments": segments}

    return build


# ----------------------------------------------------------------------------- Bézier algorithms
def _degree_elevation(family):
    def build(rng, degrees):
        curve = _curve_for(rng, family, degrees[0], rng.choice((2, 3)), rational_curve=rng.random() < 0.5)
        times = rng.randint(1, 3)
        hom = elevate(curve.homogeneous(), times)
        raised = BezierCurve.from_homogeneous(hom) if curve.is_rational else BezierCurve(hom[:, :-1])
        inp = curve_dict(curve)
        inp["times"] = times
        ans = {k: v for k, v in curve_dict(raised).items() if k != "dimension"}
        return inp, ans

    return build


def _subdivision(family):
    def build(rng, degrees):
        curve = _curve_for(rng, family, degrees[0], rng.choice((2, 3)), rational_curve=rng.random() < 0.5)
        t = _params(rng, family, 1)[0]
        if t in (0, 1):
            t = mpq(1, 2**53) if t == 0 else 1 - mpq(1, 2**53)
        left, right = subdivide(curve.homogeneous(), t)
        inp = curve_dict(curve)
        with_f64(inp, "param", t)
        ans = {}
        for name, hom in (("left", left), ("right", right)):
            piece = BezierCurve.from_homogeneous(hom) if curve.is_rational else BezierCurve(hom[:, :-1])
            ans[name] = {k: v for k, v in curve_dict(piece).items() if k not in ("degree", "dimension")}
        return inp, ans

    return build


# ----------------------------------------------------------------------------- composition
def _compose(family):
    def build(rng, degrees):
        from ..composition import compose
        from ..composition.splines import compose_spline

        n, l, m = (degrees + (degrees[-1],) * 3)[:3]
        domain = BezierCurve([[fam.rational(rng), fam.rational(rng)] for _ in range(n + 1)])
        if family == "nurbs":
            surface = _random_bspline_surface(rng, "random", l, m)
            result = compose_spline(surface, domain)
            pieces = []
            for piece in result.pieces:
                entry = {"interval": [algebraic(t) for t in piece.interval]}
                with_f64(entry, "carrier", list(piece.carrier))
                entry.update({k: v for k, v in curve_dict(piece.curve).items() if k != "dimension"})
                pieces.append(entry)
            inp = {"surface": {"type": "nurbs", **bspline_surface_dict(surface)}, "curve": curve_dict(domain)}
            return inp, {"pieces": pieces}
        wide = family == "weights_wide"
        net = [[[mpq(i, l), mpq(j, m), fam.rational(rng, -1, 1)] for j in range(m + 1)] for i in range(l + 1)]
        w = [fam.weights(rng, m + 1, wide) for _ in range(l + 1)] if (wide or rng.random() < 0.3) else None
        surface = BezierSurface(net, w)
        image = compose(surface, domain)
        piece = {"interval": [algebraic(0), algebraic(1)]}
        with_f64(piece, "carrier", [0, 1])
        piece.update({k: v for k, v in curve_dict(image).items() if k != "dimension"})
        inp = {"surface": {"type": "bezier", **surface_dict(surface)}, "curve": curve_dict(domain)}
        return inp, {"pieces": [piece]}

    return build


# ----------------------------------------------------------------------------- algebra
def _planar(rng, family: str, degree: int) -> BezierCurve:
    return fam.bezier_curve(rng, degree, 2, rational_curve=rng.random() < 0.5, wide=family == "weights_wide")


def _sub_arc(rng, curve: BezierCurve) -> BezierCurve:
    """A sub-arc ``[a, b]`` of ``curve`` (reversed half the time): same algebraic curve."""
    a, b = sorted([fam.rational(rng, 0, 1, 8), fam.rational(rng, 0, 1, 8)])
    if a == b:
        a, b = mpq(1, 4), mpq(3, 4)
    arc = curve.reparametrize(a, b)
    return arc.reversed() if rng.random() < 0.5 else arc


def _implicitize(family):
    def build(rng, degrees):
        from ..algebra.implicitize import implicit_equation

        curve = _planar(rng, family, degrees[0])
        if family == "shared_algebraic":
            curve = _sub_arc(rng, curve)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            eq = implicit_equation(curve)
        inp = curve_dict(curve)
        return inp, {"equation": implicit_terms(eq.mpoly), "degree": eq.degree, "proper": eq.proper}

    return build


def _poly_terms(expr) -> list:
    import sympy

    from ..algebra._poly import X_SYM, Y_SYM

    poly = sympy.Poly(expr, X_SYM, Y_SYM)
    terms = sorted(((int(i), int(j), int(c)) for (i, j), c in poly.terms()), key=lambda t: (t[0] + t[1], t[0]))
    return [[i, j, str(c)] for i, j, c in terms]


def _inversion(family):
    def build(rng, degrees):
        import sympy

        from ..algebra.inversion import inversion_linear_algebra

        while True:  # an improper (multiply traced) or constant curve has no inversion formula: draw again
            curve = _planar(rng, family, degrees[0])
            try:
                formula = inversion_linear_algebra(curve)
                break
            except (InputError, DegreeError):  # ImproperParametrizationError is an InputError
                continue
        params, pts = [], []
        for t in _params(rng, family, 3):
            x, y = curve.evaluate(t)
            value = formula(x, y)
            if value is None:  # a singular point: 0/0
                continue
            if sympy.Rational(value) != sympy.Rational(int(t.numerator), int(t.denominator)):  # pragma: no cover
                raise ArithmeticError(f"inversion formula gives {value} at the point of t = {t}")
            params.append(t)
            pts.append([x, y])
        inp = curve_dict(curve)
        with_f64(inp, "points", pts)
        ans = with_f64({}, "params", params)
        ans["formula"] = {"numerator": _poly_terms(formula.num), "denominator": _poly_terms(formula.den)}
        return inp, ans

    return build


def _perturbed(curve: BezierCurve, factor_roots: list, rng) -> BezierCurve:
    """``curve(t) + prod (t - r) V``: meets ``curve`` at every ``r`` (a repeated ``r``: higher contact)."""
    power = [mpq(1)]
    for r in factor_roots:
        power = [(power[k - 1] if k else 0) - r * (power[k] if k < len(power) else 0) for k in range(len(power) + 1)]
    bump = from_power(np.array(power, dtype=object))
    degree = max(curve.degree, len(factor_roots))
    base = fam.elevated_to(curve.points_array(), degree)
    bump = fam.elevated_to(bump, degree)
    v = [fam.rational(rng, -2, 2) or mpq(1), fam.rational(rng, -2, 2) or mpq(1)]
    pts = [[base[i][k] + bump[i] * v[k] for k in range(2)] for i in range(degree + 1)]
    return BezierCurve(pts)


def _intersect_pair(rng, family: str, degrees) -> tuple:
    n1, n2 = (degrees + degrees[-1:])[:2]
    if family in ("random", "weights_wide"):
        return _planar(rng, family, n1), _planar(rng, family, n2)
    base = fam.bezier_curve(rng, n1, 2, False)
    if family == "shared_algebraic":
        return base, _sub_arc(rng, base)
    t0 = fam.rational(rng, 0, 1, 16)
    if family == "tangency":
        return base, _perturbed(base, [t0, t0], rng)
    if family == "higher_contact":
        return base, _perturbed(base, [t0] * rng.randint(3, 4), rng)
    if family == "clustered":
        return base, _perturbed(base, [t0, t0 + mpq(1, 2**41)], rng)
    if family == "endpoints":
        ends = [mpq(0), mpq(1), mpq(1, 2**53), 1 - mpq(1, 2**53)]
        return base, _perturbed(base, [ends[rng.randrange(4)], ends[rng.randrange(4)]], rng)
    raise InputError(f"unknown intersect family {family!r}")  # pragma: no cover


def _intersect(family):
    def build(rng, degrees):
        from ..algebra import intersect as exact_intersect
        from ..algebra.intersect import OverlapError

        c1, c2 = _intersect_pair(rng, family, degrees)
        inp = {"curve1": curve_dict(c1), "curve2": curve_dict(c2)}
        try:
            found = exact_intersect(c1, c2)
            overlaps = []
        except OverlapError as exc:  # shared arcs, and the isolated common points besides them
            from ..algebra.intersect import CurveIntersection

            found = [CurveIntersection(t1, t2, None, _point_on(c2, t2)) for t1, t2 in getattr(exc, "points", [])]
            overlaps = _overlaps_from(exc, c1, c2)
        points = []
        for hit in found:
            points.append(
                {
                    "t1": algebraic(hit.t1),
                    "t2": algebraic(hit.t2),
                    "point": [algebraic(x) for x in hit.point],
                    "multiplicity": hit.multiplicity,
                }
            )
        return inp, {"intersections": points, "overlaps": overlaps}

    return build


def _point_on(curve: BezierCurve, t: RealAlgebraic) -> tuple:
    """The exact point ``curve(t)`` as algebraic numbers (``t`` rational or algebraic)."""
    if t.is_rational:
        return tuple(RealAlgebraic.from_rational(x) for x in curve.evaluate(t.value))
    from ..algebra.implicitize import reduced_components
    from ..algebra.numberfield import algebraic_value

    X, Y, W, _ = reduced_components(curve, warn=False)
    return algebraic_value(t, X, W), algebraic_value(t, Y, W)


def _arc_ends(exc) -> list:
    """``[((a, b), (c, d))]``: parameter intervals of the shared arcs (exact, ``lo < hi``)."""
    arcs = getattr(exc, "overlaps", None)
    if arcs:  # algebra.intersect's Overlap objects (exact ends, any reparametrization)
        return [(tuple(ov.t1_interval), tuple(ov.t2_interval)) for ov in arcs]
    if exc.mapping is None or not exc.t2_intervals:
        return []
    a, b, c, d = exc.mapping  # t1 = (a t2 + b) / (c t2 + d), monotone on each interval
    out = []
    for lo, hi in exc.t2_intervals:
        t1 = sorted(((a * lo + b) / (c * lo + d), (a * hi + b) / (c * hi + d)))
        out.append((tuple(RealAlgebraic.from_rational(x) for x in t1), (RealAlgebraic.from_rational(lo), RealAlgebraic.from_rational(hi))))
    return out


def _overlaps_from(exc, curve1: BezierCurve, curve2: BezierCurve) -> list:
    """Common arcs from an :class:`OverlapError`, ends paired by their exact points.

    Each overlap lists its two ends with increasing ``t1``; ``t2[k]`` and ``points[k]``
    belong to the end ``t1[k]`` (``t2`` decreases when the curves run opposite ways).
    """
    out = []
    for (a, b), (c, d) in _arc_ends(exc):
        start = _point_on(curve1, a)
        t2 = (c, d) if tuple(_point_on(curve2, c)) == tuple(start) else (d, c)
        points = [start, _point_on(curve1, b)]
        out.append({"t1": [algebraic(a), algebraic(b)], "t2": [algebraic(x) for x in t2], "points": [[algebraic(x) for x in p] for p in points]})
    return out


# ----------------------------------------------------------------------------- roots
def _roots(family):
    def build(rng, degrees):
        n = degrees[0]
        if family == "random":
            coeffs = np.array([fam.rational(rng, -4, 4) or mpq(1) for _ in range(n + 1)], dtype=object)
        elif family == "high_degree":
            n = rng.randint(20, MAX_DEGREE)
            chosen = [(fam.rational(rng, 0, 1, 64), 1) for _ in range(rng.randint(2, 6))]
            coeffs = fam.polynomial_with_roots(chosen, n - len(chosen), rng)
        elif family == "clustered":
            r = fam.rational(rng, 0, 1, 64)
            chosen = [(r, 1), (r + mpq(1, 2 ** rng.randint(41, 60)), 1)]
            if rng.random() < 0.5:
                chosen.append((r - mpq(1, 2 ** rng.randint(41, 60)), 1))
            coeffs = fam.polynomial_with_roots(chosen, max(0, n - len(chosen)), rng)
        elif family == "tangency":
            chosen = [(fam.rational(rng, 0, 1, 64), rng.randint(2, 4))]
            coeffs = fam.polynomial_with_roots(chosen, max(0, n - chosen[0][1]), rng)
        elif family == "endpoints":
            ends = [mpq(0), mpq(1), mpq(1, 2**53), 1 - mpq(1, 2**53), mpq(1, 2**60)]
            chosen = [(ends[rng.randrange(len(ends))], 1) for _ in range(2)]
            merged = {}
            for r, m in chosen:
                merged[r] = merged.get(r, 0) + m
            coeffs = fam.polynomial_with_roots(sorted(merged.items()), max(0, n - 2), rng)
        elif family == "extreme_coefficients":
            coeffs = np.array([fam.rational(rng, -4, 4) or mpq(1) for _ in range(n + 1)], dtype=object)
            coeffs = coeffs * (mpq(2) ** rng.choice(fam.SCALE_EXPONENTS))
        else:  # pragma: no cover
            raise InputError(f"unknown roots family {family!r}")
        found = real_roots_bernstein(coeffs, 0, 1)
        inp = {"degree": int(coeffs.shape[0] - 1)}
        with_f64(inp, "coefficients", list(coeffs))
        ans = {"roots": [{"value": algebraic(r), "multiplicity": m} for r, m in found]}
        return inp, ans

    return build


# ----------------------------------------------------------------------------- registry
def _kind(name, description, default_degrees, factory, families, max_degree=MAX_DEGREE):
    return Kind(name, description, default_degrees, {f: factory(f) for f in families}, max_degree)


_EVAL_FAMILIES = ("random", "endpoints", "weights_wide", "extreme_coefficients", "high_degree")

KINDS = {
    k.name: k
    for k in (
        _kind("curve_eval", "Bézier / rational Bézier curve: point, first and second derivative at parameters", (3,), _curve_eval, _EVAL_FAMILIES),
        _kind("surface_eval", "Bézier / rational Bézier surface: point and unnormalised normal S_u x S_v", (2, 2), _surface_eval, _EVAL_FAMILIES, max_degree=20),
        _kind("bspline_eval", "B-spline / NURBS curve and surface evaluation (de Boor)", (3, 2), _bspline_eval, ("random", "endpoints", "weights_wide", "extreme_coefficients", "high_degree")),
        _kind("knot_insertion", "B-spline / NURBS curve knot insertion (Boehm)", (3,), _knot_insertion, ("random", "endpoints", "weights_wide", "extreme_coefficients", "high_degree")),
        _kind("bezier_extraction", "B-spline / NURBS curve to Bézier segments", (3,), _bezier_extraction, ("random", "weights_wide", "extreme_coefficients", "high_degree")),
        _kind("degree_elevation", "Bézier / rational Bézier degree elevation", (3,), _degree_elevation, ("random", "weights_wide", "extreme_coefficients", "high_degree")),
        _kind("subdivision", "Bézier / rational Bézier subdivision (de Casteljau)", (3,), _subdivision, ("random", "endpoints", "weights_wide", "extreme_coefficients", "high_degree")),
        _kind("compose", "composition F(K(t)) of a Bézier or NURBS surface with a domain curve", (2, 1, 2), _compose, ("random", "nurbs", "weights_wide"), max_degree=8),
        _kind("implicitize", "implicit equation of a planar (rational) Bézier curve", (3,), _implicitize, ("random", "weights_wide", "shared_algebraic"), max_degree=12),
        _kind("inversion", "parameter of points on a planar curve, and the inversion formula", (3,), _inversion, ("random", "endpoints", "weights_wide"), max_degree=8),
        _kind("intersect", "planar curve-curve intersection: algebraic parameters, multiplicities, overlaps", (3, 3), _intersect, ("random", "tangency", "higher_contact", "clustered", "endpoints", "shared_algebraic", "weights_wide"), max_degree=8),
        _kind("roots", "real roots in [0, 1] of a Bernstein polynomial, with multiplicities", (5,), _roots, ("random", "clustered", "tangency", "endpoints", "extreme_coefficients", "high_degree")),
    )
}


#: Modules the builders of a kind import lazily (heavy: sympy, the algebra layer).
_LAZY_IMPORTS = {
    "compose": ("exactcagd.composition", "exactcagd.composition.splines"),
    "implicitize": ("exactcagd.algebra.implicitize",),
    "inversion": ("sympy", "exactcagd.algebra.inversion"),
    "intersect": ("exactcagd.algebra", "exactcagd.algebra.intersect"),
}


def preload(kinds) -> None:
    """Import what the builders of ``kinds`` import lazily.

    Called before forking worker processes, so each worker inherits the modules
    instead of importing them again (one to two seconds for sympy and the algebra layer).
    """
    import importlib

    for kind in kinds:
        for module in _LAZY_IMPORTS.get(kind, ()):
            importlib.import_module(module)


def kind_named(name: str) -> Kind:
    """The kind called ``name`` (``InputError`` naming the choices otherwise)."""
    try:
        return KINDS[name]
    except KeyError:
        raise InputError(f"unknown refdata kind {name!r}; choose one of {', '.join(KINDS)}") from None


def make_record(kind: str, family: str, seed: int, index: int, degrees: tuple) -> dict:
    """One reference record: a pure function of ``(kind, family, seed, index, degrees)``."""
    spec = kind_named(kind)
    if family not in spec.builders:
        raise InputError(f"kind {kind!r} has no family {family!r}; choose one of {', '.join(spec.families)}")
    rng = fam.record_rng(kind, family, seed, index)
    inp, ans = spec.builders[family](rng, tuple(degrees))
    return {"id": f"{kind}/{family}/{index}", "kind": kind, "family": family, "seed": seed, "index": index, "input": inp, "answer": ans}

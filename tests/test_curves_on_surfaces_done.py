"""The "done when" checks of issue 5 (Yang et al. 2012), each against an independent reference.

* public result: ``.segments`` are exact ``BezierCurve``s in 3-D (field curves included);
* every parabola segment starts/ends *exactly* at the target curve's points with exactly
  the curve's tangent directions (reference: the foundation's ``BezierCurve.evaluate`` for
  ``D(t)``, sympy's derivative of ``D`` for ``D'(t)``, end tangents from control points);
* the certified distance bound is checked against a dense mpmath sampling (30 digits) of
  the exact composed curve ``S(D(t))`` (``exactcagd.composition.compose_spline``) and of
  the approximation;
* degenerate input: an iso-parametric piece inside a spline domain curve.
"""
import mpmath
import numpy as np
import pytest
import sympy
from gmpy2 import mpq

from exactcagd import BezierCurve, BSplineCurve
from exactcagd.composition import compose_spline
from exactcagd.curves_on_surfaces import FieldBezierCurve, approximate
from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve
from exactcagd.exact.quadratic import QuadraticNumber
from test_curves_on_surfaces import _end_tangent, _sym, _to_polyline  # shared test helpers


def _unit_direction(a):
    """``a / |a_k|`` for its first non-zero component: must be a rational vector when ``a`` is a
    field multiple of a rational direction (both neighbours of a joint may live in different fields)."""
    k = 0 if a[0] != 0 else 1
    out = []
    for x in a:
        y = x / abs(a[k])
        if isinstance(y, QuadraticNumber):
            assert y.b == 0, f"{y} is not rational"
            y = y.a
        out.append(mpq(y))
    return tuple(out)


def _parallel_same_way(a, b):
    return _unit_direction(a) == _unit_direction(b)


@pytest.fixture(scope="module")
def face():
    return analytic_surface(5, 5, "face")


# ----------------------------------------------------------------------------- public result
def test_segments_are_exact_bezier_curves_in_3d(face):
    r = approximate(face, closed_domain_curve(8), "1e-2")
    assert len(r.segments) == len(r.domain_segments) > 0
    assert all(isinstance(s, BezierCurve) and s.dimension == 3 and s.degree == r.degree for s in r.segments)
    assert all(isinstance(s, BezierCurve) and s.dimension == 2 for s in r.domain_segments)
    assert any(isinstance(s, FieldBezierCurve) for s in r.segments)  # sqrt(Delta) carried, still a BezierCurve
    assert r.degree == 9 and isinstance(r.distance_bound, type(mpq(0))) and 0 < r.distance_bound <= mpq(1, 100)
    seg = next(s for s in r.segments if isinstance(s, FieldBezierCurve))
    # the inherited BezierCurve operations work on field entries
    left, right = seg.subdivide(mpq(1, 3))
    assert left.evaluate(1) == right.evaluate(0) == seg.evaluate(mpq(1, 3))
    assert seg.elevate(1).same_curve(seg)


# ----------------------------------------------------------------------------- exact end data
def test_parabola_segments_interpolate_curve_points_and_tangents_exactly():
    """A monotonic rational cubic domain curve on a one-patch bicubic surface: every cut is
    rational (shoulder points), so with ``snap_bits=None`` every segment must hit D(t) and the
    direction of D'(t) exactly."""
    face = analytic_surface(4, 4, "face")
    D = BezierCurve([["1/10", "3/20"], ["2/5", "1/5"], ["3/5", "11/20"], ["17/20", "9/10"]], [1, 2, 1, 3])
    r = approximate(face, D, "1e-3", snap_bits=None)
    assert len(r) >= 4 and r.continuity == "G1"
    t = sympy.Symbol("t")
    Dsym = D.to_sympy(t)
    dD = Dsym.diff(t)
    for i, ((t0, on0), (t1, on1)) in enumerate(r.ends):
        assert on0 and on1
        dom, seg = r.domain_segments[i], r.segments[i]
        for end, tk in ((0, t0), (1, t1)):
            assert tuple(dom.evaluate(end)) == D.evaluate(tk)  # same point, exactly
            ref = [sympy.nsimplify(dD[k].subs(t, _sym(tk))) for k in range(2)]  # D'(t), sympy
            mine = [_sym(x) for x in _end_tangent(dom, end)]
            assert sympy.simplify(mine[0] * ref[1] - mine[1] * ref[0]) == 0
            assert sympy.simplify(mine[0] * ref[0] + mine[1] * ref[1]) > 0
            # the 3-D segment starts/ends at S(D(t)) exactly
            assert tuple(seg.evaluate(end)) == face.evaluate(*D.evaluate(tk))
    # consecutive segments share their parameters: the pieces tile [0, 1]
    assert r.ends[0][0][0] == 0 and r.ends[-1][1][0] == 1
    assert all(a[1][0] == b[0][0] for a, b in zip(r.ends[:-1], r.ends[1:]))


def test_default_rounding_keeps_exact_g1_and_reports_which_ends_are_exact(face):
    D = closed_domain_curve(8)
    r = approximate(face, D, "1e-3")
    assert r.continuity == "G1" and r.g1_verified
    flags = [flag for pair in r.ends for (_, flag) in pair]
    assert any(flags) and not all(flags)  # rounded shoulder / irrational-cut joints are flagged
    for i, ((t0, on0), (t1, on1)) in enumerate(r.ends):
        for end, tk, on in ((0, t0, on0), (1, t1, on1)):
            if on:
                assert tuple(r.domain_segments[i].evaluate(end)) == D.evaluate(tk)
        # the next segment starts where this one ends (exact G0, also across rounded joints)
        j = (i + 1) % len(r)
        assert tuple(r.segments[i].evaluate(1)) == tuple(r.segments[j].evaluate(0))
        a, b = _end_tangent(r.domain_segments[i], 1), _end_tangent(r.domain_segments[j], 0)
        assert _parallel_same_way(a, b)


# ----------------------------------------------------------------------------- distance
def _mp(x):
    if isinstance(x, QuadraticNumber):
        return _mp(x.a) + _mp(x.b) * mpmath.sqrt(x.D)
    x = mpq(x)
    return mpmath.mpf(int(x.numerator)) / int(x.denominator)


def _mp_samples(curve, count):
    """Points of an exact rational curve at ``count`` equidistant parameters: exact conversion to
    the power basis (sympy-free: ``sum_i c_i C(n,i) t^i (1-t)^(n-i)`` expanded with integer
    binomials here), then mpmath Horner at the working precision (30 digits: the power basis
    of degree <= 18 loses at most ~6 of them)."""
    hom = curve.homogeneous()
    n = hom.shape[0] - 1
    power = [[0] * (n + 1) for _ in range(hom.shape[1])]
    for i in range(n + 1):
        for j in range(n - i + 1):  # C(n,i) t^i (1-t)^(n-i) = sum_j C(n,i) C(n-i,j) (-1)^j t^(i+j)
            c = sympy.binomial(n, i) * sympy.binomial(n - i, j) * (-1) ** j
            for k in range(hom.shape[1]):
                power[k][i + j] = power[k][i + j] + int(c) * hom[i, k]
    coeffs = [[_mp(x) for x in reversed(col)] for col in power]
    out = []
    for s in range(count):
        t = mpmath.mpf(s) / (count - 1)
        vals = [mpmath.polyval(c, t) for c in coeffs]
        out.append([v / vals[-1] for v in vals[:-1]])
    return out


@pytest.mark.parametrize("method,tol", [("parabola", "1e-3"), ("hyperbola", "1e-2")])
def test_certified_bound_against_mpmath_sampling(face, method, tol):
    D = closed_domain_curve(8)
    r = approximate(face, D, tol, method, angle_tol=5)
    exact = compose_spline(face, D)
    with mpmath.workdps(30):
        ex = [p for piece in exact.pieces for p in _mp_samples(piece.curve, 25)]
        ap = [p for seg in r.segments for p in _mp_samples(seg, 60)]
        ex_f = np.array([[float(c) for c in p] for p in ex])
        ap_f = np.array([[float(c) for c in p] for p in ap])
    # distances of 30-digit samples to the other curve's dense polyline (sagitta << 1e-7)
    estimate = max(_to_polyline(ex_f, ap_f).max(), _to_polyline(ap_f[::3], ex_f).max())
    assert 0 < estimate <= float(r.distance_bound) + 1e-7
    assert r.distance_bound <= mpq(tol)


# ----------------------------------------------------------------------------- degenerate input
def test_iso_parametric_piece_inside_a_spline_curve(face):
    """Control points 3..6 share u = 2/5: the middle cubic piece is the iso-line u = 2/5; it is
    approximated by itself (kind iso-u, exactly on the iso-line), the rest by parabolas, G1."""
    pts = [["1/10", "1/10"], ["1/5", "1/5"], ["2/5", "3/10"], ["2/5", "2/5"], ["2/5", "1/2"], ["2/5", "3/5"], ["3/5", "7/10"], ["4/5", "4/5"]]
    D = BSplineCurve(pts, [0, 0, 0, 0, "1/5", "2/5", "3/5", "4/5", 1, 1, 1, 1])
    assert all(D.evaluate(mpq(2, 5) + mpq(k, 25))[0] == mpq(2, 5) for k in range(6))  # span [2/5, 3/5]
    r = approximate(face, D, "1e-3")
    assert r.continuity == "G1"
    iso = [i for i, p in enumerate(r.params) if p.get("type") == "iso-u"]
    assert iso
    for i in iso:
        assert all(x == mpq(2, 5) for x in r.domain_segments[i].points_array()[:, 0])

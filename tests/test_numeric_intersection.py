"""Certified curve/curve intersection (notes ch. 7): exactcagd.numeric.intersect.

Reference: the exact algebraic route of the algebra layer (``exactcagd.algebra.intersect``:
implicit equation + real algebraic roots), independent of the numeric code; the numeric
module's own exact route (``intersect_exact``, resultants + number-field gcd) is
cross-checked against it.  Checked for every method: every exact intersection lies in a
returned box (none missed), a ``certified`` box holds exactly one, and every returned
item either holds an exact intersection or marks a place where the curves are closer
than the tolerance (none spurious beyond tol; the distance is computed exactly).
"""

import random

import numpy as np
import pytest
import sympy
from gmpy2 import mpq

from exactcagd import BezierCurve
from exactcagd.algebra import OverlapError
from exactcagd.algebra import intersect as exact_intersect
from exactcagd.errors import DegreeError, DimensionError, InputError, NotSupportedError, WeightError
from exactcagd.exact import bernstein as bz
from exactcagd.numeric import Intersection, intersect
from exactcagd.numeric.fatline import left_clip, right_clip
from exactcagd.numeric.intersect_exact import intersect_exact

METHODS = ("subdivision", "interval", "clipping")
TOL = 1e-12


def exact_point(curve, t):
    """Exact rational point of a curve at a rational parameter."""
    return [mpq(x) for x in curve.evaluate(mpq(t))]


def check(curve1, curve2, method, ref=None, tol=TOL):
    """The three guarantees of :func:`intersect` against the exact reference."""
    if ref is None:
        ref = exact_intersect(curve1, curve2)
    out = intersect(curve1, curve2, method=method, tol=tol)
    assert all(isinstance(x, Intersection) for x in out)
    for r in ref:
        assert any(x.contains(r.t1, r.t2) for x in out), (method, float(r.t1), float(r.t2), out)
    for x in out:
        inside = [r for r in ref if x.contains(r.t1, r.t2)]
        assert x.t1_interval[0] <= x.t1 <= x.t1_interval[1] and x.t2_interval[0] <= x.t2 <= x.t2_interval[1]
        if x.certified:
            assert len(inside) == 1, (method, x, len(inside))
        if not inside:
            # spurious only within tol: the curves nearly touch there (exact distance)
            p, q = exact_point(curve1, x.t1), exact_point(curve2, x.t2)
            scale = max(1, max(abs(float(c)) for c in curve1.points_array().reshape(-1)))
            assert max(abs(float(p[k] - q[k])) for k in range(2)) <= 1e3 * tol * scale, (method, x)
    return out, ref


def random_curve(rng, max_degree=3, rational_prob=0.3, size=8):
    n = rng.randint(1, max_degree)
    pts = [[rng.randint(-size, size), rng.randint(-size, size)] for _ in range(n + 1)]
    w = [rng.randint(1, 6) for _ in range(n + 1)] if rng.random() < rational_prob else None
    return BezierCurve(pts, weights=w)


def random_pairs(seed, count, **kw):
    rng = random.Random(seed)
    done = 0
    while done < count:
        a, b = random_curve(rng, **kw), random_curve(rng, **kw)
        try:
            ref = exact_intersect(a, b)
        except (OverlapError, NotSupportedError):
            continue
        done += 1
        yield a, b, ref


# ------------------------------------------------------------------ property tests over random cases
@pytest.mark.parametrize("seed", range(4))
def test_random_pairs_all_methods(seed):
    """4 x 40 random pairs (polynomial and rational, degree 1-3), three methods each."""
    found = 0
    for a, b, ref in random_pairs(seed, 40):
        found += len(ref)
        for method in METHODS:
            out, _ = check(a, b, method, ref)
            if all(r.multiplicity == 1 for r in ref) and not any(x.tangent for x in out):
                assert sum(x.certified for x in out) == len(ref)
    assert found > 10  # the sample does contain intersections


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(100, 120))
def test_random_pairs_many(seed):
    """20 x 100 random pairs up to degree 4, coordinates up to +-1000 (thousands of checks)."""
    for a, b, ref in random_pairs(seed, 100, max_degree=4, size=1000):
        for method in METHODS:
            check(a, b, method, ref)


def test_exact_routes_agree():
    """intersect_exact (resultants + gcd over Q(alpha)) equals the algebra layer's route."""
    for a, b, ref in random_pairs(7, 15):
        mine = intersect_exact(a, b)
        assert len(mine) == len(ref)
        for r in ref:
            hits = [x for x in mine if x.exact[0] == r.t1 and x.exact[1] == r.t2]
            assert len(hits) == 1 and hits[0].multiplicity == r.multiplicity


def test_exact_method_through_public_entry():
    p = BezierCurve([[0, 0], [1, 2], [2, 0]])
    q = BezierCurve([[0, "1/2"], [2, "1/2"]])
    out = intersect(p, q, method="exact")
    s = sympy.Symbol("s")
    expected = sorted(float(r) for r in sympy.solve(4 * s * (1 - s) - sympy.Rational(1, 2), s))
    assert [round(x.t1, 14) for x in out] == [round(e, 14) for e in expected]
    assert all(x.exact is not None and x.multiplicity == 1 for x in out)


# ------------------------------------------------------------------ rounding-fragile spots (deterministic)
DYADIC_AND_THIRDS = [mpq(1, 2), mpq(1, 4), mpq(3, 4), mpq(1, 8), mpq(5, 8), mpq(1, 1024), mpq(1, 3), mpq(1, 5)]


@pytest.mark.parametrize("r", DYADIC_AND_THIRDS, ids=str)
def test_degree_one_pieces_crossing_at_dyadic_parameters(r):
    """Two segments (degree-1 pieces: both fat-line clips of 7.7 are the crossing itself,
    the case where the root finder's clips crossed by one ulp) meeting at s = r, t = 1/2 and
    at s = t = r.  Every method must return one certified box holding the exact crossing."""
    a = BezierCurve([[0, 0], [1, 0]])
    for b, t in ((BezierCurve([[r, -1], [r, 1]]), mpq(1, 2)), (BezierCurve([[r, -r], [r, 1 - r]]), r)):
        for method in METHODS:
            out, ref = check(a, b, method)
            assert len(ref) == 1 and ref[0].t1 == r and ref[0].t2 == t  # the reference is right
            assert len(out) == 1 and out[0].certified and out[0].contains(r, t), (method, str(r), out)


ENDPOINT_CASES = {
    "shared start points": (BezierCurve([[0, 0], [1, 2], [3, 0]]), BezierCurve([[0, 0], [1, -1], [2, 3]])),
    "end meets start": (BezierCurve([[0, 0], [1, 2], [3, 0]]), BezierCurve([[3, 0], [4, 1], [5, -1]])),
    "segment ends on the curve": (BezierCurve([[0, 0], [1, 2], [3, 0]]), BezierCurve([["5/4", 5], ["5/4", 1]])),
    "segments share an end": (BezierCurve([[0, 0], [1, 1]]), BezierCurve([[1, 1], [2, 0]])),
    "both cross at parameter 1/2": (BezierCurve([[0, 0], [1, 2], [2, 0]]), BezierCurve([[0, 2], [1, -1], [2, 2]])),
    "line through a control vertex": (BezierCurve([[0, 0], [1, 1], [2, 0]]), BezierCurve([[1, -1], [1, 2]])),
    "lines cross at 1/3 and 2/3": (BezierCurve([[0, 0], [3, 3]]), BezierCurve([[0, 3], [3, 0]])),
}


@pytest.mark.parametrize("name", ENDPOINT_CASES)
def test_intersections_at_parameters_0_1_and_half(name):
    """Intersections exactly at t = 0 or 1 (shared ends, T-junctions) and at the midpoint
    where subdivision splits: none missed, all certified, both argument orders."""
    a, b = ENDPOINT_CASES[name]
    for c1, c2 in ((a, b), (b, a)):
        ref = exact_intersect(c1, c2)
        assert ref
        for method in METHODS:
            out, _ = check(c1, c2, method, ref)
            assert len(out) == len(ref) and all(x.certified for x in out), (name, method, out)


# ------------------------------------------------------------------ crossings within a float step of an end
# The crossing parameter s0 = 1 - 2^-k (or 2^-k) differs from the end by less than the float
# resolution of the Krawczyk box around it, so that box contains the end too; whether the
# zero lies inside [0, 1] must be decided exactly.  The partner is a segment through the
# exact point P(s0) with direction END_DIR, met at t0.  References: sympy, from the
# Bernstein sums (nothing from exactcagd).
END_CURVES = {
    "line": ([[0, 0], [3, 1]], None),
    "cubic": ([[0, 0], [1, 3], [2, -1], [3, 1]], None),
    "rational quadratic": ([[0, 0], [1, 2], [2, 0]], [1, 3, 2]),
}
END_DIR = (4, 2)  # transversal to every curve above at both ends
END_KS = (40, 52, 60, 80)


def _sympy_homogeneous(points, weights, s):
    """(N_x(s), N_y(s)), W(s) of a (rational) Bézier curve, from the Bernstein sums in sympy."""
    n = len(points) - 1
    w = weights or [1] * (n + 1)
    basis = [sympy.binomial(n, i) * s**i * (1 - s) ** (n - i) for i in range(n + 1)]
    num = [sum(sympy.Rational(p[k]) * wi * b for p, wi, b in zip(points, w, basis)) for k in range(2)]
    return num, sum(wi * b for wi, b in zip(w, basis))


def end_crossing(name, s0, t0):
    """The curve ``name`` and a segment through its exact point at ``s0`` (reached at ``t0``),
    with every intersection of the two on [0, 1]^2 from sympy: a list of ``(s, t)``."""
    points, weights = END_CURVES[name]
    (nx, ny), w = _sympy_homogeneous(points, weights, sympy.Rational(s0))
    x0 = (nx / w, ny / w)
    a = [x0[k] - t0 * END_DIR[k] for k in range(2)]
    b = [x0[k] + (1 - t0) * END_DIR[k] for k in range(2)]
    segment = BezierCurve([[str(a[0]), str(a[1])], [str(b[0]), str(b[1])]])
    s = sympy.Symbol("s")
    (nx, ny), w = _sympy_homogeneous(points, weights, s)
    # P(s) on the segment's line: cross(END_DIR, N(s) - W(s) x0) = 0 (W > 0 on [0, 1])
    g = sympy.Poly(sympy.expand(END_DIR[0] * (ny - w * x0[1]) - END_DIR[1] * (nx - w * x0[0])), s)
    ref = []
    for r in sympy.real_roots(g):
        if 0 <= r <= 1:
            (px, py), wr = _sympy_homogeneous(points, weights, r)
            t = t0 + ((px / wr - x0[0]) * END_DIR[0] + (py / wr - x0[1]) * END_DIR[1]) / (END_DIR[0] ** 2 + END_DIR[1] ** 2)
            if 0 <= t <= 1:
                ref.append((r, sympy.simplify(t)))
    return BezierCurve(points, weights=weights), segment, ref


def _holds(x, s, t, swap):
    """Exact containment for rational references, 60-digit mpmath for algebraic ones
    (those lie far from every box end)."""
    if swap:
        s, t = t, s
    if s.is_Rational and t.is_Rational:
        return x.contains(mpq(int(s.p), int(s.q)), mpq(int(t.p), int(t.q)))
    sv, tv = sympy.Rational(s.evalf(60)), sympy.Rational(t.evalf(60))
    (a, b), (c, d) = x.t1_interval, x.t2_interval
    return sympy.Rational(a) <= sv <= sympy.Rational(b) and sympy.Rational(c) <= tv <= sympy.Rational(d)


def check_end_crossing(name, s0, t0, expect_s0):
    """Both argument orders, every float method: each reference crossing in exactly one
    returned box, that box certified, nothing else returned."""
    curve, segment, ref = end_crossing(name, s0, t0)
    on_domain = 0 <= s0 <= 1 and 0 <= t0 <= 1
    assert any(r == (s0, t0) for r in ref) == on_domain == expect_s0  # the reference is right
    for c1, c2, swap in ((curve, segment, False), (segment, curve, True)):
        for method in METHODS:
            out = intersect(c1, c2, method=method)
            assert len(out) == len(ref), (name, str(s0), str(t0), method, swap, out)
            for s, t in ref:
                hits = [x for x in out if _holds(x, s, t, swap)]
                assert len(hits) == 1 and hits[0].certified, (name, str(s), str(t), method, swap, out)


@pytest.mark.parametrize("name", END_CURVES)
@pytest.mark.parametrize("end", (0, 1))
def test_crossing_within_a_float_step_of_an_end(name, end):
    """Crossings at s = 1 - 2^-k (2^-k at 0), k = 40, 52, 60, 80, exactly at the end, and
    at 1 + 2^-k (-2^-k) on the polynomial/rational extension, which is no intersection."""
    toward = 1 if end == 0 else -1
    half = sympy.Rational(1, 2)
    check_end_crossing(name, sympy.Integer(end), half, True)
    for k in END_KS:
        e = sympy.Rational(1, 2**k)
        check_end_crossing(name, end + toward * e, half, True)
        check_end_crossing(name, end - toward * e, half, False)


@pytest.mark.parametrize("name", END_CURVES)
@pytest.mark.parametrize("k", (52, 80))
def test_crossing_near_a_corner_of_the_domain(name, k):
    """Both parameters within 2^-k of an end (s near 1, t near 0 and the like), inside or
    just outside on either curve: the box crosses two faces of [0, 1]^2 at once."""
    e = sympy.Rational(1, 2**k)
    for s0, t0 in ((1 - e, e), (e, 1 - e), (1 - e, 1 - e), (1 + e, e), (1 - e, -e), (-e, 1 + e)):
        check_end_crossing(name, s0, t0, 0 <= s0 <= 1 and 0 <= t0 <= 1)


# ------------------------------------------------------------------ worked examples of chapter 7
def test_notes_7_2_homogeneous_lines():
    """7.2: the lines through (2,3),(3,1) and (2,3),(1,4) meet at (2,3); the parallel
    lines 3x+4y+2=0 and 3x+4y+3=0 do not meet (their point is at infinity)."""
    a = BezierCurve([[2, 3], [3, 1]])
    b = BezierCurve([[2, 3], [1, 4]])
    for method in METHODS:
        (x,) = intersect(a, b, method=method)
        assert x.certified and x.contains(0, 0) and x.point == (2.0, 3.0)
    # two segments on the parallel lines (x = -2/3 - 4y/3 ...)
    c = BezierCurve([[-2, 1], [2, -2]])  # 3x + 4y + 2 = 0
    d = BezierCurve([[-3, "3/2"], [1, "-3/2"]])  # 3x + 4y + 3 = 0
    assert 3 * -2 + 4 * 1 + 2 == 0 and 3 * 2 + 4 * -2 + 2 == 0 and 3 * -3 + 6 + 3 == 0
    for method in METHODS:
        assert intersect(c, d, method=method) == []


def test_notes_7_3_parabola_and_unit_circle():
    """7.3: x = 2t - 1, y = 8t^2 - 9t + 1 meets x^2 + y^2 = 1 at t = 0.06118, 0.28147,
    0.90735 and 1 (g(t) = 64t^4 - 144t^3 + 101t^2 - 22t + 1).  The circle is given as
    four rational quadratic quarter arcs (weights 1, 1, 2 on the corner-control net)."""
    parabola = BezierCurve([[-1, 1], [0, "-7/2"], [1, 0]])
    t = sympy.Symbol("t")
    assert sympy.expand(parabola.to_sympy(t)[0] - (2 * t - 1)) == 0
    assert sympy.expand(parabola.to_sympy(t)[1] - (8 * t**2 - 9 * t + 1)) == 0
    corners = [(1, 0), (0, 1), (-1, 0), (0, -1)]
    arcs = []
    for k in range(4):
        p0, p2 = corners[k], corners[(k + 1) % 4]
        arcs.append(BezierCurve([list(p0), [p0[0] + p2[0], p0[1] + p2[1]], list(p2)], weights=[2, 1, 1]))
    g = sympy.Poly(64 * t**4 - 144 * t**3 + 101 * t**2 - 22 * t + 1, t)
    printed = [0.06118, 0.28147, 0.90735, 1.0]
    assert [round(float(r), 5) for r in sorted(sympy.real_roots(g))] == printed
    for method in METHODS:
        found = []
        for arc in arcs:
            found.extend(check(parabola, arc, method)[0])
        ts = sorted({round(x.t1, 5) for x in found})
        assert ts == printed, (method, ts)
        exact = sorted(float(r) for r in sympy.real_roots(g))
        for e in exact:
            assert any(x.t1_interval[0] <= e <= x.t1_interval[1] for x in found)


def test_notes_7_3_rational_example_roots_are_negative():
    """7.3: x = (t^2+t)/(t^2+1), y = 2t/(t^2+1) against x^2 + 2x + y + 1 = 0.  g(t) is as
    printed, but its real roots are t = -1 and t = -0.3576 (printed: 1 and 0.3576;
    ledger sederberg_07_intersection).  The curve is restricted exactly to t in [-2, 0]
    (u = (t + 2)/2) and intersected with the parabola y = -(x + 1)^2, x in [-3, 3]."""
    power = np.array([[0, 0, 1], [1, 2, 0], [1, 0, 1]], dtype=object)  # rows: t^0, t^1, t^2 of (X, Y, W)
    hom = bz.restrict(bz.from_power(np.vectorize(mpq, otypes=[object])(power)), mpq(-2), mpq(0))
    curve = BezierCurve.from_homogeneous(hom)
    parabola = BezierCurve([[-3, -4], [0, 8], [3, -16]])
    t = sympy.Symbol("t")
    g = sympy.expand((t**2 + t) ** 2 + 2 * (t**2 + t) * (t**2 + 1) + 2 * t * (t**2 + 1) + (t**2 + 1) ** 2)
    assert g == 4 * t**4 + 6 * t**3 + 5 * t**2 + 4 * t + 1
    roots = sorted(float(r) for r in sympy.real_roots(sympy.Poly(g, t)))
    assert [round(r, 4) for r in roots] == [-1.0, -0.3576]
    for method in METHODS:
        out, _ = check(curve, parabola, method)
        us = sorted(x.t1 for x in out)
        assert len(out) == 2 and all(x.certified for x in out)
        assert [round(2 * u - 2, 4) for u in us] == [-1.0, -0.3576]


def test_notes_7_3_1_order_of_contact():
    """7.3.1: (1 + t^2, t) touches the unit circle at t = 0 (contact order 2).  The third
    example (1 - t^2, t + t^2) is printed with g = 4t^3 + 3t^4 (contact order 3); in fact
    g = -t^2 + 2t^3 + 2t^4 (sympy below): contact order 2, other roots (-1 +- sqrt 3)/2
    (erratum, ledger sederberg_07_intersection).  Parameters are shifted to the interior
    (t in [-1, 1] -> u = (t+1)/2) so that the touching point is an interior tangency.  The
    float methods must keep the tangency in a box (uncertified is allowed, missing is not)."""
    t = sympy.Symbol("t")
    assert sympy.expand((1 - t**2) ** 2 + (t + t**2) ** 2 - 1) == -(t**2) + 2 * t**3 + 2 * t**4
    circle_right = BezierCurve([[0, -1], [2, -1], [2, 1], [0, 1]], weights=[3, 1, 1, 3])  # x >= 0 half circle
    for X, Y, mult in (((1, 0, 1), (0, 1, 0), 2), ((1, 0, -1), (0, 1, 1), 2)):
        power = np.array([[X[0], Y[0], 1], [X[1], Y[1], 0], [X[2], Y[2], 0]], dtype=object)
        hom = bz.restrict(bz.from_power(np.vectorize(mpq, otypes=[object])(power)), mpq(-1), mpq(1))
        curve = BezierCurve.from_homogeneous(hom)
        ref = exact_intersect(curve, circle_right)
        mine = intersect_exact(curve, circle_right)
        tangent = [r for r in ref if r.t1 == mpq(1, 2)]
        assert len(tangent) == 1 and tangent[0].multiplicity == mult
        assert any(x.multiplicity == mult and x.exact[0] == mpq(1, 2) for x in mine)
        for method in METHODS:
            out, _ = check(curve, circle_right, method)
            (box,) = [x for x in out if x.contains(tangent[0].t1, tangent[0].t2)]
            # a tangency comes back as one point with its exact order (exact fallback)
            assert box.certified and box.kind == "tangent" and box.multiplicity == mult
            assert box.t1_interval[1] - box.t1_interval[0] < 1e-12


@pytest.mark.parametrize("method", ["subdivision", "interval", "clipping"])
def test_fallback_beyond_the_limits_returns_the_uncertified_box(method):
    """A tangency the float routes cannot certify goes to the exact route; when that route
    would exceed exactcagd.limits (here max_implicit_degree lowered below the degree), the
    float route's box comes back uncertified, still holding the point -- no LimitError
    for a float method.  Reference: y = (x - 1/2)^2 touches y = 0 at t = 1/2 (by hand)."""
    from exactcagd import limits

    parabola = BezierCurve([[0, "1/4"], ["1/2", "-1/4"], [1, "1/4"]])
    axis = BezierCurve([[-1, 0], [2, 0]])
    t2 = mpq(1, 2)  # x = -1 + 3 t2 = 1/2 on the axis
    with limits.raised(max_implicit_degree=1):
        out = intersect(parabola, axis, method=method)
    (box,) = [x for x in out if x.contains(mpq(1, 2), t2)]
    assert not box.certified
    answered = intersect(parabola, axis, method=method)  # default limits: the exact route answers
    (exact_box,) = [x for x in answered if x.contains(mpq(1, 2), t2)]
    assert exact_box.certified and exact_box.kind == "tangent" and exact_box.multiplicity == 2


def test_half_circle_control_net_is_a_circle():
    """Sanity of the reference curve above (independent: sympy)."""
    c = BezierCurve([[0, -1], [2, -1], [2, 1], [0, 1]], weights=[3, 1, 1, 3])
    t = sympy.Symbol("t")
    x, y = c.to_sympy(t)
    assert sympy.simplify(x**2 + y**2 - 1) == 0


def test_notes_7_7_8_clip_values():
    """7.7.8: explicit curve E = (-40, -56, -20, 96, 294) against L_min clips t < .1198 (40/334);
    E = (88, 104, 116, 48, -150) against L_max clips t > .8106 (1 - 0.75 * 48/198... = 160.5/198)."""
    e_min = np.array([-40.0, -56.0, -20.0, 96.0, 294.0])
    t0 = left_clip(-e_min)  # clip where e < 0: the curve -e must stay > 0 there
    assert t0 <= 40 / 334 and 40 / 334 - t0 < 1e-12
    e_max = np.array([88.0, 104.0, 116.0, 48.0, -150.0])
    t1 = right_clip(-e_max)
    assert t1 >= 160.5 / 198 and t1 - 160.5 / 198 < 1e-12


def test_notes_7_7_5_multiple_intersections():
    """7.7.5: curves with several intersections (here 9 = 3 x 3, Bezout's maximum) are all
    found by splitting; every one certified."""
    a = BezierCurve([[0, 0], [1, 9], [2, -9], [3, 0]])
    b = BezierCurve([[0, 0], [9, 1], [-9, 2], [0, 3]])
    c = BezierCurve([["-1/5", "1/10"], [1, 6], [2, -6], ["16/5", "1/10"]])
    ref = exact_intersect(a, c)
    assert len(ref) >= 3
    for method in METHODS:
        out, _ = check(a, c, method, ref)
        assert sum(x.certified for x in out) == len(ref)
    ref = exact_intersect(a, b)
    for method in METHODS:
        check(a, b, method, ref)


def test_nine_intersections_of_two_cubics():
    # x = 3-ish wiggles: P(t) crosses y = 0 three times, Q crosses x = 0 three times
    a = BezierCurve([[-1, -4], [-1, 12], [1, -12], [1, 4]])
    b = BezierCurve([[-4, -1], [12, -1], [-12, 1], [4, 1]])
    ref = exact_intersect(a, b)
    assert len(ref) == 9
    for method in METHODS:
        out, _ = check(a, b, method, ref)
        assert len(out) == 9 and all(x.certified for x in out)


def test_rational_curves_extreme_weights():
    arc = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1000, 1])
    line = BezierCurve([[0, 0], [2, 2]])
    ref = exact_intersect(arc, line)
    assert len(ref) == 1
    # subdivision / interval are slow on this one (~10-20 s: the sharp corner at the
    # weight-1000 vertex keeps many box pairs alive); they run in the slow stress tests
    out, _ = check(arc, line, "clipping", ref)
    assert out[0].certified


def test_interval_method_separates_crossings_1e_7_apart():
    """y = x^2 against y = 10^-14 (x = 2s - 1): crossings at s = t = (1 -+ 10^-7)/2 (exact, by
    hand), where the curves are 2 10^-7 apart in slope.  Float evaluation noise of the
    parabola (~1e-15) keeps a band of tol-sized piece pairs alive around each crossing;
    the interval method must still certify both (it ran out of budget: one box of width 1)."""
    parabola = BezierCurve([[-1, 1], [0, -1], [1, 1]])
    line = BezierCurve([[-1, mpq(1, 10**14)], [1, mpq(1, 10**14)]])
    roots = [(1 - mpq(1, 10**7)) / 2, (1 + mpq(1, 10**7)) / 2]
    out = intersect(parabola, line, method="interval")
    assert len(out) == 2 and all(x.certified for x in out), out
    for x, r in zip(out, roots):
        assert x.contains(r, r) and x.t1_interval[1] - x.t1_interval[0] < 1e-8, (x, r)


def test_clipping_history_shows_fast_convergence():
    """7.7: "quadratic convergence" of Bézier clipping near a transversal intersection:
    the parameter widths obey w_{k+1} <= C w_k^2 (measured C ~ 0.13 here; ledger)."""
    from exactcagd.numeric.intersection import _Guard, _clipping, _prepare

    p = BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]])
    q = BezierCurve([[0, 2], [2, 0], [3, 1], [4, -1]])
    c1, c2 = _prepare(p, q)
    hist = []
    _clipping(c1, c2, 64 * 2.0**-53, _Guard(10_000), hist)
    widths = [w for w, _ in hist]
    ratios = [widths[k + 1] / widths[k] ** 2 for k in range(len(widths) - 1) if widths[k + 1] > 1e-14 and widths[k] < 0.2]
    assert len(ratios) >= 2 and max(ratios) < 1.0
    assert widths[-1] < 1e-13 and len(widths) <= 8


# ------------------------------------------------------------------ bad input
def test_bad_input():
    a = BezierCurve([[0, 0], [1, 1]])
    with pytest.raises(InputError):
        intersect(a, a, method="newton")
    with pytest.raises(InputError):
        intersect(a, [[0, 0], [1, 1]])
    with pytest.raises(InputError):
        intersect(a, a, tol=-1)
    with pytest.raises(InputError):
        intersect(a, a, tol="small")
    with pytest.raises(DimensionError):
        intersect(a, BezierCurve([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(DegreeError):
        intersect(a, BezierCurve([[0, 0]]))
    with pytest.raises(WeightError):
        intersect(a, BezierCurve([[0, 0], [1, 2], [2, 0]], weights=[1, -3, 1]))


@pytest.mark.parametrize("method", METHODS + ("exact",))
def test_overlapping_curves_give_the_shared_arc(method):
    """(2s, 2s) and (1 + 2t, 1 + 2t) share the segment s in [1/2, 1], t in [0, 1/2]
    (by hand: 2s = 1 + 2t); asking for the points alone raises."""
    a = BezierCurve([[0, 0], [2, 2]])
    b = BezierCurve([[1, 1], [3, 3]])
    out = intersect(a, b, method=method)
    assert len(out) == 0
    ((S, T),) = [(o.t1_interval, o.t2_interval) for o in out.overlaps]
    assert (S[0], S[1], T[0], T[1]) == (mpq(1, 2), 1, 0, mpq(1, 2))
    with pytest.raises(NotSupportedError):  # OverlapError
        out.points()

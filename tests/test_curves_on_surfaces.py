"""G1 parabola approximation of curves on surfaces (Yang et al. 2012) and the baselines.

References used here, independent of the code under test:
* Theorem 1 / eqs. (10)-(13): end points and end tangent directions of the domain
  parabola checked with sympy (sqrt kept symbolic);
* "lies exactly on the surface": each segment equals S(domain segment) at 2N+1 rational
  parameters, evaluated by a plain tensor de Casteljau written here (two rational
  curves of degree <= N that agree at 2N+1 parameters are identical);
* G1: end tangents from the control points (P'(1) = n w_{n-1}/w_n (P_n - P_{n-1})),
  exact cross products and dot products;
* distance: dense float sampling of the exact image S(D(t)) (exact points) must stay
  below the certified bound.
"""
import math
import random

import numpy as np
import pytest
import sympy
from gmpy2 import mpq
from hypothesis import example, given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface
from exactcagd.curves_on_surfaces import FieldBezierCurve, approximate
from exactcagd.curves_on_surfaces.approximants import hyperbola, parabola, s_parabola, t_parabola
from exactcagd.curves_on_surfaces.domain import DomainCurve
from exactcagd.curves_on_surfaces.hausdorff import hausdorff_bound, piece_bound
from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve
from exactcagd.errors import DomainError, InputError
from exactcagd.exact.quadratic import QuadraticNumber
from exactcagd.reparam import cubic, quadratic

# ----------------------------------------------------------------------------- helpers


def _sym(x):
    if isinstance(x, QuadraticNumber):
        return x.to_sympy()
    x = mpq(x)
    return sympy.Rational(int(x.numerator), int(x.denominator))


def _sym_curve(hom, t):
    """Rational functions of a homogeneous Bézier array (sympy, sqrt symbolic)."""
    n = hom.shape[0] - 1
    comps = [sum(_sym(hom[i, k]) * sympy.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)) for k in range(hom.shape[1])]
    return [c / comps[-1] for c in comps[:-1]]


def _casteljau(values, t):
    level = list(values)
    while len(level) > 1:
        level = [(1 - t) * a + t * b for a, b in zip(level[:-1], level[1:])]
    return level[0]


def _eval_net(hom, u, v):
    """Plain tensor de Casteljau on a homogeneous net, any exact scalars (field points too)."""
    rows = [[_casteljau([hom[i, j, k] for j in range(hom.shape[1])], v) for k in range(hom.shape[2])] for i in range(hom.shape[0])]
    point = [_casteljau([rows[i][k] for i in range(hom.shape[0])], u) for k in range(hom.shape[2])]
    return tuple(x / point[-1] for x in point[:-1])


def _end_tangent(curve, end):
    pts, ws = curve.control_points, curve.weights or (mpq(1),) * (curve.degree + 1)
    n = curve.degree
    if end == 0:
        scale = n * ws[1] / ws[0]
        return [scale * (b - a) for a, b in zip(pts[0], pts[1])]
    scale = n * ws[n - 1] / ws[n]
    return [scale * (b - a) for a, b in zip(pts[n - 1], pts[n])]


def _cross_zero_dot_positive(a, b):
    cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    return all(c == 0 for c in cross) and sum(x * y for x, y in zip(a, b)) > 0


def _patches(S):
    if isinstance(S, BezierSurface):
        return {(0, 0): (((mpq(0), mpq(1)), (mpq(0), mpq(1))), S)}
    return S.to_bezier_patches()


def _assert_on_surface(result, S, which):
    patches = _patches(S)
    for i in which:
        seg, dom = result.segments[i], result.domain_segments[i]
        ((ua, ub), (va, vb)), patch = patches[result.patches[i]]
        N = seg.degree
        for k in range(2 * N + 1):
            t = mpq(k, 2 * N)
            u, v = dom.evaluate(t)
            ref = _eval_net(patch.homogeneous(), (u - ua) / (ub - ua), (v - va) / (vb - va))
            assert tuple(seg.evaluate(t)) == ref


def _float_points(curve, ts):
    if isinstance(curve, FieldBezierCurve):
        return curve.evaluate_float(ts)
    pts, w = curve.to_float()
    w = np.ones(len(pts)) if w is None else w
    hom = np.concatenate([pts * w[:, None], w[:, None]], axis=1)
    out = []
    for t in ts:
        level = hom.copy()
        while len(level) > 1:
            level = (1 - t) * level[:-1] + t * level[1:]
        out.append(level[0, :-1] / level[0, -1])
    return np.array(out)


def _to_polyline(p, poly):
    """Distance of each point of ``p`` to the polyline ``poly`` (float)."""
    a, b = poly[:-1], poly[1:]
    e = b - a
    ee = np.maximum((e * e).sum(-1), 1e-300)
    out = []
    for q in p:
        s = np.clip(((q - a) * e).sum(-1) / ee, 0, 1)
        out.append(np.sqrt(((a + s[:, None] * e - q) ** 2).sum(-1)).min())
    return np.array(out)


def _sampled_distance(result, S, D, samples=600):
    """A (nearly) lower estimate of the Hausdorff distance: exact image points against the
    polyline of dense approximant samples and vice versa (polyline sagitta ~1e-6 here)."""
    lo, hi = (D.domain if isinstance(D, BSplineCurve) else (mpq(0), mpq(1)))
    exact = np.array([[float(x) for x in S.evaluate(*D.evaluate(lo + (hi - lo) * mpq(k, samples)))] for k in range(samples + 1)])
    approx = np.concatenate([_float_points(seg, np.linspace(0, 1, 400)) for seg in result.segments])
    return max(_to_polyline(exact, approx).max(), _to_polyline(approx[::7], exact).max() - 1e-4)


def _check_g1(result, S, i, j):
    """Exact G1 between segments i and j (their coefficients may lie in two different fields).

    The domain tangents at the joint must be positive multiples of one *rational* direction
    D; the surface tangent T = S_u D_u + S_v D_v there (foundation derivative surfaces, exact
    rationals) must be a positive multiple of both image tangents (cross products in one
    field each)."""
    a, b = result.segments[i], result.segments[j]
    assert tuple(a.evaluate(1)) == tuple(b.evaluate(0))
    da, db = _end_tangent(result.domain_segments[i], 1), _end_tangent(result.domain_segments[j], 0)
    k = 0 if da[0] != 0 else 1
    D = [mpq(1) if c == k else _rational(da[c] / da[k]) for c in range(2)]
    if da[k] < 0:
        D = [-x for x in D]
    assert [_rational(x / db[k]) for x in db] == [_rational(x / da[k]) for x in da]
    assert (db[k] > 0) == (da[k] > 0)
    patches = _patches(S)
    ((ua, ub), (va, vb)), patch = patches[result.patches[j]]
    P = result.domain_segments[j].evaluate(0)
    u, v = (_rational(P[0]) - ua) / (ub - ua), (_rational(P[1]) - va) / (vb - va)
    Su, Sv = patch.derivative_u().evaluate(u, v), patch.derivative_v().evaluate(u, v)
    T = [su * D[0] / (ub - ua) + sv * D[1] / (vb - va) for su, sv in zip(Su, Sv)]
    assert _cross_zero_dot_positive(_end_tangent(a, 1), T)
    assert _cross_zero_dot_positive(_end_tangent(b, 0), T)


def _rational(x):
    if isinstance(x, QuadraticNumber):
        assert x.b == 0, f"{x} should be rational"
        return x.a
    return mpq(x)


@pytest.fixture(scope="module")
def face():
    return analytic_surface(5, 5, "face")


@pytest.fixture(scope="module")
def loop():
    return closed_domain_curve(8)


@pytest.fixture(scope="module")
def face_result(face, loop):
    return approximate(face, loop, "1e-2")


# ----------------------------------------------------------------------------- Theorem 1
monotone = st.tuples(
    st.integers(1, 40), st.integers(1, 40),  # chord du, dv (>0)
    st.integers(0, 30), st.integers(1, 30), st.integers(0, 30), st.integers(1, 30),  # m0 n0 m1 n1
    st.sampled_from([1, -1]), st.sampled_from([1, -1]),
)


@settings(max_examples=20, deadline=None)
@given(monotone)
def test_parabola_interpolates_end_data(data):
    """Theorem 1 with (10)-(13): same end points and end tangent directions (sympy, exact)."""
    du, dv, m0, n0, m1, n1, su, sv = data
    p0 = (mpq(1, 10), mpq(1, 5))
    p1 = (p0[0] + su * mpq(du, 50), p0[1] + sv * mpq(dv, 50))
    d0 = (su * mpq(m0, 10), sv * mpq(n0, 10))
    d1 = (su * mpq(m1, 10), sv * mpq(n1, 10))
    a = parabola(p0, d0, p1, d1)
    if m0 == 0 and m1 == 0:
        assert a is None  # no s-parabola (u0 != u1) and no t-parabola (m = 0): the caller splits
        return
    assert a is not None
    t = sympy.Symbol("t")
    u, v = _sym_curve(a.domain_hom(), t)
    du_t, dv_t = sympy.diff(u, t), sympy.diff(v, t)

    def num(expr, end):
        return sympy.N(expr.subs(t, end), 50)

    eps = sympy.Float(10) ** -40
    for end, p, d in ((0, p0, d0), (1, p1, d1)):
        assert abs(num(u, end) - _sym(p[0])) < eps and abs(num(v, end) - _sym(p[1])) < eps
        tu, tv = num(du_t, end), num(dv_t, end)
        scale = abs(tu) + abs(tv)
        assert abs(tu * _sym(d[1]) - tv * _sym(d[0])) < eps * scale  # parallel ...
        assert tu * _sym(d[0]) + tv * _sym(d[1]) > 0  # ... and the same orientation
    # Theorem 1's case split: Type 3 (X >= K) gives an s-parabola, Type 4 a t-parabola
    if m0 and m1:
        X = mpq(du * du, dv * dv)
        K = mpq(m0 * m1, n0 * n1)
        assert a.kind == ("s-parabola" if X >= K else "t-parabola")
    elif m0 == 0 or m1 == 0:
        assert a.kind == "s-parabola" and a.params["type"] == "type-1"


def test_parabola_types_and_degenerate_cases():
    o, e = (mpq(0), mpq(0)), (mpq(1), mpq(1))
    # Type 2: n0 = 0 -> t-parabola
    a = parabola(o, (mpq(1), mpq(0)), e, (mpq(1), mpq(2)))
    assert a.kind == "t-parabola" and a.params["type"] == "type-2"
    # m0 = 0 and n1 = 0 (a quarter-circle-like arc): neither family exists
    assert parabola(o, (mpq(0), mpq(1)), e, (mpq(1), mpq(0))) is None
    # non-monotonic data are rejected
    assert s_parabola(o, (mpq(-1), mpq(1)), e, (mpq(1), mpq(1))) is None
    # iso-parametric data give the straight segment u = const
    a = parabola((mpq(1, 3), mpq(0)), (mpq(0), mpq(1)), (mpq(1, 3), mpq(1)), (mpq(0), mpq(2)))
    assert a.params["type"] == "iso-u" and all(x == mpq(1, 3) for x in a.u_map[0])
    # both roots of (16) are valid parabolas with the same end data
    p0, p1, d0, d1 = o, e, (mpq(1), mpq(1)), (mpq(1), mpq(2))  # k1 = 1, k2 = 1/2
    a, b = s_parabola(p0, d0, p1, d1, "paper"), s_parabola(p0, d0, p1, d1, "other")
    assert a.params["Delta"] == b.params["Delta"] == mpq(1, 2) and a.u_map[0][1] != b.u_map[0][1]
    assert a.u_map[0][1] == (1 - a.u_map[0][1].conjugate()) and a.radicand == 2
    # X = 1 > K = 1/2: Type 3 only, no t-parabola (its Delta is 1 - 2 < 0)
    assert t_parabola(p0, d0, p1, d1) is None


def test_s_parabola_is_iso_line_of_cubic_reparameterization():
    """A rational instance (Delta a square): image == iso-line s = 1/2 of cubic(X_box)."""
    rng = random.Random(4)
    net = [[[rng.randint(-5, 5) for _ in range(3)] for _ in range(3)] for _ in range(4)]
    X = BezierSurface(net, [[rng.randint(1, 3) for _ in range(3)] for _ in range(4)])
    # joint data with Delta = (u1-u0)^2 - k1 k2 = 1/4 - 3/16 = 1/16
    p0, p1 = (mpq(1, 4), mpq(1, 5)), (mpq(3, 4), mpq(4, 5))
    d0, d1 = (mpq(1, 2), mpq(3, 5)), (mpq(3, 8), mpq(3, 5))
    a = s_parabola(p0, d0, p1, d1)
    assert a.radicand is None
    # box: u in [0, 1] (alpha_k = 1 - u_k), v in [v0, v1] -> [0, 1]
    box = X.reparametrize((0, 1), (p0[1], p1[1]))
    alphas = [1 - x for x in a.u_map[0]]
    beta = a.beta
    iso = cubic(box, alphas, (beta, beta, beta)).iso_u(mpq(1, 2))
    image = BezierCurve.from_homogeneous(a.image_hom(X.homogeneous()))
    assert iso.same_curve(image)


def test_hyperbola_is_iso_line_of_quadratic_reparameterization():
    rng = random.Random(8)
    X = BezierSurface([[[rng.randint(-5, 5) for _ in range(3)] for _ in range(3)] for _ in range(3)])
    p0, p1, mid = (mpq(1, 5), mpq(0)), (mpq(4, 5), mpq(1)), (mpq(2, 5), mpq(1, 2))
    a = hyperbola(p0, p1, mid)
    assert a.kind == "s-hyperbola"
    dom = BezierCurve.from_homogeneous(a.domain_hom())
    assert dom.evaluate(mpq(1, 3)) == mid  # u is linear: t* = (2/5 - 1/5) / (4/5 - 1/5) = 1/3
    # eq. (4): alpha(t) = a1 t + a2 (1 - t), u = 1 - alpha(t) on the iso-line s = 1/2
    a1, a2 = 1 - p1[0], 1 - p0[0]
    beta = a.beta
    iso = quadratic(X, (a1, a2), (beta, beta)).iso_u(mpq(1, 2))
    assert iso.same_curve(BezierCurve.from_homogeneous(a.image_hom(X.homogeneous())))


def test_field_image_lies_on_surface_symbolically():
    """Irrational Delta: the image is X(u(t), v(t)) identically (sympy with sqrt)."""
    X = BezierSurface([[[0, 0, 0], [0, 1, 1]], [[1, 0, 2], [1, 1, -1]]], [[1, 2], [3, 1]])
    p0, p1 = (mpq(1, 5), mpq(0)), (mpq(4, 5), mpq(1))
    a = s_parabola(p0, (mpq(1, 2), mpq(1)), p1, (mpq(1, 4), mpq(1)))  # Delta = 9/25 - 1/8 = 47/200
    assert a.radicand is not None and a.params["Delta"] == mpq(47, 200)
    t, u, v = sympy.symbols("t u v")
    ut, vt = _sym_curve(a.domain_hom(), t)
    surf = X.to_sympy(u, v)
    image = _sym_curve(a.image_hom(X.homogeneous()), t)
    for k in range(3):
        diff = sympy.together(surf[k].subs({u: ut, v: vt}, simultaneous=True) - image[k])
        assert sympy.expand(sympy.radsimp(sympy.numer(diff))) == 0


# ----------------------------------------------------------------------------- domain curve cuts
def test_events_irrational_crossing_and_monotonic_split():
    # D(t) = (t, 4 t (1 - t)): crosses v = 1/2 at t = (1 -+ 1/sqrt 2) / 2, v' = 0 at t = 1/2
    dc = DomainCurve(BezierCurve([[0, 0], [mpq(1, 2), 2], [1, 0]]))
    evs = dc.events(0, [mpq(1, 2)], [mpq(1, 2)])
    kinds = [(ev.u_line, ev.v_line, ev.mono_v) for ev in evs]
    assert kinds == [(None, mpq(1, 2), False), (mpq(1, 2), None, True), (None, mpq(1, 2), False)]
    r = evs[0].t
    assert not r.is_rational and abs(float(r) - (1 - 2**-0.5) / 2) < 1e-15
    joint = dc.joint_for_event(0, evs[0])
    assert joint.point[1] == mpq(1, 2) and not joint.exact and joint.lo[1] < joint.hi[1]


# ----------------------------------------------------------------------------- end to end
def test_parabola_end_to_end(face, loop, face_result):
    r = face_result
    assert r.continuity == "G1" and r.g1_verified
    assert r.distance_bound <= mpq(1, 100) and r.degree == 9
    assert all(s.degree == 9 for s in r.segments) and len(r.segments) == len(r.domain_segments)
    # exact G1 at every joint (closed curve: also the seam), independent tangent formula
    n = len(r.segments)
    for i in range(n):
        _check_g1(r, face, i, (i + 1) % n)
    # at least one segment carries sqrt(Delta) exactly
    assert any(isinstance(s, FieldBezierCurve) for s in r.segments)
    # the sampled distance to the exact image stays below the certificate
    assert _sampled_distance(r, face, loop) <= float(r.distance_bound) * (1 + 1e-9)


def test_segments_lie_exactly_on_surface(face, face_result):
    r = face_result
    field = [i for i, s in enumerate(r.segments) if isinstance(s, FieldBezierCurve)]
    _assert_on_surface(r, face, field[:2] + [0])


@pytest.mark.parametrize("method,degree", [("hyperbola", 6), ("polyline", 6)])
def test_baselines(face, loop, method, degree):
    r = approximate(face, loop, "1e-2", method, angle_tol=8)
    assert r.degree == degree and r.distance_bound <= mpq(1, 100) and r.continuity == "eps_T-G1"
    n = len(r.segments)
    for i in range(n):
        a, b = r.segments[i], r.segments[(i + 1) % n]
        ta = np.array([float(x) for x in _end_tangent(a, 1)])
        tb = np.array([float(x) for x in _end_tangent(b, 0)])
        assert math.degrees(math.acos(min(1, ta @ tb / np.linalg.norm(ta) / np.linalg.norm(tb)))) <= 8 + 1e-9
    _assert_on_surface(r, face, [0, n // 2])
    assert _sampled_distance(r, face, loop, 300) <= float(r.distance_bound) * (1 + 1e-9)


def test_rational_surface_and_open_curve():
    rng = random.Random(12)
    S = BezierSurface([[[i, j, rng.randint(-2, 2)] for j in range(3)] for i in range(3)], [[rng.randint(1, 3) for _ in range(3)] for _ in range(3)])
    D = BezierCurve([["1/10", "1/5"], ["1/2", "1"], ["9/10", "0"], ["4/5", "9/10"]])
    r = approximate(S, D, "1e-2")
    assert r.continuity == "G1" and r.degree == 6 and not r.closed
    assert r.domain_segments[0].evaluate(0) == (mpq(1, 10), mpq(1, 5))  # open ends stay exact
    assert r.domain_segments[-1].evaluate(1) == (mpq(4, 5), mpq(9, 10))
    _assert_on_surface(r, S, [0, len(r) - 1])
    assert _sampled_distance(r, S, D, 300) <= float(r.distance_bound) * (1 + 1e-9)


def test_iso_parametric_curve_is_exact():
    S = analytic_surface(4, 4, "face")
    D = BezierCurve([["1/3", "1/10"], ["1/3", "1/2"], ["1/3", "9/10"]])
    r = approximate(S, D, "1e-6")
    assert r.distance_bound == 0 and len(r) == 1
    patch = S.to_bezier_patches()[(0, 0)][1]
    assert r.segments[0].same_curve(patch.iso_u(mpq(1, 3)).reparametrize(mpq(1, 10), mpq(9, 10)))


# ----------------------------------------------------------------------------- Hausdorff bounds
def _hausdorff_case(seed):
    rng = random.Random(seed)
    a = BezierCurve([[rng.randint(0, 20) / 20, k / 3 + rng.randint(-2, 2) / 40] for k in range(4)], [rng.randint(1, 3) for _ in range(4)])
    b = BezierCurve([a.control_points[0], [rng.randint(0, 20) / 20, mpq(1, 2)], a.control_points[-1]])
    return a, b


@settings(max_examples=15, deadline=None)
@given(st.integers(0, 10**6))
@example(446)  # arcs bulging to opposite sides: the foot point jumps, monotone pairing fails
def test_hausdorff_bound_is_an_upper_bound(seed):
    a, b = _hausdorff_case(seed)
    ts = np.linspace(0, 1, 801)
    pa, pb = _float_points(a, ts), _float_points(b, ts)
    h = max(_to_polyline(pa, pb).max(), _to_polyline(pb, pa).max())  # ~ H from below (sagitta ~1e-6)
    hb = hausdorff_bound(a.homogeneous(), b.homogeneous(), mpq(11, 10) * mpq(h) + mpq(1, 10**4))
    assert hb is not None  # certifiable within 10 % of the truth
    assert h <= float(hb) + 1e-9
    assert piece_bound(a.homogeneous(), a.homogeneous()) >= 0


def _sympy_point_distance(p, curve, s):
    """Exact-root distance from the rational point ``p`` to a rational Bézier ``curve``:
    minimum of |C(s) - p| over the real critical points of |C(s) - p|^2 in [0, 1] and the
    ends (sympy, independent of the code under test)."""
    C = _sym_curve(curve.homogeneous(), s)
    d2 = sympy.together(sum((c - _sym(x)) ** 2 for c, x in zip(C, p)))
    num = sympy.Poly(sympy.numer(sympy.together(sympy.diff(d2, s))), s)
    cands = [sympy.Integer(0), sympy.Integer(1)] + [r for r in num.real_roots() if 0 <= r <= 1]
    return min(float(sympy.sqrt(d2.subs(s, r)).evalf(30)) for r in cands)


def test_hausdorff_bound_when_foot_points_jump():
    """Seed 446: A bulges right, B left; the nearest point of B to A(t) jumps, so the
    monotone piece pairing (a Fréchet-like bound) never came within 10 % of H and
    hausdorff_bound returned None.  Reference: exact points of A and B (rational
    parameters), their distance to the other curve from sympy's exact critical points."""
    a, b = _hausdorff_case(446)
    s = sympy.Symbol("s")
    lower = max(
        max(_sympy_point_distance(x.evaluate(mpq(k, 24)), y, s) for k in range(25))
        for x, y in ((a, b), (b, a))
    )
    assert 0.46 < lower < 0.47
    limit = mpq(11, 10) * mpq(lower) + mpq(1, 10**4)
    hb = hausdorff_bound(a.homogeneous(), b.homogeneous(), limit)
    assert hb is not None and lower <= float(hb) and hb <= limit


# ----------------------------------------------------------------------------- degenerate input
def test_degenerate_input(face):
    D = closed_domain_curve(8)
    with pytest.raises(InputError):
        approximate(face, D, 0)
    with pytest.raises(InputError):
        approximate(face, D, "-1/10")
    with pytest.raises(InputError):
        approximate(face, D, "1e-2", method="spline")
    with pytest.raises(InputError):
        approximate(face, BezierCurve([[0, 0, 0], [1, 1, 1]]), "1e-2")
    with pytest.raises(DomainError):  # leaves the domain
        approximate(face, BezierCurve([["1/10", "1/10"], ["5/2", "1/2"], ["1/10", "9/10"]]), "1e-2")
    with pytest.raises(DomainError):  # a point
        approximate(face, BezierCurve([["1/10", "1/10"], ["1/10", "1/10"]]), "1e-2")
    cusp = BezierCurve([["1/10", "1/10"], ["9/10", "9/10"], ["1/10", "9/10"], ["9/10", "1/10"]])
    with pytest.raises(DomainError, match="cusp"):
        approximate(face, cusp, "1e-2")
    r = approximate(face, cusp, "1e-1", on_corner="split")
    assert r.continuity.endswith("(G0 at corners)") and len(r.corners) == 1


def test_corner_of_a_spline_domain_curve(face):
    # interior knot of full multiplicity: a polyline-like corner at (1/2, 1/2)
    D = BSplineCurve([["1/5", "1/5"], ["1/2", "1/2"], ["4/5", "1/5"]], [0, 0, mpq(1, 2), 1, 1])
    with pytest.raises(DomainError, match="corner"):
        approximate(face, D, "1e-2")
    r = approximate(face, D, "1e-2", on_corner="split")
    assert r.corners == [(mpq(1, 2), mpq(1, 2))]


def test_nurbs_surface_exact_joints_and_c0_knot():
    D = closed_domain_curve(8)
    net = [[[i, j, (i * j) % 3] for j in range(4)] for i in range(5)]
    W = [[1 + (i + j) % 2 for j in range(4)] for i in range(5)]
    N = BSplineSurface(net, [0, 0, 0, "1/3", "2/3", 1, 1, 1], [0, 0, 0, "1/2", 1, 1, 1], W)
    r = approximate(N, D, "1e-2")
    assert r.continuity == "G1" and r.degree == 6 and len({p for p in r.patches}) > 2
    _assert_on_surface(r, N, [0, len(r) // 2])
    # a knot of full multiplicity makes the surface only C0 there: G1 of the image cannot hold
    C0 = BSplineSurface(net, [0, 0, 0, "1/2", "1/2", 1, 1, 1], [0, 0, 0, "1/2", 1, 1, 1], W)
    r0 = approximate(C0, D, "1e-1")
    assert r0.continuity.startswith("G0") and r0.g1_verified is False


def test_exact_joint_data_without_rounding():
    S = analytic_surface(4, 4, "face")
    D = closed_domain_curve(8)
    r = approximate(S, D, "1e-2", snap_bits=None)
    assert r.continuity == "G1" and r.distance_bound <= mpq(1, 100)
    # without rounding the joints at shoulder points lie on the domain curve exactly
    dc = DomainCurve(D)
    pts = {dc.point(0, mpq(k, 64)) for k in range(65)}
    assert any(seg.evaluate(0) in pts for seg in r.domain_segments[1:])


# ----------------------------------------------------------------------------- ball certificates (issue 18)
@pytest.mark.parametrize("weights", [None, [1, 3, 1]])
def test_hausdorff_certificate_catches_a_planted_violation(weights):
    """A: the segment (0, 0)-(1, 0) as a (rational) quadratic; B: the same shifted by
    delta = 3/1000 in y.  H(A, B) = delta exactly (reference: the construction).  A limit
    2^-50 below delta must not be certified (the claim H <= limit would be false); a limit
    2^-20 above must be, with a bound in [delta, limit] (the pieces are paired by float foot
    points, which costs ~1e-10 relative here: 2^-50 above delta is out of the method's reach)."""
    from exactcagd.composition import ball
    from exactcagd.curves_on_surfaces.hausdorff import _ball_rows, ball_piece_bound

    delta = mpq(3, 1000)
    a = BezierCurve([[0, 0], ["1/2", 0], [1, 0]], weights).homogeneous()
    b = BezierCurve([[0, delta], ["1/3", delta], [1, delta]]).homogeneous()
    assert hausdorff_bound(a, b, delta * (1 - mpq(1, 2**50))) is None
    stats: dict = {}
    bound = hausdorff_bound(a, b, delta * (1 + mpq(1, 2**20)), stats=stats)
    assert bound is not None and delta <= bound <= delta * (1 + mpq(1, 2**20))
    assert stats.get(ball.BALL, 0) >= 1  # the ball route decided (speed, not the proof)
    with ball.precision():
        quick = ball_piece_bound(_ball_rows(a), _ball_rows(b))
    # both bound the same formula; a zero fat-line width costs the ball sqrt(radius) ~ 1e-17 relative
    assert delta <= quick <= piece_bound(a, b) * (1 + mpq(1, 2**40))

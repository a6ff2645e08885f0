"""The binary64 interval stage of the Hausdorff certificate (issue 18, curves on surfaces).

``hausdorff.float_piece_bounds`` bounds the piece-bound formula of many piece pairs at once
in outward-rounded binary64 intervals.  References, independent of the code under test:

* the formula itself, recomputed here from scratch: exact restriction by de Casteljau on
  ``Fraction`` s, exact squared distances, square roots by ``mpmath`` at 60 digits;
* a planted violation: two parallel segments at distance ``delta`` (``H = delta`` by
  construction) -- a limit ``2^-50`` below ``delta`` must never be accepted;
* the whole algorithm with the interval stage switched off (ball and exact rationals only,
  the route before it existed): the same segments and the same certified bound.
"""
from fractions import Fraction

import mpmath
import numpy as np
import pytest
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.curves_on_surfaces import approximate
from exactcagd.curves_on_surfaces import hausdorff as hd
from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve


# ----------------------------------------------------------------------------- reference
def _restrict_coeffs(points, a, b):
    """Restriction of a Bézier polynomial with vector coefficients to [a, b] (Fractions)."""

    def split(rows, t):
        left, right, level = [rows[0]], [rows[-1]], rows
        while len(level) > 1:
            level = [[(1 - t) * x + t * y for x, y in zip(r0, r1)] for r0, r1 in zip(level[:-1], level[1:])]
            left.append(level[0])
            right.append(level[-1])
        return left, right[::-1]

    rows, _ = split(points, b)
    if a:
        _, rows = split(rows, a / b)
    return rows


def _restrict(hom, a, b):
    """Exact control points of the restriction to [a, b] (two de Casteljau splits, Fractions)."""
    rows = [[Fraction(int(x.numerator), int(x.denominator)) for x in row] for row in hom]
    return [(r[0] / r[2], r[1] / r[2]) for r in _restrict_coeffs(rows, a, b)]


def _seg_sq(p, a, b):
    e = (b[0] - a[0], b[1] - a[1])
    ap = (p[0] - a[0], p[1] - a[1])
    ee = e[0] ** 2 + e[1] ** 2
    s = ap[0] * e[0] + ap[1] * e[1]
    if s <= 0:
        return ap[0] ** 2 + ap[1] ** 2
    if s >= ee:
        return (p[0] - b[0]) ** 2 + (p[1] - b[1]) ** 2
    return ap[0] ** 2 + ap[1] ** 2 - s * s / ee


def _line_sq(p, a, b):
    e = (b[0] - a[0], b[1] - a[1])
    ap = (p[0] - a[0], p[1] - a[1])
    return (ap[0] * e[1] - ap[1] * e[0]) ** 2 / (e[0] ** 2 + e[1] ** 2)


def _sqrt(q):
    with mpmath.workdps(60):
        return mpmath.sqrt(mpmath.mpf(q.numerator) / q.denominator)


def _reference(pa, pb):
    """max over both directions of max_k dist(Q^A_k, [b_0, b_1]) + max_k dist(Q^B_k, line)."""
    out = []
    for x, y in ((pa, pb), (pb, pa)):
        if y[0] == y[-1]:
            return None  # a closed chord: the exact route's other formula (the intervals refuse it)
        part = max(_seg_sq(q, y[0], y[-1]) for q in x)
        delta = max((_line_sq(q, y[0], y[-1]) for q in y[1:-1]), default=Fraction(0))
        out.append(_sqrt(part) + _sqrt(delta))
    return max(out)


# ----------------------------------------------------------------------------- strategies
coord = st.integers(-1000, 1000).map(lambda k: mpq(k, 997))
weight = st.integers(1, 9).map(lambda k: mpq(k, 4))


@st.composite
def curve_and_piece(draw, degree):
    pts = [[draw(coord), draw(coord)] for _ in range(degree + 1)]
    ws = [draw(weight) for _ in range(degree + 1)]
    lo = draw(st.integers(0, 2**20 - 2))
    hi = draw(st.integers(lo + 1, 2**20))
    return BezierCurve(pts, ws).homogeneous(), mpq(lo, 2**20), mpq(hi, 2**20)


@settings(max_examples=40, deadline=None)
@given(curve_and_piece(3), curve_and_piece(2), curve_and_piece(3), curve_and_piece(2))
def test_float_piece_bounds_enclose_the_exact_formula(first, second, third, fourth):
    """Two piece pairs in one call: each interval contains the exact formula value (reference
    above) and is narrow (relative width <= 1e-9: a vacuous interval would fail)."""
    (ha, a0, a1), (hb, b0, b1) = first, second
    (hc, c0, c1), (hd2, d0, d1) = third, fourth
    for A, B, pairs in ((ha, hb, [(a0, a1, b0, b1), (c0, c1, d0, d1)]), (hc, hd2, [(c0, c1, d0, d1), (a0, a1, b0, b1)])):
        ends = [np.array([float(p[k]) for p in pairs]) for k in range(4)]
        lo, hi = hd.float_piece_bounds(hd._float_net(A), hd._float_net(B), *ends)
        for k, (ta, tb, sa, sb) in enumerate(pairs):
            ref = _reference(_restrict(A, Fraction(int(ta.numerator), int(ta.denominator)), Fraction(int(tb.numerator), int(tb.denominator))),
                             _restrict(B, Fraction(int(sa.numerator), int(sa.denominator)), Fraction(int(sb.numerator), int(sb.denominator))))
            if ref is None:
                assert np.isnan(lo[k]) and np.isnan(hi[k])
                continue
            if np.isnan(lo[k]):  # undecided (a chord degenerate in intervals): allowed, never wrong
                continue
            assert mpmath.mpf(lo[k]) <= ref <= mpmath.mpf(hi[k])
            scale = max(abs(float(x)) for x in list(A[:, :2].flat) + list(B[:, :2].flat))
            assert hi[k] - lo[k] <= 1e-9 * float(ref) + 1e-11 * scale


@pytest.mark.parametrize("weights", [None, [1, 3, 1]])
def test_float_certificate_catches_a_planted_violation(weights):
    """A: the segment (0,0)-(1,0) as a (rational) quadratic; B: the same shifted by delta =
    3/1000.  H(A, B) = delta.  On every sub-piece pair the interval must reach delta, so a
    limit 2^-50 below delta is never accepted by it (and the whole certificate refuses)."""
    delta = mpq(3, 1000)
    a = BezierCurve([[0, 0], ["1/2", 0], [1, 0]], weights).homogeneous()
    b = BezierCurve([[0, delta], ["1/2", delta], [1, delta]]).homogeneous()
    ends = np.array([0.0, 0.25, 0.5]), np.array([0.25, 0.5, 1.0])
    lo, hi = hd.float_piece_bounds(hd._float_net(a), hd._float_net(b), *ends, *ends)
    limit = delta * (1 - mpq(1, 2**50))
    assert all(mpq(float(x)) > limit for x in hi)  # not accepted below the true distance
    for k in range(3):
        t = [Fraction(float(e[k])) for e in ends]
        ref = _reference(_restrict(a, *t), _restrict(b, *t))
        assert ref >= mpmath.mpf(delta.numerator) / delta.denominator  # the formula bounds H
        assert mpmath.mpf(lo[k]) <= ref <= mpmath.mpf(hi[k])
    assert hd.hausdorff_bound(a, b, limit) is None
    bound = hd.hausdorff_bound(a, b, delta * (1 + mpq(1, 2**20)))
    assert bound is not None and delta <= bound


def test_batch_foot_points_equal_the_scalar_ones():
    """The level-at-once foot points (used to cut B) are bit-identical to the scalar search."""
    hf = hd._float_hom(BezierCurve([[0, 0], ["1/3", 1], ["2/3", "-1/2"], [1, "1/4"]], [1, 2, 3, 1]).homogeneous())
    foot = hd._Footer(hf)
    rng = np.random.default_rng(3)
    points = rng.uniform(-0.2, 1.2, (200, 2))
    los = rng.uniform(0, 1, 200)
    his = np.minimum(los + rng.uniform(1e-6, 0.5, 200), 1.0)
    his[:5] = 1.0
    los[5:10] = 0.0
    batch = foot.many(points, los, his)
    assert [float(x) for x in batch] == [foot(p, float(lo), float(hi)) for p, lo, hi in zip(points, los, his)]


@pytest.mark.parametrize("method, tol", [("parabola", "1e-3"), ("hyperbola", "1e-2")])
def test_interval_stage_changes_no_output(monkeypatch, method, tol):
    """With the interval stage switched off (ball, then exact rationals: the route before it)
    the result is the same: segments, domain segments, certified bound, everything."""
    S, D = analytic_surface(5, 5, "face"), closed_domain_curve(8)
    decided = []
    original = hd.float_piece_bounds

    def counting(*args):
        lo, hi = original(*args)
        decided.append(int(np.isfinite(hi).sum()))
        return lo, hi

    monkeypatch.setattr(hd, "float_piece_bounds", counting)
    fast = approximate(S, D, tol, method)
    assert sum(decided) > 0  # the interval stage ran and bounded pieces
    monkeypatch.setattr(hd, "_float_net", lambda *args: None)
    slow = approximate(S, D, tol, method)
    a, b = fast.to_dict(), slow.to_dict()
    a.pop("timings"), b.pop("timings")
    assert a == b
    assert sum(fast.certified_by.values()) == sum(slow.certified_by.values())


def test_lazy_certificate_value_lies_in_its_interval():
    """The driver refines only the candidates for the largest bound: a certificate's value
    (computed later, outside any precision context) lies in [lower, upper] and equals the
    bound hausdorff_bound returns at once; the true distance (sympy-free: the arc's apex
    height, 1/8 here) is below it."""
    a = BezierCurve([[0, 0], ["1/2", "1/4"], [1, 0]]).homogeneous()  # apex (1/2, 1/8)
    b = BezierCurve([[0, 0], ["1/3", 0], ["2/3", 0], [1, 0]]).homogeneous()
    cert = hd.hausdorff_certificate(a, b, mpq(1, 2))
    value = cert.value()
    assert cert.lower <= value <= cert.upper <= mpq(1, 2)
    assert value == hd.hausdorff_bound(a, b, mpq(1, 2)) and value >= mpq(1, 8)


@settings(max_examples=15, deadline=None)
@given(st.integers(0, 4).flatmap(lambda lv: st.tuples(st.just(lv), st.integers(0, 2**lv - 1), st.integers(0, 2**lv - 1))), st.booleans())
def test_derivative_cell_bounds_equal_the_restricted_nets(cell, rational):
    """Cell bounds (max |S_u|^2, max |S_v|^2 of the control points of the derivative nets on
    a dyadic cell, computed with flint matrices) equal the same maxima over nets restricted
    here by two de Casteljau splits per axis in Fractions."""
    from exactcagd import BezierSurface
    from exactcagd.curves_on_surfaces.surface_grid import SurfaceGrid

    level, cu, cv = cell
    net = [[[i, j, (i * j + i) % 3 - 1] for j in range(3)] for i in range(4)]
    weights = [[1 + (i + 2 * j) % 3 for j in range(3)] for i in range(4)] if rational else None
    grid = SurfaceGrid(BezierSurface(net, weights))
    got = grid._cell_bounds((0, 0), level, cu, cv)
    n = 2**level
    for axis_net, value in zip(grid.derivative_nets((0, 0)), got):
        rows = [[[Fraction(int(x.numerator), int(x.denominator)) for x in axis_net[i, j]] for j in range(axis_net.shape[1])] for i in range(axis_net.shape[0])]
        cols = [_restrict_coeffs([rows[i][j] for i in range(len(rows))], Fraction(cu, n), Fraction(cu + 1, n)) for j in range(len(rows[0]))]
        rows = [[cols[j][i] for j in range(len(cols))] for i in range(len(rows))]
        rows = [_restrict_coeffs(r, Fraction(cv, n), Fraction(cv + 1, n)) for r in rows]
        best = max(sum(x * x for x in p[:-1]) / (p[-1] * p[-1]) for r in rows for p in r)
        assert Fraction(int(value.numerator), int(value.denominator)) == best


@pytest.mark.parametrize("kind", ["segment", "hyperbola", "parabola"])
def test_domain_form_evaluates_to_the_coordinate_maps(kind):
    """The planar homogeneous form (U W_v, V W_u, W_u W_v) of an approximant equals
    (u(t), v(t)) = (U/W_u, V/W_v) at 9 rational parameters (reference: Fraction de Casteljau
    of each map separately)."""
    from exactcagd.curves_on_surfaces.approximants import hyperbola, parabola, segment

    p0, p1 = (mpq(1, 10), mpq(1, 7)), (mpq(5, 9), mpq(8, 9))
    a = {"segment": lambda: segment(p0, p1),
         "hyperbola": lambda: hyperbola(p0, p1, (mpq(1, 3), mpq(1, 2))),
         "parabola": lambda: parabola(p0, (mpq(0), mpq(1)), p1, (mpq(1), mpq(1)))}[kind]()  # Type 1: rational
    assert a is not None and a.radicand is None

    def value(coeffs, t):
        level = [Fraction(int(mpq(c).numerator), int(mpq(c).denominator)) for c in coeffs]
        while len(level) > 1:
            level = [(1 - t) * x + t * y for x, y in zip(level[:-1], level[1:])]
        return level[0]

    hom = a.domain_hom()
    for k in range(9):
        t = Fraction(k, 8)
        w = value(hom[:, 2], t)
        assert value(hom[:, 0], t) / w == value(a.u_map[0], t) / value(a.u_map[1], t)
        assert value(hom[:, 1], t) / w == value(a.v_map[0], t) / value(a.v_map[1], t)


def test_limits_beyond_the_float_range():
    """A limit past the largest binary64 number (10^400) is met with the exact bound; a tiny
    one (10^-400, below the smallest subnormal) is refused (reference: H = 1/8 from the
    construction, an arc of apex height 1/8 over its chord)."""
    a = BezierCurve([[0, 0], ["1/2", "1/4"], [1, 0]]).homogeneous()
    b = BezierCurve([[0, 0], [1, 0]]).homogeneous()
    bound = hd.hausdorff_bound(a, b, mpq(10) ** 400)
    assert bound is not None and mpq(1, 8) <= bound <= mpq(1, 4)
    assert hd.hausdorff_bound(a, b, mpq(1, 10**400)) is None


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 3), st.integers(0, 3), st.booleans(), st.randoms(use_true_random=False))
def test_flint_bernstein_product_is_the_product(m, n, field, rng):
    """bernstein_product (flint scaled forms) evaluates, at m + n + 1 rational parameters, to
    the product of the two factors' values (de Casteljau in QuadraticNumber arithmetic):
    two polynomials of degree m + n that agree there are equal."""
    from exactcagd.exact.quadratic import QuadraticNumber
    from exactcagd.reparam._mechanism import bernstein_product

    def q():
        return mpq(rng.randint(-99, 99), rng.randint(1, 50))

    a = [QuadraticNumber(q(), q(), 7) if field and rng.random() < 0.6 else q() for _ in range(m + 1)]
    b = [q() for _ in range(n + 1)]
    c = bernstein_product(a, b)
    assert len(c) == m + n + 1

    def value(coeffs, t):
        level = list(coeffs)
        while len(level) > 1:
            level = [(1 - t) * x + t * y for x, y in zip(level[:-1], level[1:])]
        return level[0]

    for k in range(m + n + 1):
        t = mpq(k + 1, m + n + 3)
        assert value(list(c), t) == value(a, t) * value(b, t)


@pytest.mark.parametrize("level", [0, 2, 4])
def test_derivative_bound_is_not_below_a_corner_value(level):
    """S(u, v) = (u, v, u v) (reference: sympy derivatives, exact): at the corner (1, 1),
    |S_u|^2 + |S_v|^2 = 2 + 2 = 4, the largest over [0, 1]^2.  The cell bound of the corner
    cell must reach it; a claim 2^-50 below it would be false."""
    import sympy

    from exactcagd import BezierSurface
    from exactcagd.curves_on_surfaces.surface_grid import SurfaceGrid

    u, v = sympy.symbols("u v")
    X = sympy.Matrix([u, v, u * v])
    true = sum(c**2 for c in X.diff(u).subs({u: 1, v: 1})) + sum(c**2 for c in X.diff(v).subs({u: 1, v: 1}))
    assert true == 4
    grid = SurfaceGrid(BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]))
    side = mpq(1, 2**level)
    bound = grid.lipschitz_sq((0, 0), (1 - side, 1), (1 - side, 1))
    assert bound >= 4 > 4 * (1 - mpq(1, 2**50))
    assert bound <= 4 + 4 * side  # tight on small cells (|S_u|^2 <= 1 + v^2 on the cell)

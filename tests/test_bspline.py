"""B-spline / NURBS curves and surfaces against an independent Cox-de Boor recursion.

The reference basis functions are computed in this test (plain recursion on
``fractions.Fraction``, and piecewise sympy polynomials per knot span), never by
exactcagd's de Boor / Boehm code.
"""

from fractions import Fraction

import pytest
import sympy as sp
from _sympy_ref import R, S, T, cox_de_boor, cox_de_boor_sym, frac, positive_rationals, small_rationals, spline_point
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface
from exactcagd.errors import DomainError, InexactInputError, InputError, KnotError, WeightError
from exactcagd.exact import knots as kn

FAST = settings(max_examples=12, deadline=None)


@st.composite
def knot_vectors(draw, p=None, max_extra=4):
    """Clamped knot vector (standard convention) with random interior knots (multiplicity <= p)."""
    p = draw(st.integers(1, 3)) if p is None else p
    a = draw(st.fractions(min_value=-2, max_value=1, max_denominator=4))
    length = draw(st.fractions(min_value=Fraction(1, 2), max_value=3, max_denominator=4))
    b = a + length
    interior = sorted(a + length * Fraction(j, 6) for j in draw(st.lists(st.integers(1, 5), max_size=max_extra)))
    # cap multiplicities at p
    capped = []
    for x in interior:
        if capped.count(x) < p:
            capped.append(x)
    knots = [a] * (p + 1) + capped + [b] * (p + 1)
    return p, knots


@st.composite
def splines(draw, rational=None, dim=None):
    p, knots = draw(knot_vectors())
    n = len(knots) - p - 1
    d = draw(st.integers(1, 3)) if dim is None else dim
    pts = draw(st.lists(st.lists(small_rationals, min_size=d, max_size=d), min_size=n, max_size=n))
    is_rat = draw(st.booleans()) if rational is None else rational
    w = draw(st.lists(positive_rationals, min_size=n, max_size=n)) if is_rat else None
    return p, knots, pts, w


def between(draw, a, b, n=17, open_=False):
    """A random rational in [a, b] (or (a, b)) on a grid of n steps."""
    a, b = Fraction(int(a.numerator), int(a.denominator)), Fraction(int(b.numerator), int(b.denominator))
    j = draw(st.integers(1, n - 1) if open_ else st.integers(0, n))
    return a + (b - a) * Fraction(j, n)


def params_in(knots, p, draw, count=3):
    a, b = knots[p], knots[-p - 1]
    ts = [a, b] + [k for k in knots if a < k < b]
    ts += [between(draw, a, b) for _ in range(count)]
    return ts


def frac_tuple(point):
    return tuple(frac(x) for x in point)


def spline_piece_sym(pts, knots, p, span, weights=None, t=T):
    """The spline on one knot span as sympy rational functions (reference)."""
    n = len(pts)
    basis = [cox_de_boor_sym(i, p, knots, t, span) for i in range(n)]
    w = [1] * n if weights is None else [R(x) for x in weights]
    den = sum(b * wi for b, wi in zip(basis, w))
    return [sum(b * wi * R(pt[k]) for b, wi, pt in zip(basis, w, pts)) / den for k in range(len(pts[0]))]


def same(a, b):
    for x, y in zip(a, b):
        nx, dx = sp.fraction(sp.together(x))
        ny, dy = sp.fraction(sp.together(y))
        if sp.expand(nx * dy - ny * dx) != 0:
            return False
    return len(a) == len(b)


# ---------------------------------------------------------------- de Boor vs Cox-de Boor
def test_reference_partition_of_unity():
    """Sanity of the test's own Cox-de Boor: the basis sums to one on the domain."""
    knots = [0, 0, 0, Fraction(1, 3), Fraction(1, 3), 1, 2, 2, 2]
    for t in [0, Fraction(1, 7), Fraction(1, 3), Fraction(5, 4), 2]:
        assert sum(cox_de_boor(i, 2, knots, t) for i in range(6)) == 1


@given(splines(), st.data())
@FAST
def test_de_boor_matches_cox_de_boor(spline, data):
    p, knots, pts, w = spline
    c = BSplineCurve(pts, knots, w)
    assert c.degree == p and c.domain == (knots[p], knots[-p - 1])
    for t in params_in(knots, p, data.draw):
        assert frac_tuple(c.evaluate(t)) == spline_point(pts, knots, p, t, w)
        assert c(t) == c.evaluate(t)


@given(splines(), st.data())
@FAST
def test_knot_insertion_preserves_spline(spline, data):
    p, knots, pts, w = spline
    c = BSplineCurve(pts, knots, w)
    a, b = c.domain
    x = between(data.draw, a, b, 9, open_=True)
    room = p - kn.multiplicity(c.knots, mpq(x))
    if room <= 0:
        with pytest.raises(KnotError):
            c.insert_knot(x)
        return
    times = data.draw(st.integers(1, room))
    c2 = c.insert_knot(x, times)
    assert len(c2.control_points) == len(pts) + times
    assert list(c2.knots) == sorted(list(c.knots) + [mpq(x)] * times)
    assert c2.is_rational == c.is_rational
    for t in params_in(knots, p, data.draw, 4) + [x]:
        assert frac_tuple(c2.evaluate(t)) == spline_point(pts, knots, p, t, w)
    # the new control polygon defines the same function for the new knot vector (independent reference)
    new_pts = [[frac(v) for v in q] for q in c2.control_points]
    new_w = None if w is None else [frac(v) for v in c2.weights]
    for t in params_in(knots, p, data.draw, 2):
        assert spline_point(new_pts, [frac(k) for k in c2.knots], p, t, new_w) == spline_point(pts, knots, p, t, w)


@given(splines(), st.data())
@FAST
def test_bezier_extraction_reproduces_each_span(spline, data):
    p, knots, pts, w = spline
    c = BSplineCurve(pts, knots, w)
    pieces = c.to_bezier()
    spans = [(x, y) for x, y in zip(c.breakpoints()[:-1], c.breakpoints()[1:])]
    assert [span for span, _ in pieces] == spans
    for (a, b), piece in pieces:
        assert isinstance(piece, BezierCurve) and piece.degree == p
        # at random rational parameters
        for _ in range(3):
            t = between(data.draw, frac(a), frac(b), 13)
            s = (mpq(t) - a) / (b - a)
            assert frac_tuple(piece.evaluate(s)) == spline_point(pts, knots, p, t, w)
        # as polynomials / rational functions on the span
        ref = spline_piece_sym(pts, knots, p, (frac(a), frac(b)), w, T)
        ref = [e.subs(T, R(a) + (R(b) - R(a)) * S) for e in ref]
        assert same(list(piece.to_sympy(S)), ref)


def test_bezier_extraction_with_double_knot_and_continuity():
    """Across a knot of multiplicity k the pieces are C^(p-k) (notes 6.4) -- checked on the pieces."""
    pts = [[0, 0], [1, 2], [3, 3], [4, 0], [6, 1], [7, 4]]
    c = BSplineCurve(pts, [0, 0, 0, 0, 1, 1, 2, 2, 2, 2])  # cubic, double knot at 1
    (s1, left), (s2, right) = c.to_bezier()
    assert s1 == (0, 1) and s2 == (1, 2)
    assert left.evaluate(1) == right.evaluate(0)
    assert left.derivative().evaluate(1) == right.derivative().evaluate(0)
    assert left.derivative().derivative().evaluate(1) != right.derivative().derivative().evaluate(0)


def test_single_span_spline_is_its_bezier_curve():
    pts = [[0, 0], [1, 3], [2, -1], [4, 2]]
    c = BSplineCurve(pts, [0, 0, 0, 0, 1, 1, 1, 1])
    [((a, b), piece)] = c.to_bezier()
    assert (a, b) == (0, 1) and piece.control_points == BezierCurve(pts).control_points


# ---------------------------------------------------------------- surfaces
@st.composite
def spline_surfaces(draw, rational=None):
    p, ku = draw(knot_vectors(max_extra=2))
    q, kv = draw(knot_vectors(max_extra=2))
    nu, nv = len(ku) - p - 1, len(kv) - q - 1
    d = draw(st.integers(1, 3))
    net = draw(st.lists(st.lists(st.lists(small_rationals, min_size=d, max_size=d), min_size=nv, max_size=nv), min_size=nu, max_size=nu))
    is_rat = draw(st.booleans()) if rational is None else rational
    w = draw(st.lists(st.lists(positive_rationals, min_size=nv, max_size=nv), min_size=nu, max_size=nu)) if is_rat else None
    return (p, ku), (q, kv), net, w


def surface_point(net, ku, p, kv, q, u, v, w=None):
    nu, nv = len(net), len(net[0])
    bu = [cox_de_boor(i, p, ku, u) for i in range(nu)]
    bv = [cox_de_boor(j, q, kv, v) for j in range(nv)]
    ww = [[Fraction(1)] * nv for _ in range(nu)] if w is None else [[Fraction(x) for x in row] for row in w]
    den = sum(bu[i] * bv[j] * ww[i][j] for i in range(nu) for j in range(nv))
    return tuple(
        sum(bu[i] * bv[j] * ww[i][j] * Fraction(net[i][j][k]) for i in range(nu) for j in range(nv)) / den
        for k in range(len(net[0][0]))
    )


@given(spline_surfaces(), st.data())
@settings(max_examples=8, deadline=None)
def test_surface_evaluate_and_patches(surface, data):
    (p, ku), (q, kv), net, w = surface
    s = BSplineSurface(net, ku, kv, w)
    assert s.degree == (p, q) and s.shape == (len(net), len(net[0]))
    us, vs = params_in(ku, p, data.draw, 1), params_in(kv, q, data.draw, 1)
    for u in us[:4]:
        for v in vs[:4]:
            assert frac_tuple(s.evaluate(u, v)) == surface_point(net, ku, p, kv, q, u, v, w)
    patches = s.to_bezier_patches()
    bu, bv = s.breakpoints()
    assert set(patches) == {(i, j) for i in range(len(bu) - 1) for j in range(len(bv) - 1)}
    for (i, j), ((ua, ub), (va, vb)), patch in ((k, sp_, pt) for k, (sp_, pt) in patches.items()):
        assert (ua, ub) == (bu[i], bu[i + 1]) and (va, vb) == (bv[j], bv[j + 1])
        assert isinstance(patch, BezierSurface) and patch.degree == (p, q) and patch.is_rational == (w is not None)
        u = between(data.draw, frac(ua), frac(ub), 11)
        v = between(data.draw, frac(va), frac(vb), 11)
        point = patch.evaluate((mpq(u) - ua) / (ub - ua), (mpq(v) - va) / (vb - va))
        assert frac_tuple(point) == surface_point(net, ku, p, kv, q, u, v, w)


def test_surface_patches_as_polynomials_and_span_selection():
    net = [[[i, j, (i * j) % 3 - i + 2 * j] for j in range(4)] for i in range(3)]
    ku, kv = [0, 0, 0, 1, 1, 1], [0, 0, 1, 2, 3, 3]  # degree 2 x 1
    w = [[1, 2, 1, 3], [2, 1, 1, 1], [1, 1, 4, 2]]
    s = BSplineSurface(net, ku, kv, w)
    patches = s.to_bezier_patches()
    assert len(patches) == 3
    for (i, j), ((ua, ub), (va, vb)), patch in ((k, a, b) for k, (a, b) in patches.items()):
        bu = [cox_de_boor_sym(a, 2, ku, U_, (ua, ub)) for a in range(3)]
        bv = [cox_de_boor_sym(b, 1, kv, V_, (va, vb)) for b in range(4)]
        den = sum(bu[a] * bv[b] * w[a][b] for a in range(3) for b in range(4))
        ref = [sum(bu[a] * bv[b] * w[a][b] * net[a][b][k] for a in range(3) for b in range(4)) / den for k in range(3)]
        sub = {U_: R(ua) + (R(ub) - R(ua)) * S, V_: R(va) + (R(vb) - R(va)) * T}
        ref = [e.subs(sub, simultaneous=True) for e in ref]
        assert same(list(patch.to_sympy(S, T)), ref)
    only = s.to_bezier_patches(v_spans={1})
    assert set(only) == {(0, 1)} and only[(0, 1)][1] == patches[(0, 1)][1]
    chosen = s.to_bezier_patches(pairs={(0, 0), (0, 2)})
    assert set(chosen) == {(0, 0), (0, 2)} and all(chosen[k] == patches[k] for k in chosen)


U_, V_ = sp.symbols("u v")


@given(spline_surfaces(), st.data())
@settings(max_examples=8, deadline=None)
def test_surface_knot_insertion_preserves(surface, data):
    (p, ku), (q, kv), net, w = surface
    s = BSplineSurface(net, ku, kv, w)
    (ua, ub), (va, vb) = s.domain
    x = between(data.draw, frac(ua), frac(ub), 7, open_=True)
    y = between(data.draw, frac(va), frac(vb), 7, open_=True)
    s2 = s
    if kn.multiplicity(s.knots_u, mpq(x)) < p:
        s2 = s2.insert_knot_u(x)
        assert s2.shape[0] == s.shape[0] + 1
    if kn.multiplicity(s.knots_v, mpq(y)) < q:
        s2 = s2.insert_knot_v(y)
        assert s2.shape[1] == s.shape[1] + 1
    for u in params_in(ku, p, data.draw, 1)[:3] + [x]:
        for v in params_in(kv, q, data.draw, 1)[:3] + [y]:
            assert frac_tuple(s2.evaluate(u, v)) == surface_point(net, ku, p, kv, q, u, v, w)


# ---------------------------------------------------------------- accessors
def test_accessors():
    c = BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], knots=[0, 0, 0, 1, 2, 2, 2], weights=[1, 2, 1, 1])
    assert c.knots == tuple(mpq(k) for k in [0, 0, 0, 1, 2, 2, 2])
    assert c.breakpoints() == (0, 1, 2) and c.is_rational and c.dimension == 2
    assert c.to_dict()["weights"] == ["1", "2", "1", "1"]
    assert "NURBS" in repr(c)
    s = BSplineSurface([[[i, j, 0] for j in range(3)] for i in range(3)], [0, 0, 1, 2, 2], [0, 0, 0, 1, 1, 1])
    assert s.domain == ((0, 2), (0, 1)) and s.breakpoints() == ((0, 1, 2), (0, 1))
    assert s.to_dict()["knots_u"] == ["0", "0", "1", "2", "2"]
    assert kn.from_notes_knots([1, 1, 1, 5, 5, 5]) == tuple(mpq(k) for k in [1, 1, 1, 1, 5, 5, 5, 5])


# ---------------------------------------------------------------- bad input
GOOD_PTS = [[0, 0], [1, 1], [2, 0], [3, 1]]


@pytest.mark.parametrize(
    "knots, error",
    [
        ([0, 0, 0, 1, 2, 2], KnotError),  # too short
        ([0, 0, 0, 1, 1, 2, 2, 2], KnotError),  # too long
        ([0, 0, 0, 2, 1, 2, 2], KnotError),  # decreasing
        ([2, 2, 2, 1, 0, 0, 0], KnotError),  # decreasing overall
        ([1, 1, 1, 1, 1, 1, 1], KnotError),  # empty domain
        ([0, 0, 0, float("nan"), 2, 2, 2], InexactInputError),
        ([0, 0, 0, "x", 2, 2, 2], InputError),
    ],
)
def test_bad_knot_vectors(knots, error):
    with pytest.raises(error):
        BSplineCurve(GOOD_PTS, knots, degree=2 if len(knots) in (6, 7) else None)


@pytest.mark.parametrize(
    "knots",
    [
        [0, 0, 1, 1, 2, 2, 3],  # not clamped at the start
        [0, 0, 0, 1, 2, 3, 3],  # not clamped at the end
        [0, 0, 0, 0, 2, 2, 2],  # end multiplicity above p + 1: the first basis function vanishes on the domain
    ],
)
def test_unclamped_knot_vectors_are_accepted(knots):
    """One class for every knot vector (issue 19.4): the domain is ``[knots[2], knots[4]]`` and the
    point at a domain end is the sympy Cox-de Boor sum there (an independent reference)."""
    import sympy

    c = BSplineCurve(GOOD_PTS, knots, degree=2)
    assert c.domain == (knots[2], knots[4])
    t = sympy.Symbol("t")
    basis = sympy.bspline_basis_set(2, [sympy.Integer(k) for k in knots], t)
    curve = [sum(b * p[k] for b, p in zip(basis, GOOD_PTS)) for k in range(2)]
    lo, hi = (sympy.Integer(x) for x in c.domain)
    last = max(sympy.Integer(k) for k in knots if k < hi)
    for end in c.domain:
        if end == c.domain[0]:  # sympy's basis is half-open on the right: the left end is inside
            ref = [x.subs(t, lo) for x in curve]
        else:  # the right end is the limit of the last span's quadratic: interpolate 3 inner points
            inner = [last + (hi - last) * sympy.Rational(j, 4) for j in (1, 2, 3)]
            ref = [sympy.interpolate([(u, x.subs(t, u)) for u in inner], t).subs(t, hi) for x in curve]
        assert [sympy.Rational(str(x)) for x in c.evaluate(end)] == ref


def test_interior_multiplicity_above_degree():
    with pytest.raises(KnotError):
        BSplineCurve([[0], [1], [2], [3], [4]], [0, 0, 0, 1, 1, 1, 2, 2, 2])


def test_degree_mismatch_and_too_few_knots():
    with pytest.raises(InputError):
        BSplineCurve(GOOD_PTS, [0, 0, 0, 1, 2, 2, 2], degree=3)
    with pytest.raises(InputError):
        BSplineCurve(GOOD_PTS, [0, 1, 2])


@pytest.mark.parametrize(
    "points, weights, error",
    [
        ([[0, 0], [1]], None, InputError),
        ([0, 1, 2, 3], None, InputError),
        (GOOD_PTS, [1, 2, 3], WeightError),
        (GOOD_PTS, [1, 2, 3, 4, 5], WeightError),
        (GOOD_PTS, [1, 0, 1, 1], WeightError),
        (GOOD_PTS, [1, 1, "-1/3", 1], WeightError),
        (GOOD_PTS, [1, 1, float("inf"), 1], InexactInputError),
    ],
)
def test_bad_points_and_weights(points, weights, error):
    with pytest.raises(error):
        BSplineCurve(points, [0, 0, 0, 1, 2, 2, 2], weights)


def test_parameters_outside_domain():
    c = BSplineCurve(GOOD_PTS, [0, 0, 0, 1, 2, 2, 2])
    for t in [-1, "-1/1000", "2001/1000", 3]:
        with pytest.raises(DomainError):
            c.evaluate(t)
    with pytest.raises(InexactInputError):
        c.evaluate(float("nan"))
    for t in [0, 2, 5]:
        with pytest.raises(DomainError):
            c.insert_knot(t)
    c.insert_knot(1)  # multiplicity 2 = p is allowed
    with pytest.raises(KnotError):
        c.insert_knot(1, 2)
    with pytest.raises(KnotError):
        c.insert_knot("1/2", 3)


def test_bad_surfaces():
    net = [[[i, j, 0] for j in range(3)] for i in range(3)]
    ku, kv = [0, 0, 1, 2, 2], [0, 0, 0, 1, 1, 1]
    with pytest.raises(InputError):
        BSplineSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0]]], ku, kv)
    with pytest.raises(KnotError):
        BSplineSurface(net, [0, 1, 1, 2, 2], kv)
    with pytest.raises(KnotError):
        BSplineSurface(net, ku, [0, 0, 0, 1, 1, 2])
    with pytest.raises(InputError):
        BSplineSurface(net, ku, [0, 0, 0, 1, 1])
    with pytest.raises(WeightError):
        BSplineSurface(net, ku, kv, weights=[[1, 1, 1], [1, 1, 1]])
    with pytest.raises(WeightError):
        BSplineSurface(net, ku, kv, weights=[[1, 1, 1], [1, 0, 1], [1, 1, 1]])
    s = BSplineSurface(net, ku, kv)
    with pytest.raises(DomainError):
        s.evaluate(3, 0)
    with pytest.raises(DomainError):
        s.evaluate(0, "3/2")
    with pytest.raises(DomainError):
        s.insert_knot_v(1)
    with pytest.raises(KnotError):
        s.insert_knot_u(1)  # already multiplicity 1 = p


def test_knot_insertion_count_must_be_a_non_negative_integer():
    c = BSplineCurve(GOOD_PTS, [0, 0, 0, 1, 2, 2, 2])
    for times in (-1, "1/2", 1.5, True, None):
        with pytest.raises(InputError, match="times must be a non-negative integer"):
            c.insert_knot("1/2", times)
    assert c.insert_knot("1/2", 0).knots == c.knots  # zero insertions: unchanged
    s = BSplineSurface([[[i, j, 0] for j in range(3)] for i in range(3)], [0, 0, 1, 2, 2], [0, 0, 0, 1, 1, 1])
    with pytest.raises(InputError, match="times"):
        s.insert_knot_v("1/2", -2)


def test_knot_messages_name_the_vector_and_the_degree():
    """Errors say which knot vector (knots / knots_u / knots_v) and what it was checked for."""
    with pytest.raises(KnotError, match="knots: expected a sequence"):
        BSplineCurve(GOOD_PTS, None)
    with pytest.raises(KnotError, match="knots: expected a sequence"):
        BSplineCurve(GOOD_PTS, "0 0 0 1 2 2 2")
    with pytest.raises(KnotError, match=r"knots \(5 knots, 4 control points, degree 0\)"):
        BSplineCurve(GOOD_PTS, [0, 0, 1, 2, 2])  # degree 0 inferred from the count
    net = [[[i, j, 0] for j in range(3)] for i in range(3)]
    with pytest.raises(KnotError, match=r"knots_v .*decreases at index 3"):
        BSplineSurface(net, [0, 0, 1, 2, 2], [0, 0, 0, 1, "1/2", 1])
    with pytest.raises(KnotError, match="knots_u: 3 knots are too few"):
        BSplineSurface(net, [0, 0, 1], [0, 0, 0, 1, 1, 1])
    with pytest.raises(InexactInputError, match=r"knots_v\[3\]"):
        BSplineSurface(net, [0, 0, 1, 2, 2], [0, 0, 0, float("inf"), 1, 1])

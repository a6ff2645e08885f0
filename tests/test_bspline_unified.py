"""One B-spline curve class for every knot vector (issue 19.4).

``geometry.BSplineCurve`` accepts clamped and unclamped knot vectors and carries the
polar-form operations that used to live in ``toolbox.SplineCurve`` (now the same class).
References are independent of the code under test: sympy's Cox-de Boor basis
(``sympy.bspline_basis_set``) and sympy substitution into the pieces.
"""

from __future__ import annotations

import pickle
from fractions import Fraction

import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from exactcagd.errors import DomainError, KnotError
from exactcagd.geometry.bspline import BSplineCurve
from exactcagd.toolbox import bspline_extras as bx

FAST = settings(max_examples=12, deadline=None)
T = sympy.Symbol("t")


@st.composite
def unclamped_curves(draw, max_degree=3, dim=2, rational=False):
    """A random curve on a knot vector whose first and last ``p + 1`` knots are not all equal."""
    p = draw(st.integers(1, max_degree))
    n = draw(st.integers(p + 1, p + 3))
    gaps = draw(st.lists(st.integers(1, 3), min_size=n + p, max_size=n + p))
    ks = [Fraction(0)]
    for g in gaps:
        ks.append(ks[-1] + Fraction(g, 2))
    # an optional interior knot of multiplicity up to p (lo < v < hi) keeps the vector valid
    if n > p + 1 and draw(st.booleans()):
        i = draw(st.integers(p + 1, n - 1))
        m = draw(st.integers(2, p)) if p > 1 else 1
        ks = ks[:i] + [ks[i]] * m + ks[i + 1 : len(ks) - m + 1]  # same length, still non-decreasing
    coords = st.integers(-4, 4).map(Fraction)
    pts = draw(st.lists(st.lists(coords, min_size=dim, max_size=dim), min_size=n, max_size=n))
    weights = draw(st.lists(st.integers(1, 4).map(Fraction), min_size=n, max_size=n)) if rational else None
    return BSplineCurve(pts, ks, weights=weights), pts, ks, weights


def cox_de_boor(pts, ks, p, weights=None):
    """The curve as sympy expressions by ``sympy.bspline_basis_set`` (independent reference)."""
    basis = sympy.bspline_basis_set(p, [sympy.Rational(k.numerator, k.denominator) for k in ks], T)
    w = [1] * len(pts) if weights is None else [sympy.Rational(x.numerator, x.denominator) for x in weights]
    den = sum(b * wi for b, wi in zip(basis, w))
    return [sum(b * wi * sympy.Rational(q[k].numerator, q[k].denominator) for b, wi, q in zip(basis, w, pts)) / den
            for k in range(len(pts[0]))]


def sample_parameters(c):
    """Left end, interior knots and three points inside every span (sympy's basis is half-open on the right)."""
    out = []
    for l in c.spans():
        a, b = c.knots[l], c.knots[l + 1]
        out += [a + (b - a) * Fraction(i, 4) for i in range(4)]
    return out


def as_sympy(x):
    return sympy.Rational(int(x.numerator), int(x.denominator))


@given(unclamped_curves())
@FAST
def test_evaluation_agrees_with_sympy_cox_de_boor(case):
    c, pts, ks, _w = case
    ref = cox_de_boor(pts, ks, c.degree)
    for t in sample_parameters(c):
        assert [as_sympy(x) for x in c.evaluate(t)] == [r.subs(T, as_sympy(t)) for r in ref]


@given(unclamped_curves(max_degree=2, rational=True))
@FAST
def test_rational_evaluation_agrees_with_sympy_cox_de_boor(case):
    c, pts, ks, w = case
    ref = cox_de_boor(pts, ks, c.degree, w)
    for t in sample_parameters(c)[::2]:
        assert [as_sympy(x) for x in c.evaluate(t)] == [sympy.simplify(r.subs(T, as_sympy(t))) for r in ref]


@given(unclamped_curves())
@FAST
def test_right_end_of_the_domain(case):
    """At ``hi = knots[n]`` sympy's half-open basis already belongs to the next span, but the
    generated vectors continue beyond ``hi`` with ``hi`` of multiplicity <= p, so the spline
    is continuous there and the Cox-de Boor sum at ``hi`` is the curve's end point."""
    c, pts, ks, _w = case
    hi = c.domain[1]
    assert hi < ks[-1] and ks.count(hi) <= c.degree
    ref = cox_de_boor(pts, ks, c.degree)
    assert [as_sympy(x) for x in c.evaluate(hi)] == [r.subs(T, as_sympy(hi)) for r in ref]


@given(unclamped_curves())
@FAST
def test_to_sympy_and_bezier_pieces_agree_with_evaluation(case):
    c, _pts, _ks, _w = case
    expr = c.to_sympy(T)
    pieces = c.to_bezier()
    assert [span for span, _ in pieces] == [(c.knots[l], c.knots[l + 1]) for l in c.spans()]
    for (a, b), piece in pieces:
        for i in range(3):
            t = a + (b - a) * Fraction(i, 2)
            assert piece.evaluate(Fraction(i, 2)) == c.evaluate(t)
            assert [expr[k].subs(T, as_sympy(t)) for k in range(c.dimension)] == [as_sympy(x) for x in c.evaluate(t)]


@given(unclamped_curves(), st.data())
@FAST
def test_clamp_insert_and_elevate_keep_the_curve(case, data):
    c, _pts, _ks, _w = case
    lo, hi = c.domain
    clamped = c.clamp()
    assert clamped.is_clamped and not c.is_clamped
    assert clamped.control_points[0] == c.evaluate(lo) and clamped.control_points[-1] == c.evaluate(hi)
    t = lo + (hi - lo) * Fraction(data.draw(st.integers(1, 6)), 7)
    assume(c.knots.count(t) < c.degree)  # a knot already of multiplicity p cannot be inserted again
    inserted = c.insert_knot(t)
    elevated = c.elevate()
    assert elevated.degree == c.degree + 1
    for s in sample_parameters(c):
        assert clamped.evaluate(s) == inserted.evaluate(s) == elevated.evaluate(s) == c.evaluate(s)


@given(unclamped_curves(rational=True))
@FAST
def test_value_equality_hash_and_round_trips(case):
    c, pts, ks, w = case
    twin = BSplineCurve(pts, ks, weights=w)
    assert c == twin and hash(c) == hash(twin)
    assert BSplineCurve.from_dict(c.to_dict()) == c
    assert pickle.loads(pickle.dumps(c)) == c
    moved = BSplineCurve([[x + 1 for x in q] for q in pts], ks, weights=w)
    assert moved != c


def test_toolbox_spline_curve_is_the_geometry_class():
    assert bx.SplineCurve is BSplineCurve
    c = bx.SplineCurve([[0, 0], [1, 2], [3, 2], [4, 0]], range(7))
    assert isinstance(c, BSplineCurve) and not c.is_clamped
    assert c.evaluate(3) == (2, 2)  # uniform quadratic at a knot: the midpoint (P1 + P2)/2
    assert bx.periodic_bspline([[0, 0], [2, 0], [2, 2], [0, 2]], 2) == bx.periodic_bspline([[0, 0], [2, 0], [2, 2], [0, 2]], 2)


def test_unclamped_errors_name_the_argument():
    c = BSplineCurve([[0, 0], [1, 1], [2, 0]], [0, 1, 2, 3, 4, 5])
    with pytest.raises(DomainError):
        c.evaluate(9)
    with pytest.raises(KnotError, match="knots"):
        BSplineCurve([[0, 0], [1, 1], [2, 0]], [0, 1, 1, 1, 2, 3])  # interior knot 1 of multiplicity 3 > degree 2


def test_composition_across_patches_with_an_unclamped_domain_curve():
    """compose_spline reads the curve through to_bezier: an unclamped domain curve gives the same
    pieces as its clamped twin, and every piece is the surface at the curve (de Boor, checked above
    against sympy) at a rational point inside and at the rational ends."""
    from exactcagd.composition import compose_spline
    from exactcagd.composition.splines import rational_between
    from exactcagd.exact.algebraic import RealAlgebraic
    from exactcagd.geometry.bspline import BSplineSurface

    F = Fraction
    net = [[[F(i, 4), F(j, 4), F((i * i + 2 * j * j + i * j) % 5, 5)] for j in range(5)] for i in range(5)]
    surface = BSplineSurface(net, [0, 0, 0, F(1, 3), F(2, 3), 1, 1, 1], [0, 0, 0, F(1, 2), F(1, 2), 1, 1, 1])
    pts = [[F(1, 10), F(1, 10)], [F(9, 10), F(2, 10)], [F(5, 10), F(9, 10)], [F(1, 10), F(6, 10)]]
    curve = BSplineCurve(pts, [F(-1, 2), F(-1, 4), 0, F(1, 2), 1, F(5, 4), F(3, 2)])
    assert not curve.is_clamped and curve.domain == (0, 1)
    result = compose_spline(surface, curve)
    twin = compose_spline(surface, curve.clamp())
    assert [piece.interval for piece in result.pieces] == [piece.interval for piece in twin.pieces]
    for piece in result.pieces:
        a, b = piece.interval
        inner = rational_between(a, b)
        assert piece.evaluate(inner) == surface.evaluate(*curve.evaluate(inner))
        for end in (a, b):
            if not isinstance(end, RealAlgebraic):
                assert piece.evaluate(end) == surface.evaluate(*curve.evaluate(end))


@given(unclamped_curves(rational=True))
@FAST
def test_float_sampling_of_unclamped_curves(case):
    """numeric.sampling's vectorised Cox-de Boor (basis_matrix) on an unclamped curve: within 1e-12
    of the exact point, domain ends included."""
    import numpy as np

    from exactcagd.numeric.sampling import sample_curve

    c, _pts, _ks, _w = case
    lo, hi = c.domain
    ts = [lo + (hi - lo) * Fraction(i, 8) for i in range(9)]
    got = sample_curve(c, np.array([float(t) for t in ts]))
    want = np.array([[float(x) for x in c.evaluate(t)] for t in ts])
    assert np.allclose(got, want, rtol=0, atol=1e-12 * (1 + np.abs(want).max()))


def test_bezier_extraction_of_degree_zero_splines():
    """Degree 0: each non-empty span is the constant of its own control point (a repeated
    knot makes an empty span whose point never shows); the exact layer's extraction used to
    hand every span the first point."""
    import numpy as np

    from exactcagd.exact.knots import extract_bezier

    points = np.array([[1], [2], [3], [4]], dtype=object)
    pieces = extract_bezier(points, (0, 1, 2, 2, 3), 0)
    assert [(a, b) for (a, b), _ in pieces] == [(0, 1), (1, 2), (2, 3)]
    assert [int(c[0][0]) for _, c in pieces] == [1, 2, 4]


def _left_limit(basis, x, end, knots, degree):
    """Limit from the left at ``end`` of a piecewise polynomial of degree ``degree``: exact
    interpolation of ``degree + 1`` points inside the last non-empty span (sympy.limit on a
    Piecewise fails on the sympy 1.10 floor)."""
    end = sympy.Rational(end)
    last = max(sympy.Rational(k) for k in knots if sympy.Rational(k) < end)
    inner = [last + (end - last) * sympy.Rational(j, degree + 2) for j in range(1, degree + 2)]
    return sympy.interpolate([(t, basis.subs(x, t)) for t in inner], x).subs(x, end)


def _cox_de_boor_surface(net, knots_u, knots_v, p, q, weights, u, v):
    """Independent reference: sympy.bspline_basis_set in u and v, tensor product, projected.
    At the right domain end the last non-empty basis functions are taken as the limit from the left."""
    x, y = sympy.symbols("x y")
    bu = sympy.bspline_basis_set(p, [sympy.Rational(k) for k in knots_u], x)
    bv = sympy.bspline_basis_set(q, [sympy.Rational(k) for k in knots_v], y)
    at_u = [_left_limit(b, x, u, knots_u, p) if u == knots_u[-1] else b.subs(x, u) for b in bu]
    at_v = [_left_limit(b, y, v, knots_v, q) if v == knots_v[-1] else b.subs(y, v) for b in bv]
    dim = len(net[0][0])
    hom = [0] * (dim + 1)
    for i, row in enumerate(net):
        for j, point in enumerate(row):
            w = 1 if weights is None else sympy.Rational(weights[i][j])
            basis = at_u[i] * at_v[j] * w
            for k in range(dim):
                hom[k] += basis * sympy.Rational(point[k])
            hom[dim] += basis
    return tuple(sympy.nsimplify(h / hom[dim]) for h in hom[:dim])


@pytest.mark.parametrize("rational", [False, True])
def test_surface_to_sympy_matches_evaluate_and_cox_de_boor(rational):
    """BSplineSurface.to_sympy at random exact (u, v) (knots and domain corners included) equals
    evaluate() and an independent tensor-product Cox-de Boor (sympy.bspline_basis_set)."""
    import random

    from exactcagd.geometry.bspline import BSplineSurface

    rng = random.Random(19 + rational)
    knots_u, knots_v = [0, 0, 0, 1, 3, 3, 3], [0, 0, 1, Fraction(5, 2), 4, 4]  # degrees (2, 1)
    net = [[[rng.randint(-5, 5), rng.randint(-5, 5), rng.randint(-5, 5)] for _ in range(4)] for _ in range(4)]
    weights = [[Fraction(rng.randint(1, 6), rng.randint(1, 3)) for _ in range(4)] for _ in range(4)] if rational else None
    s = BSplineSurface(net, knots_u, knots_v, weights)
    u, v = sympy.symbols("u v")
    expr = s.to_sympy()
    assert expr.shape == (3, 1)
    points = [(0, 0), (3, 4), (1, 1), (3, Fraction(5, 2))]
    points += [(Fraction(rng.randint(0, 300), 100), Fraction(rng.randint(0, 400), 100)) for _ in range(6)]
    for a, b in points:
        got = tuple(expr.subs({u: sympy.Rational(a), v: sympy.Rational(b)}))
        want = _cox_de_boor_surface(net, knots_u, knots_v, 2, 1, weights, sympy.Rational(a), sympy.Rational(b))
        assert got == want, (a, b)
        assert got == tuple(sympy.Rational(int(x.numerator), int(x.denominator)) for x in s.evaluate(a, b))
    assert s._repr_latex_().startswith("$S(u, v) = ")
    assert all(isinstance(row, sympy.Piecewise) for row in expr)

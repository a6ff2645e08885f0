"""BezierSurface (polynomial and rational) against sympy formulas built in the test.

Reference: F(u, v) = sum w_ij P_ij B_i^l(u) B_j^m(v) / sum w_ij B_i^l(u) B_j^m(v)
(notes 003 (15.2); Lasser & Bonneau (000) (2), (4)).
"""

import pytest
import sympy as sp
from _sympy_ref import R, U, V, positive_rationals, rational_curve, same_function, small_rationals, tensor_sum, unit_params
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve, BezierSurface
from exactcagd.errors import DegreeError, DimensionError, DomainError, InexactInputError, InputError, WeightError

FAST = settings(max_examples=10, deadline=None)
S_, T_ = sp.symbols("s t")


@st.composite
def surfaces(draw, rational=None, max_degree=(3, 2), dim=None):
    l = draw(st.integers(0, max_degree[0]))
    m = draw(st.integers(0, max_degree[1]))
    d = draw(st.integers(1, 3)) if dim is None else dim
    net = draw(st.lists(st.lists(st.lists(small_rationals, min_size=d, max_size=d), min_size=m + 1, max_size=m + 1), min_size=l + 1, max_size=l + 1))
    is_rat = draw(st.booleans()) if rational is None else rational
    w = draw(st.lists(st.lists(positive_rationals, min_size=m + 1, max_size=m + 1), min_size=l + 1, max_size=l + 1)) if is_rat else None
    return net, w


def surface_expr(s, u=U, v=V):
    net = [[[R(x) for x in p] for p in row] for row in s.control_net]
    w = None if s.weights is None else [[R(x) for x in row] for row in s.weights]
    return tensor_sum(net, u, v, w)


def curve_expr(c, t):
    pts = [[R(x) for x in p] for p in c.control_points]
    w = [1] * len(pts) if c.weights is None else [R(x) for x in c.weights]
    return rational_curve(pts, w, t)


def same(a, b):
    return len(a) == len(b) and all(same_function(x, y) for x, y in zip(a, b))


# ---------------------------------------------------------------- evaluation
@given(surfaces(), unit_params, unit_params)
@FAST
def test_evaluate_matches_definition(data, u, v):
    net, w = data
    s = BezierSurface(net, w)
    ref = tensor_sum(net, U, V, w)
    expected = tuple(e.subs({U: R(u), V: R(v)}) for e in ref)
    assert tuple(R(x) for x in s.evaluate(u, v)) == expected
    assert s(u, v) == s.evaluate(u, v)
    assert same(list(s.to_sympy(U, V)), ref)
    assert s.degree == (len(net) - 1, len(net[0]) - 1) and s.dimension == len(net[0][0])


def test_order_of_directions_irrelevant_lasser_II():
    """Lasser & Bonneau II: "algorithms in u and in v commute" -- evaluating the iso
    curves in either order gives the same point."""
    net = [[[0, 0, 1], [1, 0, 2], [2, 1, 0]], [[0, 1, 3], [1, 1, -1], [2, 2, 2]], [[0, 3, 0], [1, 2, 1], [3, 3, 3]]]
    s = BezierSurface(net, [[1, 2, 1], [3, 1, 2], [1, 1, 4]])
    for u, v in [("1/3", "2/5"), ("0", "1/2"), ("7/8", "1")]:
        assert s.iso_u(u).evaluate(v) == s.iso_v(v).evaluate(u) == s.evaluate(u, v)


def test_corners_and_boundaries():
    net = [[[i, j, i * j + 1] for j in range(4)] for i in range(3)]
    s = BezierSurface(net)
    assert s.evaluate(0, 0) == tuple(net[0][0]) and s.evaluate(1, 0) == tuple(net[2][0])
    assert s.evaluate(0, 1) == tuple(net[0][3]) and s.evaluate(1, 1) == tuple(net[2][3])
    b = s.boundary_curves()
    assert b["u0"].control_points == tuple(tuple(mpq(x) for x in p) for p in net[0])
    assert b["v1"].control_points == tuple(tuple(mpq(x) for x in row[3]) for row in net)
    assert b["u0"].degree == 3 and b["v0"].degree == 2


# ---------------------------------------------------------------- iso-parameter curves
@given(surfaces(), unit_params)
@FAST
def test_iso_curves_are_substitutions(data, c):
    net, w = data
    s = BezierSurface(net, w)
    ref = tensor_sum(net, U, V, w)
    iu, iv = s.iso_u(c), s.iso_v(c)
    assert isinstance(iu, BezierCurve) and iu.degree == s.degree[1] and iv.degree == s.degree[0]
    assert iu.is_rational == iv.is_rational == (w is not None)
    assert same(curve_expr(iu, T_), [e.subs({U: R(c), V: T_}) for e in ref])
    assert same(curve_expr(iv, T_), [e.subs({V: R(c), U: T_}) for e in ref])


# ---------------------------------------------------------------- subdivision / reparametrization / elevation
@given(surfaces(), unit_params)
@FAST
def test_subdivision_reproduces_surface(data, c):
    net, w = data
    s = BezierSurface(net, w)
    ref = tensor_sum(net, U, V, w)
    cq = R(c)
    a, b = s.subdivide_u(c)
    assert same(surface_expr(a, S_, T_), [e.subs({U: cq * S_, V: T_}) for e in ref])
    assert same(surface_expr(b, S_, T_), [e.subs({U: cq + (1 - cq) * S_, V: T_}) for e in ref])
    lo, hi = s.subdivide_v(c)
    assert same(surface_expr(lo, S_, T_), [e.subs({U: S_, V: cq * T_}) for e in ref])
    assert same(surface_expr(hi, S_, T_), [e.subs({U: S_, V: cq + (1 - cq) * T_}) for e in ref])


@given(surfaces(max_degree=(2, 2)), st.tuples(unit_params, unit_params), st.tuples(unit_params, unit_params))
@FAST
def test_reparametrize_is_substitution(data, ur, vr):
    net, w = data
    if ur[0] == ur[1] or vr[0] == vr[1]:
        with pytest.raises(DomainError):
            BezierSurface(net, w).reparametrize(ur, vr)
        return
    s = BezierSurface(net, w)
    r = s.reparametrize(ur, vr)
    ref = tensor_sum(net, U, V, w)
    sub = {U: R(ur[0]) + (R(ur[1]) - R(ur[0])) * S_, V: R(vr[0]) + (R(vr[1]) - R(vr[0])) * T_}
    assert same(surface_expr(r, S_, T_), [e.subs(sub, simultaneous=True) for e in ref])


@given(surfaces(max_degree=(2, 2)), st.integers(0, 2), st.integers(0, 2))
@FAST
def test_elevation_preserves_surface(data, ru, rv):
    net, w = data
    s = BezierSurface(net, w)
    e = s.elevate(ru, rv)
    assert e.degree == (s.degree[0] + ru, s.degree[1] + rv)
    assert same(surface_expr(e), tensor_sum(net, U, V, w))


# ---------------------------------------------------------------- derivatives and normals
@given(surfaces(max_degree=(2, 2)))
@FAST
def test_partial_derivatives_match_sympy(data):
    net, w = data
    s = BezierSurface(net, w)
    ref = tensor_sum(net, U, V, w)
    du, dv = s.derivative_u(), s.derivative_v()
    assert same(surface_expr(du), [sp.diff(e, U) for e in ref])
    assert same(surface_expr(dv), [sp.diff(e, V) for e in ref])
    if w is None:
        assert du.degree == (max(s.degree[0] - 1, 0), s.degree[1])
    else:
        assert du.degree == (2 * s.degree[0], 2 * s.degree[1])


@given(surfaces(dim=3, max_degree=(3, 3)))
@FAST
def test_corner_normals_match_cross_product_of_sympy_diffs(data):
    net, w = data
    s = BezierSurface(net, w)
    ref = sp.Matrix(tensor_sum(net, U, V, w))
    fu, fv = ref.diff(U), ref.diff(V)
    normals = s.corner_normals()
    assert set(normals) == {(0, 0), (1, 0), (0, 1), (1, 1)}
    for (cu, cv), n in normals.items():
        at = {U: cu, V: cv}
        expected = fu.subs(at).cross(fv.subs(at))
        assert [R(x) for x in n] == [sp.cancel(x) for x in expected]


def test_corner_normals_need_3d():
    with pytest.raises(DimensionError):
        BezierSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]]).corner_normals()


# ---------------------------------------------------------------- accessors
def test_accessors_and_round_trips():
    net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    s = BezierSurface(net, [[1, 2], [3, "1/2"]])
    assert s.weights == ((1, 2), (3, mpq(1, 2)))
    assert s.homogeneous().shape == (2, 2, 4)
    assert list(s.homogeneous()[0, 1]) == [0, 2, 0, 2]
    assert s.net_array().shape == (2, 2, 3)
    assert s.to_dict()["weights"] == [["1", "2"], ["3", "1/2"]]
    p = BezierSurface(net)
    assert (p.weights_array() == 1).all() and p.weights is None
    assert BezierSurface.from_homogeneous(s.homogeneous()) == s
    assert hash(BezierSurface(net)) == hash(p) and p != s
    f, fw = s.to_float()
    assert f.dtype == float and fw[1, 1] == 0.5


# ---------------------------------------------------------------- bad input
@pytest.mark.parametrize(
    "net, weights, error",
    [
        ([[[0, 0, 0], [1, 0, 0]], [[0, 1, 0]]], None, InputError),  # ragged rows
        ([[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1]]], None, InputError),  # ragged points
        ([[0, 0, 0], [1, 0, 0]], None, InputError),  # a curve, not a net
        ([], None, InputError),
        ([[[0, 0], [1, 0]], [[0, 1], [1, 1]]], [1, 2, 3, 4], WeightError),  # wrong weight shape
        ([[[0, 0], [1, 0]], [[0, 1], [1, 1]]], [[1, 2]], WeightError),
        ([[[0, 0], [1, 0]], [[0, 1], [1, 1]]], [[1, 2], [0, 1]], WeightError),  # zero
        ([[[0, 0], [1, 0]], [[0, 1], [1, 1]]], [[1, 2], [1, -3]], WeightError),  # negative
        ([[[0, 0], [1, float("nan")]], [[0, 1], [1, 1]]], None, InexactInputError),
        ([[[0, 0], [1, 0]], [[0, 1], [1, 1]]], [[1, 2], [float("inf"), 1]], InexactInputError),
    ],
)
def test_bad_construction(net, weights, error):
    with pytest.raises(error):
        BezierSurface(net, weights)


def test_bad_parameters():
    s = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    with pytest.raises(DomainError):
        s.evaluate("-1/2", 0)
    with pytest.raises(DomainError):
        s.evaluate(0, 2)
    assert s.evaluate(2, 0, extrapolate=True) == (2, 0, 0)
    with pytest.raises(DomainError):
        s.iso_u(3)
    with pytest.raises(DomainError):
        s.iso_v(-1)
    with pytest.raises(DomainError):
        s.subdivide_u("5/4")
    with pytest.raises(DomainError):
        s.subdivide_v(-1)
    with pytest.raises(InexactInputError):
        s.evaluate(float("nan"), 0)
    with pytest.raises(DegreeError):
        s.elevate(-1, 0)
    with pytest.raises(DegreeError):
        s.elevate(0, 1.5)

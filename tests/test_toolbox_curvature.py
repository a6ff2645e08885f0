"""exactcagd.toolbox.curvature and .triangular against sympy differential geometry and closed forms.

References: first and second fundamental forms computed with sympy from the rational
parametrization (derivatives of ``r = N/W`` by Leibniz), closed-form curvatures of
spheres, ellipsoids and cylinders, and sympy expansions of triangular Bernstein sums.
"""

import numpy as np
import pytest
import sympy as sp
from _sympy_ref import R, U, V, small_rationals
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st
from test_toolbox_surfaces import derivs, patches, polys, positive

from exactcagd import BezierCurve, BezierSurface
from exactcagd.errors import DegreeError, DimensionError, DomainError, InputError, WeightError
from exactcagd.toolbox import curvature as cv
from exactcagd.toolbox.triangular import TriangularBezier

SYMPY = settings(max_examples=6, deadline=None)
T = sp.Symbol("t")


def fundamental(d):
    ru, rv = sp.Matrix(d["Pu"]), sp.Matrix(d["Pv"])
    N = ru.cross(rv)
    E, F, G = ru.dot(ru), ru.dot(rv), rv.dot(rv)
    L, M, Nn = sp.Matrix(d["Puu"]).dot(N), sp.Matrix(d["Puv"]).dot(N), sp.Matrix(d["Pvv"]).dot(N)
    NN = N.dot(N)
    K = (L * Nn - M**2) / (NN * (E * G - F**2))
    X = L * G - 2 * M * F + Nn * E
    return K, X**2 / (4 * NN * (E * G - F**2) ** 2), sp.sign(X)


def as_ref(res):
    return R(res.gaussian), R(res.mean_squared), res.mean_sign


@given(patches(max_deg=3))
@settings(max_examples=4, deadline=None)
def test_corner_curvature_all_corners(case):
    net, w = case
    S = BezierSurface(net, w)
    N, W = polys(net, w)
    for corner in ((0, 0), (1, 0), (0, 1), (1, 1)):
        d = derivs(N, W, *corner)
        if sp.Matrix(d["Pu"]).cross(sp.Matrix(d["Pv"])) == sp.zeros(3, 1):
            with pytest.raises(DomainError):
                cv.corner_curvature(S, corner)
            continue
        assert as_ref(cv.corner_curvature(S, corner)) == fundamental(d), corner


@given(patches(max_deg=2), st.fractions(0, 1, max_denominator=5), st.fractions(0, 1, max_denominator=5))
@SYMPY
def test_curvature_anywhere(case, u, v):
    net, w = case
    S = BezierSurface(net, w)
    d = derivs(*polys(net, w), R(u), R(v))
    if sp.Matrix(d["Pu"]).cross(sp.Matrix(d["Pv"])) == sp.zeros(3, 1):
        return
    res = cv.surface_curvature(S, u, v)
    assert as_ref(res) == fundamental(d)
    k1, k2 = res.principal()
    H = sp.sqrt(R(res.mean_squared)) * res.mean_sign
    disc = sp.sqrt(R(res.mean_squared) - R(res.gaussian))
    for mine, ref in ((k1, H - disc), (k2, H + disc)):
        lo, hi = mine.interval(mpq(1, 10**20))
        assert R(lo) <= ref + sp.Rational(1, 10**15) and ref - sp.Rational(1, 10**15) <= R(hi)


def test_known_surfaces():
    saddle = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])  # z = u v
    res = cv.corner_curvature(saddle)
    assert res.gaussian == -1 and res.mean_squared == 0
    assert [float(k) for k in res.principal()] == [-1.0, 1.0]
    # quarter cylinder of radius 1 (rational quadratic in u, linear in v): K = 0, |H| = 1/2
    cyl = BezierSurface([[[1, 0, 0], [1, 0, 1]], [[1, 1, 0], [1, 1, 1]], [[0, 1, 0], [0, 1, 1]]], [[1, 1], [1, 1], [2, 2]])
    for u in (0, mpq(1, 3), 1):
        r = cv.surface_curvature(cyl, u, mpq(1, 2))
        assert r.gaussian == 0 and r.mean_squared == mpq(1, 4)
        k1, k2 = r.principal()
        assert sorted([float(k1), float(k2)]) == sorted([0.0, 2.0 * r.mean_sign * 0.5])
    plane = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]])
    assert cv.corner_curvature(plane).principal()[0] == 0


def test_sphere_octant_rational_patch():
    # the exact octant of the unit sphere as a degree (2, 2) rational patch (tensor form of a known parametrization)
    q = [[1, 0], [1, 1], [0, 1]]
    wq = [1, 1, 2]
    net = [[[q[i][0] * q[j][0], q[i][0] * q[j][1], q[i][1]] for j in range(3)] for i in range(3)]
    w = [[wq[i] * wq[j] for j in range(3)] for i in range(3)]
    S = BezierSurface(net, w)
    for u, v in ((0, 0), (mpq(1, 2), mpq(1, 3)), (1, mpq(2, 5))):
        x = S.evaluate(u, v)
        assert sum(c * c for c in x) == 1
        if u == 1:
            continue  # the pole: degenerate parametrization
        res = cv.surface_curvature(S, u, v)
        assert res.gaussian == 1 and res.mean_squared == 1


@given(st.integers(2, 4), st.data())
@SYMPY
def test_curve_curvature(n, data):
    pts = data.draw(st.lists(st.lists(small_rationals, min_size=2, max_size=2), min_size=n + 1, max_size=n + 1))
    w = data.draw(st.lists(positive, min_size=n + 1, max_size=n + 1))
    c = BezierCurve(pts, w)
    t0 = data.draw(st.fractions(0, 1, max_denominator=5))
    Wp = sp.expand(sum(R(w[i]) * sp.binomial(n, i) * T**i * (1 - T) ** (n - i) for i in range(n + 1)))
    Np = [sp.expand(sum(R(w[i]) * R(pts[i][k]) * sp.binomial(n, i) * T**i * (1 - T) ** (n - i) for i in range(n + 1))) for k in range(2)]
    t = R(t0)
    w0, w1, w2 = Wp.subs(T, t), Wp.diff(T).subs(T, t), Wp.diff(T, 2).subs(T, t)
    r = [x.subs(T, t) / w0 for x in Np]
    d1 = [(x.diff(T).subs(T, t) - ri * w1) / w0 for x, ri in zip(Np, r)]
    d2 = [(x.diff(T, 2).subs(T, t) - 2 * di * w1 - ri * w2) / w0 for x, ri, di in zip(Np, r, d1)]
    speed2 = d1[0] ** 2 + d1[1] ** 2
    if speed2 == 0:
        return
    cr = d1[0] * d2[1] - d1[1] * d2[0]
    try:
        res = cv.curve_curvature(c, t0)
    except DomainError:  # a control leg of the subdivided curve is degenerate
        return
    assert R(res.squared) == cr**2 / speed2**3 and res.sign == sp.sign(cr)
    if res.squared:
        assert abs(float(res.value) - float(cr / speed2 ** sp.Rational(3, 2))) < 1e-9


def test_curve_curvature_space_and_errors():
    helixish = BezierCurve([[0, 0, 0], [1, 0, 0], [1, 1, 1]])
    res = cv.curve_start_curvature(helixish)
    assert res.squared == mpq(1, 2) * mpq(1, 2) * 2  # ((n-1)/n)^2 |a x b|^2/|a|^6 with a = (1,0,0), b = (1,1,1)
    with pytest.raises(DomainError):
        cv.curve_start_curvature(BezierCurve([[0, 0], [0, 0], [1, 1]]))
    with pytest.raises(DegreeError):
        cv.curve_start_curvature(BezierCurve([[0, 0]]))
    assert cv.curve_start_curvature(BezierCurve([[0, 0], [1, 1]])).squared == 0


def test_surface_curvature_errors():
    with pytest.raises(DimensionError):
        cv.corner_curvature(BezierSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]]))
    degenerate = BezierSurface([[[0, 0, 0], [0, 0, 0]], [[1, 0, 0], [1, 1, 1]]])
    with pytest.raises(DomainError):
        cv.corner_curvature(degenerate)
    with pytest.raises(DegreeError):
        cv.corner_curvature(BezierSurface([[[0, 0, 0], [0, 1, 0]]]))


# ---------------------------------------------------------------- triangular patches
def tri_cases(max_n=3):
    def build(n):
        keys = [(i, j, n - i - j) for i in range(n + 1) for j in range(n + 1 - i)]
        return st.tuples(
            st.just(n),
            st.lists(st.lists(small_rationals, min_size=3, max_size=3), min_size=len(keys), max_size=len(keys)).map(lambda ps: dict(zip(keys, ps))),
            st.lists(positive, min_size=len(keys), max_size=len(keys)).map(lambda ws: dict(zip(keys, ws))),
        )

    return st.integers(1, max_n).flatmap(build)


def tri_polys(n, pts, ws):
    comps = [0, 0, 0, 0]
    for (i, j, k), p in pts.items():
        b = sp.factorial(n) / (sp.factorial(i) * sp.factorial(j) * sp.factorial(k)) * U**i * V**j * (1 - U - V) ** k
        comps = [c + b * R(ws[(i, j, k)]) * x for c, x in zip(comps, [R(c) for c in p] + [1])]
    comps = [sp.expand(c) for c in comps]
    return comps[:3], comps[3]


@given(tri_cases())
@SYMPY
def test_triangular_evaluate_tensor_and_corner_curvature(case):
    n, pts, ws = case
    tri = TriangularBezier(pts, ws)
    N, W = tri_polys(n, pts, ws)
    for u, v in ((mpq(1, 5), mpq(2, 7)), (mpq(1, 2), mpq(1, 2)), (0, 0)):
        assert [R(x) for x in tri.evaluate(u, v)] == [x.subs({U: R(u), V: R(v)}) / W.subs({U: R(u), V: R(v)}) for x in N]
    hom = tri.tensor_homogeneous()
    # tensor Bernstein sums of the homogeneous net reproduce the triangular numerators exactly
    for k in range(4):
        poly = sp.expand(sum(R(hom[i, j, k]) * sp.binomial(n, i) * U**i * (1 - U) ** (n - i) * sp.binomial(n, j) * V**j * (1 - V) ** (n - j) for i in range(n + 1) for j in range(n + 1)))
        assert sp.expand(poly - (N + [W])[k]) == 0
    d = derivs(N, W, 0, 0)
    if sp.Matrix(d["Pu"]).cross(sp.Matrix(d["Pv"])) == sp.zeros(3, 1):
        return
    assert as_ref(cv.triangular_corner_curvature(tri)) == fundamental(d)


def test_triangular_bad_input():
    with pytest.raises(InputError):
        TriangularBezier({(1, 0, 0): [0, 0, 0], (0, 1, 0): [1, 0, 0]})
    with pytest.raises(WeightError):
        TriangularBezier({(1, 0, 0): [0, 0, 0], (0, 1, 0): [1, 0, 0], (0, 0, 1): [0, 1, 0]}, {(1, 0, 0): 1, (0, 1, 0): 0, (0, 0, 1): 1})
    with pytest.raises(InputError):
        TriangularBezier({(1, 0, 0): [0, 0], (0, 1, 0): [1, 0, 0], (0, 0, 1): [0, 1, 0]})


# ---------------------------------------------------------------- implicit surfaces
def test_implicit_sphere_and_ellipsoid():
    x, y, z = sp.symbols("x y z")
    sphere = x**2 + y**2 + z**2 - 9
    res = cv.implicit_curvature(*cv.implicit_derivatives(sphere, [1, 2, 2]))
    assert res.gaussian == mpq(1, 9) and res.mean_squared == mpq(1, 9) and res.mean_sign == 1
    ell = x**2 / 4 + y**2 + z**2 / 9 - 1
    a2, b2, c2 = 4, 1, 9
    p = [mpq(4, 3), mpq(1, 3), mpq(2)]
    assert sum(c * c / d for c, d in zip(p, (a2, b2, c2))) == 1
    res = cv.implicit_curvature(*cv.implicit_derivatives(ell, p))
    expected = 1 / (a2 * b2 * c2 * sum(c * c / (d * d) for c, d in zip(p, (a2, b2, c2))) ** 2)
    assert res.gaussian == expected
    with pytest.raises(DomainError):
        cv.implicit_derivatives(sphere, [1, 1, 1])
    with pytest.raises(DomainError):
        cv.implicit_curvature([0, 0, 0], np.eye(3, dtype=int).tolist())
    with pytest.raises(InputError):
        cv.implicit_curvature([1, 0, 0], [[1, 2, 0], [0, 1, 0], [0, 0, 1]])


def test_implicit_matches_parametric_graph():
    x, y, z = sp.symbols("x y z")
    q = x**3 - 2 * x * y + y**2 / 3
    for px, py in ((sp.Rational(1, 2), sp.Rational(-1, 3)), (sp.Integer(1), sp.Integer(2))):
        pz = q.subs({x: px, y: py})
        res = cv.implicit_curvature(*cv.implicit_derivatives(q - z, [px, py, pz]))
        d = derivs([U, V, sp.expand(q.subs({x: U, y: V}))], sp.Integer(1), px, py)
        assert as_ref(res) == fundamental(d)  # normal r_u x r_v = -grad f

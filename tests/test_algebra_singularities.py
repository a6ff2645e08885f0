"""Double points, singular points, genus, discriminants, parametrization (notes 19, 18.4).

References: sympy's polynomial system solver for f = f_x = f_y = 0, sympy
substitution of parametrizations, the product formula for the count of double
points, float evaluation at 40 digits of the exact parameters.
"""

import random

import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.algebra import (
    ImproperParametrizationError,
    curve_discriminant,
    curve_from_polynomials,
    double_point_cubic,
    double_points,
    double_points_quartic,
    genus,
    implicitize,
    parametrize_conic,
    parametrize_rational_cubic,
    parametrize_unicursal,
    singular_points,
)
from exactcagd.errors import DegreeError, InputError, NotSupportedError

x, y, t = sp.symbols("x y t")


def _num(a, digits=40):
    from gmpy2 import mpq

    a.refine(mpq(1, 10**digits))
    return mpmath.mpf(int(a.lo.numerator)) / int(a.lo.denominator)


@settings(max_examples=8, deadline=None)
@given(st.integers(3, 5), st.randoms(use_true_random=False))
def test_double_points_of_random_curves(n, rnd):
    pts = [(rnd.randint(-8, 8), rnd.randint(-8, 8)) for _ in range(n + 1)]
    curve = BezierCurve(pts, [rnd.randint(1, 3) for _ in range(n + 1)])
    try:
        dps = double_points(curve)
    except (ImproperParametrizationError, DegreeError):
        return
    F = implicitize(curve).as_expr()
    if sp.Poly(F, x, y).total_degree() != n:
        return
    sps = singular_points(F)
    if any(p.multiplicity != 2 or p.delta != 1 for p in sps):
        return  # only nodes and simple cusps: then every double point is one parameter pair
    delta = sum(p.count for p in sps)
    assert delta == (n - 1) * (n - 2) // 2  # genus 0 (19.1), from the implicit side
    assert sum(d.count for d in dps) == delta  # the parametric side agrees
    mpmath.mp.dps = 60
    for d in dps:
        if d.point is None or len(d.point) != 2:
            continue
        px, py = (_num(v, 50) for v in d.point)
        scale = 1 + abs(px) + abs(py)
        # the point is singular on the implicit curve (gradient vanishes), relative to the size of the terms
        for g in (F, sp.diff(F, x), sp.diff(F, y)):
            size = sum(abs(c) for c in sp.Poly(g, x, y).coeffs()) * scale**n
            assert abs(sp.lambdify((x, y), g, "mpmath")(px, py)) < size * mpmath.mpf(10) ** -40
        if d.kind == "crunode" and None not in d.params:
            for tp in d.params:
                pt = [sp.lambdify(t, e, "mpmath")(_num(tp, 50)) for e in curve.to_sympy(t)]
                assert abs(pt[0] - px) < 1e-30 * scale and abs(pt[1] - py) < 1e-30 * scale


def test_cubic_and_quartic_moving_line_methods_agree():
    cubic = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 0]])
    (d,) = double_points(cubic)
    assert d.kind == "crunode" and double_point_cubic(cubic) == (3, 0)
    assert (str(d.point[0]), str(d.point[1])) == ("3", "0") and [str(p) for p in d.params] == ["-1", "1"]
    quartic = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 2], [2, 0]])
    pts, nc = double_points_quartic(quartic)
    sym = sorted((float(d.point[0]), float(d.point[1])) for d in double_points(quartic))
    assert nc == 0 and sorted((float(a), float(b)) for a, b in pts) == sym


def test_cusp_and_acnode_of_rational_cubics():
    cusp = BezierCurve([[0, 0], [1, 1], [0, 1], [1, 0]])
    (d,) = double_points(cusp)
    assert d.kind == "cusp" and str(d.params[0]) == "1/2"
    acn = curve_from_polynomials(t**2 + 1, t * (t**2 + 1))  # y^2 = x^2 (x - 1)... acnode at (0, 0)
    kinds = [d.kind for d in double_points(acn)]
    F = implicitize(acn).as_expr()
    assert kinds == ["acnode"] and sp.expand(F.subs({x: 0, y: 0})) == 0


def test_singular_points_match_sympy_solve():
    r = random.Random(5)
    for _ in range(4):
        cur = BezierCurve([[r.randint(-6, 6), r.randint(-6, 6)] for _ in range(4)])
        F = implicitize(cur).as_expr()
        ref = [s for s in sp.solve([F, sp.diff(F, x), sp.diff(F, y)], [x, y], dict=True)]
        real_ref = sorted((float(s[x]), float(s[y])) for s in ref if s[x].is_real and s[y].is_real)
        ours = sorted((float(p.point[0]), float(p.point[1])) for p in singular_points(F, include_infinity=False) if p.point)
        assert len(ours) == len(real_ref) and all(abs(a[0] - b[0]) < 1e-9 and abs(a[1] - b[1]) < 1e-9 for a, b in zip(ours, real_ref))


def test_genus_and_errors():
    assert genus(y**2 - x**3 + x) == 1
    assert genus(x**4 + y**4 - 1) == 3
    assert genus(x**2 * y**2 - x**2 - y**2) == 0  # acnode + two crunodes at infinity
    with pytest.raises(InputError):
        genus((x - y) * (x + y - 1))
    with pytest.raises(InputError):
        genus(x**2 + y**2)  # irreducible over Q, not over C
    with pytest.raises(NotSupportedError):
        genus(y**2 - x**5)  # A4 singularity: delta not computed
    with pytest.raises(InputError):
        singular_points((x**2 + y**2 - 1) ** 2)


def test_discriminant_silhouette():
    D = sp.Poly(curve_discriminant(x**3 + 9 * x**2 - 12 * y**2), x)
    assert set(sp.roots(D)) == {0, -9}


def test_parametrizations_vanish():
    f = x**2 + 4 * y**2 - 2 * x - 8
    X, Y = parametrize_conic(f)
    assert sp.simplify(f.subs({x: X, y: Y}, simultaneous=True)) == 0
    g = -21 + 46 * x - 13 * x**2 + x**3 + 25 * y - 23 * x * y + 3 * x**2 * y - 9 * y**2 + 3 * x * y**2 + y**3
    (X, Y), point = parametrize_rational_cubic(g)
    assert point == (2, 3) and sp.simplify(g.subs({x: X, y: Y}, simultaneous=True)) == 0
    quartic = (x**2 + y**2) ** 2 + 3 * x**2 * y - y**3  # ordinary triple point at the origin
    X, Y = parametrize_unicursal(quartic, (0, 0))
    assert sp.simplify(quartic.subs({x: X, y: Y}, simultaneous=True)) == 0
    with pytest.raises(InputError):
        parametrize_unicursal(x**3 + y**3 - 1, (1, 0))
    with pytest.raises(InputError):
        parametrize_rational_cubic(y**2 - x**3 - x - 1)
    with pytest.raises(NotSupportedError):
        parametrize_conic(x**2 + y**2 + 1)  # no real (hence no rational) point

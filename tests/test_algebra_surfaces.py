"""Surface implicitization and base points (notes 17.9, 17.10).

Reference: exact sympy substitution of the parametrization into the implicit
polynomial; base points checked by substitution.
"""

import random

import pytest
import sympy as sp

from exactcagd import BezierSurface
from exactcagd.algebra import SurfaceParametrization, base_point_count, implicitize_surface
from exactcagd.algebra.surfaces import base_points_affine, surface_implicit_degree_bound
from exactcagd.errors import InputError

x, y, z, s, t = sp.symbols("x y z s t")


def _vanishes(F, P):
    X, Y, Z, W = P.components()
    return sp.expand(sp.numer(sp.together(F.subs({x: X / W, y: Y / W, z: Z / W}, simultaneous=True)))) == 0


def test_bilinear_routes():
    r = random.Random(2)
    for _ in range(3):
        net = [[[r.randint(-3, 3) for _ in range(3)] for _ in range(2)] for _ in range(2)]
        P = SurfaceParametrization.from_bezier_surface(BezierSurface(net))
        Fs = [implicitize_surface(P, m).as_expr() for m in ("linear_algebra", "dixon", "groebner")]
        if sp.Poly(Fs[0], x, y, z).total_degree() == 2:
            assert Fs[0] == Fs[1] == Fs[2]
        assert _vanishes(Fs[0], P)


def test_triangular_quadratic_and_bounds():
    r = random.Random(4)
    tri = {(i, j, 2 - i - j): [r.randint(-3, 3) for _ in range(3)] for i in range(3) for j in range(3 - i)}
    P = SurfaceParametrization.from_triangular_bezier(tri)
    F = implicitize_surface(P)
    assert surface_implicit_degree_bound(P) == 4 and F.total_degree() == 4 and _vanishes(F.as_expr(), P)
    # the patch passes through its corner control points
    assert all(F.as_expr().subs({x: p[0], y: p[1], z: p[2]}) == 0 for key, p in tri.items() if 2 in key)


def test_sphere_base_points():
    P = SurfaceParametrization.from_polynomials(2 * s, 2 * t, 1 - s**2 - t**2, 1 + s**2 + t**2)
    assert base_point_count(P) == 2 and base_points_affine(P) == []
    assert implicitize_surface(P).as_expr() == x**2 + y**2 + z**2 - 1
    Q = SurfaceParametrization.from_polynomials(s * (s - 1), t * s, s, s + t**2 + s * t)
    pts = base_points_affine(Q)
    assert [(str(a), str(b)) for a, b in pts] == [("0", "0")]


def test_bad_input():
    with pytest.raises(InputError):
        SurfaceParametrization.from_polynomials(s, t, x, 1)
    with pytest.raises(InputError):
        SurfaceParametrization.from_polynomials(s, t, s * t, 0)
    with pytest.raises(InputError):
        implicitize_surface(BezierSurface([[[0, 0], [1, 0]], [[0, 1], [1, 1]]]))
    with pytest.raises(InputError):
        SurfaceParametrization.from_triangular_bezier({(1, 0, 0): (0, 0, 0), (0, 1, 0): (1, 0, 0)})
    with pytest.raises(InputError):
        implicitize_surface(SurfaceParametrization.from_polynomials(s, t, s * t), method="magic")

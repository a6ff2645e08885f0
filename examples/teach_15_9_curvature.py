"""Teaching walk-through, notes 15.9: curvature from control points, exact.

Curvature at the start of a rational Bézier curve (15.44), Gaussian and mean curvature at the
corner of a rational tensor-product patch (15.54)-(15.57), of a triangular patch (15.59)-(15.60)
and of an implicit surface (15.61)-(15.62).  K is an exact rational; H is printed as its exact
square with a sign (and as a certified algebraic number).  Saves
``examples/output/teach/ch15_curvature.png``.

Run:  python examples/teach_15_9_curvature.py
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from _teach import fmt, out_path, plt, polygon, sample, step, tex
from gmpy2 import mpq

from exactcagd import BezierCurve, BezierSurface
from exactcagd.toolbox import curvature as cv
from exactcagd.toolbox.bezier_extras import curvature as ch2_curvature
from exactcagd.toolbox.triangular import TriangularBezier


def show_surface(label, res):
    k1, k2 = res.principal()
    print(f"  {label}: K = {fmt(res.gaussian)}, H^2 = {fmt(res.mean_squared)} (sign {res.mean_sign}),"
          f" H ~ {float(res.mean):.6g}, k1, k2 ~ {float(k1):.6g}, {float(k2):.6g}")
    tex(f"Gaussian curvature K, {label}", res.gaussian, echo=False)
    tex(f"H^2, {label}", res.mean_squared, echo=False)


def main():
    step("15.9 (15.44) Curvature at the start of a rational quadratic: k = (n-1)/n w0 w2 / w1^2 * h / a^2")
    arc = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 1])  # a parabola
    circle = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])  # w1^2 = w0 w2 cos^2(45 deg): the unit quarter circle
    a2, h = mpq(1), mpq(1)  # |P1 - P0|^2 and the distance of P2 from the line P0 P1 (x = 1)
    for name, c, (w0, w1, w2) in (("parabola w = (1,1,1)", arc, (1, 1, 1)), ("quarter circle w = (1,1,2)", circle, (1, 1, 2))):
        by_hand = mpq(1, 2) * mpq(w0 * w2, w1 * w1) * h / a2
        k = cv.curve_start_curvature(c)
        print(f"  {name}: k = 1/2 * {w0 * w2}/{w1 * w1} * 1/1 = {fmt(by_hand)};  code: k^2 = {fmt(k.squared)},"
              f" chapter-2 formula: {fmt(ch2_curvature(c, 0))}")
        tex(f"k^2 at t = 0, {name}", k.squared, echo=False)

    step("15.9.1 Corner of a tensor-product patch: the unit-sphere octant as a rational (2,2) patch")
    q, wq = [[1, 0], [1, 1], [0, 1]], [1, 1, 2]
    net = [[[q[i][0] * q[j][0], q[i][0] * q[j][1], q[i][1]] for j in range(3)] for i in range(3)]
    octant = BezierSurface(net, [[wq[i] * wq[j] for j in range(3)] for i in range(3)])
    print("  net = quarter circle (x) quarter circle, weights w_i w_j with w = (1, 1, 2)")
    show_surface("corner (0,0)", cv.corner_curvature(octant))
    show_surface("point (1/3, 1/2)", cv.surface_curvature(octant, "1/3", "1/2"))
    saddle = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    show_surface("z = u v at the origin", cv.corner_curvature(saddle))

    step("15.9.2 Corner of a triangular patch: the paraboloid z = x^2 + y^2 as a quadratic triangle")
    tri = TriangularBezier({(2, 0, 0): [1, 0, 1], (0, 2, 0): [0, 1, 1], (0, 0, 2): [0, 0, 0],
                            (1, 1, 0): ["1/2", "1/2", 0], (1, 0, 1): ["1/2", 0, 0], (0, 1, 1): [0, "1/2", 0]})
    print("  P(u,v) at (1/4, 1/2) =", fmt(tri.evaluate("1/4", "1/2")), "(expected (1/4, 1/2, 5/16))")
    show_surface("corner P_002 (origin)", cv.triangular_corner_curvature(tri))
    print("  expected: K = f_xx f_yy = 4, H = 2")

    step("15.9.3 Implicit surface: the ellipsoid x^2/4 + y^2 + z^2 - 1 = 0 at (2, 0, 0) and (0, 0, 1)")
    x, y, z = sp.symbols("x y z")
    f = x**2 / 4 + y**2 + z**2 - 1
    for point in ((2, 0, 0), (0, 0, 1)):
        g, hess = cv.implicit_derivatives(f, point)
        print(f"  at {point}: grad f = {fmt(g)}, Hess f = {fmt(hess)}")
        show_surface("   ", cv.implicit_curvature(g, hess))
    print("  expected: at (2,0,0) K = a^2/(b^2 c^2) = 4, H = 2; at (0,0,1) K = 1/4 (radii 2 and 1)")

    ts = [mpq(i, 40) for i in range(41)]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for c, colour, label in ((arc, "tab:green", "parabola w = (1,1,1)"), (circle, "k", "circle w = (1,1,2)")):
        axes[0].plot(*sample(c).T, "-", color=colour, lw=2, label=label)
        axes[1].plot([float(t) for t in ts], [float(cv.curve_curvature(c, t).value) for t in ts], "-", color=colour, label=label)
    axes[0].plot(*polygon(arc).T, "o--", color="tab:blue")
    axes[0].set_aspect("equal")
    axes[0].legend(fontsize=7)
    axes[1].plot([0, 0], [0.5, 1], "ro", label="(15.44) at t = 0")
    axes[1].set_xlabel("t")
    axes[1].set_ylabel("curvature (exact: subdivide, then (15.44))")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    path = out_path("ch15_curvature.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"\npicture: {path}")


if __name__ == "__main__":
    main()

"""Teaching walk-through, notes chapters 15 and 16: tensor-product surfaces, exact.

Corner derivatives and normals (15.3), tessellation with the flatness bounds (15.4, the
notes' worked example), C^n patches and NURBS surfaces (15.5, 15.6), and the efficient
points and tangents of 15.8 / chapter 16.  Saves ``examples/output/teach/ch15_surfaces.png``.

Run:  python examples/teach_15_16_surfaces.py
"""

from __future__ import annotations

import numpy as np
from _teach import fmt, out_path, plt, step, tex
from gmpy2 import mpq

from exactcagd import BezierSurface, BSplineSurface
from exactcagd.toolbox import surfaces as sf


def grid(surface, k=16):
    return np.array([[[float(x) for x in surface.evaluate(mpq(i, k), mpq(j, k))] for j in range(k + 1)] for i in range(k + 1)])


def main():
    step("15.3 Corner derivatives of a rational biquadratic straight from the control net")
    net = [[[0, 0, 0], [0, 1, 1], [0, 2, 0]], [[1, 0, 1], [1, 1, 2], [1, 2, 1]], [[2, 0, 0], [2, 1, 1], [2, 2, 0]]]
    w = [[1, 1, 1], [1, 2, 1], [1, 1, 1]]
    S = BezierSurface(net, w)
    d = sf.corner_derivatives(S)
    tex("S(u, v)", S, echo=False)
    for key in ("P", "Pu", "Pv", "Puu", "Puv", "Pvv"):
        print(f"  {key:4s} = {fmt(d[key])}")
        tex(key, list(d[key]), echo=False)
    print("  normal P_u x P_v at the corner =", fmt(sf.cross(d["Pu"], d["Pv"])))
    tex("P_u x P_v (corner)", list(sf.cross(d["Pu"], d["Pv"])), echo=False)
    print("  normal at (1/3, 1/2) (subdivide to a corner, then the same formulas) =", fmt(sf.normal_at(S, "1/3", "1/2")))
    tex("normal at (1/3, 1/2)", list(sf.normal_at(S, "1/3", "1/2")), echo=False)

    step("15.4.2 Tessellation, the notes' example (net rebuilt from the printed second hodographs)")
    Z = [[-6, -4, 0, 0], [-2, 2, 4, 4], [-2, 2, 4, 0], [-6, -2, 0, 0]]
    T = BezierSurface([[[i, j, Z[i][j]] for j in range(4)] for i in range(4)])
    M1, M2, M3 = sf.surface_second_derivative_bounds(T)
    print(f"  (15.6): M1^2, M2^2, M3^2 = {fmt((M1, M2, M3))}  ->  M1 = 48, M2 = 36, M3 = 36")
    tex("(M1^2, M2^2, M3^2)", [M1, M2, M3], echo=False)
    print("  case 3: k = sqrt(M3/M1) = sqrt(3)/2, delta_t = sqrt(8 eps / (M1 k^2 + 2 M2 k + M3))")
    print(f"         = sqrt(0.008 / (36 + 36 sqrt 3 + 36)) = {np.sqrt(0.008 / (72 + 36 * np.sqrt(3))):.7f} (printed 0.0080677)")
    res = sf.surface_sampling_numbers(T, "1/1000")
    print(f"  certified: n_s = {res.n_s}, n_t = {res.n_t} (printed 144, 124 - see the erratum), bound holds: {res.bound_holds}")

    step("15.5 / 15.6 A bicubic NURBS surface: knot insertion and the C^n of its Bézier patches")
    knots = [0, 0, 0, 0, 1, 2, 2, 2, 2]
    bnet = [[[i, j, (i * j) % 3 - 1] for j in range(5)] for i in range(5)]
    B = BSplineSurface(bnet, knots, knots)
    B2 = B.insert_knot_u(1)
    print("  insert s = 1 (into every s-control curve): knots_u", fmt(B2.knots_u), "net", B2.shape)
    tex("knots_u after inserting s = 1", list(B2.knots_u), echo=False)
    print("  surface unchanged at (1/2, 3/2):", B2.evaluate("1/2", "3/2") == B.evaluate("1/2", "3/2"))
    patches = B.to_bezier_patches()
    (spans0, P0), (spans1, P1) = patches[(0, 0)], patches[(1, 0)]
    print("  Bézier patches:", sorted(patches), "; continuity across s = 1:",
          f"C^{sf.patch_continuity_order(P0, P1, 'u')}", "(simple knot, cubic -> C^2)")
    print("  adjacent control curves agree:", sf.control_curve_continuity_order(P0, P1, "u"))

    step("15.8 / 16 Points and tangents from four sub-nets by Horner's rule in u = s/(1-s)")
    h = sf.horner_surface_point_tangents(S, "1/3", "1/4")
    print("  point       =", fmt(h["point"]), " (de Casteljau:", fmt(S.evaluate("1/3", "1/4")) + ")")
    tex("point (1/3, 1/4)", list(h["point"]), echo=False)
    print("  tangent dir s =", fmt(h["dir_s"]), " exact P_s =", fmt(h["Ps"]))
    tex("tangent direction s", list(h["dir_s"]), echo=False)
    tex("P_s", list(h["Ps"]), echo=False)
    print("  tangent dir t =", fmt(h["dir_t"]), " exact P_t =", fmt(h["Pt"]))
    tex("tangent direction t", list(h["dir_t"]), echo=False)
    tex("P_t", list(h["Pt"]), echo=False)

    fig = plt.figure(figsize=(11, 4.5))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    g = grid(T, 12)
    ax.plot_wireframe(g[..., 0], g[..., 1], g[..., 2], linewidth=0.6)
    ax.set_title("15.4 example patch (12 x 12 of the certified 150 x 130)", fontsize=8)
    ax = fig.add_subplot(1, 2, 2, projection="3d")
    for (i, j), (_, patch) in patches.items():
        g = grid(patch, 8)
        ax.plot_surface(g[..., 0], g[..., 1], g[..., 2], alpha=0.6, color=("tab:blue", "tab:orange")[(i + j) % 2])
    ax.set_title("bicubic NURBS split into Bézier patches (15.6)", fontsize=8)
    path = out_path("ch15_surfaces.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"\npicture: {path}")


if __name__ == "__main__":
    main()

"""Teaching script, Sederberg's notes chapters 10 and 11: interpolation four ways, error
bounds and Chebyshev points; least squares, fairing and constrained fairing of points.

Run:  python examples/teach_10_11_interpolation_fitting.py
Prints the tables exactly; writes examples/output/teach/ch10_11.png.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from _teach import fmt, out_path, plt, sample, step, tex
from exactcagd.toolbox import fitting as ft
from exactcagd.toolbox import interpolation as ip

T, P = [0, 1, 3, 4], [[0, 0], [3, 3], [5, 3], [7, 0]]
step("10.1 undetermined coefficients: (0,0),(2,2),(0,3),(2,4) at t = 0, 1/4, 3/4, 1")
pc = ip.undetermined_coefficients([0, Fraction(1, 4), Fraction(3, 4), 1], [[0, 0], [2, 2], [0, 3], [2, 4]])
print("  x(t), y(t) =", list(pc.to_sympy()))
tex("(x(t), y(t))", list(pc.to_sympy()), echo=False)
print("  Bézier control points:", fmt(ip.undetermined_coefficients([0, Fraction(1, 4), Fraction(3, 4), 1], [[0, 0], [2, 2], [0, 3], [2, 4]], basis="bernstein").control_points))
tex("Bézier control points", [list(q) for q in ip.undetermined_coefficients([0, Fraction(1, 4), Fraction(3, 4), 1], [[0, 0], [2, 2], [0, 3], [2, 4]], basis="bernstein").control_points], echo=False)

step("10.3 divided differences for t = 0, 1, 3, 4")
for k, col in enumerate(ip.divided_differences(T, P)):
    print(f"  order {k}:", fmt(col))
    tex(f"divided differences of order {k}", [list(q) for q in col], echo=False)
print("  P(2) from the Newton form:", fmt(ip.newton_interpolate(T, P)(2)))
tex("P(2) (Newton form)", list(ip.newton_interpolate(T, P)(2)), echo=False)
print("  extra table row at t = 2 (c0, c1, c2):", fmt(ip.extend_divided_differences(T, P, 2)["c"]))

step("10.4 Neville's scheme at t = 2")
for k, level in enumerate(ip.neville(T, P, 2)):
    print(f"  level {k}:", fmt(level))
    tex(f"Neville level {k}", [list(q) for q in level], echo=False)

step("10.6 error bounds: uniform vs Chebyshev nodes, n = 9 on [0, 1]")
uni = ip.node_polynomial_max([Fraction(i, 9) for i in range(10)], 0, 1)
cheb = ip.chebyshev_node_polynomial_max(9, 0, 1)
print(f"  max|omega| uniform = {float(uni):.4e} (exact: a real algebraic number of degree {uni.poly.degree()})")
print(f"  max|omega| Chebyshev = 2 (1/4)^10 = {fmt(cheb)} = {float(cheb):.4e}   (the notes print the exponent n)")
tex("max|omega| uniform", uni, echo=False)
tex("max|omega| Chebyshev = 2 (1/4)^10", cheb, echo=False)
print("  Chebyshev nodes (exact roots of T_10):", [f"{float(x):.6f}" for x in ip.chebyshev_nodes(9, 0, 1)][:3], "...")
print("  Chebyshev interpolant of t^10 on [0,1] (exact remainder):", fmt([r[0] for r in ip.chebyshev_interpolant([0] * 10 + [1], 9, 0, 1).coefficients][:3]), "...")

step("11.3-11.4 least squares and fairing of 12 points (cubic, 7 control points)")
pts = [[0, 0], [1, 2], [2, 3], [3, 3], [4, 2], [5, 0], [6, -1], [7, -1], [8, 0], [9, 2], [10, 3], [11, 3]]
ts = ft.parametrize(pts)
knots = ft.knot_vector(ts, 3, 7)
print("  parameters:", fmt(ts))
print("  knots:", fmt(knots))
tex("parameters", list(ts), echo=False)
tex("knots", list(knots), echo=False)
fits = {"least squares": ft.least_squares_fit(pts, ts, knots, 3)}
for c in (Fraction(1, 10**5), Fraction(1, 10**3), Fraction(1, 10)):
    fits[f"faired c={c}"] = ft.faired_fit(pts, ts, knots, 3, c)
for name, curve in fits.items():
    print(f"  {name:16s} Lsq = {float(ft.lsq_error(curve, pts, ts)):.5f}")
con = ft.constrained_faired_fit(pts, ts, knots, 3, Fraction(1, 1000), [0, 1], [pts[0], pts[-1]])
box, cert = ft.box_constrained_fairing(pts, ts, knots, 3, "axis")
print("  constrained c=1/1000 (ends interpolated): P(0) =", fmt(con.evaluate(0)), " P(1) =", fmt(con.evaluate(1)))
tex("constrained fit P(0), P(1)", [list(con.evaluate(0)), list(con.evaluate(1))], echo=False)
print("  box-constrained fairing: exact QP, active box sides per coordinate:", [len(c["active"]) for c in cert["per_coordinate"]])

fig, axs = plt.subplots(1, 2, figsize=(12, 4.3))
xs = np.linspace(0, 1, 400)
for nodes, lab in (([i / 9 for i in range(10)], "uniform"), (ip.chebyshev_nodes_float(9, 0, 1), "Chebyshev")):
    axs[0].plot(xs, np.prod([xs - v for v in nodes], axis=0), label=lab)
axs[0].set_title("Figure 10.5: (x - x0)...(x - x9) on [0, 1]")
axs[0].set_xlabel("x")
axs[0].set_ylabel("node polynomial")
axs[0].legend()
axs[1].plot(*np.array(pts, dtype=float).T, "ko", ms=4, label="data points")
for name, curve in list(fits.items()) + [("constrained c=1/1000, ends fixed", con), ("box-constrained", box)]:
    seg = np.vstack([sample(b, 60) for _, b in curve.to_bezier()])
    axs[1].plot(*seg.T, label=name, lw=1)
axs[1].set_xlabel("x")
axs[1].set_ylabel("y")
axs[1].legend(fontsize=7)
axs[1].set_title("11: fitting and fairing (exact control points)")
fig.tight_layout()
fig.savefig(out_path("ch10_11.png"), dpi=110)
print("\nwrote", out_path("ch10_11.png"))

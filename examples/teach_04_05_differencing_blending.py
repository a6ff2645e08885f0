"""Teaching script, Sederberg's notes chapters 4 and 5: forward differencing (exact vs binary64,
choosing delta) and blending functions (properties; Timmer, Ball, Overhauser).

Run:  python examples/teach_04_05_differencing_blending.py
Prints the difference tables and property checks; writes examples/output/teach/ch04_05.png.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from _teach import fmt, out_path, plt, sample, step, tex
from exactcagd import BezierCurve
from exactcagd.toolbox import blending as bl
from exactcagd.toolbox import forward_diff as fd

step("4: the difference table of 1, 3, 2, 5, 4 (degree 4), extended by R_right = R + R_down")
full = fd.difference_table([1, 3, 2, 5, 4] + fd.extend([1, 3, 2, 5, 4], 3))
for k, row in enumerate(full[:6]):
    print(f"  Delta_{k}:" if k else "  f      :", "  ".join(f"{fmt(v):>6}" for v in row))
    tex(f"Delta_{k}" if k else "f", list(row), echo=False)

step("4: Example -- f(1)=1, f(2)=2, f(3)=4, f(5)=15, cubic: Delta_4 = 32 - 4x = 0")
print("  f(4) =", fmt(fd.solve_missing([1, 2, 4, None, 15], 3)[3]))
tex("f(4)", fd.solve_missing([1, 2, 4, None, 15], 3)[3], echo=False)

step("4: t^3 at t = k/3, 300 steps -- exact rational vs binary64 forward differencing")
report = fd.float_error_report([0, 0, 0, 1], 0, Fraction(1, 3), 300)
print(f"  max float error {float(report['max_error']):.3e} at step {report['max_error_at']}; certified bound {float(report['max_bound']):.3e}")
print("  exact last value:", fmt(fd.forward_difference([0, 0, 0, 1], 0, Fraction(1, 3), 300)[-1]))
tex("exact last value (t = 299/3)", fd.forward_difference([0, 0, 0, 1], 0, Fraction(1, 3), 300)[-1], echo=False)

step("4.1 choosing delta for a gap-free raster (d with absolute values)")
curve = BezierCurve([[2, 3], [30, 40], [60, -10], [90, 25]])
steps = fd.rasterization_steps(curve)
px = fd.rasterize(curve)
print(f"  n d = {steps} steps; {len(set(px))} distinct pixels; 8-connected: {fd.pixels_connected(px)}")
tex("n d (steps)", steps, echo=False)

step("5: properties of the blending functions")
for name in ("timmer", "ball", "overhauser"):
    rep = bl.check_properties(getattr(bl, f"{name}_basis")())
    print(f"  {name:10s} partition of unity={rep.partition_of_unity} convex hull={rep.convex_hull} symmetric={rep.symmetric} "
          f"independent={rep.linearly_independent} end points={rep.endpoint_interpolation}")
    tex(f"{name} basis", list(getattr(bl, f"{name}_basis")()), echo=False)
Q = [[0, 0], [1, 3], [4, 3], [5, 0]]
print("  Timmer -> Bézier:", fmt(bl.timmer_to_bezier(Q).control_points))
print("  Ball   -> Bézier:", fmt(bl.ball_to_bezier(Q).control_points))
print("  Overhauser segment -> Bézier:", fmt(bl.overhauser_to_bezier(Q).control_points))
tex("Timmer -> Bézier", [list(pt) for pt in bl.timmer_to_bezier(Q).control_points], echo=False)
tex("Ball -> Bézier", [list(pt) for pt in bl.ball_to_bezier(Q).control_points], echo=False)
tex("Overhauser -> Bézier", [list(pt) for pt in bl.overhauser_to_bezier(Q).control_points], echo=False)

fig, axs = plt.subplots(1, 3, figsize=(13, 4))
errs = [float(e) for e in report["errors"]]
bnds = [float(b) for b in report["bounds"]]
axs[0].semilogy(range(len(errs)), np.maximum(errs, 1e-30), label="|float - exact|")
axs[0].semilogy(range(len(bnds)), bnds, label="certified bound")
axs[0].set_title("4: float forward differencing of t^3, delta = 1/3")
axs[0].set_xlabel("step k")
axs[0].set_ylabel("error of the k-th value")
axs[0].legend(fontsize=8)
t = np.linspace(0, 1, 200)
styles = (("timmer", "-"), ("ball", "--"), ("overhauser", ":"))
for name, style in styles:
    for k, f in enumerate(getattr(bl, f"{name}_basis")()):
        fn = __import__("sympy").lambdify(bl.T, f, "numpy")
        axs[1].plot(t, np.broadcast_to(fn(t), t.shape), style, color=f"C{k}", lw=1)
axs[1].axhline(0, color="k", lw=0.5)
for name, style in styles:  # the legend: line style = basis, colour = index
    axs[1].plot([], [], style, color="k", lw=1, label=name)
for k in range(4):
    axs[1].plot([], [], color=f"C{k}", lw=3, label=f"function {k}")
axs[1].legend(fontsize=7, ncol=2, loc="upper center")
axs[1].set_xlabel("t")
axs[1].set_title("5: blending functions")
for name, col in (("timmer", "C0"), ("ball", "C1")):
    c = getattr(bl, f"{name}_to_bezier")(Q)
    axs[2].plot(*sample(c).T, color=col, label=name)
axs[2].plot(*np.array(Q, dtype=float).T, "k--o", ms=3, label="control points")
for k, seg in enumerate(bl.overhauser_spline([[-2, -1]] + Q + [[7, 2]])):
    axs[2].plot(*sample(seg).T, color="C2", lw=1, label="overhauser spline" if k == 0 else None)
axs[2].set_title("5: curves on the same control points")
axs[2].set_xlabel("x")
axs[2].set_ylabel("y")
axs[2].legend(fontsize=8)
fig.tight_layout()
fig.savefig(out_path("ch04_05.png"), dpi=110)
print("\nwrote", out_path("ch04_05.png"))

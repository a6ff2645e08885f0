"""Teaching script, Sederberg's notes chapter 2 (beyond de Casteljau): end curvature of a
rational curve, continuity, exact circular arcs, negative weights, explicit curves and integrals.

Run:  python examples/teach_02_bezier_extras.py
Prints every step exactly and writes examples/output/teach/ch02_extras.png.
"""

from __future__ import annotations

from _teach import fmt, out_path, plt, polygon, sample, step, tex
from exactcagd import BezierCurve
from exactcagd.toolbox import bezier_extras as bx

step("2.9.3 curvature at t = 0 of P0=(0,0),w0=1; P1=(4,3),w1=2; P2=(0,5),w2=4")
c = BezierCurve([[0, 0], [4, 3], [0, 5]], weights=[1, 2, 4])
from exactcagd.proofs.sederberg_02_extras import _trace_curvature  # noqa: E402

_trace_curvature()
d = bx.derivatives_at(c, 0, 2)
print("P(0), P'(0), P''(0) by the quotient rule to any order:", fmt(d))
print("(2.11) P'(0) = (w1/w0) n (P1 - P0) =", fmt(bx.end_first_derivative(c)), "; (2.12) P''(0) =", fmt(bx.end_second_derivative(c)))
tex("(P(0), P'(0), P''(0))", list(d), echo=False)
tex("(2.11) P'(0)", list(bx.end_first_derivative(c)), echo=False)
tex("(2.12) P''(0)", list(bx.end_second_derivative(c)), echo=False)
kappa = bx.curvature(c, 0)
normal = (-d[1][1], d[1][0])
scale = (1 / float(kappa)) / (float(normal[0]) ** 2 + float(normal[1]) ** 2) ** 0.5
centre = (float(normal[0]) * scale, float(normal[1]) * scale)
print("osculating circle: radius 1/kappa =", 1 / kappa, " centre ~", tuple(round(v, 4) for v in centre))
tex("kappa(0)", kappa, echo=False)
tex("1/kappa(0)", 1 / kappa, echo=False)

step("2.10 continuity of two quadratics at the joint")
p = BezierCurve([[0, 0], [1, 1], [2, 0]])
for q in (BezierCurve([[2, 0], [3, -1], [5, 0]]), BezierCurve([[2, 0], [4, -2], [5, 0]])):
    k, betas = bx.geometric_continuity(p, q)
    print("Q =", fmt(q.control_points), ": C^%s" % bx.parametric_continuity(p, q), " G^%d with beta =" % k, fmt(betas))
    tex("Q = %s: beta" % fmt(q.control_points), list(betas), echo=False)

step("2.11 a 270-degree arc of radius 5 as exact rational quadratics")
arcs = bx.circular_arc((0, 0), (5, 0), (0, -5))
for a in arcs:
    print("  points", fmt(a.control_points), " weights", fmt(a.weights))
    tex("arc points", [list(pt) for pt in a.control_points], echo=False)
    tex("arc weights", list(a.weights), echo=False)
pts, w = bx.arc_symmetric_form((0, 0), (5, 0), (3, 4))
print("standard form of the arc (5,0)->(3,4): w1 = cos(theta/2) =", w[1], "(exact, irrational)")
tex("w_1 = cos(theta/2)", w[1], echo=False)

step("2.12 b = -1 on a quarter circle: the rest of the circle")
quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], [1, 1, 2])
rest = bx.mobius_reparametrize(quarter, -1)
print("weights w_i (-1)^i:", fmt(rest.weights), "  midpoint:", fmt(rest.evaluate("1/2")))
tex("w_i (-1)^i", list(rest.weights), echo=False)
tex("P(1/2)", list(rest.evaluate("1/2")), echo=False)

step("2.14-2.15 explicit curve y = f(x) and the area under it (average of the control values)")
e = bx.explicit_curve([1, 3, 2, 0])
print("control points:", fmt(e.control_points), "  area =", bx.area_under_explicit(e))
tex("control points", [list(pt) for pt in e.control_points], echo=False)
tex("area", bx.area_under_explicit(e), echo=False)

fig, axs = plt.subplots(1, 3, figsize=(13, 4.3))
ax = axs[0]
ax.plot(*sample(c).T, "b-")
ax.plot(*polygon(c).T, "k--o", ms=3)
import numpy as np  # noqa: E402

th = np.linspace(0, 2 * np.pi, 200)
r = 1 / float(kappa)
ax.plot(centre[0] + r * np.cos(th), centre[1] + r * np.sin(th), "r:", label=f"osculating circle, kappa = {kappa}")
ax.set_aspect("equal")
ax.legend(fontsize=7)
ax.set_title("2.9.3 end curvature")
ax = axs[1]
for a in arcs:
    ax.plot(*sample(a).T, "-")
    ax.plot(*polygon(a).T, "k--o", ms=3)
ax.set_aspect("equal")
ax.set_title("2.11 exact 270-degree arc (3 pieces)")
ax = axs[2]
ax.plot(*sample(quarter).T, "b-", label="quarter circle")
ax.plot(*sample(rest).T, "r-", label="b = -1 (weights 1, -1, 2)")
ax.plot(*polygon(quarter).T, "k--o", ms=3)
ax.set_aspect("equal")
ax.legend(fontsize=7)
ax.set_title("2.12 negative weight")
fig.tight_layout()
fig.savefig(out_path("ch02_extras.png"), dpi=110)
print("\nwrote", out_path("ch02_extras.png"))

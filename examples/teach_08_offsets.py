"""Teaching script, Sederberg's notes chapter 8: offset curves, exactly where they are rational.

Run:  python examples/teach_08_offsets.py
Prints the steps; writes examples/output/teach/ch08_offsets.png.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from _teach import fmt, out_path, plt, polygon, sample, step, tex
from exactcagd import BezierCurve
from exactcagd.toolbox.offsets import offset_curve, offset_cusps, offset_point, parabola_offset, pythagorean_hodograph

step("(8.2) one offset point: exact in Q(sqrt |P'(t)|^2)")
cubic = BezierCurve([[0, 0], [1, 2], [3, 1], [4, 4]])
print("  P = cubic (0,0),(1,2),(3,1),(4,4); Omega(1/2, P)(1/3) =", offset_point(cubic, Fraction(1, 2), Fraction(1, 3)))
tex("Omega(1/2, P)(1/3)", offset_point(cubic, Fraction(1, 2), Fraction(1, 3)), echo=False)
print("  is it PH?", pythagorean_hodograph(cubic), "(None: x'^2 + y'^2 is not a square, the offset is not rational)")

step("Pythagorean-hodograph cubic: P' = (1 - t^2, 2t), |P'| = 1 + t^2")
ph = BezierCurve([[0, 0], ["1/3", 0], ["2/3", "1/3"], ["2/3", 1]])
print("  sigma =", fmt(pythagorean_hodograph(ph)), "(power coefficients)")
tex("sigma (power coefficients)", list(pythagorean_hodograph(ph)), echo=False)
off = offset_curve(ph, Fraction(1, 4))
print("  offset rho = 1/4: rational Bezier curve of degree", off.degree)
print("  weights:", fmt(off.weights))
tex("offset control points", [list(q) for q in off.control_points], echo=False)
tex("offset weights", list(off.weights), echo=False)
print("  (8.3) Omega(-1/4, Omega(1/4, P))(1/3) =", offset_point(off, Fraction(-1, 4), Fraction(1, 3)), "= P(1/3) =", ph.evaluate(Fraction(1, 3)))
tex("(8.3) Omega(-1/4, Omega(1/4, P))(1/3)", offset_point(off, Fraction(-1, 4), Fraction(1, 3)), echo=False)

step("the parabola: a rational offset of degree 6 (the notes say 8: true only as an elevated form)")
parabola = BezierCurve([[0, 0], [3, 4], [7, 1]])
par_off = parabola_offset(parabola, 1)
print("  parabola (0,0),(3,4),(7,1): offset rho = 1 has degree", par_off.degree, "weights", fmt(par_off.weights))
tex("parabola offset weights", list(par_off.weights), echo=False)

step("cusps: radius of curvature = |rho| on the concave side (Figure 8.2)")
vertex = BezierCurve([[-1, 1], [0, -1], [1, 1]])
for rho in (-4, 4, Fraction(-1, 4)):
    print(f"  rho = {rho}: cusps at", [str(t) for t in offset_cusps(vertex, rho)])
    tex(f"cusps for rho = {rho}", list(offset_cusps(vertex, rho)), echo=False)

fig, axes = plt.subplots(1, 3, figsize=(15, 5))
ts = np.linspace(0, 1, 400)


def _offset_samples(curve, rho):
    pts = sample(curve, 400)
    d = np.gradient(pts, ts, axis=0)
    n = np.stack([d[:, 1], -d[:, 0]], axis=1) / np.linalg.norm(d, axis=1)[:, None]
    return pts + rho * n


ax = axes[0]
ax.plot(*sample(ph).T, "k", label="PH cubic")
ax.plot(*sample(off).T, "r", label="exact rational offset, rho = 1/4")
ax.plot(*polygon(off).T, "r:", lw=0.8, label="its control polygon")
ax.set_title("PH cubic: exact offset")
ax = axes[1]
ax.plot(*sample(parabola).T, "k", label="parabola")
ax.plot(*sample(par_off).T, "r", label="exact degree-6 offset, rho = 1")
ax.set_title("parabola: rational offset")
ax = axes[2]
ax.plot(*sample(vertex).T, "k", label="parabola")
for rho, color in ((Fraction(-1, 4), "g"), (-4, "r")):
    ax.plot(*_offset_samples(vertex, float(rho)).T, color, lw=1, label=f"offset rho = {rho} (float samples)")
for k, t in enumerate(offset_cusps(vertex, -4)):
    p = _offset_samples(vertex, -4.0)[int(round(float(t) * 399))]
    ax.plot(*p, "ko", label="cusps (exact parameters)" if k == 0 else None)
ax.set_title("cusps where the radius of curvature is |rho|")
for ax in axes:
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(out_path("ch08_offsets.png"), dpi=100)
print("\nwrote", out_path("ch08_offsets.png"))

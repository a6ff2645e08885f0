"""Teaching script, Sederberg's notes chapter 20: hybrid curves, exact areas of polynomial
Bézier curves, and certified areas of rational curves (the semicircle of 20.4).

Run:  python examples/teach_20_integrals.py
Prints the steps; writes examples/output/teach/ch20_integrals.png.
"""

from __future__ import annotations

from fractions import Fraction

from _teach import fmt, out_path, plt, polygon, sample, step, tex
from exactcagd import BezierCurve
from exactcagd.toolbox import integrals as ig

step("20.2 area under the cubic (0,0),(1,3),(3,2),(4,0): Bernstein product and the corrected D_ij")
c = BezierCurve([[0, 0], [1, 3], [3, 2], [4, 0]])
print("  int y dx =", fmt(ig.area_under(c)), " via n sum D_ij y_i x_j =", fmt(ig.area_under_by_formula(c)))
print("  D (n = 3), corrected with 1/C(2n, i+j):")
for row in ig.d2_coefficients(3):
    print("   ", "  ".join(f"{fmt(v):>7}" for v in row))
tex("area under the cubic, int y dx", ig.area_under(c), echo=False)
tex("D (n = 3)", [list(row) for row in ig.d2_coefficients(3)], echo=False)
ix, iy = ig.first_moments(c)
tex("I_x", ix, echo=False)
tex("I_y", iy, echo=False)
tex("volume of revolution / pi", ig.volume_over_pi(c), echo=False)
print("  I_x =", fmt(ix), " I_y =", fmt(iy), " volume of revolution = pi *", fmt(ig.volume_over_pi(c)))

semi = BezierCurve([[0, 0], [0, 1], [1, 1], [1, 0]], [1, Fraction(1, 3), Fraction(1, 3), 1])
step("20.1 the semicircle of radius 1/2 as a rational cubic, as a quartic hybrid curve")
h = ig.hybrid_curve(semi, 4)
print("  fixed points P_i:", fmt([p for p in h.points if p is not None]), " m =", h.m)
print("  moving control point M(t): points", fmt(h.moving.control_points), " weights", fmt(h.moving.weights))
a = ig.polynomial_approximation(semi, 4)
print("  P_m = centre of the box of M:", fmt(a.curve.control_points[h.m]), " half sizes", fmt(a.delta),
      " |P - R| <= ||Delta|| C(4,2)/2^4 =", a.bound)

step("20.4 certified area of the semicircle (exact value pi/8 = 0.392699081...)")
for tol in (Fraction(1, 10**3), Fraction(1, 10**6)):
    value, bound = ig.rational_integral(semi, "area", tol)
    print(f"  tol {float(tol):g}: area = {float(value):.10f} +- {float(bound):.2e}  (exact rational value, {len(str(value))} chars)")

fig, axs = plt.subplots(1, 2, figsize=(11, 4.3))
ax = axs[0]
ax.fill_between(*sample(c).T, alpha=0.3, label=f"exact area {fmt(ig.area_under(c))}")
ax.plot(*sample(c).T, "b-", label="cubic Bézier curve")
ax.plot(*polygon(c).T, "k--o", ms=3, label="control polygon")
ax.set_xlabel("x")
ax.set_ylabel("y")
ax.legend(fontsize=7)
ax.set_title(f"area under a cubic = {fmt(ig.area_under(c))}")
ax = axs[1]
ax.plot(*sample(semi).T, "b-", lw=3, alpha=0.4, label="rational cubic (semicircle)")
ax.plot(*sample(a.curve).T, "r-", lw=1, label="degree-4 polynomial approximation")
ax.plot(*polygon(h.moving).T, "g--o", ms=3, label="moving control point M(t) (control polygon)")
ax.plot(*sample(h.moving).T, "g-", lw=1, label="path of M(t)")
ax.set_aspect("equal")
ax.legend(fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.08))
ax.set_title("20.1 hybrid curve")
fig.tight_layout()
fig.savefig(out_path("ch20_integrals.png"), dpi=110)
print("\nwrote", out_path("ch20_integrals.png"))

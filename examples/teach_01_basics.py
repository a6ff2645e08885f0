"""Teaching script, Sederberg's notes chapter 1: vectors, rotation about an axis, lines, conics.

Run:  python examples/teach_01_basics.py
Prints every step exactly and writes examples/output/teach/ch01_basics.png.
"""

from __future__ import annotations

import sympy as sp

from _teach import fmt, out_path, plt, step, tex
from exactcagd.toolbox import basics as b

step("1.2 angle between (1,2,4) and (3,-4,2)")
u, v = (1, 2, 4), (3, -4, 2)
print("u.v =", b.dot(u, v), "  |u|^2 =", b.length_squared(u), "  |v|^2 =", b.length_squared(v))
c = b.cos_angle(u, v)
print("cos theta =", c, "(exact, in Q(sqrt(609)))  theta =", sp.N(b.angle(u, v) * 180 / sp.pi, 8), "deg")
tex("cos theta", c, echo=False)

step("1.2 projection of (3,2,1) onto (3,6,6)")
print("(P.Q)/(Q.Q) Q =", b.dot((3, 2, 1), (3, 6, 6)), "/", b.dot((3, 6, 6), (3, 6, 6)), "* (3,6,6) =", fmt(b.project((3, 2, 1), (3, 6, 6))))

step("1.2 triangle (1,1,1), (2,4,5), (3,2,6)")
print("P2 - P1 =", fmt(b.relative((2, 4, 5), (1, 1, 1))), " P3 - P1 =", fmt(b.relative((3, 2, 6), (1, 1, 1))))
print("cross =", fmt(b.cross((1, 3, 4), (2, 1, 5))), " area =", b.triangle_area((1, 1, 1), (2, 4, 5), (3, 2, 6)))
tex("(P2 - P1) x (P3 - P1)", list(b.cross((1, 3, 4), (2, 1, 5))), echo=False)
tex("area", b.triangle_area((1, 1, 1), (2, 4, 5), (3, 2, 6)), echo=False)

step("1.3 rotate (5,7,3) by 90 deg about the axis through (1,1,1) with direction (2,1,2)")
from exactcagd.proofs.sederberg_01_basics import _trace_rotation  # noqa: E402

_trace_rotation()
print("a rational angle instead: tan(theta/2) = 1/2 gives (cos, sin) =", fmt(b.cos_sin_from_tan_half("1/2")))
print("rotated point:", fmt(b.rotate_about_axis((5, 7, 3), (1, 1, 1), (2, 1, 2), *b.cos_sin_from_tan_half("1/2"))))

step("1.5 line through (1, 2) and (4, 6); distance of (0, 0)")
line = b.line_through((1, 2), (4, 6))
print("line (a, b, c):", fmt((line.a, line.b, line.c)), "  squared distance:", b.distance_squared_to_line((0, 0), line), "  distance:", b.distance_to_line((0, 0), line))

step("1.6 the conic x^2 + xy + y^2 - 7 = 0: classify, parametrize through a rational point, implicitize back")
conic = b.Conic.of((1, 1, 1, 0, 0, -7))
print("discriminant b^2 - 4ac =", conic.discriminant, "->", b.classify_conic(conic))
X, Y, W = b.parametrize_conic(conic)
print("X(t) =", fmt(X), " Y(t) =", fmt(Y), " W(t) =", fmt(W), "(power coefficients)")
t = sp.Symbol("t")
tex("(x(t), y(t))", [sum(sp.Rational(str(fmt(cf))) * t**i for i, cf in enumerate(P)) / sum(sp.Rational(str(fmt(cf))) * t**i for i, cf in enumerate(W)) for P in (X, Y)], echo=False)
print("implicit equation recovered (a, b, c, d, e, f):", fmt(b.implicitize_conic(X, Y, W).coefficients))
print("W's discriminant d1^2 - 4 d0 d2 =", W[1] ** 2 - 4 * W[0] * W[2], "->", b.classify_parametric_conic(X, Y, W))

fig, ax = plt.subplots(figsize=(5, 5))
ts = [k / 40 - 6 for k in range(481)]
pts = [(float(sum(c * t**i for i, c in enumerate(X))) / float(sum(c * t**i for i, c in enumerate(W))),
        float(sum(c * t**i for i, c in enumerate(Y))) / float(sum(c * t**i for i, c in enumerate(W)))) for t in ts]
ax.plot(*zip(*pts), ".", ms=2, label="rational parametrization")
for t in range(-4, 5):
    num = [sum(c * t**i for i, c in enumerate(P)) for P in (X, Y, W)]
    ax.plot(float(num[0] / num[2]), float(num[1] / num[2]), "ro", ms=4)
ax.set_aspect("equal")
ax.set_title("x^2 + xy + y^2 = 7: rational points at integer t")
ax.legend()
fig.savefig(out_path("ch01_basics.png"), dpi=110)
print("\nwrote", out_path("ch01_basics.png"))

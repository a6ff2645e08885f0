"""Teaching walk-through, notes chapter 6 beyond the foundation: B-splines on any knot vector.

Periodic B-splines (6.5), Bézier end conditions (6.6), symmetric polynomials and the polar
form (6.11), combining Bézier curves into one B-spline (6.12), knot intervals (6.13) and
basis functions (6.14), all in exact rational arithmetic.  Saves
``examples/output/teach/ch06_splines.png``.

Run:  python examples/teach_06_splines.py
"""

from __future__ import annotations

import numpy as np
from _teach import fmt, out_path, plt, polygon, sample, step, tex
from gmpy2 import mpq

from exactcagd import BezierCurve
from exactcagd.toolbox import bspline_extras as bx
from exactcagd.toolbox import knot_intervals as ki


def spline_xy(curve, k=200):
    lo, hi = curve.domain
    return np.array([[float(x) for x in curve.evaluate(lo + (hi - lo) * mpq(i, k))] for i in range(k + 1)])


def main():
    step("6.5 Periodic B-spline: repeat the first p control points and knot intervals")
    P = [[0, 0], [4, 0], [5, 3], [2, 5], [-1, 3]]
    closed = bx.periodic_bspline(P, 3, intervals=[1, 2, 3, 1, 2])
    print("  unrolled knots:", fmt(closed.knots))
    tex("unrolled knots", list(closed.knots), echo=False)
    lo, hi = closed.domain
    print("  P(start) =", fmt(closed.evaluate(lo)), " P(end) =", fmt(closed.evaluate(hi)), "-> closed")
    tex("P(start) = P(end)", list(closed.evaluate(lo)), echo=False)
    d0, d1 = closed.derivative(), closed.derivative().derivative()
    print("  P'(start) = P'(end):", d0.evaluate(lo) == d0.evaluate(hi), "  P''(start) = P''(end):", d1.evaluate(lo) == d1.evaluate(hi))

    step("6.6 Bézier end conditions: clamp the unclamped uniform cubic (same curve, (p+1)-fold end knots)")
    open_curve = bx.SplineCurve(P, range(9))
    clamped = open_curve.clamp()
    print("  knots", fmt(open_curve.knots), "->", fmt(clamped.knots))
    tex("clamped knots", list(clamped.knots), echo=False)
    print("  clamped control points:", fmt(clamped.control_points))
    tex("clamped control points", [list(q) for q in clamped.control_points], echo=False)
    print("  the curve now starts at its first control point:", clamped.evaluate(clamped.domain[0]) == clamped.control_points[0])

    step("6.11 Polar form of p(t) = t^3 + 6t^2 + 3t + 1 (the notes' example)")
    a = [1, 3, 6, 1]
    print("  p[t1,t2,t3] = 1 + 3 p1 + 6 p2 + p3, p1 = (t1+t2+t3)/3, p2 = (t1t2+t1t3+t2t3)/3, p3 = t1t2t3")
    print("  symmetric p_2[1,2,3] =", fmt(bx.symmetric_basis(2, [1, 2, 3])), "= (2 + 3 + 6)/3")
    tex("p_2[1,2,3]", bx.symmetric_basis(2, [1, 2, 3]), echo=False)
    b = [bx.polar_form_value(a, [0] * (3 - i) + [1] * i) for i in range(4)]
    print("  Bernstein coefficients on [0,1]: p[0,0,0], p[0,0,1], p[0,1,1], p[1,1,1] =", fmt(b), "(printed 1, 2, 5, 11)")
    tex("(p[0,0,0], p[0,0,1], p[0,1,1], p[1,1,1])", list(b), echo=False)

    step("6.12 Combining Bézier curves into one B-spline: multiplicity = degree - continuity order")
    c1 = BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]])
    c2 = BezierCurve([[4, 0], [5, -2], [7, -1], [8, 1]])  # collinear legs, equal speed -> C^1
    c3 = BezierCurve([[8, 1], [8, 3], [9, 4], [10, 4]])  # a corner -> C^0
    print("  continuity orders:", bx.continuity_order(c1, c2), bx.continuity_order(c2, c3))
    chain = bx.bezier_chain_to_bspline([c1, c2, c3])
    print("  knots:", fmt(chain.knots))
    tex("knots", list(chain.knots), echo=False)
    print("  control points:", fmt(chain.control_points))
    tex("control points", [list(q) for q in chain.control_points], echo=False)

    step("6.13 Knot intervals: split d_2 = 3 of a periodic cubic into 1 + 2 (Figure 6.16 construction)")
    d = [1, 2, 3, 1, 2]
    c = ki.KnotIntervalCurve(P, d, 3)
    for i, lab in enumerate(c.polar_labels()):
        print(f"  polar label of P_{i}: {fmt(lab)}")
        tex(f"polar label of P_{i}", list(lab), echo=False)
    new = ki.split_cubic_construction(P, d, 2, 1)
    split = c.split_interval(2, 1)
    print("  new control points:", fmt([tuple(p) for p in new]))
    tex("new control points", [list(q) for q in new], echo=False)
    print("  construction = polar-form insertion:", bool(np.all(new == split.points_array())), "| same curve:", split.same_curve(c))
    print("  hodograph (6.6) control points:", fmt(c.hodograph().control_points))
    tex("hodograph (6.6) control points", [list(q) for q in c.hodograph().control_points], echo=False)

    step("6.14 Basis function N[0,1,2,4,5] and its refinement at k = 3")
    for (lo_, hi_), coeffs in bx.basis_function_pieces([0, 1, 2, 4, 5]):
        print(f"  on [{fmt(lo_)}, {fmt(hi_)}] Bernstein coefficients {fmt(list(coeffs))}")
        tex(f"Bernstein coefficients on [{fmt(lo_)}, {fmt(hi_)}]", list(coeffs), echo=False)
    parts = bx.refine_basis_function([0, 1, 2, 4, 5], 3)
    print("  N[0,1,2,4,5] =", " + ".join(f"{fmt(cf)} N{fmt(tuple(ks))}" for cf, ks in parts))
    tex("coefficients of the refined N's", [cf for cf, _ks in parts], echo=False)
    print("  recurrence (6.14), corrected: B_0^3(3) =", fmt(bx.basis_recurrence([0, 1, 2, 4, 5], 0, 3, 3)),
          "= N[0,1,2,4,5](3) =", fmt(bx.basis_function([0, 1, 2, 4, 5], 3)))
    tex("N[0,1,2,4,5](3)", bx.basis_function([0, 1, 2, 4, 5], 3), echo=False)

    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    ax = axes[0]
    ax.plot(*spline_xy(closed).T, "k-", lw=2, label="periodic cubic (6.5)")
    ax.plot(*np.array(P + P[:1], dtype=float).T, "o--", color="tab:blue", label="control polygon")
    ax.plot(*np.vstack([split.points_array(), split.points_array()[:1]]).astype(float).T, "s:", color="tab:red", label="after splitting d_2")
    ax.set_aspect("equal")
    ax.set_title("6.5 periodic cubic, 6.13 knot interval split", fontsize=10)
    ax.legend(fontsize=7)
    ax = axes[1]
    for k, piece in enumerate((c1, c2, c3)):
        ax.plot(*sample(piece).T, "k-", lw=2, label="three Bézier curves" if k == 0 else None)
        ax.plot(*polygon(piece).T, ":", color="gray", label="their control polygons" if k == 0 else None)
    ax.plot(*np.array(chain.control_points, dtype=float).T, "o-", color="tab:green", label="control polygon of the one B-spline (6.12)")
    ax.set_aspect("equal")
    ax.set_title("6.12 Bézier chain -> one B-spline", fontsize=10)
    ax.legend(fontsize=7)
    ax = axes[2]
    xs = [mpq(i, 50) * 5 for i in range(51)]
    ax.plot([float(x) for x in xs], [float(bx.basis_function([0, 1, 2, 4, 5], x)) for x in xs], "k-", label="N[0,1,2,4,5]")
    for cf, ks in parts:
        ax.plot([float(x) for x in xs], [float(cf * bx.basis_function(ks, x)) for x in xs], "--", label=f"{fmt(cf)} N{fmt(tuple(ks))}")
    ax.set_xlabel("t")
    ax.set_ylabel("basis function value")
    ax.set_title("6.14 N[0,1,2,4,5] refined at t = 3", fontsize=10)
    ax.legend(fontsize=7)
    fig.tight_layout()
    path = out_path("ch06_splines.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"\npicture: {path}")


if __name__ == "__main__":
    main()

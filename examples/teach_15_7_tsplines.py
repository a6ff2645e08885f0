"""Teaching walk-through, notes 15.7: cubic T-splines, exact.

Rule 1 knot vectors, the numerical example of 15.7.1 by polar form, blending-function
refinement (15.14)-(15.17), the local refinement algorithm (15.7.5) and conversion into a
tensor-product B-spline (15.7.6).  Saves ``examples/output/teach/ch15_tsplines.png``.

Run:  python examples/teach_15_7_tsplines.py
"""

from __future__ import annotations

from _teach import fmt, out_path, plt, step, tex
from gmpy2 import mpq

from exactcagd.toolbox import bspline_extras as bx
from exactcagd.toolbox.tsplines import TMesh


def t_mesh():
    """A 7 x 6 grid of knot lines with a T-junction: column 3 stops below row 2 and above row 4, row 3 stops at column 2."""
    pts = {}
    for c in range(7):
        for r in range(6):
            if (c == 3 and r in (2, 3)) or (r == 3 and c > 2):
                continue
            pts[(c, r)] = (c, r, (c * r) % 3)
    se = [(c, 0, 5) for c in range(7) if c != 3] + [(3, 0, 1), (3, 4, 5)]
    te = [(r, 0, 6) for r in (0, 1, 2, 4, 5)] + [(3, 0, 2)]
    return TMesh(range(7), range(6), pts, se, te)


def main():
    step("15.7.1 Numerical example: N[0,1,2,4,5](3) by the polar form (blossom) of one cubic segment")
    f = {"124": mpq(1), "012": mpq(0), "245": mpq(0)}
    f123 = (f["012"] + 3 * f["124"]) / 4  # 3/4 of the way from f(0,1,2) to f(1,2,4) (x = 3 on [0, 4])
    f234 = (2 * f["124"] + 2 * f["245"]) / 4  # x = 3 on [1, 5]; f(3,4,5) = 0 since f(2,4,5) = f(4,5,6) = 0
    f233 = (f123 + 2 * f234) / 3
    f334 = (2 * f234 + mpq(0)) / 3
    f333 = (f233 + f334) / 2
    for name, val in (("f(1,2,3)", f123), ("f(2,3,4)", f234), ("f(2,3,3)", f233), ("f(3,3,4)", f334), ("f(3,3,3)", f333)):
        print(f"  {name} = {fmt(val)}")
        tex(name, val, echo=False)
    print("  check: basis_function([0,1,2,4,5], 3) =", fmt(bx.basis_function([0, 1, 2, 4, 5], 3)))
    print("  N[0,1,3,5,6](4) =", fmt(bx.basis_function([0, 1, 3, 5, 6], 4)), " so B = 11/24 * 23/60 =", fmt(mpq(11, 24) * mpq(23, 60)))
    tex("N[0,1,3,5,6](4)", bx.basis_function([0, 1, 3, 5, 6], 4), echo=False)
    tex("B = N[0,1,2,4,5](3) N[0,1,3,5,6](4)", mpq(11, 24) * mpq(23, 60), echo=False)
    print("  (the notes print the s-vector of B_10 as [0,1,2,5,7]; N[0,1,2,5,7](3) =",
          fmt(bx.basis_function([0, 1, 2, 5, 7], 3)), "- see the erratum)")
    tex("N[0,1,2,5,7](3)", bx.basis_function([0, 1, 2, 5, 7], 3), echo=False)

    step("15.7.3 Refinement (15.16): insert k = 3 into [0,1,2,4,5]")
    for c, ks in bx.refine_basis_function([0, 1, 2, 4, 5], 3):
        print(f"  {fmt(c)} * N{fmt(tuple(ks))}")
        tex(f"coefficient of N{fmt(tuple(ks))}", c, echo=False)

    step("15.7.1 Rule 1 on a T-mesh and 15.7.5 local refinement")
    m = t_mesh()
    s_vec, t_vec = m.knot_vectors((2, 3))
    print("  control point at the T-junction (2,3): s-knots", fmt(s_vec), " t-knots", fmt(t_vec))
    tex("s-knots at (2,3)", list(s_vec), echo=False)
    tex("t-knots at (2,3)", list(t_vec), echo=False)
    print("  classification:", m.classify())
    r = m.refine([(3, 2)])
    added = sorted(set(r.points) - set(m.points))
    print("  insert a control point at (s3, t2); the algorithm adds", [p for p in added if p != (3, 2)], "to repair violations")
    print("  new weights:", {k: fmt(v) for k, v in r.weights.items() if v != 1}, " classification:", r.classify())
    for s, t in (("5/2", "5/2"), ("3", "7/2")):
        print(f"  P({s},{t}) before = {fmt(m.evaluate(s, t))}  after = {fmt(r.evaluate(s, t))}")
        tex(f"P({s},{t}) after refinement", list(r.evaluate(s, t)), echo=False)

    step("15.7.6 Conversion into a tensor-product B-spline (M_{1,n} of (15.19)-(15.23))")
    tp = m.to_bspline()
    S, T = tp.S, tp.T
    print("  global knots s:", fmt(S), " t:", fmt(T))
    tex("global knots s", list(S), echo=False)
    tex("global knots t", list(T), echo=False)
    print("  same point at (5/2, 5/2):", tp.evaluate("5/2", "5/2") == m.evaluate("5/2", "5/2"))

    fig, ax = plt.subplots(figsize=(5.5, 4.5))
    for c, rr in m.s_edges:
        ax.plot([c, c], [rr, rr + 1], "k-", lw=1)
    for c, rr in m.t_edges:
        ax.plot([c, c + 1], [rr, rr], "k-", lw=1)
    ax.plot(*zip(*m.points), "o", color="tab:blue", label="control points (pre-image)")
    ax.plot(*zip(*added), "s", color="tab:red", ms=9, mfc="none", label="added by local refinement")
    ax.set_title("T-mesh pre-image (15.7)")
    ax.legend(fontsize=7, loc="upper left")
    path = out_path("ch15_tsplines.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"\npicture: {path}")


if __name__ == "__main__":
    main()

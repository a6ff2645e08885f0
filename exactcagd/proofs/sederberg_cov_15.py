"""Sederberg's notes, chapter 15 items without a row: the tensor product (15.1), the second-derivative
bounds (15.6), the T-spline equation (15.7)-(15.13), blending-function refinement (15.18), the
homogeneous curve and patch of 15.8 (15.24)-(15.25), (15.34)-(15.35).  ((15.12) and (15.58) have
their rows in sederberg_15_corner_forms.)

Every check is sympy from first principles (outer products, Bernstein differentiation, the
Cox-de Boor recursion for B-splines, cross-checked with ``sympy.bspline_basis``, projection of
homogeneous sums); no exactcagd function is under test here.
"""

from __future__ import annotations

import functools
import itertools
import random

import sympy as sp

from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified, verified_range
from exactcagd.proofs.sederberg_cov_16 import check_rational_curve, check_rational_patch

DOC = "sederberg"
s, t, u, v = sp.symbols("s t u v")


def _B(n, i, var):
    return sp.binomial(n, i) * var**i * (1 - var) ** (n - i)


def _cox_de_boor(knots, x):
    """The B-spline of degree len(knots) - 2 over ``knots`` at x, by the Cox-de Boor recursion (half-open spans, exact)."""
    if len(knots) == 2:
        return sp.Integer(1) if knots[0] <= x < knots[1] else sp.Integer(0)
    d = len(knots) - 2
    left = (x - knots[0]) / (knots[d] - knots[0]) * _cox_de_boor(knots[:-1], x) if knots[d] != knots[0] else 0
    right = (knots[-1] - x) / (knots[-1] - knots[1]) * _cox_de_boor(knots[1:], x) if knots[-1] != knots[1] else 0
    return sp.nsimplify(left + right)


@functools.lru_cache(maxsize=None)
def _N_at(knots, at):
    return _cox_de_boor([sp.Integer(k) for k in knots], at)


def _N(knots, var, at):
    """The cubic B-spline N[k0, .., k4] at ``at`` (``var`` names the parameter; Cox-de Boor, exact rationals)."""
    return _N_at(tuple(knots), sp.sympify(at))


# ---------------------------------------------------------------------------- 15.1
@claim(doc=DOC, section="15", ref="(15.1)",
       statement="[a0, a1, a2]^T (x) [b0 b1 b2 b3] is the 3 x 4 array a_i b_j; the blending functions of a tensor-product surface are organised like it")
def tensor_product_array():
    a, b = sp.symbols("a0:3"), sp.symbols("b0:4")
    printed = sp.Matrix(3, 4, lambda i, j: a[i] * b[j])
    assert sp.Matrix(a) * sp.Matrix([b]) == printed  # column times row
    assert sp.Matrix(sp.kronecker_product(sp.Matrix(a), sp.Matrix([b]))) == printed
    # the bicubic Bézier blending functions B_i^3(s) B_j^3(t) are the tensor product of the two univariate bases
    Bs, Bt = sp.Matrix([_B(3, i, s) for i in range(4)]), sp.Matrix([[_B(3, j, t) for j in range(4)]])
    assert (Bs * Bt - sp.Matrix(4, 4, lambda i, j: _B(3, i, s) * _B(3, j, t))).applyfunc(sp.expand) == sp.zeros(4, 4)
    return verified("symbolic entries: the printed 3 x 4 array is the outer product (and the Kronecker product) of the column and "
                    "the row; the bicubic blending array B_i(s) B_j(t) is the outer product of the two Bernstein bases",
                    compared="printed (15.1) array vs sympy outer / Kronecker products", reference="sympy")


# ---------------------------------------------------------------------------- 15.4
@claim(doc=DOC, section="15.4", ref="(15.6)",
       statement="M1 <= m(m-1) max ||P_{i+2,j} - 2P_{i+1,j} + P_ij||, M2 <= mn max ||P_{i+1,j+1} - P_{i+1,j} - P_{i,j+1} + P_ij||, M3 <= n(n-1) max ||P_{i,j+2} - 2P_{i,j+1} + P_ij||")
def second_derivative_bounds():
    rng = random.Random(156)
    for m, n in ((2, 2), (3, 2), (3, 3), (2, 4)):
        # one coordinate at a time: every identity below is linear in the control points
        P = [[rng.randint(-9, 9) for _ in range(n + 1)] for _ in range(m + 1)]
        poly = lambda e: sp.Poly(e, s, t)  # noqa: E731
        r = poly(sum(P[i][j] * _B(m, i, s) * _B(n, j, t) for i in range(m + 1) for j in range(n + 1)))
        # the second partials are Bézier patches with the printed differences as control points (scaled) ...
        rss = poly(sum(m * (m - 1) * (P[i + 2][j] - 2 * P[i + 1][j] + P[i][j]) * _B(m - 2, i, s) * _B(n, j, t)
                       for i in range(m - 1) for j in range(n + 1)))
        rst = poly(sum(m * n * (P[i + 1][j + 1] - P[i + 1][j] - P[i][j + 1] + P[i][j]) * _B(m - 1, i, s) * _B(n - 1, j, t)
                       for i in range(m) for j in range(n)))
        rtt = poly(sum(n * (n - 1) * (P[i][j + 2] - 2 * P[i][j + 1] + P[i][j]) * _B(m, i, s) * _B(n - 2, j, t)
                       for i in range(m + 1) for j in range(n - 1)))
        assert rss == r.diff(s).diff(s) and rst == r.diff(s).diff(t) and rtt == r.diff(t).diff(t)
        # ... whose blending functions are >= 0 on [0,1]^2 and sum to 1: ||r_ss|| <= m(m-1) max ||diff|| (convex hull).
        for bm, bn in ((m - 2, n), (m - 1, n - 1), (m, n - 2)):
            assert sp.expand(sum(_B(bm, i, s) * _B(bn, j, t) for i in range(bm + 1) for j in range(bn + 1))) == 1
        # and the bound is attained at a corner when the extreme difference sits there
        assert rss.eval({s: 0, t: 0}) == m * (m - 1) * (P[2][0] - 2 * P[1][0] + P[0][0])
    return verified_range("(m, n) = (2,2), (3,2), (3,3), (2,4) with random integer control points",
                          "sympy: r_ss, r_st, r_tt equal the Bézier patches with control points m(m-1) Delta^2_s, mn Delta_s Delta_t, "
                          "n(n-1) Delta^2_t of the printed differences; their blending functions are a non-negative partition of unity, "
                          "so the norms are bounded by the largest control point (convex hull)",
                          compared="printed (15.6) vs sympy differentiation of the Bernstein form", reference="sympy")


# ---------------------------------------------------------------------------- 15.7 T-splines
_GRID_S = [-2, -1, 0, 1, 3, 4, 6, 7]  # knot lines in s (with phantom knots), a rectangular T-mesh (no T-junctions)
_GRID_T = [-1, 0, 2, 3, 5, 6, 8]


def _grid_tspline(rng):
    """Control points of a rectangular T-mesh at the knot coordinates (S[a], T[b]) and their Rule-1 knot vectors."""
    pts = {}
    for a in range(2, len(_GRID_S) - 2):
        for b in range(2, len(_GRID_T) - 2):
            w = rng.randint(1, 4)
            cart = [sp.Rational(rng.randint(-9, 9), rng.randint(1, 2)) for _ in range(3)]
            # Rule 1: on a full grid the rays meet the next two knot lines on either side
            pts[(a, b)] = dict(w=w, cart=cart, hom=[w * x for x in cart] + [w],
                                sv=_GRID_S[a - 2:a + 3], tv=_GRID_T[b - 2:b + 3])
    return pts


def _nurbs_point(pts, sv, tv):
    """(15.2) with B-spline blending functions: the tensor-product rational B-spline at (sv, tv), the basis
    functions indexed on the global knot vectors (the a-th function of the s knot sequence, not Rule 1)."""
    Ns = [_cox_de_boor([sp.Integer(k) for k in _GRID_S[i:i + 5]], sv) for i in range(len(_GRID_S) - 4)]
    Nt = [_cox_de_boor([sp.Integer(k) for k in _GRID_T[j:j + 5]], tv) for j in range(len(_GRID_T) - 4)]
    num, den = [0, 0, 0], 0
    for (a, b), p in pts.items():
        B = Ns[a - 2] * Nt[b - 2]
        den += p["w"] * B
        num = [x + p["w"] * c * B for x, c in zip(num, p["cart"])]
    return [x / den for x in num]


def _blend(p, sv, tv):
    """(15.9): B_i(s, t) = N[s_i](s) N[t_i](t) with the Rule-1 knot vectors (15.10), (15.11)."""
    return _N(p["sv"], s, sv) * _N(p["tv"], t, tv)


@claim(doc=DOC, section="15.7.1", ref="(15.7)",
       statement="P(s,t) = sum w_i P_i B_i / sum w_i B_i where P_i = (x_i, y_i, z_i, w_i) are control points in P^4 whose Cartesian coordinates are (x_i, y_i, z_i)/w_i")
def tspline_equation_weights():
    rng = random.Random(157)
    pts = _grid_tspline(rng)
    at = (sp.Rational(3, 2), sp.Rational(7, 2))
    reference = _nurbs_point(pts, *at)

    def printed(pts_, sv, tv):  # (15.7) with the text's P_i = (x_i, y_i, z_i, w_i): Cartesian part of sum w_i P_i B_i / sum w_i B_i
        Bs = {k: _blend(p, sv, tv) for k, p in pts_.items()}
        den = sum(p["w"] * Bs[k] for k, p in pts_.items())
        return [sum(p["w"] * p["hom"][c] * Bs[k] for k, p in pts_.items()) / den for c in range(3)]

    def corrected(pts_, sv, tv):  # P(s, t) = sum P_i B_i in P^4, projected (the T-spline paper's form; = (15.8))
        Bs = {k: _blend(p, sv, tv) for k, p in pts_.items()}
        H = [sum(p["hom"][c] * Bs[k] for k, p in pts_.items()) for c in range(4)]
        return [H[c] / H[3] for c in range(3)]

    def agrees_with_nurbs(form):
        got = form(pts, *at)
        return None if got == reference else f"at (s, t) = {at}: {got} vs the rational B-spline surface {reference}"

    return erratum("P(s,t) = sum w_i P_i B_i / sum w_i B_i, with P_i = (x_i, y_i, z_i, w_i) in P^4",
                   "P(s,t) = sum P_i B_i(s,t) in P^4 (Cartesian: (15.8)); or (15.7) with P_i the Cartesian points (x_i, y_i, z_i)/w_i",
                   "with the homogeneous P_i the text defines, (15.7) weights every point twice (w_i^2 in effect) and disagrees with "
                   "(15.8) and with the rational B-spline surface that a rectangular T-mesh must reduce to (15.7.1); checked on a "
                   "4 x 3 rectangular T-mesh with random weights, Cox-de Boor)",
                   printed_form=printed, corrected_form=corrected, check=L.predicate(agrees_with_nurbs), reference="sympy")


@claim(doc=DOC, section="15.7.1", ref="(15.8)-(15.11), (15.13)",
       statement="Cartesian points sum (x_i, y_i, z_i) B_i / sum w_i B_i with B_i(s,t) = N[s_i0..s_i4](s) N[t_i0..t_i4](t) for the knot vectors s_i, t_i; B_i(3,4) = N[s_i](3) N[t_i](4)")
def tspline_cartesian_form():
    rng = random.Random(158)
    pts = _grid_tspline(rng)
    for at in ((sp.Rational(3, 2), sp.Rational(7, 2)), (sp.Integer(3), sp.Integer(4)), (sp.Rational(1, 3), sp.Rational(5, 2))):
        Bs = {k: _blend(p, *at) for k, p in pts.items()}
        den = sum(p["w"] * Bs[k] for k, p in pts.items())
        form = [sum(p["hom"][c] * Bs[k] for k, p in pts.items()) / den for c in range(3)]
        assert form == _nurbs_point(pts, *at)
    # (15.13): B_i(3, 4) is the product of the two univariate values; sympy's bspline_basis agrees with the recursion
    p = pts[(3, 3)]
    prod2 = sp.bspline_basis(3, tuple(p["sv"]), 0, s).subs(s, 3) * sp.bspline_basis(3, tuple(p["tv"]), 0, t).subs(t, 4)
    assert prod2 == _blend(p, 3, 4) != 0
    return verified("4 x 3 rectangular T-mesh (Rule-1 knot vectors: the two knot lines on each side), random weights: (15.8) with "
                    "the blending functions (15.9)-(15.11) equals the tensor-product rational B-spline surface built from sympy's "
                    "global basis (Cox-de Boor recursion) at three parameters including (3, 4)",
                    compared="printed (15.8)-(15.11), (15.13) vs the tensor-product rational B-spline on the global knot vectors (Cox-de Boor) and sympy bspline_basis at (3, 4)", reference="sympy")


@claim(doc=DOC, section="15.7.3", ref="(15.18)",
       statement="knot insertion in s and t splits B_1(s,t) into scaled blending functions: B_1 = c^1 B~_1 + c^2 B~_2 + c^3 B~_3 + c^4 B~_4")
def blending_refinement():
    sv, tv = (0, 1, 3, 4, 6), (0, 2, 3, 5, 6)
    ks, kt = 2, 4  # one knot inserted in each direction
    sref, tref = sorted(sv + (ks,)), sorted(tv + (kt,))
    # the refinement coefficients solved from N = c N[sub0] + d N[sub1] at sample points (sympy linear solve), for s and for t
    coeff = {}
    for name, var, vec, ref in (("s", s, sv, sref), ("t", t, tv, tref)):
        subs_ = [ref[:5], ref[1:]]
        samples = [sp.Rational(2 * k + 1, 2) for k in range(6)]  # 1/2 .. 11/2: over both supports
        c0, c1 = sp.symbols("c0 c1")
        eqs = [c0 * _N(subs_[0], var, x) + c1 * _N(subs_[1], var, x) - _N(vec, var, x) for x in samples]
        sol = sp.solve(eqs, [c0, c1], dict=True)
        assert len(sol) == 1
        coeff[name] = [(sol[0][c0], subs_[0]), (sol[0][c1], subs_[1])]
    terms = [(cs * ct, vs, vt) for (cs, vs), (ct, vt) in itertools.product(coeff["s"], coeff["t"])]
    assert len(terms) == 4 and all(cst > 0 for cst, _, _ in terms)
    for x in (sp.Rational(1, 3), sp.Rational(5, 4), sp.Rational(13, 5), sp.Rational(27, 5)):  # off the sample points
        for y in (sp.Rational(1, 3), sp.Rational(5, 2), sp.Rational(9, 2), sp.Rational(23, 4)):
            B1 = _N(sv, s, x) * _N(tv, t, y)
            assert B1 == sum(cst * _N(vs, s, x) * _N(vt, t, y) for cst, vs, vt in terms)
    return verified("B_1 = N[0,1,3,4,6](s) N[0,2,3,5,6](t), one knot inserted in s (2) and in t (4): four positive coefficients "
                    "c^j = (s coefficient)(t coefficient) solved in sympy; B_1 = sum c^j B~_j at 16 parameters",
                    compared="printed (15.18) vs the refinement coefficients solved by linear algebra (sympy) on Cox-de Boor values", reference="sympy")


# ---------------------------------------------------------------------------- 15.8
@claim(doc=DOC, section="15.8", ref="(15.24), (15.25)",
       statement="a rational Bézier curve in R^3: p(t) = Pi(P(t)), P(t) = sum P_i B_i^n(t), P_i = w_i (x_i, y_i, z_i, 1)")
def homogeneous_curve_definition():
    assert check_rational_curve(random.Random(1524)) == 1
    return verified("n = 2, 3 random points and weights (sympy): the w component of P(t) is sum w_i B_i, the others sum w_i p_i B_i; "
                    "end points p_0, p_n; invariant under w -> c w; one parameter (rank 1): a curve, as printed",
                    compared="printed (15.24), (15.25) vs sympy projection of the homogeneous Bernstein sum", reference="sympy")


@claim(doc=DOC, section="15.8", ref="(15.34), (15.35)",
       statement="a tensor-product rational Bézier patch p(s,t) = Pi(P(s,t)), P(s,t) = sum sum P_ij B_i^m(s) B_j^n(t)")
def homogeneous_patch_definition():
    assert check_rational_patch(random.Random(1534)) == 2
    return verified("m = 2, n = 3 random points and weights (sympy): Pi(P(s,t)) is (15.2), interpolates the corners, rank 2",
                    compared="printed (15.34), (15.35) vs sympy projection of the homogeneous tensor sum", reference="sympy")

"""Ledger: Sederberg's notes, chapter 10 (polynomial interpolation, error bounds, Chebyshev
points, points and normals)."""

from __future__ import annotations

import random
from fractions import Fraction

import sympy as sp
from gmpy2 import mpq

from exactcagd import BezierCurve
from exactcagd.toolbox import interpolation as ip
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, reconstructed, verified, verified_range

t = sp.Symbol("t")
PARAMS = [0, Fraction(1, 4), Fraction(3, 4), 1]
POINTS = [[0, 0], [2, 2], [0, 3], [2, 4]]
NEWTON_T = [0, 1, 3, 4]
NEWTON_P = [[0, 0], [3, 3], [5, 3], [7, 0]]


def _q(x):
    return sp.Rational(int(x.numerator), int(x.denominator))


@claim(doc="sederberg", section="10.1", ref="power basis", statement="x = 18t - 48t^2 + 32t^3, y = 12t - 56/3 t^2 + 32/3 t^3")
def undetermined_power():
    c = ip.undetermined_coefficients(PARAMS, POINTS)
    printed = [18 * t - 48 * t**2 + 32 * t**3, 12 * t - sp.Rational(56, 3) * t**2 + sp.Rational(32, 3) * t**3]
    assert list(c.to_sympy(t)) == printed
    # independent: the printed cubics pass through the four points at the four parameters (sympy substitution)
    assert [[x.subs(t, sp.Rational(u)) for x in printed] for u in PARAMS] == POINTS
    return verified("exact solve of the 4x4 Vandermonde systems",
                    compared="printed x(t), y(t) vs sympy substitution at t = 0, 1/4, 3/4, 1 (they interpolate the four points) and vs exactcagd's Vandermonde solve", reference='sympy')


@claim(doc="sederberg", section="10.1", ref="Bernstein matrix", statement="rows (1,0,0,0), (27/64, 27/64, 9/64, 1/64), (1/64, 64/64, 64/64, 64/64), (0,0,0,1)")
def bernstein_matrix():
    rows = [[sp.binomial(3, i) * u**i * (1 - u) ** (3 - i) for i in range(4)] for u in (sp.Integer(0), sp.Rational(1, 4), sp.Rational(3, 4), sp.Integer(1))]
    assert rows[1] == [sp.Rational(27, 64), sp.Rational(27, 64), sp.Rational(9, 64), sp.Rational(1, 64)]
    assert rows[2] == [sp.Rational(1, 64), sp.Rational(9, 64), sp.Rational(27, 64), sp.Rational(27, 64)]
    def is_bernstein_row(row):
        ref = [sp.binomial(3, i) * sp.Rational(3, 4) ** i * sp.Rational(1, 4) ** (3 - i) for i in range(4)]
        return None if list(row) == ref else f"{list(row)} vs B^3_i(3/4) = {ref}"
    return reconstructed(printed="third row 1/64, 64/64, 64/64, 64/64",
                         corrected="third row 1/64, 9/64, 27/64, 27/64 (B^3_i(3/4), the mirror of the second row)",
                         detail="the extracted row is damaged; the Bernstein values at t = 3/4 are computed exactly",
        printed_form=[sp.Rational(1, 64), 1, 1, 1], corrected_form=[sp.Rational(1, 64), sp.Rational(9, 64), sp.Rational(27, 64), sp.Rational(27, 64)], check=L.predicate(is_bernstein_row),
    )


@claim(doc="sederberg", section="10.1", ref="Bézier control points", statement="x: a0 = 0, a1 = 6, a2 = -4, a3 = 2; y: 0, 4, 16/9, 4")
def undetermined_bernstein():
    c = ip.undetermined_coefficients(PARAMS, POINTS, basis="bernstein")
    assert c.control_points == ((0, 0), (6, 4), (-4, mpq(16, 9)), (2, 4))
    # independent: the Bezier cubic with the printed control points interpolates (sympy substitution)
    printed = [[0, 0], [6, 4], [-4, sp.Rational(16, 9)], [2, 4]]
    curve = [sum(printed[i][k] * sp.binomial(3, i) * t**i * (1 - t) ** (3 - i) for i in range(4)) for k in range(2)]
    assert [[x.subs(t, sp.Rational(u)) for x in curve] for u in PARAMS] == POINTS
    assert c.same_curve(ip.undetermined_coefficients(PARAMS, POINTS).to_bezier(0, 1))
    return verified("direct Bernstein solve; same curve as the power-basis solution",
                    compared="printed control points vs sympy: the Bezier cubic they define passes through the four points at the four parameters; exactcagd's Bernstein solve gives them and the same curve as the power solution", reference='sympy')


@claim(doc="sederberg", section="10.2", ref="L_i^3", statement="L0 = -16/3 (t-1/4)(t-3/4)(t-1), L1 = 32/3 t(t-3/4)(t-1), L2 = -32/3 t(t-1/4)(t-1), L3 = 16/3 t(t-1/4)(t-3/4); the expansion equals 10.1")
def lagrange_example():
    L = [b.to_sympy(t) for b in ip.lagrange_basis(PARAMS)]
    h, q = sp.Rational(1, 4), sp.Rational(3, 4)
    printed = [-sp.Rational(16, 3) * (t - h) * (t - q) * (t - 1), sp.Rational(32, 3) * t * (t - q) * (t - 1),
               -sp.Rational(32, 3) * t * (t - h) * (t - 1), sp.Rational(16, 3) * t * (t - h) * (t - q)]
    assert all(sp.expand(a - b) == 0 for a, b in zip(L, printed))
    # independent: the printed L_i are the Lagrange polynomials, L_i(t_j) = delta_ij (sympy substitution)
    assert [[x.subs(t, sp.Rational(u)) for u in PARAMS] for x in printed] == [[int(i == j) for j in range(4)] for i in range(4)]
    assert ip.lagrange_interpolate(PARAMS, POINTS) == ip.undetermined_coefficients(PARAMS, POINTS)
    assert [sp.expand(sum(P[k] * x for P, x in zip(POINTS, printed))) for k in range(2)] == [
        18 * t - 48 * t**2 + 32 * t**3, 12 * t - sp.Rational(56, 3) * t**2 + sp.Rational(32, 3) * t**3]  # "equals 10.1"
    return verified("Lagrange polynomials and the interpolating curve identical to the undetermined-coefficient solution",
                    compared='printed L_0..L_3 vs sympy: L_i(t_j) = delta_ij and sum P_i L_i expands to the printed 10.1 cubics; exactcagd lagrange_basis expands to the printed forms', reference='sympy')


@claim(doc="sederberg", section="10.2", ref="properties", statement="Lagrange blending functions are coordinate system independent but do not obey the convex hull property")
def lagrange_properties():
    L = [sp.prod([(t - sp.Rational(b)) / (sp.Rational(a) - sp.Rational(b)) for b in PARAMS if b != a]) for a in PARAMS]  # definition
    assert all(sp.expand(x - b.to_sympy(t)) == 0 for x, b in zip(L, ip.lagrange_basis(PARAMS)))
    assert sp.expand(sum(L)) == 1
    assert L[0].subs(t, sp.Rational(1, 2)) < 0
    return verified(f"sum L_i = 1; L_0(1/2) = {L[0].subs(t, sp.Rational(1, 2))} < 0",
                    compared='printed properties vs the Lagrange polynomials built from their definition in sympy: sum L_i = 1 (coordinate independence), L_0(1/2) = -1/6 < 0 (no convex hull)', reference='sympy')


@claim(doc="sederberg", section="10.3", ref="Example (Newton)", statement="divided differences (3,3), (1,0), (2,-3); (-2/3,-1), (1/3,-1); (1/4, 0); P(2) = (25/6, 4)")
def newton_example():
    table = ip.divided_differences(NEWTON_T, NEWTON_P)
    # independent: the divided-difference recursion written out here in Fraction arithmetic
    ref = [[tuple(Fraction(v) for v in p) for p in NEWTON_P]]
    for k in range(1, 4):
        ref.append([tuple((b - a) / (NEWTON_T[i + k] - NEWTON_T[i]) for a, b in zip(ref[-1][i], ref[-1][i + 1])) for i in range(4 - k)])
    assert ref[1:] == [[(3, 3), (1, 0), (2, -3)], [(Fraction(-2, 3), -1), (Fraction(1, 3), -1)], [(Fraction(1, 4), 0)]]
    assert table[1] == [(3, 3), (1, 0), (2, -3)]
    assert table[2] == [(mpq(-2, 3), -1), (mpq(1, 3), -1)]
    assert table[3] == [(mpq(1, 4), 0)]
    newton = ip.newton_interpolate(NEWTON_T, NEWTON_P)
    assert newton(2) == (mpq(25, 6), 4)
    ref = [sp.interpolate([(a, b[k]) for a, b in zip(NEWTON_T, NEWTON_P)], t).subs(t, 2) for k in range(2)]
    assert ref == [sp.Rational(25, 6), 4]
    return verified("table, Newton form and P(2) reproduced; sympy interpolation agrees",
                    compared='printed divided-difference table vs the recursion written out in the check (Fraction arithmetic) and vs exactcagd divided_differences; printed P(2) = (25/6, 4) vs sympy interpolate', reference='exact')


@claim(doc="sederberg", section="10.3", ref="Example (table row)", statement="adding the row t = 2: c0 = (7/12, -1), c1 = (17/12, -2), c2 = (25/6, 4)")
def newton_extension_example():
    out = ip.extend_divided_differences(NEWTON_T, NEWTON_P, 2)
    assert out["c"] == [(mpq(7, 12), -1), (mpq(17, 12), -2), (mpq(25, 6), 4)]
    # each printed equation: ((1/3,-1) - c0)/(1 - 2) = (1/4, 0); ((2,-3) - c1)/(3 - 2) = c0; ((7,0) - c2)/(4 - 2) = c1
    c0, c1, c2 = out["c"]
    assert tuple((a - b) / (1 - 2) for a, b in zip((mpq(1, 3), -1), c0)) == (mpq(1, 4), 0)
    assert tuple((a - b) / (3 - 2) for a, b in zip((2, -3), c1)) == c0
    assert tuple((a - b) / (4 - 2) for a, b in zip((7, 0), c2)) == c1
    return verified("the three printed divided-difference equations hold with the computed c0, c1, c2",
                    compared='the three printed divided-difference equations evaluated exactly with the computed c0, c1, c2 and the printed table entries', reference='exact')


@claim(doc="sederberg", section="10.4", ref="Aitken's lemma", statement="p_{i..k}(t) = ((t_k - t) p_{i..k-1}(t) - (t_i - t) p_{i+1..k}(t)) / (t_k - t_i)")
def aitken():
    ts = sp.symbols("t0:4")
    ys = sp.symbols("y0:4")

    def interp(i, k):  # Lagrange form of the interpolant of (t_i, y_i), ..., (t_k, y_k)
        idx = range(i, k + 1)
        return sum(ys[a] * sp.prod([(t - ts[b]) / (ts[a] - ts[b]) for b in idx if b != a]) for a in idx)

    for i, k in ((0, 1), (0, 2), (1, 3), (0, 3)):
        lhs = interp(i, k)
        rhs = ((ts[k] - t) * interp(i, k - 1) - (ts[i] - t) * interp(i + 1, k)) / (ts[k] - ts[i])
        assert sp.cancel(sp.together(lhs - rhs)) == 0
    return verified("symbolic identity for generic nodes and values, orders 1 to 3",
                    compared='printed Aitken identity vs sympy: both sides as Lagrange-form interpolants with symbolic nodes and values, difference cancels for orders 1..3', reference='sympy')


@claim(doc="sederberg", section="10.4", ref="Example (Neville)", statement="P01(2) = (6,6), P12(2) = (4,3), P23(2) = (3,6); P012(2) = (14/3,4), P123(2) = (11/3,4); P0123(2) = (25/6,4)")
def neville_example():
    lv = ip.neville(NEWTON_T, NEWTON_P, 2)
    # independent: P_{i..k}(2) is the value at 2 of the polynomial interpolating points i..k (sympy interpolate)
    for k in range(1, 4):
        for i in range(4 - k):
            ref = tuple(sp.interpolate([(NEWTON_T[j], NEWTON_P[j][c]) for j in range(i, i + k + 1)], t).subs(t, 2) for c in range(2))
            assert ref == tuple(sp.Rational(str(v)) for v in lv[k][i]), (i, k)
    assert lv[1] == [(6, 6), (4, 3), (3, 6)]
    assert lv[2] == [(mpq(14, 3), 4), (mpq(11, 3), 4)]
    assert lv[3] == [(mpq(25, 6), 4)]
    return verified("every intermediate point of the scheme reproduced exactly",
                    compared='every printed P_{i..k}(2) vs sympy interpolate of points i..k evaluated at 2, and vs exactcagd neville', reference='sympy')


@claim(doc="sederberg", section="10.6", ref="(10.1)", statement="f(x) - p(x) = f^(n+1)(xi)/(n+1)! (x - x0)...(x - xn)")
def error_formula():
    rng = random.Random(101)
    for _ in range(10):
        n = rng.randint(0, 4)
        nodes = rng.sample(range(-6, 7), n + 1)
        f = sum(rng.randint(-5, 5) * t**k for k in range(n + 2)) + t ** (n + 1)
        p = ip.lagrange_interpolate(nodes, [int(f.subs(t, x)) for x in nodes]).to_sympy(t)
        lead = sp.Poly(f, t).coeff_monomial(t ** (n + 1))
        assert sp.expand(f - p - lead * sp.prod([t - x for x in nodes])) == 0
    # and a transcendental instance as an inequality, exp on [0, 1] with 4 nodes
    x0 = [0, sp.Rational(1, 3), sp.Rational(2, 3), 1]
    p = sp.interpolate(list(zip(x0, [sp.exp(v) for v in x0])), t)
    for k in range(1, 20):
        xv = sp.Rational(k, 20)
        err = abs(sp.N(sp.exp(xv) - p.subs(t, xv), 30))
        assert err <= sp.N(sp.E / 24 * abs(sp.prod([xv - v for v in x0])), 30)
    return verified_range("10 random polynomials of degree n+1 (n <= 4); exp on [0,1] with 4 nodes at 19 points",
                          "exact identity f - p = f^(n+1)/(n+1)! omega for degree n+1; the bound holds for exp",
                          compared='printed (10.1) vs sympy: f - p - f^(n+1)/(n+1)! omega expands to 0 for 10 random polynomials f of degree n+1 (p by exactcagd Lagrange interpolation); for exp on [0,1] |e^x - p(x)| <= e/24 |omega| at 19 points (sympy, 30 digits)', reference='sympy')


@claim(doc="sederberg", section="10.6", ref="linear case", statement="|f(x) - p1(x)| <= max(f''(x))/2 (x - x0)(x - x1); <= L delta^2/8")
def linear_error():
    x0, x1 = 0, 1
    f = t**2
    p1 = t  # chord of t^2 on [0, 1]
    xv = sp.Rational(1, 2)
    lhs = abs((f - p1).subs(t, xv))
    printed_rhs = sp.Rational(2, 2) * (xv - x0) * (xv - x1)
    assert lhs == sp.Rational(1, 4) and printed_rhs < 0 < lhs
    rng = random.Random(106)
    for _ in range(8):
        c = BezierCurve([[rng.randint(-9, 9), rng.randint(-9, 9)] for _ in range(rng.randint(2, 5))])
        eps = Fraction(1, rng.choice([3, 10, 40]))
        m = ip.bezier_segments_for_tolerance(c, eps)
        assert ip.polyline_max_deviation_squared(c, m) <= eps * eps
    def is_upper_bound(rhs):
        # f = x^2 on [0, 1], p1 = x: the bound must dominate |f - p1| on [0, 1]
        for k in range(1, 10):
            xv_ = sp.Rational(k, 10)
            if rhs(xv_) < abs((f - p1).subs(t, xv_)):
                return f"at x = {xv_}: bound {rhs(xv_)} < |f - p1| = {abs((f - p1).subs(t, xv_))}"
        return None
    return erratum(printed="max(f'')/2 (x - x0)(x - x1)", corrected="max|f''|/2 |(x - x0)(x - x1)|  (<= L delta^2 / 8)",
                   detail="for f = x^2 on [0, 1] the printed right side is -1/4 at x = 1/2 while |f - p1| = 1/4; with absolute values "
                          "the bound holds, and the segment counts (10.2)-(10.3) certify 8 random curves exactly (max deviation <= eps)",
        printed_form=lambda xx: sp.Rational(2, 2) * (xx - x0) * (xx - x1), corrected_form=lambda xx: sp.Rational(2, 2) * abs((xx - x0) * (xx - x1)), check=L.predicate(is_upper_bound),
    )


@claim(doc="sederberg", section="10.6", ref="(10.2)-(10.4)", statement="m >= sqrt(sqrt(Lx^2 + Ly^2)/(8 eps)) segments; r = log2 sqrt(sqrt(Lx^2 + Ly^2)/(8 eps)) bisections")
def bezier_segments():
    rng = random.Random(104)
    for _ in range(8):
        c = BezierCurve([[rng.randint(-9, 9), rng.randint(-9, 9)] for _ in range(rng.randint(2, 4))])
        eps = Fraction(1, rng.choice([2, 7, 20]))
        m = ip.bezier_segments_for_tolerance(c, eps)
        assert ip.polyline_max_deviation_squared(c, m) <= eps * eps
        r = ip.bisection_depth(c, eps)
        assert ip.polyline_max_deviation_squared(c, 2**r) <= eps * eps
    return verified_range("8 random planar curves of degree 2-4", "exact max deviation of the m-segment and 2^r-segment polylines <= eps",
                          compared='printed (10.2)-(10.4) segment and bisection counts (exactcagd bezier_segments_for_tolerance, bisection_depth) vs the exact maximum deviation of the resulting polylines (exactcagd polyline_max_deviation_squared, exact maximization) <= eps^2', reference='independent-algorithm')


@claim(doc="sederberg", section="10.6.1", ref="uniform spacing", statement="x_i = a + (b - a)/n: for 4 <= n <= 20, max |(x - x0)...(x - xn)| ~ ((b - a)/3)^n")
def uniform_spacing():
    ratios = []
    for n in range(4, 11):
        m = ip.node_polynomial_max([Fraction(i, n) for i in range(n + 1)], 0, 1)
        ratios.append((n, float(m) * 3**n, float(m) * 3 ** (n + 1)))
    assert all(0.2 < r < 0.3 for _, r, _ in ratios) and all(0.7 < r2 < 0.9 for _, _, r2 in ratios)
    def exponent_of_estimate(expo):
        # max |w| / (1/3)^expo(n) must stay O(1) and not drift by a factor 3 per n (exact maxima, n = 4..10)
        vals = [float(ip.node_polynomial_max([Fraction(i, n) for i in range(n + 1)], 0, 1)) * 3 ** expo(n) for n in (4, 10)]
        return None if all(0.5 < v < 1.0 for v in vals) else f"max / (1/3)^e(n) = {[round(v, 3) for v in vals]} for n = 4, 10"
    return erratum(printed="x_i = a + (b - a)/n; max ~ ((b - a)/3)^n",
                   corrected="x_i = a + i (b - a)/n; max ~ ((b - a)/3)^(n+1) (there are n + 1 factors)",
                   detail="exact maxima (RealAlgebraic) for n = 4..10 on [0, 1]: max / (1/3)^n in "
                          f"[{min(r for _, r, _ in ratios):.3f}, {max(r for _, r, _ in ratios):.3f}] (off by a factor ~4), "
                          f"max / (1/3)^(n+1) in [{min(r for _, _, r in ratios):.3f}, {max(r for _, _, r in ratios):.3f}]",
        printed_form=lambda n: n, corrected_form=lambda n: n + 1, check=L.predicate(exponent_of_estimate), reference='exact',
    )


@claim(doc="sederberg", section="10.6.1", ref="uniform spacing (full range)", statement="for 4 <= n <= 20, max |(x - x0)...(x - xn)| ~ ((b - a)/3)^(n+1)", slow=True)
def uniform_spacing_full():
    ratios = []
    for n in range(4, 21):
        m = ip.node_polynomial_max([Fraction(i, n) for i in range(n + 1)], 0, 1)
        ratios.append(float(m) * 3 ** (n + 1))
        if n <= 6:  # independent: max |omega| over the critical points and ends (sympy real_roots, exact)
            w = sp.prod([t - sp.Rational(i, n) for i in range(n + 1)])
            cands = [sp.Integer(0), sp.Integer(1)] + [r for r in sp.real_roots(sp.Poly(sp.diff(w, t), t)) if 0 <= r <= 1]
            ref = max(abs(w.subs(t, r)) for r in cands)
            assert abs(float(sp.N(ref, 30)) - float(m)) <= 1e-12 * float(sp.N(ref, 30))  # m is an exact algebraic number
    assert 0.7 < min(ratios) and max(ratios) < 1.2
    return verified_range("n = 4..20 on [0, 1]", f"exact max / (1/3)^(n+1) in [{min(ratios):.3f}, {max(ratios):.3f}]",
                          compared="printed ((b-a)/3)^(n+1) estimate vs exact maxima of |omega| for n = 4..20 (exactcagd node_polynomial_max), cross-checked for n = 4..6 by sympy real_roots of omega' (agreement to 12 digits)", reference='sympy')


@claim(doc="sederberg", section="10.6.1", ref="(10.6)", statement="x_i = (a+b)/2 + (b-a)/2 cos((2i+1) pi/(2n+2)), i = 0..n-1; then max |(x - x0)...(x - xn)| = 2((b-a)/4)^n")
def chebyshev_points():
    for n, a, b in ((3, 0, 1), (5, -1, 2), (9, 0, 1)):
        nodes = ip.chebyshev_nodes(n, a, b)
        assert len(nodes) == n + 1
        w = ip.chebyshev_node_polynomial(n, a, b)
        m = ip.chebyshev_node_polynomial_max(n, a, b)
        # attained at x = b where T_{n+1} = 1, never exceeded (|T| <= 1 on [-1, 1])
        val_b = sum(c * mpq(b) ** k for k, c in enumerate(w))
        assert val_b == m == 2 * (mpq(b - a) / 4) ** (n + 1)
        assert m != 2 * (mpq(b - a) / 4) ** n
    s = sp.Symbol("s")
    for n in range(0, 8):  # monic scaling: T_{n+1}(s) / 2^n is monic with max 2^-n on [-1, 1]
        assert sp.Poly(sp.chebyshevt(n + 1, s), s).LC() == 2**n
    def max_formula(expo):
        for n_, a_, b_ in ((3, 0, 1), (5, -1, 2)):
            if ip.chebyshev_node_polynomial_max(n_, a_, b_) != 2 * (mpq(b_ - a_) / 4) ** expo(n_):
                return f"n = {n_} on [{a_}, {b_}]: max = {ip.chebyshev_node_polynomial_max(n_, a_, b_)}, formula {2 * (mpq(b_ - a_) / 4) ** expo(n_)}"
        return None
    return erratum(printed="i = 0, ..., n-1; max = 2((b-a)/4)^n",
                   corrected="i = 0, ..., n (n + 1 nodes for the n + 1 factors); max = 2((b-a)/4)^(n+1)",
                   detail="omega = ((b-a)/2)^(n+1) 2^-n T_{n+1}((2x-a-b)/(b-a)) exactly; its maximum 2((b-a)/4)^(n+1) is attained at x = b "
                          "(checked exactly for n = 3, 5, 9); the printed exponent n is off by one",
        printed_form=lambda n_: n_, corrected_form=lambda n_: n_ + 1, check=L.predicate(max_formula), reference='exact',
    )


@claim(doc="sederberg", section="10.7", ref="Hermite", statement="P(t) = P(0)(2t^3 - 3t^2 + 1) + P(1)(-2t^3 + 3t^2) + P'(0)(t^3 - 2t^2 + t) + P'(1)(t^3 - t^2)")
def hermite():
    a = sp.symbols("a0:4")
    p = sum(a[k] * t**k for k in range(4))
    p0, p1, d0, d1 = sp.symbols("p0 p1 d0 d1")
    sol = sp.solve([p.subs(t, 0) - p0, p.subs(t, 1) - p1, p.diff(t).subs(t, 0) - d0, p.diff(t).subs(t, 1) - d1], a)
    herm = sp.expand(p.subs(sol))
    printed = p0 * (2 * t**3 - 3 * t**2 + 1) + p1 * (-2 * t**3 + 3 * t**2) + d0 * (t**3 - 2 * t**2 + t) + d1 * (t**3 - t**2)
    assert sp.expand(herm - printed) == 0
    part, null = ip.interpolate_conditions(3, [(0, 0, [1, 2]), (1, 0, [3, 1]), (0, 1, [1, 1]), (1, 1, [2, -1])])
    assert null == [] and part.to_bezier().control_points == ip.hermite_cubic([1, 2], [3, 1], [1, 1], [2, -1]).control_points
    return verified("undetermined coefficients in sympy give the printed blending functions; the exact general solver agrees",
                    compared="printed Hermite blending functions vs the sympy solve of the four end conditions on a general cubic; exactcagd's general conditions solver agrees", reference='sympy')

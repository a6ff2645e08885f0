"""Ledger: Sederberg's notes, chapter 20 (hybrid curves, integrals over Bézier curves,
error bounds on integration, examples)."""

from __future__ import annotations

import random
from fractions import Fraction

import mpmath
import sympy as sp
from gmpy2 import mpq

from exactcagd import BezierCurve
from exactcagd.toolbox import integrals as ig
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, not_checkable, verified, verified_range

t = sp.Symbol("t")


def _B(n, i, x=t):
    return sp.binomial(n, i) * x**i * (1 - x) ** (n - i)


def _q(v):
    return sp.Rational(int(v.numerator), int(v.denominator))


def _sym_rational(c):
    w = [_q(v) for v in c.weights_array()]
    n = c.degree
    W = sum(w[i] * _B(n, i) for i in range(n + 1))
    return [sum(w[i] * _q(p[k]) * _B(n, i) for i, p in enumerate(c.control_points)) / W for k in range(c.dimension)]


def _pint(expr):
    """int_0^1 of a polynomial in t (sympy Poly antiderivative: fast and exact)."""
    p = sp.Poly(sp.expand(expr), t).integrate()
    return p.eval(1) - p.eval(0)


def _d2_sym(n):
    """D_ij = C_{i,j-1} - C_{i,j}, C_ij = int_0^1 B_i^n B_j^(n-1) (the definition of 20.2, sympy integrals)."""
    C = lambda i, j: _pint(_B(n, i) * _B(n - 1, j)) if 0 <= j <= n - 1 else 0  # noqa: E731
    return {(i, j): C(i, j - 1) - C(i, j) for i in range(n + 1) for j in range(n + 1)}


def _d3_sym(n):
    C = lambda i, j, k: _pint(_B(n, i) * _B(n, j) * _B(n - 1, k)) if 0 <= k <= n - 1 else 0  # noqa: E731
    return {(i, j, k): C(i, j, k - 1) - C(i, j, k) for i in range(n + 1) for j in range(n + 1) for k in range(n + 1)}


def _random_rational(rng, r):
    pts = [[Fraction(rng.randint(-9, 9), rng.randint(1, 3)) for _ in range(2)] for _ in range(r + 1)]
    w = [Fraction(rng.randint(1, 12), rng.randint(1, 4)) for _ in range(r + 1)]
    return BezierCurve(pts, w)


SEMICIRCLE = BezierCurve([[0, 0], [0, 1], [1, 1], [1, 0]], [1, Fraction(1, 3), Fraction(1, 3), 1])


@claim(doc="sederberg", section="20", ref="(20.2)-(20.6)", statement="a degree r rational curve equals the degree n hybrid curve sum_{i != m} B_i^n P_i + M(t) B_m^n with P_i, M_i from (20.4)-(20.6); M has the original weights")
def hybrid_identity():
    rng = random.Random(20)
    count = 0
    for _ in range(12):
        r = rng.randint(1, 3)
        n = rng.randint(2, 6)
        m = rng.randint(1, n - 1)
        c = _random_rational(rng, r)
        h = ig.hybrid_curve(c, n, m)
        assert h.moving.weights == c.weights and h.moving.degree == r
        x, y = _sym_rational(c)
        Mx, My = _sym_rational(h.moving)
        Hx = sum(_B(n, i) * _q(p[0]) for i, p in enumerate(h.points) if p is not None) + _B(n, m) * Mx
        Hy = sum(_B(n, i) * _q(p[1]) for i, p in enumerate(h.points) if p is not None) + _B(n, m) * My
        assert sp.cancel(Hx - x) == 0 and sp.cancel(Hy - y) == 0
        count += 1
    return verified_range("12 random rational curves, r = 1..3, n = 2..6, every admissible m drawn at random",
                          "H(t) = R(t) as rational functions (sympy cancel); M(t) has degree r and the weights w_i",
        compared='printed (20.2)-(20.6) hybrid form sum B_i^n P_i + M(t) B_m^n vs the original rational curve, both written out in sympy and compared as rational functions (cancel)',
        reference='sympy')


@claim(doc="sederberg", section="20", ref="(20.7)-(20.9)", statement="n even, m = n/2, ||M(t) - P_m|| <= ||Delta||: ||P(t) - H(t)|| <= ||Delta|| C(n, n/2) / 2^n")
def hybrid_bound():
    for n in (2, 4, 6, 8):
        f = _B(n, n // 2)
        assert sp.maximum(f, t, sp.Interval(0, 1)) == sp.binomial(n, n // 2) / sp.Integer(2) ** n
    rng = random.Random(207)
    for _ in range(10):
        c = _random_rational(rng, rng.randint(1, 4))
        n = rng.choice([2, 4, 6, 8])
        a = ig.polynomial_approximation(c, n)
        factor = sp.binomial(n, n // 2) / sp.Integer(2) ** n
        assert _q(a.bound_sq) == sum(_q(d) ** 2 for d in a.delta) * factor**2  # (20.7): ||Delta||^2 (C(n, n/2) / 2^n)^2
        assert [_q(b) for b in a.coordinate_bounds] == [abs(_q(d)) * factor for d in a.delta]  # (20.8), (20.9)
        Rx, Ry = _sym_rational(c)
        Px, Py = _poly_sym(a.curve)
        for k in range(17):
            tk = sp.Rational(k, 16)
            assert (Px.subs(t, tk) - Rx.subs(t, tk)) ** 2 + (Py.subs(t, tk) - Ry.subs(t, tk)) ** 2 <= _q(a.bound_sq)
            p, r = a.curve.evaluate(Fraction(k, 16)), c.evaluate(Fraction(k, 16))
            assert all(abs(u - v) <= b for u, v, b in zip(p, r, a.coordinate_bounds))
    return verified_range("max B^n_{n/2} symbolic for n = 2..8; 10 random rational curves at 17 exact parameters",
                          "P - H = B^n_m (P_m - M(t)) and the box of the control points M_i bounds M(t) (positive weights)",
        compared='printed (20.7)-(20.9) bound ||Delta|| C(n, n/2)/2^n vs sympy maximum of B^n_{n/2} and the sympy distance between the rational curve and its polynomial approximation at 17 exact parameters',
        reference='sympy')


def _delta_sym(c, n):
    """Delta of 20.1 from first principles: solve H(t) W(t) = R(t) W(t) for the stationary P_i (i != m) and the moving
    points M_j (M(t) = sum B_j^r w_j M_j / W, the original weights), a linear system in the Bernstein basis of degree
    n + r (sympy, exact); Delta = half the width / height of the box of the M_j."""
    r, m = c.degree, n // 2
    w = [_q(v) for v in c.weights_array()]
    R = [[_q(v) for v in p] for p in c.control_points]
    stationary = [i for i in range(n + 1) if i != m]
    A = sp.zeros(n + r + 1, len(stationary) + r + 1)
    rhs = sp.zeros(n + r + 1, 2)
    for k in range(n + r + 1):
        for col, i in enumerate(stationary):
            j = k - i
            if 0 <= j <= r:
                A[k, col] = sp.binomial(n, i) * sp.binomial(r, j) * w[j]
        j = k - m
        if 0 <= j <= r:
            A[k, len(stationary) + j] = sp.binomial(n, m) * sp.binomial(r, j) * w[j]
        for j in range(max(0, k - n), min(r, k) + 1):
            for d in range(2):
                rhs[k, d] += sp.binomial(r, j) * sp.binomial(n, k - j) * w[j] * R[j][d]
    sol = A.LUsolve(rhs)
    M = [sol[len(stationary) + j, :] for j in range(r + 1)]
    return tuple((max(p[d] for p in M) - min(p[d] for p in M)) / 2 for d in range(2))


@claim(doc="sederberg", section="20", ref="subdivision", statement="each half of a subdivided rational curve always has a smaller value of ||Delta|| than does the original")
def subdivision_shrinks_delta():
    rng = random.Random(2020)
    pairs = 0
    for _ in range(60):
        c = _random_rational(rng, rng.randint(1, 4))
        n = rng.choice([2, 4, 6])
        d = ig.polynomial_approximation(c, n).delta
        d_sym = _delta_sym(c, n)
        assert tuple(_q(x) for x in d) == d_sym
        for half in c.subdivide(Fraction(1, 2)):
            dd = ig.polynomial_approximation(half, n).delta
            assert dd[0] ** 2 + dd[1] ** 2 <= d[0] ** 2 + d[1] ** 2
            dd_sym = _delta_sym(half, n)
            assert dd_sym[0] ** 2 + dd_sym[1] ** 2 <= d_sym[0] ** 2 + d_sym[1] ** 2
            pairs += 1
    return verified_range("60 random rational curves (degree 1-4, positive weights), n in {2, 4, 6}", f"{pairs} halves, none with a larger ||Delta||",
        compared="printed claim (each half has a smaller ||Delta||) vs Delta derived from first principles in sympy: the hybrid identity H W = R W solved exactly for the P_i and the moving points M_j (original weights), Delta = half the box of the M_j; exactcagd's Delta agrees",
        reference='sympy')


@claim(doc="sederberg", section="20.2", ref="(20.11), (20.12)", statement="D_ij = (j-i)/((i+j)(2n-i-j)) C(n,i) C(n,j); D_ijk = (2k-i-j)/((i+j+k)(3n-i-j-k)) C(n,i) C(n,j) C(n,k)")
def d_coefficients():
    for n in (1, 2, 3, 4):
        C = lambda i, j: _pint(_B(n, i) * _B(n - 1, j)) if 0 <= j <= n - 1 else 0  # noqa: E731
        D = ig.d2_coefficients(n)
        for i in range(n + 1):
            for j in range(n + 1):
                assert _q(D[i, j]) == C(i, j - 1) - C(i, j)
    n = 2
    C3 = lambda i, j, k: _pint(_B(n, i) * _B(n, j) * _B(n - 1, k)) if 0 <= k <= n - 1 else 0  # noqa: E731
    D3 = ig.d3_coefficients(n)
    assert all(_q(D3[i, j, k]) == C3(i, j, k - 1) - C3(i, j, k) for i in range(3) for j in range(3) for k in range(3))
    printed01 = sp.Rational(1 - 0, (0 + 1) * (2 - 0 - 1))  # n = 1, (i, j) = (0, 1)
    def d_formula(extra):
        for n_ in (1, 2, 3):
            Cc = lambda i, j: _pint(_B(n_, i) * _B(n_ - 1, j)) if 0 <= j <= n_ - 1 else 0  # noqa: E731
            for i in range(n_ + 1):
                for j in range(n_ + 1):
                    if i + j in (0, 2 * n_):
                        continue
                    val = sp.Rational(j - i, (i + j) * (2 * n_ - i - j)) * sp.binomial(n_, i) * sp.binomial(n_, j) / extra(n_, i + j)
                    if val != Cc(i, j - 1) - Cc(i, j):
                        return f"n = {n_}, D_{i}{j} = {val}, integral definition gives {Cc(i, j - 1) - Cc(i, j)}"
        return None
    return erratum(printed="D_ij = (j-i)/((i+j)(2n-i-j)) C(n,i) C(n,j);  D_ijk = (2k-i-j)/((i+j+k)(3n-i-j-k)) C(n,i) C(n,j) C(n,k)",
                   corrected="D_ij = (j-i)/((i+j)(2n-i-j)) C(n,i) C(n,j) / C(2n,i+j);  D_ijk = ... / C(3n,i+j+k)",
                   detail=f"from the definitions D = C_{{.,j-1}} - C_{{.,j}} (sympy integrals, n = 1..4 and n = 2): e.g. n = 1: D_01 = 1/2, printed {printed01}; "
                          "the corner values -1/(2n), 1/(2n), -1/(3n), 1/(3n) are right",
        printed_form=lambda n_, s_: 1, corrected_form=lambda n_, s_: sp.binomial(2 * n_, s_), check=L.predicate(d_formula), reference='sympy',
    )


@claim(doc="sederberg", section="20.2", ref="(20.13)-(20.18)", statement="Area = n sum D_ij y_i x_j; directed sector area = n sum_{i<j} D_ij (P_i ^ P_j); I_x = n/2 sum D_ijk y_i y_j x_k; I_y = n sum D_ijk x_i y_j x_k; Volume = 2 pi I_x")
def integral_formulas():
    for n in (1, 2, 3):
        xs, ys = sp.symbols(f"x0:{n + 1}"), sp.symbols(f"y0:{n + 1}")
        X = sum(xs[i] * _B(n, i) for i in range(n + 1))
        Y = sum(ys[i] * _B(n, i) for i in range(n + 1))
        D = _d2_sym(n)
        assert all(_q(ig.d2_coefficients(n)[i, j]) == D[i, j] for i, j in D)
        area = _pint(Y * X.diff(t))
        assert sp.expand(area - n * sum(D[i, j] * ys[i] * xs[j] for i in range(n + 1) for j in range(n + 1))) == 0
        sector = _pint((X * Y.diff(t) - Y * X.diff(t)) / 2)
        assert sp.expand(sector - n * sum(D[i, j] * (xs[i] * ys[j] - ys[i] * xs[j]) for i in range(n + 1) for j in range(i + 1, n + 1))) == 0
        if n <= 2:
            D3 = _d3_sym(n)
            r = range(n + 1)
            ix = _pint(Y**2 * X.diff(t) / 2)
            iy = _pint(X * Y * X.diff(t))
            assert sp.expand(ix - sp.Rational(n, 2) * sum(D3[i, j, k] * ys[i] * ys[j] * xs[k] for i in r for j in r for k in r)) == 0
            assert sp.expand(iy - n * sum(D3[i, j, k] * xs[i] * ys[j] * xs[k] for i in r for j in r for k in r)) == 0
    c = BezierCurve([[0, 0], [1, 3], [3, 2], [4, 0]])
    assert ig.area_under(c) == ig.area_under_by_formula(c) == mpq(21, 4)
    assert ig.volume_over_pi(c) == 2 * ig.first_moments(c)[0]
    return verified("with the corrected D: symbolic identities for generic control points, n = 1..3 (areas) and n = 1, 2 (moments); "
                    "exact Bernstein-product integrals agree",
        compared='printed (20.13)-(20.18) (with the corrected D) vs sympy integrals of the Bernstein forms with generic symbolic control points; D_ij, D_ijk from their integral definition in sympy',
        reference='sympy')


@claim(doc="sederberg", section="20.3", ref="(20.19)-(20.26)", statement="|x'_P| <= n max|dx_i|; |x'_R| <= r (max w / min w)^2 max|dX_i|; |x_P| <= max|x_i|; |x_R| <= max|X_i|")
def floater_bounds():
    from exactcagd.toolbox.bezier_extras import derivatives_at

    rng = random.Random(2019)
    checked = 0
    for _ in range(25):
        c = _random_rational(rng, rng.randint(1, 4))
        bx, by = ig.derivative_bounds(c)
        vx, vy = ig.value_bounds(c)
        w = [_q(v) for v in c.weights_array()]
        pts = [[_q(v) for v in p] for p in c.control_points]
        r_ = c.degree
        ratio = (max(w) / min(w)) ** 2
        printed_d = [r_ * ratio * max(abs(pts[i + 1][k] - pts[i][k]) for i in range(r_)) for k in range(2)]  # (20.21), (20.22)
        printed_v = [max(abs(p[k]) for p in pts) for k in range(2)]  # (20.25), (20.26)
        assert [_q(bx), _q(by)] == printed_d and [_q(vx), _q(vy)] == printed_v
        X_, Y_ = _sym_rational(c)
        for k in range(0, 65, 8):  # independent values and derivatives (sympy) at 9 of the parameters
            tk = sp.Rational(k, 64)
            assert abs(X_.diff(t).subs(t, tk)) <= printed_d[0] and abs(Y_.diff(t).subs(t, tk)) <= printed_d[1]
            assert abs(X_.subs(t, tk)) <= printed_v[0] and abs(Y_.subs(t, tk)) <= printed_v[1]
        for k in range(65):
            pt, d1 = derivatives_at(c, Fraction(k, 64), 1)
            assert abs(d1[0]) <= bx and abs(d1[1]) <= by
            assert abs(pt[0]) <= vx and abs(pt[1]) <= vy
            checked += 1
    return verified_range("25 random rational curves (degree 1-4, weights in [1/4, 12]) at 65 parameters each",
                          "Floater's derivative bound and the convex-hull value bounds hold (exact values and derivatives)",
        compared='printed (20.19)-(20.26) bounds computed from the control points and weights as printed vs sympy values and derivatives of the rational curve (9 parameters) and exact derivatives (65 parameters)',
        reference='sympy')


@claim(doc="sederberg", section="20.3", ref="(20.27)-(20.30)", statement="|int y_R dx_R - int y_P dx_P| <= B_xPH B_y'H + B_yPH B_x'P, and (20.28)-(20.30) likewise")
def integration_error_bounds():
    # the integration-by-parts steps: at every parameter the integrands differ by the derivative of an
    # expression that vanishes at t = 0 and t = 1 (x_H = x_P and y_H = y_P there since 0 < m < n).
    # All four differences are rational functions with denominator W^4 and numerator degree < 41
    # (r = 3, n = 4: at most 4*3 + 4 + 4 + 3 + ... < 41), so equality at 41 exact parameters proves the identities.
    from exactcagd.toolbox.bezier_extras import derivatives_at

    a = ig.polynomial_approximation(SEMICIRCLE, 4)
    for k in range(41):
        tk = Fraction(k, 40)
        (xh, yh), (dxh, dyh) = derivatives_at(SEMICIRCLE, tk, 1)
        (xp, yp), (dxp, dyp) = derivatives_at(a.curve, tk, 1)
        # (20.27): d/dt[y_H (x_H - x_P)]
        assert yh * dxh - yp * dxp - (-(xh - xp) * dyh + (yh - yp) * dxp) == dyh * (xh - xp) + yh * (dxh - dxp)
        # (20.29): d/dt[y_H^2 (x_H - x_P)]
        assert (yh**2 * dxh - yp**2 * dxp - (-2 * (xh - xp) * yh * dyh + (yh - yp) * (yh + yp) * dxp)
                == 2 * yh * dyh * (xh - xp) + yh**2 * (dxh - dxp))
        # (20.30): d/dt[x_H y_H (x_H - x_P)]
        assert (xh * yh * dxh - xp * yp * dxp - ((xh - xp) * (-dxh * yh - xh * dyh + dxp * yp) + (yh - yp) * xh * dxp)
                == (dxh * yh + xh * dyh) * (xh - xp) + xh * yh * (dxh - dxp))
        # (20.28): d/dt[x_H (y_H - y_P) - y_H (x_H - x_P)]
        assert ((xh * dyh - yh * dxh) - (xp * dyp - yp * dxp) - ((xh - xp) * (dyh + dyp) - (yh - yp) * (dxh + dxp))
                == dxh * (yh - yp) + xh * (dyh - dyp) - dyh * (xh - xp) - yh * (dxh - dxp))
    for end in (0, 1):
        assert a.curve.evaluate(end) == SEMICIRCLE.evaluate(end)
    # the inequalities on random curves against 30-digit quadrature
    rng = random.Random(2027)
    mpmath.mp.dps = 20
    for _ in range(3):
        c = _random_rational(rng, rng.randint(2, 3))
        ap = ig.polynomial_approximation(c, 4)
        bounds = ig.integration_error_bounds(c, ap)
        # (20.27), (20.28) assembled from the printed ingredients: B_xPH, B_yPH (20.8)-(20.9), B_x'P (20.19)-(20.20),
        # B_x'R (20.21)-(20.22), each computed here from the control points and weights
        fac = sp.binomial(4, 2) / sp.Integer(2) ** 4
        bxph, byph = (abs(_q(d)) * fac for d in ap.delta)
        w = [_q(v) for v in c.weights_array()]
        R_pts = [[_q(v) for v in p] for p in c.control_points]
        P_pts = [[_q(v) for v in p] for p in ap.curve.control_points]
        dR = [c.degree * (max(w) / min(w)) ** 2 * max(abs(R_pts[i + 1][k] - R_pts[i][k]) for i in range(c.degree)) for k in range(2)]
        dP = [4 * max(abs(P_pts[i + 1][k] - P_pts[i][k]) for i in range(4)) for k in range(2)]
        assert _q(bounds["area"]) == bxph * dR[1] + byph * dP[0]  # (20.27) with B_y'H = B_y'R (H = R)
        assert _q(bounds["wedge"]) == bxph * (dR[1] + dP[1]) + byph * (dR[0] + dP[0])  # (20.28)
        x, y = _sym_rational(c)
        fx, fy = sp.lambdify(t, x, "mpmath"), sp.lambdify(t, y, "mpmath")
        dfx, dfy = sp.lambdify(t, x.diff(t), "mpmath"), sp.lambdify(t, y.diff(t), "mpmath")
        poly = {"area": ig.area_under(ap.curve), "y2dx": ig.volume_over_pi(ap.curve), "xydx": ig.first_moments(ap.curve)[1],
                "wedge": 2 * ig.sector_area(ap.curve)}
        true = {"area": lambda u: fy(u) * dfx(u), "y2dx": lambda u: fy(u) ** 2 * dfx(u), "xydx": lambda u: fx(u) * fy(u) * dfx(u),
                "wedge": lambda u: fx(u) * dfy(u) - fy(u) * dfx(u)}
        for key in poly:
            value = mpmath.quad(true[key], [0, 0.5, 1])
            assert abs(value - mpmath.mpf(int(poly[key].numerator)) / int(poly[key].denominator)) <= mpmath.mpf(float(bounds[key])) * (1 + 1e-12)
    return verified("integrands differ by exact derivatives whose boundary terms vanish (x_H = x_P at t = 0, 1), for all four integrals; "
                    "the four bounds hold for 3 random rational curves against 20-digit quadrature",
        compared="printed (20.27), (20.28) bounds assembled here from (20.8)-(20.9), (20.19)-(20.22) as printed (Delta from exactcagd's box of the M_i) vs the true integration error by 20-digit mpmath quadrature for 3 random rational curves; the (20.29), (20.30) bounds (exactcagd's) also vs mpmath; boundary terms vanish (exact end points)",
        reference='mpmath')


def _poly_sym(c):
    n = c.degree
    return [sum(_q(p[k]) * _B(n, i) for i, p in enumerate(c.control_points)) for k in range(2)]


@claim(doc="sederberg", section="20.4", ref="semicircle", statement="exact area pi/8 = .39269908...; hybrid: 0.39269906 (tolerance 1e-6), 0.39272477 (tolerance 1e-3)")
def semicircle_example():
    x, y = _sym_rational(SEMICIRCLE)
    assert sp.simplify((x - sp.Rational(1, 2)) ** 2 + y**2 - sp.Rational(1, 4)) == 0
    exact = sp.integrate(sp.cancel(y * x.diff(t)), (t, 0, 1))
    assert sp.simplify(exact - sp.pi / 8) == 0
    out = []
    for tol, printed in ((Fraction(1, 10**3), 0.39272477), (Fraction(1, 10**6), 0.39269906)):
        value, bound = ig.rational_integral(SEMICIRCLE, "area", tol)
        assert abs(float(value) - float(sp.pi / 8)) <= float(bound) and bound <= tol
        assert abs(printed - float(sp.pi / 8)) <= float(tol)
        out.append(f"tol {float(tol):g}: {float(value):.8f} +- {float(bound):.1e}")
    return verified("a semicircle of radius 1/2 as a rational cubic (weights 1, 1/3, 1/3, 1) has area pi/8 exactly (sympy); "
                    "the printed values are within their tolerances; certified here: " + "; ".join(out),
        compared="printed pi/8 and the values 0.39269906, 0.39272477 vs the sympy integral of y x' over the rational semicircle (exactly pi/8); each printed value within its tolerance of it",
        reference='sympy')


@claim(doc="sederberg", section="20.4", ref="Simpson's rule", statement="for a degree r rational curve the fourth derivative of the area (volume) integrand is a rational function of degree 48r (64r)")
def simpson_degree():
    rng = random.Random(204)
    for r in (1, 2):
        c = _random_rational(rng, r)
        h = c.homogeneous()
        X, Y, W = (sp.Poly(sum(_q(h[i, k]) * _B(r, i) for i in range(r + 1)), t) for k in range(3))
        xprime_num = X.diff(t) * W - X * W.diff(t)          # x' = xprime_num / W^2
        for num, k, reduced, naive in ((xprime_num * Y, 3, 7 * r, 48 * r), (xprime_num * Y * Y, 4, 8 * r, 64 * r)):
            for _ in range(4):  # d/dt (N / W^k) = (N' W - k N W') / W^(k+1)
                num, k = num.diff(t) * W - k * num * W.diff(t), k + 1
            g = sp.gcd(num, W)
            assert g.degree() == 0 and (W**k).degree() == reduced and num.degree() < reduced
            deg = k - 4  # the integrand's denominator is W^(k-4): degree (k-4) r, squared at each of the four steps
            assert deg * r * 2**4 == naive
    def reduced_degree(deg):
        r_ = 1
        c_ = _random_rational(random.Random(2041), r_)
        h_ = c_.homogeneous()
        X_, Y_, W_ = (sp.Poly(sum(_q(h_[i, k]) * _B(r_, i) for i in range(r_ + 1)), t) for k in range(3))
        num_, k_ = (X_.diff(t) * W_ - X_ * W_.diff(t)) * Y_, 3
        for _ in range(4):
            num_, k_ = num_.diff(t) * W_ - k_ * num_ * W_.diff(t), k_ + 1
        return None if (W_**k_).degree() == deg(r_) and sp.gcd(num_, W_).degree() == 0 else f"denominator degree {(W_**k_).degree()} for r = 1, not {deg(r_)}"
    return erratum(printed="degree 48r (64r)", corrected="degree 7r (8r) in lowest terms",
                   detail="x'y = (X'W - XW')Y / W^3 and x'y^2 = ... / W^4, so the fourth derivatives have denominators W^7 and W^8; "
                          "48r = 3r * 2^4 and 64r = 4r * 2^4 count the quotient rule with the denominator squared at each step (checked for r = 1, 2)",
        printed_form=lambda r_: 48 * r_, corrected_form=lambda r_: 7 * r_, check=L.predicate(reduced_degree),
    )


@claim(doc="sederberg", section="20.4", ref="Tables 20.1, 20.2", statement="execution times (ms) of hybrid, Simpson and trapezoid methods on a 65 Specmark workstation")
def timing_tables():
    return not_checkable("machine-specific timings of the authors' implementation; Example 1's curve (Figure 20.5) is not given in the text")

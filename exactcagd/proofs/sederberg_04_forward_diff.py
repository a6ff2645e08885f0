"""Ledger: Sederberg's notes, chapter 4 (forward differencing) and 4.1 (choosing delta)."""

from __future__ import annotations

import random
from fractions import Fraction

import sympy as sp
from gmpy2 import mpq

from exactcagd import BezierCurve
from exactcagd.toolbox import forward_diff as fd
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified, verified_range

x, d = sp.symbols("x delta")


@claim(doc="sederberg", section="4", ref="quadratic and cubic initial differences",
       statement="quadratic: Delta1 = a1 d + a2 d^2, Delta2 = 2 a2 d^2; cubic: Delta1 = a1 d + a2 d^2 + a3 d^3, Delta2 = 2a2 d^2 + 6a3 d^3, Delta3 = 6 a3 d^3")
def initial_differences():
    a = sp.symbols("a0:4")
    f = sum(a[k] * x**k for k in range(4))
    D = [f.subs(x, k * d) for k in range(4)]
    assert sp.expand(D[1] - D[0] - (a[1] * d + a[2] * d**2 + a[3] * d**3)) == 0
    assert sp.expand(D[2] - 2 * D[1] + D[0] - (2 * a[2] * d**2 + 6 * a[3] * d**3)) == 0
    assert sp.expand(D[3] - 3 * D[2] + 3 * D[1] - D[0] - 6 * a[3] * d**3) == 0
    g = a[0] + a[1] * x + a[2] * x**2
    assert sp.expand(g.subs(x, d) - g.subs(x, 0) - (a[1] * d + a[2] * d**2)) == 0
    assert sp.expand(g.subs(x, 2 * d) - 2 * g.subs(x, d) + g - (2 * a[2] * d**2)).subs(x, 0) == 0
    # first-order difference of the quadratic at general t (printed): a1 d + a2 d^2 + 2 a2 t d
    assert sp.expand(g.subs(x, x + d) - g - (a[1] * d + a[2] * d**2 + 2 * a[2] * x * d)) == 0
    return verified("sympy expansion of the differences of generic quadratic and cubic polynomials",
        compared='printed initial differences of the quadratic and cubic vs sympy expansion of f(k delta) differences for generic coefficients (and the general-t first difference)',
        reference='sympy',
    )


@claim(doc="sederberg", section="4", ref="difference table", statement="f = 1, 3, 2, 5, 4 (degree 4) continues with f(t_{i+5}) = -24, f(t_{i+6}) = -117, f(t_{i+7}) = -328; Delta_4 = -15")
def difference_table_example():
    table = fd.difference_table([1, 3, 2, 5, 4])
    assert [row[0] for row in table] == [1, 2, -3, 7, -15]
    assert fd.extend([1, 3, 2, 5, 4], 3) == [-24, -117, -328]
    p = sp.interpolate([(k, v) for k, v in enumerate([1, 3, 2, 5, 4])], x)
    assert [p.subs(x, k) for k in (5, 6, 7)] == [-24, -117, -328]
    full = fd.difference_table([1, 3, 2, 5, 4, -24, -117, -328])
    printed_rows = [[2, -1, 3, -1, -28, -93, -211], [-3, 4, -4, -27, -65, -118], [7, -8, -23, -38, -53], [-15] * 4]
    # independent: the differences of the interpolated values, taken here
    rows = [[p.subs(x, k) for k in range(8)]]
    while len(rows[-1]) > 1:
        rows.append([b_ - a_ for a_, b_ in zip(rows[-1][:-1], rows[-1][1:])])
    assert rows[0] == [1, 3, 2, 5, 4, -24, -117, -328] and rows[1:5] == printed_rows and all(v == 0 for v in rows[5])
    assert full[1:5] == printed_rows and all(v == 0 for v in full[5])
    return verified("every entry of the printed table reproduced; the interpolating quartic (sympy) gives the same values",
        compared="printed continuation -24, -117, -328 vs sympy's interpolating quartic through (0..4, f); every printed table row vs differences of those values taken in the row; exactcagd's difference_table / extend agree",
        reference='sympy',
    )


@claim(doc="sederberg", section="4", ref="Example f(4)", statement="cubic with f(1)=1, f(2)=2, f(3)=4, f(5)=15: Delta_4 = 32 - 4x = 0, so f(4) = 8")
def missing_value_example():
    X = sp.Symbol("X")
    vals = [1, 2, 4, X, 15]
    rows = [vals]
    while len(rows[-1]) > 1:
        rows.append([sp.expand(b - a) for a, b in zip(rows[-1][:-1], rows[-1][1:])])
    assert rows[3] == [X - 7, 25 - 3 * X] and rows[4] == [32 - 4 * X]
    assert fd.solve_missing([1, 2, 4, None, 15], 3)[3] == 8
    p = sp.interpolate([(1, 1), (2, 2), (3, 4), (5, 15)], x)
    assert p.subs(x, 4) == 8
    return verified("symbolic table rows (x - 7, 25 - 3x), (32 - 4x) reproduced; the interpolating cubic gives f(4) = 8",
        compared="printed rows (x - 7, 25 - 3x), (32 - 4x) and f(4) = 8 vs the symbolic difference table (sympy) and sympy's interpolating cubic through the four known points; exactcagd's solve_missing agrees",
        reference='sympy',
    )


@claim(doc="sederberg", section="4", ref="basis independence", statement="the technique is independent of the basis: n + 1 evaluations initiate the forward differencing")
def basis_independence():
    rng = random.Random(4)
    for _ in range(10):
        n = rng.randint(1, 5)
        c = [Fraction(rng.randint(-9, 9), rng.randint(1, 5)) for _ in range(n + 1)]
        delta = Fraction(1, rng.randint(2, 17))
        got = fd.forward_difference(c, 0, delta, 40, basis="bernstein")
        poly = sum(sp.Rational(ci.numerator, ci.denominator) * sp.binomial(n, i) * x**i * (1 - x) ** (n - i) for i, ci in enumerate(c))
        assert [sp.Rational(int(v.numerator), int(v.denominator)) for v in got] == [poly.subs(x, k * sp.Rational(delta.numerator, delta.denominator)) for k in range(40)]
    return verified_range("10 random Bernstein polynomials (degree 1-5), 40 steps each", "exact forward differencing equals direct sympy evaluation",
        compared="printed basis-independence claim vs direct sympy evaluation of 10 random Bernstein polynomials at k delta, 40 steps each, against exactcagd's forward differencing started from n + 1 evaluations",
        reference='sympy',
    )


@claim(doc="sederberg", section="4.1", ref="rasterization delta", statement="d = max{x_i - x_{i-1}, y_i - y_{i-1}}, delta = 1/(n d): no gaps; n d bounds the x and y components of P'")
def rasterization_delta():
    c = BezierCurve([[40, 40], [20, 30], [0, 0]])
    printed_d = max(max(b[0] - a[0], b[1] - a[1]) for a, b in zip(c.control_points[:-1], c.control_points[1:]))
    assert printed_d < 0  # the printed formula gives a negative step for a curve running left/down
    rng = random.Random(41)
    for _ in range(25):
        pts = [[rng.randint(-60, 60), rng.randint(-60, 60)] for _ in range(rng.randint(2, 5))]
        curve = BezierCurve(pts)
        px = fd.rasterize(curve)
        assert fd.pixels_connected(px)
        # n d bounds |x'| and |y'|: the hodograph's control values are n (x_i - x_{i-1})
        n = curve.degree
        dd = max(max(abs(b[0] - a[0]), abs(b[1] - a[1])) for a, b in zip(pts[:-1], pts[1:]))
        hodo = curve.derivative().control_points
        assert all(abs(v) <= n * dd for p in hodo for v in p)
    def bounds_hodograph(dfun):
        for pts_ in ([[40, 40], [20, 30], [0, 0]], [[0, 0], [5, -30], [9, 2]]):
            cv = BezierCurve(pts_)
            dd = dfun(pts_)
            if not all(abs(v) <= cv.degree * dd for p in cv.derivative().control_points for v in p):
                return f"d = {dd} for {pts_}: n d does not bound the hodograph"
        return None
    return erratum(
        printed="d = max{x_i - x_{i-1}, y_i - y_{i-1}}",
        corrected="d = max{|x_i - x_{i-1}|, |y_i - y_{i-1}|} (and ceil(n d) steps when d is not an integer)",
        detail=f"without absolute values d = {printed_d} for the curve (40,40),(20,30),(0,0); with them, 25 random curves rasterize exactly "
        "without gaps (8-connected pixels) and n d bounds every hodograph coordinate",
        printed_form=lambda ps: max(max(b_[0] - a_[0], b_[1] - a_[1]) for a_, b_ in zip(ps[:-1], ps[1:])), corrected_form=lambda ps: max(max(abs(b_[0] - a_[0]), abs(b_[1] - a_[1])) for a_, b_ in zip(ps[:-1], ps[1:])), check=L.predicate(bounds_hodograph), reference='exact',
    )


@claim(doc="sederberg", section="4", ref="float accumulation", statement="each successive evaluation requires n adds and no multiplies")
def float_versus_exact():
    # the printed scheme, written out: n + 1 direct evaluations start the table, then each step updates it
    # with the n additions D_j += D_(j+1) only (no multiplication in the loop); compared with (k/3)^3 evaluated directly
    n, delta = 3, Fraction(1, 3)
    table = [[(k * delta) ** 3 for k in range(n + 1)]]
    while len(table[-1]) > 1:
        table.append([b_ - a_ for a_, b_ in zip(table[-1][:-1], table[-1][1:])])
    D = [row[0] for row in table]  # f, Delta1, ..., Delta_n at t = 0
    values = [D[0]]
    for _ in range(299):
        for j in range(n):
            D[j] = D[j] + D[j + 1]
        values.append(D[0])
    assert values == [(k * delta) ** 3 for k in range(300)]
    report = fd.float_error_report([0, 0, 0, 1], 0, Fraction(1, 3), 300)
    assert 0 < report["max_error"] <= report["max_bound"]
    exact = fd.forward_difference([0, 0, 0, 1], 0, Fraction(1, 3), 300)
    assert exact[-1] == mpq(299, 3) ** 3
    return verified(f"t^3 at t = k/3, 300 steps: exact rational differencing is exact; binary64 differencing drifts by "
                    f"{float(report['max_error']):.3e} (certified bound {float(report['max_bound']):.3e})",
        compared="printed 'n adds, no multiplies' vs the scheme written out in the row (n + 1 direct evaluations, then only D_j += D_(j+1)) reproducing (k/3)^3 exactly for 300 steps (Fractions); binary64 drift vs exactcagd's certified bound",
        reference='exact',
    )

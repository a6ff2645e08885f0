"""Sederberg's notes, chapter 3 (polynomial evaluation and basis conversion).

The two C routines are transcribed literally and run on exact rationals; the basis
conversion formulas are checked against exactcagd's ``to_power``/``from_power``
and sympy's expansion of the Bernstein sum.
"""

from __future__ import annotations

from fractions import Fraction

import sympy as sp
from gmpy2 import mpq

from exactcagd.exact import bernstein as bz
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, reconstructed, verified, verified_range
from exactcagd.proofs._sederberg_common import Rs, bernstein_expr, rand_q, rng, t_

DOC = "sederberg"


def p_horner(p, n, t):
    """Literal transcription of the notes' C routine p_horner (3.1)."""
    h = p[n]
    for i in range(n - 1, -1, -1):
        h = t * h + p[i]
    return h


def b_horner(b, n, t):
    """Literal transcription of the notes' C routine b_horner (3.2) (exact arithmetic)."""
    u = 1 - t
    bc = 1
    tn = 1
    tmp = b[0] * u
    for i in range(1, n):
        tn = tn * t
        bc = bc * Fraction(n - i + 1) / i
        tmp = (tmp + tn * bc * b[i]) * u
    return tmp + tn * t * b[n]


def _power_coeffs(expr, n):
    coeffs = sp.Poly(expr, t_).all_coeffs()[::-1] if expr != 0 else [0]
    return [sp.Rational(c) for c in coeffs] + [sp.Integer(0)] * (n + 1 - len(coeffs))


@claim(DOC, "3.1", "p_horner", "h_n = p_n, h_(i-1) = t h_i + p_(i-1): y(t) = h_0 (n multiplies and adds)")
def horner_power_basis():
    r = rng(31)
    for n in range(0, 8):
        p = [rand_q(r) for _ in range(n + 1)]
        expr = sum(Rs(c) * t_**k for k, c in enumerate(p))
        for tq in [mpq(0), mpq(1, 3), mpq(-7, 4), mpq(5, 2)]:
            assert Rs(p_horner(p, n, tq)) == expr.subs(t_, Rs(tq))
            # and it evaluates the power form of a Bernstein polynomial like de Casteljau does
            c = bz.from_power(p)
            assert p_horner(list(bz.to_power(c)), n, tq) == bz.de_casteljau(c, tq)
    return verified_range("degrees 0..7 at t in {0, 1/3, -7/4, 5/2}", "transcribed C routine == sympy == exactcagd de Casteljau of the Bernstein form",
        compared="printed p_horner (3.1), transcribed literally and run on exact rationals, vs sympy evaluation of the power-basis polynomial, degrees 0..7 at 4 parameters; exactcagd's de Casteljau of the Bernstein form agrees",
        reference='sympy',
    )


@claim(DOC, "3.2", "b_horner", "Horner in Bernstein form with C(n,i) = (n-i+1)/i C(n,i-1) (C routine b_horner)")
def horner_bernstein_basis():
    r = rng(32)
    for n in range(0, 9):
        assert all(sp.binomial(n, i) == sp.Rational(n - i + 1, i) * sp.binomial(n, i - 1) for i in range(1, n + 1))
        b = [rand_q(r) for _ in range(n + 1)]
        expr = bernstein_expr(b)
        c = bz.as_coefficients(b)
        for tq in [mpq(0), mpq(1), mpq(1, 2), mpq(2, 7), mpq(6, 7), mpq(-1, 3), mpq(9, 4)]:
            value = b_horner([Fraction(int(x.numerator), int(x.denominator)) for x in b], n, Fraction(int(tq.numerator), int(tq.denominator)))
            assert Rs(value) == expr.subs(t_, Rs(tq))
            assert bz.horner_bernstein(c, tq) == bz.de_casteljau(c, tq) == mpq(value.numerator, value.denominator)
    return verified_range("degrees 0..8 (n = 0 included), t inside and outside [0,1]",
                          "transcribed C routine == sympy Bernstein sum == exactcagd horner_bernstein == de Casteljau",
        compared="printed b_horner (3.2), transcribed literally (exact), vs sympy evaluation of the Bernstein sum, degrees 0..8, t inside and outside [0, 1]; the binomial recurrence vs sympy.binomial; exactcagd's horner_bernstein and de Casteljau agree",
        reference='sympy',
    )


@claim(DOC, "3.3", "Taylor expansion", "B(t) = B(0) + B'(0) t + B''(0) t^2 / 2 + ... + B^(i)(0) t^i / i + ...")
def taylor_expansion_factorial():
    r = rng(33)
    b = [rand_q(r) for _ in range(6)]
    c = bz.as_coefficients(b)
    power = bz.to_power(c)
    derivs, d = [], c
    for i in range(6):
        derivs.append(bz.de_casteljau(d, 0))
        d = bz.derivative(d)
    assert [Rs(derivs[i]) / sp.factorial(i) for i in range(6)] == [Rs(x) for x in power]
    assert any(Rs(derivs[i]) / i != Rs(power[i]) for i in range(3, 6) if derivs[i] != 0)
    def taylor_coefficients(divisor):
        got = [Rs(derivs[i]) / divisor(i) for i in range(6)]
        ref = [Rs(x) for x in power]
        return None if got == ref else f"coefficients {got[:5]} vs power basis {ref[:5]}"
    return erratum(
        printed="... + B^(i)(0) t^i / i + ...",
        corrected="... + B^(i)(0) t^i / i! + ...",
        detail="Taylor coefficients need i! (as (3.1) then uses); exactcagd derivatives at 0 divided by i! equal to_power, divided by i they do not (i >= 3)",
        printed_form=lambda i: max(i, 1), corrected_form=sp.factorial, check=L.predicate(taylor_coefficients),
    )


@claim(DOC, "3.3", "(3.1)", "p_i = B^(i)(0) / i!, and the derivative coefficients n(b1-b0), ...; n(n-1)(b2 - 2b1 + b0), ...")
def power_coefficients_from_derivatives():
    r = rng(331)
    for n in range(1, 8):
        b = [rand_q(r) for _ in range(n + 1)]
        c = bz.as_coefficients(b)
        d1, d2 = bz.derivative(c), bz.derivative(bz.derivative(c))
        printed1 = [n * (b[i + 1] - b[i]) for i in range(n)]
        printed2 = [n * (n - 1) * (b[i + 2] - 2 * b[i + 1] + b[i]) for i in range(n - 1)]
        # independent reference: sympy derivatives of the Bernstein sum
        expr = bernstein_expr(b)
        assert sp.expand(bernstein_expr(printed1) - sp.diff(expr, t_)) == 0
        assert n < 2 or sp.expand(bernstein_expr(printed2) - sp.diff(expr, t_, 2)) == 0
        assert [Rs(sp.diff(expr, t_, i).subs(t_, 0)) / sp.factorial(i) for i in range(n + 1)] == _power_coeffs(expr, n)
        assert list(d1) == printed1
        if n >= 2:
            assert list(d2) == printed2
        d, values = c, []
        for _ in range(n + 1):
            values.append(bz.de_casteljau(d, 0))
            d = bz.derivative(d)
        expected = _power_coeffs(bernstein_expr(b), n)
        assert [Rs(values[i]) / sp.factorial(i) for i in range(n + 1)] == expected
    return verified_range("degrees 1..7", "exact hodographs; B^(i)(0)/i! == sympy power coefficients",
        compared="printed (3.1) p_i = B^(i)(0)/i! and the derivative coefficients n(b1 - b0), n(n-1)(b2 - 2b1 + b0) vs sympy: derivatives of the Bernstein sum (as Bernstein sums and at 0) and the expanded power coefficients, degrees 1..7; exactcagd's hodographs equal the printed coefficients",
        reference='sympy',
    )


@claim(DOC, "3.3", "B^(i)(0)", "B^(i)(0) = n(n-1)...(n-i+1) sum_(j=0)^i (-1)^(i-j+1) C(i,j) b_j")
def derivative_at_zero_sign():
    r = rng(332)
    n = 5
    b = [rand_q(r) for _ in range(n + 1)]
    c = bz.as_coefficients(b)
    d, values = c, []
    for _ in range(n + 1):
        values.append(bz.de_casteljau(d, 0))
        d = bz.derivative(d)

    def falling(i):
        out = 1
        for k in range(i):
            out *= n - k
        return out

    corrected = [falling(i) * sum((-1) ** (i - j) * sp.binomial(i, j) * Rs(b[j]) for j in range(i + 1)) for i in range(n + 1)]
    printed = [falling(i) * sum((-1) ** (i - j + 1) * sp.binomial(i, j) * Rs(b[j]) for j in range(i + 1)) for i in range(n + 1)]
    assert [Rs(v) for v in values] == corrected
    assert printed == [-x for x in corrected] and printed != corrected
    def matches_derivatives(values_):
        ref = [Rs(v) for v in values]
        return None if list(values_) == ref else f"B'(0) = {values_[1]}, exact derivative {ref[1]}"
    return erratum(
        printed="(-1)^(i-j+1)",
        corrected="(-1)^(i-j)",
        detail="with the printed sign B'(0) would be n(b0 - b1); the exact derivatives at 0 (exactcagd) match (-1)^(i-j)",
        printed_form=printed, corrected_form=corrected, check=L.predicate(matches_derivatives), reference='exact',
    )


@claim(DOC, "3.3", "difference table", "b_i^j = b_(i+1)^(j-1) - b_i^(j-1); B^(i)(0) = n!/(n-i)! b_0^i; p_i = C(n,i) b_0^i "
       "(table entries: b_1^1 = b_1^0 - b_0^0 = p_1/C(n,1), ..., b_n^0 = b_n^0 - b_(n-1)^0)")
def difference_table():
    r = rng(333)
    for n in range(0, 8):
        b = [rand_q(r) for _ in range(n + 1)]
        table = [b]
        while len(table[-1]) > 1:
            prev = table[-1]
            table.append([prev[i + 1] - prev[i] for i in range(len(prev) - 1)])
        left = [row[0] for row in table]
        power = list(bz.to_power(bz.as_coefficients(b)))
        assert [sp.binomial(n, i) * Rs(left[i]) for i in range(n + 1)] == [Rs(x) for x in power]
        # backwards: power -> Bernstein by the reverse table
        col = [Rs(p) / sp.binomial(n, i) for i, p in enumerate(power)]
        rows = [[c] for c in col]
        for j in range(n - 1, -1, -1):  # rebuild row j from row j+1 and its first entry
            row = [col[j]]
            for k in range(len(rows[j + 1])):
                row.append(row[-1] + rows[j + 1][k])
            rows[j] = row
        assert [Rs(x) for x in bz.from_power(power)] == rows[0] == [Rs(x) for x in b]
    def first_difference_label(label):
        # the entry b_1^0 - b_0^0 sits in column 1, row 0 of the forward table: its label is b_0^1
        bb = [Rs(x) for x in b]
        table_ = {(i, 0): bb[i] for i in range(len(bb))}
        if len(bb) > 1:
            table_[(0, 1)] = bb[1] - bb[0]
        i_, j_ = label
        return None if table_.get((i_, j_)) == bb[1] - bb[0] else f"b_{i_}^{j_} is not b_1^0 - b_0^0 in the forward table"
    return reconstructed(
        printed="b_1^1 = b_1^0 - b_0^0 = p_1 / C(n,1) (first column) and b_n^0 = b_n^0 - b_(n-1)^0 (second row, last column)",
        corrected="b_0^1 = b_1^0 - b_0^0 = p_1 / C(n,1) and b_(n-1)^1 = b_n^0 - b_(n-1)^0",
        detail="two table labels are garbled; the procedure (forward table, left column times C(n,i); backwards for the inverse) "
        "reproduces exactcagd to_power / from_power exactly for degrees 0..7",
        printed_form=(1, 1), corrected_form=(0, 1), check=L.predicate(first_difference_label), reference='exact',
    )


@claim(DOC, "3.3.1", "Example", "Bernstein (1, 3, 4, 6, 8) -> table rows (2,1,2,2), (-1,1,0), (2,-1), (-3) -> power (1, 8, -6, 8, -3)")
def conversion_example():
    b = [1, 3, 4, 6, 8]
    rows = [b]
    while len(rows[-1]) > 1:
        rows.append([rows[-1][i + 1] - rows[-1][i] for i in range(len(rows[-1]) - 1)])
    assert rows[1:] == [[2, 1, 2, 2], [-1, 1, 0], [2, -1], [-3]]
    power = bz.to_power(bz.as_coefficients(b))
    assert list(power) == [1, 8, -6, 8, -3]
    assert sp.expand(bernstein_expr(b) - (1 + 8 * t_ - 6 * t_**2 + 8 * t_**3 - 3 * t_**4)) == 0
    assert list(bz.from_power([1, 8, -6, 8, -3])) == b
    return verified("exactcagd to_power gives (1, 8, -6, 8, -3); sympy expansion agrees; from_power inverts",
        compared="printed table rows of 3.3.1, recomputed by differences in the row, and the printed power form (1, 8, -6, 8, -3) vs sympy expansion of the Bernstein sum (1, 3, 4, 6, 8); exactcagd's to_power / from_power agree",
        reference='sympy',
    )


@claim(DOC, "3.3.2", "closed form", "p_i = sum_(k=0)^i b_k C(n,i) C(i,k) (-1)^(i-k)")
def conversion_closed_form():
    r = rng(3332)
    for n in range(0, 9):
        b = [rand_q(r) for _ in range(n + 1)]
        formula = [sum(Rs(b[k]) * sp.binomial(n, i) * sp.binomial(i, k) * (-1) ** (i - k) for k in range(i + 1)) for i in range(n + 1)]
        assert [Rs(x) for x in bz.to_power(bz.as_coefficients(b))] == formula
        assert formula == _power_coeffs(bernstein_expr(b), n)
    return verified_range("degrees 0..8", "closed form == exactcagd to_power == sympy expansion",
        compared="printed closed form p_i = sum b_k C(n,i) C(i,k) (-1)^(i-k) vs sympy expansion of the Bernstein sum into power coefficients, degrees 0..8; exactcagd's to_power agrees",
        reference='sympy',
    )

"""Ledger: Sederberg's notes, chapter 13 (floating point error), checked exactly.

Rounding is simulated exactly with gmpy2 (``mpfr`` at ``d`` significant bits,
round-to-nearest) and with IEEE binary64 floats; every error is measured in exact
rational arithmetic (``gmpy2.mpq`` / ``fractions.Fraction``).  The affine-map claim
(13.6)-(13.8) is the building block of the certified evaluator
:mod:`exactcagd.numeric.evaluation`, whose ``3n + 1`` count uses the corrected form.
"""

from __future__ import annotations

import random
from fractions import Fraction

import gmpy2
import numpy as np
from gmpy2 import mpfr, mpq

from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, reconstructed, verified, verified_range


def _decode(bits: str) -> Fraction:
    """Decode ``s|e_s e_7..e_0|f_1 f_2 ...`` as ``(-1)^s (sum f_i 2^-i) 2^((-1)^e_s sum e_j 2^j)``."""
    sign, exponent, fraction = bits.split("|")
    magnitude = int(exponent[1:], 2)
    e = -magnitude if exponent[0] == "1" else magnitude
    f = sum(Fraction(int(b), 2 ** (i + 1)) for i, b in enumerate(fraction))
    return (-1) ** int(sign) * f * Fraction(2) ** e


@claim(
    doc="sederberg",
    section="13",
    ref="(13.1)-(13.2)",
    statement="b = (-1)^s f^e with f = sum f_i 2^-i, e = (-1)^e_s sum_{j=0..6} e_j 2^j; "
    "examples 0|000000100|1101.. = 13, 0|100000001|111.. = 7/16, 1|000000100|10011.. = -9 1/2",
)
def decoding_formula():
    printed = {
        "0|000000100|11010000000000000000000000000000": Fraction(13),
        "0|100000001|11100000000000000000000000000000": Fraction(7, 16),
        "1|000000100|10011000000000000000000000000000": Fraction(-19, 2),
    }
    for bits, value in printed.items():
        assert _decode(bits) == value, bits
    assert Fraction(1, 4) + Fraction(1, 8) + Fraction(1, 16) == Fraction(7, 16)
    def covers_exponent_bits(top):
        # (13.1) lays out the exponent magnitude as e_7 ... e_0 (8 bits): the sum must run over all of them
        layout = "0|100000001|"  # sign | exponent sign + e_7..e_0 | fraction
        bits = len(layout.split("|")[1]) - 1
        return None if top + 1 == bits else f"sum over j = 0..{top} ignores e_{top + 1}..e_{bits - 1} of the {bits}-bit exponent of (13.1)"
    return reconstructed(
        printed="b = (-1)^s f^e, exponent sum over j = 0..6, '32 bits' with 8 exponent bits + exponent sign + 23 fraction bits",
        corrected="b = (-1)^s * f * 2^e with e = (-1)^e_s sum_{j=0..7} e_j 2^j (8 magnitude bits e_7..e_0 as in (13.1)); "
        "the layout of (13.1) has 1 + 1 + 8 + 23 = 33 bits",
        detail="the three printed bit strings decode exactly to 13, 7/16 and -19/2 with the corrected formula "
        "(the '^e' of the extraction is the factor 2^e; the printed sum bound 6 contradicts e_7 in (13.1))",
        printed_form=6, corrected_form=7, check=L.predicate(covers_exponent_bits), reference='text',
    )


@claim(
    doc="sederberg",
    section="13",
    ref="1/3 example",
    statement="1/3 = 0.0101..._2 lies between 0|100000001|10101010101010101010101 and 0|100000001|101010101010101010110",
)
def one_third_neighbours():
    assert sum(Fraction(1, 4**k) for k in range(1, 60)) < Fraction(1, 3) < sum(Fraction(1, 4**k) for k in range(1, 60)) + Fraction(1, 4**59)
    lower = _decode("0|100000001|10101010101010101010101")
    upper_printed = _decode("0|100000001|101010101010101010110")
    upper = _decode("0|100000001|10101010101010101010110")
    assert lower < Fraction(1, 3) < upper and upper - lower == Fraction(1, 2**24)  # adjacent 23-bit numbers
    with gmpy2.context(precision=23, round=gmpy2.RoundDown):
        assert Fraction(*mpfr(mpq(1, 3)).as_integer_ratio()) == lower
    with gmpy2.context(precision=23, round=gmpy2.RoundUp):
        assert Fraction(*mpfr(mpq(1, 3)).as_integer_ratio()) == upper
    assert upper_printed > upper  # the printed 21-bit string is above 1/3 but not the adjacent float
    def is_upper_neighbour(fraction_bits):
        val = _decode("0|100000001|" + fraction_bits)
        return None if val == upper else f"{fraction_bits} decodes to {val}, 1/3 rounded up to 23 bits is {upper}"
    return reconstructed(
        printed="upper neighbour fraction 101010101010101010110 (21 bits); 1/3 = 0.0101\\bar0\\bar1_2",
        corrected="upper neighbour fraction 10101010101010101010110 (23 bits); 1/3 = 0.\\overline{01}_2",
        detail="the lower neighbour is as printed (1/3 rounded down to 23 bits, checked with mpfr); the upper one is "
        "1/3 rounded up, 2^-24 above; the printed 21-bit string decodes to a larger, non-adjacent number (two bits lost)",
        printed_form='101010101010101010110', corrected_form='10101010101010101010110', check=L.predicate(is_upper_neighbour), reference='exact',
    )


def _rounding_set(b: mpq, d: int) -> tuple[mpq, mpq]:
    """Exact set {x > 0 : round-to-nearest at d bits of x is b}, as (inf, sup), for b > 0 representable."""
    with gmpy2.context(precision=d):
        below = mpq(gmpy2.next_below(mpfr(b)))
        above = mpq(gmpy2.next_above(mpfr(b)))
    return (below + b) / 2, (b + above) / 2


@claim(
    doc="sederberg",
    section="13",
    ref="(13.3)",
    statement="a float b stands for the interval [b] = [b(1 - 2^-(d+1)), b(1 + 2^-(d+1))] of numbers closer to it than to any other float",
)
def float_as_interval():
    d = 23
    rng = random.Random(13)
    samples = [mpq(1, 2), mpq(1), mpq(3, 4), mpq(13), mpq(7, 16)]
    with gmpy2.context(precision=d):
        samples += [mpq(mpfr(mpq(rng.randint(1, 10**9), rng.randint(1, 10**9)))) for _ in range(200)]
    eta = mpq(1, 2**d)
    half = mpq(1, 2 ** (d + 1))
    printed_too_small = 0
    for b in samples:
        lo, hi = _rounding_set(b, d)
        assert b * (1 - eta) <= lo and hi <= b * (1 + eta)  # corrected: contained in b[1 -+ 2^-d]
        assert lo <= b * (1 - half) and b * (1 + half) <= hi  # the printed set is a subset
        printed_too_small += hi > b * (1 + half)
    assert printed_too_small == len(samples)
    # explicit counterexample: x rounds to b = 1/2 at 23 bits but lies outside the printed interval
    b, x = mpq(1, 2), mpq(1, 2) + mpq(3, 2**26)
    with gmpy2.context(precision=d):
        assert mpq(mpfr(x)) == b
    assert x > b * (1 + half)
    def contains_rounding_set(rel):
        lo_, hi_ = _rounding_set(b, d)
        xx = mpq(1, 2) + mpq(3, 2**26)
        return None if b * (1 + rel) >= hi_ and xx <= b * (1 + rel) else f"x = 1/2 + 3*2^-26 rounds to 1/2 but lies above 1/2 (1 + {rel})"
    return erratum(
        printed="[b] = b[1 - 2^-(d+1), 1 + 2^-(d+1)]",
        corrected="[b] = [b - 2^(e-d-1) (halved below a power of two), b + 2^(e-d-1)] for b = f 2^e, f in [1/2, 1); "
        "hence b[1 - 2^-(d+1), 1 + 2^-(d+1)] is strictly inside [b] and [b] is inside b[1 - 2^-d, 1 + 2^-d] "
        "(consistent with (13.5), eta = 2^-d)",
        detail="exact rounding sets at d = 23 for 205 floats: the printed interval is too small for every one; "
        "x = 1/2 + 3*2^-26 rounds to 1/2 but lies outside the printed [1/2]",
        printed_form=half, corrected_form=eta, check=L.predicate(contains_rounding_set), reference='exact',
    )


@claim(
    doc="sederberg",
    section="13",
    ref="(13.4)-(13.5)",
    statement="with eta = 2^-d, fl(x * y) in x * y [1 - eta, 1 + eta] for * in {+, -, x, /}",
)
def unit_roundoff_model():
    rng = random.Random(5)
    worst = {}
    for d in (23, 53):
        eta = mpq(1, 2**d)
        with gmpy2.context(precision=d, emin=-10**6, emax=10**6):
            for _ in range(600):
                x = mpfr(mpq(rng.randint(-10**12, 10**12), rng.randint(1, 10**9)))
                y = mpfr(mpq(rng.randint(-10**12, 10**12), rng.randint(1, 10**9)))
                if y == 0:
                    continue
                for name, exact, rounded in (
                    ("+", mpq(x) + mpq(y), x + y),
                    ("-", mpq(x) - mpq(y), x - y),
                    ("x", mpq(x) * mpq(y), x * y),
                    ("/", mpq(x) / mpq(y), x / y),
                ):
                    err = abs(mpq(rounded) - exact)
                    assert err <= eta * abs(exact), (d, name)
                    if exact:
                        worst[d] = max(worst.get(d, 0), err / (eta * abs(exact)))
    # IEEE binary64 with its exponent range: subnormal results break the relative model
    tiny = 2.0**-1074
    assert tiny * 0.5 == 0.0 and 2.0**-1070 * 0.3 != 0  # relative error 1 for the first product
    return verified_range(
        "d = 23 and d = 53, 2400 random operations each, unbounded exponent range",
        f"largest observed |fl - exact| / (eta |exact|): {float(worst[23]):.3f} (d=23), {float(worst[53]):.3f} (d=53); "
        "the bound holds only without underflow: in IEEE binary64 a subnormal result has an absolute error up to "
        "2^-1075 (fl(2^-1074 * 0.5) = 0), which exactcagd.numeric.evaluate adds as a separate absolute term",
        compared='printed (13.4)-(13.5) vs exact rational errors |fl(x op y) - x op y| (gmpy2 mpfr rounding at d = 23, 53 bits, measured in mpq) for 2400 random operations; IEEE underflow counterexample fl(2^-1074 * 0.5) = 0', reference='exact')


def _affine_fl(t: float, p0: float, p1: float) -> float:
    """The float affine map fl(fl(fl(1 - t) p0) + fl(t p1)) in IEEE binary64."""
    return (1.0 - t) * p0 + t * p1


def _eps(t: Fraction, p0: Fraction, p1: Fraction, eta: Fraction, corrected: bool) -> Fraction:
    m = (1 - t) * p0 + t * p1
    first = abs(1 - t) * abs(p0) * ((2 * (1 + eta)) if corrected else 1)
    return (first + abs(t) * abs(p1) + abs(m)) * eta


@claim(
    doc="sederberg",
    section="13",
    ref="(13.6)-(13.8)",
    statement="fl[M](p0 + e0[i], p1 + e1[i], t) in [M](...) + eps(t), "
    "eps(t) = {|1-t||p0| + |t||p1| + |p0(1-t) + p1 t|} eta [i] (piecewise form (13.7))",
)
def affine_map_error():
    eta = Fraction(1, 2**53)
    # (13.7) is (13.8) written per case: symbolic check of the three sign patterns
    for t in (Fraction(-3, 2), Fraction(1, 3), Fraction(5, 2)):
        for p0, p1 in ((Fraction(2), Fraction(-7, 3)), (Fraction(-1, 5), Fraction(4))):
            m = abs(p0 * (1 - t) + p1 * t)
            case = (abs(p0) * (1 - t) - abs(p1) * t) if t < 0 else (abs(p0) * (1 - t) + abs(p1) * t) if t <= 1 else (abs(p0) * (t - 1) + abs(p1) * t)
            assert case + m == abs(1 - t) * abs(p0) + abs(t) * abs(p1) + m
    # counterexample: fl(1 - t) inexact (t < 1/2)
    t, p0, p1 = 0.4799682504469967, 1.9542732406940162, -2.116233999614336
    T, P0, P1 = Fraction(t), Fraction(p0), Fraction(p1)
    assert Fraction(1.0 - t) != 1 - T
    err = abs(Fraction(_affine_fl(t, p0, p1)) - ((1 - T) * P0 + T * P1))
    assert err > _eps(T, P0, P1, eta, corrected=False)
    assert err <= _eps(T, P0, P1, eta, corrected=True)
    # random checks: printed form when 1 - t is exact (Sterbenz, t in [1/2, 2]); corrected form always
    rng = np.random.default_rng(138)
    worst_exact, worst_corr, broken = Fraction(0), Fraction(0), 0
    for k in range(2000):
        if k % 2:
            t = float(rng.uniform(0.5, 2.0))
        else:
            t = float(rng.uniform(-3, 0.5))
        p0 = float(rng.uniform(-2, 2))
        p1 = float(-p0 * (1 - t) / t * (1 + rng.uniform(-1e-3, 1e-3))) if k % 3 == 0 and t != 0 else float(rng.uniform(-2, 2))
        T, P0, P1 = Fraction(t), Fraction(p0), Fraction(p1)
        err = abs(Fraction(_affine_fl(t, p0, p1)) - ((1 - T) * P0 + T * P1))
        ratio_corr = err / _eps(T, P0, P1, eta, True) if err else Fraction(0)
        assert ratio_corr <= 1
        worst_corr = max(worst_corr, ratio_corr)
        if Fraction(1.0 - t) == 1 - T:
            ratio = err / _eps(T, P0, P1, eta, False) if err else Fraction(0)
            assert ratio <= 1
            worst_exact = max(worst_exact, ratio)
        else:
            broken += err > _eps(T, P0, P1, eta, False)
    assert broken > 0
    def bounds_counterexample(corrected_):
        t_, p0_, p1_ = 0.4799682504469967, 1.9542732406940162, -2.116233999614336
        T_, P0_, P1_ = Fraction(t_), Fraction(p0_), Fraction(p1_)
        err_ = abs(Fraction(_affine_fl(t_, p0_, p1_)) - ((1 - T_) * P0_ + T_ * P1_))
        e_ = _eps(T_, P0_, P1_, eta, corrected=corrected_)
        return None if err_ <= e_ else f"binary64 t = {t_}: error {float(err_):.3g} > eps {float(e_):.3g}"
    return erratum(
        printed="eps(t) = {|1-t||p0| + |t||p1| + |M(p0, p1, t)|} eta",
        corrected="valid as printed when the weights 1-t and t are exact floats (e.g. t in [1/2, 2], Sterbenz); "
        "when fl(1-t) is itself rounded: eps(t) = {2(1+eta)|1-t||p0| + |t||p1| + |M|} eta",
        detail=f"binary64 counterexample t = 0.4799682504469967, p0 = 1.9542732406940162, p1 = -2.116233999614336: "
        f"the error exceeds the printed eps (ratio 1.40); 2000 random cases: printed form never exceeded when 1-t is exact "
        f"(worst ratio {float(worst_exact):.3f}), exceeded {broken} times otherwise; corrected form never exceeded "
        f"(worst {float(worst_corr):.3f}). Proof of both with the refined model |fl(x) - x| <= eta/(1+eta)|x|: the error is "
        "(1-t)p0[(1+d0)(1+d1) - 1] + t p1 d2 + d3 S, |S| <= |M| + ...; (13.8) is its first-order part. "
        "Per de Casteljau level this is 3 rounding factors on the (1-t) branch, the k = 3n + 1 of exactcagd.numeric.evaluate",
        printed_form=False, corrected_form=True, check=L.predicate(bounds_counterexample), reference='exact',
    )


@claim(
    doc="sederberg",
    section="13",
    ref="Figure 13.1",
    statement="evaluating a curve tangent to the axis at t = 0.25 at several hundred t near 0.25 gives values that "
    "fluctuate chaotically within a band instead of a smooth graph",
)
def chaotic_band():
    from exactcagd import BezierCurve
    from exactcagd.exact import bernstein as bz
    from exactcagd.numeric.evaluation import evaluate

    # y(t) = (4t - 1)^2 (3 - 2t)(t + 5) / 3: double root at t = 1/4 (tangent to the t-axis)
    factors = [[-1, 4], [-1, 4], [3, -2], [5, 1]]
    power = [Fraction(1, 3)]
    for f in factors:
        power = [sum(power[i] * f[k - i] for i in range(len(power)) if 0 <= k - i < 2) for k in range(len(power) + 1)]
    coeffs = bz.from_power(np.array([[mpq(c.numerator, c.denominator)] for c in power], dtype=object))
    curve = BezierCurve(coeffs)
    ts = 0.25 + (np.arange(-300, 300) * 2.0**-40)

    def exact(x: float) -> Fraction:
        x = Fraction(x)
        acc = Fraction(0)
        for c in reversed(power):
            acc = acc * x + c
        return acc

    exact_values = [exact(x) for x in ts]
    exact_diffs = [b - a for a, b in zip(exact_values, exact_values[1:])]
    exact_changes = sum((a > 0) != (b > 0) for a, b in zip(exact_diffs, exact_diffs[1:]))
    assert exact_changes == 1
    report = []
    for method in ("decasteljau", "horner"):
        values, radii = evaluate(curve, ts, method=method)
        for v, r, e in zip(values[:, 0], radii[:, 0], exact_values):
            assert abs(Fraction(v) - e) <= Fraction(r)
        diffs = np.diff(values[:, 0])
        changes = int(np.sum(np.sign(diffs[1:]) != np.sign(diffs[:-1])))
        assert changes > 50
        report.append(f"{method}: {changes} changes, band radius {radii.max():.1e}")
    return verified(
        "y(t) = (4t-1)^2 (3-2t)(t+5)/3 in Bernstein form at 600 floats within 3e-10 of 1/4: the exact values change "
        f"monotonicity once, the float values chaotically ({'; '.join(report)}); every float value lies within the "
        "certified radius of the exact value (checked in rational arithmetic)",
        compared='printed Figure 13.1 behaviour vs exact rational Horner values of y(t) at the same 600 floats: exact values change monotonicity once, float de Casteljau/Horner values > 50 times; every float value lies within its certified radius of the exact value', reference='exact')

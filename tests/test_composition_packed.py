"""The fast route's integer packing (``exactcagd.composition.fast._flint_route``).

The route packs all coordinates of the surface net into one integer per control point
(base ``2^B`` digits) and reads the coordinates of the result back as balanced digits.
Checked here against an independent sympy evaluation of Lasser & Bonneau's formula
(``W^(l+m) (P, w)(X/W, Y/W)`` expanded, Theorems 1, 2), on nets and curves with large,
negative, zero and mixed-denominator entries (where a too-narrow digit would carry into
its neighbour), and the digit width's bound is shown to be attained: one bit less
corrupts a planted coordinate at the bound.
"""

from __future__ import annotations

import flint
import numpy as np
import sympy
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.composition.fast import _balanced_digits, _basis, _digit_bits, _packed_sum, compose_homogeneous_fast

T = sympy.Symbol("t")


def _sym(x) -> sympy.Rational:
    return sympy.Rational(int(x.numerator), int(x.denominator))


def _bernstein_poly(coeffs) -> sympy.Poly:
    n = len(coeffs) - 1
    return sympy.Poly(sum(_sym(c) * sympy.binomial(n, i) * T**i * (1 - T) ** (n - i) for i, c in enumerate(coeffs)), T, domain="QQ")


def _reference_columns(net: np.ndarray, curve: np.ndarray) -> list:
    """``sum_ij H_ij C(l,i) X^i (W-X)^(l-i) C(m,j) Y^j (W-Y)^(m-j)`` per coordinate, in sympy."""
    l, m, dims = net.shape[0] - 1, net.shape[1] - 1, net.shape[2]
    X, Y, W = (_bernstein_poly(curve[:, k]) for k in range(3))
    bu = [sympy.binomial(l, i) * X**i * (W - X) ** (l - i) for i in range(l + 1)]
    bv = [sympy.binomial(m, j) * Y**j * (W - Y) ** (m - j) for j in range(m + 1)]
    return [sum((bu[i] * bv[j] * _sym(net[i, j, k]) for i in range(l + 1) for j in range(m + 1)), sympy.Poly(0, T, domain="QQ")) for k in range(dims)]


_small = st.builds(mpq, st.integers(-1000, 1000), st.integers(1, 1000))
_huge = st.builds(mpq, st.integers(-(2**200), 2**200), st.integers(1, 2**90))
entries = st.one_of(st.just(mpq(0)), st.just(mpq(1)), st.just(mpq(-1)), _small, _huge)


@st.composite
def net_and_curve(draw):
    l, m, n, d = draw(st.integers(0, 3)), draw(st.integers(0, 3)), draw(st.integers(0, 3)), draw(st.integers(1, 3))
    polynomial = draw(st.booleans())
    net = np.empty((l + 1, m + 1, d + 1), dtype=object)
    for idx in np.ndindex(l + 1, m + 1, d):
        net[idx] = draw(entries)
    for i in range(l + 1):
        for j in range(m + 1):
            net[i, j, d] = mpq(1) if polynomial else draw(entries)
    curve = np.empty((n + 1, 3), dtype=object)
    for i in range(n + 1):
        curve[i, 0], curve[i, 1] = draw(entries), draw(entries)
        curve[i, 2] = mpq(1) if polynomial else draw(entries)
    return net, curve


@settings(max_examples=60, deadline=None)
@given(net_and_curve())
def test_packed_route_equals_sympy_expansion(data):
    net, curve = data
    hom = compose_homogeneous_fast(net, curve)
    l, m, n = net.shape[0] - 1, net.shape[1] - 1, curve.shape[0] - 1
    assert hom.shape == (n * (l + m) + 1, net.shape[2])
    assert all(type(v) is type(mpq(0)) for v in hom.ravel())
    for k, ref in enumerate(_reference_columns(net, curve)):
        assert _bernstein_poly(hom[:, k]) == ref


def _one_point_at_origin(top: int):
    """A degree-(2, 2) net whose (0, 0) control point carries ``top`` and ``-top``, all other
    entries ``+-top``, on the one-point curve ``(0, 0)`` (x = y = 0, w = 1): the result is
    exactly ``h_00``, and ``|h_00| = max|h|`` attains :func:`_digit_bits`' bound."""
    h = [top, -top, top] + [(-1) ** s * top for s in range(3 * 8)]
    x, y, w = flint.fmpz_poly([]), flint.fmpz_poly([]), flint.fmpz_poly([1])
    return h, _basis(x, w - x, 2), _basis(y, w - y, 2)


def test_digit_width_bound_is_attained_and_one_bit_less_fails():
    top = 2**70
    h, b, c = _one_point_at_origin(top)
    bits = _digit_bits(h, 0, 0, 1, 2, 2)
    exact = [[top], [-top], [top]]
    assert [[int(v) for v in col] for col in _balanced_digits(_packed_sum(b, c, h, 3, bits), bits, 3, 1)] == exact
    narrow = bits - 1  # |A| = 2^70 = 2^(narrow - 1): the digit overflows into the next one
    wrong = [[int(v) for v in col] for col in _balanced_digits(_packed_sum(b, c, h, 3, narrow), narrow, 3, 1)]
    assert wrong != exact


def test_planted_bound_through_the_public_route():
    """The same planted net through compose_homogeneous_fast: the exact value at the bound."""
    top = mpq(2**70)
    net = np.empty((3, 3, 3), dtype=object)
    for s, idx in enumerate(np.ndindex(3, 3, 3)):
        net[idx] = top if s % 2 == 0 else -top
    curve = np.array([[mpq(0), mpq(0), mpq(1)]], dtype=object)
    hom = compose_homogeneous_fast(net, curve)
    assert hom.shape == (1, 3) and list(hom[0]) == list(net[0, 0])


# ----------------------------------------------------------------------------- the integer form
def _fraction_de_casteljau_halves(column):
    """Bernstein coefficients on [0, 1/2] and [1/2, 1] by the de Casteljau triangle in Fractions."""
    from fractions import Fraction

    level = [Fraction(int(c.numerator), int(c.denominator)) for c in column]
    left, right = [level[0]], [level[-1]]
    while len(level) > 1:
        level = [(a + b) / 2 for a, b in zip(level[:-1], level[1:])]
        left.append(level[0])
        right.append(level[-1])
    return left, right[::-1]


@settings(max_examples=60, deadline=None)
@given(net_and_curve())
def test_scaled_form_reads_back_and_halves_like_de_casteljau(data):
    """compose_scaled is the composition (sympy expansion), read back as mpq; its halves are
    the Fraction de Casteljau halves at 1/2; its floats are the correctly rounded Fractions;
    from_homogeneous gives the same rationals back."""
    from fractions import Fraction

    from exactcagd.composition.fast import ScaledBernstein, compose_scaled

    net, curve = data
    image = compose_scaled(net, curve)
    hom = image.homogeneous()
    for k, ref in enumerate(_reference_columns(net, curve)):
        assert _bernstein_poly(hom[:, k]) == ref
    assert [list(image.row(r)) for r in (0, -1)] == [list(hom[0]), list(hom[-1])]
    fl = image.floats()
    assert [[float(Fraction(int(x.numerator), int(x.denominator))) for x in row] for row in hom.tolist()] == fl.tolist()
    for half, which in zip(image.halves(), (0, 1)):
        got = half.homogeneous()
        for k in range(hom.shape[1]):
            assert [Fraction(int(x.numerator), int(x.denominator)) for x in got[:, k]] == _fraction_de_casteljau_halves(hom[:, k])[which]
    again = ScaledBernstein.from_homogeneous(hom)
    assert (again.homogeneous() == hom).all()

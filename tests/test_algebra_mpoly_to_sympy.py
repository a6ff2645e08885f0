"""``mpoly_to_sympy``'s bivariate fast path (dense rows filled directly) against sympy's own
``Poly`` of the same expression (independent), including missing x-degrees, zero rows,
constant and huge coefficients, and the general path it must agree with."""

from __future__ import annotations

import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.algebra._poly import XY, mpoly_to_sympy, zctx

x, y, z = sympy.symbols("x y z")

terms = st.dictionaries(st.tuples(st.integers(0, 6), st.integers(0, 6)), st.integers(-(2**80), 2**80).filter(bool), min_size=1, max_size=12)


@settings(max_examples=80, deadline=None)
@given(terms)
def test_bivariate_fast_path_equals_sympy_poly(data):
    got = mpoly_to_sympy(XY.from_dict(data), (x, y))
    ref = sympy.Poly(sum(c * x**i * y**j for (i, j), c in data.items()), x, y, domain="ZZ")
    assert got == ref
    assert got.rep.to_list() == ref.rep.to_list()  # same dense representation, not only equal values
    assert got.domain == sympy.ZZ and got.gens == (x, y)


def test_gaps_and_constants():
    data = {(5, 0): 3, (0, 4): -1, (0, 0): 7}  # x-degrees 1..4 missing, y-gaps in the last row
    got = mpoly_to_sympy(XY.from_dict(data), (x, y))
    assert got.rep.to_list() == [[3], [], [], [], [], [-1, 0, 0, 0, 7]]
    assert got.as_expr() == 3 * x**5 - y**4 + 7
    assert mpoly_to_sympy(XY.from_dict({(0, 0): -5}), (x, y)).as_expr() == -5


def test_three_variables_take_the_general_path():
    ctx = zctx(("x", "y", "z"))
    data = {(1, 2, 3): 4, (0, 0, 1): -2}
    assert mpoly_to_sympy(ctx.from_dict(data), (x, y, z)) == sympy.Poly(4 * x * y**2 * z**3 - 2 * z, x, y, z)

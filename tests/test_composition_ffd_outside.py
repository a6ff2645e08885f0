"""Notes ch. 14: "points outside of the rectangle are not moved" (ffd(..., outside="keep")).
References: sympy substitution into (14.2), mpmath roots of the boundary equations, and exact
derivatives for the continuity control of Figure 14.5."""
from __future__ import annotations

from fractions import Fraction as Fr

import mpmath
import pytest
import sympy as sp

from exactcagd import BezierCurve, BezierSurface
from exactcagd.composition import ffd
from exactcagd.composition.ffd import identity_lattice
from exactcagd.errors import InputError, NotSupportedError
from exactcagd.exact.algebraic import RealAlgebraic

CUBIC = BezierCurve([["-1/2", "1/5"], ["1/2", "2"], [1, "-1/3"], ["3/2", "3/4"]])  # leaves the unit square


def _lattice(l, m, move):
    net = [[[Fr(i, l), Fr(j, m)] for j in range(m + 1)] for i in range(l + 1)]
    for (i, j), (dx, dy) in move.items():
        net[i][j] = [net[i][j][0] + dx, net[i][j][1] + dy]
    return BezierSurface(net)


def _sympy_ffd(lattice, point):
    """(14.2) by substitution: sum B_i(s) B_j(t) P_ij at the point (region = unit square)."""
    s, t = (sp.Rational(int(c.numerator), int(c.denominator)) for c in point)
    l, m = lattice.degree
    net = lattice.net_array()
    return tuple(
        sum(sp.binomial(l, i) * s**i * (1 - s) ** (l - i) * sp.binomial(m, j) * t**j * (1 - t) ** (m - j)
            * sp.Rational(int(net[i, j, k].numerator), int(net[i, j, k].denominator)) for i in range(l + 1) for j in range(m + 1))
        for k in range(2))


def test_identity_lattice_moves_nothing_and_cuts_at_the_boundary():
    result = ffd(identity_lattice(3, 2), CUBIC, outside="keep")
    assert [p.moved for p in result.pieces] == [False, True, False]
    assert all(result.joints)
    for k in range(11):
        assert result.evaluate(Fr(k, 10)) == CUBIC.evaluate(Fr(k, 10))
    # every cut lies on a boundary line: compare with mpmath roots of x(t) = 0, x(t) = 1, y(t) = 0, y(t) = 1
    mpmath.mp.dps = 40
    T = sp.Symbol("t")
    x, y = CUBIC.to_sympy(T)
    roots = []
    for eq in (x, x - 1, y, y - 1):
        coeffs = [mpmath.mpf(sp.Rational(c).p) / sp.Rational(c).q for c in sp.Poly(sp.expand(eq), T).all_coeffs()]
        roots += [mpmath.re(r) for r in mpmath.polyroots(coeffs, extraprec=100) if abs(mpmath.im(r)) < 1e-30 and 0 < mpmath.re(r) < 1]
    cuts = [p.interval[0] for p in result.pieces[1:]]
    assert len(cuts) == len(roots) == 2
    for cut in cuts:
        value = mpmath.mpf(float(cut)) if not isinstance(cut, RealAlgebraic) else None
        if value is None:
            cut.refine(Fr(1, 2**80))
            value = (mpmath.mpf(int(cut.lo.numerator)) / int(cut.lo.denominator))
        assert min(abs(value - r) for r in roots) < 1e-20


def test_inside_is_the_ffd_outside_is_the_curve_and_a_frozen_boundary_does_not_tear():
    lattice = _lattice(3, 3, {(1, 1): (Fr(1, 5), Fr(-1, 4)), (2, 2): (Fr(-1, 3), Fr(1, 7))})  # boundary frozen
    result = ffd(lattice, CUBIC, outside="keep")
    assert all(result.joints)
    moved_somewhere = False
    for k in range(21):
        t = Fr(k, 20)
        u, v = CUBIC.evaluate(t)
        got = result.evaluate(t)
        if 0 <= u <= 1 and 0 <= v <= 1:
            assert tuple(sp.Rational(int(c.numerator), int(c.denominator)) for c in got) == _sympy_ffd(lattice, (u, v))
            moved_somewhere |= tuple(got) != (u, v)
        else:
            assert tuple(got) == (u, v)
    assert moved_somewhere


def test_a_displaced_boundary_point_tears_the_curve():
    lattice = _lattice(2, 2, {(2, 1): (Fr(1, 4), 0)})  # a control point of the right edge moved
    line = BezierCurve([["-1/2", "1/2"], ["3/2", "1/2"]])  # crosses x = 0 at t = 1/4 and x = 1 at t = 3/4
    result = ffd(lattice, line, outside="keep")
    assert [p.interval[0] for p in result.pieces] == [0, Fr(1, 4), Fr(3, 4)]
    assert result.joints == [True, False]  # left edge untouched, right edge moved


@pytest.mark.parametrize("frozen,c1", [(1, False), (2, True)])
def test_continuity_control_by_freezing_rows(frozen, c1):
    """Figure 14.5: freezing the outer k rows/columns gives C^(k-1) across the boundary."""
    n = 4
    move = {(i, j): (Fr(1, 9), Fr(-1, 11)) for i in range(n + 1) for j in range(n + 1)
            if frozen <= i <= n - frozen and frozen <= j <= n - frozen}
    lattice = _lattice(n, n, move)
    line = BezierCurve([["-1/2", "1/2"], ["3/2", "1/2"]])
    result = ffd(lattice, line, outside="keep")
    assert all(result.joints)
    deformed = result.pieces[1].curve
    d_def, d_line = deformed.derivative(), line.derivative()
    same = tuple(d_def.evaluate(Fr(1, 4))) == tuple(d_line.evaluate(Fr(1, 4)))
    assert same == c1


def test_bad_input():
    with pytest.raises(InputError):
        ffd(identity_lattice(2, 2), CUBIC, outside="bogus")
    from exactcagd import BSplineCurve

    with pytest.raises(NotSupportedError):
        ffd(identity_lattice(2, 2), BSplineCurve([[0, 0], [1, 1], [2, 0]], [0, 0, 0, 1, 1, 1]), outside="keep")
    with pytest.raises(InputError):
        ffd(identity_lattice(2, 2, dimension=3), CUBIC, outside="keep")

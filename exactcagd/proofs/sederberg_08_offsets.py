"""Ledger: Sederberg's notes, chapter 8 (offset curves), checked with
:mod:`exactcagd.toolbox.offsets` and sympy's exact square roots."""

from __future__ import annotations

import itertools
from fractions import Fraction as Fr

import sympy as sp

from exactcagd import BezierCurve
from exactcagd.toolbox.offsets import offset_curve, offset_cusps, offset_point, parabola_offset
from exactcagd.proofs._ledger import claim, verified, verified_range

T = sp.Symbol("t", real=True)


def _ph_cubic(u0, u1, v0, v1) -> BezierCurve:
    """PH cubic with P' = (u^2 - v^2, 2uv), u, v linear; Bézier control points from the hodograph."""
    # hodograph Bernstein coefficients of degree 2, integrated (notes 2.7 backwards)
    h = [(u0 * u0 - v0 * v0, 2 * u0 * v0), (u0 * u1 - v0 * v1, u0 * v1 + u1 * v0), (u1 * u1 - v1 * v1, 2 * u1 * v1)]
    pts = [(Fr(0), Fr(0))]
    for hx, hy in h:
        pts.append((pts[-1][0] + Fr(hx) / 3, pts[-1][1] + Fr(hy) / 3))
    return BezierCurve([list(p) for p in pts])


@claim(doc="sederberg", section="8", ref="(8.2), (8.3)", statement="Omega(-rho, Omega(rho, P(t))) = P(t) when rho is less than the radius of curvature")
def offset_of_offset():
    count = 0
    for u0, u1, v0, v1 in itertools.product((1, 2), (-1, 3), (0, 1), (1, 2)):
        curve = _ph_cubic(u0, u1, v0, v1)
        x, y = curve.to_sympy(T)
        dx, dy = sp.diff(x, T), sp.diff(y, T)
        kappa_max = max(abs(float(((dx * sp.diff(dy, T) - dy * sp.diff(dx, T)) / (dx**2 + dy**2) ** sp.Rational(3, 2)).subs(T, sp.Rational(k, 20)))) for k in range(21))
        rho = Fr(1, 2 * int(kappa_max + 2))  # well below the minimal radius of curvature
        off = offset_curve(curve, rho)
        # independent: (8.2) twice in sympy, Omega(r, Q)(t) = Q(t) + r (-Q'_y, Q'_x)/|Q'(t)|, with exact square roots
        r = sp.Rational(rho.numerator, rho.denominator)
        omega = sp.Matrix([x - r * dy / sp.sqrt(dx**2 + dy**2), y + r * dx / sp.sqrt(dx**2 + dy**2)])
        d_omega = omega.diff(T)
        for t in (Fr(0), Fr(1, 3), Fr(1)):
            assert tuple(offset_point(off, -rho, t)) == tuple(curve.evaluate(t))
            ts = sp.Rational(t.numerator, t.denominator)
            o, do = omega.subs(T, ts), d_omega.subs(T, ts)
            back = o + r * sp.Matrix([do[1], -do[0]]) / sp.sqrt(do[0] ** 2 + do[1] ** 2)
            assert back.applyfunc(sp.nsimplify) == sp.Matrix([x.subs(T, ts), y.subs(T, ts)])
            count += 1
    return verified_range(
        "16 Pythagorean-hodograph cubics (u, v linear, integer ends), 3 parameters each",
        f"exact: the offset of a PH curve is rational with rational speed, so Omega(-rho, .) lands exactly on P ({count} checks)",
        compared="printed (8.2), (8.3) vs sympy: the offset formula applied twice (radii rho, -rho) with exact square roots "
        "gives back P(t) at t = 0, 1/3, 1; exactcagd offset_point(offset_curve(P, rho), -rho, t) equals P(t) too", reference="sympy",
    )


@claim(doc="sederberg", section="8", ref="Figure 8.2 text", statement="every point where the radius of curvature matches the offset radius creates a cusp; between cusps the derivatives of base and offset point in opposite directions")
def cusps():
    parabola = BezierCurve([[-1, 1], [0, -1], [1, 1]])  # (2t-1, (2t-1)^2), radius 1/2 at the vertex
    rho = -4
    found = offset_cusps(parabola, rho)
    x, y = parabola.to_sympy(T)
    dx, dy = sp.diff(x, T), sp.diff(y, T)
    omega = sp.Matrix([x + rho * dy / sp.sqrt(dx**2 + dy**2), y - rho * dx / sp.sqrt(dx**2 + dy**2)])
    d_omega = omega.diff(T)
    radius = (dx**2 + dy**2) ** sp.Rational(3, 2) / (dx * sp.diff(dy, T) - dy * sp.diff(dx, T))
    for t in ((2 - sp.sqrt(3)) / 4, (2 + sp.sqrt(3)) / 4):
        assert all(sp.simplify(c.subs(T, t)) == 0 for c in d_omega)  # a cusp: Omega' = 0
        assert sp.simplify(radius.subs(T, t) - abs(rho)) == 0  # where the radius of curvature equals |rho|
    mid = sp.Rational(1, 2)
    assert sp.simplify((d_omega.T * sp.Matrix([dx, dy])).subs(T, mid)[0]) < 0  # opposite directions between cusps
    assert len(found) == 2 and all(f.poly.degree() == 2 for f in found)
    return verified("parabola (2t-1, (2t-1)^2), rho = -4: cusps exactly at t = (2 -+ sqrt 3)/4 (roots of 16t^2 - 16t + 1), "
                    "Omega' = 0 there symbolically, Omega'.P' < 0 at t = 1/2",
                    compared="printed cusp claim vs sympy: at t = (2 -+ sqrt 3)/4 the radius of curvature of the parabola "
                    "equals |rho| = 4 and Omega'(t) = 0 (simplify); Omega'.P' < 0 at t = 1/2; exactcagd offset_cusps finds two "
                    "quadratic roots", reference="sympy")


@claim(doc="sederberg", section="8", ref="offsets of parabolas", statement="the offset of any parabola can be represented as a degree eight rational Bezier curve")
def parabola_degree():
    from exactcagd.algebra import implicitize

    degrees = set()
    for pts in ([[0, 0], [3, 4], [7, 1]], [[0, 0], [4, 3], [4, 8]], [[1, 1], [-2, 5], [10, 10]]):
        for rho in (Fr(1, 2), Fr(-3)):
            off = parabola_offset(BezierCurve(pts), rho)
            degrees.add((off.degree, implicitize(off).total_degree()))
    assert degrees == {(6, 6)}
    # independent: eliminate t and w (w^2 = |P'|^2) from the offset P + rho (-y', x')/w in sympy (lex Groebner basis),
    # P(t) = 2t(1-t)(3, 4) + t^2 (7, 1), the first parabola above
    t, w, X, Y = sp.symbols("t w X Y")
    rho = sp.Rational(1, 2)
    x, y = 6 * t + t**2, 8 * t - 7 * t**2
    dx, dy = sp.diff(x, t), sp.diff(y, t)
    G = sp.groebner([(X - x) * w + rho * dy, (Y - y) * w - rho * dx, w**2 - dx**2 - dy**2], t, w, X, Y, order="lex")
    implicit = [g for g in G.exprs if not g.has(t) and not g.has(w)]
    assert len(implicit) == 1 and sp.Poly(implicit[0], X, Y).total_degree() == 6
    off = parabola_offset(BezierCurve([[0, 0], [3, 4], [7, 1]]), Fr(1, 2))
    for s_ in (Fr(1, 5), Fr(1, 2), Fr(3, 4)):
        px, py = off.evaluate(s_)
        assert implicit[0].subs({X: sp.Rational(str(px)), Y: sp.Rational(str(py))}) == 0
    return verified(
        "true but not sharp: rationally parametrizing w^2 = |P'(t)|^2 gives a rational curve of degree 6, and its implicit "
        "equation has degree 6, so 6 is the minimal degree (a degree-8 form is an elevation); checked on 3 parabolas x 2 radii",
        compared="printed degree 8 vs the implicit degree of the offset (rho = 1/2) of the parabola with control points (0,0), (3,4), (7,1) by "
        "sympy elimination (lex Groebner basis of the offset equations with w^2 = |P'|^2): 6; exactcagd's degree-6 rational offset lies on that sextic at 3 "
        "parameters; exactcagd implicitize gives degree 6 for 3 parabolas x 2 radii", reference="sympy",
    )


@claim(doc="sederberg", section="8", ref="exceptions", statement="offsets of circles and straight lines are representable in Bezier form")
def circles_and_lines():
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    line = BezierCurve([[0, 0], [3, 4]])
    for t in (Fr(k, 7) for k in range(8)):
        px, py = offset_point(quarter, Fr(1, 3), t)
        assert px * px + py * py == Fr(16, 9) and all(isinstance(v, type(px)) for v in (px, py))
        lx, ly = offset_point(line, 5, t)
        assert (lx, ly) == (3 * t + 4, 4 * t - 3)
    return verified("rational quarter circle: offset points rational and on the circle of radius 4/3; line: translated by rho times the unit normal",
                    compared="printed exception vs exact expectations derived by hand: the offset points of the rational quarter circle satisfy x^2 + y^2 = (1 + 1/3)^2 and are rational; the line's offset equals (3t + 4, 4t - 3) = P(t) + 5 (4, -3)/5", reference='exact')

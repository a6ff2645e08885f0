"""Sederberg's notes, chapter 19: genus, double points, implicit curve
intersections, discriminants, parametrization of unicursal curves, undetermined
coefficients.

Independent references: sympy substitution / factorization / solve, and the
Sylvester determinant written out with sympy ``Matrix.det``.
"""

from __future__ import annotations

import random

import sympy as sp

from exactcagd import BezierCurve
from exactcagd.algebra import (
    circle_through_points,
    common_points,
    conic_through_points,
    curve_discriminant,
    double_points,
    genus,
    implicitize,
    line_section,
    parametrize_rational_cubic,
    parametrize_unicursal,
    resultant,
    singular_points,
)
from exactcagd.algebra.parametrize import translate
from exactcagd.algebra.resultants import sylvester_matrix
from exactcagd.proofs import _ledger as L
from exactcagd.proofs.sederberg_17_resultants import _sylvester_sympy
from exactcagd.proofs._ledger import claim, erratum, reconstructed, verified, verified_range

DOC = "sederberg"
x, y, t, a, b, c = sp.symbols("x y t a b c")


def _sylvester_res(f, g, var):
    """Res_var(f, g) = det of Sylvester's matrix written out in sympy (not sympy.resultant: wrong sign in odd/odd cases)."""
    fa = sp.Poly(f, var).all_coeffs()[::-1]
    ga = sp.Poly(g, var).all_coeffs()[::-1]
    S = _sylvester_sympy(fa, ga)
    assert S == sp.Matrix(sylvester_matrix(fa, ga))  # exactcagd's matrix is the same
    return sp.expand(S.det())


def _node_kind(f, px, py):
    """Kind of a double point from the definitions: f = f_x = f_y = 0, Hessian determinant < 0 crunode, > 0 acnode, 0 cusp."""
    at = {x: px, y: py}
    assert all(sp.expand(e.subs(at)) == 0 for e in (f, sp.diff(f, x), sp.diff(f, y)))
    H = sp.hessian(f, (x, y)).subs(at)
    assert H != sp.zeros(2, 2)  # a double point, not a triple point
    d = H.det()
    return "crunode" if d < 0 else "acnode" if d > 0 else "cusp"


def _genus_sympy(f):
    """(n-1)(n-2)/2 - sum m(m-1)/2 over the projective singular points, all checked ordinary (sympy, from the definitions).

    Singular points: common zeros of F, F_x, F_y, F_z of the homogenized F in the charts z = 1, (x : 1 : 0), (1 : 0 : 0);
    each is translated to the origin of an affine chart, its multiplicity m is the lowest degree present and its tangent
    cone (the lowest form) must be square-free (m distinct tangents), so that it counts m(m-1)/2 double points.
    """
    z = sp.Symbol("z")
    n = sp.Poly(f, x, y).total_degree()
    F = sp.expand(sp.Poly(f, x, y).homogenize(z).as_expr())
    grads = [sp.diff(F, v) for v in (x, y, z)]
    points = [(px, py, 1) for px, py in ((d[x], d[y]) for d in sp.solve([F.subs(z, 1)] + [g.subs(z, 1) for g in grads], [x, y], dict=True))]
    points += [(d[x], 1, 0) for d in sp.solve([F.subs({y: 1, z: 0})] + [g.subs({y: 1, z: 0}) for g in grads], [x], dict=True)]
    if all(sp.expand(e.subs({x: 1, y: 0, z: 0})) == 0 for e in [F] + grads):
        points.append((1, 0, 0))
    delta = 0
    for pt in points:
        chart = next(k for k in range(3) if pt[k] != 0)  # dehomogenize where the point's coordinate is 1 (after scaling)
        scaled = [sp.nsimplify(c / pt[chart]) for c in pt]
        others = [v for k, v in enumerate((x, y, z)) if k != chart]
        u1, u2 = sp.symbols("u1 u2")
        sub = {(x, y, z)[chart]: 1}
        sub.update({others[0]: u1 + scaled[(x, y, z).index(others[0])], others[1]: u2 + scaled[(x, y, z).index(others[1])]})
        g = sp.Poly(sp.expand(F.subs(sub, simultaneous=True)), u1, u2)
        m = min(sum(mono) for mono in g.monoms())
        cone = sum(c * u1**i * u2**j for (i, j), c in g.terms() if i + j == m)
        assert all(k == 1 for _, k in sp.sqf_list(cone)[1]), f"non-ordinary singular point {pt}"
        delta += m * (m - 1) // 2
    return sp.Rational((n - 1) * (n - 2), 2) - delta


def _parameter_pairs(curve):
    """Double points from first principles (sympy): the ordered parameter pairs s != t with P(s) ~ P(t).

    G = (P(s) x P(t)) / (s - t) (homogeneous Bernstein forms); the number of its common zeros, with multiplicity, is the
    number of standard monomials of a grevlex Gröbner basis. Returns (that number, whether none lies on s = t: no cusp).
    Each double point (ordinary node) gives the two pairs (s, t), (t, s).
    """
    s_, t_ = sp.symbols("s_ t_")
    H = curve.homogeneous()
    n = curve.degree
    hom = lambda v: sp.Matrix([sp.expand(sum(sp.Rational(str(H[i, k])) * sp.binomial(n, i) * v**i * (1 - v) ** (n - i)  # noqa: E731
                                             for i in range(n + 1))) for k in range(3)])
    G = [sp.cancel(e / (s_ - t_)) for e in hom(s_).cross(hom(t_))]
    GB = sp.groebner(G, s_, t_, order="grevlex")
    lead = [sp.Poly(g, s_, t_).monoms(order="grevlex")[0] for g in GB.exprs]
    bs = min(a for a, b in lead if b == 0)
    bt = min(b for a, b in lead if a == 0)
    count = sum(1 for a in range(bs) for b in range(bt) if not any(a >= la and b >= lb for la, lb in lead))
    diagonal_free = list(sp.groebner(G + [s_ - t_], s_, t_, order="grevlex").exprs) == [1]
    return count, diagonal_free


# ---------------------------------------------------------------- 19.1
@claim(DOC, "19.1", "genus formula", "g = (n-1)(n-2)/2 - d; lines and conics have genus 0; a rational cubic needs one double point")
def genus_formula():
    assert genus(2 * x - 3 * y + 1) == 0 and genus(x**2 + 3 * y**2 - 5) == 0
    assert genus(x**3 + 9 * x**2 - 12 * y**2) == 0  # one crunode
    assert genus(y**2 - x**3 - x - 1) == 1  # smooth cubic
    assert genus((x**2 + y**2) ** 2 + 3 * x**2 * y - y**3) == 0  # ordinary triple point: delta = 3
    examples = {2 * x - 3 * y + 1: 0, x**2 + 3 * y**2 - 5: 0, x**3 + 9 * x**2 - 12 * y**2: 0, y**2 - x**3 - x - 1: 1,
                (x**2 + y**2) ** 2 + 3 * x**2 * y - y**3: 0}
    assert all(_genus_sympy(f) == g_ == genus(f) for f, g_ in examples.items())
    return verified("line, ellipse, nodal cubic: 0; smooth cubic: 1; quartic with an ordinary triple point: 0",
        compared="printed g = (n-1)(n-2)/2 - d vs the genus computed in sympy from the definitions (projective singular points, each ordinary, m(m-1)/2 double points) for a line, an ellipse, the nodal cubic, a smooth cubic and the quartic with a triple point; exactcagd's genus agrees",
        reference='sympy')


@claim(DOC, "19.1", "maximal double points", "a rational curve of degree n has (n-1)(n-2)/2 double points (the most an irreducible curve can have)")
def rational_double_point_count():
    r = random.Random(191)
    out = []
    for n in range(3, 7):
        cur = BezierCurve([[r.randint(-9, 9), r.randint(-9, 9)] for _ in range(n + 1)], [r.randint(1, 4) for _ in range(n + 1)])
        total = sum(d.count for d in double_points(cur))
        assert total == (n - 1) * (n - 2) // 2
        pairs, no_cusp = _parameter_pairs(cur)  # independent: ordered parameter pairs with P(s) ~ P(t) (sympy Gröbner)
        assert no_cusp and pairs == 2 * total
        out.append((n, total))
    return verified_range("random rational curves n = 3..6", f"(n, double points over C) = {out}",
        compared="printed (n-1)(n-2)/2 double points vs the number of ordered parameter pairs s != t with P(s) ~ P(t), counted from first principles (sympy Groebner basis of (P(s) x P(t))/(s - t), standard monomials; none on s = t) = 2 delta; exactcagd's double_points agrees",
        reference='sympy')


@claim(DOC, "19.1", "reducible", "xy + x + y + 1 = (x + 1)(y + 1) with a double point at (-1, -1); (x^2 + y^2 - 1)(x^2 + y^2 - 4) is reducible")
def reducible_examples():
    assert sp.factor(x * y + x + y + 1) == (x + 1) * (y + 1)
    sps = singular_points(x * y + x + y + 1, include_infinity=False)
    assert [(str(p.point[0]), str(p.point[1]), p.kind) for p in sps] == [("-1", "-1", "crunode")]
    assert _node_kind(x * y + x + y + 1, -1, -1) == "crunode"
    assert len(sp.factor_list((x**2 + y**2 - 1) * (x**2 + y**2 - 4))[1]) == 2
    return verified("factorizations; the intersection point of the two lines is a crunode",
        compared='printed factorizations vs sympy factor / factor_list; the double point (-1, -1) vs f = f_x = f_y = 0 and a negative Hessian determinant (crunode) in sympy',
        reference='sympy')


# ---------------------------------------------------------------- 19.2
@claim(DOC, "19.2", "line test", "x^3 - 2xy^2 + xy + 3y^2: x = at, y = bt gives (a^3 - 2ab^2) t^3 + (ab + 3b^2) t^2: double point; tangents a = 1, b = 0 and a = -3, b = 1: crunode")
def line_test():
    f = x**3 - 2 * x * y**2 + x * y + 3 * y**2
    sec = sp.expand(f.subs({x: a * t, y: b * t}, simultaneous=True))
    assert sp.expand(sec - ((a**3 - 2 * a * b**2) * t**3 + (a * b + 3 * b**2) * t**2)) == 0
    _, mult, cone = line_section(f)
    assert mult == 2 and sp.expand(cone - (a * b + 3 * b**2)) == 0
    assert cone.subs({a: 1, b: 0}) == 0 and cone.subs({a: -3, b: 1}) == 0
    assert [p.kind for p in singular_points(f, include_infinity=False)] == ["crunode"]
    assert _node_kind(f, 0, 0) == "crunode"
    return verified("section polynomial, multiplicity 2, two real tangent directions",
        compared='printed section polynomial and tangent directions vs sympy substitution x = at, y = bt; crunode vs f = f_x = f_y = 0 and a negative Hessian determinant at the origin',
        reference='sympy')


@claim(DOC, "19.2", "crunode example", "x^3 + 9x^2 - 12y^2 = 0 is the Bézier curve (3,3), (-13,-15), (-13,15), (3,-3)")
def crunode_bezier():
    cur = BezierCurve([[3, 3], [-13, -15], [-13, 15], [3, -3]])
    X, Y = [sp.expand(e) for e in cur.to_sympy(t)]
    assert sp.expand((x**3 + 9 * x**2 - 12 * y**2).subs({x: X, y: Y}, simultaneous=True)) == 0
    assert implicitize(cur).as_expr() == x**3 + 9 * x**2 - 12 * y**2
    kinds = [(p.kind, str(p.point[0]), str(p.point[1])) for p in singular_points(x**3 + 9 * x**2 - 12 * y**2, include_infinity=False)]
    assert kinds == [("crunode", "0", "0")]
    assert _node_kind(x**3 + 9 * x**2 - 12 * y**2, 0, 0) == "crunode"
    return verified("substitution (sympy) and implicitize(); crunode at the origin",
        compared='printed x^3 + 9x^2 - 12y^2 vs sympy substitution of the Bernstein parametrization; crunode vs a negative Hessian determinant at the singular origin (sympy)',
        reference='sympy')


@claim(DOC, "19.2", "cusp, acnode", "x^3 - 3y^2 has a cusp (identical tangents), x^3 - 3x^2 - 3y^2 an acnode (complex tangents) at the origin")
def cusp_acnode():
    _, m1, cone1 = line_section(x**3 - 3 * y**2)
    _, m2, cone2 = line_section(x**3 - 3 * x**2 - 3 * y**2)
    assert m1 == m2 == 2
    assert sp.discriminant(sp.expand(cone1.subs(b, 1)), a) == 0 or sp.Poly(cone1, a).degree() < 2
    assert sp.discriminant(sp.expand(cone2.subs(b, 1)), a) < 0
    assert [p.kind for p in singular_points(x**3 - 3 * y**2, False)] == ["cusp"]
    assert [p.kind for p in singular_points(x**3 - 3 * x**2 - 3 * y**2, False)] == ["acnode"]
    assert _node_kind(x**3 - 3 * y**2, 0, 0) == "cusp" and _node_kind(x**3 - 3 * x**2 - 3 * y**2, 0, 0) == "acnode"
    return verified("tangent cones -3b^2 (double line) and -3a^2 - 3b^2 (no real line)",
        compared='printed cusp / acnode vs the Hessian determinant at the singular origin in sympy (0: double tangent line, > 0: complex tangents)',
        reference='sympy')


# ---------------------------------------------------------------- 19.3
_CIRCLE = 6 * x**2 + 6 * y**2 - 2 * x - 15 * y - 4
_HYPER = x**2 - y**2 - 1


@claim(DOC, "19.3", "resultants", "x-resultant 144y^4 - 360y^3 + 269y^2 - 60y (roots 0, 4/3, 3/4, 5/12); y-resultant 144x^4 - 48x^3 - 461x^2 + 40x + 325 (roots 1, 5/3, -5/4, -13/12)")
def implicit_intersection_resultants():
    rx = _sylvester_res(_CIRCLE, _HYPER, x)
    ry = _sylvester_res(_CIRCLE, _HYPER, y)
    assert rx == 144 * y**4 - 360 * y**3 + 269 * y**2 - 60 * y
    assert ry == 144 * x**4 - 48 * x**3 - 461 * x**2 + 40 * x + 325
    assert set(sp.roots(rx, y)) == {0, sp.Rational(4, 3), sp.Rational(3, 4), sp.Rational(5, 12)}
    assert set(sp.roots(ry, x)) == {1, sp.Rational(5, 3), sp.Rational(-5, 4), sp.Rational(-13, 12)}
    assert resultant(_CIRCLE, _HYPER, x) == rx
    pts = [(str(p), str(q)) for p, q in common_points([_CIRCLE, _HYPER])]
    assert pts == [("-5/4", "3/4"), ("-13/12", "5/12"), ("1", "0"), ("5/3", "4/3")]
    assert all(e.subs({x: sp.Rational(p), y: sp.Rational(q)}) == 0 for p, q in pts for e in (_CIRCLE, _HYPER))
    return verified("Sylvester determinants (sympy) as printed; the four points paired exactly",
        compared='printed x- and y-resultants and their roots vs determinants of Sylvester matrices written out in sympy and sympy.roots; the four paired points vs substitution into both curves',
        reference='sympy')


@claim(DOC, "19.3", "Euclid pairing", "x = 5/3: circle gives 16/6 - y^2 = 0, hyperbola 6y^2 - 15y + 28/3 = 0; gcd 3y - 4: point (5/3, 4/3)")
def euclid_pairing():
    xv = sp.Rational(5, 3)
    h = sp.expand(_HYPER.subs(x, xv))
    cc = sp.expand(_CIRCLE.subs(x, xv))
    assert sp.expand(h - (sp.Rational(16, 9) - y**2)) == 0
    assert sp.expand(cc - (6 * y**2 - 15 * y + sp.Rational(28, 3))) == 0
    assert sp.gcd(h, cc) == y - sp.Rational(4, 3) or sp.expand(sp.gcd(h, cc) * 3 - (3 * y - 4)) == 0
    def substitutions(pair):
        hyper_, circle_ = pair
        return None if sp.expand(h - hyper_) == 0 and sp.expand(cc - circle_) == 0 else f"at x = 5/3 the hyperbola gives {h}, the circle {cc}"
    return erratum(
        "circle -> 16/6 - y^2; hyperbola -> 6y^2 - 15y + 28/3",
        "hyperbola -> 16/9 - y^2; circle -> 6y^2 - 15y + 28/3",
        "the two curves are swapped and 16/6 should be 16/9 (25/9 - 1); the gcd 3y - 4 and the point (5/3, 4/3) are right",
        printed_form=(6 * y**2 - 15 * y + sp.Rational(28, 3), sp.Rational(16, 6) - y**2), corrected_form=(sp.Rational(16, 9) - y**2, 6 * y**2 - 15 * y + sp.Rational(28, 3)), check=L.predicate(substitutions),
    )


# ---------------------------------------------------------------- 19.4
@claim(DOC, "19.4", "quadratic discriminant", "Res(at^2 + bt + c, 2at + b) = a^2 (b^2 - 4ac)")
def quadratic_discriminant():
    R = _sylvester_res(a * t**2 + b * t + c, 2 * a * t + b, t)
    assert sp.expand(R - (-a * (b**2 - 4 * a * c))) == 0
    assert sp.expand(R - a**2 * (b**2 - 4 * a * c)) != 0
    return erratum("a^2 (b^2 - 4ac)", "-a (b^2 - 4ac)", "3 x 3 Sylvester determinant (sympy); it vanishes (a != 0) iff b^2 - 4ac = 0, as the notes conclude",
        printed_form=a**2 * (b**2 - 4 * a * c), corrected_form=-a * (b**2 - 4 * a * c), check=L.same_expr(R),
    )


@claim(DOC, "19.4", "curve discriminant", "Res_y(f, f_y) has roots at the x of vertical tangents and double points")
def curve_discriminant_claim():
    D = sp.factor(curve_discriminant(x**2 + y**2 - 1))
    assert set(sp.roots(sp.Poly(D, x))) == {1, -1}
    assert set(sp.roots(sp.Poly(_sylvester_res(x**2 + y**2 - 1, 2 * y, y), x))) == {1, -1}
    f = x**3 + 9 * x**2 - 12 * y**2  # crunode at 0, vertical tangent at x = -9
    D2 = sp.Poly(curve_discriminant(f), x)
    assert set(sp.roots(D2)) == {0, -9}
    assert set(sp.roots(sp.Poly(_sylvester_res(f, sp.diff(f, y), y), x))) == {0, -9}
    return verified("unit circle: x = +-1; nodal cubic: x = 0 (double point) and x = -9 (vertical tangent)",
        compared='printed roots of Res_y(f, f_y) (vertical tangents, double points) vs the Sylvester determinant written out in sympy and sympy.roots, unit circle and nodal cubic',
        reference='sympy')


# ---------------------------------------------------------------- 19.5
@claim(DOC, "19.5", "circle", "x^2 - 2x + y^2 = 0, a unit circle centred at (0, 1): y = tx gives x = 2/(1 + t^2), y = 2t/(1 + t^2)")
def parametrize_circle():
    f = x**2 - 2 * x + y**2
    assert sp.expand(f - ((x - 1) ** 2 + y**2 - 1)) == 0
    X, Y = parametrize_unicursal(f, (0, 0))
    assert sp.simplify(X - 2 / (1 + t**2)) == 0 and sp.simplify(Y - 2 * t / (1 + t**2)) == 0
    assert sp.simplify(f.subs({x: X, y: Y}, simultaneous=True)) == 0
    def centre(pt):
        return L.same_expr(sp.expand(f))(sp.expand((x - pt[0]) ** 2 + (y - pt[1]) ** 2 - 1))
    return erratum("centered at (0, 1)", "centered at (1, 0)", "x^2 - 2x + y^2 = (x - 1)^2 + y^2 - 1; the parametrization is right",
        printed_form=(0, 1), corrected_form=(1, 0), check=L.predicate(centre),
    )


@claim(DOC, "19.5", "cubic through origin", "(x^3 + 2x^2y + 3xy^2 + 4y^3) + (5x^2 + 6xy + 7y^2): x = -(5 + 6t + 7t^2)/(1 + 2t + 3t^2 + 4t^3), y = tx")
def parametrize_cubic_origin():
    f = (x**3 + 2 * x**2 * y + 3 * x * y**2 + 4 * y**3) + (5 * x**2 + 6 * x * y + 7 * y**2)
    X, Y = parametrize_unicursal(f, (0, 0))
    pX = -(5 + 6 * t + 7 * t**2) / (1 + 2 * t + 3 * t**2 + 4 * t**3)
    assert sp.simplify(X - pX) == 0 and sp.simplify(Y - t * pX) == 0
    assert sp.simplify(f.subs({x: pX, y: t * pX}, simultaneous=True)) == 0
    return verified("as printed; vanishes identically (sympy)",
        compared='printed x(t), y = t x(t) vs sympy substitution into the cubic (vanishes identically)',
        reference='sympy')


_F195 = -21 + 46 * x - 13 * x**2 + x**3 + 25 * y - 23 * x * y + 3 * x**2 * y - 9 * y**2 + 3 * x * y**2 + y**3


@claim(DOC, "19.5", "double point", "f_x, f_y as printed; Res_y(f_x, f_y) = 174 - 159x + 36x^2; Res_x = 297 - 207y + 36y^2; the double point is (2, 3)")
def double_point_by_resultants():
    fx, fy = sp.diff(_F195, x), sp.diff(_F195, y)
    assert sp.expand(fx - (46 - 26 * x + 3 * x**2 - 23 * y + 6 * x * y + 3 * y**2)) == 0
    assert sp.expand(fy - (25 - 23 * x + 3 * x**2 - 18 * y + 6 * x * y + 3 * y**2)) == 0
    assert _sylvester_res(fx, fy, y) == 174 - 159 * x + 36 * x**2
    assert _sylvester_res(fx, fy, x) == 297 - 207 * y + 36 * y**2
    sols = [s_ for s_ in sp.solve([_F195, fx, fy], [x, y], dict=True)]
    assert sols == [{x: 2, y: 3}]
    sps = singular_points(_F195)
    assert [(p.kind, str(p.point[0]), str(p.point[1])) for p in sps] == [("crunode", "2", "3")]
    return verified("partials, both resultants (Sylvester, sympy) and the unique solution (2, 3)",
        compared='printed partials, Res_y = 174 - 159x + 36x^2, Res_x = 297 - 207y + 36y^2 and the point (2, 3) vs sympy diff, Sylvester determinants written out in sympy and sympy.solve of f = f_x = f_y = 0',
        reference='sympy')


@claim(DOC, "19.5", "translation and parametrization", "substitution x = t + 2, y = t + 3 gives 2x^2 + x^3 + 7xy + 3x^2y + 6y^2 + 3xy^2 + y^3; x = (2t^3 - t)/(t+1)^3, y = (-3t^3 + 2t^2 + 7t + 3)/(t+1)^3")
def translate_and_parametrize():
    g = sp.expand(_F195.subs({x: x + 2, y: y + 3}, simultaneous=True))
    assert g == 2 * x**2 + x**3 + 7 * x * y + 3 * x**2 * y + 6 * y**2 + 3 * x * y**2 + y**3 == translate(_F195, (2, 3))
    X0 = -(6 * t**2 + 7 * t + 2) / (t**3 + 3 * t**2 + 3 * t + 1)
    assert sp.simplify(g.subs({x: X0, y: t * X0}, simultaneous=True)) == 0
    X, Y = (2 * t**3 - t) / (t**3 + 3 * t**2 + 3 * t + 1), (-3 * t**3 + 2 * t**2 + 7 * t + 3) / (t**3 + 3 * t**2 + 3 * t + 1)
    assert sp.simplify(X - (X0 + 2)) == 0 and sp.simplify(Y - (t * X0 + 3)) == 0
    assert sp.simplify(_F195.subs({x: X, y: Y}, simultaneous=True)) == 0
    (PX, PY), point = parametrize_rational_cubic(_F195)
    assert point == (2, 3) and sp.simplify(PX - X) == 0 and sp.simplify(PY - Y) == 0
    def gives_printed_g(subs_):
        return L.same_expr(g)(sp.expand(_F195.subs(subs_, simultaneous=True)))
    return reconstructed(
        "making the substitution x = t + 2, y = t + 3",
        "making the substitution x -> x + 2, y -> y + 3",
        "with the corrected substitution every printed polynomial and the final parametrization are exact (sympy)",
        printed_form={x: t + 2, y: t + 3}, corrected_form={x: x + 2, y: y + 3}, check=L.predicate(gives_printed_g),
    )


# ---------------------------------------------------------------- 19.6
@claim(DOC, "19.6", "undetermined coefficients", "(n^2 + 3n)/2 free coefficients; the conic through five points from the 5 x 6 system; the circle through three points: a = A/2, b = B/2, r = sqrt(C + a^2 + b^2)")
def undetermined():
    for n in range(1, 7):
        assert (n + 1) * (n + 2) // 2 - 1 == (n * n + 3 * n) // 2
    pts = [(1, 0), (0, 1), (-1, 0), (0, -1), (3, 5)]
    C = conic_through_points(pts).as_expr()
    assert all(C.subs({x: p[0], y: p[1]}) == 0 for p in pts) and sp.Poly(C, x, y).total_degree() == 2
    (ca, cb), r2 = circle_through_points((0, 0), (4, 0), (0, 2))
    A, B, Cc = sp.symbols("A B C")
    sol = sp.solve([A * px + B * py + Cc - (px**2 + py**2) for px, py in ((0, 0), (4, 0), (0, 2))], [A, B, Cc])
    assert (ca, cb) == (sol[A] / 2, sol[B] / 2) and r2 == sol[Cc] + ca**2 + cb**2
    assert all((px - ca) ** 2 + (py - cb) ** 2 == r2 for px, py in ((0, 0), (4, 0), (0, 2)))
    return verified("counting identity n = 1..6; a conic through 5 points; circle through 3 points (centre (2, 1), r^2 = 5)",
        compared='printed count (n^2 + 3n)/2 vs C(n+2, 2) - 1; the conic through five points vs substitution (a non-zero conic); the circle a = A/2, b = B/2, r^2 = C + a^2 + b^2 vs sympy.solve of the linear system and the distances to the three points',
        reference='sympy')

"""Ledger: Sederberg's notes, chapter 1 (vectors, rotation about an axis, lines, conics).

Every worked example of the chapter is recomputed with :mod:`exactcagd.toolbox.basics`
and every general formula is checked symbolically with sympy.
"""

from __future__ import annotations

import itertools

import sympy as sp
from gmpy2 import mpq

from exactcagd.toolbox import basics as b
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified, verified_range


def _R(x):
    return x.to_sympy() if hasattr(x, "to_sympy") else sp.Rational(int(x.numerator), int(x.denominator))


@claim(doc="sederberg", section="1.2", ref="(1.2), (1.3)", statement="P1.P2 = x1x2 + y1y2 + z1z2; P1 x P2 = (y1z2 - y2z1, x2z1 - x1z2, x1y2 - x2y1)")
def dot_and_cross():
    u, v = sp.Matrix(sp.symbols("x1 y1 z1")), sp.Matrix(sp.symbols("x2 y2 z2"))
    x1, y1, z1 = u
    x2, y2, z2 = v
    assert u.cross(v) == sp.Matrix([y1 * z2 - y2 * z1, x2 * z1 - x1 * z2, x1 * y2 - x2 * y1])
    assert b.cross((1, 2, 3), (4, 5, 6)) == (-3, 6, -3) and b.dot((1, 2, 3), (4, 5, 6)) == 32
    return verified("sympy cross product equals (1.3) componentwise; exact dot/cross on a sample",
        compared="printed (1.3) components vs sympy's Matrix.cross on symbolic vectors; exactcagd dot/cross on one sample vs hand values",
        reference='sympy',
    )


@claim(doc="sederberg", section="1.2", ref="Example (angle)", statement="angle between (1,2,4) and (3,-4,2): cos^-1(3/(sqrt21 sqrt29)) ~ 83.02 deg")
def angle_example():
    c = b.cos_angle((1, 2, 4), (3, -4, 2))
    assert sp.simplify(_R(c) - 3 / (sp.sqrt(21) * sp.sqrt(29))) == 0
    deg = float(b.angle((1, 2, 4), (3, -4, 2)).evalf(30)) * 180 / float(sp.pi.evalf(30))
    assert abs(deg - 83.02) < 0.005
    assert b.length_squared((-3, -4, 2)) == b.length_squared((3, -4, 2))
    def denominator_norms(w):
        ref = sp.sqrt(21) * sp.sqrt(29)  # |(1,2,4)| |(3,-4,2)| of the example's vectors
        got = sp.sqrt(sum(x * x for x in (1, 2, 4))) * sp.sqrt(sum(x * x for x in w))
        return None if tuple(w) == (3, -4, 2) and got == ref else f"vector {w} is not the example's (3,-4,2) (its norm is sqrt{sum(x * x for x in w)})"
    return erratum(
        printed="|(1,2,4)||(-3,-4,2)| in the denominator",
        corrected="|(1,2,4)||(3,-4,2)|",
        detail=f"typo in the sign of one component; both norms are sqrt(29), so the result 3/(sqrt21 sqrt29) = {c} "
        f"and theta = {deg:.4f} deg hold exactly",
        printed_form=(-3, -4, 2), corrected_form=(3, -4, 2), check=L.predicate(denominator_norms), reference='text',
    )


@claim(doc="sederberg", section="1.2", ref="Example (projection)", statement="projection of (3,2,1) onto (3,6,6) is 27/81 (3,6,6) = (1,2,2)")
def projection_example():
    P, Q = sp.Matrix([3, 2, 1]), sp.Matrix([3, 6, 6])
    assert P.dot(Q) == 27 and Q.dot(Q) == 81 and P.dot(Q) / Q.dot(Q) * Q == sp.Matrix([1, 2, 2])  # sympy, as printed
    assert tuple(_R(x) for x in b.project((3, 2, 1), (3, 6, 6))) == (1, 2, 2)
    return verified("exact projection (P.Q / Q.Q) Q",
        compared="printed 27/81 (3,6,6) = (1,2,2) vs sympy: P.Q, Q.Q and (P.Q / Q.Q) Q of the printed vectors; exactcagd's project() on the same",
        reference='sympy',
    )


@claim(doc="sederberg", section="1.2", ref="(1.4) Example", statement="triangle (1,1,1),(2,4,5),(3,2,6): (1,3,4)x(2,1,5) = (11,3,-5), Area = sqrt(155)/2 ~ 6.225")
def triangle_example():
    p1, p2, p3 = (sp.Matrix(p) for p in ((1, 1, 1), (2, 4, 5), (3, 2, 6)))
    # sympy, from the printed vertices
    assert p2 - p1 == sp.Matrix([1, 3, 4]) and p3 - p1 == sp.Matrix([2, 1, 5])
    normal = (p2 - p1).cross(p3 - p1)
    assert normal == sp.Matrix([11, 3, -5]) and sp.sqrt(normal.dot(normal)) / 2 == sp.sqrt(155) / 2
    area = b.triangle_area((1, 1, 1), (2, 4, 5), (3, 2, 6))
    assert sp.simplify(_R(area) - sp.sqrt(155) / 2) == 0 and abs(float(area) - 6.225) < 5e-4
    return verified(f"exact area {area} = {float(area):.6f}",
        compared="printed (1,3,4) x (2,1,5) = (11,3,-5) and Area = sqrt(155)/2 ~ 6.225 vs sympy Matrix differences, cross product and sqrt(n.n)/2 of the printed vertices; exactcagd's triangle_area on the same",
        reference='sympy',
    )


@claim(doc="sederberg", section="1.1", ref="Heron's formula", statement="Area = sqrt(s(s-l1)(s-l2)(s-l3)), s = (l1+l2+l3)/2")
def heron_formula():
    l1, l2, l3 = sp.symbols("l1 l2 l3", positive=True)
    s = (l1 + l2 + l3) / 2
    heron2 = sp.expand(s * (s - l1) * (s - l2) * (s - l3))
    squared_form = (4 * l1**2 * l2**2 - (l1**2 + l2**2 - l3**2) ** 2) / 16
    assert sp.expand(heron2 - squared_form) == 0
    # and against the cross-product area (1.4) on the example triangle
    sq = [b.length_squared(b.relative(x, y)) for x, y in (((2, 4, 5), (1, 1, 1)), ((3, 2, 6), (2, 4, 5)), ((1, 1, 1), (3, 2, 6)))]
    assert b.heron_area_squared(*sq) == b.triangle_area_squared((1, 1, 1), (2, 4, 5), (3, 2, 6)) == mpq(155, 4)
    return verified("Heron's product expands to (4 a^2 b^2 - (a^2 + b^2 - c^2)^2)/16; equals (1.4) on the example",
        compared='printed Heron formula vs sympy expansion against (4 a^2 b^2 - (a^2 + b^2 - c^2)^2)/16; on the example triangle Heron equals the cross-product area (1.4) = 155/4 (squared)',
        reference='sympy',
    )


def _trace_rotation():
    from exactcagd.exact.scalars import rational_str

    def fmt(v):
        return "(" + ", ".join(rational_str(x) for x in v) + ")"

    p, base, d = (5, 7, 3), (1, 1, 1), (2, 1, 2)
    n = tuple(x / 3 for x in b.vec(d))
    print("n =", fmt(n))
    k = b.dot(b.relative(p, base), n)
    C = tuple(bi + k * ni for bi, ni in zip(b.vec(base), n))
    print("C = B + [(P - B).n] n =", fmt(C))
    u = b.relative(p, C)
    print("u = P - C =", fmt(u))
    v = b.cross(n, u)
    print("v = n x u =", fmt(v))
    print("r = u cos 90 + v sin 90 = v;  P' = C + r =", fmt(b.rotate_about_axis(p, base, d, 0, 1)))


@claim(doc="sederberg", section="1.3", ref="Example (1.10)", statement="rotate (5,7,3) by 90 deg about axis (2,1,2) through (1,1,1): C = (5,3,5), u = (0,4,-2), v = (-10/3,4/3,8/3), r = v",
       trace=_trace_rotation)
def rotation_example():
    # the printed intermediates, recomputed in sympy from (1.6)-(1.10)
    P, B, n = sp.Matrix([5, 7, 3]), sp.Matrix([1, 1, 1]), sp.Matrix([2, 1, 2]) / 3
    assert (P - B).dot(n) == 6
    C = B + (P - B).dot(n) * n
    assert C == sp.Matrix([5, 3, 5])
    u = P - C
    assert u == sp.Matrix([0, 4, -2])
    v = n.cross(u)
    assert v == sp.Matrix([sp.Rational(-10, 3), sp.Rational(4, 3), sp.Rational(8, 3)])
    # independent reference for the result: Rodrigues' rotation matrix cos I + sin [n]_x + (1 - cos) n n^T at 90 deg
    K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    rodrigues = B + (K + n * n.T) * (P - B)
    assert rodrigues == C + v == sp.Matrix([sp.Rational(5, 3), sp.Rational(13, 3), sp.Rational(23, 3)])
    result = b.rotate_about_axis((5, 7, 3), (1, 1, 1), (2, 1, 2), 0, 1)
    assert sp.Matrix([_R(x) for x in result]) == rodrigues
    return verified(f"all printed intermediates reproduced; P' = C + r = {tuple(str(x) for x in result)} (not printed), equal to the sympy rotation",
        compared="printed C = (5,3,5), u = (0,4,-2), v = (-10/3,4/3,8/3) vs sympy evaluation of (1.6)-(1.10); the rotated point C + v vs Rodrigues' rotation matrix (sympy) at 90 deg; exactcagd's rotate_about_axis on the same",
        reference='sympy',
    )


@claim(doc="sederberg", section="1.3", ref="after (1.8)", statement="Then, r is computed using equation (3.1)")
def rotation_cross_reference():
    # (1.5) is r = u cos + v sin; equation (3.1) of the notes is Horner's rule
    u, v = sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0])
    th = sp.Symbol("theta")
    r = u * sp.cos(th) + v * sp.sin(th)
    assert sp.simplify(r.dot(r)) == 1 and sp.simplify(r.dot(u) - sp.cos(th)) == 0
    EQS = {"(3.1)": "Horner's rule", "(1.5)": "r = u cos(theta) + v sin(theta)"}

    def is_rotation_equation(tag):
        return None if "cos" in EQS[tag] else f"equation {tag} is {EQS[tag]}"
    return erratum(printed="equation (3.1)", corrected="equation (1.5): r = u cos(theta) + v sin(theta)",
                   detail="(3.1) in chapter 3 is Horner's algorithm; the rotation step is (1.5), checked: |r| = |u|, r.u = cos theta",
        printed_form='(3.1)', corrected_form='(1.5)', check=L.predicate(is_rotation_equation), reference='text',
    )


@claim(doc="sederberg", section="1.3.1", ref="(1.11)-(1.27)", statement="4x4 matrix M of the rotation about an arbitrary axis, with T1, T2, T3")
def rotation_matrix_form():
    x, y, z, Bx, By, Bz, cth, sth = sp.symbols("x y z B_x B_y B_z cos_theta sin_theta", real=True)
    a, c_ = sp.symbols("alpha beta", real=True)
    # a unit vector n, parametrized rationally by the inverse stereographic projection
    den = 1 + a**2 + c_**2
    nx, ny, nz = 2 * a / den, 2 * c_ / den, (1 - a**2 - c_**2) / den
    n = sp.Matrix([nx, ny, nz])
    P, B = sp.Matrix([x, y, z]), sp.Matrix([Bx, By, Bz])
    C = B + (P - B).dot(n) * n
    u = P - C
    v = n.cross(u)
    vec_form = C + u * cth + v * sth  # cos, sin enter linearly: independent symbols suffice
    Bn = B.dot(n)
    M = sp.Matrix([
        [nx**2 + (ny**2 + nz**2) * cth, nx * ny * (1 - cth) - nz * sth, nx * nz * (1 - cth) + ny * sth, (Bx - Bn * nx) * (1 - cth) + (nz * By - ny * Bz) * sth],
        [nx * ny * (1 - cth) + nz * sth, ny**2 + (nx**2 + nz**2) * cth, ny * nz * (1 - cth) - nx * sth, (By - Bn * ny) * (1 - cth) + (nx * Bz - nz * Bx) * sth],
        [nx * nz * (1 - cth) - ny * sth, ny * nz * (1 - cth) + nx * sth, nz**2 + (nx**2 + ny**2) * cth, (Bz - Bn * nz) * (1 - cth) + (ny * Bx - nx * By) * sth],
    ])
    mat_form = M * sp.Matrix([x, y, z, 1])
    assert all(sp.cancel(e) == 0 for e in (mat_form - vec_form))
    # (1.16): u_x = x(1 - nx^2) - y nx ny - z nx nz + (B.n) nx - B_x
    assert sp.cancel(u[0] - (x * (1 - nx**2) - y * nx * ny - z * nx * nz + Bn * nx - Bx)) == 0
    return verified("M (x,y,z,1)^T equals C + u cos + v sin identically for every unit n (rational parametrization of the sphere) and symbolic B, theta",
        compared='printed matrix M of (1.11)-(1.27) applied to (x, y, z, 1) vs the vector form C + u cos + v sin in sympy (cancel), for a symbolic unit n (rational sphere parametrization), symbolic B and theta; (1.16) likewise',
        reference='sympy',
    )


@claim(doc="sederberg", section="1.5.1", ref="(1.35), Fig. 1.8.b", statement="with P0 at t0 = 1 and P1 at t1 = 4, t = 2 is one third of the way from P0 to P1")
def affine_line_example():
    P0, P1 = sp.Matrix([0, 0]), sp.Matrix([3, 6])
    assert sp.Rational(2 - 1, 4 - 1) == sp.Rational(1, 3) and P0 + sp.Rational(1, 3) * (P1 - P0) == sp.Matrix([1, 2])
    p = b.affine_point((0, 0), 1, (3, 6), 4, 2)
    assert tuple(_R(x) for x in p) == (1, 2)
    g, a_, be = sp.symbols("gamma alpha beta")
    Pa, Pb = sp.symbols("P_a P_b")
    assert sp.simplify(Pa + (g - a_) / (be - a_) * (Pb - Pa) - ((be - g) * Pa + (g - a_) * Pb) / (be - a_)) == 0
    return verified("P(2) = P0 + (P1 - P0)/3; the two forms of P(gamma) agree symbolically",
        compared="printed 'one third of the way' vs sympy: (2 - 1)/(4 - 1) and P0 + (P1 - P0)/3; the two printed forms of P(gamma) agree symbolically",
        reference='sympy',
    )


@claim(doc="sederberg", section="1.5.2", ref="line through two points", statement="|X Y W; X1 Y1 W1; X2 Y2 W2| = (Y1W2 - Y2W1) X + (X2W1 - X1W2) Y + (X1Y2 - X2Y1) W")
def line_determinant():
    X, Y, W, X1, Y1, W1, X2, Y2, W2 = sp.symbols("X Y W X1 Y1 W1 X2 Y2 W2")
    det = sp.Matrix([[X, Y, W], [X1, Y1, W1], [X2, Y2, W2]]).det()
    assert sp.expand(det - ((Y1 * W2 - Y2 * W1) * X + (X2 * W1 - X1 * W2) * Y + (X1 * Y2 - X2 * Y1) * W)) == 0
    line = b.line_through((1, 2, 1), (3, 1, 2))
    assert line((1, 2)) == 0 and line((mpq(3, 2), mpq(1, 2))) == 0
    return verified("cofactor expansion equals the printed line; exact line_through on homogeneous points",
        compared="printed line coefficients vs sympy's 3 x 3 determinant expanded symbolically",
        reference='sympy',
    )


@claim(doc="sederberg", section="1.5.3", ref="normalized line", statement="with a'^2 + b'^2 = 1, f(x,y) is the signed distance of (x,y) to the line; |c'| is the distance of the origin")
def normalized_line_distance():
    a_, b_, c_, x, y = sp.symbols("a b c x y", real=True)
    # foot of the perpendicular: (x, y) - f/(a^2 + b^2) (a, b)
    f = a_ * x + b_ * y + c_
    fx, fy = x - f / (a_**2 + b_**2) * a_, y - f / (a_**2 + b_**2) * b_
    assert sp.simplify(a_ * fx + b_ * fy + c_) == 0
    dist2 = sp.simplify((x - fx) ** 2 + (y - fy) ** 2)
    assert sp.simplify(dist2 - f**2 / (a_**2 + b_**2)) == 0
    line = b.Line(3, 4, -10)
    assert b.signed_distance((0, 0), line) == -2 and b.distance_squared_to_line((3, 4), line) == 225 / mpq(25)
    return verified("squared distance to the foot point is f^2/(a^2+b^2) symbolically",
        compared='printed signed-distance claim vs sympy: squared distance to the perpendicular foot point equals f^2/(a^2 + b^2), symbolically',
        reference='sympy',
    )


@claim(doc="sederberg", section="1.6", ref="discriminant", statement="b^2 - 4ac > 0: hyperbola (two real points at infinity), = 0: parabola, < 0: ellipse")
def conic_discriminant():
    X, Y = sp.symbols("X Y")
    count = 0
    for a_, b_, c_ in itertools.product(range(-3, 4), repeat=3):
        if a_ == b_ == c_ == 0:
            continue
        form = a_ * X**2 + b_ * X * Y + c_ * Y**2
        # real points of aX^2 + bXY + cY^2 = 0 on the projective line, counted with multiplicity
        roots = sp.Poly(form.subs(Y, 1), X).real_roots() if sp.Poly(form.subs(Y, 1), X).degree() > 0 else []
        at_y0 = 2 - sp.Poly(form.subs(Y, 1), X).degree() if a_ == 0 else 0  # roots at X/Y = infinity
        real = len(roots) + at_y0
        distinct = len(set(roots)) + (1 if at_y0 else 0)
        kind = b.classify_conic((a_, b_, c_, 1, 1, 1)).split()[-1]
        expected = "hyperbola" if (real == 2 and distinct == 2) else ("parabola" if real == 2 else "ellipse")
        disc = b_ * b_ - 4 * a_ * c_
        printed_rule = "hyperbola" if disc > 0 else ("parabola" if disc == 0 else "ellipse")
        assert printed_rule == expected and kind == expected, (a_, b_, c_)
        count += 1
    return verified_range("all (a, b, c) in [-3, 3]^3", f"{count} quadratic parts: real points at infinity counted by sympy agree with the discriminant rule",
        compared="printed rule (sign of b^2 - 4ac) vs the real points at infinity of a X^2 + b XY + c Y^2, counted with multiplicity by sympy's real_roots, for all 342 (a, b, c) in [-3, 3]^3; exactcagd's classify_conic agrees",
        reference='sympy',
    )


@claim(doc="sederberg", section="1.6.1", ref="parametric discriminant", statement="d1^2 - 4 d0 d2 > 0: hyperbola, < 0: ellipse, = 0: parabola")
def parametric_conic_discriminant():
    import random

    rng = random.Random(6)
    xs, ys = sp.symbols("x y")
    checked = 0
    for _ in range(150):
        X, Y, W = ([rng.randint(-3, 3) for _ in range(3)] for _ in range(3))
        con = b.implicitize_conic(X, Y, W)
        if con is None or con.a == con.b == con.c == 0:
            continue
        if b.classify_conic(con).startswith("degenerate"):
            continue
        d0, d1, d2 = W
        disc = d1 * d1 - 4 * d0 * d2
        expected = "hyperbola" if disc > 0 else ("parabola" if disc == 0 else "ellipse")
        # independent reference: implicitize by the Sylvester determinant (sympy) of X(t) - x W(t), Y(t) - y W(t)
        # and classify by the implicit discriminant b^2 - 4ac of its quadratic part
        f = [X[k] - xs * W[k] for k in range(3)]
        g = [Y[k] - ys * W[k] for k in range(3)]
        syl = sp.Matrix([[f[2], f[1], f[0], 0], [0, f[2], f[1], f[0]], [g[2], g[1], g[0], 0], [0, g[2], g[1], g[0]]])
        implicit = sp.Poly(sp.expand(syl.det()), xs, ys)
        assert implicit.total_degree() == 2
        A_, B_, C_ = (implicit.coeff_monomial(mono) for mono in (xs**2, xs * ys, ys**2))
        idisc = B_ * B_ - 4 * A_ * C_
        assert sp.sign(idisc) == sp.sign(disc) and b.classify_conic(con) == expected
        checked += 1
    return verified_range("150 random integer parametrizations with entries in [-3, 3]",
                          f"{checked} non-degenerate conics: implicitized exactly, implicit and parametric discriminants agree",
        compared="printed rule (sign of d1^2 - 4 d0 d2) vs the implicit discriminant of the conic implicitized by a sympy Sylvester determinant of X(t) - x W(t), Y(t) - y W(t); exactcagd's classify_conic agrees",
        reference='sympy',
    )

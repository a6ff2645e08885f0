"""Sederberg's notes, chapter 15 (tensor-product surfaces), the foundation's part: (15.2),
15.1 patches and control curves, 15.2 surface de Casteljau / elevation, 15.6 NURBS
surfaces.  15.3-15.5, 15.7 and 15.9 are in ``sederberg_15_extras.py``.

Notation of the notes: P(s, t) with P_ij, i = 0..m in s and j = 0..n in t (15.2); in
exactcagd the net axis 0 runs with u = s and axis 1 with v = t.
"""

from __future__ import annotations

import itertools
from fractions import Fraction

import numpy as np
import sympy as sp
from gmpy2 import mpq

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface
from exactcagd.exact import bernstein as bz
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified
from exactcagd.proofs.sederberg_15_nurbs import _ref_point as _cox_de_boor_point
from exactcagd.proofs._sederberg_common import Rs, rand_pos, rand_q, rng, s_, t_

DOC = "sederberg"


def _net(r, m, n, dim=3):
    return [[[rand_q(r) for _ in range(dim)] for _ in range(n + 1)] for _ in range(m + 1)]


def _weights(r, m, n):
    return [[rand_pos(r) for _ in range(n + 1)] for _ in range(m + 1)]


def _surface_exprs(net, weights=None, s=s_, t=t_):
    """(15.2) written out in sympy."""
    m, n = len(net) - 1, len(net[0]) - 1
    w = [[1] * (n + 1) for _ in range(m + 1)] if weights is None else weights
    B = lambda k, i, x: sp.binomial(k, i) * x**i * (1 - x) ** (k - i)  # noqa: E731
    den = sp.expand(sum(Rs(w[i][j]) * B(m, i, s) * B(n, j, t) for i in range(m + 1) for j in range(n + 1)))
    return [sp.expand(sum(Rs(w[i][j]) * Rs(net[i][j][k]) * B(m, i, s) * B(n, j, t) for i in range(m + 1) for j in range(n + 1))) / den for k in range(len(net[0][0]))]


# ---------------------------------------------------------------- 15, 15.1
@claim(DOC, "15", "(15.2)", "P(s,t) = sum w_ij P_ij B_i^m(s) B_j^n(t) / sum w_ij B_i^m(s) B_j^n(t)")
def surface_equation():
    r = rng(150)
    net, w = _net(r, 2, 3), _weights(r, 2, 3)
    surf = BezierSurface(net, w)
    ref = _surface_exprs(net, w)
    for a, b in [(0, 0), (mpq(1, 3), mpq(3, 4)), (1, mpq(1, 2)), (mpq(5, 7), 1)]:
        assert tuple(Rs(x) for x in surf.evaluate(a, b)) == tuple(e.subs({s_: Rs(a), t_: Rs(b)}) for e in ref)
    return verified("rational 2 x 3 patch: exact tensor de Casteljau == printed quotient (sympy) at 4 parameter pairs",
        compared="printed (15.2) quotient expanded in sympy vs exactcagd's tensor de Casteljau at 4 parameter pairs",
        reference='sympy')


@claim(DOC, "15.1", "(15.3), (15.4)", "bicubic blending functions laid out like the control points: entry of P_ij is B_i^3(s) B_j^3(t)", covers=["(15.1)"])
def bicubic_blending_layout():
    printed_rows = [  # (15.4) top row first; columns s-index 0..3
        [(1 - s_) ** 3 * t_**3, 3 * s_ * (1 - s_) ** 2 * t_**3, 3 * s_**2 * (1 - s_) * t_**3, s_**3 * t_**3],
        [(1 - s_) ** 3 * 3 * t_**2 * (1 - t_), 3 * s_ * (1 - s_) ** 2 * 3 * t_**2 * (1 - t_), 3 * s_**2 * (1 - s_) * 3 * t_**2 * (1 - t_), s_**3 * 3 * t_**2 * (1 - t_)],
        [(1 - s_) ** 3 * 3 * t_ * (1 - t_) ** 2, 3 * s_ * (1 - s_) ** 2 * 3 * t_ * (1 - t_) ** 2, 3 * s_**2 * (1 - s_) * 3 * t_ * (1 - t_) ** 2, s_**3 * 3 * t_ * (1 - t_) ** 2],
        [(1 - s_) ** 3 * (1 - t_) ** 3, 3 * s_ * (1 - s_) ** 2 * (1 - t_) ** 3, 3 * s_**2 * (1 - s_) * (1 - t_) ** 3, s_**3 * (1 - t_) ** 3],
    ]
    # (15.3): row r from the top holds P_(c, 3-r) in column c
    for i, j in itertools.product(range(4), range(4)):
        net = [[[int((a, b) == (i, j))] for b in range(4)] for a in range(4)]
        surf = BezierSurface(net)
        expr = printed_rows[3 - j][i]
        assert sp.expand(expr - sp.binomial(3, i) * s_**i * (1 - s_) ** (3 - i) * sp.binomial(3, j) * t_**j * (1 - t_) ** (3 - j)) == 0
        for a, b in [(mpq(1, 3), mpq(2, 5)), (mpq(3, 4), mpq(1, 7))]:
            assert Rs(surf.evaluate(a, b)[0]) == expr.subs({s_: Rs(a), t_: Rs(b)})
    return verified("each P_ij's blending function (unit net, exactcagd) equals the printed entry at the (15.3) position",
        compared="printed (15.4) entries at their (15.3) positions vs sympy B_i^3(s) B_j^3(t) identically, and vs exactcagd's unit-net evaluation",
        reference='sympy')


@claim(DOC, "15.1", "(15.5)", "P(c, t) = sum_j Q_j(c) B_j^n(t), Q_j(c) = sum_i P_ij B_i^m(c); corners P(0,0) = P_00, P(1,0) = P_m0, P(0,1) = P_0n, P(1,1) = P_mn")
def iso_curves_and_corners():
    r = rng(151)
    net, w = _net(r, 2, 3), _weights(r, 2, 3)
    surf = BezierSurface(net)
    for c in [mpq(0), mpq(2, 9), mpq(1)]:
        iso = surf.iso_u(c)
        beads = [BezierCurve([net[i][j] for i in range(3)]).evaluate(c) for j in range(4)]
        assert iso.control_points == tuple(beads)
        ref = _surface_exprs(net)
        for k in range(5):
            assert iso.evaluate(mpq(k, 4)) == surf.evaluate(c, mpq(k, 4))
            assert tuple(Rs(x) for x in iso.evaluate(mpq(k, 4))) == tuple(e.subs({s_: Rs(c), t_: sp.Rational(k, 4)}) for e in ref)
    rat = BezierSurface(net, w)
    corners = {(0, 0): net[0][0], (1, 0): net[2][0], (0, 1): net[0][3], (1, 1): net[2][3]}
    for (a, b), p in corners.items():
        assert surf.evaluate(a, b) == rat.evaluate(a, b) == tuple(mpq(x) for x in p)
    return verified("iso-parameter curves' control points are the beads Q_j(c) (exact); the corners are interpolated (polynomial and rational)",
        compared="printed (15.5) beads Q_j(c) vs exactcagd's iso-curve control points; the iso-curve vs sympy (15.2) at s = c; printed corners vs the control points",
        reference='sympy')


@claim(DOC, "15.1", "control curves", "the i-th s-control curve is defined by P_ij, j = 0..n; there are m+1 s-control curves; "
       "the beads Q_j(c) slide along the s-control curves")
def control_curve_definition():
    r = rng(1511)
    net = _net(r, 2, 3)
    surf = BezierSurface(net)
    c = mpq(3, 8)
    beads = surf.iso_u(c).control_points  # Q_j(c), j = 0..n: n + 1 = 4 beads
    # bead j lies on the curve through P_0j, ..., P_mj (a curve in s), not on the row P_i0..P_in
    for j in range(4):
        assert BezierCurve([net[i][j] for i in range(3)]).evaluate(c) == beads[j]
    assert len(beads) == 4 != 3  # n + 1 beads, but only m + 1 = 3 curves of the printed kind
    def beads_on_curves(axis):
        # the bead Q_j(c) must lie on the j-th s-control curve: the curve through P_ij with i running (axis 'i')
        for j in range(4):
            pts_ = [net[i][j] for i in range(3)] if axis == "i" else [net[min(j, 2)][k] for k in range(4)]
            if BezierCurve(pts_).evaluate(c) != beads[j]:
                return f"bead Q_{j}(c) is not on the curve P_ij, {'j' if axis == 'j' else 'i'} = 0.. (n + 1 beads, m + 1 such curves)"
        return None
    return erratum(
        printed="the curve defined by P_ij, j = 0..n is the i-th s-control curve (m+1 of them); P_ij, i = 0..m the j-th t-control curve",
        corrected="the s-control curves (along which the n+1 beads Q_j(c) slide, and which are split to subdivide at s = sigma) are P_ij, i = 0..m, one for each j (n+1 of them)",
        detail="Q_j(c) = sum_i P_ij B_i^m(c) is a point of the curve with control points P_0j..P_mj; exactcagd iso_u(c) control points equal these beads",
        printed_form='j', corrected_form='i', check=L.predicate(beads_on_curves),
    )


@claim(DOC, "15.1", "boundary curves", "P(0,t) is the degree-three Bézier curve with control points P_00, P_10, P_20, P_30; P(s,1) is the degree-two curve with P_30, P_31, P_32 (2 x 3 patch)")
def boundary_curves():
    r = rng(152)
    net = _net(r, 2, 3)  # degree 2 in s, 3 in t
    surf = BezierSurface(net)
    b = surf.boundary_curves()
    p0t, ps1 = b["u0"], b["v1"]
    assert p0t.degree == 3 and ps1.degree == 2
    assert p0t.control_points == tuple(tuple(mpq(x) for x in net[0][j]) for j in range(4))  # P_00, P_01, P_02, P_03
    assert ps1.control_points == tuple(tuple(mpq(x) for x in net[i][3]) for i in range(3))  # P_03, P_13, P_23
    ref = _surface_exprs(net)
    assert all(sp.expand(e.subs(s_, 0) - f) == 0 for e, f in zip(ref, [sp.expand(x) for x in p0t.to_sympy(t_)]))
    def is_boundary_p0t(idx):
        if any(i >= len(net) or j >= len(net[0]) for i, j in idx):
            return f"P_{idx} is not a control net of the 2 x 3 patch (no row i = 3): the subscripts are transposed"
        pts_ = [tuple(mpq(x_) for x_ in net[i][j]) for i, j in idx]
        return None if tuple(pts_) == p0t.control_points and all(sp.expand(e.subs(s_, 0) - f_) == 0 for e, f_ in zip(ref, [sp.expand(x_) for x_ in BezierCurve([list(p_) for p_ in pts_]).to_sympy(t_)])) else f"P_{idx} are not the control points of P(0, t) (sympy P(0, t))"
    return erratum(
        printed="P(0,t): P_00, P_10, P_20, P_30;  P(s,1): P_30, P_31, P_32",
        corrected="P(0,t): P_00, P_01, P_02, P_03;  P(s,1): P_03, P_13, P_23 (first index = s, as in (15.2), (15.3))",
        detail="the printed subscripts are transposed; exactcagd boundary curves of a 2 x 3 patch have the corrected control points and agree with sympy",
        printed_form=[(0, 0), (1, 0), (2, 0), (3, 0)], corrected_form=[(0, 0), (0, 1), (0, 2), (0, 3)], check=L.predicate(is_boundary_p0t),
    )


# ---------------------------------------------------------------- 15.2
@claim(DOC, "15.2", "Fig. 15.3", "P_[0,1/2]x[0,1/2] is obtained by splitting at t = 1/2 into P_[0,1]x[0,1/2] and P_[0,1/2]x[1/2,1], then P_[0,1]x[0,1/2] at s = 1/2")
def surface_subdivision_example():
    r = rng(153)
    net, w = _net(r, 2, 3), _weights(r, 2, 3)
    surf = BezierSurface(net, w)
    low, high = surf.subdivide_v("1/2")
    quarter, _ = low.subdivide_u("1/2")
    assert quarter == surf.reparametrize((0, "1/2"), (0, "1/2"))
    assert high == surf.reparametrize((0, 1), ("1/2", 1))
    # independent check on the polynomial patch with the same net (sympy substitution)
    poly = BezierSurface(net)
    ref = _surface_exprs(net)
    got = _surface_exprs([[list(p) for p in row] for row in poly.subdivide_v("1/2")[1].control_net])
    for a, b in zip(got, ref):
        assert sp.expand(a - b.subs(t_, (1 + t_) / 2)) == 0
    def is_other_half(srange):
        return None if high == surf.reparametrize(srange, ("1/2", 1)) else f"the upper half of the split at t = 1/2 is not P_{srange} x [1/2, 1]"
    return erratum(
        printed="P_[0,1/2] x [1/2,1]",
        corrected="P_[0,1] x [1/2,1] (the other half of the split at t = 1/2)",
        detail="exactcagd subdivide_v(1/2) then subdivide_u(1/2) gives the [0,1/2]^2 patch (== reparametrize); the upper half covers s in [0,1]",
        printed_form=(0, '1/2'), corrected_form=(0, 1), check=L.predicate(is_other_half), reference='exact',
    )


@claim(DOC, "15.2", "subdivision / elevation", "subdivide at s = sigma by subdividing the s-control curves; degree elevate by elevating the control curves")
def surface_subdivision_and_elevation():
    r = rng(154)
    net, w = _net(r, 3, 2), _weights(r, 3, 2)
    surf = BezierSurface(net, w)
    sigma = mpq(2, 5)
    a, b = surf.subdivide_u(sigma)
    hom = surf.homogeneous()
    for j in range(3):
        column = BezierCurve.from_homogeneous(hom[:, j, :])
        left, right = column.subdivide(sigma)
        assert left.control_points == tuple(tuple(p) for p in a.net_array()[:, j]) and right.weights == tuple(b.weights_array()[:, j])
    e = surf.elevate(1, 2)
    for i in range(4):
        row = BezierCurve.from_homogeneous(hom[i, :, :]).elevate(2)
        assert row.weights == tuple(BezierSurface.from_homogeneous(bz.along(1, bz.elevate, hom, 2)).weights_array()[i])
    ref = _surface_exprs(net, w)
    for a, b in [(mpq(1, 3), mpq(2, 7)), (mpq(4, 5), mpq(1, 2)), (mpq(1), mpq(1, 9))]:
        assert tuple(Rs(x) for x in e.evaluate(a, b)) == tuple(x.subs({s_: Rs(a), t_: Rs(b)}) for x in ref)
    return verified("rational 3 x 2 patch: subdividing every column curve == surface subdivision; the (1, 2)-elevated patch agrees with the printed quotient (sympy) at 3 points",
        compared="printed rule (subdivide / elevate each control curve) vs exactcagd's surface subdivision and elevation; the elevated patch vs sympy (15.2) at 3 points",
        reference='sympy')


# ---------------------------------------------------------------- 15.6 NURBS surfaces
@claim(DOC, "15.6", "NURBS surface", "knot insertion and Bézier splitting of a NURBS surface act on every control curve: "
       "split each s-control curve into Bézier curves, then each resulting t-control curve")
def nurbs_surface_splitting():
    r = rng(156)
    ku, kv = [0, 0, 0, 0, 1, 3, 3, 3, 3], [0, 0, 0, 2, 5, 5, 5]
    nu, nv = len(ku) - 4, len(kv) - 3
    net = [[[rand_q(r) for _ in range(3)] for _ in range(nv)] for _ in range(nu)]
    w = [[rand_pos(r) for _ in range(nv)] for _ in range(nu)]
    surf = BSplineSurface(net, ku, kv, w)
    hom = np.array([[[mpq(x) * w[i][j] for x in net[i][j]] + [mpq(w[i][j])] for j in range(nv)] for i in range(nu)], dtype=object)
    # by hand: every column (a curve in u) split, then every row of the result split in v
    columns = [BSplineCurve([list(p) for p in hom[:, j, :]], ku).to_bezier() for j in range(nv)]
    n_u = len(columns[0])
    patches = surf.to_bezier_patches()
    for a in range(n_u):
        strip = np.array([[list(p) for p in columns[j][a][1].control_points] for j in range(nv)], dtype=object)  # (nv, p+1, 4)
        rows = [BSplineCurve([list(p) for p in strip[:, i, :]], kv).to_bezier() for i in range(strip.shape[1])]
        for b in range(len(rows[0])):
            hom_patch = np.array([[list(p) for p in rows[i][b][1].control_points] for i in range(strip.shape[1])], dtype=object)
            assert BezierSurface.from_homogeneous(hom_patch) == patches[(a, b)][1]
    # knot insertion in t then in s leaves the surface unchanged
    refined = surf.insert_knot_v(mpq(7, 2)).insert_knot_u(2)
    for u, v in [(mpq(1, 2), mpq(1)), (mpq(2), mpq(4)), (mpq(3), mpq(5)), (mpq(5, 2), mpq(7, 2))]:
        assert refined.evaluate(u, v) == surf.evaluate(u, v)
        F = lambda x: Fraction(int(mpq(x).numerator), int(mpq(x).denominator))  # noqa: E731
        cox_de_boor = _cox_de_boor_point([[[F(x) for x in p] for p in row] for row in net], [[F(x) for x in row] for row in w], [Fraction(k) for k in ku], [Fraction(k) for k in kv], 3, 2, Fraction(int(u.numerator), int(u.denominator)), Fraction(int(v.numerator), int(v.denominator)))
        assert tuple(Fraction(int(x.numerator), int(x.denominator)) for x in refined.evaluate(u, v)) == cox_de_boor
    return verified("rational bicubic x biquadratic NURBS: exactcagd's patches == splitting the homogeneous control curves by hand; knot insertion exact",
        compared="printed 15.6 rule (split each s-control curve, then each t-control curve) vs exactcagd's to_bezier_patches; the knot-refined surface vs an independent Cox-de Boor evaluation on Fractions",
        reference='independent-algorithm')

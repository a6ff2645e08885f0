"""Ledger: Sederberg's notes (003) 15.6, NURBS surfaces.

The operations themselves are the foundation's
(:class:`exactcagd.geometry.bspline.BSplineSurface`) and the continuity test is
:func:`exactcagd.toolbox.surfaces.patch_continuity_order`.  The references here are
independent: a plain Cox-de Boor recursion on Fractions for the rational tensor-product
equation (15.2) with B-spline blending functions, and the curve algorithms applied to
each control curve separately, as the notes prescribe.
"""

from __future__ import annotations

import random
from fractions import Fraction as Fr

import numpy as np
import sympy as sp
from gmpy2 import mpq

from exactcagd.geometry.bspline import BSplineCurve, BSplineSurface
from exactcagd.toolbox.surfaces import patch_continuity_order
from exactcagd.proofs._ledger import claim, verified_range


def _N(i, p, K, t):
    """Cox-de Boor on Fractions, half-open spans; the last span is closed at the domain end."""
    if p == 0:
        if K[i] <= t < K[i + 1]:
            return Fr(1)
        last = max(j for j in range(len(K) - 1) if K[j] < K[j + 1])
        return Fr(1) if (i == last and t == K[i + 1]) else Fr(0)
    a = (t - K[i]) / (K[i + p] - K[i]) * _N(i, p - 1, K, t) if K[i + p] != K[i] else 0
    b = (K[i + p + 1] - t) / (K[i + p + 1] - K[i + 1]) * _N(i + 1, p - 1, K, t) if K[i + p + 1] != K[i + 1] else 0
    return a + b


def _ref_point(net, w, Ku, Kv, p, q, u, v):
    """(15.2) with B-spline blending functions, on Fractions."""
    num, den = [Fr(0)] * len(net[0][0]), Fr(0)
    for i in range(len(net)):
        for j in range(len(net[0])):
            b = w[i][j] * _N(i, p, Ku, u) * _N(j, q, Kv, v)
            den += b
            num = [a + b * c for a, c in zip(num, net[i][j])]
    return tuple(a / den for a in num)


def _surface(rng, p, q, Ku, Kv):
    nu, nv = len(Ku) - p - 1, len(Kv) - q - 1
    net = [[[Fr(rng.randint(-9, 9), 2) for _ in range(3)] for _ in range(nv)] for _ in range(nu)]
    w = [[Fr(rng.randint(1, 4), rng.randint(1, 2)) for _ in range(nv)] for _ in range(nu)]
    return net, w, BSplineSurface(net, Ku, Kv, w)


def _fr(x):
    return Fr(int(x.numerator), int(x.denominator))


CASES = [(3, 3, [0, 0, 0, 0, 1, 3, 4, 4, 4, 4], [0, 0, 0, 0, 2, 5, 5, 5, 5]), (2, 3, [0, 0, 0, 1, 1, 2, 2, 2], [0, 0, 0, 0, 1, 1, 1, 1])]


@claim(doc="sederberg", section="15.6", ref="NURBS surface",
       statement="a tensor-product NURBS surface is (15.2) with B-spline blending functions, one knot vector for s and one for t")
def nurbs_equation():
    rng = random.Random(156)
    for p, q, Ku, Kv in CASES:
        net, w, S = _surface(rng, p, q, Ku, Kv)
        for u in (Ku[-1] * f for f in (Fr(0), Fr(1, 8), Fr(1, 4), Fr(5, 8), Fr(1))):
            for v in (Kv[-1] * f for f in (Fr(0), Fr(3, 7), Fr(1))):
                assert tuple(_fr(x) for x in S.evaluate(mpq(u.numerator, u.denominator), mpq(v.numerator, v.denominator))) == _ref_point(net, w, Ku, Kv, p, q, u, v)
    return verified_range("bicubic on [0,4]x[0,5] with a double interior knot pattern; (2,3) with a double u knot",
                          "exact points against Cox-de Boor on Fractions, 15 parameter pairs each, rational weights",
        compared='printed (15.2) with B-spline blending functions vs an independent Cox-de Boor recursion on Fractions at 15 parameter pairs per surface',
        reference='independent-algorithm')


@claim(doc="sederberg", section="15.6", ref="knot insertion",
       statement="to insert a knot into the s knot vector of a NURBS surface, insert it into each s-control curve")
def knot_insertion_by_control_curves():
    rng = random.Random(1561)
    for p, q, Ku, Kv in CASES:
        net, w, S = _surface(rng, p, q, Ku, Kv)
        for k in (mpq(1, 2), mpq(3, 2)):
            new = S.insert_knot_u(k)
            for j in range(len(net[0])):  # the curve through P_0j, ..., P_{n_u - 1, j} (parameter s)
                curve = BSplineCurve([row[j] for row in net], Ku, [row[j] for row in w]).insert_knot(k)
                assert curve.control_points == tuple(row[j] for row in new.control_net)
                assert curve.weights == tuple(row[j] for row in new.weights)
            for u, v in ((Ku[-1] * Fr(1, 4), Kv[-1] * Fr(2, 3)), (Ku[-1] * Fr(3, 4), Kv[-1] * Fr(1, 5))):
                assert tuple(_fr(x) for x in new.evaluate(mpq(u.numerator, u.denominator), mpq(v.numerator, v.denominator))) == _ref_point(net, w, Ku, Kv, p, q, u, v)
        new = S.insert_knot_v(mpq(1, 2))
        for i in range(len(net)):
            curve = BSplineCurve(net[i], Kv, w[i]).insert_knot(mpq(1, 2))
            assert curve.control_points == new.control_net[i]
    return verified_range("the two surfaces of the equation claim, knots 1/2 and 3/2 in s, 1/2 in t",
                          "the inserted net equals the curve insertion applied to each control curve separately, and the surface "
                          "is unchanged (Cox-de Boor reference)",
        compared='printed rule (insert into each s-control curve) vs the curve knot insertion applied to each control curve; refined surface vs the Cox-de Boor evaluation of (15.2) on Fractions',
        reference='independent-algorithm')


@claim(doc="sederberg", section="15.6", ref="splitting into Bézier patches",
       statement="split each s-control curve into Bézier curves, then each resulting t-control curve; the Bézier patches reproduce the surface")
def bezier_patches_by_control_curves():
    rng = random.Random(1562)
    for p, q, Ku, Kv in CASES:
        net, w, S = _surface(rng, p, q, Ku, Kv)
        patches = S.to_bezier_patches()
        # step 1: every s-control curve into Bézier pieces (homogeneous, so that weights travel along)
        strips = {}
        for j in range(len(net[0])):
            curve = BSplineCurve([row[j] for row in net], Ku, [row[j] for row in w])
            for a, (span, piece) in enumerate(curve.to_bezier()):
                strips.setdefault((a, span), []).append(piece.homogeneous())
        # step 2: every t-control curve of each strip into Bézier pieces
        for (a, uspan), columns in strips.items():
            strip = np.stack(columns, axis=1)  # (p+1, n_v, 4)
            for i in range(p + 1):
                hom = strip[i]
                curve = BSplineCurve([tuple(x / h[-1] for x in h[:-1]) for h in hom], Kv, [h[-1] for h in hom])
                for b, (vspan, piece) in enumerate(curve.to_bezier()):
                    (us, vs), patch = patches[(a, b)]
                    assert (us, vs) == (uspan, vspan)
                    assert np.all(piece.homogeneous() * patch.homogeneous()[i][0][-1] == patch.homogeneous()[i] * piece.homogeneous()[0][-1])
        for (a, b), ((us, vs), patch) in patches.items():
            u = (us[0] + us[1]) / 2
            v = (vs[0] + 2 * vs[1]) / 3
            ref = _ref_point(net, w, Ku, Kv, p, q, _fr(u), _fr(v))
            assert tuple(_fr(x) for x in patch.evaluate((u - us[0]) / (us[1] - us[0]), (v - vs[0]) / (vs[1] - vs[0]))) == ref
    return verified_range("the two surfaces of the equation claim",
                          "the two-pass split (curves in s, then in t) gives the foundation's patches (homogeneous rows equal up "
                          "to the scale of a rational Bézier form), and each patch reproduces the Cox-de Boor surface",
        compared="printed two-pass split (s-control curves, then t-control curves) vs the foundation's to_bezier_patches; each patch vs the Cox-de Boor evaluation of (15.2) on Fractions",
        reference='independent-algorithm')


def _sym_patch_at(patch, u, v, direction):
    """(15.2) of a Bézier patch written out in sympy from its homogeneous net, the other parameter fixed: a rational curve."""
    H = patch.homogeneous()
    H = H if direction == "u" else np.swapaxes(H, 0, 1)
    m, n = len(H) - 1, len(H[0]) - 1
    B = lambda k, i, x: sp.binomial(k, i) * x**i * (1 - x) ** (k - i)  # noqa: E731
    comps = [sum(sp.Rational(_fr(H[i][j][c])) * B(m, i, u) * B(n, j, v) for i in range(m + 1) for j in range(n + 1)) for c in range(len(H[0][0]))]
    return [sp.expand(x) / sp.expand(comps[-1]) for x in comps[:-1]]


def _sympy_continuity_order(left, right, h_left, h_right, direction):
    """Largest r with d^k/ds^k equal across the joint for k <= r (s the global knot parameter), sympy at two v."""
    x = sp.Symbol("x")
    order = None
    for y in (sp.Rational(1, 3), sp.Rational(4, 5)):
        L_, R_ = _sym_patch_at(left, x, y, direction), _sym_patch_at(right, x, y, direction)
        k = 0
        while k <= 6 and all(sp.simplify(sp.diff(a, x, k).subs(x, 1) / sp.Rational(_fr(h_left)) ** k - sp.diff(b, x, k).subs(x, 0) / sp.Rational(_fr(h_right)) ** k) == 0 for a, b in zip(L_, R_)):
            k += 1
        order = k - 1 if order is None else min(order, k - 1)
    return order


@claim(doc="sederberg", section="15.6", ref="automatic C^n",
       statement="with B-spline surfaces the control curves in both directions are automatically C^n (C^{p-k} across a knot of multiplicity k)")
def automatic_continuity():
    rng = random.Random(1563)
    for p, q, Ku, Kv in CASES:
        net, w, S = _surface(rng, p, q, Ku, Kv)
        net_poly = BSplineSurface(net, Ku, Kv)
        for surface in (net_poly, S):
            patches = surface.to_bezier_patches()
            for (a, b), ((us, vs), patch) in patches.items():
                if (a + 1, b) in patches:
                    (us2, _), nxt = patches[(a + 1, b)]
                    order = patch_continuity_order(patch, nxt, "u", us[1] - us[0], us2[1] - us2[0])
                    assert order == _sympy_continuity_order(patch, nxt, us[1] - us[0], us2[1] - us2[0], "u"), us
                    assert order >= p - Ku.count(us[1]), (order, us)
                    if surface is net_poly:
                        assert order == p - Ku.count(us[1])  # generic net: not smoother than the knot allows
                if (a, b + 1) in patches:
                    (_, vs2), nxt = patches[(a, b + 1)]
                    order = patch_continuity_order(patch, nxt, "v", vs[1] - vs[0], vs2[1] - vs2[0])
                    assert order == _sympy_continuity_order(patch, nxt, vs[1] - vs[0], vs2[1] - vs2[0], "v"), vs
                    assert order >= q - Kv.count(vs[1])
                    if surface is net_poly:
                        assert order == q - Kv.count(vs[1])
    return verified_range("the two surfaces of the equation claim, polynomial and rational",
                          "exact continuity order of adjacent Bézier patches across every interior knot line: p - multiplicity "
                          "(equality for the random polynomial nets)",
        compared="printed C^{p-k} across a knot of multiplicity k vs the continuity order measured in sympy: derivatives of adjacent Bézier patches (written out from their homogeneous nets) across every interior knot line, scaled by the knot spans, at two transverse parameters; exactcagd's patch_continuity_order agrees",
        reference='sympy')

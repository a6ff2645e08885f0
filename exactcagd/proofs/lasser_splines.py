"""Lasser & Bonneau (000), Remarks 1 and 2: trim curves on (rational) spline surfaces."""

from __future__ import annotations

import random
from fractions import Fraction as Fr

from gmpy2 import mpq

from exactcagd import BSplineCurve, BSplineSurface
from exactcagd.composition import compose_spline
from exactcagd.composition.splines import rational_between
from exactcagd.exact.algebraic import RealAlgebraic
from exactcagd.proofs._ledger import claim, verified_range


def _random_spline_pair(rng, rational: bool):
    p, q = rng.choice([(2, 2), (3, 2), (2, 3)])
    ku = [0] * (p + 1) + sorted(Fr(rng.randint(1, 7), 8) for _ in range(2)) + [1] * (p + 1)
    kv = [0] * (q + 1) + [Fr(1, 2)] * rng.randint(1, q) + [1] * (q + 1)
    nu, nv = len(ku) - p - 1, len(kv) - q - 1
    if len(set(ku[p + 1 : -p - 1])) < 2:
        ku = [0] * (p + 1) + [Fr(1, 4), Fr(5, 8)] + [1] * (p + 1)
        nu = len(ku) - p - 1
    net = [[[Fr(i, nu - 1), Fr(j, nv - 1), Fr(rng.randint(-8, 8), 8)] for j in range(nv)] for i in range(nu)]
    w = [[Fr(rng.randint(1, 6), rng.randint(1, 3)) for _ in range(nv)] for _ in range(nu)] if rational else None
    surface = BSplineSurface(net, ku, kv, w)
    pts = [[Fr(rng.randint(1, 15), 16), Fr(rng.randint(1, 15), 16)] for _ in range(5)]
    wc = [Fr(rng.randint(1, 6), rng.randint(1, 3)) for _ in range(5)] if rational else None
    kc = [0, 0, 0, Fr(1, 3), Fr(2, 3), 1, 1, 1]
    curve = BSplineCurve(pts, kc, wc)
    raw = {"net": net, "ku": ku, "kv": kv, "w": w, "p": p, "q": q, "pts": pts, "kc": kc, "wc": wc}
    return surface, curve, raw


def _basis(knots, degree, x):
    """Cox-de Boor recursion from the definition (Fractions; 0/0 := 0), for x inside the knot range."""
    N = [Fr(1) if knots[i] <= x < knots[i + 1] else Fr(0) for i in range(len(knots) - 1)]
    for d in range(1, degree + 1):
        nxt = []
        for i in range(len(knots) - d - 1):
            a = (x - knots[i]) / (knots[i + d] - knots[i]) * N[i] if knots[i + d] != knots[i] else Fr(0)
            b = (knots[i + d + 1] - x) / (knots[i + d + 1] - knots[i + 1]) * N[i + 1] if knots[i + d + 1] != knots[i + 1] else Fr(0)
            nxt.append(a + b)
        N = nxt
    return N


def _reference_image(raw, t):
    """F(K(t)) by the Cox-de Boor basis written out here (not exactcagd's evaluators), exact."""
    Nc = _basis(raw["kc"], 2, t)
    wc = raw["wc"] or [Fr(1)] * len(raw["pts"])
    den = sum(n * w for n, w in zip(Nc, wc))
    u, v = (sum(n * w * pt[k] for n, w, pt in zip(Nc, wc, raw["pts"])) / den for k in range(2))
    Nu, Nv = _basis(raw["ku"], raw["p"], u), _basis(raw["kv"], raw["q"], v)
    net = raw["net"]
    w = raw["w"] or [[Fr(1)] * len(net[0]) for _ in net]
    terms = [(Nu[i] * Nv[j] * w[i][j], net[i][j]) for i in range(len(net)) for j in range(len(net[0]))]
    den = sum(c for c, _ in terms)
    return tuple(sum(c * pt[k] for c, pt in terms) / den for k in range(3))


def _check(rational: bool, trials: int, seed: int):
    rng = random.Random(seed)
    pieces = joints = irrational = tight = 0
    for _ in range(trials):
        surface, curve, raw = _random_spline_pair(rng, rational)
        result = compose_spline(surface, curve)
        for piece in result.pieces:
            t = rational_between(*piece.interval)
            assert tuple(Fr(str(x)) for x in piece.evaluate(t)) == _reference_image(raw, Fr(str(t)))
            assert piece.evaluate(t) == surface.evaluate(*curve.evaluate(t))
            pieces += 1
            irrational += not piece.exact
        for joint in result.joints:
            joints += 1
            if joint.remark_bound is not None and joint.measured is not None:
                assert joint.measured >= joint.remark_bound, joint
                tight += joint.measured == joint.remark_bound
            # the joint is a crossing of a knot line or a knot of K: the parameter is exact
            assert isinstance(joint.parameter, (RealAlgebraic, mpq))
    return pieces, joints, irrational, tight


@claim(doc="lasser", section="III", ref="Remark 1", statement="split K at the patch edges of F and its knots; every segment is composed by Theorem 1; F(K(t)) is C^e, e = min{a, b}")
def remark1():
    pieces, joints, irrational, tight = _check(False, 6, 21)
    return verified_range(
        "6 random clamped B-spline surfaces (degrees (2,2)/(3,2)/(2,3), simple and multiple knots) x C1 quadratic spline curves",
        f"{pieces} pieces agree with de Boor evaluation F(K(t)) at rational points ({irrational} pieces end at irrational "
        f"crossing parameters, carried exactly); at all {joints} joints the measured order of contact is >= min(a, b) "
        f"(equality at {tight}); e = min(a, b) is a lower bound (the order can be higher, e.g. a C1 double knot)",
        compared="composed pieces (compose_spline) at a rational point inside each piece vs F(K(t)) by the Cox-de Boor basis written out in the row (exact Fractions; also exactcagd's de Boor evaluation); at each joint exactcagd's measured order of contact vs Remark 1's e = min(a, b)",
        reference='exact',
    )


@claim(doc="lasser", section="V", ref="Remark 2", statement="rational Bézier splines can be treated as described in Remark 1")
def remark2():
    pieces, joints, irrational, tight = _check(True, 4, 22)
    return verified_range(
        "4 random NURBS surfaces x NURBS curves",
        f"{pieces} rational pieces agree with de Boor evaluation ({irrational} with irrational ends, carried exactly); "
        f"{joints} joints with measured order >= min(a, b) (equality at {tight})",
        compared="rational composed pieces at a rational point inside each piece vs the NURBS surface at the NURBS curve point by the Cox-de Boor basis written out in the row (exact Fractions); at each joint exactcagd's measured order of contact vs min(a, b)",
        reference='exact',
    )

"""Reference records: the exchange format (float companions, algebraic numbers) and every kind's
exact answer, each checked against an independent reference (gmpy2 mpfr rounding, sympy
substitution / symbolic B-spline bases / real_roots, mpmath root refinement)."""
import itertools
import json
from fractions import Fraction

import gmpy2
import jsonschema
import mpmath
import pytest
import sympy as sp
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.exact.algebraic import real_roots
from exactcagd.refdata.kinds import KINDS, make_record
from exactcagd.refdata.manifest import schema_path
from exactcagd.refdata.records import algebraic, exact, f64, f64_float
from exactcagd.refdata.schemagen import kind_schema, schema_text

t = sp.Symbol("t")


def Q(v):
    """An exact record value as a sympy Rational."""
    return sp.Rational(v) if isinstance(v, str) else sp.Integer(v)


def _mpfr_round(q: Fraction) -> float:
    """Independent rounding: MPFR at 53 bits, round to nearest, IEEE subnormals and overflow."""
    with gmpy2.context(gmpy2.ieee(64)):
        return float(gmpy2.mpfr(gmpy2.mpq(q.numerator, q.denominator)))


@settings(max_examples=300, deadline=None)
@given(st.integers(1, 2**80), st.integers(1, 2**80), st.integers(-1120, 1030), st.sampled_from([1, -1]))
def test_f64_companion_is_correctly_rounded(num, den, exp, sign):
    q = Fraction(sign * num, den) * Fraction(2) ** exp
    assert f64_float(mpq(q.numerator, q.denominator)) == _mpfr_round(q)
    assert f64(mpq(q.numerator, q.denominator)) == float.hex(_mpfr_round(q))


def test_exact_form_and_ties_to_even():
    assert exact(mpq(6, 4)) == "3/2" and exact(mpq(-8, 4)) == -2
    # 1 + 2^-53 is a tie between 1 and 1 + 2^-52: ties go to the even one (1)
    assert f64(1 + mpq(1, 2**53)) == float.hex(1.0)
    assert f64(1 + mpq(3, 2**53)) == float.hex(1 + 2**-51)


def test_algebraic_number_encoding_against_mpmath():
    (root, _), = [r for r in real_roots([-2, 0, 1], 0, 2)]  # sqrt(2)
    enc = algebraic(root)
    assert enc["poly"] == [-2, 0, 1]
    lo, hi = (Q(v) for v in enc["interval"])
    assert lo < sp.sqrt(2) < hi
    assert float.fromhex(enc["f64"]) == float(mpmath.mpf(mpmath.sqrt(2)))  # mpmath default 53-bit RN
    assert algebraic(mpq(1, 3)) == {"poly": [-1, 3], "interval": ["1/3", "1/3"], "f64": float.hex(1 / 3)}


def _records(kind, count=2, degrees=None):
    spec = KINDS[kind]
    for family in spec.families:
        for i in range(count):
            yield json.loads(json.dumps(make_record(kind, family, 5, i, degrees or spec.default_degrees)))


def _bernstein(points, weights, s):
    n = len(points) - 1
    w = [Q(x) for x in weights] if weights else [1] * (n + 1)
    basis = [sp.binomial(n, i) * s**i * (1 - s) ** (n - i) for i in range(n + 1)]
    den = sum(b * wi for b, wi in zip(basis, w))
    return [sum(b * wi * Q(p[k]) for b, wi, p in zip(basis, w, points)) / den for k in range(len(points[0]))]


def _check_f64(values, companions):
    """Every companion is the correctly rounded value of its exact field (through Fraction)."""
    if isinstance(values, list):
        assert len(values) == len(companions)
        for v, c in zip(values, companions):
            _check_f64(v, c)
    else:
        assert float.fromhex(companions) == _mpfr_round(Fraction(values))


def test_curve_eval_against_sympy_derivatives():
    for rec in _records("curve_eval", 1, degrees=(3,)):
        inp, ans = rec["input"], rec["answer"]
        if rec["family"] in ("high_degree",):
            continue
        curve = _bernstein(inp["control_points"], inp.get("weights"), t)
        for k, s in enumerate(inp["params"]):
            at = {t: Q(s)}
            assert [c.subs(at) for c in curve] == [Q(v) for v in ans["values"][k]]
            assert [sp.diff(c, t).subs(at) for c in curve] == [Q(v) for v in ans["first_derivatives"][k]]
            assert [sp.diff(c, t, 2).subs(at) for c in curve] == [Q(v) for v in ans["second_derivatives"][k]]
        _check_f64(ans["values"], ans["values_f64"])
        _check_f64(inp["params"], inp["params_f64"])


def test_surface_eval_against_sympy_normal():
    u, v = sp.symbols("u v")
    for rec in _records("surface_eval", 1, degrees=(2, 1)):
        if rec["family"] == "high_degree":
            continue
        inp, ans = rec["input"], rec["answer"]
        net, w = inp["control_points"], inp.get("weights")
        l, m = len(net) - 1, len(net[0]) - 1
        B = lambda n, i, x: sp.binomial(n, i) * x**i * (1 - x) ** (n - i)
        wt = lambda i, j, w=w: Q(w[i][j]) if w else 1
        den = sum(B(l, i, u) * B(m, j, v) * wt(i, j) for i in range(l + 1) for j in range(m + 1))
        S = sp.Matrix([sum(B(l, i, u) * B(m, j, v) * wt(i, j) * Q(net[i][j][k]) for i in range(l + 1) for j in range(m + 1)) / den for k in range(3)])
        N = S.diff(u).cross(S.diff(v))
        for k, (pu, pv) in enumerate(inp["params"]):
            at = {u: Q(pu), v: Q(pv)}
            assert [sp.simplify(x.subs(at)) for x in S] == [Q(x) for x in ans["values"][k]]
            assert [sp.simplify(x.subs(at)) for x in N] == [Q(x) for x in ans["normals"][k]]
        _check_f64(ans["normals"], ans["normals_f64"])


def _sympy_bspline(curve, s):
    knots = [Q(k) for k in curve["knots"]]
    p = curve["degree"]
    basis = sp.bspline_basis_set(p, knots, t)
    w = [Q(x) for x in curve["weights"]] if "weights" in curve else [1] * len(basis)
    vals = [b.subs(t, s) for b in basis]
    if s == knots[-1]:  # sympy's basis is right-open: take the last point
        vals = [0] * (len(basis) - 1) + [1]
    den = sum(b * wi for b, wi in zip(vals, w))
    return [sum(b * wi * Q(pt[k]) for b, wi, pt in zip(vals, w, curve["control_points"])) / den for k in range(len(curve["control_points"][0]))]


def test_bspline_kinds_against_sympy_bases():
    for rec in _records("bspline_eval", 2, degrees=(2, 2)):
        inp = rec["input"]
        if inp["object"] == "curve" and rec["family"] != "high_degree":
            for k, s in list(enumerate(inp["params"]))[:2]:
                assert _sympy_bspline(inp, Q(s)) == [Q(x) for x in rec["answer"]["values"][k]]
    for rec in _records("knot_insertion", 1, degrees=(2,)):
        if rec["family"] == "high_degree":
            continue
        inp, ans = rec["input"], rec["answer"]
        refined = {"degree": inp["degree"], "knots": ans["knots"], "control_points": ans["control_points"], **({"weights": ans["weights"]} if "weights" in ans else {})}
        assert len(ans["knots"]) == len(inp["knots"]) + inp["times"]
        for s in (sp.Rational(5, 9), Q(inp["knot"])):
            assert _sympy_bspline(refined, s) == _sympy_bspline(inp, s)
    for rec in _records("bezier_extraction", 1, degrees=(2,)):
        if rec["family"] == "high_degree":
            continue
        inp = rec["input"]
        for seg in rec["answer"]["segments"]:
            a, b = (Q(x) for x in seg["interval"])
            for s in (sp.Rational(3, 4),):
                assert _bernstein(seg["control_points"], seg.get("weights"), s) == _sympy_bspline(inp, a + s * (b - a))


def test_elevation_and_subdivision_against_sympy():
    for rec in _records("degree_elevation", 1):
        inp, ans = rec["input"], rec["answer"]
        assert ans["degree"] == inp["degree"] + inp["times"]
        for s in (sp.Rational(1, 5), sp.Rational(2, 3)):
            assert _bernstein(ans["control_points"], ans.get("weights"), s) == _bernstein(inp["control_points"], inp.get("weights"), s)
    for rec in _records("subdivision", 1):
        inp, ans = rec["input"], rec["answer"]
        if rec["family"] == "high_degree":
            continue
        c = Q(inp["param"])
        s = sp.Rational(2, 7)
        full = lambda x, inp=inp: _bernstein(inp["control_points"], inp.get("weights"), x)
        assert _bernstein(ans["left"]["control_points"], ans["left"].get("weights"), s) == full(c * s)
        assert _bernstein(ans["right"]["control_points"], ans["right"].get("weights"), s) == full(c + (1 - c) * s)


def test_compose_against_sympy_substitution():
    u, v = sp.symbols("u v")
    for rec in _records("compose", 1, degrees=(2, 1, 2)):
        inp, ans = rec["input"], rec["answer"]
        surf, curve = inp["surface"], inp["curve"]
        if surf["type"] != "bezier":
            continue
        net, w = surf["control_points"], surf.get("weights")
        l, m = len(net) - 1, len(net[0]) - 1
        B = lambda n, i, x: sp.binomial(n, i) * x**i * (1 - x) ** (n - i)
        wt = lambda i, j, w=w: Q(w[i][j]) if w else 1
        s = sp.Rational(3, 11)
        uu, vv = _bernstein(curve["control_points"], curve.get("weights"), s)
        at = {u: uu, v: vv}
        den = sum(B(l, i, u) * B(m, j, v) * wt(i, j) for i in range(l + 1) for j in range(m + 1)).subs(at)
        point = [sum(B(l, i, u) * B(m, j, v) * wt(i, j) * Q(net[i][j][k]) for i in range(l + 1) for j in range(m + 1)).subs(at) / den for k in range(3)]
        (piece,) = ans["pieces"]
        assert _bernstein(piece["control_points"], piece.get("weights"), s) == point


def _implicit(terms):
    x, y = sp.symbols("x y")
    return sum(sp.Integer(int(c)) * x**i * y**j for i, j, c in terms), x, y


def _homogeneous_components(points, weights):
    """Bernstein numerators X, Y and denominator W of a planar (rational) curve, in sympy."""
    n = len(points) - 1
    w = [Q(x) for x in weights] if weights else [1] * (n + 1)
    basis = [sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]
    X = sum(b * wi * Q(p[0]) for b, wi, p in zip(basis, w, points))
    Y = sum(b * wi * Q(p[1]) for b, wi, p in zip(basis, w, points))
    return X, Y, sum(b * wi for b, wi in zip(basis, w))


def test_implicitize_and_inversion_against_sympy():
    for rec in _records("implicitize", 2):
        terms = rec["answer"]["equation"]
        d = rec["answer"]["degree"]
        assert d == max(i + j for i, j, _ in terms)
        X, Y, W = _homogeneous_components(rec["input"]["control_points"], rec["input"].get("weights"))
        # f(X/W, Y/W) W^d = sum c X^i Y^j W^(d-i-j) vanishes identically in t
        assert sp.expand(sum(int(c) * X**i * Y**j * W ** (d - i - j) for i, j, c in terms)) == 0
    for rec in _records("inversion", 1):
        num, x, y = _implicit(rec["answer"]["formula"]["numerator"])
        den, _, _ = _implicit(rec["answer"]["formula"]["denominator"])
        for (px, py), s in zip(rec["input"]["points"], rec["answer"]["params"]):
            assert num.subs({x: Q(px), y: Q(py)}) / den.subs({x: Q(px), y: Q(py)}) == Q(s)
            assert _bernstein(rec["input"]["control_points"], rec["input"].get("weights"), Q(s)) == [Q(px), Q(py)]


def _mp_root(alg):
    """The algebraic number refined independently by mpmath bisection inside its interval (60 digits)."""
    lo, hi = (Q(v) for v in alg["interval"])
    if lo == hi:
        return mpmath.mpf(lo.p) / lo.q
    poly = alg["poly"]
    f = lambda z: mpmath.polyval(poly[::-1], z)
    with mpmath.workdps(80):
        a, b = mpmath.mpf(lo.p) / lo.q, mpmath.mpf(hi.p) / hi.q
        fa = f(a)
        for _ in range(250):  # plain bisection on the sign change
            mid = (a + b) / 2
            if (f(mid) > 0) == (fa > 0):
                a, fa = mid, f(mid)
            else:
                b = mid
        return (a + b) / 2


def test_intersections_against_mpmath_and_counts():
    for rec in _records("intersect", 1):
        if rec["family"] == "weights_wide":
            continue
        c1, c2 = rec["input"]["curve1"], rec["input"]["curve2"]
        ans = rec["answer"]
        if rec["family"] == "shared_algebraic":  # a sub-arc: one overlap (plus self-crossings of the shared curve)
            assert len(ans["overlaps"]) == 1
            for ov in ans["overlaps"]:
                for k in range(2):
                    p1 = _bernstein(c1["control_points"], c1.get("weights"), Q(ov["t1"][k]["interval"][0]))
                    p2 = _bernstein(c2["control_points"], c2.get("weights"), Q(ov["t2"][k]["interval"][0]))
                    assert p1 == p2 == [Q(v["interval"][0]) for v in ov["points"][k]]
        with mpmath.workdps(60):
            for hit in ans["intersections"]:
                t1, t2 = _mp_root(hit["t1"]), _mp_root(hit["t2"])
                P1 = [sp.lambdify(t, e, "mpmath")(t1) for e in _bernstein(c1["control_points"], c1.get("weights"), t)]
                P2 = [sp.lambdify(t, e, "mpmath")(t2) for e in _bernstein(c2["control_points"], c2.get("weights"), t)]
                assert max(abs(a - b) for a, b in zip(P1, P2)) < mpmath.mpf(10) ** -40
                assert float(P1[0]) == pytest.approx(float.fromhex(hit["point"][0]["f64"]), rel=1e-15, abs=1e-300)
        if rec["family"] in ("tangency", "higher_contact"):
            assert max(h["multiplicity"] or 1 for h in ans["intersections"]) >= 2
        if rec["family"] == "clustered":
            ts = sorted(float.fromhex(h["t1"]["f64"]) for h in ans["intersections"])
            assert any(b - a < 2.0**-40 for a, b in itertools.pairwise(ts))


def test_roots_against_sympy_real_roots():
    for rec in _records("roots", 2, degrees=(4,)):
        coeffs = [Q(c) for c in rec["input"]["coefficients"]]
        n = len(coeffs) - 1
        p = sp.Poly(sum(c * sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i, c in enumerate(coeffs)), t)
        factors = sp.factor_list(p)[1]
        want = sorted(((r, m) for f, m in factors for r in sp.Poly(f, t).real_roots() if 0 <= r <= 1), key=lambda rm: float(rm[0]))
        got = rec["answer"]["roots"]
        assert [m for _, m in want] == [r["multiplicity"] for r in got]
        for (r, _), root in zip(want, got):
            lo, hi = (Q(v) for v in root["value"]["interval"])
            assert lo <= r <= hi
            assert float.fromhex(root["value"]["f64"]) == float(sp.N(r, 60))


def test_every_kind_validates_and_a_broken_record_does_not():
    for kind in KINDS:
        validator = jsonschema.Draft202012Validator(kind_schema(kind))
        for rec in _records(kind, 1):
            validator.validate(rec)
    rec = next(_records("roots", 1))
    rec["input"]["coefficients"][0] = 0.5  # a float where an exact number belongs
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.Draft202012Validator(kind_schema("roots")).validate(rec)


def test_published_schemas_are_up_to_date():
    for kind in KINDS:
        assert schema_path(kind).read_text(encoding="utf-8") == schema_text(kind), f"run python -m exactcagd.refdata.schemagen ({kind})"
        jsonschema.Draft202012Validator.check_schema(json.loads(schema_path(kind).read_text()))


def _walk_pairs(node, out):
    """Collect (exact, companion) pairs: every key X with a sibling X_f64, and every algebraic number."""
    if isinstance(node, dict):
        if set(node) == {"poly", "interval", "f64"}:
            out.append(("algebraic", node))
            return
        for key, value in node.items():
            if key.endswith("_f64"):
                assert key[:-4] in node, f"companion {key} without its exact field"
                out.append(("pair", (node[key[:-4]], value)))
            else:
                _walk_pairs(value, out)
    elif isinstance(node, list):
        for item in node:
            _walk_pairs(item, out)


def _exact_leaves(exact_value, companion):
    if isinstance(exact_value, list):
        assert isinstance(companion, list) and len(exact_value) == len(companion)
        for e, c in zip(exact_value, companion):
            yield from _exact_leaves(e, c)
    else:
        yield exact_value, companion


def test_every_exact_value_has_a_correctly_rounded_companion():
    """Walk one record of every kind and family: each X_f64 is MPFR's rounding of X; each algebraic
    number's polynomial changes sign on its interval and its f64 is the rounding of the root refined by mpmath."""
    checked = 0
    for kind in KINDS:
        for rec in _records(kind, 1):
            pairs = []
            _walk_pairs(rec, pairs)
            for what, item in pairs:
                if what == "pair":
                    for e, c in _exact_leaves(*item):
                        assert isinstance(e, int) or "/" in e
                        assert c == float.hex(_mpfr_round(Fraction(e)))
                        checked += 1
                    continue
                lo, hi = (Fraction(v) for v in item["interval"])
                poly = item["poly"]
                value = lambda x, poly=poly: sum(c * x**k for k, c in enumerate(poly))
                if lo == hi:
                    assert value(lo) == 0 and item["f64"] == float.hex(_mpfr_round(lo))
                else:
                    assert value(lo) * value(hi) < 0
                    with mpmath.workdps(80):
                        root = _mp_root(item)
                        assert float.fromhex(item["f64"]) == float(mpmath.mpf(root))
                checked += 1
    assert checked > 1000

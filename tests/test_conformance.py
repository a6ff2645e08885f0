"""``exactcagd conformance``: suite checks, the error measures, the grader, and runs on peers.

References are independent of the grader: ulp distances against ``numpy.nextafter``
stepping, scaled ulps against ``fractions.Fraction``, planted answers (exact answers
perturbed by a known number of ulps, a dropped or duplicated root) whose grades are
known in advance, and the peers' own results on data where they are known to be right.
"""

from __future__ import annotations

import json
import math
import re
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.cli import main
from exactcagd.errors import InputError, NotSupportedError
from exactcagd.refdata import conformance as conf
from exactcagd.refdata.adapters import load_adapter
from exactcagd.refdata.adapters.base import Adapter, Unsupported

KINDS = ["curve_eval", "surface_eval", "bspline_eval", "knot_insertion", "bezier_extraction", "degree_elevation",
         "subdivision", "compose", "inversion", "intersect", "roots"]


@pytest.fixture(scope="session")
def suite(tmp_path_factory):
    """A small suite (2 records per family; implicitize left out: no peer answers it)."""
    from exactcagd.refdata.suite import write_suite

    path = tmp_path_factory.mktemp("suite") / "small"
    write_suite(path, count=2, kinds=KINDS)
    return path


# ----------------------------------------------------------------------------- measures
finite = st.floats(allow_nan=False, allow_infinity=False)


@settings(max_examples=200, deadline=None)
@given(finite, st.integers(0, 300), st.sampled_from([-math.inf, math.inf]))
def test_ulp_distance_counts_nextafter_steps(x, k, direction):
    y = x
    for _ in range(k):
        if math.isinf(y):
            return
        y = float(np.nextafter(y, direction))
    if math.isinf(y):
        return
    assert conf.ulp_distance(y, x) == k
    assert conf.ulp_distance(x, y) == k


def test_ulp_distance_special_values():
    tiny = 5e-324
    assert conf.ulp_distance(-tiny, tiny) == 2
    assert conf.ulp_distance(0.0, -0.0) == 0
    assert conf.ulp_distance(math.inf, math.inf) == 0
    assert conf.ulp_distance(1.0, math.inf) == math.inf
    assert conf.ulp_distance(math.nan, 1.0) == math.inf


@settings(max_examples=100, deadline=None)
@given(finite, finite, st.floats(min_value=1e-300, max_value=1e300))
def test_scaled_ulps_is_exact_difference_over_ulp_of_scale(a, b, scale):
    expected = abs(Fraction(a) - Fraction(b)) / Fraction(math.ulp(scale))
    assert conf.scaled_ulps(a, b, scale) == (float(expected) if expected < 2**1024 else math.inf)


def test_stats_percentiles():
    s = conf.Stats()
    for x in range(1, 201):
        s.add(float(x))
    assert s.summary() == {"n": 200, "max": 200.0, "median": 100.5, "p99": 198.0}


# ----------------------------------------------------------------------------- suite checks
def test_open_suite_accepts_a_fresh_suite(suite):
    opened = conf.open_suite(suite)
    assert set(KINDS) == set(opened.kinds)
    assert sum(1 for _ in opened.records("roots")) == opened.count("roots") > 0


def _copy(suite, tmp_path) -> Path:
    import shutil

    target = tmp_path / "copy"
    shutil.copytree(suite, target)
    return target


@pytest.mark.parametrize("damage, words", [
    ("no-folder", "is not a folder"),
    ("no-manifest", "has no manifest.json"),
    ("bad-json", "is not valid JSON"),
    ("version", "format_version '2.0'"),
    ("hash", "does not match its sha256"),
    ("missing-file", "is missing from"),
])
def test_open_suite_refuses_damaged_suites(suite, tmp_path, damage, words, capsys):
    path = _copy(suite, tmp_path)
    manifest = path / "manifest.json"
    if damage == "no-folder":
        path = path / "roots.jsonl"
    elif damage == "no-manifest":
        manifest.unlink()
    elif damage == "bad-json":
        manifest.write_text("{not json")
    elif damage == "version":
        data = json.loads(manifest.read_text())
        data["format_version"] = "2.0"
        manifest.write_text(json.dumps(data))
    elif damage == "hash":
        with open(path / "roots.jsonl", "a") as handle:
            handle.write("\n")
    elif damage == "missing-file":
        (path / "roots.jsonl").unlink()
    with pytest.raises(InputError, match=re.escape(words)):
        conf.open_suite(path)
    assert main(["conformance", "--kernel", "geomdl", "--suite", str(path), "--out", str(tmp_path / "r")]) == 2
    assert words in capsys.readouterr().err


# ----------------------------------------------------------------------------- grader on planted answers
def _hex(x) -> float:
    return float.fromhex(x)


def _nudge(x: float, k: int) -> float:
    for _ in range(k):
        x = float(np.nextafter(x, math.inf))
    return x


def _separated(answer) -> bool:
    """At least two roots, all simple and 1e-3 apart: dropping or inventing one is unambiguous."""
    roots = sorted(_hex(r["value"]["f64"]) for r in answer)
    return len(roots) >= 2 and all(r["multiplicity"] == 1 for r in answer) and min(np.diff(roots)) > 1e-3


def _far_from(roots) -> float:
    return max((k / 1000 for k in range(1001)), key=lambda x: min(abs(x - r) for r in roots))


class PlantedAdapter(Adapter):
    """Answers from the exact answer itself, with known damage (the test knows the grades)."""

    name, kinds = "planted", ("bspline_eval", "roots", "knot_insertion")

    def __init__(self, record_answers):
        self.answers = record_answers  # id -> answer
        self.current = None

    def bspline_eval(self, inp):
        values = np.vectorize(_hex)(np.array(self.answers[self.current]["values_f64"], dtype=object)).astype(float)
        values[0, 0] = _nudge(values[0, 0], 7)  # one value 7 ulps up
        return {"values": values}

    def roots(self, inp):
        answer = self.answers[self.current]["roots"]
        if _separated(answer):
            roots = [_hex(r["value"]["f64"]) for r in answer]
            return {"roots": roots[1:] + [_far_from(roots)]}  # the first missed, one invented
        raise ValueError("planted crash")

    def knot_insertion(self, inp):
        raise Unsupported("planted limit")


def test_grader_reports_planted_errors(suite):
    opened = conf.open_suite(suite)
    adapter = PlantedAdapter({})
    results = {}
    for kind in adapter.kinds:
        result = conf.KindResult(kind)
        for record in opened.records(kind):
            adapter.answers[record["id"]] = record["answer"]
            adapter.current = record["id"]
            conf.grade_record(result, adapter, record)
        results[kind] = result.to_json()
    ev = results["bspline_eval"]
    assert ev["fields"]["values"]["ulps"]["max"] == 7 and ev["crashes"] == 0
    assert ev["fields"]["values"]["ulps"]["median"] == 0
    assert ev["worst"][0]["ulps"] == 7
    roots_records = [r for r in opened.records("roots")]
    multi = [r for r in roots_records if _separated(r["answer"]["roots"])]
    assert multi
    assert results["roots"]["missed"] == len(multi) and results["roots"]["extra"] == len(multi)
    assert results["roots"]["crashes"] == len(roots_records) - len(multi)
    assert results["roots"]["crash_examples"][0]["error"] == "ValueError: planted crash"
    ki = results["knot_insertion"]
    assert ki["unsupported"] == ki["records"] and ki["unsupported_reasons"] == {"planted limit": ki["records"]}


def _match(computed, exact):
    result = conf.KindResult("roots")
    grader = conf._Grader(result, {"id": "roots/x/0", "family": "x", "kind": "roots"})
    conf._match_solutions(grader, "roots", computed, exact)
    return result.missed, result.extra, result.unresolved


def test_matching_tolerance_follows_multiplicity():
    # a double root computed 1e-7 away is found (sqrt(eps) conditioning); a simple one 1e-5 away is not
    assert _match([(0.5 + 1e-7,), (0.25 + 1e-5,)], [((0.5,), 2), ((0.25,), 1)]) == (1, 1, 0)
    # a triple root may move by eps^(1/3) ~ 6e-6: found; three answers for it are allowed, a fourth is extra
    assert _match([(0.5 + 5e-5,)], [((0.5,), 3)]) == (0, 0, 0)
    assert _match([(0.5,)] * 4, [((0.5,), 3)]) == (0, 1, 0)


def test_matching_clusters():
    # two simple roots 2^-41 apart: one answer is an unresolved cluster, not a miss; none is two misses
    pair = [((0.3,), 1), ((0.3 + 2.0**-41,), 1)]
    assert _match([(0.3 + 1e-9,)], pair) == (0, 0, 1)
    assert _match([], pair) == (2, 0, 0)
    assert _match([(0.3,), (0.3 + 2.0**-41,)], pair) == (0, 0, 0)
    # roots far apart are separate clusters
    assert _match([(0.1,)], [((0.1,), 1), ((0.9,), 1)]) == (1, 0, 0)


# ----------------------------------------------------------------------------- adapters
def test_load_adapter_errors(monkeypatch):
    with pytest.raises(InputError, match="unknown kernel 'parasolid'"):
        load_adapter("parasolid")
    with pytest.raises(InputError, match="cannot import 'no_such_module'"):
        load_adapter("no_such_module:Kernel")
    with pytest.raises(InputError, match="has no class 'Nope'"):
        load_adapter("exactcagd.refdata.adapters.base:Nope")
    from exactcagd.refdata import exporters

    real = exporters.importlib.import_module

    def fake(name, *args):
        if name.split(".")[0] == "OCP":
            raise ImportError("No module named 'OCP'")
        return real(name, *args)

    monkeypatch.setattr(exporters.importlib, "import_module", fake)
    with pytest.raises(NotSupportedError, match="'cadquery-ocp' is not installed"):
        load_adapter("occ")


def _report(tmp_path, suite, kernel, *extra):
    out = tmp_path / f"report-{kernel}"
    assert main(["conformance", "--kernel", kernel, "--suite", str(suite), "--out", str(out), "--quiet", *extra]) == 0
    assert (out / "report.md").is_file() and (out / "errors.png").stat().st_size > 1000
    return json.loads((out / "report.json").read_text()), (out / "report.md").read_text()


def test_geomdl_conformance_run(suite, tmp_path):
    pytest.importorskip("geomdl")
    report, text = _report(tmp_path, suite, "geomdl")
    kinds = report["kinds"]
    assert set(kinds) == {"curve_eval", "surface_eval", "bspline_eval", "knot_insertion", "bezier_extraction",
                          "degree_elevation", "subdivision"}
    assert "intersect" in report["not_supported_kinds"]
    # on random data geomdl is a correct float kernel: a few scaled ulps (exact de Boor reference)
    for kind in ("bspline_eval", "degree_elevation", "knot_insertion"):
        assert kinds[kind]["families"]["random"]["max_scaled_ulps"] <= 64, kind
        assert kinds[kind]["families"]["random"]["crashes"] == 0
    assert "# Conformance of geomdl" in text and "| bspline_eval |" in text


def test_bezier_conformance_run(suite, tmp_path):
    pytest.importorskip("bezier")
    report, _ = _report(tmp_path, suite, "bezier", "--kinds", "curve_eval,roots,intersect")
    kinds = report["kinds"]
    assert set(kinds) == {"curve_eval", "roots", "intersect"}
    assert kinds["curve_eval"]["unsupported_reasons"].get("bezier has no rational curves", 0) > 0
    assert kinds["curve_eval"]["families"]["random"]["max_scaled_ulps"] <= 64
    assert kinds["roots"]["families"]["random"]["missed"] == 0


def test_occ_conformance_run(suite, tmp_path):
    pytest.importorskip("OCP")
    report, text = _report(tmp_path, suite, "occ", "--kinds", "bspline_eval,compose,intersect")
    kinds = report["kinds"]
    assert kinds["bspline_eval"]["families"]["random"]["max_scaled_ulps"] <= 64
    assert kinds["compose"]["estimate_ratio"]["n"] == kinds["compose"]["answered"] > 0
    assert kinds["intersect"]["families"]["random"]["crashes"] == 0


def test_unknown_kind_and_limit(suite, tmp_path, capsys):
    assert main(["conformance", "--kernel", "geomdl", "--suite", str(suite), "--out", str(tmp_path / "r"), "--kinds", "nope"]) == 2
    assert "'nope' is not in this suite" in capsys.readouterr().err
    report, _ = _report(tmp_path, suite, "geomdl", "--limit", "1", "--kinds", "curve_eval")
    assert report["kinds"]["curve_eval"]["records"] == 1


def test_docs_example_adapter_runs(suite, tmp_path, monkeypatch):
    """The page-of-code adapter in docs/conformance.md works as printed."""
    doc = (Path(__file__).resolve().parents[1] / "docs" / "conformance.md").read_text()
    code = re.search(r"```python\n# my_kernel.py\n(.*?)```", doc, re.S).group(1)
    (tmp_path / "my_kernel.py").write_text(code)
    monkeypatch.syspath_prepend(str(tmp_path))
    sys.modules.pop("my_kernel", None)
    report, _ = _report(tmp_path, suite, "my_kernel:NumpyKernel")
    assert set(report["kinds"]) == {"curve_eval", "roots"}
    assert report["kinds"]["curve_eval"]["families"]["random"]["max_scaled_ulps"] <= 64


def test_compose_under_estimate_is_charged_above_noise_only(suite):
    from gmpy2 import mpq

    record = next(conf.open_suite(suite).records("compose"))
    ts = [k / 8 for k in range(9)]
    exact = [conf._exact_composed_point(record["input"], mpq(t)) for t in ts]

    def grade(offset, claimed):
        result = conf.KindResult("compose")
        points = [[float(x) + offset for x in p] for p in exact]
        conf._grade_compose(conf._Grader(result, record), {"params": ts, "points": points, "claimed_error": claimed}, record)
        return result.under_estimates

    assert grade(1e-9, 1e-12) == 1  # 1e-9 off, 1e-12 claimed: an under-estimate
    assert grade(1e-9, 1e-8) == 0  # honest claim
    assert grade(0.0, 0.0) == 0  # correctly rounded samples against a claim of 0: float noise


def test_bad_output_folder(suite, tmp_path, capsys):
    target = tmp_path / "a-file"
    target.write_text("x")
    for out in ("/dev/null", str(target)):
        assert main(["conformance", "--kernel", "geomdl", "--suite", str(suite), "--out", out]) == 2
        assert "--out" in capsys.readouterr().err
    assert target.read_text() == "x"


def test_rounded_data_answer_is_the_exact_answer_for_the_float_data(suite):
    """The floor's reference: exact values of the *rounded* data, checked with sympy's Bernstein sum."""
    import sympy

    record = next(r for r in conf.open_suite(suite).records("curve_eval") if "weights" in r["input"])
    inp = record["input"]
    pts = [[sympy.Rational(Fraction(_hex(x))) for x in p] for p in inp["control_points_f64"]]
    w = [sympy.Rational(Fraction(_hex(x))) for x in inp["weights_f64"]]
    n = len(pts) - 1
    got = conf.rounded_data_answer(record)["values"]
    for k, t in enumerate(inp["params_f64"]):
        t = sympy.Rational(Fraction(_hex(t)))
        basis = [sympy.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]
        den = sum(w[i] * basis[i] for i in range(n + 1))
        for d in range(len(pts[0])):
            value = sum(w[i] * pts[i][d] * basis[i] for i in range(n + 1)) / den
            assert sympy.Rational(Fraction(int(got[k][d].numerator), int(got[k][d].denominator))) == value
    assert conf.rounded_data_answer(next(conf.open_suite(suite).records("roots"))) is None

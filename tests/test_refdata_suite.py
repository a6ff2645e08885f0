"""Reference suites: byte-identical from 1 job, 2 jobs and a Dask LocalCluster; every file
validates against its published schema; the manifest's hashes and counts match the files;
bad input is refused before any work; ``--format bezier`` writes the bezier package's fixture layout."""
import hashlib
import json
import os

import jsonschema
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.cli import main
from exactcagd.errors import InputError, OutputError
from exactcagd.refdata import manifest as manifest_mod
from exactcagd.refdata.kinds import KINDS
from exactcagd.refdata.suite import write_kind, write_suite

SMALL_KINDS = ["roots", "curve_eval", "intersect"]


@pytest.fixture(autouse=True)
def _fixed_commit(monkeypatch):
    # other commits may land between two runs of a test; the manifest's commit is not what is compared
    monkeypatch.setattr(manifest_mod, "git_commit", lambda: "0" * 40)


def _tree_bytes(folder):
    return {p: (folder / p).read_bytes() for p in sorted(os.listdir(folder)) if (folder / p).is_file()}


def test_suite_bytes_do_not_depend_on_the_executor(tmp_path):
    one = write_suite(tmp_path / "one", seed=3, count=2, kinds=SMALL_KINDS, jobs=1)
    two = write_suite(tmp_path / "two", seed=3, count=2, kinds=SMALL_KINDS, jobs=2)
    assert one == two
    assert _tree_bytes(tmp_path / "one") == _tree_bytes(tmp_path / "two")
    write_suite(tmp_path / "again", seed=3, count=2, kinds=SMALL_KINDS, jobs=1)
    assert _tree_bytes(tmp_path / "one") == _tree_bytes(tmp_path / "again")
    write_suite(tmp_path / "other", seed=4, count=2, kinds=SMALL_KINDS, jobs=1)
    assert (tmp_path / "one" / "roots.jsonl").read_bytes() != (tmp_path / "other" / "roots.jsonl").read_bytes()


def test_dask_local_cluster_gives_the_same_bytes(tmp_path, capsys):
    distributed = pytest.importorskip("distributed")
    write_suite(tmp_path / "local", seed=2, count=2, kinds=SMALL_KINDS, jobs=1)
    write_suite(tmp_path / "dask", seed=2, count=2, kinds=SMALL_KINDS, jobs=2, dask=True)
    assert _tree_bytes(tmp_path / "local") == _tree_bytes(tmp_path / "dask")
    assert capsys.readouterr().err.count("dask dashboard:") == 1  # one cluster for the whole suite
    write_kind(tmp_path / "local.jsonl", "roots", 12, seed=2, family="all", jobs=2)
    # an existing cluster (--scheduler ADDR); threads only, to keep the test quick
    with distributed.LocalCluster(n_workers=1, processes=False, dashboard_address=None) as cluster:
        write_kind(tmp_path / "sched.jsonl", "roots", 12, seed=2, family="all", jobs=2, scheduler=cluster.scheduler_address)
    assert (tmp_path / "sched.jsonl").read_bytes() == (tmp_path / "local.jsonl").read_bytes()


def test_progress_bar_only_on_a_terminal_or_when_asked(tmp_path, capsys):
    assert main(["refdata", "roots", "--count", "3", "--out", str(tmp_path / "a.jsonl"), "--jobs", "1"]) == 0
    assert "rec/s" not in capsys.readouterr().err  # stderr is not a terminal under pytest
    assert main(["refdata", "roots", "--count", "3", "--out", str(tmp_path / "b.jsonl"), "--jobs", "1", "--progress"]) == 0
    err = capsys.readouterr().err
    assert "3/3" in err and "rec/s" in err and "ETA" in err
    assert (tmp_path / "a.jsonl").read_bytes() == (tmp_path / "b.jsonl").read_bytes()


def test_every_file_of_a_suite_validates_and_matches_its_manifest(tmp_path):
    out = tmp_path / "suite"
    manifest = write_suite(out, seed=0, count=1, jobs=2)
    on_disk = json.loads((out / "manifest.json").read_text())
    assert on_disk == manifest
    assert manifest["kinds"] == list(KINDS)
    assert set(manifest["dependencies"]) >= {"gmpy2", "python-flint", "sympy"}
    for kind in manifest["kinds"]:
        schema_file = out / manifest["schemas"][kind]["file"]
        assert hashlib.sha256(schema_file.read_bytes()).hexdigest() == manifest["schemas"][kind]["sha256"]
        validator = jsonschema.Draft202012Validator(json.loads(schema_file.read_text()))
        data = out / f"{kind}.jsonl"
        entry = manifest["files"][f"{kind}.jsonl"]
        assert hashlib.sha256(data.read_bytes()).hexdigest() == entry["sha256"]
        lines = data.read_text().splitlines()
        assert len(lines) == entry["records"] == sum(manifest["counts"][kind].values())
        families = []
        for line in lines:
            record = json.loads(line)
            validator.validate(record)
            families.append(record["family"])
        assert families == list(KINDS[kind].families)  # one record per family, in family order


def test_records_are_in_index_order_and_ids_are_unique(tmp_path):
    out = tmp_path / "r.jsonl"
    assert main(["refdata", "roots", "--count", "7", "--family", "all", "--out", str(out), "--jobs", "2"]) == 0
    ids = [json.loads(line)["id"] for line in out.read_text().splitlines()]
    assert len(ids) == len(set(ids)) == 7 * len(KINDS["roots"].families)
    first = [i for i in ids if i.startswith("roots/random/")]
    assert first == [f"roots/random/{k}" for k in range(7)]


@pytest.mark.parametrize(
    "argv, needle",
    [
        (["refdata", "nosuchkind"], "unknown refdata kind"),
        (["refdata", "roots", "--degree", "0"], "--degree"),
        (["refdata", "roots", "--degree", "x"], "--degree"),
        (["refdata", "roots", "--degree", "41"], "--degree"),
        (["refdata", "roots", "--degree", "3,3"], "--degree"),
        (["refdata", "compose", "--degree", "2,1,2,2"], "--degree"),
        (["refdata", "intersect", "--degree", "30"], "--degree"),
        (["refdata", "roots", "--count", "0"], "--count"),
        (["refdata", "roots", "--count", "-3"], "--count"),
        (["refdata", "roots", "--count", "100000000000"], "--count"),
        (["refdata", "roots", "--jobs", "0"], "--jobs"),
        (["refdata", "roots", "--family", "nurbs"], "--family"),
        (["refdata", "roots", "--out", "/dev/null"], "--out"),
        (["refdata", "roots", "--format", "bezier", "--out", "-"], "--out"),
        (["refdata", "roots", "--format", "xml"], "--format"),
        (["refdata", "suite"], "--out"),
        (["refdata", "suite", "--out", "/tmp/x", "--degree", "3"], "--degree"),
    ],
)
def test_bad_input_is_refused_with_the_argument_named(argv, needle, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert needle in err and "error" in err


def test_output_that_is_a_directory_or_device_is_refused_before_work(tmp_path, monkeypatch):
    calls = []
    from exactcagd.refdata import stream

    monkeypatch.setattr(stream, "make_record", lambda *a: calls.append(a))
    with pytest.raises(OutputError):
        write_kind(tmp_path, "roots", 3)  # a directory
    with pytest.raises(OutputError):
        write_kind("/dev/null", "roots", 3)
    (tmp_path / "file").write_text("x")
    with pytest.raises(OutputError):
        write_suite(tmp_path / "file", count=1)  # a file where a folder belongs
    with pytest.raises(InputError):
        write_kind(tmp_path / "x.jsonl", "roots", 0)
    assert calls == []


def test_stdout_output(capsys):
    assert main(["refdata", "subdivision", "--count", "2", "--jobs", "1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert [json.loads(line)["id"] for line in lines] == ["subdivision/random/0", "subdivision/random/1"]


def _convert_float(value):
    """The bezier harness's number reader (tests/functional/utils.py), re-stated: int, hex or 'N/D'."""
    if isinstance(value, list):
        return [_convert_float(v) for v in value]
    if isinstance(value, int):
        return float(value)
    if value.startswith(("0x", "-0x")):
        return float.fromhex(value)
    numerator, denominator = value.split("/")
    return float(numerator) / float(denominator)


def test_bezier_fixture_layout(tmp_path):
    out = tmp_path / "bezier"
    assert main(["refdata", "intersect", "--format", "bezier", "--family", "all", "--count", "2", "--out", str(out), "--jobs", "2"]) == 0
    curves = json.loads((out / "curves.json").read_text())
    cases = json.loads((out / "curve_intersections.json").read_text())
    assert cases and isinstance(curves, dict)
    allowed_case = {"curve1", "curve2", "id", "type", "note", "intersections", "curve1_params", "curve1_polys", "curve2_params", "curve2_polys"}
    for key, info in curves.items():
        assert key.isdigit() and set(info) <= {"control_points", "implicitized", "note"}
        nodes = _convert_float(info["control_points"])
        assert len(nodes) == 2 and len(nodes[0]) == len(nodes[1]) >= 2
    types = set()
    for case in cases:
        assert set(case) <= allowed_case and case["curve1"] in curves and case["curve2"] in curves
        types.add(case["type"])
        n = len(case["curve1_params"])
        s = _convert_float(case["curve1_params"])
        assert s == sorted(s), "the harness requires increasing curve1_params"
        assert len(case["curve2_params"]) == len(case["curve1_polys"]) == len(case["curve2_polys"]) == n
        assert [len(row) for row in case["intersections"]] == [n, n]
        # each parameter is a root of its polynomial (the polynomials are exact, the values rounded)
        for params, polys in (("curve1_params", "curve1_polys"), ("curve2_params", "curve2_polys")):
            assert all(isinstance(c, int) for poly in case[polys] for c in poly)  # the harness requires integers
            for value, poly in zip(_convert_float(case[params]), case[polys]):
                scale = sum(abs(c) for c in poly)
                assert abs(sum(c * value**k for k, c in enumerate(poly))) <= 1e-12 * scale
    assert {"tangent", "coincident"} <= types
    bezier = pytest.importorskip("bezier")
    import numpy as np

    for case in cases[:5]:
        c1 = bezier.Curve.from_nodes(np.asfortranarray(_convert_float(curves[case["curve1"]]["control_points"])))
        point = c1.evaluate(_convert_float(case["curve1_params"])[0]) if case["curve1_params"] else None
        if point is not None:
            expected = _convert_float([row[0] for row in case["intersections"]])
            assert np.allclose(point.ravel(), expected, atol=1e-9)


def test_bezier_fixture_implicitized_triples(tmp_path):
    out = tmp_path / "bz"
    assert main(["refdata", "implicitize", "--format", "bezier", "--count", "4", "--out", str(out), "--jobs", "1"]) == 0
    curves = json.loads((out / "curves.json").read_text())
    assert json.loads((out / "curve_intersections.json").read_text()) == []
    import sympy as sp

    x, y, s = sp.symbols("x y s")
    for info in curves.values():
        xs, ys = ([sp.Rational(str(v)) for v in row] for row in info["control_points"])
        n = len(xs) - 1
        X = sum(sp.binomial(n, i) * s**i * (1 - s) ** (n - i) * xs[i] for i in range(n + 1))
        Y = sum(sp.binomial(n, i) * s**i * (1 - s) ** (n - i) * ys[i] for i in range(n + 1))
        f = sum(c * x**i * y**j for c, i, j in info["implicitized"])
        assert sp.expand(f.subs({x: X, y: Y})) == 0
        assert info["implicitized"][0][0] > 0
        order = [(i + j, i) for _, i, j in info["implicitized"]]
        assert order == sorted(order)


@pytest.mark.slow
def test_standard_suite_is_reproducible_and_valid(tmp_path):
    """The full standard suite (about 4,500 records): 1 job and 2 jobs give the same bytes, every record validates."""
    write_suite(tmp_path / "a", jobs=2)
    write_suite(tmp_path / "b", jobs=1)
    assert _tree_bytes(tmp_path / "a") == _tree_bytes(tmp_path / "b")
    manifest = json.loads((tmp_path / "a" / "manifest.json").read_text())
    assert 3000 <= sum(f["records"] for f in manifest["files"].values()) <= 6000
    for kind in manifest["kinds"]:
        validator = jsonschema.Draft202012Validator(json.loads((tmp_path / "a" / manifest["schemas"][kind]["file"]).read_text()))
        for line in (tmp_path / "a" / f"{kind}.jsonl").read_text().splitlines():
            validator.validate(json.loads(line))


@settings(max_examples=200, deadline=None)
@given(st.integers(1, 5000), st.integers(1, 64))
def test_batches_partition_the_indices_in_order(count, workers):
    from exactcagd.refdata.stream import MAX_BATCH, plan_batches

    batches = plan_batches("roots", "random", count, 0, (3,), workers)
    assert [i for b in batches for i in range(b.start, b.stop)] == list(range(count))
    assert all(1 <= b.size <= MAX_BATCH for b in batches)


@settings(max_examples=25, deadline=None)
@given(st.integers(-(2**40), 2**40), st.integers(0, 10**6), st.sampled_from(["roots", "subdivision", "degree_elevation"]))
def test_a_record_depends_only_on_its_identity(seed, index, kind):
    from exactcagd.refdata.kinds import make_record
    from exactcagd.refdata.stream import BatchSpec, batch_lines, record_line

    spec = KINDS[kind]
    line = record_line(make_record(kind, "random", seed, index, spec.default_degrees))
    assert batch_lines(BatchSpec(kind, "random", seed, spec.default_degrees, index, index + 1)) == [line]
    assert json.loads(line)["id"] == f"{kind}/random/{index}"

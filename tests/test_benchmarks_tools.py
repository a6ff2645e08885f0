"""Tests of the benchmark machinery: runner conventions, RUNS.md merging, optional peers,
and the error measurement of the curve-on-surface benchmark (against closed-form distances)."""

from __future__ import annotations

import sys
import types

import numpy as np
import pytest
from gmpy2 import mpq

import benchmarks._common as common
from benchmarks.__main__ import call_main, write_runs
from benchmarks.bench_peers_curve_on_surface import Pieces, _elevate_float, distance_to, hausdorff
from benchmarks.bench_peers_evaluate import max_error
from exactcagd import BezierCurve


def test_call_main_both_conventions():
    seen = []
    call_main(types.SimpleNamespace(main=lambda: seen.append(common.parse_quick("x"))), True)
    call_main(types.SimpleNamespace(main=lambda quick=False: seen.append(quick)), True)
    assert seen == [True, True]
    assert common.RUNNER_QUICK is None


def test_write_runs_merges_within_a_mode(tmp_path, monkeypatch):
    monkeypatch.setattr(common, "RESULTS", tmp_path)  # the runner reads the one results root there (bench --out sets it)
    write_runs([["bench_a", "quick", "t", "ok", "1.0", "1 MB"], ["bench_b", "quick", "t", "ok", "2.0", "1 MB"]], True)
    write_runs([["bench_b", "quick", "t2", "FAILED: x", "3.0", "2 MB"]], True)
    text = (tmp_path / "RUNS.md").read_text()
    assert "| bench_a | quick | t | ok | 1.0 | 1 MB |" in text
    assert "| bench_b | quick | t2 | FAILED: x | 3.0 | 2 MB |" in text
    assert "| bench_b | quick | t | ok" not in text
    # a full run keeps its own record and leaves the quick one alone
    write_runs([["bench_b", "full", "t3", "ok", "9.0", "3 MB"]], False)
    assert "| bench_b | full | t3 | ok | 9.0 | 3 MB |" in (tmp_path / "full" / "RUNS.md").read_text()
    assert (tmp_path / "RUNS.md").read_text() == text


def test_quick_and_full_runs_never_share_result_files(tmp_path, monkeypatch):
    """A quick run must not replace the committed full-mode tables (and vice versa)."""
    monkeypatch.setattr(common, "RESULTS", tmp_path)
    written = []
    module = types.SimpleNamespace(main=lambda quick=False: written.append(common.write_result("topic", "T", f"quick={quick}")))
    call_main(module, True)
    call_main(module, False)
    assert written == [tmp_path / "topic.md", tmp_path / "full" / "topic.md"]
    assert "quick=True" in written[0].read_text() and "quick=False" in written[1].read_text()
    monkeypatch.setattr(common, "_PARSED_QUICK", None)  # restored after the test: parse_quick sets it
    monkeypatch.setattr(sys, "argv", ["bench_x", "--quick"])
    assert common.parse_quick("x") and common.results_dir() == tmp_path


def test_optional_peer_absent(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "no_such_peer_pkg", None)
    assert common.optional_peer("no_such_peer_pkg", "rows") is None
    assert "SKIP rows" in capsys.readouterr().out


def test_ratio_and_bytes():
    assert common.ratio(3.0, 1.5) == "2x"
    assert common.ratio(1.0, 0) == "-"
    assert common.fmt_bytes(3 << 20) == "3.0 MB"


def test_max_error_exact():
    exact = [[mpq(1, 3), mpq(0)]]
    third = mpq(*(1 / 3).as_integer_ratio())
    expected = max(abs(third - mpq(1, 3)), mpq(2) ** -60)
    assert max_error(np.array([[1 / 3, 2.0**-60]]), exact) == float(expected)


def test_elevate_float_matches_exact():
    c = BezierCurve([[0, 0, 0], [1, 2, 0], [3, 1, 1]], [1, 2, 3])
    hom = np.vectorize(float, otypes=[float])(c.homogeneous())
    mine = _elevate_float(hom, 5)
    ref = np.vectorize(float, otypes=[float])(c.elevate(3).homogeneous())
    assert np.allclose(mine, ref, rtol=1e-15, atol=0)


def test_hausdorff_parallel_segments():
    a = BezierCurve([[0, 0, 0], [mpq(1, 3), 0, 0], [mpq(2, 3), 0, 0], [1, 0, 0]])
    b = BezierCurve([[0, mpq(1, 1000), 0], [1, mpq(1, 1000), 0]])
    assert hausdorff(Pieces.from_curves([a]), Pieces.from_curves([b])) == pytest.approx(1e-3, rel=1e-9)


def test_hausdorff_circles_through_joints():
    """Quarter arcs of radius 1 and 1 + d (the second split in 3 pieces): distance d exactly."""
    def arc(r):
        # x = r (1 - t^2)/(1 + t^2), y = 2 r t/(1 + t^2): homogeneous Bernstein data give weights 1, 1, 2
        return BezierCurve([[r, 0, 0], [r, r, 0], [0, r, 0]], [1, 1, 2])

    d = mpq(1, 10**6)
    inner = arc(mpq(1))
    outer = arc(1 + d)
    pieces = [outer.reparametrize(mpq(0), mpq(1, 3)), outer.reparametrize(mpq(1, 3), mpq(2, 3)),
              outer.reparametrize(mpq(2, 3), mpq(1))]
    # independent check that the data are circles: |P(1/2)| = r
    x, y, _ = inner.evaluate(mpq(1, 2))
    assert x * x + y * y == 1
    h = hausdorff(Pieces.from_curves(pieces), Pieces.from_curves([inner]))
    assert h == pytest.approx(float(d), rel=1e-6)
    pts = Pieces.from_curves([inner]).samples(50)[2]
    assert np.allclose(distance_to(pts, Pieces.from_curves(pieces), 8), float(d), rtol=1e-6)

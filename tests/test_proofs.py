"""Run every registered proof of the ledger (fast ones always, heavy ones under -m slow)."""
import pytest

from exactcagd.proofs._ledger import discover, run_claim

CLAIMS = discover()


def _params(slow: bool):
    return [pytest.param(c, id=c.key) for c in CLAIMS if c.slow == slow]


@pytest.mark.parametrize("claim", _params(False))
def test_fast_claim(claim):
    row = run_claim(claim)
    assert row.outcome is not None, row.error


@pytest.mark.slow
@pytest.mark.parametrize("claim", _params(True))
def test_slow_claim(claim):
    row = run_claim(claim)
    assert row.outcome is not None, row.error


# ---------------------------------------------------------------- the verify command (issue 6)
# The command is exercised on a small stand-in registry (monkeypatched selection, one
# process) so that failure reporting is checked without running the whole ledger.
import json  # noqa: E402

from exactcagd.apps import verify as verify_app  # noqa: E402
from exactcagd.cli import main as cli_main  # noqa: E402
from exactcagd.proofs._ledger import Claim, erratum, verified  # noqa: E402


def _fake_claims():
    def ok():
        return verified("1 + 1 == 2 checked")

    def wrong():
        return erratum("1 + 1 = 3", "1 + 1 = 2", "exact integer sum: 2 != 3")

    def broken():
        assert 1 + 1 == 3, "printed 1 + 1 = 3 does not hold"

    return [
        Claim("sederberg", "17.3", "(x)", "ok claim", False, ok),
        Claim("sederberg", "17.4", "(y)", "erratum claim", False, wrong),
        Claim("yang", "5", "(z)", "broken claim", False, broken),
    ]


def test_verify_reports_failures_and_exits_nonzero(tmp_path, monkeypatch, capsys):
    claims = _fake_claims()
    monkeypatch.setattr(verify_app, "select_claims", lambda doc=None, fast=False: [c for c in claims if doc in (None, c.doc)])
    code = cli_main(["verify", "--jobs", "1", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 1
    assert "FAILED" in out and "printed 1 + 1 = 3 does not hold" in out
    md = (tmp_path / "LEDGER.md").read_text()
    assert "**FAILED**" in md and "AssertionError: printed 1 + 1 = 3 does not hold" in md
    # erratum rows show printed vs corrected and the separating check
    assert "printed: `1 + 1 = 3` → corrected: `1 + 1 = 2`; exact integer sum: 2 != 3" in md
    rows = json.loads((tmp_path / "ledger.json").read_text())["claims"]
    assert [r["status"] for r in rows] == ["verified", "erratum", "FAILED"]


def test_verify_json_and_doc_selection(tmp_path, monkeypatch, capsys):
    claims = _fake_claims()
    monkeypatch.setattr(verify_app, "select_claims", lambda doc=None, fast=False: [c for c in claims if doc in (None, c.doc)])
    code = cli_main(["verify", "--doc", "sederberg", "--json", "--jobs", "1", "--out", str(tmp_path)])
    data = json.loads(capsys.readouterr().out)
    assert code == 0
    assert [r["ref"] for r in data["claims"]] == ["(x)", "(y)"] and all(r["doc"] == "sederberg" for r in data["claims"])
    assert data["claims"][1]["printed"] == "1 + 1 = 3" and data["claims"][1]["corrected"] == "1 + 1 = 2"


def test_select_claims_by_document():
    for doc in ("lasser", "yang", "sederberg"):
        sel = verify_app.select_claims(doc)
        assert sel and {c.doc for c in sel} == {doc}
    assert not any(c.slow for c in verify_app.select_claims(None, fast=True))


def test_trace_prints_bezout_derivation(capsys):
    assert cli_main(["verify", "--trace", "sederberg_17_resultants.degree_two_example"]) == 0
    out = capsys.readouterr().out
    # (17.9): the Bezout matrix of t^2 - 7t + 12, t^2 - 3t + 2 and its determinant
    assert "[   4 | -10 ]" in out and "[ -10 |  22 ]" in out and "det = -12" in out
    assert cli_main(["verify", "--trace", "no_such_claim_key"]) == 1

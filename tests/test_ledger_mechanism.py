"""The ledger's rules (issue 17): differential errata, independent references, traceable runs.

The mechanism tests use small stand-in claims; the static tests read every registered
claim's source (AST) and reject checks whose only reference is the code under test.
"""
import ast
import inspect
import json
import textwrap
from pathlib import Path

import pytest
import sympy

from exactcagd.apps import verify as verify_app
from exactcagd.cli import main as cli_main
from exactcagd.proofs._ledger import (
    LOST,
    Claim,
    convention,
    discover,
    erratum,
    predicate,
    reconstructed,
    run_claim,
    same_expr,
    same_value,
    tags_in,
    verified,
)

x, y = sympy.symbols("x y")
ROOT = Path(__file__).resolve().parent.parent
CLAIMS = discover()


def _row(outcome):
    return run_claim(Claim("sederberg", "1", "(t)", "stand-in", False, lambda: outcome))


# ---------------------------------------------------------------- differential check
def test_erratum_runs_both_forms_and_stores_the_counterexample():
    row = _row(erratum("x^2 + 1", "x^2 + 2x + 1", "expand", printed_form=x**2 + 1, corrected_form=x**2 + 2 * x + 1,
                       check=same_expr(sympy.expand((x + 1) ** 2))))
    assert row.status == "erratum"
    assert row.outcome.counterexample == "at x = 1/3: form = 10/9, reference = 16/9"


def test_erratum_whose_printed_form_passes_is_failed():
    row = _row(erratum("p", "c", "d", printed_form=(x + 1) ** 2, corrected_form=x**2 + 2 * x + 1,
                       check=same_expr(sympy.expand((x + 1) ** 2))))
    assert row.status == "FAILED" and "printed form passes" in row.error


def test_erratum_whose_corrected_form_fails_is_failed():
    row = _row(erratum("p", "c", "d", printed_form=x**2, corrected_form=x**2 + 1, check=same_expr(x**2 + 2 * x + 1)))
    assert row.status == "FAILED" and "corrected form fails" in row.error


def test_reconstructed_lost_text_needs_a_reason_and_checks_the_reconstruction():
    with pytest.raises(ValueError):
        reconstructed("p", "c", "d", printed_form=LOST, corrected_form=1, check=same_value(1))
    row = _row(reconstructed("lost", "1", "d", printed_form=LOST, corrected_form=1, check=same_value(1), lost_reason="figure lost"))
    assert row.status == "reconstructed" and "figure lost" in row.outcome.counterexample
    row = _row(reconstructed("lost", "2", "d", printed_form=LOST, corrected_form=2, check=same_value(1), lost_reason="figure lost"))
    assert row.status == "FAILED"


def test_convention_needs_the_normalised_printed_form_to_pass():
    ref = same_expr(sympy.Matrix([1, 2, 3]))
    ok = convention("-(1,2,3)", "(1,2,3)", "common sign", printed_form=sympy.Matrix([-1, -2, -3]),
                    corrected_form=sympy.Matrix([1, 2, 3]), check=ref, normalise=lambda m: -m)
    assert _row(ok).status == "convention"
    bad = convention("-(1,2,4)", "(1,2,3)", "not a common sign", printed_form=sympy.Matrix([-1, -2, -4]),
                     corrected_form=sympy.Matrix([1, 2, 3]), check=ref, normalise=lambda m: -m)
    assert _row(bad).status == "FAILED"


def test_predicate_and_matrix_counterexamples():
    check = predicate(lambda n: None if n % 2 == 0 else f"{n} is odd")
    assert check(4) is None and check(3) == "3 is odd"
    assert same_expr(sympy.Matrix([[1, x]]))(sympy.Matrix([[1, y]])) == "entry (0, 1): y vs reference x"


def test_tags_in_expands_ranges():
    assert tags_in("(12.35)-(12.37)") == ["(12.35)", "(12.36)", "(12.37)"]
    assert tags_in("Theorem 1") == []


# ---------------------------------------------------------------- traceability and reader's view
def _fake():
    def ok():
        return verified("1 + 1 == 2", compared="printed 1 + 1 = 2 vs integer addition", reference="exact")

    def wrong():
        return erratum("x + x = x^2", "x + x = 2x", "sympy", printed_form=x**2, corrected_form=2 * x, check=same_expr(x + x))

    return [Claim("sederberg", "17.3", "(x)", "ok claim", False, ok), Claim("yang", "5", "(y)", "erratum claim", False, wrong)]


def test_run_records_version_commit_dependencies_date_machine(tmp_path, monkeypatch, capsys):
    claims = _fake()
    monkeypatch.setattr(verify_app, "select_claims", lambda doc=None, fast=False: claims)
    assert cli_main(["verify", "--jobs", "1", "--out", str(tmp_path), "--html", str(tmp_path / "html")]) == 0
    data = json.loads((tmp_path / "ledger.json").read_text())
    run = data["run"]
    import exactcagd

    assert run["exactcagd"] == exactcagd.__version__
    assert run["dependencies"]["sympy"] == sympy.__version__
    assert run["machine"]["cpu_count"] >= 1 and run["date"].endswith("Z")
    if (ROOT / ".git").exists():
        assert run["git_commit"] and len(run["git_commit"].split()[0]) == 40
    md = (tmp_path / "LEDGER.md").read_text()
    assert f"exactcagd {exactcagd.__version__}" in md and "CPUs" in md
    assert "counterexample (printed): at x = 1/3: form = 1/9, reference = 2/3" in md
    assert "compared: printed 1 + 1 = 2 vs integer addition" in md
    page = (tmp_path / "html" / "yang.html").read_text()
    assert "<math" in page and "counterexample" in page and "def wrong" in page and "#fbd9d3" in page
    assert (tmp_path / "html" / "index.html").exists()


def test_labels_printed_by_verify_are_accepted_by_trace(tmp_path, monkeypatch, capsys):
    sel = verify_app.select_claims("sederberg")
    label = next(c.label for c in sel if c.key.endswith("degree_two_example"))
    monkeypatch.setattr(verify_app, "select_claims", lambda doc=None, fast=False: [c for c in sel if c.label == label])
    assert cli_main(["verify", "--jobs", "1", "--out", str(tmp_path)]) == 0
    printed = capsys.readouterr().out
    assert label in printed
    assert cli_main(["verify", "--trace", label]) == 0
    assert "det = -12" in capsys.readouterr().out

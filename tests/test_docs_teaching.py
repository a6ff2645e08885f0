"""``exactcagd verify --trace LABEL --trace-format markdown|latex``: a derivation trace as a
block for lecture notes; the traced values are checked against sympy's rotation matrix."""

from __future__ import annotations

import sympy as sp

from exactcagd.cli import main


def _rotated() -> tuple:
    """(5,7,3) rotated by 90 degrees about the axis through (1,1,1) along (2,1,2): Rodrigues' formula."""
    n = sp.Matrix([2, 1, 2]) / 3
    K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    R = sp.eye(3) + K * sp.sin(sp.pi / 2) + K * K * (1 - sp.cos(sp.pi / 2))
    p = R * (sp.Matrix([5, 7, 3]) - sp.Matrix([1, 1, 1])) + sp.Matrix([1, 1, 1])
    return tuple(sp.nsimplify(x) for x in p)


def test_trace_as_markdown_and_latex(capsys):
    expected = ", ".join(str(x) for x in _rotated())
    assert expected == "5/3, 13/3, 23/3"
    assert main(["verify", "--trace", "sederberg 1.3 Example (1.10)", "--trace-format", "markdown"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("### sederberg 1.3 Example (1.10)\n\n")
    assert "```text\n" in out and f"P' = C + r = ({expected})" in out
    assert main(["verify", "--trace", "sederberg 1.3 Example (1.10)", "--trace-format", "latex"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("\\subsection*{sederberg 1.3 Example (1.10)}\n")
    assert "\\begin{verbatim}\n" in out and f"({expected})\n\\end{{verbatim}}" in out


def test_trace_text_format_is_unchanged(capsys):
    assert main(["verify", "--trace", "rotation_example"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("== exactcagd.proofs.sederberg_01_basics.rotation_example: sederberg 1.3 Example (1.10)\n   rotate")
    assert "   n = (2/3, 1/3, 2/3)\n" in out

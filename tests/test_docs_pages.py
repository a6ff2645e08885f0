"""Doctests of the documentation pages (docs/**/*.md): every fenced ```python block with
``>>>`` prompts runs as a doctest, one namespace per page (so a page reads top to bottom),
and the scene-format reference generated at build time covers every key of the schema."""

from __future__ import annotations

import doctest
import json
import re
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parent.parent / "docs"
PAGES = sorted(p for p in DOCS.rglob("*.md") if "_build" not in p.parts and "_generated" not in p.parts)
FENCE = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def page_examples(text: str) -> list[str]:
    return [block for block in FENCE.findall(text) if ">>>" in block]


@pytest.mark.parametrize("page", PAGES, ids=[str(p.relative_to(DOCS)) for p in PAGES])
def test_page_examples_run(page):
    blocks = page_examples(page.read_text())
    if not blocks:
        pytest.skip("no examples on this page")
    parser, globs = doctest.DocTestParser(), {"__name__": f"docs_{page.stem}"}
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for k, block in enumerate(blocks):
        test = parser.get_doctest(block, globs, f"{page.name}[{k}]", str(page), 0)
        runner.run(test, clear_globs=False)
        globs = test.globs  # DocTest copies its globals: carry them to the next block
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed on {page.name}"


def test_the_examples_of_a_page_are_found():
    text = "x\n```python\n>>> 1 + 1\n2\n```\n```python\nno prompt\n```\n"
    assert page_examples(text) == [">>> 1 + 1\n2\n"]


def test_scene_format_reference_covers_every_schema_key():
    import sys

    sys.path.insert(0, str(DOCS / "_ext"))
    from exactcagd_docs import scene_format_page

    from exactcagd.scenes.spec import LIMITS, PRODUCT_KINDS

    page = scene_format_page()
    schema = json.loads((DOCS.parent / "exactcagd" / "scenes" / "scene.schema.json").read_text())

    def keys(node):
        for name, sub in node.get("properties", {}).items():
            yield name
            yield from keys(sub)

    for node in [schema, *schema["$defs"].values()]:
        for key in keys(node):
            assert f"`{key}`" in page, key
    for name in schema["$defs"]:
        assert f"(def-{name})=" in page
    for kind in PRODUCT_KINDS:
        assert f"| `{kind}` |" in page
    for limit, value in LIMITS.items():
        assert f"| `{limit}` | {value} |" in page


def test_teaching_page_typesets_the_recorded_steps(tmp_path, monkeypatch):
    """A teaching page shows each step of the script's output, the values recorded by
    ``_teach.tex`` as display math, and the pictures."""
    import sys

    sys.path.insert(0, str(DOCS / "_ext"))
    import exactcagd_docs as ext

    monkeypatch.setattr(ext, "GENERATED", tmp_path)
    (tmp_path / "teaching").mkdir()
    run = tmp_path / "run"
    run.mkdir()
    (run / "stdout.txt").write_text("\n== 1.2 angle [u, v]\nu.v = 3\n\n== 1.3 next\nx = 1/2\n")
    (run / "teach_01_basics.steps.json").write_text(json.dumps(
        [{"title": "1.2 angle [u, v]", "items": [{"label": "cos theta", "latex": "\\frac{\\sqrt{609}}{203}"}]},
         {"title": "1.3 next", "items": []}]))
    ext._teaching_page("teach_01_basics", run, [run / "ch01_basics.png"])
    page = (tmp_path / "teaching" / "teach_01_basics.md").read_text()
    assert "## 1.2 angle \\[u, v\\]" in page and "## 1.3 next" in page
    assert "```{math}\n\\text{cos theta} = \\frac{\\sqrt{609}}{203}\n```" in page
    assert "u.v = 3" in page and "x = 1/2" in page
    assert "```{image} ../gallery/teach_01_basics__ch01_basics.png" in page

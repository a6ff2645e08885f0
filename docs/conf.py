"""Sphinx configuration of the exactcagd documentation.

Build: ``.ci/docs`` (or ``sphinx-build -W -b html docs docs/_build/html``).  The build needs no
network: MathJax is loaded by the reader's browser at view time.
"""

from __future__ import annotations

import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS / "_ext"))

from exactcagd import __version__  # noqa: E402

project = "exactcagd"
author = "exactcagd contributors"
copyright = "exactcagd contributors, MIT licence"
release = version = __version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.doctest",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "myst_parser",
    "exactcagd_docs",
]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
exclude_patterns = ["_build", "_ext", "README.md"]
root_doc = "index"

html_theme = "alabaster"
html_theme_options = {"description": "exact computer algebra for CAGD", "fixed_sidebar": True}
html_static_path: list[str] = []

# autodoc: numpy-style docstrings, members in source order, no import side effects beyond the package
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "show-inheritance": True}
autodoc_typehints = "none"
napoleon_numpy_docstring = True
napoleon_google_docstring = False
napoleon_use_rtype = False

# doctest builder: the pages' examples and the docstrings autodoc pulls in
doctest_global_setup = "import exactcagd"
doctest_test_doctest_blocks = "default"


def _escape_bars(app, what, name, obj, options, lines) -> None:
    """Docstrings write |x| for absolute values and norms, which reST reads as substitutions:
    escape every ``|`` outside inline literals (and outside reST tables and doctest lines)."""
    text = "\n".join(lines)
    parts = text.split("``")
    for k in range(0, len(parts), 2):  # even parts lie outside ``literals``
        parts[k] = "\n".join(
            line if _table_or_doctest(line.strip()) else line.replace("|", "\\|") for line in parts[k].split("\n"))
    lines[:] = "``".join(parts).split("\n")


def _table_or_doctest(line: str) -> bool:
    return line.startswith(("+-", "+=", ">>>", "...")) or (len(line) > 1 and line[0] == line[-1] == "|")


def setup(app):
    app.connect("autodoc-process-docstring", _escape_bars)

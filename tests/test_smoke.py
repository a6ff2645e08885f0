"""Smoke test: the package imports and the version is consistent with pyproject."""
import re
from pathlib import Path

import exactcagd


def test_version_matches_pyproject():
    """pyproject takes the version from exactcagd/_version.py (read at build time); the installed
    metadata and the package agree with that file's literal."""
    from importlib.metadata import version

    root = Path(__file__).resolve().parents[1]
    text = (root / "pyproject.toml").read_text()
    assert re.search(r'^version = \{attr = "exactcagd._version.__version__"\}', text, re.M)
    literal = re.search(r'^__version__ = "([^"]+)"', (root / "exactcagd" / "_version.py").read_text(), re.M).group(1)
    assert literal == exactcagd.__version__ == version("exactcagd")

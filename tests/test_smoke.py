"""Smoke test: the package imports and the version is consistent with pyproject."""
import re
from pathlib import Path

import exactcagd


def test_version_matches_pyproject():
    text = (Path(__file__).resolve().parents[1] / "pyproject.toml").read_text()
    assert re.search(r'^version = "([^"]+)"', text, re.M).group(1) == exactcagd.__version__

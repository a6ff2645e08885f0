"""``manifest.json`` of a reference suite: what was generated, by what, and hashes to check it.

Fields: ``format_version``, ``exactcagd`` (version and git commit when the package
runs from a git checkout), ``dependencies`` (versions), ``seed`` and ``record_rng`` (how
each record's random source derives from it), ``kinds`` (names in
file order), ``counts`` (per kind and family), ``schemas`` (per kind: file name and
sha256 of the published JSON Schema), ``files`` (per data file: kind, records, sha256).
Nothing in it depends on the time or the executor, so two runs give the same bytes.

>>> sorted(dependency_versions())[:3]
['gmpy2', 'mpmath', 'numpy']
"""

from __future__ import annotations

import hashlib
import json
import subprocess
from importlib import metadata
from pathlib import Path

from .. import __version__
from .records import FORMAT_VERSION

__all__ = ["SCHEMA_DIR", "build_manifest", "dependency_versions", "git_commit", "manifest_text", "schema_path", "sha256_file"]

SCHEMA_DIR = Path(__file__).with_name("schemas")
_DEPENDENCIES = ("gmpy2", "python-flint", "sympy", "numpy", "mpmath")


def schema_path(kind: str) -> Path:
    """The published JSON Schema of ``kind`` (package data)."""
    return SCHEMA_DIR / f"{kind}.schema.json"


def sha256_file(path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def dependency_versions() -> dict:
    out = {}
    for name in _DEPENDENCIES:
        try:
            out[name] = metadata.version(name)
        except metadata.PackageNotFoundError:  # pragma: no cover
            out[name] = None
    return out


def git_commit() -> str | None:
    """HEAD of the git checkout the package runs from (``None`` for an installed wheel)."""
    root = Path(__file__).resolve().parents[2]
    if not (root / ".git").exists():
        return None
    try:
        out = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True, text=True, timeout=10, check=True)
    except (OSError, subprocess.SubprocessError):
        return None
    return out.stdout.strip() or None


def build_manifest(seed: int, kinds: list, counts: dict, files: dict) -> dict:
    """The manifest as a dict; ``files`` maps file name to ``{"kind", "records", "sha256"}``."""
    return {
        "format_version": FORMAT_VERSION,
        "exactcagd": {"version": __version__, "git_commit": git_commit()},
        "dependencies": dependency_versions(),
        "seed": seed,
        "record_rng": "random.Random('exactcagd-refdata:<kind>:<family>:<seed>:<index>') (Python's random, string seed); a record is a pure function of its id, seed and degrees",
        "kinds": list(kinds),
        "counts": counts,
        "schemas": {kind: {"file": f"schemas/{kind}.schema.json", "sha256": sha256_file(schema_path(kind))} for kind in kinds},
        "files": files,
    }


def manifest_text(manifest: dict) -> str:
    return json.dumps(manifest, indent=1, sort_keys=True) + "\n"

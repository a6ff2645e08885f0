"""The scene cache: rendered outputs stored as plain data, keyed by content and code.

An entry is what a product wrote (its exact JSON, its PNG) plus its one-line info,
under ``<out>/.cache/``::

    <key>.entry.json     {"format": ..., "key": ..., "info": {...}, "files": {".json": sha256, ...}}
    <key>.out.json       the bytes of the product's .json output
    <key>.out.png        the bytes of a picture

Nothing in the cache is ever executed or unpickled: a manifest is parsed with
:func:`json.loads` and checked field by field, and every blob must match the SHA-256
the manifest names; anything else is a miss (the product is computed again and the
entry rewritten).  A planted file can therefore at most substitute output bytes,
which anyone able to write into the output folder can do anyway.

The key (:func:`product_key`) hashes the product's scene entry, the specs of the
objects it uses, the keys of the products it uses, the float policy, and
:func:`code_fingerprint` -- a hash of every ``.py`` file of the installed exactcagd
package plus the versions of the libraries that shape the output -- so an editable
install whose code changed misses the cache.

>>> len(product_key({"kind": "implicit", "name": "f", "curve": "k"}, {"k": {"type": "bezier"}}, {}, "reject"))
24
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import re
import stat
from pathlib import Path

from ..outputs import atomic_write_bytes

__all__ = ["code_fingerprint", "product_key", "ProductCache", "CacheEntry", "FORMAT"]

FORMAT = "exactcagd-scene-cache/2"
SUFFIXES = (".json", ".png")
_KEY = re.compile(r"^[0-9a-f]{24}$")
_HEX = re.compile(r"^[0-9a-f]{64}$")
_LIBRARIES = ("gmpy2", "python-flint", "sympy", "numpy", "mpmath", "matplotlib")


@functools.lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """SHA-256 over the source of the exactcagd package and the versions of its libraries.

    Computed once per process (about 170 files and one directory listing per ``sys.path``
    entry: 20-30 ms on the project's machine).  Any edit of any
    module changes it, which is coarser than needed but never reuses a result computed
    by other code.
    """
    import exactcagd

    root = Path(exactcagd.__file__).resolve().parent
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*.py")):
        digest.update(path.relative_to(root).as_posix().encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    versions = _library_versions()
    for name in _LIBRARIES:
        digest.update(f"{name}={versions.get(name, 'absent')}\0".encode())
    return digest.hexdigest()


_DIST = re.compile(r"^([A-Za-z0-9_.]+)-([^-]+?)\.(?:dist|egg)-info$")


def _library_versions() -> dict:
    """Installed versions of ``_LIBRARIES`` from the ``*.dist-info`` folder names on ``sys.path``.

    One directory listing per path entry (the first match wins, as for imports); about
    1 ms where ``importlib.metadata.version`` took 15 ms per library.
    """
    import os
    import sys

    wanted = {name.replace("-", "_").lower(): name for name in _LIBRARIES}
    found: dict = {}
    for entry in sys.path:
        try:
            names = os.listdir(entry or ".")
        except OSError:
            continue
        for folder in names:
            match = _DIST.match(folder)
            if match:
                name = wanted.get(match.group(1).replace("-", "_").replace(".", "_").lower())
                if name and name not in found:
                    found[name] = match.group(2)
    return found


def product_key(product: dict, inputs: dict, dependencies: dict, policy: str) -> str:
    """Cache key of one product: 24 hex digits of a SHA-256 over its content and the code.

    Parameters
    ----------
    product : the product's scene entry (kind, name, options).
    inputs : ``{name: spec}`` of the scene objects it uses.
    dependencies : ``{name: key}`` of the products it uses (a picture of an approximation).
    policy : the scene's float policy.
    """
    payload = json.dumps(
        {"code": code_fingerprint(), "policy": policy, "product": product, "inputs": inputs, "dependencies": dependencies},
        sort_keys=True,
        default=str,
    )
    return hashlib.sha256(payload.encode()).hexdigest()[:24]


MAX_MANIFEST_BYTES = 1 << 20


def _read_regular(path: Path, limit: int | None = None) -> bytes | None:
    """Bytes of ``path`` if it is a regular file (not a link, FIFO or device) of at most ``limit`` bytes.

    A planted FIFO would block a plain read forever and a link to ``/dev/zero`` would
    never end; they are misses.  ``O_NONBLOCK`` keeps the open of a FIFO from waiting.
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        return None
    info = os.fstat(fd)
    if not stat.S_ISREG(info.st_mode) or (limit is not None and info.st_size > limit):
        os.close(fd)
        return None
    with os.fdopen(fd, "rb") as handle:
        return handle.read()


class CacheEntry:
    """A validated cache entry: ``info`` and the output blobs (read on demand)."""

    def __init__(self, cache: "ProductCache", key: str, info: dict, files: dict):
        self.cache, self.key, self.info, self.files = cache, key, info, files

    def read(self) -> dict | None:
        """``{suffix: bytes}`` of the outputs, or ``None`` if a blob is missing or does not match its hash."""
        out = {}
        for suffix, digest in self.files.items():
            data = _read_regular(self.cache.blob_path(self.key, suffix))
            if data is None or hashlib.sha256(data).hexdigest() != digest:
                return None
            out[suffix] = data
        return out


class ProductCache:
    """The ``.cache`` folder of an output directory (created on the first store)."""

    def __init__(self, folder):
        self.folder = Path(folder)

    def manifest_path(self, key: str) -> Path:
        return self.folder / f"{key}.entry.json"

    def blob_path(self, key: str, suffix: str) -> Path:
        return self.folder / f"{key}.out{suffix}"

    def lookup(self, key: str) -> CacheEntry | None:
        """The entry of ``key`` if its manifest is well-formed data for this key, else ``None``."""
        raw = _read_regular(self.manifest_path(key), MAX_MANIFEST_BYTES)
        try:
            data = json.loads(raw.decode("utf-8")) if raw is not None else None
        except (ValueError, RecursionError):
            return None
        if not (
            isinstance(data, dict)
            and set(data) == {"format", "key", "info", "files"}
            and data["format"] == FORMAT
            and data["key"] == key
            and isinstance(data["info"], dict)
            and all(isinstance(k, str) and isinstance(v, str) for k, v in data["info"].items())
            and isinstance(data["files"], dict)
            and all(s in SUFFIXES and isinstance(h, str) and _HEX.match(h) for s, h in data["files"].items())
        ):
            return None
        return CacheEntry(self, key, data["info"], data["files"])

    def store(self, key: str, files: dict, info: dict) -> None:
        """Store the outputs ``{suffix: bytes}`` and ``info`` (strings) of ``key``: blobs first, manifest last."""
        if not _KEY.match(key) or not set(files) <= set(SUFFIXES):
            raise ValueError(f"bad cache entry {key!r} {sorted(files)}")  # pragma: no cover - internal misuse
        self.folder.mkdir(parents=True, exist_ok=True)
        digests = {}
        for suffix, data in files.items():
            atomic_write_bytes(self.blob_path(key, suffix), data)
            digests[suffix] = hashlib.sha256(data).hexdigest()
        manifest = {"format": FORMAT, "key": key, "info": {k: str(v) for k, v in info.items()}, "files": digests}
        atomic_write_bytes(self.manifest_path(key), json.dumps(manifest, indent=1, sort_keys=True).encode())

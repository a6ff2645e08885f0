"""Coverage of the three source documents by the ledger: every numbered equation, section and worked example.

:func:`inventory` parses the seed texts (``/work/shared/seeds`` or ``$EXACTCAGD_SEEDS``):

- equation tags printed at the end of a display (``... (12.35)$$``, ``\\tag{10}``, a line ``(13)``);
- sections: the table of contents of the notes (``12.3.3 Title<TAB>page``), the numbered headings of
  Yang et al. (``4.3. Title``) and the roman headings of Lasser & Bonneau (``III. Title``);
- worked examples: lines opening with ``Example`` (one item per section, ``Example §7.7.7``).

Rows declare what they cover (:attr:`exactcagd.proofs._ledger.Claim.covered`: the section, the
tags in ``ref``, and ``covers=[...]``).  An item is covered when a row of the same document covers
it; a section is also covered by a row of one of its subsections.  Items left uncovered must be
listed with a reason in ``proofs/coverage.toml`` (``tests/test_ledger_coverage.py`` enforces it).

Example
-------
>>> from exactcagd.proofs.coverage import equation_tags
>>> equation_tags("$$a \\\\leq t_0 < t_n \\\\leq b \\\\quad (12.35)$$")
['(12.35)']
"""

from __future__ import annotations

import os
import re
from pathlib import Path

SEED_FILES = {"lasser": "000_", "sederberg": "003_", "yang": "004_"}
DEFAULT_SEEDS = Path("/work/shared/seeds")

_TAG_END = re.compile(r"(?:\\tag\{|\()(\d+(?:\.\d+)?)[)}]\s*(?:\$\$)?\s*[,.]?\s*$")
_TOC = re.compile(r"^(\d+(?:\.\d+)+)\s+\S.*\t\d+\s*$")
_YANG_HEAD = re.compile(r"^(\d+(?:\.\d+)*)\.\s+[A-Z]")
_ROMAN_HEAD = re.compile(r"^(I|II|III|IV|V|VI|VII|VIII|IX|X)\.\s+[A-Z]")
_NOTES_HEAD = re.compile(r"^(\d+(?:\.\d+)+)\s+[A-Z]")
_CHAPTER = re.compile(r"^Chapter (\d+)\s*$")


def seeds_dir() -> Path | None:
    """The seed texts' directory, or None when they are not available (a fresh install)."""
    path = Path(os.environ.get("EXACTCAGD_SEEDS", DEFAULT_SEEDS))
    return path if path.is_dir() else None


def equation_tags(line: str) -> list[str]:
    """Equation tags printed at the end of a display line (or alone on a line)."""
    stripped = line.strip()
    if "$$" not in line and "\\tag" not in line and not re.fullmatch(r"\(?\d+(?:\.\d+)?\)?", stripped):
        return []
    if re.fullmatch(r"\(\d+(?:\.\d+)?\)", stripped):
        return [stripped]
    m = _TAG_END.search(line)
    return [f"({m.group(1)})"] if m else []


def _read(doc: str, root: Path) -> list[str]:
    path = next(root.glob(SEED_FILES[doc] + "*.txt"))
    return path.read_text().splitlines()


def inventory(root: Path | None = None) -> dict[str, list[str]]:
    """Per document: the numbered equations, sections and worked examples of the seed text."""
    root = root or seeds_dir()
    if root is None:
        raise FileNotFoundError("seed texts not found (set EXACTCAGD_SEEDS)")
    out = {}
    for doc in SEED_FILES:
        lines = _read(doc, root)
        items: list[str] = []
        section = ""
        in_body = doc != "sederberg"
        in_toc = False
        for line in lines:
            if doc == "sederberg":
                if line.strip() in ("Contents", "List of Figures", "List of Tables"):
                    in_toc = line.strip() == "Contents"
                    continue
                if in_toc and _TOC.match(line):
                    items.append(f"§{_TOC.match(line).group(1)}")
                    continue
                if _CHAPTER.match(line):
                    in_body = True
                    section = _CHAPTER.match(line).group(1)
                    continue
                head = _NOTES_HEAD.match(line)
                if in_body and head and len(line) < 90:
                    section = head.group(1)
            elif doc == "yang":
                head = _YANG_HEAD.match(line)
                if head and len(line) < 90:
                    section = head.group(1)
                    items.append(f"§{section}")
            else:
                head = _ROMAN_HEAD.match(line)
                if head and len(line) < 90:
                    section = head.group(1)
                    items.append(f"§{section}")
            if not in_body:
                continue
            items += equation_tags(line)
            if re.match(r"^\**Example\b", line.strip()) and section:
                items.append(f"Example §{section}")
        out[doc] = list(dict.fromkeys(items))
    return out


def covered_items(claims) -> dict[str, set[str]]:
    """Per document: the items the registered rows cover (sections count for their parents too)."""
    out: dict[str, set[str]] = {doc: set() for doc in SEED_FILES}
    for c in claims:
        got = out[c.doc]
        for item in c.covered:
            got.add(item)
            if item.startswith("§"):
                parts = item[1:].split(".")
                for k in range(1, len(parts)):
                    got.add("§" + ".".join(parts[:k]))
        if "example" in c.ref.lower() or "example" in c.statement.lower()[:40]:
            got.add(f"Example §{c.section}")
    return out


def uncovered(claims=None, root: Path | None = None) -> dict[str, list[str]]:
    """Per document: inventory items no row covers."""
    if claims is None:
        from exactcagd.proofs._ledger import discover

        claims = discover()
    inv = inventory(root)
    cov = covered_items(claims)
    return {doc: [item for item in items if item not in cov[doc]] for doc, items in inv.items()}


def load_exemptions(path: Path) -> dict[str, dict[str, str]]:
    """``proofs/coverage.toml``: ``[doc]`` tables mapping an item to the reason it has no row."""
    import tomllib

    data = tomllib.loads(path.read_text())
    return {doc: dict(data.get(doc, {})) for doc in SEED_FILES}


def summary(claims=None, root: Path | None = None) -> dict[str, tuple[int, int]]:
    """Per document: (covered, total) items."""
    inv = inventory(root)
    miss = uncovered(claims, root)
    return {doc: (len(inv[doc]) - len(miss[doc]), len(inv[doc])) for doc in inv}


def main() -> int:
    """Print the per-document coverage and the uncovered items (``python -m exactcagd.proofs.coverage``)."""
    for doc, (done, total) in summary().items():
        print(f"{doc}: {done}/{total} items covered")
    for doc, items in uncovered().items():
        for item in items:
            print(f"  {doc} {item}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

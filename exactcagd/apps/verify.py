"""``exactcagd verify``: run the proof ledger and write ``LEDGER.md`` / ``ledger.json``.

Claims are discovered in the ``proofs`` package (see ``proofs/_ledger.py``), run in
parallel worker processes, reported one line each as they finish, and summarized in a
table.  A failing claim is reported as FAILED and makes the command exit with 1.
"""

from __future__ import annotations

import json
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

from exactcagd.outputs import atomic_write_text, check_output_dir

_CLAIMS: dict = {}


def _init_worker() -> None:
    from exactcagd.proofs._ledger import discover

    _CLAIMS.update({c.key: c for c in discover()})


def _run_key(key: str) -> dict:
    from exactcagd.proofs._ledger import run_claim

    if not _CLAIMS:
        _init_worker()
    return _row_dict(run_claim(_CLAIMS[key]))


def _row_dict(row) -> dict:
    from exactcagd.proofs._ledger import form_latex, form_mathml, form_text

    c, o = row.claim, row.outcome
    return {
        "key": c.key,
        "label": c.label,
        "doc": c.doc,
        "section": c.section,
        "ref": c.ref,
        "statement": c.statement,
        "status": row.status,
        "detail": (o.detail if o else row.error) or "",
        "printed": o.printed if o else None,
        "corrected": o.corrected if o else None,
        "range": o.range if o else None,
        "compared": o.compared if o else None,
        "reference": o.reference if o else None,
        "differential": bool(o and o.differential),
        "printed_form": form_text(o.printed_form) if o and o.differential else None,
        "corrected_form": form_text(o.corrected_form) if o and o.differential else None,
        "printed_latex": form_latex(o.printed_form) if o and o.differential else None,
        "corrected_latex": form_latex(o.corrected_form) if o and o.differential else None,
        "printed_mathml": form_mathml(o.printed_form) if o and o.differential else None,
        "corrected_mathml": form_mathml(o.corrected_form) if o and o.differential else None,
        "counterexample": o.counterexample if o else None,
        "covers": c.covered,
        "source": _source_location(c.func),
        "seconds": round(row.seconds, 3),
        "slow": c.slow,
    }


def _source_location(func) -> str:
    """``exactcagd/proofs/<module>.py:<line>`` of a claim's check."""
    import inspect

    import exactcagd

    try:
        line = inspect.getsourcelines(func)[1]
        path = Path(inspect.getsourcefile(func)).resolve()
    except (OSError, TypeError):
        return func.__module__
    root = Path(exactcagd.__file__).resolve().parent.parent
    try:
        path = path.relative_to(root)
    except ValueError:
        pass
    return f"{path}:{line}"


def run_metadata() -> dict:
    """What produced this run: exactcagd version and git commit, dependency versions, date, machine."""
    import datetime
    import os
    import platform
    import subprocess
    from importlib import metadata

    import exactcagd

    deps = {}
    for name in ("gmpy2", "python-flint", "sympy", "numpy", "mpmath"):
        try:
            deps[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            deps[name] = None
    commit = None
    root = Path(exactcagd.__file__).resolve().parent.parent
    try:
        out = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True, text=True, timeout=10)
        if out.returncode == 0:
            commit = out.stdout.strip()
            dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--", "exactcagd"], capture_output=True, text=True, timeout=10)
            if dirty.returncode == 0 and dirty.stdout.strip():
                commit += " (with uncommitted changes)"
    except (OSError, subprocess.SubprocessError):
        pass
    return {
        "exactcagd": getattr(exactcagd, "__version__", None),
        "git_commit": commit,
        "python": platform.python_version(),
        "dependencies": deps,
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "machine": {"platform": platform.platform(), "machine": platform.machine(), "cpu_count": os.cpu_count()},
    }


def _section_key(section: str):
    parts = []
    for p in str(section).replace("-", ".").split("."):
        parts.append((0, int(p), "") if p.isdigit() else (1, 0, p))
    return parts


def select_claims(doc=None, fast=False):
    from exactcagd.proofs._ledger import discover

    claims = [c for c in discover() if (doc is None or c.doc == doc) and not (fast and c.slow)]
    return sorted(claims, key=lambda c: (c.doc, _section_key(c.section), c.ref, c.key))


def run_ledger(claims, jobs: int = 2, progress=None) -> list[dict]:
    """Run claims (in ``jobs`` processes when > 1); return row dicts in ledger order."""
    order = {c.key: i for i, c in enumerate(claims)}
    rows = []
    if jobs <= 1 or len(claims) < 2:
        from exactcagd.proofs._ledger import run_claim

        for c in claims:
            rows.append(_row_dict(run_claim(c)))
            if progress:
                progress(rows[-1], len(rows), len(claims))
    else:
        with ProcessPoolExecutor(max_workers=jobs, initializer=_init_worker) as pool:
            futures = [pool.submit(_run_key, c.key) for c in claims]
            for fut in as_completed(futures):
                rows.append(fut.result())
                if progress:
                    progress(rows[-1], len(rows), len(claims))
    return sorted(rows, key=lambda r: order[r["key"]])


def _cell(text) -> str:
    return str(text or "").replace("|", "\\|").replace("\n", " ")


def ledger_markdown(rows: list[dict], total_seconds: float, meta: dict | None = None) -> str:
    from exactcagd.proofs._ledger import DOCS

    counts: dict = {}
    for r in rows:
        counts[r["status"]] = counts.get(r["status"], 0) + 1
    lines = [
        "# Proof ledger",
        "",
        "Generated by `exactcagd verify`: every claim below was decided by a check against an independent derivation (sympy, mpmath or exact arithmetic written out in the row); errata, reconstructions and conventions are differential: the printed form fails the check (counterexample shown), the corrected form passes.",
        "",
        "Summary: " + ", ".join(f"{k}: {v}" for k, v in sorted(counts.items())) + f" — {len(rows)} claims, {total_seconds:.1f} s.",
        "",
    ]
    if meta:
        deps = ", ".join(f"{k} {v}" for k, v in meta["dependencies"].items())
        m = meta["machine"]
        lines += [
            f"Run: exactcagd {meta['exactcagd']} (commit {meta['git_commit'] or 'not a git checkout'}), "
            f"Python {meta['python']}; {deps}; {meta['date']}; {m['platform']}, {m['cpu_count']} CPUs.",
            "",
            "Erratum, convention and reconstructed rows are differential: the printed form fails an independent "
            "check (the counterexample is shown), the corrected form passes it.",
            "",
        ]
    for doc, title in DOCS.items():
        sub = [r for r in rows if r["doc"] == doc]
        if not sub:
            continue
        lines += [f"## {title}", "", "| section | ref | claim | status | detail | time (s) |", "|---|---|---|---|---|---|"]
        for r in sub:
            detail = r["detail"]
            if r["range"]:
                detail = f"range: {r['range']}; {detail}"
            if r["status"] in ("erratum", "reconstructed", "convention"):
                detail = f"printed: `{r['printed']}` → corrected: `{r['corrected']}`; {detail}"
                if r.get("counterexample"):
                    detail += f"; counterexample (printed): {r['counterexample']}"
            if r.get("compared"):
                detail = f"compared: {r['compared']}; {detail}"
            lines.append(
                f"| {_cell(r['section'])} | {_cell(r['ref'])} | {_cell(r['statement'])} | **{r['status']}** | {_cell(detail)} | {r['seconds']:.2f} |"
            )
        lines.append("")
    return "\n".join(lines)


def _default_out() -> Path:
    """The current directory: a run never writes into the installed package."""
    return Path.cwd()


def ledger_basename(doc=None, fast=False) -> str:
    """``LEDGER`` for the full ledger; a partial run gets its own name so it never overwrites it.

    >>> ledger_basename(), ledger_basename("yang"), ledger_basename(fast=True)
    ('LEDGER', 'LEDGER-yang', 'LEDGER-fast')
    """
    parts = ["LEDGER"] + ([doc] if doc else []) + (["fast"] if fast else [])
    return "-".join(parts)


def main(args) -> int:
    if args.trace:
        return _trace(args.trace, getattr(args, "trace_format", "text"))
    check_output_dir(args.out if args.out else _default_out())  # before the work, not after it
    claims = select_claims(args.doc, args.fast)
    if not claims:
        print("no claims registered for this selection", file=sys.stderr)
        return 1
    start = time.perf_counter()

    def progress(row, done, total):
        if not args.json:
            print(f"[{done:>3}/{total}] {row['status']:<15} {row['seconds']:7.2f}s  {row['label']}", flush=True)

    rows = run_ledger(claims, jobs=args.jobs, progress=progress)
    total = time.perf_counter() - start
    meta = run_metadata()
    out = Path(args.out) if args.out else _default_out()
    out.mkdir(parents=True, exist_ok=True)
    base = ledger_basename(args.doc, args.fast)
    payload = {"run": meta, "seconds": round(total, 2), "claims": rows}
    _atomic_write(out / f"{base}.md", ledger_markdown(rows, total, meta))
    _atomic_write(out / f"{base.lower()}.json", json.dumps(payload, indent=1))
    if getattr(args, "html", None):
        from exactcagd.proofs.ledger_html import write_html

        write_html(payload, Path(args.html))
    failed = [r for r in rows if r["status"] == "FAILED"]
    if args.json:
        print(json.dumps(payload, indent=1))
    else:
        print(_summary_table(rows))
        print(f"\n{len(rows)} claims in {total:.1f} s; ledger written to {out / (base + '.md')}")
        for r in failed:
            print(f"FAILED {r['key']}: {r['detail']}")
    return 1 if failed else 0


def _summary_table(rows: list[dict]) -> str:
    width = max(len(f"{r['doc']} {r['section']} {r['ref']}") for r in rows)
    lines = [f"{'claim':<{width}}  status"]
    for r in rows:
        lines.append(f"{(r['doc'] + ' ' + r['section'] + ' ' + r['ref']):<{width}}  {r['status']}")
    return "\n".join(lines)


def _trace(fragment: str, fmt: str = "text") -> int:
    """Print the derivation trace of the matching claims; ``fmt`` "markdown" or "latex" gives a
    block to paste into lecture notes (the steps verbatim, the claim as its heading)."""
    import contextlib
    import io

    from exactcagd.proofs._ledger import discover

    claims = discover()
    matches = [c for c in claims if fragment in c.key]
    if not matches:  # a label as printed by ``verify`` ("sederberg 17.3.3 (17.9)")
        wanted = " ".join(fragment.split())
        matches = [c for c in claims if " ".join(c.label.split()) == wanted]
    if not matches:
        print(f"no claim key or label matches {fragment!r}", file=sys.stderr)
        return 1
    for c in matches:
        steps = io.StringIO()
        with contextlib.redirect_stdout(steps):
            if c.trace is None:
                print("(no derivation trace for this claim)")
            else:
                c.trace()
        print(_trace_block(c, steps.getvalue().rstrip("\n"), fmt))
    return 0


def _trace_block(c, steps: str, fmt: str) -> str:
    title = f"{c.doc} {c.section} {c.ref}"
    if fmt == "markdown":
        return f"### {title}\n\n{c.statement}\n\n```text\n{steps}\n```\n"
    if fmt == "latex":
        special = {"\\": r"\textbackslash{}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}",
                   **{ch: "\\" + ch for ch in "&%$#_{}"}}

        def esc(text: str) -> str:
            return text.translate(str.maketrans(special))

        return (f"\\subsection*{{{esc(title)}}}\n{esc(c.statement)}\n\n"
                f"\\begin{{verbatim}}\n{steps}\n\\end{{verbatim}}\n")
    indented = "\n".join("   " + line if line else line for line in steps.splitlines())
    return f"== {c.key}: {title}\n   {c.statement}\n{indented}"


def _atomic_write(path: Path, text: str) -> None:
    atomic_write_text(path, text)

"""The ledger as browsable HTML: one page per document, grouped by section.

Each row shows its status (coloured), the claim as printed, what was compared with what,
printed vs corrected formula typeset as presentation MathML (no script, works offline),
the counterexample to the printed form, and the source of its check (inline, with the
module and line).  ``exactcagd verify --html DIR`` calls :func:`write_html`; a docs build
can call :func:`render_pages` and include the pages.

Example
-------
>>> from exactcagd.proofs.ledger_html import render_pages
>>> pages = render_pages({"run": None, "seconds": 0.1, "claims": [{"key": "k", "label": "yang 5 (6)",
...     "doc": "yang", "section": "5", "ref": "(6)", "statement": "s", "status": "verified", "detail": "d"}]})
>>> sorted(pages)
['index.html', 'yang.html']
"""

from __future__ import annotations

import html
import importlib
import inspect
from pathlib import Path

COLOURS = {
    "verified": "#d8f0d8",
    "verified-range": "#e6f5d0",
    "erratum": "#fbd9d3",
    "convention": "#fdf0c8",
    "reconstructed": "#dde6fa",
    "not-checkable": "#e8e8e8",
    "FAILED": "#ff8a80",
}

_STYLE = """
body { font-family: sans-serif; max-width: 70em; margin: 1em auto; line-height: 1.4; }
.row { border: 1px solid #bbb; border-radius: 4px; margin: 0.6em 0; padding: 0.4em 0.8em; }
.status { font-weight: bold; padding: 0 0.4em; border-radius: 3px; }
pre { background: #f6f6f6; padding: 0.5em; overflow-x: auto; font-size: 85%; }
table.forms td { vertical-align: top; padding: 0.2em 1em 0.2em 0; }
code { background: #f3f3f3; }
"""


def _e(text) -> str:
    return html.escape(str(text or ""))


def _source(key: str, where: str | None) -> str | None:
    """The check's source: by ``key`` (module.function), else from ``where`` (path:line)."""
    module, _, name = key.rpartition(".")
    try:
        return inspect.getsource(getattr(importlib.import_module(module), name))
    except Exception:  # noqa: BLE001 - a nested or renamed function: read the file at its line
        pass
    if not where or ":" not in where:
        return None
    import exactcagd

    path, _, line = where.rpartition(":")
    path = Path(path)
    if not path.is_absolute():
        path = Path(exactcagd.__file__).resolve().parent.parent / path
    try:
        lines = path.read_text().splitlines(keepends=True)
        return "".join(inspect.getblock(lines[int(line) - 1:]))
    except (OSError, ValueError, IndexError):
        return None


def _formula(mathml, latex, text) -> str:
    if mathml:
        return mathml
    if latex:
        return f"<code>${_e(latex)}$</code>"
    return f"<code>{_e(text)}</code>"


def _row_html(r: dict, with_source: bool) -> str:
    status = r["status"]
    parts = [
        f'<div class="row" id="{_e(r["key"])}" style="background:{COLOURS.get(status, "#fff")}">',
        f'<span class="status">{_e(status)}</span> <b>{_e(r["ref"])}</b> — {_e(r["statement"])}',
    ]
    if r.get("compared"):
        parts.append(f"<p><i>compared:</i> {_e(r['compared'])}" + (f" (reference: {_e(r.get('reference'))})" if r.get("reference") else "") + "</p>")
    if status in ("erratum", "convention", "reconstructed"):
        parts.append('<table class="forms">')
        parts.append(f"<tr><td>printed</td><td>{_e(r.get('printed'))}</td><td>{_formula(r.get('printed_mathml'), r.get('printed_latex'), r.get('printed_form'))}</td></tr>")
        parts.append(f"<tr><td>corrected</td><td>{_e(r.get('corrected'))}</td><td>{_formula(r.get('corrected_mathml'), r.get('corrected_latex'), r.get('corrected_form'))}</td></tr>")
        parts.append("</table>")
        if r.get("counterexample"):
            parts.append(f"<p><i>counterexample to the printed form:</i> <code>{_e(r['counterexample'])}</code></p>")
        if not r.get("differential"):
            parts.append("<p><i>(legacy row: no differential check yet)</i></p>")
    if r.get("range"):
        parts.append(f"<p><i>range:</i> {_e(r['range'])}</p>")
    parts.append(f"<p>{_e(r.get('detail'))}</p>")
    if r.get("covers"):
        parts.append(f"<p><small>covers: {_e(', '.join(r['covers']))}</small></p>")
    if with_source:
        src = _source(r["key"], r.get("source"))
        where = r.get("source") or r["key"]
        parts.append(f"<details><summary>check: <code>{_e(where)}</code></summary><pre>{_e(src or '(source not available)')}</pre></details>")
    parts.append("</div>")
    return "\n".join(parts)


def _page(title: str, body: str) -> str:
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{_e(title)}</title>"
            f"<style>{_STYLE}</style></head><body>{body}</body></html>\n")


def _section_key(section: str):
    from exactcagd.apps.verify import _section_key as key

    return key(section)


def render_pages(payload: dict, with_source: bool = True) -> dict[str, str]:
    """File name -> HTML text: ``index.html`` and one page per document of the ledger ``payload``."""
    from exactcagd.proofs._ledger import DOCS

    rows = payload["claims"]
    meta = payload.get("run")
    pages = {}
    index = ["<h1>Proof ledger</h1>"]
    if meta:
        index.append(f"<p>exactcagd {_e(meta.get('exactcagd'))}, commit <code>{_e(meta.get('git_commit'))}</code>, "
                     f"{_e(meta.get('date'))}, {_e(meta.get('machine', {}).get('platform'))}</p>")
    index.append("<ul>")
    for doc, title in DOCS.items():
        sub = [r for r in rows if r["doc"] == doc]
        if not sub:
            continue
        counts: dict = {}
        for r in sub:
            counts[r["status"]] = counts.get(r["status"], 0) + 1
        summary = ", ".join(f'<span class="status" style="background:{COLOURS.get(k, "#fff")}">{_e(k)} {v}</span>' for k, v in sorted(counts.items()))
        index.append(f'<li><a href="{doc}.html">{_e(title)}</a> — {len(sub)} claims: {summary}</li>')
        body = [f'<p><a href="index.html">ledger</a></p><h1>{_e(title)}</h1>']
        sections = sorted({r["section"] for r in sub}, key=_section_key)
        body.append("<p>" + " · ".join(f'<a href="#sec-{_e(s)}">{_e(s)}</a>' for s in sections) + "</p>")
        for s in sections:
            body.append(f'<h2 id="sec-{_e(s)}">Section {_e(s)}</h2>')
            body += [_row_html(r, with_source) for r in sub if r["section"] == s]
        pages[f"{doc}.html"] = _page(title, "\n".join(body))
    index.append("</ul>")
    pages["index.html"] = _page("Proof ledger", "\n".join(index))
    return pages


def write_html(payload: dict, out: Path) -> list[Path]:
    """Write :func:`render_pages` into directory ``out``; return the written paths."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for name, text in render_pages(payload).items():
        (out / name).write_text(text)
        written.append(out / name)
    return written

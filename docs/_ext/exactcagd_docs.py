"""Pages the documentation build writes itself, so they cannot drift from the code.

* ``_generated/scene_format.md`` -- the scene file reference, from
  ``exactcagd/scenes/scene.schema.json`` and ``exactcagd.scenes.spec`` (``PRODUCT_KINDS``,
  ``LIMITS``);
* ``_generated/gallery.md`` and ``_generated/gallery/*.png`` -- every example's picture,
  produced by running the examples during the build (:data:`EXAMPLES`);
* ``_generated/teaching/*.md`` -- one page per teaching script: its derivation steps typeset
  (the LaTeX recorded by ``examples/_teach.tex``), its printed output and its pictures.

The examples run in two processes at once.  Their outputs are kept under
``docs/_build/gallery-cache/<hash>`` where the hash covers every source file of the
package and of ``examples/``: a rebuild with unchanged sources reuses them, any change
reruns every example (a clean checkout always runs them).
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

DOCS = Path(__file__).resolve().parent.parent
ROOT = DOCS.parent
GENERATED = DOCS / "_generated"
EXAMPLES_DIR = ROOT / "examples"

#: Gallery entries: (key, title, what it shows, argv with {out} for the output folder)
EXAMPLES = [
    ("hill_trim", "The README scene: a cubic trim curve on a bicubic B-spline hill",
     "`exactcagd run examples/scenes/hill_trim.toml`: the domain, the exact image curve, the exact "
     "intersections (numbered, with a zoom inset, lifted onto the surface in 3-D) and the G1 "
     "parabola approximation with its true distance to the exact image under the certified bound.",
     ["{exactcagd}", "run", "examples/scenes/hill_trim.toml", "--out", "{out}", "--no-cache"]),
    ("lasser", "Lasser & Bonneau, figures 3-9",
     "`python examples/lasser_figures.py`: trim curves K(t) in the domain, their exact images F(K(t)) "
     "and the G1 cubic approximations of section VIII; figure 9 is the biquintic free-form deformation.",
     [sys.executable, "examples/lasser_figures.py", "--out", "{out}"]),
    ("yang", "Yang et al.: G1 parabola curves on a NURBS surface",
     "`python examples/yang_tables.py --picture face:parabola:1e-2`: the face stand-in's closed domain curve, "
     "the parabola segments by kind and their images on the surface.",
     [sys.executable, "examples/yang_tables.py", "--picture", "face:parabola:1e-2", "--out", "{out}"]),
] + [
    (path.stem, path.stem, f"`python examples/{path.name}`", [sys.executable, f"examples/{path.name}"])
    for path in sorted(EXAMPLES_DIR.glob("teach_*.py"))
    if path.name != "teach_splines_surfaces.py"  # runs four of the scripts above again
]


# ----------------------------------------------------------------------------- scene format
def _type_of(node: dict, defs: dict) -> str:
    if "$ref" in node:
        name = node["$ref"].rsplit("/", 1)[-1]
        return f"[{name}](#def-{name})"
    if "const" in node:
        return f"`{json.dumps(node['const'])}`"
    if "enum" in node:
        return "one of " + ", ".join(f"`{json.dumps(v)}`" for v in node["enum"])
    if "anyOf" in node or "oneOf" in node:
        return " or ".join(_type_of(n, defs) for n in node.get("anyOf", node.get("oneOf")))
    kind = node.get("type", "any")
    if kind == "array" and "items" in node:
        return f"array of {_type_of(node['items'], defs)}"
    if kind == "object" and isinstance(node.get("additionalProperties"), dict):
        return f"table: name -> {_type_of(node['additionalProperties'], defs)}"
    return kind


def _constraints(node: dict) -> str:
    words = []
    for key, text in (("minItems", "at least {} items"), ("maxItems", "at most {} items"), ("minimum", ">= {}"),
                      ("maximum", "<= {}"), ("maxLength", "at most {} characters")):
        if key in node:
            words.append(text.format(node[key]))
    if "pattern" in node:
        words.append(f"matches `{node['pattern']}`")
    if node.get("additionalProperties") is False:
        words.append("no other keys")
    return "; ".join(words)


#: What a key means, where the schema says only its type (the schema's own descriptions come first)
NOTES = {
    "name": "names the object or product; output files are called after it",
    "float_policy": "`\"reject\"`: a float anywhere is an error; `\"exact\"`: a float is taken at its exact binary value",
    "top.surfaces": "surfaces by name", "top.curves": "curves by name", "products": "what to compute, in order",
    "control_net": "rows of control points (`net[i][j]`, i along u) or a `grid` generator",
    "control_points": "control points in order; 2-D curves are domain (trim) curves",
    "weights": "positive weights (rational / NURBS); omitted: all 1",
    "knots_u": "knot vector in u (B-spline only)", "knots_v": "knot vector in v (B-spline only)",
    "knots": "knot vector (B-spline only): non-decreasing, length = points + degree + 1",
    "kind": "the product kind; see the table of keys per kind below",
    "surface": "name of a surface of this scene", "curve": "name of a curve of this scene",
    "lattice": "name of a Bézier surface used as a free-form deformation lattice",
    "curves": "names of two curves to intersect", "of": "names of the objects and products to draw",
    "only_crossed_by": "extract only the Bézier patches this curve crosses",
    "tol": "tolerance of the approximation (exact number)",
    "method": "algorithm; which values apply depends on the kind",
    "reduce": "reduce the exact image to its true degree",
    "samples": "float samples per curve in a picture", "title": "picture title",
    "generator": "always `\"grid\"`", "size": "`[nu, nv]` control points", "z": "height polynomial in x, y",
    "domain": "parameter domain of the grid (optional)", "type": "object type", "description": "free text",
}


def _row(name: str, node: dict, required, defs, where: str) -> str:
    note = node.get("description", "") or NOTES.get(f"{where}.{name}", NOTES.get(name, ""))
    cells = [f"`{name}`", _type_of(node, defs), "yes" if name in required else "",
             " ".join(x for x in (note, _constraints(node)) if x)]
    return "| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |"


def _table(node: dict, defs: dict, where: str = "") -> list[str]:
    required = set(node.get("required", []))
    lines = ["| key | type | required | notes |", "|---|---|---|---|"]
    lines += [_row(k, v, required, defs, where) for k, v in node.get("properties", {}).items()]
    return lines


def scene_format_page() -> str:
    """The scene file reference, generated from the schema and the validator's tables."""
    from exactcagd.scenes import spec

    schema = json.loads((ROOT / "exactcagd" / "scenes" / "scene.schema.json").read_text())
    defs = schema["$defs"]
    out = ["# Scene file format", "",
           "```{note}", "Generated at build time from `exactcagd/scenes/scene.schema.json` and "
           "`exactcagd.scenes.spec` (`PRODUCT_KINDS`, `LIMITS`); edit those, not this page.", "```", "",
           schema.get("description", ""), "",
           "A scene is a TOML or JSON file; `exactcagd plan FILE` shows what it will compute, "
           "`exactcagd run FILE --out DIR` computes it.  The README's scene:", "",
           "```{literalinclude} ../../examples/scenes/hill_trim.toml", ":language: toml", "```", "",
           "## Top level", ""]
    out += _table(schema, defs, "top") + [""]
    for name, node in schema.get("properties", {}).items():
        if "properties" in node:
            out += [f"### `[{name}]`", ""] + _table(node, defs) + [""]
    for name, node in defs.items():
        out += [f"(def-{name})=", f"## `{name}`", ""]
        if node.get("description"):
            out += [node["description"], ""]
        if "properties" in node:
            out += _table(node, defs) + [""]
        else:
            out += [f"{_type_of(node, defs)}" + (f" ({_constraints(node)})" if _constraints(node) else ""), ""]
        if name == "number":
            out += ["Exact: an integer, `\"p/q\"` or a decimal string such as `\"0.125\"` (taken exactly). "
                    "A TOML/JSON float is refused under `float_policy = \"reject\"` and taken at its exact "
                    "binary value under `\"exact\"`.", ""]
        if name == "grid":
            out += ["Places the control point `(i/(nu-1), j/(nv-1), z(x, y))`; `z` is a polynomial in "
                    "`x`, `y` with rational coefficients, evaluated exactly.", ""]
    out += ["## Keys of each product kind", "",
            "Every product has `kind` and may have `name`; the other keys depend on the kind "
            f"(from `PRODUCT_KINDS`; the default approximation method is `{spec.DEFAULT_APPROXIMATION}`):", "",
            "| kind | required | optional |", "|---|---|---|"]
    for kind, (req, opt) in spec.PRODUCT_KINDS.items():
        out.append(f"| `{kind}` | {', '.join(f'`{k}`' for k in sorted(req))} | {', '.join(f'`{k}`' for k in sorted(opt))} |")
    out += ["", "## Limits", "",
            "Checked before any work starts; exceeding one raises `SceneLimitError` "
            "(raise a limit deliberately with `exactcagd.scenes.spec.LIMITS[name] = value`).", "",
            "| limit | value |", "|---|---|"]
    out += [f"| `{k}` | {v} |" for k, v in spec.LIMITS.items()]
    return "\n".join(out) + "\n"


# ----------------------------------------------------------------------------- gallery
def _source_hash() -> str:
    digest = hashlib.sha256(sys.version.encode())
    for folder in (ROOT / "exactcagd", EXAMPLES_DIR):
        for path in sorted(folder.rglob("*")):
            if path.is_file() and path.suffix in {".py", ".toml", ".json"} and "output" not in path.parts:
                digest.update(str(path.relative_to(ROOT)).encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()[:16]


def _run_example(entry, folder: Path) -> tuple[str, float, int]:
    key, _title, _what, argv = entry
    out = folder / key
    out.mkdir(parents=True, exist_ok=True)
    exe = shutil.which("exactcagd") or "exactcagd"
    argv = [a.replace("{out}", str(out)).replace("{exactcagd}", exe) for a in argv]
    env = dict(os.environ, EXACTCAGD_EXAMPLES_OUT=str(out), MPLBACKEND="Agg", PYTHONHASHSEED="0")
    start = time.perf_counter()
    proc = subprocess.run(argv, cwd=ROOT, env=env, capture_output=True, text=True, timeout=900, check=False)
    (out / "stdout.txt").write_text(proc.stdout)
    (out / "stderr.txt").write_text(proc.stderr)
    return key, time.perf_counter() - start, proc.returncode


def run_examples(cache_root: Path, logger=None) -> Path:
    """Run every example (two at a time) into a folder keyed by the sources' hash."""
    folder = cache_root / _source_hash()
    done = folder / "DONE"
    if done.exists():
        return folder
    if folder.exists():
        shutil.rmtree(folder)
    folder.mkdir(parents=True)
    with ThreadPoolExecutor(max_workers=int(os.environ.get("EXACTCAGD_DOCS_JOBS", "2"))) as pool:
        results = list(pool.map(lambda e: _run_example(e, folder), EXAMPLES))
    failed = [(k, rc) for k, _s, rc in results if rc != 0]
    for key, seconds, rc in results:
        if logger:
            logger.info(f"gallery: {key} {seconds:.1f} s" + ("" if rc == 0 else f" FAILED (exit {rc})"))
    if failed:
        details = "\n".join(f"--- {k} (exit {rc})\n" + (folder / k / "stderr.txt").read_text()[-3000:] for k, rc in failed)
        raise RuntimeError(f"examples failed: {failed}\n{details}")
    done.write_text(json.dumps({k: round(s, 1) for k, s, _ in results}))
    return folder


def _pictures(folder: Path) -> list[Path]:
    return sorted(p for p in folder.rglob("*.png") if not any(part.startswith(".") for part in p.relative_to(folder).parts))


def gallery_pages(folder: Path) -> None:
    """Copy the pictures next to the generated pages and write the gallery and teaching pages."""
    images = GENERATED / "gallery"
    if images.exists():
        shutil.rmtree(images)
    images.mkdir(parents=True)
    lines = ["# Gallery", "",
             "Every picture on this page was drawn by the documentation build, by running the example "
             "(so it shows what the code does today).  Run any of them yourself with the command shown.", ""]
    teaching = GENERATED / "teaching"
    if teaching.exists():
        shutil.rmtree(teaching)
    teaching.mkdir(parents=True)
    for key, title, what, _argv in EXAMPLES:
        pngs = _pictures(folder / key)
        if not pngs:
            raise RuntimeError(f"example {key} drew no picture")
        if key.startswith("teach_"):
            _teaching_page(key, folder / key, pngs)
            lines += [f"## {title}", "", what + f"; the derivation: {{doc}}`teaching/{key}`.", ""]
        else:
            lines += [f"## {title}", "", what, ""]
        for png in pngs:
            target = images / f"{key}__{png.name}"
            shutil.copyfile(png, target)
            lines += [f"```{{image}} gallery/{target.name}", f":alt: {key}: {png.stem}", ":width: 100%", "```", ""]
    (GENERATED / "gallery.md").write_text("\n".join(lines))


def _teaching_page(key: str, folder: Path, pngs: list[Path]) -> None:
    script = EXAMPLES_DIR / f"{key}.py"
    doc = _module_docstring(script)
    title = " ".join(doc.split("\n\n")[0].split()) if doc else key
    lines = [f"# {_md_text(title)}", "",
             f"Run `python examples/{key}.py`.  The steps below are the script's own output, produced by "
             "the documentation build; exact values are typeset by sympy where the script records them.", ""]
    for png in pngs:
        lines += [f"```{{image}} ../gallery/{key}__{png.name}", f":alt: {png.stem}", ":width: 90%", "```", ""]
    steps_file = folder / f"{key}.steps.json"
    steps = json.loads(steps_file.read_text()) if steps_file.exists() else []
    sections = _stdout_sections((folder / "stdout.txt").read_text())
    typeset = {s["title"]: s["items"] for s in steps}
    for title, body in sections:
        lines += [f"## {_md_text(title)}" if title else "## Output", ""]
        for item in typeset.get(title, []):
            lines += ["```{math}", rf"\text{{{_tex_text(item['label'])}}} = {item['latex']}", "```", ""]
        if body.strip():
            lines += ["```text", body.rstrip(), "```", ""]
    lines += ["## The script", "", f"```{{literalinclude}} ../../../examples/{key}.py", ":language: python", "```", ""]
    (GENERATED / "teaching" / f"{key}.md").write_text("\n".join(lines))


def _md_text(text: str) -> str:
    """Printed text as a Markdown heading: brackets and stars are literal."""
    for ch in "\\[]*_`<>":
        text = text.replace(ch, "\\" + ch)
    return text


def _tex_text(text: str) -> str:
    for ch in "\\{}_^#$%&~":
        text = text.replace(ch, "\\" + ch if ch not in "\\^~" else " ")
    return text


def _stdout_sections(text: str) -> list[tuple[str, str]]:
    """Split a teaching script's output at its ``== title`` lines."""
    sections, title, body = [], "", []
    for line in text.splitlines():
        if line.startswith("== "):
            if title or "".join(body).strip():
                sections.append((title, "\n".join(body)))
            title, body = line[3:].strip(), []
        else:
            body.append(line)
    sections.append((title, "\n".join(body)))
    return sections


def _module_docstring(path: Path) -> str:
    import ast

    return ast.get_docstring(ast.parse(path.read_text())) or ""


# ----------------------------------------------------------------------------- sphinx hook
def generate(app) -> None:
    from sphinx.util import logging

    logger = logging.getLogger(__name__)
    GENERATED.mkdir(exist_ok=True)
    (GENERATED / "scene_format.md").write_text(scene_format_page())
    if app.builder.name in {"doctest", "linkcheck"} and (GENERATED / "gallery.md").exists():
        return  # the doctest run needs the pages, not new pictures
    folder = run_examples(Path(app.outdir).parent / "gallery-cache", logger)
    gallery_pages(folder)


def ledger_pages(app, exception) -> None:
    """The committed ledger (``proofs/ledger.json``) rendered as browsable pages under
    ``ledger/`` of the HTML output: status colours, printed vs corrected formulae, the
    counterexamples and each check's source (``exactcagd.proofs.ledger_html``)."""
    if exception is not None or app.builder.name != "html":
        return
    from exactcagd.proofs.ledger_html import render_pages

    payload = json.loads((ROOT / "proofs" / "ledger.json").read_text())
    out = Path(app.outdir) / "ledger"
    out.mkdir(exist_ok=True)
    for name, html in render_pages(payload).items():
        (out / name).write_text(html, encoding="utf-8")


def setup(app):
    app.connect("builder-inited", generate)
    app.connect("build-finished", ledger_pages)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}

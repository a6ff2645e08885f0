"""``exactcagd plan`` and ``exactcagd run``: the lazy scene runner.

Steps: validate the whole scene and build its exact objects (nothing is computed
before the scene is known to be sound) -> plan each product (what it needs, what it
skips and why, whether it is cached) -> compute the products not cached, with a
progress line each -> write every output atomically at the end (exact JSON with
float companions, PNG pictures, ``summary.json``).  Results are cached by a content
hash of the product and the objects it uses, so an unchanged scene reruns instantly.

>>> # exactcagd run examples/scenes/hill_trim.toml --out out
"""

from __future__ import annotations

import hashlib
import json
import pickle
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from .. import __version__
from ..errors import ExactCAGDError, InputError
from . import products as handlers
from .build import build_curve, build_surface
from .serialize import atomic_write_bytes
from .spec import Scene, SceneError, load_scene

__all__ = ["Runner", "cmd_plan", "cmd_run"]


@dataclass
class PlanItem:
    product: dict
    key: str
    cached: bool
    needs: list[str] = field(default_factory=list)
    skips: list[str] = field(default_factory=list)


class Runner:
    """Holds a validated scene, its exact objects, the plan and the cache location."""

    def __init__(self, scene: Scene, out_dir, use_cache: bool = True):
        self.scene = scene
        self.out_dir = Path(out_dir)
        self.scene_dir = self.out_dir / scene.name
        self.cache_dir = self.out_dir / ".cache"
        self.use_cache = use_cache
        self.objects = self._build_objects()

    # ------------------------------------------------------------------ objects
    def _build_objects(self) -> dict:
        objects = {}
        for name, spec in self.scene.surfaces.items():
            objects[name] = _built(build_surface, spec, name, self.scene.float_policy, f"surfaces.{name}")
        for name, spec in self.scene.curves.items():
            objects[name] = _built(build_curve, spec, name, self.scene.float_policy, f"curves.{name}")
        return objects

    # ------------------------------------------------------------------ planning
    def cache_key(self, product: dict) -> str:
        refs = handlers.references(product)
        specs = {r: self.scene.object_spec(r) for r in refs if r in self.scene.surfaces or r in self.scene.curves}
        for r in refs:  # a product that uses another product depends on that one's spec too
            for other in self.scene.products:
                if other["name"] == r:
                    specs[r] = other
        payload = json.dumps(
            {"version": __version__, "policy": self.scene.float_policy, "product": product, "inputs": specs},
            sort_keys=True,
            default=str,
        )
        return hashlib.sha256(payload.encode()).hexdigest()[:24]

    def _cache_path(self, key: str) -> Path:
        return self.cache_dir / f"{key}.pickle"

    def plan(self) -> list[PlanItem]:
        items = []
        for product in self.scene.products:
            key = self.cache_key(product)
            cached = self.use_cache and self._cache_path(key).is_file()
            needs, skips = handlers.plan(product, self)
            items.append(PlanItem(product, key, cached, needs, skips))
        return items

    # ------------------------------------------------------------------ running
    def run(self, progress=print) -> dict:
        """Compute every product (cache first); write all outputs at the end.

        Each product is snapshotted (pickled) the moment it is computed or loaded: later
        products may refine its exact numbers in place (an isolating interval narrowed by
        a float conversion or a comparison), so its JSON is rendered from a copy of the
        snapshot, and the cache stores the same snapshot. A fresh run and a cached run
        therefore write identical exact outputs.
        """
        results, infos, snapshots = {}, {}, {}
        plan = self.plan()
        total = len(plan)
        for index, item in enumerate(plan, 1):
            name = item.product["name"]
            start = time.perf_counter()
            if item.cached:
                snapshots[name] = self._cache_path(item.key).read_bytes()
                result, info = pickle.loads(snapshots[name])
                status = "cached"
            else:
                progress(f"[{index}/{total}] {item.product['kind']:<14} {name} ...")
                result, info = handlers.compute(item.product, self, results)
                snapshots[name] = _snapshot(name, result, info)
                status = "computed"
            seconds = time.perf_counter() - start
            info = dict(info, status=status, seconds=round(seconds, 3))
            results[name], infos[name] = result, info
            progress(f"[{index}/{total}] {item.product['kind']:<14} {name}: {status} in {seconds:.2f} s")
        self._write(plan, results, infos, snapshots)
        return {"results": results, "infos": infos}

    def _write(self, plan, results, infos, snapshots) -> None:
        """Write all outputs; each file atomically, cache entries after the outputs."""
        files = {}
        for item in plan:
            name = item.product["name"]
            blob = snapshots.get(name)
            own = pickle.loads(blob)[0] if blob is not None else results[name]
            rendered = handlers.render(item.product, own, self, results)
            for suffix, data in rendered.items():
                files[self.scene_dir / f"{name}{suffix}"] = data
        summary = {
            "scene": self.scene.name,
            "source": self.scene.source,
            "exactcagd": __version__,
            "products": [
                {"name": item.product["name"], "kind": item.product["kind"], **_json_safe(infos[item.product["name"]])}
                for item in plan
            ],
        }
        files[self.scene_dir / "summary.json"] = json.dumps(summary, indent=1).encode()
        for path, data in files.items():
            atomic_write_bytes(path, data if isinstance(data, bytes) else data.encode())
        if self.use_cache:
            for item in plan:
                blob = snapshots.get(item.product["name"])
                if not item.cached and blob is not None:
                    atomic_write_bytes(self._cache_path(item.key), blob)


def _snapshot(name: str, result, info: dict) -> bytes | None:
    """The pickled (result, info) of a product as computed, or None (reported) if it does not pickle."""
    try:
        return pickle.dumps((result, _strip(info)))
    except (TypeError, AttributeError, pickle.PicklingError) as exc:
        print(f"note: {name} is not cached ({exc})", file=sys.stderr)
        return None


def _strip(info: dict) -> dict:
    return {k: v for k, v in info.items() if k not in ("status", "seconds")}


def _json_safe(info: dict) -> dict:
    return json.loads(json.dumps(info, default=str))


def _built(builder, spec, name, policy, where):
    try:
        return builder(spec, name, policy)
    except SceneError:
        raise
    except InputError as exc:
        raise SceneError(f"{where}: {exc}") from None


def _format_plan(runner: Runner, items: list[PlanItem]) -> str:
    lines = [f"scene {runner.scene.name!r} ({runner.scene.source}): {len(items)} product(s)"]
    for name, obj in runner.objects.items():
        lines.append(f"  object {name}: {obj!r}")
    for item in items:
        p = item.product
        state = "cached (will be reused)" if item.cached else "to compute"
        lines.append(f"- {p['kind']} {p['name']}: {state}")
        for need in item.needs:
            lines.append(f"    computes: {need}")
        for skip in item.skips:
            lines.append(f"    skips:    {skip}")
    return "\n".join(lines)


def cmd_plan(args) -> int:
    runner = Runner(load_scene(args.scene), args.out, use_cache=not args.no_cache)
    print(_format_plan(runner, runner.plan()))
    return 0


def cmd_run(args) -> int:
    runner = Runner(load_scene(args.scene), args.out, use_cache=not args.no_cache)
    print(_format_plan(runner, runner.plan()))
    start = time.perf_counter()
    try:
        out = runner.run(progress=lambda line: print(line, flush=True))
    except ExactCAGDError:
        raise
    except KeyboardInterrupt:  # pragma: no cover - nothing was written yet
        print("interrupted: no output written", file=sys.stderr)
        return 130
    print(f"\n{'product':<24} {'kind':<14} {'status':<9} {'time':>8}  summary")
    for name, info in out["infos"].items():
        kind = next(p["kind"] for p in runner.scene.products if p["name"] == name)
        print(f"{name:<24} {kind:<14} {info['status']:<9} {info['seconds']:>7.2f}s  {info.get('summary', '')}")
    print(f"\nwrote {runner.scene_dir}/ in {time.perf_counter() - start:.2f} s")
    return 0

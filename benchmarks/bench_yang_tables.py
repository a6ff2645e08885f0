"""The seeds' own tables in the one benchmark run: Yang et al. (2012) Tables 1-4 analogues.

Delegates to ``examples/yang_tables.py`` (stand-in models, the three methods and the exact
composition at eps_D = 1e-1 ... 1e-5, the paper's printed figures alongside).  Full mode
rewrites ``benchmarks/results/yang_tables.md`` (about 6 minutes on 2 cores); quick mode
runs two models at two tolerances without pictures (about 3 minutes) and writes
``examples/output/yang/tables.md`` only, so the committed full table is not replaced by
a partial one.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

SCRIPT = Path(__file__).resolve().parent.parent / "examples" / "yang_tables.py"


def main(quick: bool = False) -> None:
    if not SCRIPT.exists():
        raise FileNotFoundError(f"{SCRIPT} is part of the repository checkout: run the benchmarks from a clone")
    spec = importlib.util.spec_from_file_location("yang_tables", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.main(["--quick", "--no-pictures"] if quick else [])


if __name__ == "__main__":
    main()

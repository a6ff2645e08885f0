"""The version of exactcagd, in a module that imports nothing (``exactcagd --version`` reads it
without loading the exact machinery; ``pyproject.toml`` reads it at build time)."""

__version__ = "0.1.0"

"""Scenes: files describing exact objects and wanted products; planner, runner, reference data."""

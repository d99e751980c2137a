"""Shared test settings: hypothesis profiles (fewer examples in CI) and small helpers."""
from __future__ import annotations

import importlib.util
import os
from pathlib import Path
from types import ModuleType

from hypothesis import HealthCheck, settings

settings.register_profile("default", max_examples=60, deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("ci", max_examples=20, deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("deep", max_examples=500, deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE") or ("ci" if os.environ.get("CI") else "default"))

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"


def hand_derivations() -> ModuleType:
    """tests/cases/derive.py, the textbook cases' hand derivations (Freudenstein, Norton's
    rate equations, loop closures), as a module; it is also a script, so it is loaded by
    path."""
    spec = importlib.util.spec_from_file_location("hand_derivations", ROOT / "tests" / "cases" / "derive.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module

"""Each joint kind's module shows a small model solved (its docstring's example, a number
derived by hand beside it), run here as a doctest for every kind the registry lists, so an
example that stops being true fails the suite."""
from __future__ import annotations

import doctest
import importlib

import pytest

from kinematika.joints import MODULES


@pytest.mark.parametrize("name", list(MODULES))
def test_the_kinds_example_holds(name):
    module = importlib.import_module(f"kinematika.joints.{MODULES[name]}")
    tests = [t for t in doctest.DocTestFinder().find(module) if t.name == module.__name__ and t.examples]
    assert tests, f"{name}: its module's docstring has no example"
    said: list[str] = []
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    result = runner.run(tests[0], out=said.append)
    assert result.failed == 0 and result.attempted == len(tests[0].examples), "".join(said)

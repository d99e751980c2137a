"""The kinds of question a model asks of a solved instant (`ask:`), each in one module that
says everything the kind means (what its target names, what it needs solved, how it is
answered, its unit, and how the views show, draw, explain and key it: `base.QuestionKind`),
and the registry the rest of kinematika asks (`QUESTIONS`, `answer`). Adding a kind is
adding its module and its line below (docs/questions.md).

A kind's module is imported when a question of that kind is first asked about, or when
every kind is asked for (iterating `QUESTIONS`), as the joints' kinds are.
"""
from __future__ import annotations

import functools
from collections.abc import Iterator, Mapping
from importlib import import_module
from typing import Any, Optional

from .base import About, Asked, Figure, Level, Quantity, QuestionKind, Solved, Steps, Words

MODULES = {                        # the question's key in model files -> its module, in the
    "velocity": "velocity",        # order the contract lists them (the order of the schema's
    "acceleration": "acceleration",    # keys and of messages that list them)
    "omega": "omega",
    "alpha": "alpha",
    "icr": "icr",
    "curvature": "curvature",
    "decompose": "decompose",
    "contact": "contact",
    "axis": "axis",
    "pole": "pole",
    "intrinsic": "intrinsic",
    "inflection": "inflection",
}


class Registry(Mapping):
    """The kinds by name, each imported on first use (then remembered)."""

    def __init__(self) -> None:
        self._loaded: dict[str, QuestionKind] = {}

    def __getitem__(self, name: str) -> QuestionKind:
        found = self._loaded.get(name)
        if found is None:
            module = MODULES[name]           # KeyError for an unknown kind, as a dict's
            found = self._loaded[name] = import_module(f".{module}", __name__).KIND
        return found

    def __iter__(self) -> Iterator[str]:
        return iter(MODULES)

    def __len__(self) -> int:
        return len(MODULES)


QUESTIONS: Mapping[str, QuestionKind] = Registry()

__all__ = ["MODULES", "QUESTIONS", "About", "Asked", "Figure", "Level", "Quantity", "QuestionKind", "Solved",
           "Steps", "Words", "answer", "field_kinds"]


def answer(sol: Solved, q: Asked) -> Any:
    """The raw answer (backend scalars) to one question: its kind's `answer`."""
    return QUESTIONS[q.kind].answer(sol, q)


@functools.cache
def field_kinds(kinds: Optional[tuple[str, ...]] = None) -> dict[str, Optional[Quantity]]:
    """The kind of quantity of every field a compound answer of `kinds` (names; default every
    kind) may have (`QuestionKind.fields` together: a field's name means the same in every
    answer). Only the kinds named are imported. Not to be changed: it is remembered."""
    out: dict[str, Optional[Quantity]] = {}
    for name in MODULES if kinds is None else kinds:
        out.update(QUESTIONS[name].fields)
    return out

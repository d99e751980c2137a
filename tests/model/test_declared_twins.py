"""The schema's records that pydantic builds at run time (`create_model`: a cam on a body, a
joint with every key its kinds declare, a question with every kind's keys) are declared for
mypy under `TYPE_CHECKING` with the same fields. Those declarations are a twin of the run-time
classes; this test keeps them equal: the names a declaration annotates, with its declared
base's fields (a cam on a body is declared as a `CamSpec`), are exactly the fields of the class
pydantic builds, so a new joint key that is not declared fails here. A declaration that reads
its other fields by name (`__getattr__`: a question's kinds) stands for the registry's keys."""
from __future__ import annotations

import ast
import inspect

import pytest

from kinematika.model import schema
from kinematika.questions import QUESTIONS

TWINS = ("BodyCamSpec", "JointSpec", "QuestionSpec")


def _declared() -> dict[str, set[str]]:
    """The fields of each class declared under `if TYPE_CHECKING:` in the schema: its annotated
    names, its declared bases' fields, and the question kinds where it reads names itself."""
    tree = ast.parse(inspect.getsource(schema))
    found: dict[str, set[str]] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING":
            for cls in (n for n in node.body if isinstance(n, ast.ClassDef)):
                names = {s.target.id for s in cls.body
                         if isinstance(s, ast.AnnAssign) and isinstance(s.target, ast.Name)}
                for base in (b.id for b in cls.bases if isinstance(b, ast.Name) and b.id != "Strict"):
                    names |= set(getattr(schema, base).model_fields)
                if any(isinstance(f, ast.FunctionDef) and f.name == "__getattr__" for f in cls.body):
                    names |= set(QUESTIONS)
                found[cls.name] = names
    return found


@pytest.mark.parametrize("name", TWINS)
def test_a_declaration_for_mypy_has_the_run_time_fields(name):
    declared = _declared()
    assert name in declared, f"{name} is no longer declared under TYPE_CHECKING"
    built = getattr(schema, name)
    inherited = {f for base in built.__mro__[1:] for f in getattr(base, "model_fields", {})}
    assert declared[name] == set(built.model_fields) - inherited, name

"""Every public name says what it is for: the briefing's rule ("a docstring on every public
name that says what and why"), kept true by reading the package's source (ast; nothing is
imported, so a module that needs an extra is read as well).

Required: a docstring on every module of src/kinematika; on every function and class defined
at module level whose name does not start with `_`; and on every public method of those
classes (properties included; dunder methods, private methods, a property's setter and
deleter and `typing.overload` stubs excluded: the getter's or the implementation's docstring
is theirs)."""
from __future__ import annotations

import ast
from collections.abc import Iterator
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent.parent / "src" / "kinematika"
ROOT = PACKAGE.parent.parent

Def = ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef


def _decorator_names(node: Def) -> list[str]:
    """The decorators as dotted text (``property``, ``x.setter``, ``typing.overload``)."""
    return [ast.unparse(d.func if isinstance(d, ast.Call) else d) for d in node.decorator_list]


def _explained_elsewhere(node: Def) -> bool:
    """A property's setter or deleter (its getter holds the docstring) or an overload stub."""
    return any(name.endswith((".setter", ".deleter")) or name.split(".")[-1] == "overload"
               for name in _decorator_names(node))


def _module_level(body: list[ast.stmt]) -> Iterator[Def]:
    """The definitions at a module's top level, those under an ``if``/``try`` there included
    (``if TYPE_CHECKING:``, an optional import's fallback)."""
    for stmt in body:
        if isinstance(stmt, Def):
            yield stmt
        elif isinstance(stmt, ast.If):
            yield from _module_level(stmt.body)
            yield from _module_level(stmt.orelse)
        elif isinstance(stmt, ast.Try):
            for block in (stmt.body, stmt.orelse, stmt.finalbody, *(h.body for h in stmt.handlers)):
                yield from _module_level(block)


def _public(name: str) -> bool:
    return not name.startswith("_")


def offenders(path: Path) -> Iterator[str]:
    """``file:line kind name`` for each public thing of module `path` without a docstring."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    where = path.relative_to(ROOT) if path.is_relative_to(ROOT) else path
    if ast.get_docstring(tree) is None:
        yield f"{where}:1 module"
    for node in _module_level(tree.body):
        if not _public(node.name) or _explained_elsewhere(node):
            continue
        kind = "class" if isinstance(node, ast.ClassDef) else "function"
        if ast.get_docstring(node) is None:
            yield f"{where}:{node.lineno} {kind} {node.name}"
        if isinstance(node, ast.ClassDef):
            for item in node.body:
                if (isinstance(item, ast.FunctionDef | ast.AsyncFunctionDef) and _public(item.name)
                        and not _explained_elsewhere(item) and ast.get_docstring(item) is None):
                    yield f"{where}:{item.lineno} method {node.name}.{item.name}"


def test_the_walk_sees_the_package():
    """The walk reads the real package (a wrong path would pass the test below on nothing)."""
    modules = sorted(PACKAGE.rglob("*.py"))
    assert len(modules) > 100
    assert PACKAGE / "solution.py" in modules


def test_the_rule_catches_what_it_should(tmp_path: Path):
    """The rule on a module written here: each kind of offender found, each exemption kept."""
    source = '''
import typing
def f(): pass
def _g(): pass
class C:
    def m(self): pass
    def __init__(self): pass
    def _h(self): pass
    @property
    def p(self):
        """Documented."""
    @p.setter
    def p(self, value): pass
    @typing.overload
    def o(self, x: int) -> int: ...
    def o(self, x):
        """Documented."""
class _Hidden:
    def m(self): pass
if typing.TYPE_CHECKING:
    def t(): pass
'''
    probe = tmp_path / "probe.py"
    probe.write_text(source, encoding="utf-8")
    found = [line.split(" ", 1)[1] for line in offenders(probe)]
    assert found == ["module", "function f", "class C", "method C.m", "function t"]


def test_every_public_name_has_a_docstring():
    """Lists every offender as file:line, to be written one by one."""
    missing = [line for path in sorted(PACKAGE.rglob("*.py")) for line in offenders(path)]
    assert not missing, f"{len(missing)} public names without a docstring:\n" + "\n".join(missing)

"""The one-pass YAML reader (`model.files._plain_yaml`) against PyYAML's own loader, on
generated documents, every model file of the repository and hostile text: the same Python values (their types too), or the
text left to the full reader; and, through `parse_text`, the same errors as the full reader
alone gives (one line naming the place)."""
from __future__ import annotations

import json
import random
from pathlib import Path

import pytest
import yaml
from hypothesis import given, strategies as st

from kinematika.errors import KinematikaError
from kinematika.model import files
from kinematika.model.files import _UNUSUAL, _plain_yaml, parse_text

ROOT = Path(__file__).parents[2]
LOADER = getattr(yaml, "CSafeLoader", None) or yaml.SafeLoader   # the parser the model files are read with
                                 # (libyaml and PyYAML's Python scanner differ on a few texts: a tab in a flow)
MODEL_FILES = sorted([*ROOT.glob("examples/*.yaml"), *ROOT.glob("benchmarks/models/*.yaml"),
                      *ROOT.glob("tests/**/*.yaml")])

# texts a resolver reads in many ways: YAML 1.1's booleans, nulls, numbers in every base,
# sexagesimals, dates, specials, and strings that look like them
TRICKY = ["yes", "Yes", "NO", "on", "Off", "y", "n", "true", "False", "~", "null", "Null", "NULL", "",
          "0", "-0", "+1", "007", "08", "0o17", "0x1F", "0b101", "1_000", "1__0", "1.5", "-2.", ".5", "+.5e3",
          "1e5", "1.0e+5", "6.8523015e+5", "685.230_15e+03", "190:20:30", "1:30.5", ".inf", "-.INF", ".NaN",
          "2001-12-14", "2001-12-14t21:59:43.10-05:00", "2001-12-14 21:59:43.10 -5", "2001-1-1", "=", "<<",
          "O1", "A0", "ground", "θ", "ünï", "a b", "1.5.2", "12e", "0x", "-", "--", "x-", "nan", "Inf"]
WORD = st.one_of(st.sampled_from(TRICKY),
                 st.text(alphabet="0123456789+-._:eExob yYnNtT~θ", min_size=1, max_size=8))


def _quoted(text: str, style: str) -> str:
    if style == "'":
        return "'" + text.replace("'", "''") + "'"
    return json.dumps(text)          # a JSON string is a double-quoted YAML scalar (\\u escapes too)


@st.composite
def scalars(draw: st.DrawFn) -> str:
    """A scalar as written: plain (which may not be valid YAML there), or quoted."""
    text = draw(WORD)
    style = draw(st.sampled_from(["plain", "plain", "plain", "'", '"']))
    return text if style == "plain" else _quoted(text, style)


def _flow(tree: object) -> str:
    if isinstance(tree, dict):
        return "{" + ", ".join(f"{k}: {_flow(v)}" for k, v in tree.items()) + "}"
    if isinstance(tree, list):
        return "[" + ", ".join(_flow(v) for v in tree) + "]"
    return str(tree)


def _block(tree: object, indent: int = 0) -> str:
    pad = " " * indent
    if isinstance(tree, dict) and tree:
        return "".join(f"{pad}{k}:\n{_block(v, indent + 2)}" if isinstance(v, (dict, list)) and v
                       else f"{pad}{k}: {_flow(v)}\n" for k, v in tree.items())
    if isinstance(tree, list) and tree:
        return "".join(f"{pad}-\n{_block(v, indent + 2)}" if isinstance(v, (dict, list)) and v
                       else f"{pad}- {_flow(v)}\n" for v in tree)
    return f"{pad}{_flow(tree)}\n"


TREES = st.recursive(scalars(), lambda inner: st.one_of(
    st.lists(inner, max_size=4), st.dictionaries(scalars(), inner, max_size=4)), max_leaves=12)


@st.composite
def documents(draw: st.DrawFn) -> str:
    tree = draw(TREES)
    return _flow(tree) + "\n" if draw(st.booleans()) else _block(tree)


def _outcome(read) -> tuple:
    """What a reader gives: its tree (repr: values and types), or its error (one line)."""
    try:
        return "tree", repr(read())
    except KinematikaError as err:
        return "error", err.kind, str(err)


def _full_reader(text: str) -> tuple:
    """`parse_text` without the one-pass reader: PyYAML's loader, then the tree's checks."""
    def read():
        tree = files._yaml(text, "m.yaml")
        files.check_tree(tree, "m.yaml")
        return tree
    return _outcome(read)


def _same_as_pyyaml(text: str) -> None:
    tree = _plain_yaml(text)
    if tree is not _UNUSUAL:
        assert repr(tree) == repr(yaml.load(text, Loader=LOADER)), text        # values and types
    assert _outcome(lambda: parse_text(text, "yaml", "m.yaml")) == _full_reader(text), text


@given(documents())
def test_a_generated_document_reads_as_the_safe_loader_reads_it(text):
    _same_as_pyyaml(text)


def test_the_generated_documents_are_mostly_read_in_one_pass():
    """(so that the test above compares trees, not only the fallback)"""
    rng = random.Random(34)
    texts = [_block({w: [w, {w: w}]}) for w in rng.sample(TRICKY, 40)]
    read = [t for t in texts if _plain_yaml(t) is not _UNUSUAL]
    assert len(read) >= 35


@pytest.mark.parametrize("path", MODEL_FILES, ids=[str(p.relative_to(ROOT)) for p in MODEL_FILES])
def test_every_model_file_in_the_repository_reads_as_the_safe_loader_reads_it(path):
    _same_as_pyyaml(path.read_text(encoding="utf-8"))


HOSTILE = ["\t", ":", ": ", "- ", "#", "&a ", "*a", "!!str ", "<<: ", "? ", "'", '"', "\\ud800", '"\\ud800"',
           "{", "}", "[", "]", ",", "|", ">", "\n", "\n---\n", "...", "%YAML 1.1\n", "\x00", "\ufeff", "é", "  "]


@pytest.mark.parametrize("seed", range(8))
def test_hostile_text_gives_the_full_readers_tree_or_error(seed):
    """Example files cut, doubled and sprinkled with YAML's indicators (fixed seeds): the
    same tree or the same error, line and column as the full reader's."""
    rng = random.Random(seed)
    examples = sorted(ROOT.glob("examples/*.yaml"))
    for _ in range(25):
        text = rng.choice(examples).read_text(encoding="utf-8")[:3000]
        for _ in range(rng.randint(1, 4)):
            at = rng.randrange(len(text) + 1)
            move = rng.random()
            if move < 0.6:
                text = text[:at] + rng.choice(HOSTILE) + text[at:]
            elif move < 0.8:
                text = text[:at] + text[at + rng.randint(1, 20):]
            else:
                text = text[:at] + text[at:at + 40] + text[at:]
        _same_as_pyyaml(text)

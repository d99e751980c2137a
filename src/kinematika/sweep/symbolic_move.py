"""`move` in a model with symbolic parameters (to come)."""
from __future__ import annotations

from ..errors import KinematikaError
from ..model.model import Model


def symbolic_moved(model: Model, jid: str, amount: float, where: str) -> Model:
    raise KinematikaError("schema", "moving a model with symbolic parameters needs numbers: give "
                          "them values (--set NAME=VALUE)", where)

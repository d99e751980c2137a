"""Which tasks the four-bar path takes: a four-bar model, the task's point on its coupler
(path, motion) or its output the rocker or the coupler (function), timed by its crank."""
from __future__ import annotations

from typing import Optional

import numpy as np

from ...errors import KinematikaError
from ...model.model import Model
from ..designs import Vary
from .linkage import four_bar_roles
from .problem import FourBarTask
from .task import Task


def fast_task(model: Model, task: Task, varied: list[Vary]) -> Optional[FourBarTask]:
    """The task on the closed-form four-bar, or None when the model or the task is another
    (the general path takes it). A requirement only a four-bar can meet, asked of another
    model, is a usage error."""
    roles = four_bar_roles(model)
    point = None
    ok = roles is not None
    if roles is not None and task.kind in ("path", "motion"):
        ref = model.resolve_point(task.point, "--point") if task.point else None
        ok = ref is not None and ref.body == roles.coupler
        point = ref.point if ref is not None else None
    if roles is not None and task.kind == "function":
        ok = task.body in (roles.rocker, roles.coupler)
    if roles is not None and ok and task.timing is not None:
        ok = task.timing.joint == roles.joint
    if roles is None or not ok:
        if task.requires.crank_rocker:
            raise KinematikaError("usage", "require-crank-rocker-four-bar", "--require")
        return None
    low = np.array([v.low for v in varied])
    high = np.array([v.high for v in varied])
    return FourBarTask(model, task, roles, [v.name for v in varied], low, high, point)

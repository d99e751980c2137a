"""Exact starting designs, where closed forms give them."""
from __future__ import annotations

import numpy as np

from .problem import FourBarTask


def starts(fbt: FourBarTask) -> list[np.ndarray]:
    """Designs (search vectors) that meet the targets exactly, for the search to start from."""
    return []

"""Progress of long work: a caller's callback, or a rich progress bar on a terminal."""
from __future__ import annotations

import sys
from typing import Callable, Optional

Reporter = Callable[[Optional[int]], None]


def reporter(progress: bool | Callable[[int, int], None], total: int, label: str) -> Reporter:
    """A callable `(done)` — `None` when finished — for `progress`: a callable `(done, total)`,
    True for a rich progress bar (only when stderr is a terminal), or False for nothing."""
    if callable(progress):
        return lambda done: progress(done, total) if done is not None else None
    if not progress or not sys.stderr.isatty():
        return lambda done: None
    from rich.progress import Progress

    bar = Progress(transient=True)
    task = bar.add_task(label, total=total)
    bar.start()

    def update(done: Optional[int]) -> None:
        if done is None:
            bar.stop()
        else:
            bar.update(task, completed=done)

    return update

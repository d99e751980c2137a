"""What every painting function shares: the axes, the scene, where infinite lines stop,
the label board, and how each body's drawing is placed (moved in an animation)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Optional

from .geometry import Box
from .labels import LabelBoard
from .scene import Scene


@dataclass
class Canvas:
    """What every painting function paints into: the matplotlib axes, the `Scene`, the `view`
    infinite lines are clipped to, the label board, whether labels and English words are shown,
    each body's placement in an animation and the artists moving with it, and the language
    numbers are written in."""

    ax: Any
    scene: Scene
    view: Box                                  # infinite lines and far things are clipped here
    board: LabelBoard = field(default_factory=LabelBoard)
    labels: bool = True
    words: bool = True                         # English words in labels ("at ∞"); a bare figure
                                               # embedded in a page of any language has none
    placement: Optional[Callable[[str], Any]] = None   # body -> extra transform (animation)
    moving: dict = field(default_factory=dict)         # body -> artists that move with it
    lang: Optional[str] = None                 # numbers as this language writes them (DrawOptions)

    @property
    def size(self) -> float:
        """The mechanism's extent, which symbols, arrows and margins are scaled by."""
        return self.scene.size

    def transform(self, body: Optional[str]) -> Any:
        """Data transform for artists fixed in `body`: the body's placement, then the axes'."""
        if body is None or self.placement is None:
            return self.ax.transData
        return self.placement(body) + self.ax.transData

    def add(self, artist: Any, body: Optional[str] = None) -> Any:
        """Add a line or patch fixed in `body` (None: fixed on the page).

        As a plain artist (`add_artist`: drawn in the same order, clipped to the axes), not
        by `add_line`/`add_patch`, which also widen the axes' data limits for autoscaling:
        every figure's limits are set before it is painted (`figure.new_figure`) and nothing
        autoscales, so that was a fifth of painting's time spent on limits never read."""
        artist.set_transform(self.transform(body))
        self.ax.add_artist(artist)
        if body is not None:
            self.moving.setdefault(body, []).append(artist)
        return artist

    def label(self, anchor: Any, text: str, colour: str, priority: int, gid: str,
              prefer: Any = None, **kw: Any) -> None:
        """Put a label on the board at `anchor` (placed when the figure is finished, clear of
        the others; lower `priority` first), unless labels are off."""
        if self.labels:
            self.board.add(anchor, text, colour, priority, gid, prefer, **kw)


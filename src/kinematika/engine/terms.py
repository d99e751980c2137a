"""The factors of the acceleration terms that come from the velocities: the one hook through
which a view solves a mechanism *as a student with a known mistake would* (kinematika's
exercises name the mistake behind a wrong answer by solving again with it).

    a_P = a_O + α × r + n · ω × (ω × r)                      (normal, centripetal term)
    a_P(b) = a_P(a) + a_rel + c · 2 ω_a × v_rel              (Coriolis term)

Mechanics is n = c = 1 (`MECHANICS`), which every command uses. A mistaken world is
`Terms(coriolis=0)` (the Coriolis term left out), `Terms(coriolis=2)` (doubled) or
`Terms(normal=0)` (the centripetal terms left out). The engine reads the factors in these
places only, all at the acceleration level or below it:

- `levels.AccelerationLevel.point`: n on ω × (ω × r) in every joint's and driver's rows;
- `joints.derivatives.sliding`: c on 2 v_rel·(ω_a × e) (the joints that slide: prismatic,
  slot, cylindrical), through `Level.terms` (`engine.levels`, taken from the velocities'
  `Motion`);
- `drivers._velocity`: c on the Coriolis term of a relative velocity driver's acceleration;
- `motion.Motion`: n in the reported point accelerations, c in the relative frame's
  Coriolis term; in a mistaken world a relative point acceleration is the composition at
  the point, a_rel = a_P(b) − a_P(F) − c · 2 ω_F × v_rel, as the student writes it.

The factors are small integers, so that with mechanics' 1 every formula is the one written
without them (exact and numeric alike): a factor of 1 multiplies nothing.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Terms:
    """Factors on the Coriolis term (`coriolis`, c) and on the normal terms (`normal`, n)."""

    coriolis: int = 1
    normal: int = 1

    @property
    def mechanics(self) -> bool:
        """Whether these are the true factors (every command's)."""
        return self.coriolis == 1 and self.normal == 1

    def normal_part(self, vector: tuple) -> tuple:
        """n · ω × (ω × r), given ω × (ω × r)."""
        return vector if self.normal == 1 else tuple(self.normal * c for c in vector)

    def coriolis_factor(self) -> int:
        """2c: the factor of ω × v_rel in the Coriolis term."""
        return 2 * self.coriolis


MECHANICS = Terms()

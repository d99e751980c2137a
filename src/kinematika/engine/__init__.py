"""The engine: one instant of a model evaluated (`instant`, `positions`), its joints and drivers
written as linear rows in the bodies' twists (`joints`, `drivers`, `levels`), the velocity
system and then the acceleration system with the same matrix solved on numbers or on symbols
(`system`, `linsolve`, `exact`), and the solved `motion` every view reads."""

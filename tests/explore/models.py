"""Model families for design studies, written by dimensions (constructions) with parameters."""
from __future__ import annotations

FOUR_BAR = """
name: Four-bar family
parameters:
  g: 5.2        # ground O2-O4
  a: 2.25       # crank
  b: 6.1        # coupler
  c: 4.35       # rocker
  px: 3.4       # coupler point P along AB
  py: -1.15     # and to its left
  theta: deg(52)
  w: 9.5
points:
  O2: [0, 0]
  O4: [g, 0]
  A: {from: O2, distance: a, angle: theta}
  B: {circles: [[A, b], [O4, c]], side: left}
  P: {frame: [A, B], at: [px, py]}
bodies:
  ground: [O2, O4]
  crank: [O2, A]
  coupler: [A, B, P]
  rocker: [O4, B]
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [crank, coupler], at: A}
  - {type: revolute, bodies: [coupler, rocker], at: B}
  - {type: revolute, bodies: [ground, rocker], at: O4}
drivers:
  - {omega: crank, value: w, alpha: -21}
"""

SLIDER_CRANK = """
name: Offset slider-crank family
parameters:
  r: 1
  l: 3
  e: 0.5
  theta: deg(60)
points:
  O: [0, 0]
  A: {from: O, distance: r, angle: theta}
  B: {circle: [A, l], line: {through: [0, e], direction: [1, 0]}, side: ahead}
bodies:
  ground: [O]
  crank: [O, A]
  rod: [A, B]
  slider: [B]
joints:
  - {type: revolute, bodies: [ground, crank], at: O}
  - {type: revolute, bodies: [crank, rod], at: A}
  - {type: revolute, bodies: [rod, slider], at: B}
  - {type: prismatic, bodies: [ground, slider], along: [1, 0]}
drivers:
  - {joint: j1, rate: 10, accel: 2}
"""

QUICK_RETURN = """
name: Whitworth-type quick return (crank and slotted lever)
parameters:
  r: 0.1
  c: 0.3
  L: 0.5
  th: deg(30)
points:
  O4: [0, 0]
  O2: [0, c]
  A: {from: O2, distance: r, angle: th}
  B: {from: O4, distance: L, angle: 0, reference: [O4, A]}
bodies:
  ground: [O4, O2]
  crank: [O2, A]
  rocker: [O4, A, B]
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [ground, rocker], at: O4}
  - {type: slot, bodies: [rocker, crank], at: A, along: [O4, B]}
drivers:
  - {omega: crank, value: 10, alpha: 0}
"""

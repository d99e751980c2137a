"""The model file's shape checked in plain Python: `spec_of` returns `schema`'s records
for a file that is right, or None so that pydantic checks it and says what is wrong.

GENERATED from `schema` by `python -m kinematika.model.generate_shape`:
do not edit (why and how: that module's docstring).
"""
from __future__ import annotations

from typing import Any, Optional

from ..joints import KINDS
from .plain import (REQUIRED, Record, by_type, checked, either, exact, first_key, listed,
                    mapping, one_of, optional, pydantic_decides, record)

JOINT_KEYS = ('at', 'along', 'axis', 'internal')

ParameterSpec, parameter_spec = record('ParameterSpec', {
    'value': (optional(exact(int, float, str)), None),
    'positive': (exact(bool), True),
    'symbolic': (exact(bool), False),
    'description': (optional(exact(str)), None),
})
value = exact(int, float, str)
vector = listed(value)
location = either(exact(str), vector)
PolarSpec, polar_spec = record('PolarSpec', {
    'from_': (location, REQUIRED),
    'distance': (value, REQUIRED),
    'angle': (value, REQUIRED),
    'reference': (optional(listed(location, 2, 2)), None),
}, keys={'from_': 'from'})
FrameSpec, frame_spec = record('FrameSpec', {
    'frame': (listed(location, 2, 2), REQUIRED),
    'at': (listed(value, 2, 2), REQUIRED),
})
circle_ref = listed(either(exact(str, int, float), vector), 2, 2)
CirclesSpec, circles_spec = record('CirclesSpec', {
    'circles': (listed(circle_ref, 2, 2), REQUIRED),
    'side': (optional(one_of('left', 'right')), None),
    'near': (optional(vector), None),
})
LineSpec, line_spec = record('LineSpec', {
    'through': (location, REQUIRED),
    'direction': (vector, REQUIRED),
})
line_ref = either(listed(location, 2, 2), line_spec)
CircleLineSpec, circle_line_spec = record('CircleLineSpec', {
    'circle': (listed(either(exact(str, int, float), vector), 2, 2), REQUIRED),
    'line': (line_ref, REQUIRED),
    'side': (optional(one_of('ahead', 'behind')), None),
    'near': (optional(vector), None),
})
LinesSpec, lines_spec = record('LinesSpec', {
    'lines': (listed(line_ref, 2, 2), REQUIRED),
})
construction_spec = first_key(
    ('from', polar_spec), ('frame', frame_spec), ('circles', circles_spec),
    ('circle', circle_line_spec), ('lines', lines_spec))
point_spec = by_type({dict: construction_spec, list: vector})
CircleSpec, circle_spec = record('CircleSpec', {
    'center': (location, REQUIRED),
    'radius': (value, REQUIRED),
    'arc': (optional(listed(exact(int, float), 2, 2)), None),
})
DiscSpec, disc_spec = record('DiscSpec', {
    'center': (location, REQUIRED),
    'radius': (value, REQUIRED),
    'axis': (vector, REQUIRED),
})
PlaneSpec, plane_spec = record('PlaneSpec', {
    'through': (location, REQUIRED),
    'normal': (vector, REQUIRED),
})
CurveSpec, curve_spec = record('CurveSpec', {
    'through': (listed(location, 3, 10000), REQUIRED),
    'closed': (exact(bool), False),
})
BodySpec, body_spec = record('BodySpec', {
    'points': (listed(exact(str)), list),
    'circle': (optional(either(circle_spec, listed(circle_spec))), None),
    'line': (optional(line_spec), None),
    'disc': (optional(disc_spec), None),
    'plane': (optional(plane_spec), None),
    'curve': (optional(curve_spec), None),
    'cam': (optional(pydantic_decides), None),
    'description': (optional(exact(str)), None),
})
joint_type = one_of(*KINDS)
JointSpec, joint_spec = record('JointSpec', {
    'type': (joint_type, REQUIRED),
    'bodies': (listed(exact(str), 2, 2), REQUIRED),
    'id': (optional(exact(str)), None),
    'at': (optional(exact(str)), None),
    'along': (optional(vector), None),
    'axis': (optional(vector), None),
    'internal': (optional(exact(bool)), None),
    'description': (optional(exact(str)), None),
})
OmegaDriver, omega_driver = record('OmegaDriver', {
    'omega': (exact(str), REQUIRED),
    'value': (either(exact(int, float, str), vector), REQUIRED),
    'alpha': (either(exact(int, float, str), vector), 0),
    'relative_to': (optional(exact(str)), None),
})
JointDriver, joint_driver = record('JointDriver', {
    'joint': (exact(str), REQUIRED),
    'rate': (value, REQUIRED),
    'accel': (value, 0),
})
VelocityDriver, velocity_driver = record('VelocityDriver', {
    'velocity': (exact(str), REQUIRED),
    'value': (either(exact(int, float, str), vector), REQUIRED),
    'acceleration': (either(exact(int, float, str), vector), 0),
    'along': (optional(vector), None),
    'relative_to': (optional(exact(str)), None),
})
driver_spec = first_key(
    ('omega', omega_driver), ('joint', joint_driver), ('velocity', velocity_driver))
QuestionSpec, question_spec = record('QuestionSpec', {
    'velocity': (optional(exact(str)), None),
    'acceleration': (optional(exact(str)), None),
    'omega': (optional(exact(str)), None),
    'alpha': (optional(exact(str)), None),
    'icr': (optional(exact(str)), None),
    'curvature': (optional(exact(str)), None),
    'decompose': (optional(exact(str)), None),
    'contact': (optional(exact(str)), None),
    'axis': (optional(exact(str)), None),
    'pole': (optional(exact(str)), None),
    'intrinsic': (optional(exact(str)), None),
    'inflection': (optional(exact(str)), None),
    'relative_to': (optional(exact(str)), None),
    'moving': (optional(exact(str)), None),
})
SweepSpec, sweep_spec = record('SweepSpec', {
    'joint': (optional(exact(str)), None),
    'by': (value, 360),
    'steps': (exact(int), 360),
})
SimulateSpec, simulate_spec = record('SimulateSpec', {
    'time': (value, REQUIRED),
    'steps': (exact(int), 200),
})
DimensionSpec, dimension_spec = record('DimensionSpec', {
    'between': (listed(exact(str), 2, 2), REQUIRED),
    'along': (optional(one_of('x', 'y', 'aligned')), None),
    'label': (optional(exact(str)), None),
})
ExerciseSpec, exercise_spec = record('ExerciseSpec', {
    'title': (mapping(exact(str)), dict),
    'statement': (mapping(exact(str)), dict),
    'units': (mapping(exact(str)), dict),
    'length': (exact(str), 'm'),
    'ask': (optional(listed(exact(int))), None),
    'tolerance': (exact(int, float), 0.01),
    'weights': (optional(listed(exact(int, float))), None),
    'dimensions': (listed(dimension_spec), list),
})
LanguageNames, language_names = record('LanguageNames', {
    'title': (optional(exact(str)), None),
    'bodies': (mapping(exact(str)), dict),
    'points': (mapping(exact(str)), dict),
    'joints': (mapping(exact(str)), dict),
    'parameters': (mapping(exact(str)), dict),
    'data': (listed(exact(str)), list),
    'notes': (listed(exact(str)), list),
})
ModelSpec, model_spec = record('ModelSpec', {
    'name': (optional(exact(str)), None),
    'description': (optional(exact(str)), None),
    'dimension': (optional(one_of(2, 3)), None),
    'frame': (exact(str), 'ground'),
    'parameters': (mapping(optional(either(exact(int, float, str), parameter_spec))), dict),
    'points': (mapping(point_spec), REQUIRED),
    'bodies': (mapping(either(listed(exact(str)), body_spec)), REQUIRED),
    'joints': (listed(joint_spec), list),
    'drivers': (listed(driver_spec), list),
    'ask': (optional(listed(question_spec)), None),
    'sweep': (optional(sweep_spec), None),
    'simulate': (optional(simulate_spec), None),
    'move': (optional(mapping(value)), None),
    'draw_at': (optional(mapping(exact(int, float))), None),
    'up': (optional(listed(exact(int, float))), None),
    'exercise': (optional(exercise_spec), None),
    'names': (optional(mapping(language_names)), None),
    'notation': (optional(mapping(either(exact(str), mapping(exact(str))))), None),
})

RECORDS = (
    ModelSpec, ParameterSpec, PolarSpec, FrameSpec, CirclesSpec, CircleLineSpec, LineSpec, LinesSpec,
    BodySpec, CircleSpec, DiscSpec, PlaneSpec, CurveSpec, JointSpec, OmegaDriver, JointDriver,
    VelocityDriver, QuestionSpec, SweepSpec, SimulateSpec, ExerciseSpec, DimensionSpec,
    LanguageNames,
)


def spec_of(tree: Any) -> Optional[Record]:
    """The checked model file, or None when pydantic must look at it (it may be wrong)."""
    return checked(model_spec, tree)

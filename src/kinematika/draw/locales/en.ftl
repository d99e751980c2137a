# The words a figure writes itself (kinematika draw --lang): legend, notes, far-off labels.
legend-velocity = velocity
legend-acceleration = acceleration
legend-centre = instant centre
legend-kennedy = Kennedy line
legend-normal = normal to a wheel or slot
legend-pole = acceleration pole
legend-curvature = curvature circle
note-at-infinity = { $labels } at infinity, direction { $direction }
note-no-relative-motion = { $count ->
    [one] { $labels }: no relative motion
   *[other] no relative motion: { $labels }
}
note-enlarged = arrows are to scale within each kind (the longest is { $longest } of the drawing); those marked “enlarged” are drawn at the minimum length ({ $shortest })
note-3d = 3D model: { $view } orthographic projection{ $up ->
    [none] {""}
   *[other] , { $up } up
} (axes x, y, z shown at the lower right)
view-iso = isometric
note-bodies = bodies: { $bodies }
note-drawn-at-given = symbolic model drawn at { $values } (its draw_at values)
note-drawn-at-some = symbolic model drawn at { $values } (draw_at values, generic ones for the rest)
note-drawn-at-generic = symbolic model drawn at generic values { $values } (a model's draw_at sets them)
note-curvature-rest = { $label } is at rest: no path curvature
note-curvature-straight = { $label }: the path is straight here (infinite radius)
label-far-off = { $label } at { $place }
label-at-infinity = { $label } at ∞
label-curvature-centre = { $label }, centre { $place }

## English messages of `kinematika explain`. Placeholders in braces are filled by the
## renderer with symbols, values or other messages; keep them in every translation.

sec-data = Data
data-numeric = Units: lengths in { $unit }, { $accelerations ->
        [0] velocities in { $unit }/s and angular velocities in rad/s.
       *[other] velocities in { $unit }/s, accelerations in { $unit }/s², angular velocities in rad/s and angular accelerations in rad/s².
    }
data-planar = Planar motion: angular velocities{ $accelerations ->
        [0] {""}
       *[other] {" "}and accelerations
    } are signed, counter-clockwise positive.
data-relative = The notation of a relative quantity names both bodies: { $v } is the velocity of the point { $point } of { $body_b } seen from { $body_a }{ WORD($rate) ->
        [yes] , and { $w } the angular velocity of { $body_b } relative to { $body_a }.
       *[no] .
    }
data-spatial = Angular velocities and accelerations are vectors (right-hand rule about their direction).
data-symbolic = The data are symbols, and every result is an exact formula in them. The figures are drawn at sample values of the symbols, given under each figure.
data-symbol = a symbol (any value)
data-constructed = placed by construction (see Position)
data-circles = centre { $centre }, radii { $radii }
data-circle = centre { $centre }, radius { $radius }
data-line = through { $through }, direction { $direction }
data-plane = through { $through }, normal { $direction }
col-symbol = symbol
col-value = value
col-position = position
col-shape = shape
col-given = data
sec-structure = Structure
col-body = body
col-points = points
col-joint = joint
col-bodies = bodies
col-where = where
col-omega = angular velocity
col-alpha = angular acceleration
col-question = question
col-answer = answer
structure-subscripts = Notation: { $pairs }.
rate-precession = the precession
structure-subscript_pair = { $sym } is the angular velocity of { $body }
# a relative rate the model's notation writes otherwise (C5-2.1's δ̇ for ω_{fork rel chassis}): defined where the notation line is (twenty-eighth round d)
structure-subscript_noted_rel = { $sym } is the angular velocity of { $body } relative to { $other }
structure-subscript_drag = { $equal } is the drag { WORD($kind) ->
        [accel] acceleration
       *[speed] velocity
    } of { $point }
structure-subscript_member = { $sym } is the velocity of the point of { $body } at { $point }
structure-subscript_rel = { $sym } is the { WORD($kind) ->
        [rate2] angular acceleration of { $body }
        [speed] velocity of the point { $point } of { $body }
        [accel] acceleration of the point { $point } of { $body }
       *[rate] angular velocity of { $body }
    } relative to { $other } (two names joined by “rel”: the first body relative to the second)
structure-shaped = { $body }, { $shape } of radius { $radius }
# a body with several round shapes: its welded wheels, said once (twenty-ninth round b)
structure-shaped_welded = { $body }, { $n ->
        [2] two
       *[other] { $n }
    } wheels in one piece, of radii { $radii }
# the fixed body with no shape: its own name, marked fixed; the text names it so wherever it is a reference (twenty-seventh round e)
structure-frame_named = { $body } (fixed)
structure-welded = { $bodies } { $bodies_n ->
        [one] is
       *[other] are
    } fixed to { $frame }: { $bodies_n ->
        [one] it is part of it and does not move; all its
       *[other] they are part of it and do not move; all their
    } points have zero velocity and acceleration.
structure-contacts_wheel = { $points_n ->
        [one] contact point under { $points }
       *[other] contact points under { $points }
    }
structure-contacts_rolling = { $points_n ->
        [one] contact point { $points }
       *[other] contact points { $points }
    }
# the frame's row names the parts welded to it: they are the frame (twenty-ninth round b)
structure-frame_parts = { $body }, with { $parts }
structure-fixed_part = { $body } (fixed to { $frame })
structure-dof = The mechanism has { $dof ->
        [one] one degree
        [2] two degrees
        [3] three degrees
       *[other] { $dof } degrees
    } of freedom.
structure-dof_data = The mechanism has { $dof ->
        [one] one degree
        [2] two degrees
        [3] three degrees
       *[other] { $dof } degrees
    } of freedom, one for each datum ({ $data }).
shape-concentric = { $n ->
        [2] two concentric circles
       *[other] { $n } concentric circles
    }
shape-circle = circle
shape-line = line
shape-disc = disc
shape-plane = plane
joint-revolute = revolute (R)
joint-prismatic = prismatic (P)
joint-revolute_word = hinge
joint-prismatic_word = prismatic pair
joint-slot = pin in slot
joint-slot_fixed = sliding contact on a fixed line
joint-wheel = wheel (knife edge)
joint-rolling = rolling
joint-gear = gear
joint-weld = rigid joint
joint-spherical = spherical
joint-cylindrical = cylindrical
along-joint = { WORD($verb) ->
        [only] along { $dir }
        [rolls] the wheel at { $point } rolls along { $dir }
       *[slides] { $point } slides along { $dir }
    }
along-horizontal = a horizontal line
along-vertical = a vertical line
along-angle = { $vec }, at { $deg }° to the horizontal
along-vector = { $vec }
along-line = { $line }
fig-arrow-velocity = the velocity of { $point }
fig-arrow-drag = the drag velocity ({ $sym })
fig-arrow-relative = the relative velocity ({ $sym })
fig-own_drag = the velocity of { $point } and its drag velocity ({ $sym })
fig-rest = ; { $count ->
        [one] { $points } has zero velocity at this instant{ $centre }, written beside it
       *[other] { $points } have zero velocity at this instant, written beside them
    }
fig-contact = The three points that coincide at the contact { $point } at this instant, on the mechanism to scale: the point of { $a }, the point of { $b } and the geometric contact point { $geom }. { $moving ->
        [0] {""}
        [one] { $format ->
            [md] The arrow
           *[other] The { $accel ->
                [0] blue
               *[other] red
            } arrow
        } is { $arrows }{ $moduli ->
            [0] {""}
            [2] {", with its magnitude, in "}{ $unit }
           *[other] {", with its magnitude"}
        }
       *[other] { $format ->
            [md] The arrows
           *[other] The { $accel ->
                [0] blue
               *[other] red
            } arrows
        } are { $arrows }, to one scale{ $moduli ->
            [0] {""}
            [2] {", with their magnitudes, in "}{ $unit }
           *[other] {", with their magnitudes"}
        }
    }{ $still ->
        [0] .
        [one] { $moving ->
            [0] {""}
           *[other] {"; "}
        }{ $zeros } is zero, written beside { $point }.
       *[other] { $moving ->
            [0] {""}
           *[other] {"; "}
        }{ $zeros } are zero, written beside { $point }.
    }
fig-mechanism = The mechanism at this instant, to scale{ $dim ->
        [3] , in isometric projection (the axes x, y, z at the lower right)
       *[other] {""}
    }; { $arrows ->
        [0] no velocity is drawn
        [1] { $format ->
            [md] the arrow
           *[other] the blue arrow
        } is the velocity of { $points }{ $moduli ->
            [0] {""}
            [2] {", with its magnitude, in "}{ $unit }/s
           *[other] {", with its magnitude"}
        }
        [3] { $points } has zero velocity at this instant{ $centre }, written beside it
        [4] { $format ->
            [md] the arrows
           *[other] the blue arrows
        } are { $points }, to one scale{ $moduli ->
            [0] {""}
            [2] {", with their magnitudes, in "}{ $unit }/s
           *[other] {", with their magnitudes"}
        }
       *[other] { $format ->
            [md] the arrows
           *[other] the blue arrows
        } are the velocities of { $points }, to one scale{ $moduli ->
            [0] {""}
            [2] {", with their magnitudes, in "}{ $unit }/s
           *[other] {", with their magnitudes"}
        }
    }{ $rest }; the bodies are numbered.
fig-rest_centre = {" "}(it is the instant centre of { $body })
fig-mechanism_named = The mechanism at this instant, to scale{ $dim ->
        [3] , in isometric projection (the axes x, y, z at the lower right)
       *[other] {""}
    }; { $arrows ->
        [0] no velocity is drawn
        [1] { $format ->
            [md] the arrow
           *[other] the blue arrow
        } is the velocity of { $points }{ $moduli ->
            [0] {""}
            [2] {", with its magnitude, in "}{ $unit }/s
           *[other] {", with its magnitude"}
        }
        [3] { $points } has zero velocity at this instant{ $centre }, written beside it
        [4] { $format ->
            [md] the arrows
           *[other] the blue arrows
        } are { $points }, to one scale{ $moduli ->
            [0] {""}
            [2] {", with their magnitudes, in "}{ $unit }/s
           *[other] {", with their magnitudes"}
        }
       *[other] { $format ->
            [md] the arrows
           *[other] the blue arrows
        } are the velocities of { $points }, to one scale{ $moduli ->
            [0] {""}
            [2] {", with their magnitudes, in "}{ $unit }/s
           *[other] {", with their magnitudes"}
        }
    }{ $rest }.
fig-at_pole = { $count ->
    [one] { $images } is at the pole o, since { $zero }.
   *[other] { $images } are at the pole o, since { $zero }.
}
fig-moved_aside = A term that would lie on another arrow is drawn beside it, parallel and to scale; { $format ->
        [md] dashed lines join
       *[other] grey dashes join
    } its ends to the points it runs between.
fig-too_short = { $count ->
    [one] { $terms } is too short to be seen at this scale (shorter than an arrowhead); its value is in the text.
   *[other] { $terms } are too short to be seen at this scale (shorter than an arrowhead); their values are in the text.
}
fig-o_prime = The image of O is lettered o′, because the letter o names the pole.
fig-o_prime_named = o′, the image of O,
fig-o_prime_fixed = o′, the image of the fixed point O of { $body },
fig-centre_image = { $count ->
    [one] the image of the instant centre { $centre }
   *[other] the images of the instant centres { $centre }
}
fig-primed = The image of the point { $point } is { $image } ({ $symbol } is the { $what }).
fig-a_symbol = symbol of a datum
fig-polygon_v = Velocity polygon, to scale. From the pole o its terms are laid head to tail{ $result ->
        [1] , and their sum { $sym } closes it
       *[other] {""}
    }{ $format ->
        [md] {""}
       *[other] {" "}(known terms in black{ $unknown ->
            [1] , terms found in this step in red
           *[other] {""}
        }{ $result ->
            [1] , the sum in blue
           *[other] {""}
        })
    }. Each vertex is the image of a point.
fig-polygon_a = Acceleration polygon, to scale. From the pole o its terms are laid head to tail{ $result ->
        [1] , and their sum { $sym } closes it
       *[other] {""}
    }{ $format ->
        [md] {""}
       *[other] {" "}(known terms in black{ $unknown ->
            [1] , terms found in this step in red
           *[other] {""}
        }{ $result ->
            [1] , the sum in blue
           *[other] {""}
        })
    }. Each vertex is the image of a point.
fig-sample = Drawn at sample values of the symbols.
sec-position = Position
pos-intro = Position analysis: each moving point is placed as the statement places it, from points already placed.
pos-named = Here { $name } = { $formula }.
pos-moved = The mechanism is analysed where the move takes it, each body carried from the drawing as follows.
pos-turn_angle = { $body } { COUNT($body) ->
        [many] have
       *[one] has
    } turned by { $angle } about { $pivot }.
pos-turn_toward = { $body } { COUNT($body) ->
        [many] have
       *[one] has
    } turned as the line { $line } has.
pos-turn_shift = { $body } { COUNT($body) ->
        [many] have
       *[one] has
    } moved { $shift } along { COUNT($body) ->
        [many] their
       *[one] its
    } guide.
pos-carried = { $point } is carried with { $body }: { $point } = { $at }.
pos-polar = { $point } is at distance { $distance } from { $origin }, at { $angle } from the x axis: { $point } = { $at }.
pos-polar_ref = { $point } is at distance { $distance } from { $origin }, at { $angle } from the direction { $ref }: { $point } = { $at }.
pos-frame = { $point } is at a distance { $x } from { $origin } along { $line } and { $y } across it, on the left as one looks from { $from } towards { $to }: { $point } = { $at }.
pos-frame_right = { $point } is at a distance { $x } from { $origin } along { $line } and { $y } across it, on the right as one looks from { $from } towards { $to }: { $point } = { $at }.
pos-frame_on = { $point } is at a distance { $x } from { $origin } along { $line }: { $point } = { $at }.
pos-circles = { $point } is at distance { $r1 } from { $c1 } and { $r2 } from { $c2 }: the intersection of two circles, about { $c1 } and about { $c2 }. Of the two points where they meet, it is { $which }: { $point } = { $at }.
pos-circle_line = { $point } is at distance { $r } from { $c } on the line { $line }: the intersection of a circle about { $c } and a line. Of the two points where they meet, it is { $which }: { $point } = { $at }.
pos-lines = { $point } is where the lines { $l1 } and { $l2 } meet: { $point } = { $at }.
pos-line_dir = through { $through } along { $dir }
pos-left = the one on the left as one looks from { $a } towards { $b }
pos-right = the one on the right as one looks from { $a } towards { $b }
pos-upper = the upper one
pos-lower = the lower one
pos-leftmost = the one on the left
pos-rightmost = the one on the right
pos-ahead = the one farther along the line { $line }
pos-behind = the one farther back along the line { $line }
pos-near = the one nearer the sketch point { $near }
pos-touch = the single point where they touch
pos-assembly = { $which }, { $assembly }
pos-open = the open assembly (the links do not cross)
pos-crossed = the crossed assembly (the links cross)

sec-order = Order of solution
order-assur = The mechanism is decomposed into its inputs and dyads; each is solved from bodies already known:
order-blocks = The bodies are found in this order, each from bodies already known:
order-item = { $n }. { $kind }: { $bodies }, from { $known }.
order-item_group = { $n }. { $bodies }, from { $known }.
order-item_through = { $n }. { $kind }: { $bodies }, from { $known }, through { $through }.
order-item_group_through = { $n }. { $bodies }, from { $known }, through { $through }.
order-item_data = { $n }. { $kind }: { $bodies }, from the data.
order-item_group_data = { $n }. { $bodies }, from the data.
order-from = { $name }
kind-input = input (driven body)
kind-RRR = RRR dyad
kind-RRP = RRP dyad
kind-RPR = RPR dyad
kind-PRP = PRP dyad
kind-other = group solved together
step-title = Step { $n }: { $kind } — { $bodies }
step-title_group = Step { $n }: { $bodies }
sec-velocities = Velocities
sec-accelerations = Accelerations
v-intro = Each vector equation is annotated as in the notes: M: magnitude known; D: direction known; ?: unknown; ⊥ and ∥ give a known direction.{ $marks ->
        [1] { WORD($clash) ->
            [M] {" "}Here M marks a known magnitude; it is not the point M.
           *[other] {" "}Here D marks a known direction; it is not the point D.
        }
        [2] {" "}Here M and D are these marks; they are not the points M and D.
       *[other] {""}
    } A planar vector equation solves two unknowns{ $format ->
        [md] : the terms marked ?, which the step finds
       *[other] ; the terms found in the step are in red
    }.
a-intro = With the velocities known, every normal term and every Coriolis term is known; the tangential and relative terms are the unknowns.
a-intro_relative = With the velocities known, every normal term is known; the tangential and relative terms are the unknowns.
a-intro_normal = With the velocities known, the normal terms are known; the tangential terms are the unknowns.
eq-shared_rate = The terms { $terms } share one unknown, { $rate }: their magnitudes are { $mags }, so their two ? count as one.
a-named = Where a formula written out would be past reading, the angular velocities found in “{ sec-velocities }” are written by name: { $name } for the ω of { $body }, and so for every body.
driver-omega = Given: { $sym } = { $value }.
driver-omega_sense = Given: { $sym } = { $value }, { $faster ->
        [1] in the sense of { $w }: { $body } { COUNT($body) ->
            [many] are
           *[one] is
        } speeding up
       *[other] against { $w }: { $body } { COUNT($body) ->
            [many] are
           *[one] is
        } slowing down
    }.
# a point given no acceleration: said as the notes say it, it moves at constant velocity (twenty-ninth round a)
driver-steady = Given: { $point } moves at constant velocity ({ $sym } = 0).
# a body given no angular acceleration: it turns at a constant rate (twenty-ninth round a)
driver-omega_steady = Given: { $body } { COUNT($body) ->
        [many] turn
       *[one] turns
    } at a constant rate ({ $sym } = 0).
driver-velocity = Given: { $sym } = { $value }.
driver-along = Given: the component of { $sym } along { $along } is { $value }.
driver-whole = Given: { $sym } = { $value }, { $heading }.
driver-held = At this instant { $b } { COUNT($b) ->
        [many] do
       *[one] does
    } not turn relative to { $a } about the pin { $point }: { $sym } = 0.
driver-held_accel = The pin { $point } has no relative angular acceleration at this instant: { $sym } = 0.
heading-right = to the right
heading-left = to the left
heading-up = upwards
heading-down = downwards
heading-along = along { $along }
readoff-along_x = along x:
readoff-along_y = along y:
input-revolute = { $body } { COUNT($body) ->
        [many] turn
       *[one] turns
    } about the fixed pivot { $point }: { COUNT($body) ->
        [many] their
       *[one] its
    } points move on circles about { $point }.
input-prismatic = { $body } { COUNT($body) ->
        [many] slide
       *[one] slides
    } without turning along { COUNT($body) ->
        [many] their
       *[one] its
    } guide.
other-intro = These bodies are found together from the conditions of their joints:
cond-revolute = pin at { $point }: { $point } is one point of { $a } and of { $b }.
cond-prismatic = prismatic pair: { $b } { COUNT($b) ->
        [many] slide
       *[one] slides
    } along { $a } without turning relative to { COUNT($a) ->
        [many] them
       *[one] it
    }.
cond-slot = pin { $point } in a slot: its velocity relative to the slotted body is along the slot.
cond-slot_fixed = the point { $point } of { $b } { COUNT($b) ->
        [many] slide
       *[one] slides
    } along a line fixed to { $a }: its velocity is along that line.
cond-wheel = wheel at { $point }: no sideways velocity relative to { $a }.
cond-weld = { $a } and { $b } move as one body.
cond-spherical = ball joint at { $point }: { $point } is one point of { $a } and of { $b }.
cond-cylindrical = cylindrical pair: { $b } { COUNT($b) ->
        [many] turn
       *[one] turns
    } about and slides along the axis of { $a }.
rolling-noslip = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] mesh
               *[one] meshes
            } with { $a }
       *[other] { $b } { COUNT($b) ->
            [many] roll
           *[one] rolls
        } on { $a } without slipping
    }: at the contact { $point } both material points have the same velocity.
rolling-noslip_edge = { $b } { COUNT($b) ->
        [many] do
       *[one] does
    } not slip on { $a }: at the contact { $point } both material points have the same velocity.
rolling-same_edge = { $b } { COUNT($b) ->
        [many] do
       *[one] does
    } not slip on { $a }: at the contact { $point } both material points have the same velocity, { $sym } = { $other }.
rolling-glide = { $b } { COUNT($b) ->
        [many] roll
       *[one] rolls
    } without slipping on the edge of { $a }. Seen from { $a }, { COUNT($b) ->
        [many] their
       *[one] its
    } centre { $centre } keeps its distance from the edge: it moves along a line parallel to the tangent at { $point }. With axes at { $centre } turning with { $a }, the motion of { $centre } is the drag motion (that of the point of { $a } there) plus the relative motion along that line (and, for accelerations, the Coriolis term).
rolling-kept = the contact is kept: at { $point } the accelerations of the material points of { $b } and { $a } differ only by a term along the common normal; there is no Coriolis term, since at a rolling contact the two points have no relative velocity: { $vrel } = 0.
path-circle = { $b } { COUNT($b) ->
        [many] roll
       *[one] rolls
    } without slipping on { $a }, which does not move. { COUNT($b) ->
        [many] Their
       *[one] Its
    } centre { $centre } keeps its distance from { $a }: it moves on the circle of radius { $radius } about { $o }, so { $ac } has a normal part { $vs }² / { $radius } towards { $o }; and since { $vc } = { $w } × { $arm } at every instant (the contact { $point } is the instant centre), its tangential part is { $al } × { $arm }.
path-found = { $b } { COUNT($b) ->
        [many] roll
       *[one] rolls
    } without slipping on { $a }, which does not move. { $ac }, found in Step { $step }, splits into a normal part { $vs }² / { $radius } towards { $o } and a tangential part, which is { $al } × { $arm } since { $vc } = { $w } × { $arm } at every instant (the contact { $point } is the instant centre).
path-line = { $b } { COUNT($b) ->
        [many] roll
       *[one] rolls
    } without slipping on { $a }, which does not move. { COUNT($b) ->
        [many] Their
       *[one] Its
    } centre { $centre } keeps its distance from { $a }: it moves on a straight line, with no normal acceleration; and since { $vc } = { $w } × { $arm } at every instant (the contact { $point } is the instant centre), its acceleration is its tangential part alone: { $ac } = { $at } = { $al } × { $arm }.
rolling-equal = No slip at the contact { $point }: { $sym } = { $other }.
rolling-same = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] mesh
               *[one] meshes
            } with { $a }
       *[other] { $b } { COUNT($b) ->
            [many] roll
           *[one] rolls
        } on { $a } without slipping
    }: at the contact { $point } both material points have the same velocity, { $sym } = { $other }.
rolling-centre = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] mesh
               *[one] meshes
            } with { $a }
       *[other] { $b } { COUNT($b) ->
            [many] roll
           *[one] rolls
        } without slipping on { $a }
    }, which does not move: the point { $point } of { $b } at the contact has no velocity, { $sym } = 0, so it is the instant centre of { $b }.
dir-guide = guide of { $holder }
dir-normal_at = normal at { $point }
how-prismatic = (prismatic pair: no relative rotation)
carry-anchor = From the solution of the group: { $sym } = { $value }.
sense-ccw = counter-clockwise
sense-cw = clockwise
sec-rates_summary = Angular velocities and accelerations
sec-rates_summary_v = Angular velocities
sec-centres = Instant centres
centres-intro = The symbol I with the numbers of two bodies ({ $example }: bodies 1 and 3) names the instant centre of their relative motion: the point where the relative velocity is zero.
centres-intro_named = The symbol I with a body's name ({ $pair }) names the instant centre of { $body } relative to { $frame }: the point where the relative velocity is zero.
centres-intro_named_rel = The symbol I with a body's name ({ $pair }) names the instant centre of { $body } relative to { $frame }, and with two names joined by “rel” that of the first body relative to the second: the point where the relative velocity is zero.
centre-line = { $centre }: { $why } { $where }
centre-joint-revolute = the pin { $joint },
# a pin to the fixed body: a permanent centre; a strand's, where it is tied (twenty-ninth round b)
centre-joint-revolute_fixed = the fixed pin { $joint }, a permanent centre,
centre-joint-revolute_tied = the point { $joint } where { $body } is tied to { $frame }, a permanent centre,
centre-joint-rolling = the contact point { $joint } (rolling without slipping),
centre-joint-gear = the contact { $joint } of the pitch circles,
centre-joint-prismatic = the pair is prismatic: the relative motion is a translation and the instant centre is perpendicular to the guide,
centre-joint-weld = the two bodies are one rigid body:
centre-kennedy = by Aronhold–Kennedy it lies on the line through { $l1 } (third body { $k1 }) and on the line through { $l2 } (third body { $k2 }); these lines { $far ->
        [1] are parallel, so
       *[other] meet
    }
centre-velocities = the velocities relative to { $frame } of { $p }, { $vp }, and of { $q }, { $vq }, are perpendicular to the lines joining them to the instant centre; the perpendiculars meet
centre-lines = it lies on { $first } and on { $second }; these lines { $far ->
        [1] are parallel, so
       *[other] meet
    }
centre-omega = with the velocities found in “{ sec-velocities }”, the angular velocity relative to { $frame } { COUNT($frame) ->
        [many] are
       *[one] is
    } zero: the relative motion is a translation and the instant centre is
centre-at = at { $point }.
centre-infinity = { $body } translates relative to { $frame } ({ $w } = 0): every point has the velocity { $v }; its instant centre is at infinity, in the direction perpendicular to { $v }.
centre-infinity_one = { $body } translates relative to { $frame } ({ $w } = 0): every point has one velocity; its instant centre is at infinity, in the direction { $direction }, perpendicular to that velocity.
centre-rest = there is no relative motion.
sec-rates = Angular velocities and accelerations
rates-intro = Each body turns relative to the body that carries it: { $w }, and, differentiating in the fixed axes, { $a }.
rates-intro_v = Each body turns relative to the body that carries it: { $w }.
fields-intro_v = The velocity of every point, from a point of the same body already known (its joint):
fields-intro_a = The acceleration of every point, from a point of the same body already known (its joint):
sec-composition = Composition of motions
composition-intro = The motion of a point is its drag motion (that of the point of the moving frame that coincides with it) plus its motion relative to the frame, plus, for accelerations, the Coriolis term { $cor }.
composition-point = Point { $point } of { $body }, moving frame { $frame }:
composition-drag = { WORD($kind) ->
        [accel] { sec-accelerations }
       *[speed] { sec-velocities }
    }. Drag:
composition-relative = Relative: { $sym }, the motion seen from the moving frame, { $frame }:
composition-rolls = { $body } { COUNT($body) ->
        [many] roll
       *[one] rolls
    } on { $frame } without slipping at { $point }: seen from { $frame }, { $point } is the instant centre of { $body }, { $sym } = 0, and every point of { $body } turns about it.
sec-curvature = Curvature of paths
curvature-intro = The acceleration splits into a tangential part along the velocity and a normal part across it; the radius of curvature is { $rho }.
curvature-point = Point { $point }: velocity { $v }.
curvature-rest = Point { $point } has zero velocity at this instant: its path has no radius of curvature there (ℜ = |v|²/|aⁿ| needs a velocity).
curvature-straight = The normal acceleration of { $point } is zero: its path is straight here (or at an inflection point).
curvature-circle = Point { $point }: it keeps its distance from the fixed point { $o }, so its path is the circle of radius { $radius } about { $o }; the radius of curvature is that radius:
curvature-circle_centre = The centre of curvature of the path of { $point } is { $o }, at { $centre }.
curvature-centre = The centre of curvature of the path of { $point } is at { $centre }, on the side of the normal acceleration.
curvature-centre_from = The centre of curvature of the path of { $point } is { $where }.
curvature-named = With { $d } = { $arm } = { $length }, { $rho } = { $value }.
curvature-from = { WORD($side) ->
        [up] { $rho } above { $point }
        [down] { $rho } below { $point }
        [left] { $rho } to the left of { $point }
        [right] { $rho } to the right of { $point }
       *[other] { $rho } from { $point }, along { $an }
    }
curvature-intrinsic = With { $speed }, the unit tangent is { $tangent }; { $split }, with { $tangential }, and { $rest }, { $normal }:
sec-answers = Answers
answers-none = The model asks no questions.
ask-icr = instant centre of { $body } relative to { $frame }
ask-axis = screw axis of { $body } relative to { $frame }
ask-pole = acceleration pole of { $body } relative to { $frame }
ask-inflection = inflection circle and pole tangent of { $body } relative to { $frame }
ask-contact = the three coincident points at the contact { $joint }
ask-decompose = composition of the motion of { $point }, moving frame { $frame }
ask-curvature = radius of curvature of the path of { $point } relative to { $frame }
ask-intrinsic = tangential and normal acceleration of { $point } relative to { $frame }
ans-rest = no relative motion
# an asked planar rate with its sense, as the notes ask it (“valor i sentit”: twenty-eighth round d)
ans-sensed = { $value } ({ $sense })
ans-point = position
ans-from = distance from { $point }
ans-direction = direction
ans-center = centre of curvature
ans-center_from = centre of curvature { $where }
ans-tangent = unit tangent
ans-slide = velocity along the axis
ans-translation = a translation: no inflection circle
ans-inflection_pole = instant centre I
ans-inflection_center = centre of the inflection circle
ans-inflection_diameter = diameter of the inflection circle
ans-inflection_point = inflection pole (across the circle from I)
ans-pole_tangent = pole tangent (unit, the way I moves)
ans-pole_normal = pole normal (unit, from I to the inflection pole)
ans-pole_velocity = velocity of I along the centrodes
centre-proportional-between = by Aronhold–Kennedy it lies on the line through { $l1 } and on the line through { $l2 }, but these are one and the same line, so they do not fix it. On that line the velocities relative to { $frame } are perpendicular to the line and proportional to the distance from the instant centre: { $p } moves at { $vp } and { $q } at { $vq }, in opposite senses, so the instant centre lies between them, where the speed falls to zero:
centre-proportional-outside = by Aronhold–Kennedy it lies on the line through { $l1 } and on the line through { $l2 }, but these are one and the same line, so they do not fix it. On that line the velocities relative to { $frame } are perpendicular to the line and proportional to the distance from the instant centre: { $p } moves at { $vp } and { $q } at { $vq }, in the same sense, so the instant centre lies beyond the slower one, where the speed falls to zero:
composition-slide = { $point } slides along its guide: its relative motion is along the guide, { $sym } = { $value }.
composition-slide_seen = { $body } { COUNT($body) ->
        [many] slide
       *[one] slides
    } along { $frame } without turning relative to it, so every point of { COUNT($body) ->
        [many] them
       *[one] it
    }, { $point } too, has the relative { WORD($kind) ->
        [accel] acceleration
       *[speed] velocity
    } found in “{ sec-velocities }”: { $sym } = { $value }.
composition-slide_seen_step = { $body } { COUNT($body) ->
        [many] slide
       *[one] slides
    } along { $frame } without turning relative to it, so every point of { COUNT($body) ->
        [many] them
       *[one] it
    }, { $point } too, has the relative { WORD($kind) ->
        [accel] acceleration
       *[speed] velocity
    } found in Step { $step }: { $sym } = { $value }.
composition-drag_seen = { $sym } = { $value }, the { WORD($kind) ->
        [accel] acceleration
       *[speed] velocity
    } of the point of { $frame } that coincides with { $point }, found in Step { $step }.
composition-drag_terms = { $sym } = { $terms } = { $value }: the first terms of the equation of Step { $step }.
composition-sum_seen = So { $sym } = { $terms } is the equation with which Step { $step } found { $seen }.
composition-reverse = { $sym } = −{ $back } = { $value }: the reverse of the relative { WORD($kind) ->
        [accel] acceleration
       *[speed] velocity
    } found in Step { $step }.
composition-reverse_rolling = No slip: { $vel } = 0, so there is no Coriolis term and { $sym } = −{ $back } = { $value }, the reverse of the relative acceleration found in Step { $step }.
composition-pin = { $point } is a pin, a point of both bodies: it has no relative motion, { $sym } = 0.
vehicle-driven = The wheel { $joint } does not slip: { $point } has no velocity across the wheel's plane, so its given speed along the plane is its whole velocity: { $sym } = { $value }.
vehicle-line-wheel = the perpendicular at { $point } to the plane of wheel { $joint } (its axle: the wheel does not slip sideways)
vehicle-line-velocity = the perpendicular to { $sym } at { $point }
vehicle-equiprojective = By equiprojectivity ({ $q } and { $p } are points of { $body }), their velocities have the same component along { $seg }: { $vp } · { $seg }/|{ $seg }| = { $vq } · { $seg }/|{ $seg }|, with { $seg }/|{ $seg }| = { $unit }, so that { $vq } · { $seg }/|{ $seg }| = { $proj }. { $p } is on the axle of wheel { $joint }, so { $vp } lies along the wheel's plane: { $vp } = |{ $vp }| e, with e = { $along } and e · { $seg }/|{ $seg }| = { $cos }. Hence |{ $vp }| = ({ $proj }) / ({ $cos }) = { $speed }, and { $vp } = { $value }.
vehicle-equiprojective_along = By equiprojectivity ({ $q } and { $p } are points of { $body }), their velocities have the same component along { $seg }: { $vp } · { $seg }/|{ $seg }| = { $vq } · { $seg }/|{ $seg }|, with { $seg }/|{ $seg }| = { $unit }, so that { $vq } · { $seg }/|{ $seg }| = { $proj }. { $p } is on the axle of wheel { $joint }, so { $vp } lies along the wheel's plane, the line { $seg }: { $vp } = |{ $vp }| { $seg }/|{ $seg }|. Hence |{ $vp }| = { $speed }, and { $vp } = { $value }.
vehicle-line-wheel_own = the perpendicular at { $point } to the plane of wheel { $joint } (its axle, which is also the perpendicular to { $sym } through { $witness }: the wheel does not slip sideways)
vehicle-pin_shared = { $point } is the pin common to { $a } and { $b }: { $sym } = { $other }.
vehicle-pin_shared_one = { $point } is the pin common to { $a } and { $b }: { $sym } is the velocity of both.
vehicle-centre = The instant centre of { $body } lies on { $first } and on { $second }; they meet at { $centre } = { $where }, which has no velocity: { $rest } = 0. Every point of { $body } moves perpendicular to the line joining it to { $centre }, at a speed proportional to its distance:
vehicle-translation = The lines of { $body } are parallel, so { COUNT($body) ->
        [many] they translate: every point moves as { $point }
       *[one] it translates: every point moves as { $point }
    }.
vehicle-translation_equal = { $p } and { $q } have the same velocity, { $vp } = { $vq } = { $value }, so { $body } { COUNT($body) ->
        [many] translate: every point has the velocity { $value }
       *[one] translates: every point has the velocity { $value }
    }.
vehicle-spin = The wheel { $joint } rolls without slipping (radius { $radius }): its centre { $point } moves along the wheel's plane with the speed { $product }, where { $spin } is its spin about its axle, so:
triad-intro = { $body } { COUNT($body) ->
        [many] are
       *[one] is
    } held by three binary links, { $links }: no vector equation of a single point has only two unknowns. As textbooks do for a triad, take the Assur point { $point }, where the lines { $l1 } and { $l3 } meet, as a point of { $body }:
triad-collinear = On each side the two unknown terms are perpendicular to one line ({ $point } lies on { $l1 } and on { $l3 }), so each side has one unknown magnitude: two unknowns, and the polygon closes.
triad-closure = With { $point } known as a point of the ternary link, its pin { $pin } closes as in a dyad:
loop-intro = The bodies { $bodies } close a loop: going round it, the relative angular velocities add up to zero, each along its joint's axis (three scalar equations for the unknown rates { $rate } along the axes { $axis }):
loop-solve = The three components give the unknown rates:
loop-solve_alpha = Differentiating in the fixed axes, the relative angular accelerations and the terms { $cross } add up to zero round the loop; the three components give the unknown { $rate }:
dir-axis = axis { $joint }
dir-wheel = wheel { $joint }
how-weld = (fixed to each other: one rigid body)
group-wheel_v = The wheel { $joint } does not slip sideways: the velocity of { $point } lies in the wheel's plane.
group-wheel_a = The wheel { $joint } does not slip sideways at any instant, and its plane turns with { $body }: the acceleration of { $point } is a tangential part in the plane and a normal part across it, { $w } × { $v }.
how-translation = (it translates)
translation-same = { $body } { COUNT($body) ->
        [many] do
       *[one] does
    } not turn ({ $w } = 0{ $accel ->
        [1] , { $a } = 0
       *[other] {""}
    }): { COUNT($body) ->
        [many] they translate, and all their
       *[one] it translates, and all its
    } points have one { $accel ->
        [1] acceleration
       *[other] velocity
    }:
translation-points = All the points of { $body } have one { $accel ->
        [1] acceleration
       *[other] velocity
    }:
fig-centres = The instant centres (rings, I with the numbers of two bodies) on the mechanism{ $kennedy ->
        [0] { $normals_n ->
            [0] .
           *[other] , with the lines they are found on (dash-dot: { $normals }).
        }
       *[other] , with the lines they are found on (dash-dot: lines through two centres{ $normals_n ->
            [0] {""}
           *[other] {" "}and { $normals }
        }).
    }
fig-centres_named = The instant centres (rings, I with the bodies' names) on the mechanism{ $kennedy ->
        [0] { $normals_n ->
            [0] .
           *[other] , with the lines they are found on (dash-dot: { $normals }).
        }
       *[other] , with the lines they are found on (dash-dot: lines through two centres{ $normals_n ->
            [0] {""}
           *[other] {" "}and { $normals }
        }).
    }
fig-normal-wheel = the perpendiculars to the wheels
fig-normal-slot = the normals to the slots
fig-normal-slot_fixed = the normals to the lines the points slide on
fig-normal-normal = the common normals at the contacts
fig-normal-radius = the perpendiculars to the points' velocities
fig-assur = The Assur point { $point }: the lines { $l1 } and { $l3 } (dashed) drawn on until they meet; { $point } is taken as a point of the ternary link.
fig-drawn_at = Drawn at { $values }.
fig-level_v = Velocity polygon, to scale: from the pole o, the velocity of each point{ $format ->
        [md] {""}
       *[other] {" "}(blue)
    } ends at its image, lettered as the point{ $image ->
        [0] {""}
       *[other] {" "}({ $image } for { $point })
    }{ $between ->
        [0] .
       *[other] ; between the images, the relative velocities of the equations of { $span ->
            [1] Step { $first }
            [2] Steps { $first } and { $last }
           *[other] Steps { $first } to { $last }
        }{ $format ->
            [md] {""}
           *[other] {" "}(black)
        }, head to tail.
    }
fig-level_a = Acceleration polygon, to scale: from the pole o, the acceleration of each point{ $format ->
        [md] {""}
       *[other] {" "}(blue)
    } ends at its image, lettered as the point{ $image ->
        [0] {""}
       *[other] {" "}({ $image } for { $point })
    }{ $between ->
        [0] .
       *[other] ; between the images, the terms of the equations of { $span ->
            [1] Step { $first }
            [2] Steps { $first } and { $last }
           *[other] Steps { $first } to { $last }
        } ({ $format ->
            [md] {""}
           *[other] black:{" "}
        }normal and tangential, relative and Coriolis), head to tail.
    }
fig-level_a_relative = Acceleration polygon, to scale: from the pole o, the acceleration of each point{ $format ->
        [md] {""}
       *[other] {" "}(blue)
    } ends at its image, lettered as the point{ $image ->
        [0] {""}
       *[other] {" "}({ $image } for { $point })
    }{ $between ->
        [0] .
       *[other] ; between the images, the terms of the equations of { $span ->
            [1] Step { $first }
            [2] Steps { $first } and { $last }
           *[other] Steps { $first } to { $last }
        } ({ $format ->
            [md] {""}
           *[other] black:{" "}
        }normal and tangential, and relative), head to tail.
    }
fig-level_a_normal = Acceleration polygon, to scale: from the pole o, the acceleration of each point{ $format ->
        [md] {""}
       *[other] {" "}(blue)
    } ends at its image, lettered as the point{ $image ->
        [0] {""}
       *[other] {" "}({ $image } for { $point })
    }{ $between ->
        [0] .
       *[other] ; between the images, the terms of the equations of { $span ->
            [1] Step { $first }
            [2] Steps { $first } and { $last }
           *[other] Steps { $first } to { $last }
        } ({ $format ->
            [md] {""}
           *[other] black:{" "}
        }normal and tangential), head to tail.
    }
col-number = no.

# higher pairs (joints.contact, curved_slot, cam)
shape-curveshape = curve
shape-camshape = cam
joint-contact = contact (higher pair)
joint-curved_slot = pin in a curved slot
joint-cam = cam and follower
cond-contact = contact: { $a } and { $b } keep touching; they may slide along the common tangent.
cond-curved_slot = pin { $point } in a curved slot: its velocity relative to the slotted body is along the slot's tangent.
cond-cam = cam: the follower { $b } { COUNT($b) ->
        [many] keep
       *[one] keeps
    } touching the cam { $a }.
dir-tangent = tangent at { $point }
dir-centre = towards the centre of curvature { $point }
higher-intro = The higher pair is written as the motion of { $point } along its path relative to { $holder } (a slot along the tangent, curved with radius { $radius }): the relative acceleration has a normal part v²/ρ towards the path's centre of curvature.
higher-straight = The higher pair is written as the motion of { $point } along a straight path relative to { $holder } (a slot along the tangent).
centre-weld = { $body } { COUNT($body) ->
        [many] are
       *[one] is
    } fixed to { $other }: they are one rigid body, so the instant centre is that of { $other }, { $same },
centre-line-kennedy = the line through { $l } (Aronhold–Kennedy, third body { $k })
centre-line-moves = the perpendicular to { $v } through { $point } ({ $point } moves with { $body }, which turns about { $pivot })
centre-line-rolls = the perpendicular to { $v } through { $point } ({ $roller } { COUNT($roller) ->
        [many] do
       *[one] does
    } not slip on { $on }, so the point { $point } of { $b } has the velocity of { $body } there, and { $body } { COUNT($body) ->
        [many] turn
       *[one] turns
    } about { $pivot })
centre-line-rolls_still = the perpendicular to { $v } through { $point } ({ $roller } { COUNT($roller) ->
        [many] do
       *[one] does
    } not slip on { $on }, so the point { $point } of { $b } has the velocity of { $body }, which { COUNT($body) ->
        [many] translate
       *[one] translates
    })
centre-line-moves_still = the perpendicular to { $v } through { $point } ({ $point } moves with { $body }, which translates)
centre-line-guide = the perpendicular to the guide through { $pivot } (at { $pivot }′, the foot of the perpendicular from { $pivot } to the guide, the velocity relative to { $body } is along the guide and the drag velocity is perpendicular to { $pivot }{ $pivot }′, that is, along the guide too: the velocity of the point of { $b } at { $pivot }′ follows the guide)
centre-carried-slip = {" "}({ $b } { COUNT($b) ->
        [many] do
       *[one] does
    } not slip on { $body }, so its point { $point } has the velocity of { $body } there)
centre-carried-between = { $p } moves with { $k1 } about { $c1 }{ $why1 }, and { $q } with { $k2 } about { $c2 }{ $why2 }: both velocities relative to { $frame } are perpendicular to the line through { $p } and { $q }, so the instant centre lies on that line; on it the velocities are proportional to the distance from the instant centre: { $p } moves at { $vp } and { $q } at { $vq }, in opposite senses, so the instant centre lies between them, where the speed falls to zero:
# the construction repeated for a body symmetric to one done: referred to (twenty-ninth round b)
centre-carried_as = as for { $first }, it lies on the line through { $p } and { $q }, at { $dist } from { $near }:
centre-carried-between_from = { $p } moves with { $k1 } about { $c1 }{ $why1 }, and { $q } with { $k2 } about { $c2 }{ $why2 }: both velocities relative to { $frame } are perpendicular to the line through { $p } and { $q }, so the instant centre lies on that line; on it the velocities are proportional to the distance from the instant centre: { $p } moves at { $vp } and { $q } at { $vq }, in opposite senses, so the instant centre lies between them, where the speed falls to zero, at { $dist } from { $near }:
centre-carried-outside = { $p } moves with { $k1 } about { $c1 }{ $why1 }, and { $q } with { $k2 } about { $c2 }{ $why2 }: both velocities relative to { $frame } are perpendicular to the line through { $p } and { $q }, so the instant centre lies on that line; on it the velocities are proportional to the distance from the instant centre: { $p } moves at { $vp } and { $q } at { $vq }, in the same sense, so the instant centre lies beyond the slower one, where the speed falls to zero:
centre-carried-outside_from = { $p } moves with { $k1 } about { $c1 }{ $why1 }, and { $q } with { $k2 } about { $c2 }{ $why2 }: both velocities relative to { $frame } are perpendicular to the line through { $p } and { $q }, so the instant centre lies on that line; on it the velocities are proportional to the distance from the instant centre: { $p } moves at { $vp } and { $q } at { $vq }, in the same sense, so the instant centre lies beyond the slower one, where the speed falls to zero, at { $dist } from { $near }:
centre-line-slot = the normal at { $point } to the slot (relative to the slotted body, { $point } can only move along the slot)
centre-line-slot_fixed = the normal at { $point } to the line of { $a } along which it slides
centre-line-wheel = the axle of wheel { $joint }, the normal at { $point } to its plane (it does not slip sideways)
centre-field = it lies on the perpendicular to { $v } through { $q }, at the distance { $arm } = |{ $v }| / |{ $w }| = { $dist } from { $q }, { $side }, so the instant centre is
centre-rate = from { $w } (found in “{ sec-velocities }” through { $line }): it lies on the perpendicular to { $v } through { $q }, at the distance { $arm } = |{ $v }| / |{ $w }| = { $dist } from { $q }, { $side }, so the instant centre is
centre-rate_step = from { $w } (found in Step { $step } through { $line }): it lies on the perpendicular to { $v } through { $q }, at the distance { $arm } = |{ $v }| / |{ $w }| = { $dist } from { $q }, { $side }, so the instant centre is
# the side of a point a centre lies on, named (centre-field: below A, to the left of A)
side-above = above { $q }
side-below = below { $q }
side-left = to the left of { $q }
side-right = to the right of { $q }
side-above_left = above and to the left of { $q }
side-above_right = above and to the right of { $q }
side-below_left = below and to the left of { $q }
side-below_right = below and to the right of { $q }
centre-check = Check with the velocities found in “{ sec-velocities }”: on the perpendicular to { $v } through { $q }, at the distance { $arm } = |{ $v }| / |{ $w }| = { $dist } from { $q }, { $side }, the same point: { $centre } is { $where }
sec-centres_v = Instant centres found from the velocities
how-centre_infinity = (it translates: its instant centre { $centre } is at infinity)
how-constant_rate = ({ $sym } = { $value } is constant: { $line } keeps its length, and its rate is set by the radii and by { $rates }, which is constant)
how-constant_speed = ({ $point } runs on the circle of radius { $line } = { $length } about { $centre } at the constant speed { $v } = { $speed }, so { $sym } = { $value } is constant)
idle-rolling = { $body } rolls without slipping on { $fixed }: its contact point { $point } is its instant centre, so:
idle-symmetry = { $body } is placed like { $like } (the same radius, the same joints with the same bodies): by symmetry it turns alike:
idle-unused = { $bodies } { $count ->
        [one] does
       *[other] do
    } not enter the question: no step needs { $count ->
        [one] its angular velocity
       *[other] their angular velocities
    }.
how-tangent = (it stays { WORD($way) ->
        [vertical] vertical
        [horizontal] horizontal
       *[other] parallel to itself
    }, tangent to { $a } and { $b }: it translates, and all its points have the same velocity)
how-glides = ({ $p } and { $q } both move on the line { $line } at every instant: the body translates along it without turning)
how-parallel_paths = ({ $p } and { $q } each stay at their wheel's radius from the flat ground, so they move on parallel straight lines at every instant: the body translates without turning)
how-translates_always = (it translates at every instant, as the velocities showed)
centres-found_above = { $centre } = { $value }: placed in “{ sec-velocities }”, in the velocity step of { $body }.
centres-witness = { $name }
centres-placed_in_step = { $centre }: placed in Step { $step }, from the velocities of { $points }.
centres-found_above_step = { $centre }: placed in Step { $step }, with the velocities of { $body }.
centre-site = { $point } is the instant centre { $centre } of { $body } relative to { $frame }, placed in “{ sec-centres }”: { $sym } = 0.
centre-site_s = { $centre }, placed in “{ sec-centres }”, has no velocity: { $sym } = 0.
centre-site_here = { $point } is the instant centre { $centre } of { $body } relative to { $frame }, found just above: { $sym } = 0.
centre-site_s_here = { $centre }, found just above, has no velocity: { $sym } = 0.
sec-contact = Contact points
geom-rule = The rule for every rolling contact: no slip holds at every instant at the geometric contact point (here { $geom }), which moves; differentiating the no-slip condition along it gives { $rule }: the tangential components of the two accelerations are equal and the normal ones differ by this term, along the common normal. It needs the velocity of the geometric point:
geom-bar = { $geom }, the geometric contact point, belongs to neither body: it stays on the line of the centres { $c1 } and { $c2 }, always with { $part }/{ $whole } = { $ratio }, so it moves as a point of a bar hinged at { $c1 } and { $c2 }:
geom-bar_told = { $geom }, the geometric contact point, stays on the line of the centres { $c1 } and { $c2 }, always with { $part }/{ $whole } = { $ratio }, so it moves as a point of a bar hinged at { $c1 } and { $c2 }:
geom-foot = { $geom }, the geometric contact point, is the foot of the perpendicular from the centre { $centre } to the line of { $line }: { $radius } is a radius, perpendicular to the line, and turns with it:
contact-intro = At the contact { $point } three points coincide, with different motions: the point of { $a }, the point of { $b }, and the geometric contact point { $geom }, which is a point of neither.
contact-above = { $sym } = { $value }, worked out in “{ sec-accelerations }” for the acceleration of the contact.
contact-written_centre = { $sym } = { $value }, found in Step { $step }: { $point } is the instant centre of { $body }.
contact-written = { $sym } = { $value }, found in Step { $step }.
contact-fixed = { $sym }: { $point } as a point of { $body }{ FIXED($body) ->
        [yes] {""}
       *[no] { COUNT($body) ->
            [many] , which are fixed,
           *[one] , which is fixed,
        }
    } { COUNT($body) ->
        [many] do
       *[one] does
    } not move: { $sym } = 0.
fig-step_v = Velocity polygon of this step, to scale: from the pole o, the velocity of each point{ $format ->
        [md] {""}
       *[other] {" "}(blue)
    } ends at its image, lettered as the point{ $between ->
        [0] .
       *[other] ; between the images, the terms of this step's equations{ $format ->
            [md] {""}
           *[other] {" "}(black)
        }, head to tail.
    }
fig-step_a = Acceleration polygon of this step, to scale: from the pole o, the acceleration of each point{ $format ->
        [md] {""}
       *[other] {" "}(blue)
    } ends at its image, lettered as the point{ $between ->
        [0] .
       *[other] ; between the images, the terms of this step's equations{ $format ->
            [md] {""}
           *[other] {" "}(black)
        }, head to tail.
    }
col-point = point
col-what = what it is
what-centre = centre of { $body }
what-joint = { $kind } between { $a } and { $b }
what-touching = the point of { $body } where { COUNT($body) ->
        [many] they touch
       *[one] it touches
    } { $other }
what-contact = contact point ({ $kind }) between { $a } and { $b }
what-body = a point of { $bodies }
what-of = { $name }
note-text = Note: { $text }
sec-checks = Checks
check-willis = Willis' formula: seen from { $carrier }, the train is an ordinary one ({ $planet }, whose axle { $carrier } { COUNT($carrier) ->
        [many] carry
       *[one] carries
    }, meshes with { $s1 } and { $s2 }, { $fixed ->
        [0] which turn about the fixed axis through { $axis }
       *[other] whose axis is the fixed axis through { $axis }
    }), so { $formula } = { $radii } = { $train }{ $r1 ->
        [0] {""}
       *[other] , with { $r1 } and { $r2 }
    }. With the angular velocities found in “{ sec-velocities }”, { $values } = { $ratio }: they agree.
check-belt = Seen from { $holder }, which carries both axles, { $line } slips on neither { $a } nor { $b }: { $equation }, so { $ratio }; with the angular velocities found in “{ sec-velocities }”, { $values }: they agree.
pair-relation_v = Seen from { $holder }, which carries both axles, the axles are fixed: { $a } and { $b } turn about them and do not slip on each other, so { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(with { $radii })
    }:
pair-relation = Seen from { $holder }, which carries both axles, the axles are fixed: { $a } and { $b } turn about them and do not slip on each other, so { $equation } at every instant; differentiating, with the radii constant, { $derived }{ $radii ->
        [0] {""}
       *[other] {" "}(with { $radii })
    }:
drive-relation_a = Differentiating, with the radii constant: { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(with { $radii })
    }:
drive-relation = Seen from { $holder }, which carries both axles, the axles are fixed and the straight run of { $line } translates: it slips on neither { $a } nor { $b }, so both move it at one speed, { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(with { $radii })
    }:
check-train = The train's ratio is the product of its stages': { $ratio }; with the angular velocities found in “{ sec-velocities }”, the ratio is { $value }.
check-quick = Time ratio of the quick return: { $lever } is at an end of its swing when the slot is tangent to the circle of { $pin } (the crank { $o2 }{ $pin } perpendicular to { $o4 }{ $pin }), where cos θ = { $o2 }{ $pin } / { $o2 }{ $o4 } = { $r } / { $d }, θ = { $theta }. Turning steadily, { $crank } sweeps 360° − 2θ = { $slow } in one stroke and 2θ = { $fast } in the other: time ratio { $ratio }.
driver-slide = Given: the sliding velocity in the prismatic pair { $joint } is { $value }.
driver-slide_accel = Given: the sliding acceleration in the prismatic pair { $joint } is { $value }.
centre-line-normal = the common normal at the contact { $point } (the bodies slide on each other there: no relative velocity along it)
# a centre from two parallel velocities perpendicular to the line through their points (the notes' proportional construction)
centre-parallel-between = the points { $p } and { $q } of { $body } move, relative to { $frame }, at { $sp } = { $vp } and { $sq } = { $vq }, both perpendicular to the line through { $p } and { $q }. Along that line the velocity varies linearly, in proportion to the distance from the instant centre, and these two have opposite senses, so the instant centre lies between them, where the speed falls to zero, at { $dist } from { $q }:
centre-parallel-outside = the points { $p } and { $q } of { $body } move, relative to { $frame }, at { $sp } = { $vp } and { $sq } = { $vq }, both perpendicular to the line through { $p } and { $q }. Along that line the velocity varies linearly, in proportion to the distance from the instant centre, and these two have the same sense, so the instant centre lies beyond the slower one, where the speed falls to zero, at { $dist } from { $q }:
# a normal acceleration: its magnitude, then the vector with its direction (never a magnitude = a vector)
term-magnitude = { $mag } = { $how }, towards { $point }: { $sym } = { $value }

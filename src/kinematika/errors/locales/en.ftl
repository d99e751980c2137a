## The errors' and warnings' messages, in English (the default; the contract's tests read
## these). Each key is one message; its variables are named as the code names them. The
## other languages' files have the same keys and variables (tests/core/test_messages.py).

## the words of other programs: an operating system's reason, a file reader's complaint
reason = { $text }
problem = { $text }

## reading files (model/files.py)
model-not-a-path = a model is a file path, a dict or a Mechanism, not { $type }
file-empty = the file is empty
model-not-a-mapping = a model is a mapping with keys points, bodies, joints, drivers; this file holds { $holds }
holds = { $what ->
        [list] a list
        [text] a text
        [nothing] nothing
       *[value] a single value
    }
file-type-unknown = unknown file type { $suffix }: { $noun ->
        [cam-file] a cam file
       *[model-file] a model file
    } ends in { $suffixes }
file-not-utf8 = the file is not UTF-8 text (byte { $byte })
file-missing = no such file
file-unreadable = cannot read the file: { $reason }
file-is-a-folder = this is a folder, not a model file
file-too-large = the file is too large for a model (more than { $limit } bytes)
file-no-end = the file gave no end within { $seconds } s (a pipe or a device, not a model file)
text-too-large = the text is too large for a model (more than { $limit } characters)
text-unreadable = unreadable { $format }: { $detail }
file-too-deep = the file is nested too deeply to be a model (more than { $levels } levels{ $line ->
        [0] {""}
       *[other] , line { $line }
    })
name-too-long = the name { $name } has { $length } characters: names have at most { $limit }
text-lone-surrogate = the text { $text } holds a lone surrogate, which is not Unicode text
key-duplicate = duplicate key { $key }{ $line ->
        [0] {""}
       *[other] {" "}at line { $line }
    }: each key may appear only once
json-invalid = invalid JSON at line { $line }, column { $column }: { $problem }
toml-invalid = invalid TOML: { $problem }
yaml-invalid = invalid YAML{ $line ->
        [0] {""}
       *[other] {" "}at line { $line }, column { $column }
    }: { $problem }
yaml-alias-inside = the alias *{ $alias } at line { $line } is inside what it names
yaml-alias-unknown = the alias *{ $alias } at line { $line } names no anchor
yaml-aliases-too-many = the aliases expand to more than { $limit } values (at line { $line }): too many for a model
model-no-cam = this model has no cam: give a body a `cam:` shape

## words that messages share
none = none
or-word = or
more = , … ({ $n } more)
integer-bits = an integer of { $bits } bits

## expressions (expressions.py)
expr-expected = expected a number or an expression, got { $got }
expr-not-finite = expected a finite number in the range of floats, got { $got }
expr-empty = empty expression
expr-too-long = expression longer than { $limit } characters
expr-unreadable = cannot read expression { $source }: { $detail }
expr-unreadable-bare = cannot read expression { $source }
expr-too-deep = expression { $source } is nested too deeply
expr-constant = in { $source }: only numbers may be written as constants
expr-number-too-large = in { $source }: a number is too large
expr-unknown-function = in { $source }: unknown function { $function } (known: { $known })
expr-arguments = in { $source }: { $function } takes { $count } argument(s)
expr-not-allowed = in { $source }: { $part } is not allowed in an expression
expr-unknown-name = in { $source }: unknown name { $name } (not a parameter)
expr-function-fails = in { $source }: { $function } cannot be evaluated ({ $why })
expr-exponent = in { $source }: the exponent { $exponent } is too large (at most { $limit } in absolute value)
expr-division-by-zero = in { $source }: division by zero
expr-too-large = in { $source }: the value is too large
expr-not-real = in { $source }: the value is not real
expr-underflow = in { $source }: the value is too small for floating-point numbers (it would be taken as 0)
expr-not-finite-value = in { $source }: the value is not finite
expr-too-many-digits = in { $source }: the value has too many digits for exact formulas (more than { $limit })
expr-degree = in { $source }: the formula's degree in the symbols is above { $limit }: too high for exact formulas
parameter-no-value = parameter '{ $name }' has no value
number-too-many-digits = the number { $number } has too many digits for exact formulas (more than { $limit } as a fraction): round it, or solve with numbers

## the model's shape (model/build.py, model/model.py)
model-mapping = a model is a mapping with keys points, bodies, joints, drivers
frame-missing = there is no fixed body '{ $frame }': name one body '{ $frame }' or set `frame:` to one of { $bodies }
parameter-name-invalid = '{ $name }' is not a valid parameter name (letters, digits and _, not starting with a digit)
unknown-name-in = unknown name '{ $name }' in '{ $text }'
unknown-name-in-parameters = unknown name '{ $name }' in '{ $text }' (parameters: { $parameters })
components-count = expected { $dims } components, got { $got }
model-no-points = a model needs at least one point
name-invalid = '{ $name }' cannot be a name: names are not empty and have no '@' (it joins a point to its body: B@rocker)
construction-planar = points by construction are planar; give a 3D model's points as coordinates [x, y, z]
planar-two-coordinates = a planar model (dimension 2) has 2 coordinates per point
point-listed-twice = point '{ $point }' is listed twice
point-not-carried = point '{ $point }' is not carried by any body: list it in a body's points
unknown-point = unknown point '{ $point }' (points: { $points })
vector-size = a { $dim ->
        [2] planar
       *[other] 3D
    } model needs { $dim } { $what ->
        [coordinates] coordinates
       *[components] components
    }, got { $got }
shapes-3d-only = disc and plane shapes belong to 3D models; use circle and line in a planar model
shapes-planar-only = curves and cams belong to planar models
unknown-body = unknown body '{ $body }' (bodies: { $bodies })
joint-id-empty = a joint id is not empty
joint-id-twice = joint id '{ $id }' is used twice
joint-same-body = a joint needs two different bodies, got '{ $body }' twice
joint-point-not-on-body = the { $kind } point '{ $point }' is not on body '{ $body }': list '{ $point }' in its points
direction-same-points = a direction needs two different points
unknown-joint = unknown joint '{ $joint }' (joints: { $joints })
unknown-joint-bare = unknown joint '{ $joint }'
expected-one-number = expected one number (the component along `along`), got a vector
expected-vector = expected a vector of { $dim } components (or give `along` for one component)
questions-too-many = { $count } questions: at most { $limit } in one model
question-one-key = a question has exactly one of the keys { $keys }
contact-not-touching = '{ $text }' is not a { $kinds } joint (those are: { $joints })
decompose-needs-moving = a decompose question needs `moving: BODY`, the moving frame
moving-only-decompose = `moving` belongs to decompose questions
question-planar-only = { $kind } is a planar question; ask for the screw `axis` in 3D
question-3d-only = the screw axis is a 3D question; ask for `icr` in a planar model
steps-at-least-one = steps must be at least 1

## what pydantic finds wrong with a file's shape (model/build.py, cams/spec.py)
schema-problems = { $problem }{ $others ->
        [0] {""}
        [one] {" "}(and { $others } more problem)
       *[other] {" "}(and { $others } more problems)
    }
driver-second-kind = a driver has exactly one of { $kinds }; '{ $key }' is a second one
unknown-key = unknown key '{ $key }'
missing-key = missing key '{ $key }'
not-one-of = { $value } is not one of { $expected }
unexpected-value = unexpected value { $value }: { $problem }
pydantic = { $text }
point-name-not-text = a point is named by a string such as 'B' or 'B@rocker', got { $got }
point-body-after-at = '{ $text }': name the body after '@' (as in '{ $example }')
body-not-carrying = body '{ $body }' does not carry point '{ $point }' (carried by { $carriers })
point-ambiguous = point '{ $point }' is carried by { $carriers }, which move differently there: write { $choices }
unknown-parameter = unknown parameter '{ $name }' (parameters: { $parameters })
name-or-note-empty = a name or a note is not empty
notation-key-unknown = '{ $key }' is neither a parameter (parameters: { $parameters }) nor omega(BODY), omega(BODY/OTHER), alpha(…)
notation-rate-bodies = '{ $key }': a rate is of one body, or of one body relative to another (omega(blades/block))
notation-spelling = '{ $name }' is not a symbol's name: letters, digits and _ as sympy spells them (omega_0 is ω₀, vdot is v̇, R_roda)
draw-at-has-value = '{ $name }' has a value already: draw_at gives numbers to symbolic parameters (null)
draw-at-not-finite = '{ $name }' is drawn at { $value }: give a finite{ $positive ->
        [true] {" "}positive
       *[other] {""}
    } number
draw-at-range = '{ $name }' is drawn at { $value }: figures are drawn with numbers between { $low } and { $high } in size
up-planar = up names the vertical of a 3D model; a planar model is drawn in its own plane
up-direction = up is a non-zero direction of 3 numbers, such as [0, 1, 0]
construction-cycle = the constructions refer to each other in a cycle: { $cycle }
construction-point-expected = expected a point's name or coordinates [x, y], got { $got }
construction-coordinates = constructions are planar: coordinates [x, y], got { $got } components
construction-circle-radius = a circle is [centre, radius]: the radius is one number
circle-arc = a circle's arc [from, to] (degrees, counter-clockwise) is a part of the circle: 0 < to − from < 360 (here { $start } to { $end })
construction-line-direction = a line's direction is a vector; for a line through two points write [P, Q]
construction-direction-planar = constructions are planar: a direction [dx, dy]
near-symbolic = `near` needs numbers; in a model with symbolic parameters choose the intersection with `side`
near-point = `near` is a sketch point [x, y]
two-points-same = two different points are needed, got '{ $point }' twice
statement-placeholder = {"{"}{ $name }{"}"} is not a parameter (parameters: { $parameters })
unit-not-length = '{ $unit }' is not a length unit (units: { $units })
question-missing = question { $number } does not exist: the model asks { $count } (numbered from 1)
graded-once = name each graded question once (at least one)
tolerance-relative = the tolerance is relative, between 0 and 1: got { $tolerance }
unknown-point-bare = unknown point '{ $point }'
unknown-unit = unknown unit '{ $unit }' (units: { $units })
parameters-mapping = parameters are a mapping of names to values, got { $type }

## cams (cams/*.py) and curves (curves/*.py)
cam-translating-no-key = a translating follower has no '{ $key }'
cam-oscillating-no-offset = an oscillating follower has no 'offset' (place its pivot)
cam-oscillating-pivot = an oscillating follower needs 'pivot' (its distance from the cam's centre)
cam-oscillating-arm = an oscillating follower needs 'arm' (pivot to roller centre or knife edge)
cam-roller-radius = a roller follower needs 'radius'
cam-no-radius = a { $contact } follower has no 'radius'
cam-polynomial-only = only a polynomial segment takes '{ $key }' conditions
cam-dwell-to = a dwell keeps the follower still: leave out 'to'
cam-segment-to = a { $law } segment needs 'to' (the displacement at its end)
cam-below-lowest = the follower would go below its lowest position (s < 0, inside the base circle)
cam-segment-still = a { $law } segment must move the follower: 'to' equals the displacement it starts from (use a dwell)
cam-span = the segments span { $total }°; a disc cam's program spans 360°
cam-program-ends = the program ends at s = { $end }, not where it starts (0): a disc cam's motion repeats every turn
cam-no-polynomial = these boundary conditions have no polynomial
cam-program-or-profile = give the cam's motion as 'program' or its shape as 'profile' (one of them)
cam-base-missing = missing key 'base' (the base circle's radius)
cam-speed-once = give the cam's speed once: omega (rad/s), rpm, or velocity (a translating cam)
cam-speed-translating = a translating cam's speed is its 'velocity'
cam-speed-disc = a disc cam's speed is 'omega' or 'rpm'
cam-plate-translating = a translating cam drives a translating follower
cam-plate-flat = a flat face cannot follow a translating cam (use a roller or a knife edge)
cam-plate-offset = a translating cam's follower has no offset
cam-offset-prime = the offset { $offset } must be smaller than the prime circle's radius { $radius }
cam-face-base = the face cannot touch the base circle: need 0 < base + face < pivot
cam-arm-reach = the arm cannot reach the prime circle (radius { $radius }): need |pivot − arm| < { $radius } < pivot + arm
cam-arm-past = the program turns the arm { $turn }° from { $start }°, past { $reach }° (where the follower loses the cam)
cam-file-mapping = a cam file is a mapping with keys cam, follower, program (or profile), speed
value-problem = { $value }: { $problem }
cam-profile-disc = a cam given by profile points is a disc cam
cam-profile-base = a cam given by profile points has the base circle its profile gives: leave out 'base'
cam-follower-misses = the follower does not reach the cam
cam-knife-misses = the knife edge's path misses the cam
cam-jump = the { $quantity ->
        [velocity] velocity
       *[acceleration] acceleration
    } jumps by { $size } { $unit } at { $at }{ $place } ({ $quantity ->
        [velocity] infinite acceleration
       *[acceleration] infinite jerk
    }: the fundamental law of cam design is broken)
curve-line-direction = a line's direction must not be zero
curve-unbounded = an unbounded curve has no points to draw: give it a finite domain
spline-points = a spline's points are a list of (x, y) pairs
spline-too-few = a { $closed ->
        [true] closed
       *[false] open
    } spline needs at least { $need } points
spline-points-differ = a spline's consecutive points must differ
circle-radius-positive = a circle's radius must be positive
arc-angles = an arc runs counter-clockwise from a0 to a1, with a0 < a1 ≤ a0 + 2π
cam-flat-translating = a flat-faced follower cannot follow a translating cam

## joints (joints/*.py)
and-word = and
nothing = {""}
sweep-velocity-only = a sweep cannot follow a { $kind } joint{ $dim ->
        [3] {" "}in 3D
       *[other] {""}
    }: its condition is on velocities only, so the positions depend on the path taken{ $in_time ->
        [true] ; `kinematika simulate` follows it in time
       *[other] {""}
    }
joint-other-dimension = a { $kind } joint belongs to a { $dim ->
        [2] 3D
       *[other] planar
    } model
joint-needs-key = a { $kind } joint needs `{ $key }`
internal-owners = `internal` belongs to { $owners } joints
joint-no-key = a { $kind } joint has no `{ $key }`{ $planar ->
        [true] {" "}in a planar model (rotations are about z)
       *[other] {""}
    }
joint-no-rate = a { $kind } joint has no rate to drive; drive a body's omega or a point's velocity
rounding-hint = , more than the tolerance { $tolerance } (1e-6 of the model's size): write { $point } by construction, or with more digits
slot-off-line = slot point '{ $point }' is off the line { $line }: gap { $gap }{ $hint }
cam-joint-first-body = a cam joint's first body carries the cam: give '{ $body }' a `cam:` shape
cam-joint-face = a flat-faced follower touches with its face: give '{ $body }' a `line` (the face)
cam-joint-at = a cam joint needs `at`: the follower's { $roller ->
        [true] roller's centre
       *[other] knife edge
    }
curved-slot-outline = a curved slot is cut along a circle or curve of '{ $body }': give that body one
cylindrical-two-rates = a cylindrical joint has two rates (turning and sliding): drive the body's omega relative_to the other body and a point's velocity along the axis
rolling-needs-shapes = a { $kind } joint needs a shape on both bodies: give '{ $body }' a { $dim ->
        [2] circle or line
       *[other] disc or plane
    }
shapes-cannot-roll = these shapes cannot roll on each other
no-touch = '{ $body }' does not touch '{ $other }': gap { $gap }{ $hint }
the-contact-or-centre = the contact or centre
the-contact = the contact
contact-not-at = the contact is not at '{ $point }': it is { $distance } away{ $hint }
internal-circles-only = `internal` tells how two circles touch; this is a { $contact } contact
rolling-internal-wrong = the { $kind } pair is declared { $said } but its { $kind ->
        [gear] pitch circles
       *[other] circles
    } touch { $said ->
        [internal] externally
       *[external] internally
    }
disc-flat-on-plane = disc '{ $disc }' lies flat on the plane of '{ $plane }': it touches along its face, not at a point
sweep-rolling-only = a sweep follows rolling of circles and lines only
contact-acceleration-curve = the geometric contact point's acceleration on a general curve needs its curvature's rate: ask for the bodies' points
straight-outlines = two straight outlines touch along a line, not at a point: join them by a prismatic joint
pair-cannot = { $kind } between '{ $body }' and '{ $other }': { $why }
touching-needs-outlines = a { $kind } joint needs an outline on both bodies: give '{ $body }' a circle, line or curve (or name its point with `at`)
outlines-cannot-touch = these outlines cannot touch at a point

## the conditions of the motion, named in messages (joints/*.py, engine/drivers.py, engine/idle.py)
row-joint = { $id }: { $label }
row-driver = { $where } ({ $label })
row-joint-rate = rate of joint { $joint } = { $value }
row-rate = { $name } of { $body }
row-rate-relative = { $name } of { $body } relative to { $relative }
row-equals = { $label } = { $value }
row-component = { $label } ({ $axis }) = { $value }
row-point-along = { $name } of { $point } along the given direction = { $value }
row-point = { $name } of { $point }
row-idle = no idle spin of { $body } about { $axis }
row-curved-slot = { $point } stays in the curved slot of { $body }
row-turning-axis = relative rotation only about the axis ({ $n })
row-sliding-axis = relative sliding only along the axis ({ $n })
row-across-guide = no relative motion across the guide ({ $n })
row-moves-with = { $point } moves with { $other } ({ $axis })
row-no-slip = no slip at the contact of { $body } and { $other } ({ $axis })
row-slot = { $point } stays on the slot of { $body }
row-turns-with = { $body } turns with { $other }
row-body-moves-with = { $body } moves with { $other } ({ $axis })
row-no-sideways = { $point } has no sideways velocity relative to { $body }
row-touching = { $b } keeps touching { $a }
row-cam-touching = the follower { $b } keeps touching the cam { $a }
row-no-rotation = no relative rotation
row-no-rotation-axis = no relative rotation ({ $axis })

## the mobility of the mechanism (engine/mobility.py)
infinite = infinite
dead-point = a dead point: the drivers do not fix the motion here; { $count ->
        [0] the drivers depend
        [one] { $drivers } depends
       *[other] { $drivers } depend
    } on the joints (condition number { $condition } of the dimensionless Jacobian, limit { $limit })
mobility-free = the mechanism has { $dof ->
        [one] { $dof } degree
       *[other] { $dof } degrees
    } of freedom but the drivers give { $conditions ->
        [one] { $conditions } independent condition
       *[other] { $conditions } independent conditions
    }; left free: { $count ->
        [0] some motion
       *[other] { $free }
    }
drivers-conflict = the drivers conflict, their values do not agree with each other or the joints: { $named } ({ $dof ->
        [one] { $dof } degree
       *[other] { $dof } degrees
    } of freedom; { $given ->
        [one] { $given } driver condition
       *[other] { $given } driver conditions
    }, { $conditions } independent)

## the instant: values, directions, points by construction (engine/*.py)
direction-zero = a direction cannot be the zero vector
direction-not-exact = this direction cannot be made a unit vector exactly: its components are too far apart in size (write the small one as 0)
direction-points-coincide = a direction needs two different points: { $start } and { $end } coincide
value-not-real = a value is not a real number for the symbols' values (the square root or a power of a negative quantity?)
parameters-cycle = parameters refer to each other in a cycle: { $names }
points-not-real = the points are not real for any values of the symbols tried (a square root of a negative number?)
curves-need-numbers = curves and cams are drawn from numbers: give the parameters their values (or solve without --symbolic)
curve-through-points = the curve cannot be drawn through its points: { $why }
radius-positive = a radius must be positive, got { $radius }
jacobian-singular-large = the { $rows }×{ $columns } constraint Jacobian is singular or not square (sparse LU); the system is too large to say which conditions are missing or dependent
structurally-singular = the system has no structurally independent set of conditions for every unknown
angle-in-radians = the angle { $angle } is in radians: { $degrees }°, { $turns } turns; for { $angle }° write deg({ $written })
point-too-large = the exact coordinates of { $point } would have about { $size } operations (more than { $limit }): too large for formulas; give more parameters numbers, or solve without --symbolic
length-positive = { $what ->
       *[radius] a radius
    } must be positive, got { $value }
direction-points-same = the two points that give the direction coincide
fit-each-side = , one on each side of { $line }
fit-on-line = {" "}on the line { $line }
circles-same-centre = the circles about { $a } and { $b } have the same centre
circles-apart = the circles about { $a } ({ $ra }) and { $b } ({ $rb }) do not meet: centres { $d } apart, { $gap } more than { $ra } + { $rb }
circles-inside = the circles about { $a } ({ $ra }) and { $b } ({ $rb }) do not meet: the circle about { $inner } lies inside the one about { $outer } (centres { $d } apart, { $gap } less than |{ $ra } − { $rb }|)
line-direction-zero = a line's direction cannot be the zero vector
circle-misses-line = the circle about { $centre } ({ $radius }) misses the line { $line }: the line is { $distance } from { $centre }, { $gap } more than the radius
lines-parallel = the lines { $a } and { $b } are parallel: they do not meet
line-points-coincide = the line { $line } is given by two points that coincide
two-points-fit = two points fit{ $relation }: { $points }; choose one with side: { $first } or { $second }, or near: [x, y]
beyond-floats = beyond what floats hold
model-size-range = the model's size is { $size }: kinematika computes with lengths between { $low } and { $high }, in any unit; write the lengths in another unit
rates-range = the drivers' values are out of range for this mechanism (a rate of { $rate } per unit of time): kinematika computes with rates between { $low } and { $high }; write the times in another unit
values-overflow = the model's values are too large: its velocities or accelerations overflow the range of floating-point numbers

## limits of the work, optional modules, languages (budget.py, extras.py, languages.py)
over-budget = finding { $what } takes { $counted ->
        [true] more than { $steps } steps of exact algebra
       *[other] longer than { $seconds } s of CPU time
    }{ $staged ->
        [true] {" "}({ $stage })
       *[other] {""}
    }: they are too large; { $advice }
exact-formulas = the exact formulas
stage-solving = solving the equations exactly
stage-simplifying = simplifying the formulas
advice-symbolic = give some parameters numbers, or solve without --symbolic
advice-null = give numbers to some of the parameters left as symbols (null: { $names })
advice-numbers = give some parameters numbers
module-missing = { $what } needs { $module }, which is not installed: install it with { $command }
writing-parquet = writing Parquet (or write .npz)
writing-dxf = writing DXF
study-on-dask = a study on a Dask cluster
unknown-language = unknown language '{ $lang }' (languages: { $langs })
centres-planar = instant centres are planar; ask for the screw `axis` of each body in 3D

## sweeps, moves and assemblies (sweep/*.py)
assembly-not-whole = an assembly is a whole number, got { $got }
assembly-missing = there is no assembly { $number }: this mechanism has { $count } at its drawn input (see `kinematika assemblies`)
assemblies-too-many = { $dyads } dyads close in two ways each: listing 2^{ $dyads } assemblies is beyond the limit of 2^{ $limit }
sweep-by-varied = the sweep's length ({ $by }) depends on a varied parameter: give it as a number (--by)
move-not-number = { $problem } (a move is a number of degrees or lengths)
move-not-finite = a move is a finite number
move-not-driven = joint '{ $joint }' is not driven; `move` advances a driven joint ({ $count ->
        [0] none here
       *[other] { $driven }
    })
move-unreachable = { $joint } cannot be moved { $amount }{ $unit }: the mechanism meets a dead point or comes apart after { $got }{ $unit }
sweep-by-needed = joint '{ $joint }' is { $kind }: give the sweep's length (`by` in the model's sweep section, or --by)
steps-whole = steps must be a whole number, got { $got }
steps-range = steps must be between 1 and { $limit }, got { $got }
steps-too-many-values = { $steps } steps of { $per_row } values each are more than a sweep holds ({ $limit } values): take at most { $most } steps
by-number = by must be a number, got { $got }
by-finite = by must be a finite number
sweep-no-driven-joint = no driven joint to sweep: drive a joint's rate, or the omega or velocity of a body joined to the frame by a revolute or prismatic joint
sweep-not-driven = joint '{ $joint }' is not driven; a sweep advances a driven joint: { $driven }
fixture-shape = { $shape }'s place
fixture-joint = joint { $joint }'s direction
move-symbolic-3d = a 3D model with symbolic parameters cannot be moved: give its parameters values (--set NAME=VALUE)
move-symbolic-once = a model with symbolic parameters is moved once: give all its moves together
move-same-body = two moves turn the same body: give it one move
move-not-input = joint '{ $joint }' does not join a body to the frame: move a model with symbolic parameters by its input joint
move-at-values = cannot move: at values of the symbols where the model holds ({ $values }), { $problem }
move-exact-numbers = cannot move exactly: point '{ $point }' follows the input in numbers, not in its exact coordinates (give the parameters values)
move-exact-rolls = cannot move exactly: point '{ $point }' is on '{ $body }', which rolls on a line: its turn is the path of its centre over its radius, no closed form here (give the parameters values)
move-exact-no-form = cannot move exactly: point '{ $point }' does not follow the input: no construction, rolling ratio or other body gives the pose of '{ $body }' in closed form; write { $point } by construction (or give values)
move-exact-constructed = cannot move exactly: point '{ $point }' does not follow the input: it is constructed from points that do not move with { $body }; construct it from those (or give values)
move-exact-fixture = cannot move exactly: '{ $body }' turns with no closed form here, and its { $what } is written in numbers; give it by points (or give the parameters values)
body-no-point = body '{ $body }' carries no point, so its shapes cannot be moved: list one of its points
cannot-assemble-there = the mechanism cannot be assembled there
sweep-at = increment { $k } ({ $joint } = { $value } { $unit })
sweep-drivers-contradict = the drivers as written contradict the joints at { $at }: a vector driver (3D ω, a velocity) stays fixed in the ground axes as the mechanism turns; drive the joint's rate instead
sweep-singular = the configuration at { $at } is singular for the drivers (a dead point: condition number above 1e+10){ $said ->
        [true] {" "}({ $what })
       *[other] {""}
    }; use --skip-bad to skip such positions
sweep-cannot-assemble = the mechanism cannot be assembled at { $at }{ $said ->
        [true] : { $what } cannot close the loop
       *[other] {""}
    }; use --skip-bad to skip such positions

## studies and synthesis (explore/*.py)
metrics-once = each metric once, and none named as a parameter or 'assembles'/'reason'
study-needs-numbers = a study needs numbers: give a value to { $names } or vary it
vary-form = --vary expects NAME=LOW:HIGH (as a=1:5), got { $got }
vary-interval = --vary { $name }: the interval must be finite with LOW <= HIGH, got { $got }
vary-none = name at least one parameter to vary (--vary NAME=LOW:HIGH)
varied-twice = a parameter is varied twice: { $names }
grid-or-samples = give either --grid N or --samples N
grid-positive = --grid and --samples take a positive number
designs-too-many = { $count } designs: at most { $limit }
motion-error-two-points = motion_error: body '{ $body }' needs two points to have an orientation
metric-unknown = unknown metric '{ $metric }'; metrics: grashof, transmission, dead_points, time_ratio[:BODY], range:BODY, peak_omega:BODY, peak_alpha:BODY, peak_speed:POINT, peak_accel:POINT, path_error:POINT=FILE.csv, motion_error:POINT=FILE.csv, structural_error:BODY=FILE.csv, angle|omega|alpha:BODY=X, speed|accel|x|y:POINT=X
grashof-four-bar = grashof needs a model whose moving loop is a four-bar driven at its crank
time-ratio-linkage = time_ratio without a body needs a four-bar or slider-crank; name the output (time_ratio:BODY)
transmission-linkage = transmission needs a four-bar or slider-crank driven at its crank
metric-at-input = { $metric }=X takes the input's position X (a number, { $unit } from the drawn position), got { $got }
input-outside-sweep = the input must lie in the sweep's range { $low } to { $high } { $unit }
time-ratio-full-turn = time_ratio needs the sweep of a full turn of the crank (by: 360)
target-csv = { $name }: a target file is a .csv file
table-not-numbers = { $name }, line { $line }: expected numbers, got { $got }
table-columns = { $name }, line { $line }: expected { $columns } finite numbers
table-empty = { $name } holds no rows of numbers
cannot-write = cannot write { $path }: { $reason }
cannot-read = cannot read { $path }: { $reason }
study-no-column = the study has no column '{ $name }' (columns: { $columns })
study-worker-died = a worker process of the study ended abruptly (out of memory?): try fewer --workers or a smaller --chunk
dask-unreachable = cannot reach the Dask scheduler at { $scheduler }: { $reason }
study-interrupted = { $folder } holds an interrupted study: add --resume to continue it, or delete that folder to start again
study-different = { $folder } holds a different study (another model, parameters, designs or metrics): delete it to start again
study-output = the output is a .parquet or .csv file, got { $name }
study-stopped = { $problem }{ $note }
study-kept = ; { $kept } designs are kept in { $folder }: run again with --resume to go on
study-needs-model = a study needs a model file or a model's text
function-unknown-name = in { $source }: unknown name '{ $name }' (the function is of x, the input's increment)
function-not-finite = { $source } is not finite over { $low } to { $high }

## exercises (exercise/*.py)
variant-missing = there is no variant { $number } (variants 1 to { $count })
vary-unknown-parameter = --vary { $name }: unknown parameter (parameters: { $parameters })
vary-none-step = name at least one parameter to vary (--vary NAME=LOW:HIGH[:STEP])
exercise-needs-numbers = an exercise needs numbers: give every symbolic parameter a value (or vary it)
exercise-no-model = exercise.json does not name the model file
exercise-lacks = exercise.json lacks vary, seed or lang
exercise-cannot-read = cannot read { $path }: { $reason } (is it a folder `kinematika exercise` wrote?)
file-not-json = { $name } is not JSON: { $problem }
file-not-json-object = { $name } is not a JSON object
csv-not-utf8 = { $name } is not UTF-8 text
csv-no-column = { $name } has no column '{ $column }' (its header: { $count ->
        [0] none
       *[other] { $header }
    })
variants-numbered = variants are numbered 1, 2, … with a value of each varied parameter
variants-none = no variants
key-mismatch = key.csv does not match the model solved again (variant { $variant }, { $question }): was the model or the key edited?
question-not-asked = '{ $question }' is not asked in variant { $variant } (its questions: { $asked })
row-no-student = a row without a student
variant-not-number = variant { $got } is not a number
answered-twice = { $student } answers { $question } of variant { $variant } twice (first on line { $first })
statement-missing = the exercise section has no statement in '{ $lang }' (it has { $langs })
vary-step-form = --vary expects NAME=LOW:HIGH[:STEP] (as s=300:500:10), got { $got }
vary-step-interval = --vary { $name }: give LOW <= HIGH and a positive STEP, got { $got }
vary-grid-large = --vary { $name }: { $count } values on the grid, at most { $limit }: take a larger step
count-range = --count takes 1 to { $limit } variants, got { $got }
grids-too-small = the grids hold { $total } different variants, fewer than --count { $count }: widen an interval or take smaller steps
variants-few = only { $found } of { $count } variants found in { $drawn } drawn: { $apart } do not assemble, { $dead } are near a dead point, { $close } cannot tell a usual mistake from the right answer; change the intervals
weights-count = give one weight per graded question: { $count }, got { $got }
weight-positive = a weight is a positive number, got { $got }
reveal-after-check = the worked solution comes after a check: send the answers with it
students-first-column = { $name }: the first column must hold the students' ids
student-twice = student { $student } is listed twice (lines { $first } and { $line })
student-variant-range = variant { $got } is not one of 1 to { $count }
table-unreadable = cannot read { $path }: { $reason }
table-empty = { $name } is empty (a header, then one row per line)
table-no-column = { $name } has no column '{ $column }' (its header: { $header }; columns: { $columns })
row-fields = { $count } fields, the header has { $header } (a value with a comma needs quotes)
row-not-read = { $place }: not read: { $error }
students-unknown = not on the class list (left out): { $students }
grade-column = { $column ->
        [question] question
        [answers] answers
        [right] right
        [carried] carried
        [mistakes] mistakes
        [student] student
        [variant] variant
       *[score] score
    }
grade-score = { $score } %
exercise-not-drawn-rounding = not drawn: { $data }: rounding the data to 3 figures moves { $question } by { $gap } %
exercise-not-drawn-mistake = not drawn: { $data }: { $kind } gives { $question } within { $gap } % of the right answer
exercise-narrowed = variant { $number }: the margin of { $question } narrowed to { $tolerance } % to tell { $kind } apart (it gives { $gap } % off)
exercise-wrote = wrote { $count } { $count ->
        [one] variant
       *[other] variants
    } to { $folder }
exercise-progress = figures and worked solutions: { $done }/{ $total }
pdf-skipped = PDF skipped: { $program } is not installed ({ $hint })

## figures and explanations (draw/*.py, explain/*.py, web/strings.py)
animate-planar = animate draws planar models; draw a 3D model's instant with `kinematika draw`
ffmpeg-missing = writing .mp4 needs the ffmpeg program, which is not installed (on Debian or Ubuntu: apt install ffmpeg; with conda: conda install ffmpeg); or write a .gif, which needs nothing more
sweep-none-assembled = no position of the sweep could be assembled
trace-unknown-point = unknown point '{ $point }' to trace
plot-format = cannot plot to '{ $name }': give a .png, .svg or .pdf file
draw-at-not-real = the model cannot be drawn at these values: point { $point } is not real there
unknown-format = unknown format '{ $format }' (formats: { $formats })
catalogue-no-message = no message '{ $key }' in the '{ $lang }' catalogue
catalogue-message-error = message '{ $key }' of the '{ $lang }' catalogue: { $problem }
page-message-error = page message '{ $key }' ({ $lang }): { $problem }

## the command line (cli/*.py)
out-of-memory = the work needs more memory than this machine gives; make the model or the sweep smaller
internal-error = internal error ({ $detail }); rerun with KINEMATIKA_DEBUG=1 and report it
no-folder = there is no folder { $folder }
it-is-a-folder = it is a folder
it-is-a-file = it is a file
the-output-file = the output file
students-none = { $name } names no students (a header, then one per row)
synthesis-one-target = give one of --target (path), --target-function (function) or --target-motion (motion)
function-needs-output = function generation needs --output BODY
path-needs-point = path and motion generation need --point P
map-or-pareto = give --map X,Y,METRIC or --pareto M1,M2
option-names-count = { $option } takes { $count } names separated by commas
study-unreadable = cannot read the study { $path }: { $reason }
option-name-value = { $option } expects NAME=VALUE, got { $got }
cannot-serve = cannot serve on { $address }: { $reason }
format-needs-output = --format { $format } needs -o FILE, the file to write
sweep-format = { $got } is not a sweep format: give --format { $formats } or a file ending in one of them

## the page and its API (web/*.py)
build-op = 'op' is an object whose 'op' is one of { $actions }
tool-picks = the { $tool } tool takes { $count } picks ({ $picks })
build-path = 'path' is a list of keys and indices
build-value = 'value' is a number or an expression
build-value-empty = 'value' is empty
build-value-finite = 'value' is not a finite number
build-nothing-at = nothing at { $path } in the model
delete-missing = no { $element } to delete
delete-what = { $element }: delete point:NAME, body:NAME, joint:ID, driver:N or ask:N
delete-no-point = no point '{ $point }' to delete
delete-no-body = no body '{ $body }' to delete (the ground stays)
driver-value = a driver's value is a number or an expression
input-body-or-joint = the input is a moving body or a joint of the model
question-kind = { $question }: a question is one of { $kinds }
question-target = 'target' names the point or body asked about
target-not-moving = { $target } is on no moving body
format-one-of = { $format }: a format is one of { $formats }
toml-null = { $place } is null, which TOML cannot write (a symbolic parameter): keep this model in YAML or JSON
the-model = the model
drag-constructed = { $point } is constructed: drag it in a YAML or JSON model, or edit its construction
no-point-in-model = no point '{ $point }' in the model
drag-not-planar = { $point } is not a planar point with two coordinates
drag-formula = { $point } is placed by the formula { $formula }: change its parameters to move it
drag-lines-meet = { $point } is where two lines meet: drag the points its lines go through
model-unreadable = the model cannot be read: { $problem }
drag-toml-form = the point '{ $point }' is not written as `{ $point } = [x, y]` in the [points] table
request-vary = 'vary' is a list of NAME=LOW:HIGH[:STEP] texts
request-answers = 'answers' maps question ids (q2.y) to the typed numbers
request-reveal = 'reveal' is true or false
request-whole-range = '{ $key }' is a whole number, { $low } to { $high }
request-whole-least = '{ $key }' is a whole number, at least { $low }
request-one-variant = without 'vary' the exercise has one variant, the model's data
help-no-document = no document '{ $name }' (the help serves docs/*.md)
no-free-point-name = no free point name
not-finite-number = { $value } is not a finite number
pick-no-point = no point '{ $point }' placed yet
link-two-points = a link joins two different points
link-length = a link needs some length: put its end elsewhere
point-two-conditions = { $point } is already placed by two conditions: delete one of its links first
slot-own-points = the slot runs along two points of { $body }: pick another body or another pin
plate-two-points = { $body } needs two points before a third is fixed to it
track-once = the ground has a track already: one straight track a model
wheel-centre = put the wheel's centre away from its contact point
gear-centre = put the second gear's centre away from the first
no-body = no body '{ $body }'
slot-outline-once = { $body } has an outline already: one slot a body
pin-other-body = the pin { $pin } is on no other body than { $body }: pick a pin of another body
slot-centre-pin = the slot's centre cannot be the pin
contact-two-bodies = a contact joins two different bodies
contact-no-outline = { $body } has no outline (a circle, a line, a curve, a cam) to touch with: write its shape in the text first
tool-unknown = unknown tool '{ $tool }' (the palette has { $tools })
request-not-json = the request is not JSON: { $problem }
request-object = the request is a JSON object with at least the key 'model'
request-unknown-key = unknown key '{ $key }' for /api/{ $endpoint } (accepted: { $accepted })
request-model = 'model' is required: the model file's text
request-points = 'points' is a list of point names
request-width = 'width' is a figure width in inches, 1 to 100
request-frame = 'frame' is the box the figure shows, [x0, y0, x1, y1] with x0 < x1 and y0 < y1
request-op = 'op' is the action: an object with its key 'op'
request-to = 'to' is the point's new place [x, y]
request-point = 'point' names the point to move
request-choice = { $value }: { $key } is one of { $choices }
request-flag = '{ $key }' is true, false or null
request-text = '{ $key }' is a text
request-number = '{ $key }' is a number
request-assignments = '{ $key }' maps names to numbers or expressions
request-assignment = { $key }: a number or an expression
no-example = no bundled example '{ $name }'
server-busy = the server is busy: try again in a moment
server-timeout = the computation took longer than { $seconds } s and was given up
no-template = no template '{ $name }'
request-content-type = send the request as JSON (Content-Type: application/json)
request-too-large = the request is too large ({ $size } bytes; at most { $limit })
internal-error-page = internal error ({ $detail }); please report it

## the lines the command line prints (cli/__init__.py, cli/shared.py)
error-line = error ({ $kind }): { $text }
internal-line = error: { $text }
warning-line = warning: { $text }
usage-line = error (usage): { $text } (see { $command } --help)
aborted = aborted
click = { $text }
serving-open = serving on { $host }: anyone who can reach this machine on port { $port } can use the page (it reads no file, but it computes for them)

## limit positions and rows of a sweep (sweep/limit_positions.py, sweep/continuation.py, sweep/move.py)
sweep-too-many-limits = the motion passes more than { $limit } limit positions; sweep a shorter travel
sweep-not-followed = the motion cannot be followed past { $joint } = { $value } { $unit } (after { $travel } { $unit } of travel): { $why }
follow-turns-back = it turns back at once: branches of the motion meet there
follow-cannot-close = { $bodies } cannot close there, and it is not a limit position
follow-not-corrected = the curve could not be corrected there
follow-starts-at-limit = it starts at a limit position
follow-branches-meet = branches of the motion meet there
follow-runs-off = the mechanism runs off to infinity there
follow-too-many-steps = more than { $limit } continuation steps between two rows
follow-not-assembled = the mechanism could not be assembled there
follow-stuck = the mechanism cannot be assembled a step further, and it is not a limit position
row-needs-numbers = a row of the sweep needs numbers for every parameter
row-out-of-range = row { $row }: the sweep has rows 0 to { $last }
row-cannot-assemble = row { $row } of the sweep cannot be assembled

## renaming on the page (web/rename.py)
rename-not-a-name = '{ $name }' is not a name: a letter, then letters, digits or _
rename-element = '{ $element }': rename body:NAME or point:NAME
rename-language = '{ $lang }': a language is one of { $langs }
rename-nothing = no '{ $element }' to name
rename-no-body = no body '{ $name }' to rename
rename-body-exists = there is a body '{ $name }' already
rename-no-point = no point '{ $name }' to rename
rename-point-exists = there is a point '{ $name }' already

## the model's notation of indices and spins (model/wording.py)
index-twice = bodies '{ $first }' and '{ $second }' would both be written '{ $index }'
spin-not-wheel = joint '{ $joint }' is not a wheel: only a wheel has a spin
spin-shape = a spin is {"{"}symbol: NAME, radius: PARAMETER{"}"} (symbol: phidot, radius: r)
spin-radius-unknown = the radius '{ $radius }' is not a parameter (parameters: { $parameters })
index-shape = '{ $index }' is not a body's index: one to four letters or digits (N, 1, R, T)
contact-name-shape = '{ $index }' is not a contact's name: one to four letters or digits (F, J, K2)

## symbols at their draw_at numbers, travel, straight outlines (sweep/posing.py, sweep/plan.py, joints/touching.py)
needs-draw-at = { $what ->
        [move] a move
        [simulate] a simulation
       *[sweep] a sweep
    } needs numbers: give { $names } a value, or the model a `draw_at` number for each symbol
at-draw-numbers = { $what ->
        [move] moved
       *[sweep] swept
    } at the draw_at numbers of its symbols: { $values }{ $said ->
        [true] {" "}({ $why })
       *[other] {""}
    }
travel-too-far = { $what } { $amount } is more than a sweep or move travels: at most { $most }{ $unit ->
        [angle] ° ({ $turns } turns)
       *[length] {" "}({ $turns } times the mechanism's size)
    }
two-straights-touch = two straight outlines touch along a line, not at a point: join them by a prismatic joint

## synthesis: its task, its target file, its four-bar (explore/synthesis/*.py, cli/explore.py)
synthesis-no-design = no design of the intervals completes its cycle{ $requirements ->
        [0] {""}
       *[other] {" "}and meets the requirements
    }
synthesis-no-full-turn = no design found completes a full turn of its input
synthesis-nothing-found = no design within the --vary intervals assembles at every target{ $count ->
        [0] {""}
       *[other] {" "}and meets { $requirements }
    }; widen the intervals or search longer
require-crank-rocker-four-bar = --require crank-rocker needs a four-bar driven at its crank (a crank and two links closing on the frame), its point on the coupler
require-transmission-linkage = --require transmission=DEG needs a four-bar or a slider-crank driven at its crank
require-transmission-angle = --require transmission=DEG: DEG is an angle between 0 and 90 degrees, got { $got }
requirement-unknown = unknown requirement '{ $requirement }'; requirements: { $requirements }
timing-needs-four-bar = --timing needs a four-bar driven at its crank, the task's point on its coupler (other models: leave the targets' timing free)
timing-form = --timing expects JOINT or JOINT=START, got { $got }
timing-start-number = --timing { $joint }=START: START must be a number, got { $got }
timing-start-finite = --timing { $joint }=START: START must be finite
objective-form = --objective is sse or max, got { $got }
output-zero-form = --output-zero is 'free' or an angle in degrees, got { $got }
output-zero-function-only = --output-zero is for function generation only (--target-function)
output-zero-needs-four-bar = --output-zero needs a four-bar whose output is its rocker or coupler
output-not-rocker-or-coupler = the output '{ $output }' is not the four-bar's rocker ({ $rocker }) or coupler ({ $coupler })
body-needs-two-points = body '{ $body }' needs two points to have a direction
targets-too-few = { $name }: { $count } { $count ->
        [one] target
       *[other] targets
    }; synthesis needs at least { $least }
target-columns-count = { $name }: { $count } { $count ->
        [one] column
       *[other] columns
    }; this task reads { $reads }
target-column-unread = { $name }: column '{ $column }' is not read by this task{ $timing ->
        [true] {" "}(give --timing JOINT to use it)
       *[other] {""}
    }; it reads { $reads }
target-column-missing = { $name }: no column '{ $column }' (this task reads { $reads })
target-header-twice = { $name }, line { $line }: each column named once
target-row-width = { $name }, line { $line }: { $count } values where the file has { $columns } columns
target-not-finite = { $name }, line { $line }: expected finite numbers
target-weight-positive = { $name }, line { $line }: a weight must be positive
target-first-input = { $name }, line { $line }: the first target's input is 0 (the inputs count from the first target)
target-inputs-increase = { $name }, line { $line }: the { $column } values must increase ({ $before } then { $after })
## motion in time (simulate/)
simulate-time-not-evaluated = the simulation's time cannot be evaluated: { $problem }
simulate-time-missing = how long to follow the motion: give --time SECONDS (or a `simulate: {"{"}time: ...{"}"}` section in the model)
simulate-time-positive = the time must be a positive number of seconds, got { $got }
simulate-steps-too-many = { $steps } steps of { $per_row } values each are more than a simulation holds ({ $limit } values): take at most { $most } steps
simulate-time-too-short = the time { $time } s is too short to follow from t = { $start } s
simulate-time-needs-value = the time t needs a value: the drawn configuration's time (usually 0)
simulate-time-only-in-rates = the time t may be used only in drivers' rates (a rate that changes in time); here it would move the mechanism by itself
simulate-unknown-method = unknown method '{ $method }' (the methods of scipy.integrate.solve_ivp: { $methods })
simulate-at = at t = { $at } s: { $what }
simulate-rate-not-taken = the rate's derivative in time cannot be taken: { $problem }
simulate-rate-not-evaluated = the rate's derivative in time cannot be evaluated ({ $problem })
simulate-rate-not-real = the rate's derivative in time is not a finite real number (a square root of a negative number?)
simulate-rate-not-finite = the rate's derivative in time is not finite (a square root or a logarithm at zero?)
simulate-velocity-matrix = the velocity equations cannot be solved (their matrix is not made of finite numbers)
simulate-too-many-evaluations = the motion needs more than { $limit } velocity solutions to be followed (limits.SIMULATE_EVALUATIONS): it is too stiff (a part that settles much faster than the rest moves) or too nearly singular
simulate-dead-point = the motion reaches a dead point at t = { $at } s: the velocities cannot be found past it (the constraint Jacobian's condition number reaches { $condition })
simulate-not-followed = the motion cannot be followed past t = { $at } s: { $why }
simulate-integrator-stopped = the integrator stopped ({ $message })
simulate-positions-not-finite = the integrated positions are not finite numbers
simulate-projection-fails = the integrated positions cannot be brought back onto the joints' position conditions (the motion has left what they allow)
simulate-velocity-only = a simulation cannot follow a { $kind } joint{ $dim ->
        [3] {" "}in 3D
       *[other] {""}
    }: its condition is on velocities only, so the positions depend on the path taken
animation-file-type = cannot write { $name }: give a .gif or .mp4 file

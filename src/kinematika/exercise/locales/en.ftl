## kinematika's exercises in English: statements, sheets, the key, the quiz's feedback and
## the page's exercise mode. Keep the placeholders ({ $name }) as they are.

statement-default = The mechanism of the figure is drawn at the instant of the analysis. Data: { $data }.
units-note-planar = Give lengths in { $unit }, velocities in { $unit }/s and accelerations in { $unit }/s², as x and y components in the axes of the figure; angular velocities in rad/s and angular accelerations in rad/s², counter-clockwise positive.
units-note-spatial = Give lengths in { $unit }, velocities in { $unit }/s and accelerations in { $unit }/s², as x, y and z components; angular velocities in rad/s and angular accelerations in rad/s², as vectors.

ask-omega = the angular velocity of { $body }
ask-omega-rel = the angular velocity of { $body } relative to { $frame }
ask-alpha = the angular acceleration of { $body }
ask-alpha-rel = the angular acceleration of { $body } relative to { $frame }
ask-velocity = the velocity of point { $point } of { $body }
ask-velocity-rel = the velocity of point { $point } of { $body } relative to { $frame }
ask-acceleration = the acceleration of point { $point } of { $body }
ask-acceleration-rel = the acceleration of point { $point } of { $body } relative to { $frame }
ask-icr = the instant centre of rotation of { $body }
ask-icr-rel = the instant centre of rotation of { $body } relative to { $frame }
ask-pole = the acceleration pole of { $body }
ask-curvature = the curvature of the path of point { $point } of { $body }
ask-decompose = the motion of point { $point } of { $body } as drag, relative and Coriolis parts, moving frame { $frame }
ask-intrinsic = the tangential and normal accelerations of point { $point } of { $body }
ask-contact = the motion of the three coincident points at the contact { $joint }
ask-axis = the instantaneous screw axis of { $body }
ask-other = question { $n }

part-point = position
part-center = centre
part-radius = radius
part-velocity = velocity
part-acceleration = acceleration
part-drag = drag
part-relative = relative
part-coriolis = Coriolis
part-total = total
part-direction = direction
part-omega = angular velocity
part-slide = sliding speed
part-speed = speed
part-tangential = tangential
part-normal = normal

sheet-title = Exercise
sheet-student = Student
sheet-name = Name
sheet-variant = Variant { $n }
sheet-find = Find
sheet-answer = answer
key-title = Answer key
key-values = Answers
key-solution = Worked solution
key-question = question
key-value = value
key-margin = right within ±

feedback-right = Right.
feedback-wrong = Not right: see the worked solution.
mistake-coriolis-omitted = This is the value with the Coriolis term 2 ω × v_rel left out.
mistake-coriolis-doubled = This is the value with the Coriolis term counted twice.
mistake-normal-omitted = This is the value with the normal (centripetal) terms ω² r left out.
mistake-sense-reversed = This is the value with the sense of a given ω or α reversed.
mistake-drag-as-absolute = This is the motion of the coincident point of the guide (the drag), not the point's own.
mistake-degrees-as-radians = This is the value with an angle given in degrees taken as radians.
mistake-units-mm-as-m = This is the value with the millimetres of the data taken as metres.
mistake-components-swapped = These are the components swapped.

page-check = Check
page-show = Show the worked solution
page-your-answer = your answer
page-link = Link to this exercise
page-score = { $right } of { $total } right

## Los ejercicios de kinematika en castellano: enunciados, hojas, solucionario, la
## retroalimentación del cuestionario y el modo ejercicio de la página. Deje las marcas
## entre llaves ({ $name }) como están.

statement-default = El mecanismo de la figura está dibujado en el instante del análisis. Datos: { $data }.
units-note-planar = Dé las longitudes en { $unit }, las velocidades en { $unit }/s y las aceleraciones en { $unit }/s², por sus componentes x e y en los ejes de la figura; las velocidades angulares en rad/s y las aceleraciones angulares en rad/s², positivas en sentido antihorario.
units-note-spatial = Dé las longitudes en { $unit }, las velocidades en { $unit }/s y las aceleraciones en { $unit }/s², por sus componentes x, y y z; las velocidades angulares en rad/s y las aceleraciones angulares en rad/s², como vectores.

ask-omega = la velocidad angular de { $body }
ask-omega-rel = la velocidad angular de { $body } respecto de { $frame }
ask-alpha = la aceleración angular de { $body }
ask-alpha-rel = la aceleración angular de { $body } respecto de { $frame }
ask-velocity = la velocidad del punto { $point } de { $body }
ask-velocity-rel = la velocidad del punto { $point } de { $body } respecto de { $frame }
ask-acceleration = la aceleración del punto { $point } de { $body }
ask-acceleration-rel = la aceleración del punto { $point } de { $body } respecto de { $frame }
ask-icr = el centro instantáneo de rotación de { $body }
ask-icr-rel = el centro instantáneo de rotación de { $body } respecto de { $frame }
ask-pole = el polo de aceleraciones de { $body }
ask-curvature = la curvatura de la trayectoria del punto { $point } de { $body }
ask-decompose = el movimiento del punto { $point } de { $body } como arrastre, relativo y Coriolis, referencia móvil { $frame }
ask-intrinsic = las aceleraciones tangencial y normal del punto { $point } de { $body }
ask-contact = el movimiento de los tres puntos coincidentes en el contacto { $joint }
ask-axis = el eje instantáneo de rotación y deslizamiento de { $body }
ask-velocity-point = la velocidad del punto { $point }
ask-velocity-rel-point = la velocidad del punto { $point } respecto de { $frame }
ask-acceleration-point = la aceleración del punto { $point }
ask-acceleration-rel-point = la aceleración del punto { $point } respecto de { $frame }
ask-curvature-point = la curvatura de la trayectoria del punto { $point }
ask-intrinsic-point = las aceleraciones tangencial y normal del punto { $point }
ask-other = pregunta { $n }

part-point = posición
part-center = centro
part-radius = radio
part-velocity = velocidad
part-acceleration = aceleración
part-drag = arrastre
part-relative = relativa
part-coriolis = Coriolis
part-total = total
part-direction = dirección
part-omega = velocidad angular
part-slide = velocidad de deslizamiento
part-speed = celeridad
part-tangential = tangencial
part-normal = normal
part-tangent = tangente unitaria
part-tangential_vector = vector aceleración tangencial
part-normal_vector = vector aceleración normal
part-geometric = punto de contacto geométrico
part-pole = polo
part-diameter = diámetro de la circunferencia de inflexiones
part-inflection_pole = polo de inflexiones
part-pole_tangent = tangente polar
part-pole_normal = normal polar
part-pole_velocity = velocidad del polo
part-of-body = punto de { $body }
ask-inflection = la circunferencia de inflexiones y la tangente polar de { $body }

sheet-title = Ejercicio
sheet-student = Estudiante
sheet-name = Nombre
sheet-variant = Variante { $n }
sheet-find = Calcule
sheet-answer = respuesta
key-title = Solucionario
key-values = Respuestas
key-solution = Resolución paso a paso
key-question = pregunta
key-value = valor
key-margin = correcto dentro de ±

feedback-right = Correcto.
feedback-wrong = No es correcto: vea la resolución paso a paso.
mistake-coriolis-omitted = Este es el valor que se obtiene omitiendo el término de Coriolis 2 ω × v_rel.
mistake-coriolis-doubled = Este es el valor que se obtiene contando dos veces el término de Coriolis.
mistake-normal-omitted = Este es el valor que se obtiene omitiendo los términos normales (centrípetos) ω² r.
mistake-sense-reversed = Este es el valor que se obtiene invirtiendo el sentido de una ω o una α dadas.
mistake-drag-as-absolute = Este es el movimiento del punto coincidente de la guía (el arrastre), no el del propio punto.
mistake-degrees-as-radians = Este es el valor que se obtiene tomando como radianes un ángulo dado en grados.
mistake-units-mm-as-m = Este es el valor que se obtiene tomando como metros los milímetros de los datos.
mistake-components-swapped = Las componentes están intercambiadas.
feedback-unit = El número es correcto en { $unit }; la casilla pide { $asked }.
mistake-wrong-unit = La unidad no es de esta magnitud (la casilla pide la suya).
mistake-wrong-variant = No es una pregunta de tu variante: responde a la variante que te ha tocado.
feedback-carried = Se sigue de tu respuesta anterior a { $question }: se da por buena.

page-check = Comprobar
page-show = Ver la resolución paso a paso
page-your-answer = su respuesta
page-link = Enlace a este ejercicio
page-score = { $right } de { $total } correctas

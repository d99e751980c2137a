## Mensajes en castellano de `kinematika explain` (términos del curso: velocidad,
## aceleración, arrastre, relativa, CIR). Conservar los marcadores entre llaves.

sec-data = Datos
data-numeric = Unidades: longitudes en { $unit }, { $accelerations ->
        [0] velocidades en { $unit }/s y velocidades angulares en rad/s.
       *[other] velocidades en { $unit }/s, aceleraciones en { $unit }/s², velocidades angulares en rad/s y aceleraciones angulares en rad/s².
    }
data-planar = Movimiento plano: las velocidades{ $accelerations ->
        [0] {" "}angulares
       *[other] {" "}y aceleraciones angulares
    } llevan signo, positivas en sentido antihorario.
data-relative = La notación de una magnitud relativa indica los dos sólidos: { $v } es la velocidad del punto { $point } de { $body_b } vista desde { $body_a }{ WORD($rate) ->
        [yes] , y { $w } la velocidad angular de { $body_b } respecto de { $body_a }.
       *[no] .
    }
data-spatial = Las velocidades y aceleraciones angulares son vectores (regla de la mano derecha alrededor de su dirección).
data-symbolic = Los datos son símbolos, y cada resultado es una fórmula exacta en función de ellos. Las figuras se dibujan con valores de muestra de los símbolos, indicados bajo cada figura.
data-symbol = un símbolo (cualquier valor)
data-constructed = situado por construcción (véase Posición)
data-circles = centro { $centre }, radios { $radii }
data-circle = centro { $centre }, radio { $radius }
data-line = por { $through }, dirección { $direction }
data-plane = por { $through }, normal { $direction }
col-symbol = símbolo
col-value = valor
col-position = posición
col-shape = forma
col-given = datos
sec-structure = Estructura
col-body = sólido
col-points = puntos
col-joint = par
col-bodies = sólidos
col-where = dónde
col-omega = velocidad angular
col-alpha = aceleración angular
col-question = pregunta
col-answer = respuesta
structure-subscripts = Notación: { $pairs }.
rate-precession = la precesión
structure-subscript_pair = { $sym } es la velocidad angular de { $body }
# a relative rate the model's notation writes otherwise (C5-2.1's δ̇ for ω_{fork rel chassis}): defined where the notation line is (twenty-eighth round d)
structure-subscript_noted_rel = { $sym } es la velocidad angular de { $body } respecto de { $other }
structure-subscript_drag = { $equal } es la { WORD($kind) ->
        [accel] aceleración
       *[speed] velocidad
    } de arrastre de { $point }
structure-subscript_member = { $sym } es la velocidad del punto de { $body } situado en { $point }
structure-subscript_rel = { $sym } es la { WORD($kind) ->
        [rate2] aceleración angular de { $body }
        [speed] velocidad del punto { $point } de { $body }
        [accel] aceleración del punto { $point } de { $body }
       *[rate] velocidad angular de { $body }
    } respecto de { $other } (dos nombres unidos por «rel»: el primer sólido respecto del segundo)
structure-shaped = { $body }, { $shape } de radio { $radius }
# a body with several round shapes: its welded wheels, said once (twenty-ninth round b)
structure-shaped_welded = { $body }, { $n ->
        [2] dos
       *[other] { $n }
    } ruedas solidarias de radios { $radii }
# the fixed body with no shape: its own name, marked fixed; the text names it so wherever it is a reference (twenty-seventh round e)
structure-frame_named = { $body } ({ GENDER($body) ->
        [f] fija
       *[m] fijo
    })
structure-welded = { $bodies } { COUNT($bodies) ->
        [many] están { GENDER($bodies) ->
            [f] fijadas
           *[m] fijados
        } a { $frame }: forman parte de él y no se mueven
       *[one] { $bodies_n ->
            [one] está { GENDER($bodies) ->
                [f] fijada
               *[m] fijado
            } a { $frame }: forma parte de él y no se mueve
           *[other] están fijados a { $frame }: forman parte de él y no se mueven
        }
    }; todos sus puntos tienen velocidad y aceleración nulas.
structure-contacts_wheel = { $points_n ->
        [one] punto de contacto bajo { $points }
       *[other] puntos de contacto bajo { $points }
    }
structure-contacts_rolling = { $points_n ->
        [one] punto de contacto { $points }
       *[other] puntos de contacto { $points }
    }
# the frame's row names the parts welded to it: they are the frame (twenty-ninth round b)
structure-frame_parts = { $body }, con { $parts }
structure-fixed_part = { $body } (fijo a { $frame })
structure-dof = El mecanismo tiene { $dof ->
        [one] un grado
        [2] dos grados
        [3] tres grados
       *[other] { $dof } grados
    } de libertad.
structure-dof_data = El mecanismo tiene { $dof ->
        [one] un grado
        [2] dos grados
        [3] tres grados
       *[other] { $dof } grados
    } de libertad, uno por cada dato ({ $data }).
shape-concentric = { $n ->
        [2] dos circunferencias concéntricas
       *[other] { $n } circunferencias concéntricas
    }
shape-circle = circunferencia
shape-line = recta
shape-disc = disco
shape-plane = plano
joint-revolute = par de rotación (R)
joint-prismatic = par prismático (P)
joint-revolute_word = articulación
joint-prismatic_word = par prismático
joint-slot = pasador en ranura
joint-slot_fixed = contacto con deslizamiento sobre una recta fija
joint-wheel = rueda (sin deslizamiento lateral)
joint-rolling = rodadura
joint-gear = engranaje
joint-weld = sólidos solidarios
joint-spherical = par esférico
joint-cylindrical = par cilíndrico
along-joint = { WORD($verb) ->
        [only] a lo largo de { $dir }
        [rolls] la rueda en { $point } rueda a lo largo de { $dir }
       *[slides] { $point } desliza a lo largo de { $dir }
    }
along-horizontal = una recta horizontal
along-vertical = una recta vertical
along-angle = { $vec }, a { $deg }° de la horizontal
along-vector = { $vec }
along-line = { $line }
fig-arrow-velocity = la velocidad de { $point }
fig-arrow-drag = la velocidad de arrastre ({ $sym })
fig-arrow-relative = la velocidad relativa ({ $sym })
fig-own_drag = la velocidad de { $point } y su velocidad de arrastre ({ $sym })
fig-rest = ; { $count ->
        [one] { $points } tiene velocidad nula en este instante{ $centre }, escrita a su lado
       *[other] { $points } tienen velocidad nula en este instante, escrita a su lado
    }
fig-contact = Los tres puntos que coinciden en el contacto { $point } en este instante, sobre el mecanismo a escala: el punto de { $a }, el punto de { $b } y el punto geométrico de contacto { $geom }. { $moving ->
        [0] {""}
        [one] { $format ->
            [md] La flecha
           *[other] La flecha { $accel ->
                [0] azul
               *[other] roja
            }
        } es { $arrows }{ $moduli ->
            [0] {""}
            [2] {", con su módulo, en "}{ $unit }
           *[other] {", con su módulo"}
        }
       *[other] { $format ->
            [md] Las flechas
           *[other] Las flechas { $accel ->
                [0] azules
               *[other] rojas
            }
        } son { $arrows }, a una misma escala{ $moduli ->
            [0] {""}
            [2] {", con sus módulos, en "}{ $unit }
           *[other] {", con sus módulos"}
        }
    }{ $still ->
        [0] .
        [one] { $moving ->
            [0] {""}
           *[other] {"; "}
        }{ $zeros } es nula, escrita junto a { $point }.
       *[other] { $moving ->
            [0] {""}
           *[other] {"; "}
        }{ $zeros } son nulas, escritas junto a { $point }.
    }
fig-mechanism = El mecanismo en este instante, a escala{ $dim ->
        [3] , en proyección isométrica (los ejes x, y, z abajo a la derecha)
       *[other] {""}
    }; { $arrows ->
        [0] no se dibuja ninguna velocidad
        [1] { $format ->
            [md] la flecha
           *[other] la flecha azul
        } es la velocidad de { $points }{ $moduli ->
            [0] {""}
            [2] {", con su módulo, en "}{ $unit }/s
           *[other] {", con su módulo"}
        }
        [3] { $points } tiene velocidad nula en este instante{ $centre }, escrita a su lado
        [4] { $format ->
            [md] las flechas
           *[other] las flechas azules
        } son { $points }, a una misma escala{ $moduli ->
            [0] {""}
            [2] {", con sus módulos, en "}{ $unit }/s
           *[other] {", con sus módulos"}
        }
       *[other] { $format ->
            [md] las flechas
           *[other] las flechas azules
        } son las velocidades de { $points }, a una misma escala{ $moduli ->
            [0] {""}
            [2] {", con sus módulos, en "}{ $unit }/s
           *[other] {", con sus módulos"}
        }
    }{ $rest }; los sólidos están numerados.
fig-rest_centre = {" "}(es el CIR de { $body })
fig-mechanism_named = El mecanismo en este instante, a escala{ $dim ->
        [3] , en proyección isométrica (los ejes x, y, z abajo a la derecha)
       *[other] {""}
    }; { $arrows ->
        [0] no se dibuja ninguna velocidad
        [1] { $format ->
            [md] la flecha
           *[other] la flecha azul
        } es la velocidad de { $points }{ $moduli ->
            [0] {""}
            [2] {", con su módulo, en "}{ $unit }/s
           *[other] {", con su módulo"}
        }
        [3] { $points } tiene velocidad nula en este instante{ $centre }, escrita a su lado
        [4] { $format ->
            [md] las flechas
           *[other] las flechas azules
        } son { $points }, a una misma escala{ $moduli ->
            [0] {""}
            [2] {", con sus módulos, en "}{ $unit }/s
           *[other] {", con sus módulos"}
        }
       *[other] { $format ->
            [md] las flechas
           *[other] las flechas azules
        } son las velocidades de { $points }, a una misma escala{ $moduli ->
            [0] {""}
            [2] {", con sus módulos, en "}{ $unit }/s
           *[other] {", con sus módulos"}
        }
    }{ $rest }.
fig-at_pole = { $count ->
    [one] { $images } está en el polo o, ya que { $zero }.
   *[other] { $images } están en el polo o, ya que { $zero }.
}
fig-moved_aside = Un término que quedaría sobre otra flecha se dibuja a su lado, paralelo y a escala; { $format ->
        [md] unas líneas discontinuas unen
       *[other] unos trazos grises unen
    } sus extremos con los puntos entre los que va.
fig-too_short = { $count ->
    [one] { $terms } es demasiado corto para verse a esta escala (más corto que una punta de flecha); su valor está en el texto.
   *[other] { $terms } son demasiado cortos para verse a esta escala (más cortos que una punta de flecha); sus valores están en el texto.
}
fig-o_prime = La imagen de O se designa o′, porque la letra o designa el polo.
fig-o_prime_named = o′, la imagen de O,
fig-o_prime_fixed = o′, la imagen del punto fijo O de { $body },
fig-centre_image = { $count ->
    [one] la imagen del CIR { $centre }
   *[other] las imágenes de los CIR { $centre }
}
fig-primed = La imagen del punto { $point } es { $image } ({ $symbol }: { $what }).
fig-a_symbol = un dato
fig-polygon_v = Polígono de velocidades, a escala. Desde el polo o, sus términos se dibujan uno tras otro{ $result ->
        [1] {" "}y su suma, { $sym }, lo cierra
       *[other] {""}
    }{ $format ->
        [md] {""}
       *[other] {" "}(en negro los términos conocidos{ $unknown ->
            [1] , en rojo los hallados en este paso
           *[other] {""}
        }{ $result ->
            [1] , en azul la suma
           *[other] {""}
        })
    }. Cada vértice es la imagen de un punto.
fig-polygon_a = Polígono de aceleraciones, a escala. Desde el polo o, sus términos se dibujan uno tras otro{ $result ->
        [1] {" "}y su suma, { $sym }, lo cierra
       *[other] {""}
    }{ $format ->
        [md] {""}
       *[other] {" "}(en negro los términos conocidos{ $unknown ->
            [1] , en rojo los hallados en este paso
           *[other] {""}
        }{ $result ->
            [1] , en azul la suma
           *[other] {""}
        })
    }. Cada vértice es la imagen de un punto.
fig-sample = Dibujado con valores de muestra de los símbolos.
sec-position = Posición
pos-intro = Análisis de posición: cada punto móvil se sitúa como lo sitúa el enunciado, a partir de puntos ya situados.
pos-named = Aquí { $name } = { $formula }.
pos-moved = El mecanismo se analiza donde lo lleva el movimiento pedido, cada sólido llevado desde el dibujo como sigue.
pos-turn_angle = { $body } ha girado { $angle } alrededor de { $pivot }.
pos-turn_toward = { $body } ha girado como la recta { $line }.
pos-turn_shift = { $body } se ha desplazado { $shift } a lo largo de su guía.
pos-carried = { $point } se mueve con { $body }: { $point } = { $at }.
pos-polar = { $point } está a una distancia { $distance } de { $origin }, a { $angle } del eje x: { $point } = { $at }.
pos-polar_ref = { $point } está a una distancia { $distance } de { $origin }, a { $angle } de la dirección { $ref }: { $point } = { $at }.
pos-frame = { $point } está a una distancia { $x } de { $origin } según { $line } y a una distancia { $y } en perpendicular, a la izquierda mirando desde { $from } hacia { $to }: { $point } = { $at }.
pos-frame_right = { $point } está a una distancia { $x } de { $origin } según { $line } y a una distancia { $y } en perpendicular, a la derecha mirando desde { $from } hacia { $to }: { $point } = { $at }.
pos-frame_on = { $point } está a una distancia { $x } de { $origin } según { $line }: { $point } = { $at }.
pos-circles = { $point } está a una distancia { $r1 } de { $c1 } y { $r2 } de { $c2 }: la intersección de dos circunferencias, de centros { $c1 } y { $c2 }. De los dos puntos en que se cortan, es { $which }: { $point } = { $at }.
pos-circle_line = { $point } está a una distancia { $r } de { $c } sobre la recta { $line }: la intersección de una circunferencia de centro { $c } y una recta. De los dos puntos en que se cortan, es { $which }: { $point } = { $at }.
pos-lines = { $point } es el punto en que se cortan las rectas { $l1 } y { $l2 }: { $point } = { $at }.
pos-line_dir = por { $through } según { $dir }
pos-left = el que queda a la izquierda mirando desde { $a } hacia { $b }
pos-right = el que queda a la derecha mirando desde { $a } hacia { $b }
pos-upper = el de arriba
pos-lower = el de abajo
pos-leftmost = el de la izquierda
pos-rightmost = el de la derecha
pos-ahead = el que está más adelante en el sentido de la recta { $line }
pos-behind = el que está más atrás en el sentido de la recta { $line }
pos-near = el más cercano al punto del croquis { $near }
pos-touch = el único punto en que se tocan
pos-assembly = { $which }, { $assembly }
pos-open = la configuración abierta (las barras no se cruzan)
pos-crossed = la configuración cruzada (las barras se cruzan)

sec-order = Orden de resolución
order-assur = El mecanismo se descompone en sus entradas y díadas; cada una se resuelve a partir de sólidos ya conocidos:
order-blocks = Los sólidos se hallan en este orden, cada uno a partir de sólidos ya conocidos:
order-item = { $n }. { $kind }: { $bodies }, a partir { $known }.
order-item_group = { $n }. { $bodies }, a partir { $known }.
order-item_through = { $n }. { $kind }: { $bodies }, a partir { $known }, a través { $through }.
order-item_group_through = { $n }. { $bodies }, a partir { $known }, a través { $through }.
order-item_data = { $n }. { $kind }: { $bodies }, a partir de los datos.
order-item_group_data = { $n }. { $bodies }, a partir de los datos.
order-from = de { $name }
kind-input = entrada (sólido motor)
kind-RRR = díada RRR
kind-RRP = díada RRP
kind-RPR = díada RPR
kind-PRP = díada PRP
kind-other = grupo resuelto en conjunto
step-title = Paso { $n }: { $kind } — { $bodies }
step-title_group = Paso { $n }: { $bodies }
sec-velocities = Velocidades
sec-accelerations = Aceleraciones
v-intro = Cada ecuación vectorial se anota como en los apuntes: M: módulo conocido; D: dirección conocida; ?: desconocido; ⊥ y ∥ dan una dirección conocida.{ $marks ->
        [1] { WORD($clash) ->
            [M] {" "}Aquí M indica un módulo conocido; no es el punto M.
           *[other] {" "}Aquí D indica una dirección conocida; no es el punto D.
        }
        [2] {" "}Aquí M y D son estas marcas; no son los puntos M y D.
       *[other] {""}
    } Cada ecuación vectorial plana permite hallar dos incógnitas{ $format ->
        [md] : los términos marcados con ?
       *[other] ; en rojo, los términos que se hallan en cada paso
    }.
a-intro = Una vez halladas las velocidades, todos los términos normales y de Coriolis son conocidos; las incógnitas son los términos tangenciales y relativos.
a-intro_relative = Una vez halladas las velocidades, todos los términos normales son conocidos; las incógnitas son los términos tangenciales y relativos.
a-intro_normal = Una vez halladas las velocidades, los términos normales son conocidos; las incógnitas son los términos tangenciales.
eq-shared_rate = Los términos { $terms } tienen una sola incógnita, { $rate }: sus módulos son { $mags }, y sus dos ? cuentan como una.
a-named = Donde una fórmula desarrollada sería ilegible, las velocidades angulares halladas en «{ sec-velocities }» se escriben por su nombre: { $name } para la ω de { $body }, y así para cada sólido.
driver-omega = Dato: { $sym } = { $value }.
driver-omega_sense = Dato: { $sym } = { $value }, { $faster ->
        [1] en el sentido de { $w }: { $body } { COUNT($body) ->
            [many] se aceleran
           *[one] se acelera
        }
       *[other] en sentido contrario a { $w }: { $body } { COUNT($body) ->
            [many] se frenan
           *[one] se frena
        }
    }.
# a point given no acceleration: said as the notes say it, it moves at constant velocity (twenty-ninth round a)
driver-steady = Dato: { $point } se mueve con velocidad constante ({ $sym } = 0).
# a body given no angular acceleration: it turns at a constant rate (twenty-ninth round a)
driver-omega_steady = Dato: { $body } { COUNT($body) ->
        [many] giran
       *[one] gira
    } con velocidad angular constante ({ $sym } = 0).
driver-velocity = Dato: { $sym } = { $value }.
driver-along = Dato: la componente de { $sym } según { $along } es { $value }.
driver-whole = Dato: { $sym } = { $value }, { $heading }.
driver-held = En este instante { $b } no { COUNT($b) ->
        [many] giran
       *[one] gira
    } respecto de { $a } en la articulación { $point }: { $sym } = 0.
driver-held_accel = La articulación { $point } no tiene aceleración angular relativa en este instante: { $sym } = 0.
heading-right = hacia la derecha
heading-left = hacia la izquierda
heading-up = hacia arriba
heading-down = hacia abajo
heading-along = según { $along }
readoff-along_x = según x:
readoff-along_y = según y:
input-revolute = { $body } { COUNT($body) ->
        [many] giran
       *[one] gira
    } alrededor del punto fijo { $point }: sus puntos describen circunferencias centradas en { $point }.
input-prismatic = { $body } { COUNT($body) ->
        [many] se trasladan
       *[one] se traslada
    } sin girar a lo largo de su guía.
other-intro = Estos sólidos se hallan a la vez a partir de las condiciones de sus pares:
cond-revolute = par de rotación en { $point }: { $point } es un punto de { $a } y de { $b }.
cond-prismatic = par prismático: { $b } { COUNT($b) ->
        [many] se deslizan
       *[one] se desliza
    } sobre { $a } sin girar respecto de él.
cond-slot = pasador { $point } en ranura: su velocidad relativa al sólido ranurado sigue la ranura.
cond-slot_fixed = el punto { $point } de { $b } desliza a lo largo de una recta fija a { $a }: su velocidad sigue esa recta.
cond-wheel = rueda en { $point }: sin velocidad lateral respecto de { $a }.
cond-weld = { $a } y { $b } se mueven como un solo sólido.
cond-spherical = par esférico en { $point }: { $point } es un punto de { $a } y de { $b }.
cond-cylindrical = par cilíndrico: { $b } { COUNT($b) ->
        [many] giran
       *[one] gira
    } alrededor del eje de { $a } y se desliza a lo largo de él.
# every body, a wheel too, "rueda sin deslizar" (the textbook's verb; plural "ruedan"): the
# readers of round 20 asked for "la rueda rueda sin deslizar" over round 15a's "gira"
rolling-noslip = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] engranan
               *[one] engrana
            } con { $a }
       *[other] { $b } { COUNT($b) ->
                [many] ruedan
               *[one] rueda
            } sin deslizar sobre { $a }
    }: en el contacto { $point } los dos puntos materiales tienen la misma velocidad.
rolling-noslip_edge = { $b } no { COUNT($b) ->
        [many] deslizan
       *[one] desliza
    } sobre { $a }: en el contacto { $point } los dos puntos materiales tienen la misma velocidad.
rolling-same_edge = { $b } no { COUNT($b) ->
        [many] deslizan
       *[one] desliza
    } sobre { $a }: en el contacto { $point } los dos puntos materiales tienen la misma velocidad, { $sym } = { $other }.
rolling-glide = { $b } { COUNT($b) ->
            [many] ruedan
           *[one] rueda
        } sin deslizar sobre el borde de { $a }. Visto desde { $a }, su centro { $centre } mantiene la distancia al borde: se mueve según una recta paralela a la tangente en { $point }. Con ejes en { $centre } que giran con { $a }, el movimiento de { $centre } es el de arrastre (el del punto de { $a } que coincide con él) más el relativo, a lo largo de esa recta (y, en aceleraciones, el término de Coriolis).
rolling-kept = el contacto se mantiene: en { $point } las aceleraciones de los puntos materiales de { $b } y de { $a } solo difieren en un término según la normal común; no hay término de Coriolis, porque en un contacto de rodadura los dos puntos no tienen velocidad relativa: { $vrel } = 0.
path-circle = { $b } { COUNT($b) ->
            [many] ruedan
           *[one] rueda
        } sin deslizar sobre { $a }, que no se mueve. Su centro { $centre } mantiene la distancia a { $a }: describe la circunferencia de radio { $radius } centrada en { $o }, así que { $ac } tiene una componente normal { $vs }² / { $radius } hacia { $o }; y como { $vc } = { $w } × { $arm } en todo instante (el contacto { $point } es el CIR), su componente tangencial es { $al } × { $arm }.
path-found = { $b } { COUNT($b) ->
            [many] ruedan
           *[one] rueda
        } sin deslizar sobre { $a }, que no se mueve. { $ac }, hallada en el paso { $step }, tiene una componente normal { $vs }² / { $radius } hacia { $o } y una tangencial, que es { $al } × { $arm }, ya que { $vc } = { $w } × { $arm } en todo instante (el contacto { $point } es el CIR).
path-line = { $b } { COUNT($b) ->
            [many] ruedan
           *[one] rueda
        } sin deslizar sobre { $a }, que no se mueve. Su centro { $centre } mantiene la distancia a { $a }: describe una recta, sin aceleración normal; y como { $vc } = { $w } × { $arm } en todo instante (el contacto { $point } es el CIR), su aceleración es solo su componente tangencial: { $ac } = { $at } = { $al } × { $arm }.
rolling-equal = Sin deslizamiento en el contacto { $point }: { $sym } = { $other }.
rolling-same = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] engranan
               *[one] engrana
            } con { $a }
       *[other] { $b } { COUNT($b) ->
                [many] ruedan
               *[one] rueda
            } sin deslizar sobre { $a }
    }: en el contacto { $point } los dos puntos materiales tienen la misma velocidad, { $sym } = { $other }.
rolling-centre = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] engranan
               *[one] engrana
            } con { $a }
       *[other] { $b } { COUNT($b) ->
                [many] ruedan
               *[one] rueda
            } sin deslizar sobre { $a }
    }, que no se mueve: el punto { $point } de { $b } en el contacto no tiene velocidad, { $sym } = 0, así que es el CIR de { $b }.
dir-guide = guía de { $holder }
dir-normal_at = normal en { $point }
how-prismatic = (par prismático: sin rotación relativa)
carry-anchor = De la resolución del grupo: { $sym } = { $value }.
sense-ccw = antihorario
sense-cw = horario
sec-rates_summary = Velocidades y aceleraciones angulares
sec-rates_summary_v = Velocidades angulares
sec-centres = Centros instantáneos de rotación (CIR)
centres-intro = El símbolo I, con los números de dos sólidos ({ $example }: sólidos 1 y 3), designa el CIR de su movimiento relativo: el punto donde la velocidad relativa es nula.
centres-intro_named = El símbolo I, con el nombre de un sólido ({ $pair }), designa el CIR de { $body } respecto de { $frame }: el punto donde la velocidad relativa es nula.
centres-intro_named_rel = El símbolo I, con el nombre de un sólido ({ $pair }), designa el CIR de { $body } respecto de { $frame }, y, con dos nombres unidos por «rel», el del primero respecto del segundo: el punto donde la velocidad relativa es nula.
centre-line = { $centre }: { $why } { $where }
centre-joint-revolute = el eje de la articulación { $joint },
# a pin to the fixed body: a permanent centre; a strand's, where it is tied (twenty-ninth round b)
centre-joint-revolute_fixed = el eje de la articulación fija { $joint }, un centro permanente,
centre-joint-revolute_tied = el punto { $joint }, donde { $body } está atado a { $frame }, un centro permanente,
centre-joint-rolling = el punto de contacto { $joint } (rodadura sin deslizamiento),
centre-joint-gear = el contacto { $joint } de las circunferencias primitivas,
centre-joint-prismatic = el par es prismático: el movimiento relativo es una traslación y el CIR está en la perpendicular a la guía,
centre-joint-weld = los dos sólidos son solidarios:
centre-kennedy = por Aronhold–Kennedy está en la recta que pasa por { $l1 } (tercer sólido { $k1 }) y en la recta que pasa por { $l2 } (tercer sólido { $k2 }); estas rectas { $far ->
        [1] son paralelas, así que
       *[other] se cortan
    }
centre-velocities = las velocidades respecto de { $frame } de { $p }, { $vp }, y de { $q }, { $vq }, son perpendiculares a las rectas que los unen con el CIR; las perpendiculares se cortan
centre-lines = está en { $first } y en { $second }; estas rectas { $far ->
        [1] son paralelas, así que
       *[other] se cortan
    }
centre-omega = con las velocidades halladas en «{ sec-velocities }», la velocidad angular respecto de { $frame } es nula: el movimiento relativo es una traslación y el CIR está
centre-at = en { $point }.
centre-infinity = { $body } se traslada respecto de { $frame } ({ $w } = 0): todos sus puntos tienen la velocidad { $v }; su CIR está en el infinito, en la dirección perpendicular a { $v }.
centre-infinity_one = { $body } se traslada respecto de { $frame } ({ $w } = 0): todos sus puntos tienen la misma velocidad; su CIR está en el infinito, en la dirección perpendicular a esa velocidad, { $direction }.
centre-rest = no hay movimiento relativo.
sec-rates = Velocidades y aceleraciones angulares
rates-intro = Cada sólido gira respecto del sólido que lo lleva: { $w }, y, derivando en los ejes fijos, { $a }.
rates-intro_v = Cada sólido gira respecto del sólido que lo lleva: { $w }.
fields-intro_v = La velocidad de cada punto, a partir de un punto del mismo sólido ya conocido (su par):
fields-intro_a = La aceleración de cada punto, a partir de un punto del mismo sólido ya conocido (su par):
sec-composition = Composición de movimientos
composition-intro = El movimiento de un punto es el de arrastre (el del punto de la referencia móvil que coincide con él) más el relativo a esa referencia, más, en aceleraciones, el término de Coriolis { $cor }.
composition-point = Punto { $point } de { $body }, referencia móvil { $frame }:
composition-drag = { WORD($kind) ->
        [accel] { sec-accelerations }
       *[speed] { sec-velocities }
    }. Arrastre:
composition-relative = Relativo: { $sym }, el movimiento visto desde la referencia móvil, { $frame }:
composition-rolls = { $body } { COUNT($body) ->
            [many] ruedan
           *[one] rueda
        } sin deslizar sobre { $frame } en { $point }: visto desde { $frame }, { $point } es el CIR de { $body }, { $sym } = 0, y todos sus puntos giran alrededor de él.
sec-curvature = Curvatura de las trayectorias
curvature-intro = La aceleración se descompone en una parte tangencial, según la velocidad, y una normal, perpendicular a ella; el radio de curvatura es { $rho }.
curvature-point = Punto { $point }: velocidad { $v }.
curvature-rest = El punto { $point } tiene velocidad nula en este instante: su trayectoria no tiene ahí radio de curvatura (ℜ = |v|²/|aⁿ| necesita una velocidad).
curvature-straight = La aceleración normal de { $point } es nula: su trayectoria es recta aquí (o tiene un punto de inflexión).
curvature-circle = Punto { $point }: mantiene la distancia al punto fijo { $o }, así que su trayectoria es la circunferencia de radio { $radius } centrada en { $o }; el radio de curvatura es ese radio:
curvature-circle_centre = El centro de curvatura de la trayectoria de { $point } es { $o }, en { $centre }.
curvature-centre = El centro de curvatura de la trayectoria de { $point } está en { $centre }, del lado de la aceleración normal.
curvature-centre_from = El centro de curvatura de la trayectoria de { $point } está { $where }.
curvature-named = Con { $d } = { $arm } = { $length }, { $rho } = { $value }.
curvature-from = { WORD($side) ->
        [up] a { $rho } por encima de { $point }
        [down] a { $rho } por debajo de { $point }
        [left] a { $rho } a la izquierda de { $point }
        [right] a { $rho } a la derecha de { $point }
       *[other] a { $rho } de { $point }, según { $an }
    }
curvature-intrinsic = Con { $speed }, la tangente unitaria es { $tangent }; { $split }, con { $tangential }, y { $rest }, { $normal }:
sec-answers = Respuestas
answers-none = El modelo no hace preguntas.
ask-icr = CIR de { $body } respecto de { $frame }
ask-axis = eje instantáneo de rotación y deslizamiento de { $body } respecto de { $frame }
ask-pole = polo de aceleraciones de { $body } respecto de { $frame }
ask-inflection = circunferencia de inflexiones y tangente polar de { $body } respecto de { $frame }
ask-contact = los tres puntos coincidentes en el contacto { $joint }
ask-decompose = composición del movimiento de { $point }, referencia móvil { $frame }
ask-curvature = radio de curvatura de la trayectoria de { $point } respecto de { $frame }
ask-intrinsic = aceleración tangencial y normal de { $point } respecto de { $frame }
ans-rest = sin movimiento relativo
# an asked planar rate with its sense, as the notes ask it (“valor i sentit”: twenty-eighth round d)
ans-sensed = { $value } ({ $sense })
ans-point = posición
ans-from = distancia a { $point }
ans-direction = dirección
ans-center = centro de curvatura
ans-center_from = centro de curvatura { $where }
ans-tangent = tangente unitaria
ans-slide = velocidad a lo largo del eje
ans-translation = una traslación: sin circunferencia de inflexiones
ans-inflection_pole = centro instantáneo I
ans-inflection_center = centro de la circunferencia de inflexiones
ans-inflection_diameter = diámetro de la circunferencia de inflexiones
ans-inflection_point = polo de inflexiones (opuesto a I en la circunferencia)
ans-pole_tangent = tangente polar (unitaria, en el sentido en que se mueve I)
ans-pole_normal = normal polar (unitaria, de I al polo de inflexiones)
ans-pole_velocity = velocidad de I a lo largo de la base y la ruleta
centre-proportional-between = por Aronhold–Kennedy está en la recta que pasa por { $l1 } y en la que pasa por { $l2 }, pero son una misma recta y no lo fijan. En esa recta las velocidades respecto de { $frame } son perpendiculares a ella y proporcionales a la distancia al CIR: { $p } se mueve con { $vp } y { $q } con { $vq }, en sentidos opuestos, así que el CIR está entre ambos, donde la velocidad se anula:
centre-proportional-outside = por Aronhold–Kennedy está en la recta que pasa por { $l1 } y en la que pasa por { $l2 }, pero son una misma recta y no lo fijan. En esa recta las velocidades respecto de { $frame } son perpendiculares a ella y proporcionales a la distancia al CIR: { $p } se mueve con { $vp } y { $q } con { $vq }, en el mismo sentido, así que el CIR está más allá del más lento, donde la velocidad se anula:
composition-slide = { $point } desliza a lo largo de su guía: su movimiento relativo sigue la guía, { $sym } = { $value }.
composition-slide_seen = { $body } desliza a lo largo de { $frame } sin girar respecto de él, así que todos sus puntos, también { $point }, tienen la { WORD($kind) ->
        [accel] aceleración
       *[speed] velocidad
    } relativa hallada en «{ sec-velocities }»: { $sym } = { $value }.
composition-slide_seen_step = { $body } desliza a lo largo de { $frame } sin girar respecto de él, así que todos sus puntos, también { $point }, tienen la { WORD($kind) ->
        [accel] aceleración
       *[speed] velocidad
    } relativa hallada en el paso { $step }: { $sym } = { $value }.
composition-drag_seen = { $sym } = { $value }, la { WORD($kind) ->
        [accel] aceleración
       *[speed] velocidad
    } del punto de { $frame } que coincide con { $point }, hallada en el paso { $step }.
composition-drag_terms = { $sym } = { $terms } = { $value }: los primeros términos de la ecuación del paso { $step }.
composition-sum_seen = Así, { $sym } = { $terms } es la ecuación del paso { $step }, con la que { $seen_n ->
        [one] se halló
       *[other] se hallaron
    } { $seen }.
composition-reverse = { $sym } = −{ $back } = { $value }: la opuesta de la { WORD($kind) ->
        [accel] aceleración
       *[speed] velocidad
    } relativa hallada en el paso { $step }.
composition-reverse_rolling = Sin deslizamiento: { $vel } = 0, así que no hay término de Coriolis y { $sym } = −{ $back } = { $value }, la opuesta de la aceleración relativa hallada en el paso { $step }.
composition-pin = { $point } es una articulación, punto de ambos sólidos: no tiene movimiento relativo, { $sym } = 0.
vehicle-driven = La rueda { $joint } no desliza: { $point } no tiene velocidad perpendicular al plano de la rueda, así que su velocidad dada según el plano es toda su velocidad: { $sym } = { $value }.
vehicle-line-wheel = la perpendicular al plano de la rueda { $joint } por el punto { $point } (su eje: la rueda no desliza lateralmente)
vehicle-line-velocity = la perpendicular a { $sym } por el punto { $point }
vehicle-equiprojective = Por la propiedad de equiproyectividad ({ $q } y { $p } son puntos de { $body }), sus velocidades tienen la misma componente según { $seg }: { $vp } · { $seg }/|{ $seg }| = { $vq } · { $seg }/|{ $seg }|, con { $seg }/|{ $seg }| = { $unit }, de modo que { $vq } · { $seg }/|{ $seg }| = { $proj }. { $p } está en el eje de la rueda { $joint }, así que { $vp } tiene la dirección del plano de la rueda: { $vp } = |{ $vp }| e, con e = { $along } y e · { $seg }/|{ $seg }| = { $cos }. Por tanto, |{ $vp }| = ({ $proj }) / ({ $cos }) = { $speed }, y { $vp } = { $value }.
vehicle-equiprojective_along = Por la propiedad de equiproyectividad ({ $q } y { $p } son puntos de { $body }), sus velocidades tienen la misma componente según { $seg }: { $vp } · { $seg }/|{ $seg }| = { $vq } · { $seg }/|{ $seg }|, con { $seg }/|{ $seg }| = { $unit }, de modo que { $vq } · { $seg }/|{ $seg }| = { $proj }. { $p } está en el eje de la rueda { $joint }, así que { $vp } tiene la dirección del plano de la rueda, la recta { $seg }: { $vp } = |{ $vp }| { $seg }/|{ $seg }|. Por tanto, |{ $vp }| = { $speed }, y { $vp } = { $value }.
vehicle-line-wheel_own = la perpendicular al plano de la rueda { $joint } por el punto { $point } (su eje, que es también la perpendicular a { $sym } por { $witness }: la rueda no desliza lateralmente)
vehicle-pin_shared = { $point } es el pasador común a { $a } y { $b }: { $sym } = { $other }.
vehicle-pin_shared_one = { $point } es el pasador común a { $a } y { $b }: { $sym } es la velocidad de ambos.
vehicle-centre = El CIR de { $body } está en { $first } y en { $second }; se cortan en { $centre } = { $where }, que no tiene velocidad: { $rest } = 0. Cada punto de { $body } se mueve perpendicularmente a la recta que lo une con { $centre }, con celeridad proporcional a su distancia:
vehicle-translation = Las rectas de { $body } son paralelas, así que se traslada: todos sus puntos se mueven como { $point }.
vehicle-translation_equal = { $p } y { $q } tienen la misma velocidad, { $vp } = { $vq } = { $value }, así que { $body } se traslada: todos sus puntos tienen la velocidad { $value }.
vehicle-spin = La rueda { $joint } rueda sin deslizar (radio { $radius }): su centro { $point } se mueve en el plano de la rueda con celeridad { $product }, donde { $spin } es su rotación propia alrededor de su eje, de modo que:
triad-intro = { $body } está sujeto por tres barras binarias, { $links }: ninguna ecuación vectorial de un solo punto tiene solo dos incógnitas. Como hacen los textos para una tríada, se toma el punto de Assur { $point }, donde se cortan las rectas { $l1 } y { $l3 }, como punto de { $body }:
triad-collinear = En cada miembro los dos términos desconocidos son perpendiculares a una misma recta ({ $point } está en { $l1 } y en { $l3 }), así que cada miembro tiene un solo módulo desconocido: dos incógnitas, y el polígono se cierra.
triad-closure = Conocido { $point } como punto del eslabón ternario, su articulación { $pin } se cierra como en una díada:
loop-intro = Los sólidos { $bodies } cierran un lazo: al recorrerlo, las velocidades angulares relativas suman cero, cada una según el eje de su par (tres ecuaciones escalares para las velocidades { $rate } desconocidas según los ejes { $axis }):
loop-solve = Las tres componentes dan las velocidades desconocidas:
loop-solve_alpha = Derivando en los ejes fijos, las aceleraciones angulares relativas y los términos { $cross } suman cero a lo largo del lazo; las tres componentes dan las { $rate } desconocidas:
dir-axis = eje { $joint }
dir-wheel = rueda { $joint }
how-weld = (solidarios: un solo sólido rígido)
group-wheel_v = La rueda { $joint } no desliza lateralmente: la velocidad de { $point } está en el plano de la rueda.
group-wheel_a = La rueda { $joint } no desliza lateralmente en ningún instante y su plano gira con { $body }: la aceleración de { $point } tiene una parte tangencial en el plano y una normal perpendicular a él, { $w } × { $v }.
how-translation = (se traslada)
translation-same = { $body } no gira ({ $w } = 0{ $accel ->
        [1] , { $a } = 0
       *[other] {""}
    }): se traslada, y todos sus puntos tienen la misma { $accel ->
        [1] aceleración
       *[other] velocidad
    }:
translation-points = Todos los puntos de { $body } tienen la misma { $accel ->
        [1] aceleración
       *[other] velocidad
    }:
fig-centres = Los centros instantáneos (anillos, I con los números de dos sólidos) sobre el mecanismo{ $kennedy ->
        [0] { $normals_n ->
            [0] .
           *[other] , con las rectas en que se hallan (trazo y punto: { $normals }).
        }
       *[other] , con las rectas en que se hallan (trazo y punto: rectas que pasan por dos centros{ $normals_n ->
            [0] {""}
           *[other] {" "}y { $normals }
        }).
    }
fig-centres_named = Los centros instantáneos (anillos, I con los nombres de los sólidos) sobre el mecanismo{ $kennedy ->
        [0] { $normals_n ->
            [0] .
           *[other] , con las rectas en que se hallan (trazo y punto: { $normals }).
        }
       *[other] , con las rectas en que se hallan (trazo y punto: rectas que pasan por dos centros{ $normals_n ->
            [0] {""}
           *[other] {" "}y { $normals }
        }).
    }
fig-normal-wheel = las perpendiculares a las ruedas
fig-normal-slot = las normales a las ranuras
fig-normal-slot_fixed = las normales a las rectas por las que deslizan los puntos
fig-normal-normal = las normales comunes en los contactos
fig-normal-radius = las perpendiculares a las velocidades de los puntos
fig-assur = El punto de Assur { $point }: las rectas { $l1 } y { $l3 } (a trazos) prolongadas hasta cortarse; { $point } se toma como punto del eslabón ternario.
fig-drawn_at = Dibujado con { $values }.
fig-level_v = Polígono de velocidades, a escala: desde el polo o, la velocidad de cada punto{ $format ->
        [md] {""}
       *[other] {" "}(azul)
    } acaba en su imagen, con la letra del punto{ $image ->
        [0] {""}
       *[other] {" "}({ $image } para { $point })
    }{ $between ->
        [0] .
       *[other] ; entre las imágenes, las velocidades relativas de las ecuaciones { $span ->
            [1] del paso { $first }
            [2] de los pasos { $first } y { $last }
           *[other] de los pasos { $first } a { $last }
        }{ $format ->
            [md] {""}
           *[other] {" "}(negro)
        }, una tras otra.
    }
fig-level_a = Polígono de aceleraciones, a escala: desde el polo o, la aceleración de cada punto{ $format ->
        [md] {""}
       *[other] {" "}(azul)
    } acaba en su imagen, con la letra del punto{ $image ->
        [0] {""}
       *[other] {" "}({ $image } para { $point })
    }{ $between ->
        [0] .
       *[other] ; entre las imágenes, los términos de las ecuaciones { $span ->
            [1] del paso { $first }
            [2] de los pasos { $first } y { $last }
           *[other] de los pasos { $first } a { $last }
        } ({ $format ->
            [md] {""}
           *[other] negro:{" "}
        }normales y tangenciales, relativos y de Coriolis), uno tras otro.
    }
fig-level_a_relative = Polígono de aceleraciones, a escala: desde el polo o, la aceleración de cada punto{ $format ->
        [md] {""}
       *[other] {" "}(azul)
    } acaba en su imagen, con la letra del punto{ $image ->
        [0] {""}
       *[other] {" "}({ $image } para { $point })
    }{ $between ->
        [0] .
       *[other] ; entre las imágenes, los términos de las ecuaciones { $span ->
            [1] del paso { $first }
            [2] de los pasos { $first } y { $last }
           *[other] de los pasos { $first } a { $last }
        } ({ $format ->
            [md] {""}
           *[other] negro:{" "}
        }normales y tangenciales, y relativos), uno tras otro.
    }
fig-level_a_normal = Polígono de aceleraciones, a escala: desde el polo o, la aceleración de cada punto{ $format ->
        [md] {""}
       *[other] {" "}(azul)
    } acaba en su imagen, con la letra del punto{ $image ->
        [0] {""}
       *[other] {" "}({ $image } para { $point })
    }{ $between ->
        [0] .
       *[other] ; entre las imágenes, los términos de las ecuaciones { $span ->
            [1] del paso { $first }
            [2] de los pasos { $first } y { $last }
           *[other] de los pasos { $first } a { $last }
        } ({ $format ->
            [md] {""}
           *[other] negro:{" "}
        }normales y tangenciales), uno tras otro.
    }
col-number = n.º

# higher pairs (joints.contact, curved_slot, cam)
shape-curveshape = curva
shape-camshape = leva
joint-contact = contacto (par superior)
joint-curved_slot = pasador en ranura curva
joint-cam = leva y seguidor
cond-contact = contacto: { $a } y { $b } siguen en contacto; pueden deslizar según la tangente común.
cond-curved_slot = pasador { $point } en ranura curva: su velocidad relativa al sólido ranurado sigue la tangente de la ranura.
cond-cam = leva: el seguidor { $b } sigue en contacto con la leva { $a }.
dir-tangent = tangente en { $point }
dir-centre = hacia el centro de curvatura { $point }
higher-intro = El par superior se escribe como el movimiento de { $point } por su trayectoria relativa a { $holder } (una ranura según la tangente, curva de radio { $radius }): la aceleración relativa tiene una parte normal v²/ρ hacia el centro de curvatura de la trayectoria.
higher-straight = El par superior se escribe como el movimiento de { $point } por una trayectoria recta relativa a { $holder } (una ranura según la tangente).
centre-weld = { $body } y { $other } son solidarios: son un solo sólido rígido, así que el CIR es el de { $other }, { $same },
centre-line-kennedy = la recta que pasa por { $l } (Aronhold–Kennedy, tercer sólido { $k })
centre-line-moves = la perpendicular a { $v } por { $point } ({ $point } se mueve con { $body }, que { COUNT($body) ->
        [many] giran
       *[one] gira
    } alrededor de { $pivot })
centre-line-rolls = la perpendicular a { $v } por { $point } ({ $roller } no { COUNT($roller) ->
        [many] deslizan
       *[one] desliza
    } sobre { $on }, así que el punto { $point } de { $b } tiene la velocidad de { $body } en ese punto, y { $body } { COUNT($body) ->
        [many] giran
       *[one] gira
    } alrededor de { $pivot })
centre-line-rolls_still = la perpendicular a { $v } por { $point } ({ $roller } no { COUNT($roller) ->
        [many] deslizan
       *[one] desliza
    } sobre { $on }, así que el punto { $point } de { $b } tiene la velocidad de { $body }, que se { COUNT($body) ->
        [many] trasladan
       *[one] traslada
    })
centre-line-moves_still = la perpendicular a { $v } por { $point } ({ $point } se mueve con { $body }, que se { COUNT($body) ->
        [many] trasladan
       *[one] traslada
    })
centre-line-guide = la perpendicular a la guía por { $pivot } (en { $pivot }′, el pie de la perpendicular desde { $pivot } a la guía, la velocidad relativa a { $body } es paralela a la guía y la de arrastre es perpendicular a { $pivot }{ $pivot }′, es decir, también paralela a la guía: la velocidad del punto de { $b } en { $pivot }′ sigue la guía)
centre-carried-slip = {" "}({ $b } no { COUNT($b) ->
        [many] deslizan
       *[one] desliza
    } sobre { $body }, así que su punto { $point } tiene la velocidad de { $body } en ese punto)
centre-carried-between = { $p } se mueve con { $k1 } alrededor de { $c1 }{ $why1 }, y { $q } con { $k2 } alrededor de { $c2 }{ $why2 }: ambas velocidades respecto de { $frame } son perpendiculares a la recta que pasa por { $p } y { $q }, así que el CIR está en esa recta; en ella las velocidades son proporcionales a la distancia al CIR: { $p } se mueve con { $vp } y { $q } con { $vq }, en sentidos opuestos, así que el CIR está entre ambos, donde la velocidad se anula:
# the construction repeated for a body symmetric to one done: referred to (twenty-ninth round b)
centre-carried_as = como para { $first }, está en la recta que pasa por { $p } y { $q }, a { $dist } de { $near }:
centre-carried-between_from = { $p } se mueve con { $k1 } alrededor de { $c1 }{ $why1 }, y { $q } con { $k2 } alrededor de { $c2 }{ $why2 }: ambas velocidades respecto de { $frame } son perpendiculares a la recta que pasa por { $p } y { $q }, así que el CIR está en esa recta; en ella las velocidades son proporcionales a la distancia al CIR: { $p } se mueve con { $vp } y { $q } con { $vq }, en sentidos opuestos, así que el CIR está entre ambos, donde la velocidad se anula, a { $dist } de { $near }:
centre-carried-outside = { $p } se mueve con { $k1 } alrededor de { $c1 }{ $why1 }, y { $q } con { $k2 } alrededor de { $c2 }{ $why2 }: ambas velocidades respecto de { $frame } son perpendiculares a la recta que pasa por { $p } y { $q }, así que el CIR está en esa recta; en ella las velocidades son proporcionales a la distancia al CIR: { $p } se mueve con { $vp } y { $q } con { $vq }, en el mismo sentido, así que el CIR está más allá del más lento, donde la velocidad se anula:
centre-carried-outside_from = { $p } se mueve con { $k1 } alrededor de { $c1 }{ $why1 }, y { $q } con { $k2 } alrededor de { $c2 }{ $why2 }: ambas velocidades respecto de { $frame } son perpendiculares a la recta que pasa por { $p } y { $q }, así que el CIR está en esa recta; en ella las velocidades son proporcionales a la distancia al CIR: { $p } se mueve con { $vp } y { $q } con { $vq }, en el mismo sentido, así que el CIR está más allá del más lento, donde la velocidad se anula, a { $dist } de { $near }:
centre-line-slot = la normal en { $point } a la ranura (respecto del sólido ranurado, { $point } solo puede moverse a lo largo de la ranura)
centre-line-slot_fixed = la normal en { $point } a la recta de { $a } por la que desliza
centre-line-wheel = el eje de la rueda { $joint }, la normal en { $point } a su plano (no desliza lateralmente)
centre-field = está en la perpendicular a { $v } por { $q }, a la distancia { $arm } = |{ $v }| / |{ $w }| = { $dist } de { $q }, { $side }, de modo que el CIR está
centre-rate = a partir de { $w } (hallada en «{ sec-velocities }» a través de { $line }): está en la perpendicular a { $v } por { $q }, a la distancia { $arm } = |{ $v }| / |{ $w }| = { $dist } de { $q }, { $side }, así que el CIR está
centre-rate_step = a partir de { $w } (hallada en el paso { $step } a través de { $line }): está en la perpendicular a { $v } por { $q }, a la distancia { $arm } = |{ $v }| / |{ $w }| = { $dist } de { $q }, { $side }, así que el CIR está
# the side of a point a centre lies on, named (centre-field: below A, to the left of A)
side-above = por encima de { $q }
side-below = por debajo de { $q }
side-left = a la izquierda de { $q }
side-right = a la derecha de { $q }
side-above_left = por encima y a la izquierda de { $q }
side-above_right = por encima y a la derecha de { $q }
side-below_left = por debajo y a la izquierda de { $q }
side-below_right = por debajo y a la derecha de { $q }
centre-check = Comprobación con las velocidades halladas en «{ sec-velocities }»: en la perpendicular a { $v } por { $q }, a la distancia { $arm } = |{ $v }| / |{ $w }| = { $dist } de { $q }, { $side }, el mismo punto: { $centre } está { $where }
sec-centres_v = CIR hallados a partir de las velocidades
how-centre_infinity = (se traslada: su CIR { $centre } está en el infinito)
how-constant_rate = ({ $sym } = { $value } es constante: { $line } conserva su longitud, y su velocidad angular la fijan los radios y { $rates }, que es constante)
how-constant_speed = ({ $point } recorre la circunferencia de radio { $line } = { $length } centrada en { $centre } con la celeridad constante { $v } = { $speed }, así que { $sym } = { $value } es constante)
idle-rolling = { $body } { COUNT($body) ->
        [many] ruedan
       *[one] rueda
    } sin deslizar sobre { $fixed }: su punto de contacto { $point } es su CIR, de modo que:
idle-symmetry = { $body } tiene la misma disposición que { $like } (el mismo radio, los mismos enlaces con los mismos sólidos): por simetría gira igual:
idle-unused = { $bodies } no { $count ->
        [one] interviene
       *[other] intervienen
    } en la pregunta: ningún paso necesita { $count ->
        [one] su velocidad angular
       *[other] sus velocidades angulares
    }.
how-tangent = (se mantiene { WORD($way) ->
        [vertical] vertical
        [horizontal] horizontal
       *[other] paralelo a sí mismo
    }, tangente a { $a } y a { $b }: se traslada, y todos sus puntos tienen la misma velocidad)
how-glides = ({ $p } y { $q } se mueven siempre sobre la recta { $line }: el sólido se traslada a lo largo de ella, sin girar)
how-parallel_paths = ({ $p } y { $q } se mantienen siempre a una altura igual al radio de su rueda sobre el suelo plano, así que se mueven sobre rectas paralelas: el sólido se traslada, sin girar)
how-translates_always = (se traslada en todo instante, como se ha visto en las velocidades)
centres-found_above = { $centre } = { $value }: hallado en «{ sec-velocities }», en el paso de velocidades de { $body }.
centres-witness = de { $name }
centres-placed_in_step = { $centre }: hallado en el paso { $step }, a partir de las velocidades { $points }.
centres-found_above_step = { $centre }: hallado en el paso { $step }, con las velocidades de { $body }.
centre-site = { $point } es el CIR { $centre } de { $body } respecto de { $frame }, hallado en «{ sec-centres }»: { $sym } = 0.
centre-site_s = { $centre }, hallado en «{ sec-centres }», no tiene velocidad: { $sym } = 0.
centre-site_here = { $point } es el CIR { $centre } de { $body } respecto de { $frame }, hallado justo antes: { $sym } = 0.
centre-site_s_here = { $centre }, hallado justo antes, no tiene velocidad: { $sym } = 0.
sec-contact = Puntos de contacto
geom-rule = La regla de todo contacto de rodadura: la condición de no deslizamiento se cumple en cada instante en el punto geométrico de contacto (aquí { $geom }), que se mueve; derivándola a lo largo de él se obtiene { $rule }: las componentes tangenciales de las dos aceleraciones son iguales y las normales difieren en este término, según la normal común. Hace falta la velocidad del punto geométrico:
geom-bar = { $geom }, el punto geométrico de contacto, no pertenece a ninguno de los dos sólidos: está siempre en la recta de los centros { $c1 } y { $c2 }, con { $part }/{ $whole } = { $ratio }, y se mueve como un punto de una barra articulada en { $c1 } y { $c2 }:
geom-bar_told = { $geom }, el punto geométrico de contacto, está siempre en la recta de los centros { $c1 } y { $c2 }, con { $part }/{ $whole } = { $ratio }, y se mueve como un punto de una barra articulada en { $c1 } y { $c2 }:
geom-foot = { $geom }, el punto geométrico de contacto, es el pie de la perpendicular desde el centro { $centre } a la recta de { $line }: { $radius } es un radio, perpendicular a la recta, y gira con ella:
contact-intro = En el contacto { $point } coinciden tres puntos con cinemáticas diferentes: el punto de { $a }, el punto de { $b } y el punto geométrico de contacto { $geom }, que no pertenece a ninguno de los dos.
contact-above = { $sym } = { $value }, obtenida en «{ sec-accelerations }» para la aceleración del contacto.
contact-written_centre = { $sym } = { $value }, hallada en el paso { $step }: { $point } es el CIR de { $body }.
contact-written = { $sym } = { $value }, hallada en el paso { $step }.
contact-fixed = { $sym }: { $point } como punto de { $body }{ FIXED($body) ->
        [yes] {""}
       *[no] , que es fijo,
    } no se mueve: { $sym } = 0.
fig-step_v = Polígono de velocidades de este paso, a escala: desde el polo o, la velocidad de cada punto{ $format ->
        [md] {""}
       *[other] {" "}(azul)
    } acaba en su imagen, con la letra del punto{ $between ->
        [0] .
       *[other] ; entre las imágenes, los términos de las ecuaciones de este paso{ $format ->
            [md] {""}
           *[other] {" "}(negro)
        }, uno tras otro.
    }
fig-step_a = Polígono de aceleraciones de este paso, a escala: desde el polo o, la aceleración de cada punto{ $format ->
        [md] {""}
       *[other] {" "}(azul)
    } acaba en su imagen, con la letra del punto{ $between ->
        [0] .
       *[other] ; entre las imágenes, los términos de las ecuaciones de este paso{ $format ->
            [md] {""}
           *[other] {" "}(negro)
        }, uno tras otro.
    }
col-point = punto
col-what = qué es
what-centre = centro de { $body }
what-joint = { $kind } entre { $a } y { $b }
what-touching = el punto de { $body } donde toca { $other }
what-contact = punto de contacto ({ $kind }) entre { $a } y { $b }
what-body = un punto { $bodies }
what-of = de { $name }
note-text = Nota: { $text }
sec-checks = Comprobaciones
check-willis = Fórmula de Willis: vista desde { $carrier }, el tren es ordinario ({ $planet }, cuyo eje lleva { $carrier }, engrana con { $s1 } y { $s2 }, { $fixed ->
        [0] que giran alrededor del eje fijo que pasa por { $axis }
       *[other] cuyo eje es el eje fijo por { $axis }
    }), de modo que { $formula } = { $radii } = { $train }{ $r1 ->
        [0] {""}
       *[other] , con { $r1 } y { $r2 }
    }. Con las velocidades angulares halladas en «{ sec-velocities }», { $values } = { $ratio }: coinciden.
check-belt = Vista desde { $holder }, que lleva los dos ejes, { $line } no desliza sobre { $a } ni sobre { $b }: { $equation }, de modo que { $ratio }; con las velocidades angulares halladas en «{ sec-velocities }», { $values }: coinciden.
pair-relation_v = Vistos desde { $holder }, que lleva los dos ejes, los ejes están fijos: { $a } y { $b } giran alrededor de ellos y no deslizan entre sí, de modo que { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(con { $radii })
    }:
pair-relation = Vistos desde { $holder }, que lleva los dos ejes, los ejes están fijos: { $a } y { $b } giran alrededor de ellos y no deslizan entre sí, de modo que { $equation } en todo instante; derivando, con los radios constantes, { $derived }{ $radii ->
        [0] {""}
       *[other] {" "}(con { $radii })
    }:
drive-relation_a = Derivando, con los radios constantes: { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(con { $radii })
    }:
drive-relation = Vistos desde { $holder }, que lleva los dos ejes, los ejes están fijos y el tramo recto de { $line } se traslada: no desliza sobre { $a } ni sobre { $b }, así que sus periferias tienen la misma velocidad, { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(con { $radii })
    }:
check-train = La relación de la transmisión es el producto de las de sus etapas: { $ratio }; con las velocidades angulares halladas en «{ sec-velocities }», la relación vale { $value }.
check-quick = Razón de tiempos del retorno rápido: { $lever } está en un extremo de su oscilación cuando la ranura es tangente a la circunferencia de { $pin } (la manivela { $o2 }{ $pin } perpendicular a { $o4 }{ $pin }), donde cos θ = { $o2 }{ $pin } / { $o2 }{ $o4 } = { $r } / { $d }, θ = { $theta }. Girando uniformemente, { $crank } barre 360° − 2θ = { $slow } en una carrera y 2θ = { $fast } en la otra: razón de tiempos { $ratio }.
driver-slide = Dato: la velocidad de deslizamiento en el par prismático { $joint } es { $value }.
driver-slide_accel = Dato: la aceleración de deslizamiento en el par prismático { $joint } es { $value }.
centre-line-normal = la normal común en el contacto { $point } (los sólidos deslizan uno sobre otro: ninguna velocidad relativa según ella)
# un CIR a partir de dos velocidades paralelas y perpendiculares a la recta de sus puntos (la construcción proporcional de los apuntes)
centre-parallel-between = los puntos { $p } y { $q } de { $body } se mueven, respecto de { $frame }, con { $sp } = { $vp } y { $sq } = { $vq }, ambas perpendiculares a la recta que pasa por { $p } y { $q }. A lo largo de esa recta la velocidad varía linealmente, proporcional a la distancia al CIR, y estas dos tienen sentidos opuestos, así que el CIR está entre ambos, donde la velocidad se anula, a { $dist } de { $q }:
centre-parallel-outside = los puntos { $p } y { $q } de { $body } se mueven, respecto de { $frame }, con { $sp } = { $vp } y { $sq } = { $vq }, ambas perpendiculares a la recta que pasa por { $p } y { $q }. A lo largo de esa recta la velocidad varía linealmente, proporcional a la distancia al CIR, y estas dos tienen el mismo sentido, así que el CIR está más allá del más lento, donde la velocidad se anula, a { $dist } de { $q }:
# a normal acceleration: its magnitude, then the vector with its direction (never a magnitude = a vector)
term-magnitude = { $mag } = { $how }, hacia { $point }: { $sym } = { $value }

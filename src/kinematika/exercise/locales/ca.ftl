## Els exercicis de kinematika en català: enunciats, fulls, solucionari, la retroacció del
## qüestionari i el mode exercici de la pàgina. Deixeu les marques entre claus ({ $name })
## tal com són.

statement-default = El mecanisme de la figura està dibuixat en l’instant de l’anàlisi. Dades: { $data }.
units-note-planar = Doneu les longituds en { $unit }, les velocitats en { $unit }/s i les acceleracions en { $unit }/s², per les seves components x i y en els eixos de la figura; les velocitats angulars en rad/s i les acceleracions angulars en rad/s², positives en sentit antihorari.
units-note-spatial = Doneu les longituds en { $unit }, les velocitats en { $unit }/s i les acceleracions en { $unit }/s², per les seves components x, y i z; les velocitats angulars en rad/s i les acceleracions angulars en rad/s², com a vectors.

ask-omega = la velocitat angular { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-omega-rel = la velocitat angular { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-alpha = l’acceleració angular { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-alpha-rel = l’acceleració angular { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-velocity = la velocitat del punt { $point } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-velocity-rel = la velocitat del punt { $point } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-acceleration = l’acceleració del punt { $point } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-acceleration-rel = l’acceleració del punt { $point } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-icr = el centre instantani de rotació { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-icr-rel = el centre instantani de rotació { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-pole = el pol d’acceleracions { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-curvature = la curvatura de la trajectòria del punt { $point } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-decompose = el moviment del punt { $point } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } com a arrossegament, relatiu i Coriolis, referència mòbil { $frame }
ask-intrinsic = les acceleracions tangencial i normal del punt { $point } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-contact = el moviment dels tres punts coincidents al contacte { $joint }
ask-axis = l’eix instantani de rotació i lliscament { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-velocity-point = la velocitat del punt { $point }
ask-velocity-rel-point = la velocitat del punt { $point } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-acceleration-point = l’acceleració del punt { $point }
ask-acceleration-rel-point = l’acceleració del punt { $point } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-curvature-point = la curvatura de la trajectòria del punt { $point }
ask-intrinsic-point = les acceleracions tangencial i normal del punt { $point }
ask-other = pregunta { $n }

part-point = posició
part-center = centre
part-radius = radi
part-velocity = velocitat
part-acceleration = acceleració
part-drag = arrossegament
part-relative = relativa
part-coriolis = Coriolis
part-total = total
part-direction = direcció
part-omega = velocitat angular
part-slide = velocitat de lliscament
part-speed = celeritat
part-tangential = tangencial
part-normal = normal
part-tangent = tangent unitària
part-tangential_vector = vector acceleració tangencial
part-normal_vector = vector acceleració normal
part-geometric = punt de contacte geomètric
part-pole = pol
part-diameter = diàmetre de la circumferència d’inflexions
part-inflection_pole = pol d’inflexions
part-pole_tangent = tangent polar
part-pole_normal = normal polar
part-pole_velocity = velocitat del pol
part-of-body = punt { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
ask-inflection = la circumferència d’inflexions i la tangent polar { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }

sheet-title = Exercici
sheet-student = Estudiant
sheet-name = Nom
sheet-variant = Variant { $n }
sheet-find = Calculeu
sheet-answer = resposta
key-title = Solucionari
key-values = Respostes
key-solution = Resolució pas a pas
key-question = pregunta
key-value = valor
key-margin = correcte dins de ±
key-common = La resolució: la part comuna a totes les variants
key-see-common = Les parts de la resolució comunes a totes les variants s’imprimeixen una sola vegada, al principi del solucionari.
key-students = Assignada a
key-variant = Variant
key-data = Dades
key-contents = Índex

feedback-right = Correcte.
feedback-wrong = No és correcte: vegeu la resolució pas a pas.
mistake-coriolis-omitted = Aquest és el valor que s’obté ometent el terme de Coriolis 2 ω × v_rel.
mistake-coriolis-doubled = Aquest és el valor que s’obté comptant dues vegades el terme de Coriolis.
mistake-normal-omitted = Aquest és el valor que s’obté ometent els termes normals (centrípets) ω² r.
mistake-sense-reversed = Aquest és el valor que s’obté invertint el sentit d’una ω o una α donades.
mistake-drag-as-absolute = Aquest és el moviment del punt coincident de la guia (l’arrossegament), no el del mateix punt.
mistake-degrees-as-radians = Aquest és el valor que s’obté prenent com a radiants un angle donat en graus.
mistake-units-mm-as-m = Aquest és el valor que s’obté prenent com a metres els mil·límetres de les dades.
mistake-components-swapped = Les components estan intercanviades.
feedback-unit = El nombre és correcte en { $unit }; la casella demana { $asked }.
mistake-wrong-unit = La unitat no és d’aquesta magnitud (la casella demana la seva).
mistake-wrong-variant = No és una pregunta de la teva variant: respon la variant que t’ha tocat.
feedback-carried = Se segueix de la teva resposta anterior a { $question }: es dona per bona.

page-check = Comprova
page-show = Mostra la resolució pas a pas
page-your-answer = la vostra resposta
page-link = Enllaç a aquest exercici
page-score = { $right } de { $total } correctes

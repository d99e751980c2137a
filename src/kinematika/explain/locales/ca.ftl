## Missatges en català de `kinematika explain` (termes del curs: velocitat, acceleració,
## arrossegament, relativa, CIR). Cal conservar els marcadors entre claus.

sec-data = Dades
data-numeric = Unitats: longituds en { $unit }, { $accelerations ->
        [0] velocitats en { $unit }/s i velocitats angulars en rad/s.
       *[other] velocitats en { $unit }/s, acceleracions en { $unit }/s², velocitats angulars en rad/s i acceleracions angulars en rad/s².
    }
data-planar = Moviment pla: les velocitats{ $accelerations ->
        [0] {" "}angulars
       *[other] {" "}i acceleracions angulars
    } tenen signe, positives en sentit antihorari.
data-relative = La notació d’una magnitud relativa indica els dos sòlids: { $v } és la velocitat del punt { $point } { ELISION($body_b) ->
        [vowel] d’{ $body_b }
       *[other] de { $body_b }
    } vista des { ELISION($body_a) ->
        [vowel] d’{ $body_a }
       *[other] de { $body_a }
    }{ WORD($rate) ->
        [yes] , i { $w } la velocitat angular { ELISION($body_b) ->
            [vowel] d’{ $body_b }
           *[other] de { $body_b }
        } respecte { ELISION($body_a) ->
            [vowel] d’{ $body_a }
           *[other] de { $body_a }
        }.
       *[no] .
    }
data-spatial = Les velocitats i acceleracions angulars són vectors (regla de la mà dreta al voltant de la seva direcció).
data-symbolic = Les dades són símbols, i cada resultat és una fórmula exacta en funció d’aquests. Les figures es dibuixen amb valors de mostra dels símbols, indicats sota cada figura.
data-symbol = un símbol (qualsevol valor)
data-constructed = situat per construcció (vegeu Posició)
data-circles = centre { $centre }, radis { $radii }
data-circle = centre { $centre }, radi { $radius }
data-line = per { $through }, direcció { $direction }
data-plane = per { $through }, normal { $direction }
col-symbol = símbol
col-value = valor
col-position = posició
col-shape = forma
col-given = dades
sec-structure = Estructura
col-body = sòlid
col-points = punts
col-joint = enllaç
col-bodies = sòlids
col-where = on
col-omega = velocitat angular
col-alpha = acceleració angular
col-question = pregunta
col-answer = resposta
structure-subscripts = Notació: { $pairs }.
rate-precession = la precessió
structure-subscript_pair = { $sym } és la velocitat angular { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
# a relative rate the model's notation writes otherwise (C5-2.1's δ̇ for ω_{fork rel chassis}): defined where the notation line is (twenty-eighth round d)
structure-subscript_noted_rel = { $sym } és la velocitat angular { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($other) ->
        [vowel] d’{ $other }
       *[other] de { $other }
    }
structure-subscript_drag = { $equal } és { WORD($kind) ->
        [accel] l’acceleració
       *[speed] la velocitat
    } d’arrossegament { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    }
structure-subscript_member = { $sym } és la velocitat del punt { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } situat a { $point }
structure-subscript_rel = { $sym } és { WORD($kind) ->
        [rate2] l’acceleració angular
        [speed] la velocitat del punt { $point }
        [accel] l’acceleració del punt { $point }
       *[rate] la velocitat angular
    } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($other) ->
        [vowel] d’{ $other }
       *[other] de { $other }
    } (dos noms units per «rel», relatiu a: el primer sòlid respecte del segon)
structure-shaped = { $body }, { $shape } de radi { $radius }
# a body with several round shapes: its welded wheels, said once (twenty-ninth round b)
structure-shaped_welded = { $body }, { $n ->
        [2] dues
       *[other] { $n }
    } rodes solidàries de radis { $radii }
# the fixed body with no shape: its own name, marked fixed; the text names it so wherever it is a reference (twenty-seventh round e)
structure-frame_named = { $body } ({ GENDER($body) ->
        [f] fixa
       *[m] fix
    })
structure-welded = { $bodies } { $bodies_n ->
        [one] és fix a
       *[other] són fixos a
    } { $frame }: { $bodies_n ->
        [one] en forma part i no es mou
       *[other] en formen part i no es mouen
    }; tots els seus punts tenen velocitat i acceleració nul·les.
structure-contacts_wheel = { $points_n ->
        [one] punt de contacte sota { $points }
       *[other] punts de contacte sota { $points }
    }
structure-contacts_rolling = { $points_n ->
        [one] punt de contacte { $points }
       *[other] punts de contacte { $points }
    }
# the frame's row names the parts welded to it: they are the frame (twenty-ninth round b)
structure-frame_parts = { $body }, amb { $parts }
structure-fixed_part = { $body } (fix a { $frame })
structure-dof = El mecanisme té { $dof ->
        [one] un grau
        [2] dos graus
        [3] tres graus
       *[other] { $dof } graus
    } de llibertat.
structure-dof_data = El mecanisme té { $dof ->
        [one] un grau
        [2] dos graus
        [3] tres graus
       *[other] { $dof } graus
    } de llibertat, un per cada dada ({ $data }).
shape-concentric = { $n ->
        [2] dues circumferències concèntriques
       *[other] { $n } circumferències concèntriques
    }
shape-circle = circumferència
shape-line = recta
shape-disc = disc
shape-plane = pla
joint-revolute = articulació (R)
joint-prismatic = prismàtic (P)
joint-revolute_word = articulació
joint-prismatic_word = parell prismàtic
joint-slot = passador en ranura
joint-slot_fixed = contacte amb lliscament sobre una recta fixa
joint-wheel = roda (sense lliscament lateral)
joint-rolling = rodolament
joint-gear = engranatge
joint-weld = sòlids solidaris
joint-spherical = ròtula esfèrica
joint-cylindrical = cilíndric
along-joint = { WORD($verb) ->
        [only] segons { $dir }
        [rolls] la roda a { $point } rodola segons { $dir }
       *[slides] { $point } llisca segons { $dir }
    }
along-horizontal = una recta horitzontal
along-vertical = una recta vertical
along-angle = { $vec }, a { $deg }° de l’horitzontal
along-vector = { $vec }
along-line = { $line }
fig-arrow-velocity = la velocitat { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    }
fig-arrow-drag = la velocitat d’arrossegament ({ $sym })
fig-arrow-relative = la velocitat relativa ({ $sym })
fig-own_drag = la velocitat { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } i la seva velocitat d’arrossegament ({ $sym })
fig-rest = ; { $count ->
        [one] { $points } té velocitat nul·la en aquest instant{ $centre }, escrita al costat
       *[other] { $points } tenen velocitat nul·la en aquest instant, escrita al costat
    }
fig-contact = Els tres punts que coincideixen al contacte { $point } en aquest instant, sobre el mecanisme a escala: el punt { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    }, el punt { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    } i el punt geomètric de contacte { $geom }. { $moving ->
        [0] {""}
        [one] { $format ->
            [md] La fletxa
           *[other] La fletxa { $accel ->
                [0] blava
               *[other] vermella
            }
        } és { $arrows }{ $moduli ->
            [0] {""}
            [2] {", amb el seu mòdul, en "}{ $unit }
           *[other] {", amb el seu mòdul"}
        }
       *[other] { $format ->
            [md] Les fletxes
           *[other] Les fletxes { $accel ->
                [0] blaves
               *[other] vermelles
            }
        } són { $arrows }, a una mateixa escala{ $moduli ->
            [0] {""}
            [2] {", amb els seus mòduls, en "}{ $unit }
           *[other] {", amb els seus mòduls"}
        }
    }{ $still ->
        [0] .
        [one] { $moving ->
            [0] {""}
           *[other] {"; "}
        }{ $zeros } és nul·la, escrita al costat { ELISION($point) ->
            [vowel] d’{ $point }
           *[other] de { $point }
        }.
       *[other] { $moving ->
            [0] {""}
           *[other] {"; "}
        }{ $zeros } són nul·les, escrites al costat { ELISION($point) ->
            [vowel] d’{ $point }
           *[other] de { $point }
        }.
    }
fig-mechanism = El mecanisme en aquest instant, a escala{ $dim ->
        [3] , en projecció isomètrica (els eixos x, y, z a baix a la dreta)
       *[other] {""}
    }; { $arrows ->
        [0] no s’hi dibuixa cap velocitat
        [1] { $format ->
            [md] la fletxa
           *[other] la fletxa blava
        } és la velocitat { ELISION($points) ->
        [vowel] d’{ $points }
       *[other] de { $points }
    }{ $moduli ->
            [0] {""}
            [2] {", amb el seu mòdul, en "}{ $unit }/s
           *[other] {", amb el seu mòdul"}
        }
        [3] { $points } té velocitat nul·la en aquest instant{ $centre }, escrita al costat
        [4] { $format ->
            [md] les fletxes
           *[other] les fletxes blaves
        } són { $points }, a una mateixa escala{ $moduli ->
            [0] {""}
            [2] {", amb els seus mòduls, en "}{ $unit }/s
           *[other] {", amb els seus mòduls"}
        }
       *[other] { $format ->
            [md] les fletxes
           *[other] les fletxes blaves
        } són les velocitats { ELISION($points) ->
        [vowel] d’{ $points }
       *[other] de { $points }
    }, a una mateixa escala{ $moduli ->
            [0] {""}
            [2] {", amb els seus mòduls, en "}{ $unit }/s
           *[other] {", amb els seus mòduls"}
        }
    }{ $rest }; els sòlids estan numerats.
fig-rest_centre = {" "}(és el CIR { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    })
fig-mechanism_named = El mecanisme en aquest instant, a escala{ $dim ->
        [3] , en projecció isomètrica (els eixos x, y, z a baix a la dreta)
       *[other] {""}
    }; { $arrows ->
        [0] no s’hi dibuixa cap velocitat
        [1] { $format ->
            [md] la fletxa
           *[other] la fletxa blava
        } és la velocitat { ELISION($points) ->
        [vowel] d’{ $points }
       *[other] de { $points }
    }{ $moduli ->
            [0] {""}
            [2] {", amb el seu mòdul, en "}{ $unit }/s
           *[other] {", amb el seu mòdul"}
        }
        [3] { $points } té velocitat nul·la en aquest instant{ $centre }, escrita al costat
        [4] { $format ->
            [md] les fletxes
           *[other] les fletxes blaves
        } són { $points }, a una mateixa escala{ $moduli ->
            [0] {""}
            [2] {", amb els seus mòduls, en "}{ $unit }/s
           *[other] {", amb els seus mòduls"}
        }
       *[other] { $format ->
            [md] les fletxes
           *[other] les fletxes blaves
        } són les velocitats { ELISION($points) ->
        [vowel] d’{ $points }
       *[other] de { $points }
    }, a una mateixa escala{ $moduli ->
            [0] {""}
            [2] {", amb els seus mòduls, en "}{ $unit }/s
           *[other] {", amb els seus mòduls"}
        }
    }{ $rest }.
fig-at_pole = { $count ->
    [one] { $images } és al pol o, ja que { $zero }.
   *[other] { $images } són al pol o, ja que { $zero }.
}
fig-moved_aside = Un terme que quedaria sobre una altra fletxa es dibuixa al seu costat, paral·lel i a escala; { $format ->
        [md] unes línies discontínues uneixen
       *[other] uns traços grisos uneixen
    } els seus extrems amb els punts entre els quals va.
fig-too_short = { $count ->
    [one] { $terms } és massa curt per veure’s a aquesta escala (més curt que una punta de fletxa); el seu valor és al text.
   *[other] { $terms } són massa curts per veure’s a aquesta escala (més curts que una punta de fletxa); els seus valors són al text.
}
fig-o_prime = La imatge d’O es designa o′, perquè la lletra o designa el pol.
fig-o_prime_named = o′, la imatge d’O,
fig-o_prime_fixed = o′, la imatge del punt fix O de { $body },
fig-centre_image = { $count ->
    [one] la imatge del CIR { $centre }
   *[other] les imatges dels CIR { $centre }
}
fig-primed = La imatge del punt { $point } és { $image } ({ $symbol }: { $what }).
fig-a_symbol = una dada
fig-polygon_v = Polígon de velocitats, a escala. Des del pol o, els seus termes es dibuixen l’un darrere l’altre{ $result ->
        [1] {" "}i la seva suma, { $sym }, el tanca
       *[other] {""}
    }{ $format ->
        [md] {""}
       *[other] {" "}(en negre els termes coneguts{ $unknown ->
            [1] , en vermell els trobats en aquest pas
           *[other] {""}
        }{ $result ->
            [1] , en blau la suma
           *[other] {""}
        })
    }. Cada vèrtex és la imatge d’un punt.
fig-polygon_a = Polígon d’acceleracions, a escala. Des del pol o, els seus termes es dibuixen l’un darrere l’altre{ $result ->
        [1] {" "}i la seva suma, { $sym }, el tanca
       *[other] {""}
    }{ $format ->
        [md] {""}
       *[other] {" "}(en negre els termes coneguts{ $unknown ->
            [1] , en vermell els trobats en aquest pas
           *[other] {""}
        }{ $result ->
            [1] , en blau la suma
           *[other] {""}
        })
    }. Cada vèrtex és la imatge d’un punt.
fig-sample = Dibuixat amb valors de mostra dels símbols.
sec-position = Posició
pos-intro = Anàlisi de posició: cada punt mòbil se situa com el situa l’enunciat, a partir de punts ja situats.
pos-named = Aquí { $name } = { $formula }.
pos-moved = El mecanisme s’analitza on el porta el moviment demanat, cada sòlid portat des del dibuix com segueix.
pos-turn_angle = { $body } ha girat { $angle } al voltant { ELISION($pivot) ->
        [vowel] d’{ $pivot }
       *[other] de { $pivot }
    }.
pos-turn_toward = { $body } ha girat com la recta { $line }.
pos-turn_shift = { $body } s’ha desplaçat { $shift } al llarg de la seva guia.
pos-carried = { $point } es mou amb { $body }: { $point } = { $at }.
pos-polar = { $point } és a una distància { $distance } { ELISION($origin) ->
        [vowel] d’{ $origin }
       *[other] de { $origin }
    }, a { $angle } de l’eix x: { $point } = { $at }.
pos-polar_ref = { $point } és a una distància { $distance } { ELISION($origin) ->
        [vowel] d’{ $origin }
       *[other] de { $origin }
    }, a { $angle } de la direcció { $ref }: { $point } = { $at }.
pos-frame = { $point } és a una distància { $x } { ELISION($origin) ->
        [vowel] d’{ $origin }
       *[other] de { $origin }
    } segons { $line } i a una distància { $y } en perpendicular, a l’esquerra mirant { ELISION($from) ->
        [vowel] d’{ $from }
       *[other] de { $from }
    } cap a { $to }: { $point } = { $at }.
pos-frame_right = { $point } és a una distància { $x } { ELISION($origin) ->
        [vowel] d’{ $origin }
       *[other] de { $origin }
    } segons { $line } i a una distància { $y } en perpendicular, a la dreta mirant { ELISION($from) ->
        [vowel] d’{ $from }
       *[other] de { $from }
    } cap a { $to }: { $point } = { $at }.
pos-frame_on = { $point } és a una distància { $x } { ELISION($origin) ->
        [vowel] d’{ $origin }
       *[other] de { $origin }
    } segons { $line }: { $point } = { $at }.
pos-circles = { $point } és a una distància { $r1 } { ELISION($c1) ->
        [vowel] d’{ $c1 }
       *[other] de { $c1 }
    } i { $r2 } { ELISION($c2) ->
        [vowel] d’{ $c2 }
       *[other] de { $c2 }
    }: la intersecció de dues circumferències, de centres { $c1 } i { $c2 }. Dels dos punts on es tallen, és { $which }: { $point } = { $at }.
pos-circle_line = { $point } és a una distància { $r } { ELISION($c) ->
        [vowel] d’{ $c }
       *[other] de { $c }
    } sobre la recta { $line }: la intersecció d’una circumferència de centre { $c } i una recta. Dels dos punts on es tallen, és { $which }: { $point } = { $at }.
pos-lines = { $point } és el punt on es tallen les rectes { $l1 } i { $l2 }: { $point } = { $at }.
pos-line_dir = per { $through } segons { $dir }
pos-left = el que queda a l’esquerra mirant { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } cap a { $b }
pos-right = el que queda a la dreta mirant { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } cap a { $b }
pos-upper = el de dalt
pos-lower = el de baix
pos-leftmost = el de l’esquerra
pos-rightmost = el de la dreta
pos-ahead = el que és més endavant en el sentit de la recta { $line }
pos-behind = el que és més enrere en el sentit de la recta { $line }
pos-near = el més proper al punt de l’esbós { $near }
pos-touch = l’únic punt on es toquen
pos-assembly = { $which }, { $assembly }
pos-open = la configuració oberta (les barres no es creuen)
pos-crossed = la configuració creuada (les barres es creuen)

sec-order = Ordre de resolució
order-assur = El mecanisme es descompon en les seves entrades i díades; cadascuna es resol a partir de sòlids ja coneguts:
order-blocks = Els sòlids es troben en aquest ordre, cadascun a partir de sòlids ja coneguts:
order-item = { $n }. { $kind }: { $bodies }, a partir { $known }.
order-item_group = { $n }. { $bodies }, a partir { $known }.
order-item_through = { $n }. { $kind }: { $bodies }, a partir { $known }, a través { $through }.
order-item_group_through = { $n }. { $bodies }, a partir { $known }, a través { $through }.
order-item_data = { $n }. { $kind }: { $bodies }, a partir de les dades.
order-item_group_data = { $n }. { $bodies }, a partir de les dades.
order-from = { ELISION($name) ->
        [vowel] d’{ $name }
       *[other] de { $name }
    }
kind-input = entrada (sòlid motor)
kind-RRR = díade RRR
kind-RRP = díade RRP
kind-RPR = díade RPR
kind-PRP = díade PRP
kind-other = grup resolt conjuntament
step-title = Pas { $n }: { $kind } — { $bodies }
step-title_group = Pas { $n }: { $bodies }
sec-velocities = Velocitats
sec-accelerations = Acceleracions
v-intro = Cada equació vectorial s’anota com als apunts: M: mòdul conegut; D: direcció coneguda; ?: desconegut; ⊥ i ∥ donen una direcció coneguda.{ $marks ->
        [1] { WORD($clash) ->
            [M] {" "}Aquí M indica un mòdul conegut; no és el punt M.
           *[other] {" "}Aquí D indica una direcció coneguda; no és el punt D.
        }
        [2] {" "}Aquí M i D són aquestes marques; no són els punts M i D.
       *[other] {""}
    } Una equació vectorial plana resol dues incògnites{ $format ->
        [md] : el pas troba els termes marcats amb ?
       *[other] : el pas troba els termes marcats en vermell
    }.
a-intro = Conegudes les velocitats, tots els termes normals i de Coriolis són coneguts; les incògnites són els termes tangencials i relatius.
a-intro_relative = Conegudes les velocitats, tots els termes normals són coneguts; les incògnites són els termes tangencials i relatius.
a-intro_normal = Conegudes les velocitats, els termes normals són coneguts; les incògnites són els termes tangencials.
eq-shared_rate = Els termes { $terms } tenen una sola incògnita, { $rate }: els seus mòduls són { $mags }, i els seus dos ? compten com una.
a-named = On una fórmula desenvolupada seria il·legible, les velocitats angulars trobades a «{ sec-velocities }» s’escriuen pel seu nom: { $name } per a la ω de { $body }, i així per a cada sòlid.
driver-omega = Dada: { $sym } = { $value }.
driver-omega_sense = Dada: { $sym } = { $value }, { $faster ->
        [1] en el sentit de { $w }: { $body } { COUNT($body) ->
            [many] s’acceleren
           *[one] s’accelera
        }
       *[other] en sentit contrari a { $w }: { $body } { COUNT($body) ->
            [many] es frenen
           *[one] es frena
        }
    }.
# a point given no acceleration: said as the notes say it, it moves at constant velocity (twenty-ninth round a)
driver-steady = Dada: { $point } es mou amb velocitat constant ({ $sym } = 0).
# a body given no angular acceleration: it turns at a constant rate (twenty-ninth round a)
driver-omega_steady = Dada: { $body } { COUNT($body) ->
        [many] giren
       *[one] gira
    } amb velocitat angular constant ({ $sym } = 0).
driver-velocity = Dada: { $sym } = { $value }.
driver-along = Dada: la component de { $sym } segons { $along } és { $value }.
driver-whole = Dada: { $sym } = { $value }, { $heading }.
driver-held = En aquest instant { $b } no { COUNT($b) ->
        [many] giren
       *[one] gira
    } respecte { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } a l’articulació { $point }: { $sym } = 0.
driver-held_accel = L’articulació { $point } no té acceleració angular relativa en aquest instant: { $sym } = 0.
heading-right = cap a la dreta
heading-left = cap a l’esquerra
heading-up = cap amunt
heading-down = cap avall
heading-along = segons { $along }
readoff-along_x = segons x:
readoff-along_y = segons y:
input-revolute = { $body } { COUNT($body) ->
        [many] giren
       *[one] gira
    } al voltant del punt fix { $point }: els seus punts descriuen circumferències centrades a { $point }.
input-prismatic = { $body } { COUNT($body) ->
        [many] es traslladen
       *[one] es trasllada
    } sense girar al llarg de la seva guia.
other-intro = Aquests sòlids es troben alhora a partir de les condicions dels seus enllaços:
cond-revolute = articulació a { $point }: { $point } és un punt { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } i { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    }.
cond-prismatic = enllaç prismàtic: { $b } { COUNT($b) ->
        [many] llisquen
       *[one] llisca
    } sobre { $a } sense girar respecte { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    }.
cond-slot = passador { $point } en ranura: la seva velocitat relativa al sòlid amb ranura segueix la ranura.
cond-slot_fixed = el punt { $point } { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    } llisca al llarg d’una recta solidària a { $a }: la seva velocitat segueix aquesta recta.
cond-wheel = roda a { $point }: sense velocitat lateral respecte { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    }.
cond-weld = { $a } i { $b } es mouen com un sol sòlid.
cond-spherical = ròtula a { $point }: { $point } és un punt { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } i { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    }.
cond-cylindrical = enllaç cilíndric: { $b } { COUNT($b) ->
        [many] giren
       *[one] gira
    } al voltant de l’eix { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } i hi llisca.
rolling-noslip = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] engranen
               *[one] engrana
            } amb { $a }
       *[other] { $b } { COUNT($b) ->
            [many] rodolen
           *[one] rodola
        } sense lliscar sobre { $a }
    }: al contacte { $point } els dos punts materials tenen la mateixa velocitat.
rolling-noslip_edge = { $b } no { COUNT($b) ->
        [many] llisquen
       *[one] llisca
    } sobre { $a }: al contacte { $point } els dos punts materials tenen la mateixa velocitat.
rolling-same_edge = { $b } no { COUNT($b) ->
        [many] llisquen
       *[one] llisca
    } sobre { $a }: al contacte { $point } els dos punts materials tenen la mateixa velocitat, { $sym } = { $other }.
rolling-glide = { $b } { COUNT($b) ->
        [many] rodolen
       *[one] rodola
    } sense lliscar sobre la vora { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    }. Des { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    }, el seu centre { $centre } manté la distància a la vora: es mou segons una recta paral·lela a la tangent a { $point }. Amb eixos a { $centre } que giren amb { $a }, el moviment { ELISION($centre) ->
        [vowel] d’{ $centre }
       *[other] de { $centre }
    } és el d’arrossegament (el del punt { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } que hi coincideix) més el relatiu, al llarg d’aquesta recta (i, en acceleracions, el terme de Coriolis).
rolling-kept = el contacte es manté: a { $point } les acceleracions dels punts materials { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    } i { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } només difereixen en un terme segons la normal comuna; no hi ha terme de Coriolis, perquè en un contacte de rodolament els dos punts no tenen velocitat relativa: { $vrel } = 0.
path-circle = { $b } { COUNT($b) ->
        [many] rodolen
       *[one] rodola
    } sense lliscar sobre { $a }, que no es mou. El seu centre { $centre } manté la distància a { $a }: descriu la circumferència de radi { $radius } centrada a { $o }, de manera que { $ac } té una component normal { $vs }² / { $radius } cap a { $o }; i com que { $vc } = { $w } × { $arm } a cada instant (el contacte { $point } és el CIR), la seva component tangencial és { $al } × { $arm }.
path-found = { $b } { COUNT($b) ->
        [many] rodolen
       *[one] rodola
    } sense lliscar sobre { $a }, que no es mou. { $ac }, trobada al pas { $step }, té una component normal { $vs }² / { $radius } cap a { $o } i una de tangencial, que és { $al } × { $arm }, ja que { $vc } = { $w } × { $arm } a cada instant (el contacte { $point } és el CIR).
path-line = { $b } { COUNT($b) ->
        [many] rodolen
       *[one] rodola
    } sense lliscar sobre { $a }, que no es mou. El seu centre { $centre } manté la distància a { $a }: descriu una recta, sense acceleració normal; i com que { $vc } = { $w } × { $arm } a cada instant (el contacte { $point } és el CIR), la seva acceleració és només la seva component tangencial: { $ac } = { $at } = { $al } × { $arm }.
rolling-equal = Sense lliscament al contacte { $point }: { $sym } = { $other }.
rolling-same = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] engranen
               *[one] engrana
            } amb { $a }
       *[other] { $b } { COUNT($b) ->
            [many] rodolen
           *[one] rodola
        } sense lliscar sobre { $a }
    }: al contacte { $point } els dos punts materials tenen la mateixa velocitat, { $sym } = { $other }.
rolling-centre = { $gear ->
        [1] { $b } { COUNT($b) ->
                [many] engranen
               *[one] engrana
            } amb { $a }
       *[other] { $b } { COUNT($b) ->
            [many] rodolen
           *[one] rodola
        } sense lliscar sobre { $a }
    }, que no es mou: el punt { $point } { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    } al contacte no té velocitat, { $sym } = 0; per tant, és el CIR { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    }.
dir-guide = guia { ELISION($holder) ->
        [vowel] d’{ $holder }
       *[other] de { $holder }
    }
dir-normal_at = normal en { $point }
how-prismatic = (enllaç prismàtic: sense rotació relativa)
carry-anchor = De la resolució del grup: { $sym } = { $value }.
sense-ccw = antihorari
sense-cw = horari
sec-rates_summary = Velocitats i acceleracions angulars
sec-rates_summary_v = Velocitats angulars
sec-centres = Centres instantanis de rotació (CIR)
centres-intro = El símbol I, amb els números de dos sòlids ({ $example }: sòlids 1 i 3), designa el CIR del seu moviment relatiu: el punt on la velocitat relativa és nul·la.
centres-intro_named = El símbol I, amb el nom d’un sòlid ({ $pair }), designa el CIR { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }: el punt on la velocitat relativa és nul·la.
centres-intro_named_rel = El símbol I, amb el nom d’un sòlid ({ $pair }), designa el CIR { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }, i, amb dos noms units per «rel» (relatiu a), el del primer respecte del segon: el punt on la velocitat relativa és nul·la.
centre-line = { $centre }: { $why } { $where }
centre-joint-revolute = l’eix de l’articulació { $joint },
# a pin to the fixed body: a permanent centre; a strand's, where it is tied (twenty-ninth round b)
centre-joint-revolute_fixed = l’eix de l’articulació fixa { $joint }, un centre permanent,
centre-joint-revolute_tied = el punt { $joint }, on { $body } és lligat a { $frame }, un centre permanent,
centre-joint-rolling = el punt de contacte { $joint } (rodolament sense lliscament),
centre-joint-gear = el contacte { $joint } de les circumferències primitives,
centre-joint-prismatic = l’enllaç és prismàtic: el moviment relatiu és una translació i el CIR és a la perpendicular a la guia,
centre-joint-weld = els dos sòlids són solidaris:
centre-kennedy = per Aronhold–Kennedy és a la recta que passa per { $l1 } (tercer sòlid { $k1 }) i a la recta que passa per { $l2 } (tercer sòlid { $k2 }); aquestes rectes { $far ->
        [1] són paral·leles, de manera que
       *[other] es tallen
    }
centre-velocities = les velocitats respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } { ELISION($p) ->
        [vowel] d’{ $p }
       *[other] de { $p }
    }, { $vp }, i { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }, { $vq }, són perpendiculars a les rectes que els uneixen amb el CIR; les perpendiculars es tallen
centre-lines = és a { $first } i a { $second }; aquestes rectes { $far ->
        [1] són paral·leles, de manera que
       *[other] es tallen
    }
centre-omega = amb les velocitats trobades a «{ sec-velocities }», la velocitat angular respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } és nul·la: el moviment relatiu és una translació i el CIR és
centre-at = a { $point }.
centre-infinity = { $body } es trasllada respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } ({ $w } = 0): tots els seus punts tenen la velocitat { $v }; el seu CIR és a l’infinit, en la direcció perpendicular a { $v }.
centre-infinity_one = { $body } es trasllada respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } ({ $w } = 0): tots els seus punts tenen la mateixa velocitat; el seu CIR és a l’infinit, en la direcció perpendicular a aquesta velocitat, { $direction }.
centre-rest = no hi ha moviment relatiu.
sec-rates = Velocitats i acceleracions angulars
rates-intro = Cada sòlid gira respecte del sòlid que el porta: { $w }, i, derivant en els eixos fixos, { $a }.
rates-intro_v = Cada sòlid gira respecte del sòlid que el porta: { $w }.
fields-intro_v = La velocitat de cada punt, a partir d’un punt del mateix sòlid ja conegut (el seu enllaç):
fields-intro_a = L’acceleració de cada punt, a partir d’un punt del mateix sòlid ja conegut (el seu enllaç):
sec-composition = Composició de moviments
composition-intro = El moviment d’un punt és el d’arrossegament (el del punt de la referència mòbil que coincideix amb ell) més el relatiu a aquesta referència, més, en acceleracions, el terme de Coriolis { $cor }.
composition-point = Punt { $point } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }, referència mòbil { $frame }:
composition-drag = { WORD($kind) ->
        [accel] { sec-accelerations }
       *[speed] { sec-velocities }
    }. Arrossegament:
composition-relative = Relatiu: { $sym }, el moviment vist des de la referència mòbil, { $frame }:
composition-rolls = { $body } { COUNT($body) ->
        [many] rodolen
       *[one] rodola
    } sense lliscar sobre { $frame } a { $point }: vist des { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }, { $point } és el CIR { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }, { $sym } = 0, i tots els seus punts giren al voltant d’aquest punt.
sec-curvature = Curvatura de les trajectòries
curvature-intro = L’acceleració es descompon en una part tangencial, segons la velocitat, i una de normal, perpendicular a ella; el radi de curvatura és { $rho }.
curvature-point = Punt { $point }: velocitat { $v }.
curvature-rest = El punt { $point } té velocitat nul·la en aquest instant: la seva trajectòria no hi té radi de curvatura (ℜ = |v|²/|aⁿ| necessita una velocitat).
curvature-straight = L’acceleració normal { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } és nul·la: la seva trajectòria és recta aquí (o hi té un punt d’inflexió).
curvature-circle = Punt { $point }: manté la distància al punt fix { $o }, de manera que la seva trajectòria és la circumferència de radi { $radius } centrada a { $o }; el radi de curvatura és aquest radi:
curvature-circle_centre = El centre de curvatura de la trajectòria { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } és { $o }, a { $centre }.
curvature-centre = El centre de curvatura de la trajectòria { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } és a { $centre }, del costat de l’acceleració normal.
curvature-centre_from = El centre de curvatura de la trajectòria { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } és { $where }.
curvature-named = Amb { $d } = { $arm } = { $length }, { $rho } = { $value }.
curvature-from = { WORD($side) ->
        [up] a { $rho } per sobre { ELISION($point) ->
            [vowel] d’{ $point }
           *[other] de { $point }
        }
        [down] a { $rho } per sota { ELISION($point) ->
            [vowel] d’{ $point }
           *[other] de { $point }
        }
        [left] a { $rho } a l’esquerra { ELISION($point) ->
            [vowel] d’{ $point }
           *[other] de { $point }
        }
        [right] a { $rho } a la dreta { ELISION($point) ->
            [vowel] d’{ $point }
           *[other] de { $point }
        }
       *[other] a { $rho } { ELISION($point) ->
            [vowel] d’{ $point }
           *[other] de { $point }
        }, en la direcció d’{ $an }
    }
curvature-intrinsic = Amb { $speed }, la tangent unitària és { $tangent }; { $split }, amb { $tangential }, i { $rest }, { $normal }:
sec-answers = Respostes
answers-none = El model no fa preguntes.
ask-icr = CIR { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-axis = eix instantani de rotació i lliscament { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-pole = pol d’acceleracions { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-inflection = circumferència d’inflexions i tangent polar { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-contact = els tres punts coincidents al contacte { $joint }
ask-decompose = composició del moviment { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    }, referència mòbil { $frame }
ask-curvature = radi de curvatura de la trajectòria { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ask-intrinsic = acceleració tangencial i normal { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }
ans-rest = sense moviment relatiu
# an asked planar rate with its sense, as the notes ask it (“valor i sentit”: twenty-eighth round d)
ans-sensed = { $value } ({ $sense })
ans-point = posició
ans-from = distància { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    }
ans-direction = direcció
ans-center = centre de curvatura
ans-center_from = centre de curvatura { $where }
ans-tangent = tangent unitària
ans-slide = velocitat al llarg de l’eix
ans-translation = una translació: sense circumferència d’inflexions
ans-inflection_pole = centre instantani I
ans-inflection_center = centre de la circumferència d’inflexions
ans-inflection_diameter = diàmetre de la circumferència d’inflexions
ans-inflection_point = pol d’inflexions (oposat a I a la circumferència)
ans-pole_tangent = tangent polar (unitària, en el sentit en què es mou I)
ans-pole_normal = normal polar (unitària, d’I al pol d’inflexions)
ans-pole_velocity = velocitat d’I al llarg de la base i la ruleta
centre-proportional-between = per Aronhold–Kennedy és a la recta que passa per { $l1 } i a la que passa per { $l2 }, però són una mateixa recta i no el fixen. En aquesta recta les velocitats respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } hi són perpendiculars i proporcionals a la distància al CIR: { $p } es mou amb { $vp } i { $q } amb { $vq }, en sentits oposats, de manera que el CIR és entre tots dos, on la velocitat s’anul·la:
centre-proportional-outside = per Aronhold–Kennedy és a la recta que passa per { $l1 } i a la que passa per { $l2 }, però són una mateixa recta i no el fixen. En aquesta recta les velocitats respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } hi són perpendiculars i proporcionals a la distància al CIR: { $p } es mou amb { $vp } i { $q } amb { $vq }, en el mateix sentit, de manera que el CIR és més enllà del més lent, on la velocitat s’anul·la:
composition-slide = { $point } llisca al llarg de la seva guia: el seu moviment relatiu segueix la guia, { $sym } = { $value }.
composition-slide_seen = { $body } llisca al llarg de { $frame } sense girar respecte d’ell, i per tant tots els seus punts, també { $point }, tenen { WORD($kind) ->
        [accel] l’acceleració
       *[speed] la velocitat
    } relativa trobada a «{ sec-velocities }»: { $sym } = { $value }.
composition-slide_seen_step = { $body } llisca al llarg de { $frame } sense girar respecte d’ell, i per tant tots els seus punts, també { $point }, tenen { WORD($kind) ->
        [accel] l’acceleració
       *[speed] la velocitat
    } relativa trobada al pas { $step }: { $sym } = { $value }.
composition-drag_seen = { $sym } = { $value }, { WORD($kind) ->
        [accel] l’acceleració
       *[speed] la velocitat
    } del punt { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } que coincideix amb { $point }, trobada al pas { $step }.
composition-drag_terms = { $sym } = { $terms } = { $value }: els primers termes de l’equació del pas { $step }.
composition-sum_seen = Així, { $sym } = { $terms } és l’equació del pas { $step }, amb la qual { $seen_n ->
        [one] s’ha trobat
       *[other] s’han trobat
    } { $seen }.
composition-reverse = { $sym } = −{ $back } = { $value }: l’oposada { WORD($kind) ->
        [accel] de l’acceleració
       *[speed] de la velocitat
    } relativa trobada al pas { $step }.
composition-reverse_rolling = Sense lliscament: { $vel } = 0, de manera que no hi ha terme de Coriolis i { $sym } = −{ $back } = { $value }, l’oposada de l’acceleració relativa trobada al pas { $step }.
composition-pin = { $point } és una articulació, punt de tots dos sòlids: no té moviment relatiu, { $sym } = 0.
vehicle-driven = La roda { $joint } no llisca: { $point } no té velocitat perpendicular al pla de la roda, de manera que la seva velocitat donada segons el pla és tota la seva velocitat: { $sym } = { $value }.
vehicle-line-wheel = la perpendicular al pla de la roda { $joint } pel punt { $point } (el seu eix: la roda no llisca lateralment)
vehicle-line-velocity = la perpendicular a { $sym } pel punt { $point }
vehicle-equiprojective = Per la propietat d’equiprojectivitat ({ $q } i { $p } són punts { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }), les seves velocitats tenen la mateixa component segons { $seg }: { $vp } · { $seg }/|{ $seg }| = { $vq } · { $seg }/|{ $seg }|, amb { $seg }/|{ $seg }| = { $unit }, de manera que { $vq } · { $seg }/|{ $seg }| = { $proj }. { $p } és a l’eix de la roda { $joint }, de manera que { $vp } té la direcció del pla de la roda: { $vp } = |{ $vp }| e, amb e = { $along } i e · { $seg }/|{ $seg }| = { $cos }. Per tant, |{ $vp }| = ({ $proj }) / ({ $cos }) = { $speed }, i { $vp } = { $value }.
vehicle-equiprojective_along = Per la propietat d’equiprojectivitat ({ $q } i { $p } són punts { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }), les seves velocitats tenen la mateixa component segons { $seg }: { $vp } · { $seg }/|{ $seg }| = { $vq } · { $seg }/|{ $seg }|, amb { $seg }/|{ $seg }| = { $unit }, de manera que { $vq } · { $seg }/|{ $seg }| = { $proj }. { $p } és a l’eix de la roda { $joint }, de manera que { $vp } té la direcció del pla de la roda, la recta { $seg }: { $vp } = |{ $vp }| { $seg }/|{ $seg }|. Per tant, |{ $vp }| = { $speed }, i { $vp } = { $value }.
vehicle-line-wheel_own = la perpendicular al pla de la roda { $joint } pel punt { $point } (el seu eix, que és també la perpendicular a { $sym } per { $witness }: la roda no llisca lateralment)
vehicle-pin_shared = { $point } és el passador comú a { $a } i { $b }: { $sym } = { $other }.
vehicle-pin_shared_one = { $point } és el passador comú a { $a } i { $b }: { $sym } és la velocitat de tots dos.
vehicle-centre = El CIR { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } és a { $first } i a { $second }; es tallen a { $centre } = { $where }, que no té velocitat: { $rest } = 0. Cada punt { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } es mou perpendicularment a la recta que l’uneix amb { $centre }, amb celeritat proporcional a la seva distància:
vehicle-translation = Les rectes { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } són paral·leles, de manera que es trasllada: tots els seus punts es mouen com { $point }.
vehicle-translation_equal = { $p } i { $q } tenen la mateixa velocitat, { $vp } = { $vq } = { $value }, de manera que { $body } es trasllada: tots els seus punts tenen la velocitat { $value }.
vehicle-spin = La roda { $joint } rodola sense lliscar (radi { $radius }): el seu centre { $point } es mou en el pla de la roda amb celeritat { $product }, on { $spin } és la seva rotació pròpia al voltant del seu eix, de manera que:
triad-intro = { $body } està subjectat per tres barres binàries, { $links }: cap equació vectorial d’un sol punt no té només dues incògnites. Com fan els textos per a una tríada, es pren el punt d’Assur { $point }, on es tallen les rectes { $l1 } i { $l3 }, com a punt { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }:
triad-collinear = A cada membre els dos termes desconeguts són perpendiculars a una mateixa recta ({ $point } és a { $l1 } i a { $l3 }), de manera que cada membre té un sol mòdul desconegut: dues incògnites, i el polígon es tanca.
triad-closure = Conegut { $point } com a punt de la barra ternària, la seva articulació { $pin } es tanca com en una díade:
loop-intro = Els sòlids { $bodies } tanquen un llaç: en recórrer-lo, les velocitats angulars relatives sumen zero, cadascuna segons l’eix del seu enllaç (tres equacions escalars per a les velocitats { $rate } desconegudes segons els eixos { $axis }):
loop-solve = Les tres components donen les velocitats desconegudes:
loop-solve_alpha = Derivant en els eixos fixos, les acceleracions angulars relatives i els termes { $cross } sumen zero al llarg del llaç; les tres components donen les { $rate } desconegudes:
dir-axis = eix { $joint }
dir-wheel = roda { $joint }
how-weld = (solidaris: un sol sòlid rígid)
group-wheel_v = La roda { $joint } no llisca lateralment: la velocitat { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } és al pla de la roda.
group-wheel_a = La roda { $joint } no llisca lateralment en cap instant i el seu pla gira amb { $body }: l’acceleració { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } té una part tangencial al pla i una de normal perpendicular al pla, { $w } × { $v }.
how-translation = (es trasllada)
translation-same = { $body } { COUNT($body) ->
        [many] no giren
       *[one] no gira
    } ({ $w } = 0{ $accel ->
        [1] , { $a } = 0
       *[other] {""}
    }): es trasllada, i tots els seus punts tenen la mateixa { $accel ->
        [1] acceleració
       *[other] velocitat
    }:
translation-points = Tots els punts { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } tenen la mateixa { $accel ->
        [1] acceleració
       *[other] velocitat
    }:
fig-centres = Els centres instantanis (anells, I amb els números de dos sòlids) sobre el mecanisme{ $kennedy ->
        [0] { $normals_n ->
            [0] .
           *[other] , amb les rectes on es troben (traç i punt: { $normals }).
        }
       *[other] , amb les rectes on es troben (traç i punt: rectes que passen per dos centres{ $normals_n ->
            [0] {""}
           *[other] {" "}i { $normals }
        }).
    }
fig-centres_named = Els centres instantanis (anells, I amb els noms dels sòlids) sobre el mecanisme{ $kennedy ->
        [0] { $normals_n ->
            [0] .
           *[other] , amb les rectes on es troben (traç i punt: { $normals }).
        }
       *[other] , amb les rectes on es troben (traç i punt: rectes que passen per dos centres{ $normals_n ->
            [0] {""}
           *[other] {" "}i { $normals }
        }).
    }
fig-normal-wheel = les perpendiculars a les rodes
fig-normal-slot = les normals a les ranures
fig-normal-slot_fixed = les normals a les rectes per on llisquen els punts
fig-normal-normal = les normals comunes als contactes
fig-normal-radius = les perpendiculars a les velocitats dels punts
fig-assur = El punt d’Assur { $point }: les rectes { $l1 } i { $l3 } (a traços) perllongades fins que es tallen; { $point } es pren com a punt de la barra ternària.
fig-drawn_at = Dibuixat amb { $values }.
fig-level_v = Polígon de velocitats, a escala: des del pol o, la velocitat de cada punt{ $format ->
        [md] {""}
       *[other] {" "}(blau)
    } acaba a la seva imatge, amb la lletra del punt{ $image ->
        [0] {""}
       *[other] {" "}({ $image } per a { $point })
    }{ $between ->
        [0] .
       *[other] ; entre les imatges, les velocitats relatives de les equacions { $span ->
            [1] del pas { $first }
            [2] dels passos { $first } i { $last }
           *[other] dels passos { $first } a { $last }
        }{ $format ->
            [md] {""}
           *[other] {" "}(negre)
        }, l’una darrere l’altra.
    }
fig-level_a = Polígon d’acceleracions, a escala: des del pol o, l’acceleració de cada punt{ $format ->
        [md] {""}
       *[other] {" "}(blau)
    } acaba a la seva imatge, amb la lletra del punt{ $image ->
        [0] {""}
       *[other] {" "}({ $image } per a { $point })
    }{ $between ->
        [0] .
       *[other] ; entre les imatges, els termes de les equacions { $span ->
            [1] del pas { $first }
            [2] dels passos { $first } i { $last }
           *[other] dels passos { $first } a { $last }
        } ({ $format ->
            [md] {""}
           *[other] negre:{" "}
        }normals i tangencials, relatius i de Coriolis), l’un darrere l’altre.
    }
fig-level_a_relative = Polígon d’acceleracions, a escala: des del pol o, l’acceleració de cada punt{ $format ->
        [md] {""}
       *[other] {" "}(blau)
    } acaba a la seva imatge, amb la lletra del punt{ $image ->
        [0] {""}
       *[other] {" "}({ $image } per a { $point })
    }{ $between ->
        [0] .
       *[other] ; entre les imatges, els termes de les equacions { $span ->
            [1] del pas { $first }
            [2] dels passos { $first } i { $last }
           *[other] dels passos { $first } a { $last }
        } ({ $format ->
            [md] {""}
           *[other] negre:{" "}
        }normals i tangencials, i relatius), l’un darrere l’altre.
    }
fig-level_a_normal = Polígon d’acceleracions, a escala: des del pol o, l’acceleració de cada punt{ $format ->
        [md] {""}
       *[other] {" "}(blau)
    } acaba a la seva imatge, amb la lletra del punt{ $image ->
        [0] {""}
       *[other] {" "}({ $image } per a { $point })
    }{ $between ->
        [0] .
       *[other] ; entre les imatges, els termes de les equacions { $span ->
            [1] del pas { $first }
            [2] dels passos { $first } i { $last }
           *[other] dels passos { $first } a { $last }
        } ({ $format ->
            [md] {""}
           *[other] negre:{" "}
        }normals i tangencials), l’un darrere l’altre.
    }
col-number = núm.

# higher pairs (joints.contact, curved_slot, cam)
shape-curveshape = corba
shape-camshape = lleva
joint-contact = contacte (parell superior)
joint-curved_slot = passador en ranura corba
joint-cam = lleva i seguidor
cond-contact = contacte: { $a } i { $b } es mantenen en contacte; poden lliscar segons la tangent comuna.
cond-curved_slot = passador { $point } en ranura corba: la seva velocitat relativa al sòlid amb ranura segueix la tangent de la ranura.
cond-cam = lleva: el seguidor { $b } es manté en contacte amb la lleva { $a }.
dir-tangent = tangent a { $point }
dir-centre = cap al centre de curvatura { $point }
higher-intro = El parell superior s’escriu com el moviment { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } per la seva trajectòria relativa a { $holder } (una ranura segons la tangent, corba de radi { $radius }): l’acceleració relativa té una part normal v²/ρ cap al centre de curvatura de la trajectòria.
higher-straight = El parell superior s’escriu com el moviment { ELISION($point) ->
        [vowel] d’{ $point }
       *[other] de { $point }
    } per una trajectòria recta relativa a { $holder } (una ranura segons la tangent).
centre-weld = { $body } i { $other } són solidaris: són un sol sòlid rígid, de manera que el CIR és el { ELISION($other) ->
        [vowel] d’{ $other }
       *[other] de { $other }
    }, { $same },
centre-line-kennedy = la recta que passa per { $l } (Aronhold–Kennedy, tercer sòlid { $k })
centre-line-moves = la perpendicular a { $v } per { $point } ({ $point } es mou amb { $body }, que { COUNT($body) ->
        [many] giren
       *[one] gira
    } al voltant { ELISION($pivot) ->
        [vowel] d’{ $pivot }
       *[other] de { $pivot }
    })
centre-line-rolls = la perpendicular a { $v } per { $point } ({ $roller } no { COUNT($roller) ->
        [many] llisquen
       *[one] llisca
    } sobre { $on }, de manera que el punt { $point } de { $b } té la velocitat de { $body } en aquest punt, i { $body } { COUNT($body) ->
        [many] giren
       *[one] gira
    } al voltant { ELISION($pivot) ->
        [vowel] d’{ $pivot }
       *[other] de { $pivot }
    })
centre-line-rolls_still = la perpendicular a { $v } per { $point } ({ $roller } no { COUNT($roller) ->
        [many] llisquen
       *[one] llisca
    } sobre { $on }, de manera que el punt { $point } de { $b } té la velocitat de { $body }, que es { COUNT($body) ->
        [many] traslladen
       *[one] trasllada
    })
centre-line-moves_still = la perpendicular a { $v } per { $point } ({ $point } es mou amb { $body }, que es { COUNT($body) ->
        [many] traslladen
       *[one] trasllada
    })
centre-line-guide = la perpendicular a la guia per { $pivot } (a { $pivot }′, el peu de la perpendicular des de { $pivot } a la guia, la velocitat relativa { ELISION($body) ->
        [vowel] a l’{ $body }
       *[other] a { $body }
    } és paral·lela a la guia i la d’arrossegament és perpendicular a { $pivot }{ $pivot }′, és a dir, també paral·lela a la guia: la velocitat del punt { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    } a { $pivot }′ segueix la guia)
centre-carried-slip = {" "}({ $b } no { COUNT($b) ->
        [many] llisquen
       *[one] llisca
    } sobre { $body }, de manera que el seu punt { $point } té la velocitat de { $body } en aquest punt)
centre-carried-between = { $p } es mou amb { $k1 } al voltant { ELISION($c1) ->
        [vowel] d’{ $c1 }
       *[other] de { $c1 }
    }{ $why1 }, i { $q } amb { $k2 } al voltant { ELISION($c2) ->
        [vowel] d’{ $c2 }
       *[other] de { $c2 }
    }{ $why2 }: totes dues velocitats respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } són perpendiculars a la recta que passa per { $p } i { $q }, de manera que el CIR és en aquesta recta; en ella les velocitats són proporcionals a la distància al CIR: { $p } es mou amb { $vp } i { $q } amb { $vq }, en sentits oposats, de manera que el CIR és entre tots dos, on la velocitat s’anul·la:
# the construction repeated for a body symmetric to one done: referred to (twenty-ninth round b)
centre-carried_as = com per a { $first }, és a la recta que passa per { $p } i { $q }, a { $dist } { ELISION($near) ->
        [vowel] d’{ $near }
       *[other] de { $near }
    }:
centre-carried-between_from = { $p } es mou amb { $k1 } al voltant { ELISION($c1) ->
        [vowel] d’{ $c1 }
       *[other] de { $c1 }
    }{ $why1 }, i { $q } amb { $k2 } al voltant { ELISION($c2) ->
        [vowel] d’{ $c2 }
       *[other] de { $c2 }
    }{ $why2 }: totes dues velocitats respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } són perpendiculars a la recta que passa per { $p } i { $q }, de manera que el CIR és en aquesta recta; en ella les velocitats són proporcionals a la distància al CIR: { $p } es mou amb { $vp } i { $q } amb { $vq }, en sentits oposats, de manera que el CIR és entre tots dos, on la velocitat s’anul·la, a { $dist } { ELISION($near) ->
        [vowel] d’{ $near }
       *[other] de { $near }
    }:
centre-carried-outside = { $p } es mou amb { $k1 } al voltant { ELISION($c1) ->
        [vowel] d’{ $c1 }
       *[other] de { $c1 }
    }{ $why1 }, i { $q } amb { $k2 } al voltant { ELISION($c2) ->
        [vowel] d’{ $c2 }
       *[other] de { $c2 }
    }{ $why2 }: totes dues velocitats respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } són perpendiculars a la recta que passa per { $p } i { $q }, de manera que el CIR és en aquesta recta; en ella les velocitats són proporcionals a la distància al CIR: { $p } es mou amb { $vp } i { $q } amb { $vq }, en el mateix sentit, de manera que el CIR és més enllà del més lent, on la velocitat s’anul·la:
centre-carried-outside_from = { $p } es mou amb { $k1 } al voltant { ELISION($c1) ->
        [vowel] d’{ $c1 }
       *[other] de { $c1 }
    }{ $why1 }, i { $q } amb { $k2 } al voltant { ELISION($c2) ->
        [vowel] d’{ $c2 }
       *[other] de { $c2 }
    }{ $why2 }: totes dues velocitats respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    } són perpendiculars a la recta que passa per { $p } i { $q }, de manera que el CIR és en aquesta recta; en ella les velocitats són proporcionals a la distància al CIR: { $p } es mou amb { $vp } i { $q } amb { $vq }, en el mateix sentit, de manera que el CIR és més enllà del més lent, on la velocitat s’anul·la, a { $dist } { ELISION($near) ->
        [vowel] d’{ $near }
       *[other] de { $near }
    }:
centre-line-slot = la normal a la ranura per { $point } (respecte del sòlid ranurat, { $point } només es pot moure al llarg de la ranura)
centre-line-slot_fixed = la normal a la recta { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    } per { $point }, el punt que hi llisca
centre-line-wheel = l’eix de la roda { $joint }, la normal al seu pla a { $point } (no llisca lateralment)
centre-field = és a la perpendicular a { $v } per { $q }, a la distància { $arm } = |{ $v }| / |{ $w }| = { $dist } { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }, { $side }, de manera que el CIR és
centre-rate = a partir de { $w } (trobada a «{ sec-velocities }» a través { ELISION($line) ->
        [vowel] d’{ $line }
       *[other] de { $line }
    }): és a la perpendicular a { $v } per { $q }, a la distància { $arm } = |{ $v }| / |{ $w }| = { $dist } { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }, { $side }, de manera que el CIR és
centre-rate_step = a partir de { $w } (trobada al pas { $step } a través { ELISION($line) ->
        [vowel] d’{ $line }
       *[other] de { $line }
    }): és a la perpendicular a { $v } per { $q }, a la distància { $arm } = |{ $v }| / |{ $w }| = { $dist } { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }, { $side }, de manera que el CIR és
# the side of a point a centre lies on, named (centre-field: below A, to the left of A)
side-above = per sobre { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }
side-below = per sota { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }
side-left = a l’esquerra { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }
side-right = a la dreta { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }
side-above_left = per sobre i a l’esquerra { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }
side-above_right = per sobre i a la dreta { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }
side-below_left = per sota i a l’esquerra { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }
side-below_right = per sota i a la dreta { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }
centre-check = Comprovació amb les velocitats trobades a «{ sec-velocities }»: a la perpendicular a { $v } per { $q }, a la distància { $arm } = |{ $v }| / |{ $w }| = { $dist } { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }, { $side }, el mateix punt: { $centre } és { $where }
sec-centres_v = CIR trobats a partir de les velocitats
how-centre_infinity = (es trasllada: el seu CIR { $centre } és a l’infinit)
how-constant_rate = ({ $sym } = { $value } és constant: { $line } conserva la seva longitud, i la seva velocitat angular la fixen els radis i { $rates }, que és constant)
how-constant_speed = ({ $point } recorre la circumferència de radi { $line } = { $length } centrada a { $centre } amb la celeritat constant { $v } = { $speed }, de manera que { $sym } = { $value } és constant)
idle-rolling = { $body } rodola sense lliscar sobre { $fixed }: el punt de contacte { $point } n’és el CIR, de manera que:
idle-symmetry = { $body } té la mateixa disposició que { $like } (el mateix radi, els mateixos enllaços amb els mateixos sòlids): per simetria gira igual:
idle-unused = { $bodies } no { $count ->
        [one] intervé
       *[other] intervenen
    } en la pregunta: cap pas no necessita { $count ->
        [one] la seva velocitat angular
       *[other] les seves velocitats angulars
    }.
how-tangent = (es manté { WORD($way) ->
        [vertical] vertical
        [horizontal] horitzontal
       *[other] paral·lel a si mateix
    }, tangent a { $a } i a { $b }: es trasllada, i tots els seus punts tenen la mateixa velocitat)
how-glides = ({ $p } i { $q } es mouen sempre sobre la recta { $line }: el sòlid es trasllada al llarg d’aquesta recta, sense girar)
how-parallel_paths = ({ $p } i { $q } es mantenen sempre a una altura igual al radi de la seva roda sobre el terra pla, de manera que es mouen sobre rectes paral·leles: el sòlid es trasllada, sense girar)
how-translates_always = (es trasllada en tot instant, com s’ha vist a les velocitats)
centres-found_above = { $centre } = { $value }: trobat a «{ sec-velocities }», al pas de velocitats { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }.
centres-witness = { ELISION($name) ->
        [vowel] d’{ $name }
       *[other] de { $name }
    }
centres-placed_in_step = { $centre }: trobat al pas { $step }, a partir de les velocitats { $points }.
centres-found_above_step = { $centre }: trobat al pas { $step }, amb les velocitats { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }.
centre-site = { $point } és el CIR { $centre } de { $body } respecte de { $frame }, trobat a «{ sec-centres }»: { $sym } = 0.
centre-site_s = { $centre }, trobat a «{ sec-centres }», no té velocitat: { $sym } = 0.
centre-site_here = { $point } és el CIR { $centre } de { $body } respecte de { $frame }, trobat just abans: { $sym } = 0.
centre-site_s_here = { $centre }, trobat just abans, no té velocitat: { $sym } = 0.
sec-contact = Punts de contacte
geom-rule = La regla de tot contacte de rodolament: la condició de no lliscament es compleix a cada instant al punt geomètric de contacte (aquí { $geom }), que es mou; derivant-la al llarg d’aquest punt s’obté { $rule }: les components tangencials de les dues acceleracions són iguals i les normals difereixen en aquest terme, segons la normal comuna. Cal la velocitat del punt geomètric:
geom-bar = { $geom }, el punt geomètric de contacte, no pertany a cap dels dos sòlids: és sempre a la recta dels centres { $c1 } i { $c2 }, amb { $part }/{ $whole } = { $ratio }, i es mou com un punt d’una barra articulada a { $c1 } i { $c2 }:
geom-bar_told = { $geom }, el punt geomètric de contacte, és sempre a la recta dels centres { $c1 } i { $c2 }, amb { $part }/{ $whole } = { $ratio }, i es mou com un punt d’una barra articulada a { $c1 } i { $c2 }:
geom-foot = { $geom }, el punt geomètric de contacte, és el peu de la perpendicular des del centre { $centre } a la recta { ELISION($line) ->
        [vowel] d’{ $line }
       *[other] de { $line }
    }: { $radius } és un radi, perpendicular a la recta, i gira amb ella:
contact-intro = Al contacte { $point } coincideixen tres punts amb cinemàtiques diferents: el punt { ELISION($a) ->
        [vowel] d’{ $a }
       *[other] de { $a }
    }, el punt { ELISION($b) ->
        [vowel] d’{ $b }
       *[other] de { $b }
    } i el punt geomètric de contacte { $geom }, que no pertany a cap dels dos.
contact-above = { $sym } = { $value }, obtinguda a «{ sec-accelerations }» per a l’acceleració del contacte.
contact-written_centre = { $sym } = { $value }, trobada al pas { $step }: { $point } és el CIR { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }.
contact-written = { $sym } = { $value }, trobada al pas { $step }.
contact-fixed = { $sym }: { $point } com a punt { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }{ FIXED($body) ->
        [yes] {""}
       *[no] , que és fix,
    } no es mou: { $sym } = 0.
fig-step_v = Polígon de velocitats d’aquest pas, a escala: des del pol o, la velocitat de cada punt{ $format ->
        [md] {""}
       *[other] {" "}(blau)
    } acaba a la seva imatge, amb la lletra del punt{ $between ->
        [0] .
       *[other] ; entre les imatges, els termes de les equacions d’aquest pas{ $format ->
            [md] {""}
           *[other] {" "}(negre)
        }, l’un darrere l’altre.
    }
fig-step_a = Polígon d’acceleracions d’aquest pas, a escala: des del pol o, l’acceleració de cada punt{ $format ->
        [md] {""}
       *[other] {" "}(blau)
    } acaba a la seva imatge, amb la lletra del punt{ $between ->
        [0] .
       *[other] ; entre les imatges, els termes de les equacions d’aquest pas{ $format ->
            [md] {""}
           *[other] {" "}(negre)
        }, l’un darrere l’altre.
    }
col-point = punt
col-what = què és
what-centre = centre { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    }
what-joint = { $kind } entre { $a } i { $b }
what-touching = el punt { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } on toca { $other }
what-contact = punt de contacte ({ $kind }) entre { $a } i { $b }
what-body = un punt { $bodies }
what-of = { ELISION($name) ->
        [vowel] d’{ $name }
       *[other] de { $name }
    }
note-text = Nota: { $text }
sec-checks = Comprovacions
check-willis = Fórmula de Willis: vista des { ELISION($carrier) ->
        [vowel] d’{ $carrier }
       *[other] de { $carrier }
    }, el tren és ordinari ({ $carrier } porta l’eix de { $planet }, que engrana amb { $s1 } i amb { $s2 }, { $fixed ->
        [0] que giren al voltant de l’eix fix que passa per { $axis }
       *[other] l’eix de les quals és l’eix fix que passa per { $axis }
    }), de manera que { $formula } = { $radii } = { $train }{ $r1 ->
        [0] {""}
       *[other] , amb { $r1 } i { $r2 }
    }. Amb les velocitats angulars trobades a «{ sec-velocities }», { $values } = { $ratio }: coincideixen.
check-belt = Vista des { ELISION($holder) ->
        [vowel] d’{ $holder }
       *[other] de { $holder }
    }, que porta els dos eixos, { $line } no llisca ni sobre { $a } ni sobre { $b }: { $equation }, de manera que { $ratio }; amb les velocitats angulars trobades a «{ sec-velocities }», { $values }: coincideixen.
pair-relation_v = Vistos des { ELISION($holder) ->
        [vowel] d’{ $holder }
       *[other] de { $holder }
    }, que porta els dos eixos, els eixos són fixos: { $a } i { $b } giren al seu voltant i no llisquen entre si, de manera que { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(amb { $radii })
    }:
pair-relation = Vistos des { ELISION($holder) ->
        [vowel] d’{ $holder }
       *[other] de { $holder }
    }, que porta els dos eixos, els eixos són fixos: { $a } i { $b } giren al seu voltant i no llisquen entre si, de manera que { $equation } a cada instant; derivant, amb els radis constants, { $derived }{ $radii ->
        [0] {""}
       *[other] {" "}(amb { $radii })
    }:
drive-relation_a = Derivant, amb els radis constants: { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(amb { $radii })
    }:
drive-relation = Vistos des { ELISION($holder) ->
        [vowel] d’{ $holder }
       *[other] de { $holder }
    }, que porta els dos eixos, els eixos són fixos i el tram recte { ELISION($line) ->
        [vowel] d’{ $line }
       *[other] de { $line }
    } es trasllada: no llisca sobre { $a } ni sobre { $b }, de manera que les seves perifèries tenen la mateixa velocitat, { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}(amb { $radii })
    }:
check-train = La relació de la transmissió és el producte de les de les seves etapes: { $ratio }; amb les velocitats angulars trobades a «{ sec-velocities }», la relació val { $value }.
check-quick = Raó de temps del retorn ràpid: { $lever } és en un extrem de la seva oscil·lació quan la ranura és tangent a la circumferència { ELISION($pin) ->
        [vowel] d’{ $pin }
       *[other] de { $pin }
    } (la manovella { $o2 }{ $pin } perpendicular a { $o4 }{ $pin }), on cos θ = { $o2 }{ $pin } / { $o2 }{ $o4 } = { $r } / { $d }, θ = { $theta }. Girant uniformement, { $crank } escombra 360° − 2θ = { $slow } en una carrera i 2θ = { $fast } en l’altra: raó de temps { $ratio }.
driver-slide = Dada: la velocitat de lliscament a l’enllaç prismàtic { $joint } és { $value }.
driver-slide_accel = Dada: l’acceleració de lliscament a l’enllaç prismàtic { $joint } és { $value }.
centre-line-normal = la normal comuna al contacte { $point } (els sòlids llisquen l’un sobre l’altre: cap velocitat relativa segons ella)
# un CIR a partir de dues velocitats paral·leles i perpendiculars a la recta dels seus punts (la construcció proporcional dels apunts)
centre-parallel-between = els punts { $p } i { $q } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } es mouen, respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }, amb { $sp } = { $vp } i { $sq } = { $vq }, totes dues perpendiculars a la recta que passa per { $p } i { $q }. Al llarg d’aquesta recta la velocitat varia linealment, proporcional a la distància al CIR, i aquestes dues tenen sentits oposats, de manera que el CIR és entre tots dos, on la velocitat s’anul·la, a { $dist } { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }:
centre-parallel-outside = els punts { $p } i { $q } { ELISION($body) ->
        [vowel] d’{ $body }
       *[other] de { $body }
    } es mouen, respecte { ELISION($frame) ->
        [vowel] d’{ $frame }
       *[other] de { $frame }
    }, amb { $sp } = { $vp } i { $sq } = { $vq }, totes dues perpendiculars a la recta que passa per { $p } i { $q }. Al llarg d’aquesta recta la velocitat varia linealment, proporcional a la distància al CIR, i aquestes dues tenen el mateix sentit, de manera que el CIR és més enllà del més lent, on la velocitat s’anul·la, a { $dist } { ELISION($q) ->
        [vowel] d’{ $q }
       *[other] de { $q }
    }:
# a normal acceleration: its magnitude, then the vector with its direction (never a magnitude = a vector)
term-magnitude = { $mag } = { $how }, cap a { $point }: { $sym } = { $value }

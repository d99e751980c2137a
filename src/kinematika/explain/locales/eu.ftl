## `kinematika explain`-en euskarazko mezuak (ikastaroaren terminoak: abiadura,
## azelerazioa, arrastrea, erlatiboa). Giltza arteko markak bere horretan utzi.

sec-data = Datuak
data-numeric = Unitateak: luzerak { $unit }-tan, { $accelerations ->
        [0] abiadurak { $unit }/s-tan eta abiadura angeluarrak rad/s-tan.
       *[other] abiadurak { $unit }/s-tan, azelerazioak { $unit }/s²-tan, abiadura angeluarrak rad/s-tan eta azelerazio angeluarrak rad/s²-tan.
    }
data-planar = Mugimendu laua: { $accelerations ->
        [0] abiadura angeluarrek
       *[other] abiadura eta azelerazio angeluarrek
    } zeinua dute, positiboak erlojuaren orratzen aurkako noranzkoan.
data-relative = Magnitude erlatibo baten notazioak bi solidoak adierazten ditu: { $v } { $body_b } solidoaren { $point } puntuaren abiadura da { $body_a } solidotik ikusita{ WORD($rate) ->
        [yes] , eta { $w } { $body_b } solidoaren abiadura angeluarra { $body_a } solidoarekiko.
       *[no] .
    }
data-spatial = Abiadura eta azelerazio angeluarrak bektoreak dira (eskuineko eskuaren araua beren norabidearen inguruan).
data-symbolic = Datuak ikurrak dira eta emaitzak formula gisa ematen dira; irudiak ikurren balio jakin batzuekin marraztu dira, irudi bakoitzaren azpian emanak.
data-symbol = ikur bat (edozein balio)
data-constructed = eraikuntzaz kokatua (ikus Posizioa)
data-circles = zentroa { $centre }, erradioak { $radii }
data-circle = zentroa { $centre }, erradioa { $radius }
data-line = { $through } puntutik, { $direction } norabidean
data-plane = { $through } puntutik, { $direction } normalarekin
col-symbol = ikurra
col-value = balioa
col-position = posizioa
col-shape = forma
col-given = datuak
sec-structure = Egitura
col-body = solidoa
col-points = puntuak
col-joint = lotura
col-bodies = solidoak
col-where = non
col-omega = abiadura angeluarra
col-alpha = azelerazio angeluarra
col-question = galdera
col-answer = erantzuna
structure-subscripts = Notazioa: { $pairs }.
rate-precession = prezesioa
structure-subscript_pair = { $sym } { $body } solidoaren abiadura angeluarra da
# a relative rate the model's notation writes otherwise (C5-2.1's δ̇ for ω_{fork rel chassis}): defined where the notation line is (twenty-eighth round d)
structure-subscript_noted_rel = { $sym } { $body } solidoaren abiadura angeluarra da { $other } solidoarekiko
structure-subscript_drag = { $equal } { $point } puntuaren arrastre-{ WORD($kind) ->
        [accel] azelerazioa
       *[speed] abiadura
    } da
structure-subscript_member = { $sym } { $body } solidoaren { $point } puntuarekin bat datorren puntuaren abiadura da
structure-subscript_rel = { $sym } { $body } solidoaren { WORD($kind) ->
        [rate2] azelerazio angeluarra
        [speed] { $point } puntuaren abiadura
        [accel] { $point } puntuaren azelerazioa
       *[rate] abiadura angeluarra
    } da { $other } solidoarekiko («rel» hitzaz lotutako bi izen: lehen solidoa bigarrenarekiko)
structure-shaped = { $body }, { $radius } erradioko { $shape }
# a body with several round shapes: its welded wheels, said once (twenty-ninth round b)
structure-shaped_welded = { $body }, { $radii } erradioko { $n ->
        [2] bi
       *[other] { $n }
    } gurpil solidario
# the fixed body with no shape: its own name, marked fixed; the text names it so wherever it is a reference (twenty-seventh round e)
structure-frame_named = { $body } (finkoa)
structure-welded = { $bodies } { $frame } solidoari zurrunki lotuta { $bodies_n ->
        [one] dago: haren zati da eta ez da mugitzen
       *[other] daude: haren zati dira eta ez dira mugitzen
    }; { $bodies_n ->
        [one] haren
       *[other] haien
    } puntu guztien abiadura eta azelerazioa nuluak dira.
structure-contacts_wheel = { $points_n ->
        [one] { $points } puntuaren azpiko kontaktu-puntua
       *[other] { $points } puntuen azpiko kontaktu-puntuak
    }
structure-contacts_rolling = { $points_n ->
        [one] { $points } (kontaktu-puntua)
       *[other] { $points } (kontaktu-puntuak)
    }
# the frame's row names the parts welded to it: they are the frame (twenty-ninth round b)
structure-frame_parts = { $body }, { $parts } barne
structure-fixed_part = { $body } ({ $frame } solidoari zurrunki lotuta: finkoa)
structure-dof = Mekanismoak { $dof ->
        [one] askatasun-gradu bat du
        [2] bi askatasun-gradu ditu
        [3] hiru askatasun-gradu ditu
       *[other] { $dof } askatasun-gradu ditu
    }.
structure-dof_data = Mekanismoak { $dof ->
        [one] askatasun-gradu bat du
        [2] bi askatasun-gradu ditu
        [3] hiru askatasun-gradu ditu
       *[other] { $dof } askatasun-gradu ditu
    }, datu bakoitzeko bat ({ $data }).
shape-concentric = { $n ->
        [2] bi zirkunferentzia zentrokide
       *[other] { $n } zirkunferentzia zentrokide
    }
shape-circle = zirkunferentzia
shape-line = zuzena
shape-disc = diskoa
shape-plane = planoa
joint-revolute = giltzadura (R)
joint-prismatic = prismatikoa (P)
joint-revolute_word = giltzadura
joint-prismatic_word = lotura prismatikoa
joint-slot = ziria arteka batean
joint-slot_fixed = zuzen finko bateko irristadurazko kontaktua
joint-wheel = gurpila (alboko irristarik gabe)
joint-rolling = errodadura
joint-gear = engranajea
joint-weld = lotura zurruna
joint-spherical = esferikoa
joint-cylindrical = zilindrikoa
along-joint = { WORD($verb) ->
        [only] norabidea: { $dir }
        [rolls] { $point } puntuko gurpila errodatu egiten da; norabidea: { $dir }
       *[slides] { $point } puntua irristatu egiten da; norabidea: { $dir }
    }
along-horizontal = horizontala
along-vertical = bertikala
along-angle = { $vec }, horizontalarekiko { $deg }°
along-vector = { $vec }
along-line = { $line }
fig-arrow-velocity = { $point } puntuaren abiadura
fig-arrow-drag = arrastre-abiadura ({ $sym })
fig-arrow-relative = abiadura erlatiboa ({ $sym })
fig-own_drag = { $point } puntuaren abiadura eta arrastre-abiadura ({ $sym })
fig-rest = ; { $count ->
        [one] { $points } puntuaren abiadura nulua da une honetan{ $centre }, ondoan idatzita
       *[other] { $points } puntuen abiadura nulua da une honetan, ondoan idatzita
    }
fig-contact = { $point } kontaktuan une honetan bat datozen hiru puntuak, mekanismoaren gainean eskalan: { $a } solidoaren puntua, { $b } solidoaren puntua eta { $geom } kontaktu-puntu geometrikoa. { $moving ->
        [0] {""}
        [one] { $format ->
            [md] Gezia
           *[other] Gezi { $accel ->
                [0] urdina
               *[other] gorria
            }
        } { $arrows } da{ $moduli ->
            [0] {""}
            [2] {", bere moduluarekin ("}{ $unit }-tan)
           *[other] {", bere moduluarekin"}
        }
       *[other] { $format ->
            [md] Geziak
           *[other] Gezi { $accel ->
                [0] urdinak
               *[other] gorriak
            }
        } { $arrows } dira, eskala berean{ $moduli ->
            [0] {""}
            [2] {", beren moduluekin ("}{ $unit }-tan)
           *[other] {", beren moduluekin"}
        }
    }{ $still ->
        [0] .
        [one] { $moving ->
            [0] {""}
           *[other] {"; "}
        }{ $zeros } nulua da, { $point } puntuaren ondoan idatzita.
       *[other] { $moving ->
            [0] {""}
           *[other] {"; "}
        }{ $zeros } nuluak dira, { $point } puntuaren ondoan idatzita.
    }
fig-mechanism = Mekanismoa une honetan, eskalan{ $dim ->
        [3] , proiekzio isometrikoan (x, y, z ardatzak behean eskuinean)
       *[other] {""}
    }; { $arrows ->
        [0] ez da abiadurarik marrazten
        [1] { $format ->
            [md] gezia
           *[other] gezi urdina
        } { $points } puntuaren abiadura da{ $moduli ->
            [0] {""}
            [2] {", bere moduluarekin ("}{ $unit }/s-tan)
           *[other] {", bere moduluarekin"}
        }
        [3] { $points } puntuaren abiadura nulua da une honetan{ $centre }, ondoan idatzita
        [4] { $format ->
            [md] geziak
           *[other] gezi urdinak
        } { $points } dira, eskala berean{ $moduli ->
            [0] {""}
            [2] {", beren moduluekin ("}{ $unit }/s-tan)
           *[other] {", beren moduluekin"}
        }
       *[other] { $format ->
            [md] geziak
           *[other] gezi urdinak
        } { $points } puntuen abiadurak dira, eskala berean{ $moduli ->
            [0] {""}
            [2] {", beren moduluekin ("}{ $unit }/s-tan)
           *[other] {", beren moduluekin"}
        }
    }{ $rest }; solidoak zenbakituta daude.
fig-rest_centre = {" "}({ $body } solidoaren biraketa-zentro instantaneoa da)
fig-mechanism_named = Mekanismoa une honetan, eskalan{ $dim ->
        [3] , proiekzio isometrikoan (x, y, z ardatzak behean eskuinean)
       *[other] {""}
    }; { $arrows ->
        [0] ez da abiadurarik marrazten
        [1] { $format ->
            [md] gezia
           *[other] gezi urdina
        } { $points } puntuaren abiadura da{ $moduli ->
            [0] {""}
            [2] {", bere moduluarekin ("}{ $unit }/s-tan)
           *[other] {", bere moduluarekin"}
        }
        [3] { $points } puntuaren abiadura nulua da une honetan{ $centre }, ondoan idatzita
        [4] { $format ->
            [md] geziak
           *[other] gezi urdinak
        } { $points } dira, eskala berean{ $moduli ->
            [0] {""}
            [2] {", beren moduluekin ("}{ $unit }/s-tan)
           *[other] {", beren moduluekin"}
        }
       *[other] { $format ->
            [md] geziak
           *[other] gezi urdinak
        } { $points } puntuen abiadurak dira, eskala berean{ $moduli ->
            [0] {""}
            [2] {", beren moduluekin ("}{ $unit }/s-tan)
           *[other] {", beren moduluekin"}
        }
    }{ $rest }.
fig-at_pole = { $count ->
    [one] { $images } o poloan dago, { $zero } baita.
   *[other] { $images } o poloan daude, { $zero } baita.
}
fig-moved_aside = Beste gezi baten gainean legokeen terminoa haren alboan marrazten da, paraleloan eta eskalan; { $format ->
        [md] marra etenek
       *[other] marra eten grisek
    } haren muturrak lotzen dituzte bere bi puntuekin.
fig-too_short = { $count ->
    [one] { $terms } laburregia da eskala honetan ikusteko (gezi-punta bat baino laburragoa); haren balioa testuan dago.
   *[other] { $terms } laburregiak dira eskala honetan ikusteko (gezi-punta bat baino laburragoak); haien balioak testuan daude.
}
fig-o_prime = O puntuaren irudia o′ izendatzen da, o letrak poloa izendatzen baitu.
fig-o_prime_named = o′, O-ren irudia,
fig-o_prime_fixed = o′, { $body } solidoaren O puntu finkoaren irudia,
fig-centre_image = { $count ->
    [one] { $centre } zentroaren irudia
   *[other] { $centre } zentroen irudiak
}
fig-primed = { $point } puntuaren irudia { $image } da, { $symbol } { $what } baita.
fig-a_symbol = datu baten ikurra
fig-polygon_v = Abiaduren poligonoa, eskalan. Haren terminoak o polotik hasita bata bestearen ondoren marrazten dira{ $result ->
        [1] , eta haien baturak, { $sym } bektoreak, poligonoa ixten du
       *[other] {""}
    }{ $format ->
        [md] {""}
       *[other] {" "}(beltzez termino ezagunak{ $unknown ->
            [1] , gorriz urrats honetan aurkitutakoak
           *[other] {""}
        }{ $result ->
            [1] , urdinez batura
           *[other] {""}
        })
    }. Erpin bakoitza puntu baten irudia da.
fig-polygon_a = Azelerazioen poligonoa, eskalan. Haren terminoak o polotik hasita bata bestearen ondoren marrazten dira{ $result ->
        [1] , eta haien baturak, { $sym } bektoreak, poligonoa ixten du
       *[other] {""}
    }{ $format ->
        [md] {""}
       *[other] {" "}(beltzez termino ezagunak{ $unknown ->
            [1] , gorriz urrats honetan aurkitutakoak
           *[other] {""}
        }{ $result ->
            [1] , urdinez batura
           *[other] {""}
        })
    }. Erpin bakoitza puntu baten irudia da.
fig-sample = Ikurren lagin-balioekin marraztua.
sec-position = Posizioa
pos-intro = Posizio-analisia: puntu mugikor bakoitza enuntziatuak kokatzen duen moduan kokatzen da, aurretik kokatutako puntuetatik abiatuta.
pos-named = Hemen, { $name } = { $formula }.
pos-moved = Mekanismoa eskatutako mugimenduak eramaten duen lekuan aztertzen da; solido bakoitza marrazkitik honela eraman da.
pos-turn_angle = { $body } solidoak { $angle } biratu du { $pivot } puntuaren inguruan.
pos-turn_toward = { $body } solidoak { $line } zuzenak bezala biratu du.
pos-turn_shift = { $body } solidoa { $shift } mugitu da gidan zehar.
pos-carried = { $point } puntua { $body } solidoarekin mugitzen da: { $point } = { $at }.
pos-polar = { $point } puntua { $origin } puntutik { $distance } distantziara dago, x ardatzarekiko { $angle } angeluan: { $point } = { $at }.
pos-polar_ref = { $point } puntua { $origin } puntutik { $distance } distantziara dago, { $ref } norabidearekiko { $angle } angeluan: { $point } = { $at }.
pos-frame = { $point } puntua { $origin } puntutik { $x } distantziara dago { $line } zuzenean zehar, eta { $y } haren perpendikularrean, { $from } puntutik { $to } puntura begiratuta ezkerretara: { $point } = { $at }.
pos-frame_right = { $point } puntua { $origin } puntutik { $x } distantziara dago { $line } zuzenean zehar, eta { $y } haren perpendikularrean, { $from } puntutik { $to } puntura begiratuta eskuinetara: { $point } = { $at }.
pos-frame_on = { $point } puntua { $origin } puntutik { $x } distantziara dago { $line } zuzenean zehar: { $point } = { $at }.
pos-circles = { $point } puntua { $c1 } puntutik { $r1 } distantziara eta { $c2 } puntutik { $r2 } distantziara dago: bi zirkunferentziaren ebakidura, { $c1 } eta { $c2 } zentrodunak. Ebakitzen diren bi puntuetatik, { $which } da: { $point } = { $at }.
pos-circle_line = { $point } puntua { $c } puntutik { $r } distantziara dago, { $line } zuzenean: { $c } zentroko zirkunferentzia baten eta zuzen baten ebakidura. Ebakitzen diren bi puntuetatik, { $which } da: { $point } = { $at }.
pos-lines = { $point } puntua { $l1 } eta { $l2 } zuzenen ebakidura da: { $point } = { $at }.
pos-line_dir = { $through } puntutik { $dir } norabidean doan
pos-left = { $a } puntutik { $b } puntura begiratuta ezkerrean dagoena
pos-right = { $a } puntutik { $b } puntura begiratuta eskuinean dagoena
pos-upper = goikoa
pos-lower = behekoa
pos-leftmost = ezkerrekoa
pos-rightmost = eskuinekoa
pos-ahead = { $line } zuzenaren noranzkoan aurrerago dagoena
pos-behind = { $line } zuzenaren noranzkoan atzerago dagoena
pos-near = { $near } zirriborro-puntutik hurbilen dagoena
pos-touch = ukitzen diren puntu bakarra
pos-assembly = { $which } ({ $assembly })
pos-open = konfigurazio irekia: barrak ez dira gurutzatzen
pos-crossed = konfigurazio gurutzatua: barrak gurutzatzen dira

sec-order = Ebazpen-ordena
order-assur = Mekanismoa bere sarreretan eta bi elementuko taldeetan deskonposatzen da; bakoitza jadanik ezagunak diren solidoetatik ebazten da:
order-blocks = Solidoak ordena honetan ebazten dira, bakoitza jadanik ezagunak diren solidoetatik:
order-item = { $n }. { $kind }: { $bodies }, { $known } { $known_n ->
        [one] solidotik
       *[other] solidoetatik
    }.
order-item_group = { $n }. { $bodies }, { $known } { $known_n ->
        [one] solidotik
       *[other] solidoetatik
    }.
order-item_through = { $n }. { $kind }: { $bodies }, { $known } { $known_n ->
        [one] solidotik
       *[other] solidoetatik
    }, { $through } { $through_n ->
        [one] solidoaren
       *[other] solidoen
    } bidez.
order-item_group_through = { $n }. { $bodies }, { $known } { $known_n ->
        [one] solidotik
       *[other] solidoetatik
    }, { $through } { $through_n ->
        [one] solidoaren
       *[other] solidoen
    } bidez.
order-item_data = { $n }. { $kind }: { $bodies }, datuetatik.
order-item_group_data = { $n }. { $bodies }, datuetatik.
order-from = { $name }
kind-input = sarrera (solido eragilea)
kind-RRR = RRR loturak dituen bi elementuko taldea
kind-RRP = RRP loturak dituen bi elementuko taldea
kind-RPR = RPR loturak dituen bi elementuko taldea
kind-PRP = PRP loturak dituen bi elementuko taldea
kind-other = batera ebatzitako taldea
step-title = { $n }. urratsa: { $kind } — { $bodies }
step-title_group = { $n }. urratsa: { $bodies }
sec-velocities = Abiadurak
sec-accelerations = Azelerazioak
v-intro = Ekuazio bektorial bakoitza apunteetan bezala idazten da: M: modulua ezaguna; D: norabidea ezaguna; ?: ezezaguna (norabidea edo modulua); ⊥ eta ∥ ikurrek norabide ezaguna adierazten dute.{ $marks ->
        [1] { WORD($clash) ->
            [M] {" "}Hemen M letrak modulu ezaguna adierazten du; ez da M puntua.
           *[other] {" "}Hemen D letrak norabide ezaguna adierazten du; ez da D puntua.
        }
        [2] {" "}Hemen M eta D letrak marka hauek dira; ez dira M eta D puntuak.
       *[other] {""}
    } Planoko ekuazio bektorial batek bi ezezagun ebazten ditu{ $format ->
        [md] : urrats bakoitzean ? ikurraz markatutako terminoak
       *[other] : urrats bakoitzean gorriz idatzitako terminoak
    }.
a-intro = Abiadurak ezagunak direnez, termino normal guztiak eta Coriolisen termino guztiak ezagunak dira; ezezagunak termino tangentzialak eta erlatiboak dira.
a-intro_relative = Abiadurak ezagunak direnez, termino normal guztiak ezagunak dira; ezezagunak termino tangentzialak eta erlatiboak dira.
a-intro_normal = Abiadurak ezagunak direnez, termino normalak ezagunak dira; ezezagunak termino tangentzialak dira.
eq-shared_rate = { $terms } terminoek ezezagun bakarra dute, { $rate }: haien moduluak { $mags } dira; beraz, haien bi ? ikurrek ezezagun bakar bat adierazten dute, { $rate }.
a-named = Formula bat garatuta irakurtezina litzatekeen lekuan, «{ sec-velocities }» atalean aurkitutako abiadura angeluarrak izenez idazten dira: { $name } { $body } solidoaren ω-rako, eta horrela solido bakoitzerako.
driver-omega = Datua: { $sym } = { $value }.
driver-omega_sense = Datua: { $sym } = { $value }, { $faster ->
        [1] { $w } abiadura angeluarraren noranzko berean: { $body } azkartzen ari da
       *[other] { $w } abiadura angeluarraren aurkako noranzkoan: { $body } moteltzen ari da
    }.
# a point given no acceleration: said as the notes say it, it moves at constant velocity (twenty-ninth round a)
driver-steady = Datua: { $point } puntua abiadura konstantez mugitzen da ({ $sym } = 0).
# a body given no angular acceleration: it turns at a constant rate (twenty-ninth round a)
driver-omega_steady = Datua: { $body } abiadura angeluar konstantez biratzen da ({ $sym } = 0).
driver-velocity = Datua: { $sym } = { $value }.
driver-along = Datua: { $sym } bektorearen { $along } norabideko osagaia { $value } da.
driver-whole = Datua: { $sym } = { $value }, { $heading }.
driver-held = Une honetan { $b } solidoa ez da biratzen { $a } solidoarekiko { $point } giltzaduran: { $sym } = 0.
driver-held_accel = { $point } giltzadurak ez du azelerazio angeluar erlatiborik une honetan: { $sym } = 0.
heading-right = eskuinerantz
heading-left = ezkerrerantz
heading-up = gorantz
heading-down = beherantz
heading-along = { $along } norabidean
readoff-along_x = x norabidean:
readoff-along_y = y norabidean:
input-revolute = { $body } { $point } puntu finkoaren inguruan biratzen da: haren puntuek { $point } zentrodun zirkunferentziak deskribatzen dituzte.
input-prismatic = { $body } biratu gabe traslatzen da bere gidan zehar.
other-intro = Solido hauek batera ebazten dira beren loturen baldintzetatik:
cond-revolute = giltzadura { $point } puntuan: { $point } { $a } eta { $b } solidoen puntu bat da.
cond-prismatic = lotura prismatikoa: { $b } solidoa { $a } solidoaren gainean irristatzen da, harekiko biratu gabe.
cond-slot = { $point } ziria arteka batean: artekadun solidoarekiko abiadura artekaren norabidean dago.
cond-slot_fixed = { $b } solidoaren { $point } puntua { $a } solidoari lotutako zuzen batean zehar irristatzen da: haren abiadura zuzen horren norabidean dago.
cond-wheel = gurpila { $point } puntuan: ez dago alboko abiadurarik { $a } solidoarekiko.
cond-weld = { $a } eta { $b } solido bakar bat bezala mugitzen dira.
cond-spherical = lotura esferikoa { $point } puntuan: { $point } { $a } eta { $b } solidoen puntu bat da.
cond-cylindrical = lotura zilindrikoa: { $b } solidoa { $a } solidoaren ardatzaren inguruan biratzen eta haren luzeran irristatzen da.
rolling-noslip = { $gear ->
        [1] { $b } solidoak { $a } solidoarekin engranatzen du
       *[other] { $b } solidoa { $a } solidoaren gainean errodatzen da irristatu gabe
    }: { $point } kontaktuan bi puntu materialek abiadura bera dute.
rolling-noslip_edge = { $b } solidoa ez da irristatzen { $a } solidoaren gainean: { $point } kontaktuan bi puntu materialek abiadura bera dute.
rolling-same_edge = { $b } solidoa ez da irristatzen { $a } solidoaren gainean: { $point } kontaktuan bi puntu materialek abiadura bera dute, { $sym } = { $other }.
rolling-glide = { $b } solidoa irristatu gabe errodatzen da { $a } solidoaren ertzaren gainean. { $a } solidotik ikusita, haren { $centre } zentroak ertzarekiko distantzia mantentzen du: { $point } puntuko ukitzailearen zuzen paralelo batean zehar mugitzen da. { $a } solidoarekin batera biratzen duten ardatzak { $b } solidoaren { $centre } zentroan definituz, { $centre } puntuaren mugimendua arrastre-mugimendua ({ $a } solidoaren bertako puntuarena) gehi zuzen horretako mugimendu erlatiboa da (eta, azelerazioetan, Coriolisen terminoa).
rolling-kept = kontaktua mantentzen da: { $point } puntuan { $b } eta { $a } solidoen puntu materialen azelerazioak normal komunaren norabideko termino batean baino ez dira desberdinak; ez dago Coriolisen terminorik, errodadura-kontaktu batean bi puntuek ez baitute abiadura erlatiborik: { $vrel } = 0.
path-circle = { $b } solidoa irristatu gabe errodatzen da { $a } solidoaren gainean, eta { $a } ez da mugitzen. Haren { $centre } zentroak { $a } solidoarekiko distantzia mantentzen du: { $o } zentroko eta { $radius } erradioko zirkunferentzia deskribatzen du; beraz, { $ac } azelerazioak { $vs }² / { $radius } osagai normala du, { $o } aldera; eta une oro { $vc } = { $w } × { $arm } denez ({ $point } kontaktua biraketa-zentro instantaneoa da), haren osagai tangentziala { $al } × { $arm } da.
path-found = { $b } solidoa irristatu gabe errodatzen da { $a } solidoaren gainean, eta { $a } ez da mugitzen. { $step }. urratsean aurkitutako { $ac } azelerazioak { $vs }² / { $radius } osagai normala du, { $o } aldera, eta osagai tangentziala { $al } × { $arm } da, une oro { $vc } = { $w } × { $arm } baita ({ $point } kontaktua biraketa-zentro instantaneoa da).
path-line = { $b } solidoa irristatu gabe errodatzen da { $a } solidoaren gainean, eta { $a } ez da mugitzen. Haren { $centre } zentroak { $a } solidoarekiko distantzia mantentzen du: zuzen bat deskribatzen du, azelerazio normalik gabe; eta une oro { $vc } = { $w } × { $arm } denez ({ $point } kontaktua biraketa-zentro instantaneoa da), haren azelerazioa osagai tangentziala da soilik: { $ac } = { $at } = { $al } × { $arm }.
rolling-equal = Irristadurarik ez { $point } kontaktuan: { $sym } = { $other }.
rolling-same = { $gear ->
        [1] { $b } solidoak { $a } solidoarekin engranatzen du
       *[other] { $b } solidoa { $a } solidoaren gainean errodatzen da irristatu gabe
    }: { $point } kontaktuan bi puntu materialek abiadura bera dute, { $sym } = { $other }.
rolling-centre = { $gear ->
        [1] { $b } solidoak { $a } solidoarekin engranatzen du
       *[other] { $b } solidoa { $a } solidoaren gainean errodatzen da irristatu gabe
    }, eta { $a } solidoa ez da mugitzen: kontaktuko { $point } puntuak, { $b } solidoarenak, ez du abiadurarik, { $sym } = 0; beraz, { $b } solidoaren biraketa-zentro instantaneoa da.
dir-guide = { $holder } solidoaren gida
dir-normal_at = { $point } puntuko normala
how-prismatic = (lotura prismatikoa: biraketa erlatiborik gabe)
carry-anchor = Taldearen ebazpenetik: { $sym } = { $value }.
sense-ccw = erlojuaren orratzen aurkako noranzkoan
sense-cw = erlojuaren orratzen noranzkoan
sec-rates_summary = Abiadura eta azelerazio angeluarrak
sec-rates_summary_v = Abiadura angeluarrak
sec-centres = Biraketa-zentro instantaneoak
centres-intro = I ikurrak, bi solidoren zenbakiekin ({ $example }: 1 eta 3 solidoak), haien mugimendu erlatiboaren biraketa-zentro instantaneoa adierazten du: abiadura erlatiboa nulua den puntua.
centres-intro_named = I ikurrak, solido baten izena azpiindize duela, solido horren biraketa-zentro instantaneoa (BZI) adierazten du { $frame } solidoarekiko, hau da, { $frame } solidoarekiko abiadura nulua duen puntua (adibidez, { $pair } { $body } solidoarena da).
centres-intro_named_rel = I ikurrak, solido baten izena azpiindize duela, solido horren biraketa-zentro instantaneoa (BZI) adierazten du { $frame } solidoarekiko, hau da, { $frame } solidoarekiko abiadura nulua duen puntua (adibidez, { $pair } { $body } solidoarena da); «rel» hitzaz lotutako bi izenekin, lehen solidoarena bigarrenarekiko.
centre-line = { $centre }: { $why } { $where }
centre-joint-revolute = { $joint } giltzaduraren ardatza,
# a pin to the fixed body: a permanent centre; a strand's, where it is tied (twenty-ninth round b)
centre-joint-revolute_fixed = { $joint } ardatza, zentro iraunkorra,
centre-joint-revolute_tied = { $joint } puntua, { $body } { $frame } solidoari lotuta dagoen lekua, zentro iraunkorra,
centre-joint-rolling = { $joint } kontaktu-puntua (irristatu gabeko errodadura),
centre-joint-gear = zirkunferentzia primitiboen { $joint } kontaktua,
centre-joint-prismatic = lotura prismatikoa da: mugimendu erlatiboa translazio bat da eta BZIa gidaren perpendikularrean dago,
centre-joint-weld = bi solidoak zurrunki lotuta daude:
centre-kennedy = Aronhold–Kennedyren teoremaz, { $l1 } zentroetatik pasatzen den zuzenean dago ({ $k1 } hirugarren solidoa) eta { $l2 } zentroetatik pasatzen denean ({ $k2 } hirugarren solidoa); zuzen horiek { $far ->
        [1] paraleloak dira; beraz,
       *[other] ebakitzen dira
    }
centre-velocities = { $frame } solidoarekiko { $p } puntuaren abiadura, { $vp }, eta { $q } puntuarena, { $vq }, BZIarekin lotzen dituzten zuzenekiko perpendikularrak dira; perpendikularrak ebakitzen dira
centre-lines = bi zuzen hauetan dago: { $first }, eta { $second }; zuzen horiek { $far ->
        [1] paraleloak dira; beraz,
       *[other] ebakitzen dira
    }
centre-omega = «{ sec-velocities }» atalean aurkitutako abiadurekin, { $frame } solidoarekiko abiadura angeluarra nulua da: mugimendu erlatiboa translazio bat da eta BZIa
centre-at = { $point } puntuan.
centre-infinity = { $body } solidoa traslatzen da { $frame } solidoarekiko ({ $w } = 0): puntu guztiek { $v } abiadura dute; biraketa-zentro instantaneoa infinituan dago, { $v } abiadurarekiko norabide perpendikularrean.
centre-infinity_one = { $body } solidoa traslatzen da { $frame } solidoarekiko ({ $w } = 0): puntu guztiek abiadura bera dute; biraketa-zentro instantaneoa infinituan dago, abiadura horrekiko norabide perpendikularrean, { $direction }.
centre-rest = ez dago mugimendu erlatiborik.
sec-rates = Abiadura eta azelerazio angeluarrak
rates-intro = Solido bakoitza daraman solidoarekiko biratzen da: { $w }, eta, ardatz finkoetan deribatuz, { $a }.
rates-intro_v = Solido bakoitza daraman solidoarekiko biratzen da: { $w }.
fields-intro_v = Puntu bakoitzaren abiadura, solido bereko puntu ezagun batetik (bere loturatik):
fields-intro_a = Puntu bakoitzaren azelerazioa, solido bereko puntu ezagun batetik (bere loturatik):
sec-composition = Mugimenduen konposizioa
composition-intro = Puntu baten mugimendua arrastre-mugimendua da (erreferentzia mugikorrean puntuarekin bat datorren puntuarena) gehi erreferentzia horrekiko mugimendu erlatiboa, gehi, azelerazioetan, Coriolisen terminoa { $cor }.
composition-point = { $body } solidoaren { $point } puntua, { $frame } erreferentzia mugikorra:
composition-drag = { WORD($kind) ->
        [accel] { sec-accelerations }
       *[speed] { sec-velocities }
    }. Arrastrea:
composition-relative = Erlatiboa: { $sym }, { $frame } erreferentzia mugikorretik ikusten den mugimendua:
composition-rolls = { $body } solidoa { $frame } solidoaren gainean errodatzen da irristatu gabe { $point } puntuan: { $frame } solidotik ikusita, { $point } da { $body } solidoaren biraketa-zentro instantaneoa, { $sym } = 0, eta haren puntu guztiek haren inguruan biratzen dute.
sec-curvature = Ibilbideen kurbadura
curvature-intro = Azelerazioa bi zatitan banatzen da: abiaduraren norabideko zati tangentziala eta harekiko perpendikularra den zati normala; kurbadura-erradioa { $rho } da.
curvature-point = { $point } puntua: abiadura { $v }.
curvature-rest = { $point } puntuaren abiadura nulua da une honetan: haren ibilbideak ez du hor kurbadura-erradiorik (ℜ = |v|²/|aⁿ| abiadura bat behar du).
curvature-straight = { $point } puntuaren azelerazio normala nulua da: haren ibilbidea zuzena da hemen (edo inflexio-puntu bat du).
curvature-circle = { $point } puntua: { $o } puntu finkoarekiko distantzia mantentzen du; beraz, haren ibilbidea { $o } zentroko eta { $radius } erradioko zirkunferentzia da, eta kurbadura-erradioa erradio hori da:
curvature-circle_centre = { $point } puntuaren ibilbidearen kurbadura-zentroa { $o } puntua da, { $centre } posizioan.
curvature-centre = { $point } puntuaren ibilbidearen kurbadura-zentroa { $centre } puntuan dago, azelerazio normalaren aldean.
curvature-centre_from = { $point } puntuaren ibilbidearen kurbadura-zentroa { $where } dago.
curvature-named = { $d } = { $arm } = { $length } izanik, { $rho } = { $value }.
curvature-from = { WORD($side) ->
        [up] { $point } puntuaren gainetik { $rho } distantziara
        [down] { $point } puntuaren azpitik { $rho } distantziara
        [left] { $point } puntuaren ezkerretara { $rho } distantziara
        [right] { $point } puntuaren eskuinetara { $rho } distantziara
       *[other] { $point } puntutik { $rho } distantziara, { $an } azelerazioaren norabidean
    }
curvature-intrinsic = { $speed } izanik, ukitzaile unitarioa { $tangent } da; { $split }, { $tangential } izanik, eta { $rest }, { $normal }:
sec-answers = Erantzunak
answers-none = Ereduak ez du galderarik egiten.
ask-icr = { $body } solidoaren biraketa-zentro instantaneoa { $frame } solidoarekiko
ask-axis = { $body } solidoaren biraketa eta irristadura ardatz instantaneoa { $frame } solidoarekiko
ask-pole = { $body } solidoaren azelerazio-poloa { $frame } solidoarekiko
ask-inflection = { $body } solidoaren inflexio-zirkunferentzia eta polo-tangentea { $frame } solidoarekiko
ask-contact = { $joint } kontaktuan bat datozen hiru puntuak
ask-decompose = { $point } puntuaren mugimenduaren konposizioa, { $frame } erreferentzia mugikorra
ask-curvature = { $point } puntuaren ibilbidearen kurbadura-erradioa { $frame } solidoarekiko
ask-intrinsic = { $point } puntuaren azelerazio tangentziala eta normala { $frame } solidoarekiko
ans-rest = ez dago mugimendu erlatiborik
# an asked planar rate with its sense, as the notes ask it (“valor i sentit”: twenty-eighth round d)
ans-sensed = { $value } ({ $sense })
ans-point = posizioa
ans-from = { $point } puntura dagoen distantzia
ans-direction = norabidea
ans-center = kurbadura-zentroa
ans-center_from = kurbadura-zentroa { $where }
ans-tangent = ukitzaile unitarioa
ans-slide = ardatzaren norabideko abiadura
ans-translation = translazio bat: ez dago inflexio-zirkunferentziarik
ans-inflection_pole = I biraketa-zentro instantaneoa
ans-inflection_center = inflexio-zirkunferentziaren zentroa
ans-inflection_diameter = inflexio-zirkunferentziaren diametroa
ans-inflection_point = inflexio-poloa (zirkunferentzian I-ren aurkakoa)
ans-pole_tangent = polo-tangentea (unitarioa, I mugitzen den noranzkoan)
ans-pole_normal = polo-normala (unitarioa, I-tik inflexio-polora)
ans-pole_velocity = I zentroaren abiadura polodietan zehar
centre-proportional-between = Aronhold–Kennedyren teoremaz, { $l1 } zentroetatik pasatzen den zuzenean eta { $l2 } zentroetatik pasatzen denean dago, baina zuzen bera dira eta ez dute finkatzen. Zuzen horretan { $frame } solidoarekiko abiadurak zuzenarekiko perpendikularrak eta BZIrainoko distantziarekiko proportzionalak dira: { $p } puntuak { $vp } abiadura du eta { $q } puntuak { $vq }, aurkako noranzkoetan; beraz, BZIa bien artean dago, abiadura nulua den tokian:
centre-proportional-outside = Aronhold–Kennedyren teoremaz, { $l1 } zentroetatik pasatzen den zuzenean eta { $l2 } zentroetatik pasatzen denean dago, baina zuzen bera dira eta ez dute finkatzen. Zuzen horretan { $frame } solidoarekiko abiadurak zuzenarekiko perpendikularrak eta BZIrainoko distantziarekiko proportzionalak dira: { $p } puntuak { $vp } abiadura du eta { $q } puntuak { $vq }, noranzko berean; beraz, BZIa motelenaren haratago dago, abiadura nulua den tokian:
composition-slide = { $point } puntua bere gidan zehar irristatzen da: haren mugimendu erlatiboa gidaren norabidean dago, { $sym } = { $value }.
composition-slide_seen = { $body } solidoa { $frame } solidoan zehar irristatzen da, harekiko biratu gabe; beraz, haren puntu guztiek, { $point } puntuak ere, «{ sec-velocities }» atalean aurkitutako { WORD($kind) ->
        [accel] azelerazio
       *[speed] abiadura
    } erlatiboa dute: { $sym } = { $value }.
composition-slide_seen_step = { $body } solidoa { $frame } solidoan zehar irristatzen da, harekiko biratu gabe; beraz, haren puntu guztiek, { $point } puntuak ere, { $step }. urratsean aurkitutako { WORD($kind) ->
        [accel] azelerazio
       *[speed] abiadura
    } erlatiboa dute: { $sym } = { $value }.
composition-drag_seen = { $sym } = { $value }, { $frame } solidoaren { $point } puntuarekin bat datorren puntuaren { WORD($kind) ->
        [accel] azelerazioa
       *[speed] abiadura
    }, { $step }. urratsean aurkitua.
composition-drag_terms = { $sym } = { $terms } = { $value }: { $step }. urratseko ekuazioaren lehen terminoak dira.
composition-sum_seen = Beraz, { $step }. urratsean { $seen } aurkitzeko erabilitako ekuazioa { $sym } = { $terms } da.
composition-reverse = { $sym } = −{ $back } = { $value }: { $step }. urratsean aurkitutako { WORD($kind) ->
        [accel] azelerazio
       *[speed] abiadura
    } erlatiboaren aurkakoa.
composition-reverse_rolling = Irristadurarik ez: { $vel } = 0; beraz, ez dago Coriolisen terminorik, eta { $sym } = −{ $back } = { $value }, { $step }. urratsean aurkitutako azelerazio erlatiboaren aurkakoa.
composition-pin = { $point } puntua giltzadura bat da, bi solidoen puntua: ez du mugimendu erlatiborik, { $sym } = 0.
vehicle-driven = { $joint } gurpila ez da irristatzen: { $point } puntuak ez du abiadurarik gurpilaren planoarekiko perpendikularki; beraz, planoaren norabideko abiadura emana da haren abiadura osoa: { $sym } = { $value }.
vehicle-line-wheel = { $joint } gurpilaren planoarekiko perpendikularra { $point } puntuan (haren ardatza: gurpila ez da alboetara irristatzen)
vehicle-line-velocity = { $sym } abiadurarekiko perpendikularra { $point } puntuan
vehicle-equiprojective = Ekiproiektibitatearen propietateagatik ({ $q } eta { $p } { $body } solidoaren puntuak dira), haien abiadurek osagai bera dute { $seg } zuzenean: { $vp } · { $seg }/|{ $seg }| = { $vq } · { $seg }/|{ $seg }|, non { $seg }/|{ $seg }| = { $unit }; beraz, { $vq } · { $seg }/|{ $seg }| = { $proj }. { $p } puntua { $joint } gurpilaren ardatzean dago; beraz, { $vp } gurpilaren planoaren norabidean dago: { $vp } = |{ $vp }| e, non e = { $along } eta e · { $seg }/|{ $seg }| = { $cos }. Ondorioz, |{ $vp }| = ({ $proj }) / ({ $cos }) = { $speed }, eta { $vp } = { $value }.
vehicle-equiprojective_along = Ekiproiektibitatearen propietateagatik ({ $q } eta { $p } { $body } solidoaren puntuak dira), haien abiadurek osagai bera dute { $seg } zuzenean: { $vp } · { $seg }/|{ $seg }| = { $vq } · { $seg }/|{ $seg }|, non { $seg }/|{ $seg }| = { $unit }; beraz, { $vq } · { $seg }/|{ $seg }| = { $proj }. { $p } puntua { $joint } gurpilaren ardatzean dago; beraz, { $vp } gurpilaren planoaren norabidean dago, { $seg } zuzenean: { $vp } = |{ $vp }| { $seg }/|{ $seg }|. Ondorioz, |{ $vp }| = { $speed }, eta { $vp } = { $value }.
vehicle-line-wheel_own = { $joint } gurpilaren planoarekiko perpendikularra { $point } puntuan (haren ardatza, { $witness } puntuan { $sym } abiadurarekiko perpendikularra ere badena: gurpila ez da alboetara irristatzen)
vehicle-pin_shared = { $point } { $a } eta { $b } solidoen giltzadura komuna da: { $sym } = { $other }.
vehicle-pin_shared_one = { $point } { $a } eta { $b } solidoen giltzadura komuna da: { $sym } bien abiadura da.
vehicle-centre = { $body } solidoaren biraketa-zentro instantaneoa bi zuzen hauetan dago: { $first }, eta { $second }; { $centre } = { $where } puntuan ebakitzen dira, eta zentro horrek ez du abiadurarik: { $rest } = 0; solidoaren puntu bakoitza { $centre } zentrorainoko zuzenarekiko perpendikularki mugitzen da, distantziarekiko proportzionala den abiadurarekin:
vehicle-translation = { $body } solidoaren zuzenak paraleloak dira; beraz, solidoa traslatzen da: puntu guztiak { $point } bezala mugitzen dira.
vehicle-translation_equal = { $p } eta { $q } puntuek abiadura bera dute, { $vp } = { $vq } = { $value }; beraz, { $body } solidoa traslatzen da: puntu guztiek { $value } abiadura dute.
vehicle-spin = { $joint } gurpila irristatu gabe errodatzen da ({ $radius } erradioa): haren { $point } zentroa gurpilaren planoan mugitzen da { $product } abiaduraz, { $spin } gurpilak bere ardatzaren inguruan duen biraketa propioa izanik; beraz:
triad-intro = { $body } hiru barra bitarrek eusten dute, { $links }: puntu bakar baten ekuazio bektorialek ez dute bi ezezagun soilik. Triadetarako testuek egiten duten bezala, { $point } Assur puntua hartzen da, { $l1 } eta { $l3 } zuzenak ebakitzen diren tokia, { $body } solidoaren puntu gisa:
triad-collinear = Alde bakoitzean bi termino ezezagunak zuzen berarekiko perpendikularrak dira ({ $point } { $l1 } zuzenean eta { $l3 } zuzenean dago); beraz, alde bakoitzak modulu ezezagun bakarra du: bi ezezagun, eta poligonoa ixten da.
triad-closure = { $point } barra hirutarraren puntu gisa ezaguna denez, haren { $pin } giltzadura bi elementuko talde batean bezala ixten da:
loop-intro = { $bodies } solidoek begizta bat ixten dute: hura osatzean, abiadura angeluar erlatiboen batura zero da, bakoitza bere loturaren ardatzaren norabidean (hiru ekuazio eskalar { $axis } ardatzen norabideko { $rate } abiadura ezezagunetarako):
loop-solve = Hiru osagaiek abiadura ezezagunak ematen dituzte:
loop-solve_alpha = Ardatz finkoetan deribatuz, azelerazio angeluar erlatiboen eta { $cross } terminoen batura zero da begiztan; hiru osagaiek { $rate } ezezagunak ematen dituzte:
dir-axis = { $joint } ardatza
dir-wheel = { $joint } gurpila
how-weld = (lotura zurruna: solido bakarra)
group-wheel_v = { $joint } gurpila ez da alboetara irristatzen: { $point } puntuaren abiadura gurpilaren planoan dago.
group-wheel_a = { $joint } gurpila ez da inoiz alboetara irristatzen, eta haren planoa { $body } solidoarekin batera biratzen da: { $point } puntuaren azelerazioak zati tangentzial bat du planoan eta zati normal bat planoarekiko perpendikularra, { $w } × { $v }.
how-translation = (traslatzen da)
translation-same = { $body } solidoa ez da biratzen ({ $w } = 0{ $accel ->
        [1] , { $a } = 0
       *[other] {""}
    }): traslatzen da, eta haren puntu guztiek { $accel ->
        [1] azelerazio
       *[other] abiadura
    } bera dute:
translation-points = { $body } solidoaren puntu guztiek { $accel ->
        [1] azelerazio
       *[other] abiadura
    } bera dute:
fig-centres = Biraketa-zentro instantaneoak (eraztunak, I bi solidoren zenbakiekin) mekanismoaren gainean{ $kennedy ->
        [0] { $normals_n ->
            [0] .
           *[other] , aurkitzeko zuzenekin (marra-puntua: { $normals }).
        }
       *[other] , aurkitzeko zuzenekin (marra-puntua: bi zentrotatik pasatzen diren zuzenak{ $normals_n ->
            [0] {""}
           *[other] {" "}eta { $normals }
        }).
    }
fig-centres_named = Biraketa-zentro instantaneoak (eraztunak, I solidoen izenekin) mekanismoaren gainean{ $kennedy ->
        [0] { $normals_n ->
            [0] .
           *[other] , aurkitzeko zuzenekin (marra-puntua: { $normals }).
        }
       *[other] , aurkitzeko zuzenekin (marra-puntua: bi zentrotatik pasatzen diren zuzenak{ $normals_n ->
            [0] {""}
           *[other] {" "}eta { $normals }
        }).
    }
fig-normal-wheel = gurpilen perpendikularrak
fig-normal-slot = arteken perpendikularrak
fig-normal-slot_fixed = puntuak irristatzen diren zuzenen perpendikularrak
fig-normal-normal = kontaktuetako normal komunak
fig-normal-radius = puntuen abiaduren perpendikularrak
fig-assur = { $point } Assur puntua: { $l1 } eta { $l3 } zuzenak (marra etenez) ebaki arte luzatuta; { $point } barra hirutarraren puntutzat hartzen da.
fig-drawn_at = Balio hauekin marraztua: { $values }.
fig-level_v = Abiaduren poligonoa, eskalan: o polotik, puntu bakoitzaren abiadura{ $format ->
        [md] {""}
       *[other] {" "}(urdinez)
    } haren irudian amaitzen da, puntuaren letrarekin{ $image ->
        [0] {""}
       *[other] {" "}({ $point }-rentzat { $image })
    }{ $between ->
        [0] .
       *[other] ; irudien artean, { $span ->
            [1] { $first }. urratseko
            [2] { $first }. eta { $last }. urratsetako
           *[other] { $first }.–{ $last }. urratsetako
        } ekuazioen abiadura erlatiboak{ $format ->
            [md] {""}
           *[other] {" "}(beltzez)
        }, bata bestearen ondoren.
    }
fig-level_a = Azelerazioen poligonoa, eskalan: o polotik, puntu bakoitzaren azelerazioa{ $format ->
        [md] {""}
       *[other] {" "}(urdinez)
    } haren irudian amaitzen da, puntuaren letrarekin{ $image ->
        [0] {""}
       *[other] {" "}({ $point }-rentzat { $image })
    }{ $between ->
        [0] .
       *[other] ; irudien artean, { $span ->
            [1] { $first }. urratseko
            [2] { $first }. eta { $last }. urratsetako
           *[other] { $first }.–{ $last }. urratsetako
        } ekuazioen terminoak ({ $format ->
            [md] {""}
           *[other] beltzez:{" "}
        }normalak eta tangentzialak, erlatiboak eta Coriolisen terminoak), bata bestearen ondoren.
    }
fig-level_a_relative = Azelerazioen poligonoa, eskalan: o polotik, puntu bakoitzaren azelerazioa{ $format ->
        [md] {""}
       *[other] {" "}(urdinez)
    } haren irudian amaitzen da, puntuaren letrarekin{ $image ->
        [0] {""}
       *[other] {" "}({ $point }-rentzat { $image })
    }{ $between ->
        [0] .
       *[other] ; irudien artean, { $span ->
            [1] { $first }. urratseko
            [2] { $first }. eta { $last }. urratsetako
           *[other] { $first }.–{ $last }. urratsetako
        } ekuazioen terminoak ({ $format ->
            [md] {""}
           *[other] beltzez:{" "}
        }normalak eta tangentzialak, eta erlatiboak), bata bestearen ondoren.
    }
fig-level_a_normal = Azelerazioen poligonoa, eskalan: o polotik, puntu bakoitzaren azelerazioa{ $format ->
        [md] {""}
       *[other] {" "}(urdinez)
    } haren irudian amaitzen da, puntuaren letrarekin{ $image ->
        [0] {""}
       *[other] {" "}({ $point }-rentzat { $image })
    }{ $between ->
        [0] .
       *[other] ; irudien artean, { $span ->
            [1] { $first }. urratseko
            [2] { $first }. eta { $last }. urratsetako
           *[other] { $first }.–{ $last }. urratsetako
        } ekuazioen terminoak ({ $format ->
            [md] {""}
           *[other] beltzez:{" "}
        }normalak eta tangentzialak), bata bestearen ondoren.
    }
col-number = zk.

# higher pairs (joints.contact, curved_slot, cam)
shape-curveshape = kurba
shape-camshape = espeka
joint-contact = kontaktua (goi-mailako bikotea)
joint-curved_slot = ziria arteka kurbatu batean
joint-cam = espeka eta jarraitzailea
cond-contact = kontaktua: { $a } eta { $b } ukitzen jarraitzen dute; ukitzaile komunean irristatu daitezke.
cond-curved_slot = { $point } ziria arteka kurbatu batean: artekadun solidoarekiko abiadura artekaren ukitzailean dago.
cond-cam = espeka: { $b } jarraitzaileak { $a } espeka ukitzen jarraitzen du.
dir-tangent = ukitzailea { $point } puntuan
dir-centre = { $point } kurbadura-zentrorantz
higher-intro = Goi-mailako bikotea { $point } puntuaren mugimendu gisa idazten da, { $holder } solidoarekiko bere ibilbidean ({ $radius } erradioko arteka kurbatua, ukitzailearen norabidean): azelerazio erlatiboak v²/ρ osagai normala du ibilbidearen kurbadura-zentrorantz.
higher-straight = Goi-mailako bikotea { $point } puntuaren mugimendu gisa idazten da, { $holder } solidoarekiko ibilbide zuzen batean (arteka bat ukitzailearen norabidean).
centre-weld = { $body } eta { $other } zurrunki lotuta daude: solido bakarra dira; beraz, BZIa { $other } solidoarena da, { $same },
centre-line-kennedy = { $l } zentroetatik pasatzen den zuzena (Aronhold–Kennedy, { $k } hirugarren solidoa)
centre-line-moves = { $point } puntuan { $v } abiadurarekiko perpendikularra ({ $point } puntua { $pivot } puntuaren inguruan biratzen den { $body } solidoarekin mugitzen da)
centre-line-rolls = { $point } puntuan { $v } abiadurarekiko perpendikularra ({ $roller } solidoa ez da irristatzen { $on } solidoaren gainean: { $b } solidoaren { $point } puntuak { $body } solidoaren abiadura du, eta { $body } solidoa { $pivot } puntuaren inguruan biratzen da)
centre-line-rolls_still = { $point } puntuan { $v } abiadurarekiko perpendikularra ({ $roller } solidoa ez da irristatzen { $on } solidoaren gainean: { $b } solidoaren { $point } puntuak traslatzen den { $body } solidoaren abiadura du)
centre-line-moves_still = { $point } puntuan { $v } abiadurarekiko perpendikularra ({ $point } puntua traslatzen den { $body } solidoarekin mugitzen da)
centre-line-guide = { $pivot } puntuan gidarekiko perpendikularra ({ $pivot }′ da { $pivot } puntutik gidara doan perpendikularraren oina. Han, { $body } solidoarekiko abiadura erlatiboa gidarekiko paraleloa da, eta arrastrekoa { $pivot }{ $pivot }′ zuzenarekiko perpendikularra, hau da, hori ere gidarekiko paraleloa; beraz, { $b } solidoaren { $pivot }′ puntuko abiadura gidaren norabidean dago)
centre-carried-slip = {" "}({ $b } solidoa ez da irristatzen { $body } solidoaren gainean: bere { $point } puntuak { $body } solidoaren abiadura du bertan)
centre-carried-between = { $p } puntua { $k1 } solidoarekin mugitzen da { $c1 } puntuaren inguruan{ $why1 }, eta { $q } puntua { $k2 } solidoarekin { $c2 } puntuaren inguruan{ $why2 }: bi abiadurak, { $frame } solidoarekiko, { $p } eta { $q } puntuetatik pasatzen den zuzenarekiko perpendikularrak dira; beraz, BZIa zuzen horretan dago, eta bertan abiadurak BZIrainoko distantziarekiko proportzionalak dira: { $p } puntuak { $vp } abiadura du eta { $q } puntuak { $vq }, aurkako noranzkoetan; beraz, BZIa bien artean dago, abiadura nulua den tokian:
# the construction repeated for a body symmetric to one done: referred to (twenty-ninth round b)
centre-carried_as = { $first } solidoan bezala, { $p } eta { $q } puntuetatik pasatzen den zuzenean dago, { $near } puntutik { $dist } distantziara:
centre-carried-between_from = { $p } puntua { $k1 } solidoarekin mugitzen da { $c1 } puntuaren inguruan{ $why1 }, eta { $q } puntua { $k2 } solidoarekin { $c2 } puntuaren inguruan{ $why2 }: bi abiadurak, { $frame } solidoarekiko, { $p } eta { $q } puntuetatik pasatzen den zuzenarekiko perpendikularrak dira; beraz, BZIa zuzen horretan dago, eta bertan abiadurak BZIrainoko distantziarekiko proportzionalak dira: { $p } puntuak { $vp } abiadura du eta { $q } puntuak { $vq }, aurkako noranzkoetan; beraz, BZIa bien artean dago, abiadura nulua den tokian, { $near } puntutik { $dist } distantziara:
centre-carried-outside = { $p } puntua { $k1 } solidoarekin mugitzen da { $c1 } puntuaren inguruan{ $why1 }, eta { $q } puntua { $k2 } solidoarekin { $c2 } puntuaren inguruan{ $why2 }: bi abiadurak, { $frame } solidoarekiko, { $p } eta { $q } puntuetatik pasatzen den zuzenarekiko perpendikularrak dira; beraz, BZIa zuzen horretan dago, eta bertan abiadurak BZIrainoko distantziarekiko proportzionalak dira: { $p } puntuak { $vp } abiadura du eta { $q } puntuak { $vq }, noranzko berean; beraz, BZIa motelenaren haratago dago, abiadura nulua den tokian:
centre-carried-outside_from = { $p } puntua { $k1 } solidoarekin mugitzen da { $c1 } puntuaren inguruan{ $why1 }, eta { $q } puntua { $k2 } solidoarekin { $c2 } puntuaren inguruan{ $why2 }: bi abiadurak, { $frame } solidoarekiko, { $p } eta { $q } puntuetatik pasatzen den zuzenarekiko perpendikularrak dira; beraz, BZIa zuzen horretan dago, eta bertan abiadurak BZIrainoko distantziarekiko proportzionalak dira: { $p } puntuak { $vp } abiadura du eta { $q } puntuak { $vq }, noranzko berean; beraz, BZIa motelenaren haratago dago, abiadura nulua den tokian, { $near } puntutik { $dist } distantziara:
centre-line-slot = artekarekiko normala { $point } puntuan (artekadun solidoarekiko, { $point } artekaren luzeran baino ezin da mugitu)
centre-line-slot_fixed = { $point } puntuan, { $a } solidoaren zuzenarekiko normala ({ $point } puntua zuzen horretan zehar irristatzen da)
centre-line-wheel = { $joint } gurpilaren ardatza, haren planoarekiko normala { $point } puntuan (ez da alboetara irristatzen)
centre-field = { $q } puntutik { $v } abiadurari marraztutako perpendikularrean dago, { $q } puntutik { $arm } = |{ $v }| / |{ $w }| = { $dist } distantziara, { $side }; beraz, BZIa
centre-rate = { $w } abiadura angeluarretik («{ sec-velocities }» atalean { $line } solidoaren bidez aurkitua): { $q } puntutik { $v } abiadurari marraztutako perpendikularrean dago, { $q } puntutik { $arm } = |{ $v }| / |{ $w }| = { $dist } distantziara, { $side }; beraz, BZIa
centre-rate_step = { $w } abiadura angeluarretik ({ $step }. urratsean { $line } solidoaren bidez aurkitua): { $q } puntutik { $v } abiadurari marraztutako perpendikularrean dago, { $q } puntutik { $arm } = |{ $v }| / |{ $w }| = { $dist } distantziara, { $side }; beraz, BZIa
# the side of a point a centre lies on, named (centre-field: below A, to the left of A)
side-above = { $q } puntuaren gainean
side-below = { $q } puntuaren azpian
side-left = { $q } puntuaren ezkerrean
side-right = { $q } puntuaren eskuinean
side-above_left = { $q } puntuaren gainean eta ezkerrean
side-above_right = { $q } puntuaren gainean eta eskuinean
side-below_left = { $q } puntuaren azpian eta ezkerrean
side-below_right = { $q } puntuaren azpian eta eskuinean
centre-check = Egiaztapena «{ sec-velocities }» atalean aurkitutako abiadurekin: { $q } puntutik { $v } abiadurari marraztutako perpendikularrean, { $q } puntutik { $arm } = |{ $v }| / |{ $w }| = { $dist } distantziara, { $side }, puntu bera: { $centre }, { $where }
sec-centres_v = Abiaduretatik aurkitutako biraketa-zentro instantaneoak
how-centre_infinity = (traslatzen da: { $centre } biraketa-zentro instantaneoa infinituan dago)
how-constant_rate = ({ $sym } = { $value } konstantea da: { $line } zuzenak bere luzera gordetzen du, eta haren abiadura angeluarra erradioek eta { $rates } konstanteak finkatzen dute)
how-constant_speed = ({ $point } puntuak { $centre } zentroko eta { $line } = { $length } erradioko zirkunferentzia deskribatzen du { $v } = { $speed } abiadura konstantez; beraz, { $sym } = { $value } konstantea da)
idle-rolling = { $body } irristatu gabe errodatzen da { $fixed } solidoaren gainean: kontaktuko { $point } puntua haren biraketa-zentro instantaneoa da; beraz:
idle-symmetry = { $body } { $like } bezala kokatuta dago (erradio bera, lotura berak solido berekin): simetriagatik berdin biratzen da:
idle-unused = { $bodies } ez { $count ->
        [one] da
       *[other] dira
    } galderan sartzen: urratsek ez dute { $count ->
        [one] haren abiadura angeluarra
       *[other] haien abiadura angeluarrak
    } behar.
how-tangent = ({ WORD($way) ->
        [vertical] bertikal
        [horizontal] horizontal
       *[other] bere buruarekiko paralelo
    } mantentzen da, { $a } eta { $b } solidoekiko ukitzaile: traslatzen da, eta bere puntu guztiek abiadura bera dute)
how-glides = ({ $p } eta { $q } puntuak { $line } zuzenean zehar mugitzen dira une oro: solidoa zuzen horretan zehar traslatzen da, biratu gabe)
how-parallel_paths = ({ $p } eta { $q } puntuetako bakoitza bere gurpilaren erradioaren altueran dago lur lautik; beraz, zuzen paraleloetan mugitzen dira une oro: solidoa traslatzen da, biratu gabe)
how-translates_always = (une oro traslatzen da, abiaduretan ikusi den bezala)
centres-found_above = { $centre } = { $value }: «{ sec-velocities }» atalean aurkitua, { $body } solidoaren abiadura-urratsean.
centres-witness = { $name }
centres-placed_in_step = { $centre }: { $step }. urratsean aurkitua, { $points } puntuen abiaduretatik.
centres-found_above_step = { $centre }: { $step }. urratsean aurkitua, { $body } solidoaren abiadurekin.
centre-site = { $point } puntua { $body } solidoaren biraketa-zentro instantaneoa da { $frame } solidoarekiko ({ $centre }, «{ sec-centres }» atalean aurkitua): { $sym } = 0.
centre-site_s = «{ sec-centres }» atalean aurkitutako { $centre } zentroak ez du abiadurarik: { $sym } = 0.
centre-site_here = { $point } puntua { $body } solidoaren biraketa-zentro instantaneoa da { $frame } solidoarekiko ({ $centre }, goian aurkitua): { $sym } = 0.
centre-site_s_here = Goian aurkitutako { $centre } zentroak ez du abiadurarik: { $sym } = 0.
sec-contact = Kontaktu-puntuak
geom-rule = Errodadura-kontaktu ororen araua: irristatu gabeko baldintza une oro betetzen da mugitzen den kontaktu-puntu geometrikoan (hemen { $geom }); puntu horretan zehar deribatuz { $rule } lortzen da: bi azelerazioen osagai tangentzialak berdinak dira, eta normalak termino horretan bereizten dira, normal komunaren norabidean. Puntu geometrikoaren abiadura behar da:
geom-bar = { $geom }, kontaktu-puntu geometrikoa, ez da bi solidoetako batena ere: beti dago { $c1 } eta { $c2 } zentroen zuzenean, { $part }/{ $whole } = { $ratio } izanik, eta { $c1 } eta { $c2 } puntuetan giltzatutako barra baten puntu bat bezala mugitzen da:
geom-bar_told = { $geom }, kontaktu-puntu geometrikoa, beti dago { $c1 } eta { $c2 } zentroen zuzenean, { $part }/{ $whole } = { $ratio } izanik, eta { $c1 } eta { $c2 } puntuetan giltzatutako barra baten puntu bat bezala mugitzen da:
geom-foot = { $geom }, kontaktu-puntu geometrikoa, { $centre } zentrotik { $line } solidoaren zuzenera marraztutako perpendikularraren oina da: { $radius } erradio bat da, zuzenarekiko perpendikularra, eta zuzenarekin batera biratzen da:
contact-intro = { $point } kontaktuan hiru puntu datoz bat, zinematika desberdinekin: { $a } solidoaren puntua, { $b } solidoaren puntua eta { $geom } kontaktu-puntu geometrikoa, ez dena ez batena ez bestearena.
contact-above = { $sym } = { $value }, «{ sec-accelerations }» atalean lortua kontaktuaren azelerazioa kalkulatzeko.
contact-written_centre = { $sym } = { $value }, { $step }. urratsean aurkitua: { $point } puntua { $body } solidoaren biraketa-zentro instantaneoa da.
contact-written = { $sym } = { $value }, { $step }. urratsean aurkitua.
contact-fixed = { $sym }: { $point }, { $body } solidoaren puntu gisa, ez da mugitzen{ FIXED($body) ->
        [yes] {""}
       *[no] , solidoa finkoa baita
    }: { $sym } = 0.
fig-step_v = Urrats honetako abiaduren poligonoa, eskalan: o polotik, puntu bakoitzaren abiadura{ $format ->
        [md] {""}
       *[other] {" "}(urdina)
    } haren irudian amaitzen da, puntuaren letrarekin{ $between ->
        [0] .
       *[other] ; irudien artean, urrats honetako ekuazioen terminoak{ $format ->
            [md] {""}
           *[other] {" "}(beltza)
        }, bata bestearen atzetik.
    }
fig-step_a = Urrats honetako azelerazioen poligonoa, eskalan: o polotik, puntu bakoitzaren azelerazioa{ $format ->
        [md] {""}
       *[other] {" "}(urdina)
    } haren irudian amaitzen da, puntuaren letrarekin{ $between ->
        [0] .
       *[other] ; irudien artean, urrats honetako ekuazioen terminoak{ $format ->
            [md] {""}
           *[other] {" "}(beltza)
        }, bata bestearen atzetik.
    }
col-point = puntua
col-what = zer den
what-centre = { $body } solidoaren zentroa
what-joint = { $kind }, { $a } eta { $b } solidoen artean
what-touching = { $body } solidoak { $other } ukitzen duen puntua
what-contact = kontaktu-puntua ({ $kind }), { $a } eta { $b } solidoen artean
what-body = { $bodies } puntua
what-of = { $name } solidoaren
note-text = Oharra: { $text }
sec-checks = Egiaztapenak
check-willis = Willisen formula: { $carrier } solidotik ikusita, trena arrunta da ({ $planet } solidoaren ardatza { $carrier } solidoak darama; { $planet } solidoak { $s1 } eta { $s2 } solidoekin engranatzen du, eta { $fixed ->
        [0] horiek { $axis } puntutik pasatzen den ardatz finkoaren inguruan biratzen dira
       *[other] horien ardatza { $axis } puntutik pasatzen den ardatz finkoa da
    }); beraz, { $formula } = { $radii } = { $train }{ $r1 ->
        [0] {""}
       *[other] , { $r1 } eta { $r2 } izanik
    }. Aurkitutako abiadura angeluarrekin, { $values } = { $ratio }: bat datoz.
check-belt = Bi ardatzak daramatzan { $holder } solidotik ikusita, { $line } solidoa ez da irristatzen ez { $a } solidoaren gainean ez { $b } solidoaren gainean: { $equation }; beraz, { $ratio }; «{ sec-velocities }» atalean aurkitutako abiadura angeluarrekin, { $values }: bat datoz.
pair-relation_v = Bi ardatzak daramatzan { $holder } solidotik ikusita, ardatzak finkoak dira: { $a } eta { $b } haien inguruan biratzen dira eta ez dute elkarren gainean irristatzen; beraz, { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}({ $radii } izanik)
    }:
pair-relation = Bi ardatzak daramatzan { $holder } solidotik ikusita, ardatzak finkoak dira: { $a } eta { $b } haien inguruan biratzen dira eta ez dute elkarren gainean irristatzen; beraz, { $equation } une oro; deribatuz, erradioak konstanteak direnez, { $derived }{ $radii ->
        [0] {""}
       *[other] {" "}({ $radii } izanik)
    }:
drive-relation_a = Deribatuz, erradioak konstanteak direnez: { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}({ $radii } izanik)
    }:
drive-relation = Bi ardatzak daramatzan { $holder } solidotik ikusita, ardatzak finkoak dira eta { $line } solidoaren zati zuzena traslatzen da: ez da irristatzen ez { $a } solidoaren gainean ez { $b } solidoaren gainean; beraz, bien periferiek abiadura bera dute, { $equation }{ $radii ->
        [0] {""}
       *[other] {" "}({ $radii } izanik)
    }:
check-train = Transmisioaren erlazioa etapen erlazioen biderkadura da: { $ratio }; «{ sec-velocities }» atalean aurkitutako abiadura angeluarrekin, erlazioa { $value } da.
check-quick = Itzulera azkarraren denbora-erlazioa: { $lever } solidoa bere kulunkaren mutur batean dago artekak { $pin } puntuaren zirkunferentzia ukitzen duenean ({ $o2 }{ $pin } biradera { $o4 }{ $pin } zuzenarekiko perpendikularra), non cos θ = { $o2 }{ $pin } / { $o2 }{ $o4 } = { $r } / { $d }, θ = { $theta }. Abiadura konstantean biratuz, { $crank } solidoak 360° − 2θ = { $slow } egiten ditu kurtsa batean eta 2θ = { $fast } bestean: denbora-erlazioa { $ratio }.
driver-slide = Datua: { $joint } lotura prismatikoko irristatze-abiadura { $value } da.
driver-slide_accel = Datua: { $joint } lotura prismatikoko irristatze-azelerazioa { $value } da.
centre-line-normal = { $point } kontaktuko normal komuna (solidoak elkarren gainean irristatzen dira: ez dago abiadura erlatiborik haren norabidean)
# zentro bat, bi puntuen zuzenarekiko perpendikularrak diren bi abiadura paralelotatik (apunteen eraikuntza proportzionala)
centre-parallel-between = { $body } solidoaren { $p } eta { $q } puntuek, { $frame } solidoarekiko, { $sp } = { $vp } eta { $sq } = { $vq } abiadurak dituzte, eta biak { $p } eta { $q } puntuetatik pasatzen den zuzenarekiko perpendikularrak dira. Zuzen horretan abiadura linealki aldatzen da, BZIrainoko distantziarekiko proportzionala, eta bi hauek aurkako noranzkoak dituzte; beraz, BZIa bien artean dago, abiadura nulua den tokian, { $q } puntutik { $dist } distantziara:
centre-parallel-outside = { $body } solidoaren { $p } eta { $q } puntuek, { $frame } solidoarekiko, { $sp } = { $vp } eta { $sq } = { $vq } abiadurak dituzte, eta biak { $p } eta { $q } puntuetatik pasatzen den zuzenarekiko perpendikularrak dira. Zuzen horretan abiadura linealki aldatzen da, BZIrainoko distantziarekiko proportzionala, eta bi hauek noranzko bera dute; beraz, BZIa motelenaren haratago dago, abiadura nulua den tokian, { $q } puntutik { $dist } distantziara:
# a normal acceleration: its magnitude, then the vector with its direction (never a magnitude = a vector)
term-magnitude = { $mag } = { $how }, { $point } punturantz: { $sym } = { $value }

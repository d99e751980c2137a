## kinematika-ren ariketak euskaraz: enuntziatuak, orriak, erantzun-gakoa, galdetegiaren
## atzeraelikadura eta orriaren ariketa-modua. Giltza arteko markak ({ $name }) bere horretan
## utzi.

statement-default = Irudiko mekanismoa analisiaren unean marraztuta dago. Datuak: { $data }.
units-note-planar = Eman luzerak { $unit }-tan, abiadurak { $unit }/s-tan eta azelerazioak { $unit }/s²-tan, irudiko ardatzetako x eta y osagaien bidez; abiadura angeluarrak rad/s-tan eta azelerazio angeluarrak rad/s²-tan, positiboak erlojuaren orratzen aurkako noranzkoan.
units-note-spatial = Eman luzerak { $unit }-tan, abiadurak { $unit }/s-tan eta azelerazioak { $unit }/s²-tan, x, y eta z osagaien bidez; abiadura angeluarrak rad/s-tan eta azelerazio angeluarrak rad/s²-tan, bektore gisa.

ask-omega = { $body } solidoaren abiadura angeluarra
ask-omega-rel = { $body } solidoaren abiadura angeluarra { $frame } solidoarekiko
ask-alpha = { $body } solidoaren azelerazio angeluarra
ask-alpha-rel = { $body } solidoaren azelerazio angeluarra { $frame } solidoarekiko
ask-velocity = { $body } solidoaren { $point } puntuaren abiadura
ask-velocity-rel = { $body } solidoaren { $point } puntuaren abiadura { $frame } solidoarekiko
ask-acceleration = { $body } solidoaren { $point } puntuaren azelerazioa
ask-acceleration-rel = { $body } solidoaren { $point } puntuaren azelerazioa { $frame } solidoarekiko
ask-icr = { $body } solidoaren biraketa-zentro instantaneoa
ask-icr-rel = { $body } solidoaren biraketa-zentro instantaneoa { $frame } solidoarekiko
ask-pole = { $body } solidoaren azelerazio-poloa
ask-curvature = { $body } solidoaren { $point } puntuaren ibilbidearen kurbadura
ask-decompose = { $body } solidoaren { $point } puntuaren mugimendua arrastre, erlatibo eta Coriolisen zatietan, { $frame } erreferentzia mugikorra
ask-intrinsic = { $body } solidoaren { $point } puntuaren azelerazio tangentziala eta normala
ask-contact = { $joint } kontaktuan bat datozen hiru puntuen mugimendua
ask-axis = { $body } solidoaren biraketa eta irristadura ardatz instantaneoa
ask-velocity-point = { $point } puntuaren abiadura
ask-velocity-rel-point = { $point } puntuaren abiadura { $frame } solidoarekiko
ask-acceleration-point = { $point } puntuaren azelerazioa
ask-acceleration-rel-point = { $point } puntuaren azelerazioa { $frame } solidoarekiko
ask-curvature-point = { $point } puntuaren ibilbidearen kurbadura
ask-intrinsic-point = { $point } puntuaren azelerazio tangentziala eta normala
ask-other = { $n }. galdera

part-point = posizioa
part-center = zentroa
part-radius = erradioa
part-velocity = abiadura
part-acceleration = azelerazioa
part-drag = arrastrea
part-relative = erlatiboa
part-coriolis = Coriolis
part-total = osoa
part-direction = norabidea
part-omega = abiadura angeluarra
part-slide = irristadura-abiadura
part-speed = lastertasuna
part-tangential = tangentziala
part-normal = normala
part-tangent = bektore tangente unitarioa
part-tangential_vector = azelerazio tangentzialaren bektorea
part-normal_vector = azelerazio normalaren bektorea
part-geometric = kontaktu-puntu geometrikoa
part-pole = poloa
part-diameter = inflexio-zirkunferentziaren diametroa
part-inflection_pole = inflexio-poloa
part-pole_tangent = polo-tangentea
part-pole_normal = polo-normala
part-pole_velocity = poloaren abiadura
part-of-body = { $body } solidoaren puntua
ask-inflection = { $body } solidoaren inflexio-zirkunferentzia eta polo-tangentea

sheet-title = Ariketa
sheet-student = Ikaslea
sheet-name = Izena
sheet-variant = { $n }. aldaera
sheet-find = Kalkulatu
sheet-answer = erantzuna
key-title = Erantzun-gakoa
key-values = Erantzunak
key-solution = Ebazpena urratsez urrats
key-question = galdera
key-value = balioa
key-margin = onartutako tartea ±

feedback-right = Zuzena.
feedback-wrong = Ez da zuzena: ikusi ebazpena urratsez urrats.
mistake-coriolis-omitted = Balio hau Coriolisen 2 ω × v_erl terminoa ahaztuta lortzen da.
mistake-coriolis-doubled = Balio hau Coriolisen terminoa bi aldiz kontatuta lortzen da.
mistake-normal-omitted = Balio hau termino normalak (zentripetuak), ω² r, ahaztuta lortzen da.
mistake-sense-reversed = Balio hau emandako ω edo α baten noranzkoa alderantzikatuta lortzen da.
mistake-drag-as-absolute = Hau gidan bat datorren puntuaren mugimendua da (arrastrea), ez puntuarena bera.
mistake-degrees-as-radians = Balio hau gradutan emandako angelu bat radiantzat hartuta lortzen da.
mistake-units-mm-as-m = Balio hau datuen milimetroak metrotzat hartuta lortzen da.
mistake-components-swapped = Osagaiak trukatuta daude.
feedback-unit = Zenbakia zuzena da { $unit }-tan; laukiak { $asked } eskatzen du.
mistake-wrong-unit = Unitatea ez da magnitude honena (laukiak berea eskatzen du).
mistake-wrong-variant = Hau ez da zure aldaeraren galdera: erantzun egokitu zaizun aldaera.
feedback-carried = Zure aurreko { $question } erantzunetik ondorioztatzen da: zuzentzat ematen da.

page-check = Egiaztatu
page-show = Erakutsi ebazpena urratsez urrats
page-your-answer = zure erantzuna
page-link = Ariketa honetarako esteka
page-score = { $total } erantzunetik { $right } zuzen

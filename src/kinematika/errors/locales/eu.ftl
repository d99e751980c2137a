## Erroreen eta abisuen mezuak, euskaraz. Ikastaroaren terminoak: solidoa, lotura (bi soliden
## artekoa), eragileak, askatasun-gradua, puntu hila, muntaia, ekorketa. Eredu-fitxategiaren
## gakoak (`at`, 'base', points…) idazten diren bezala uzten dira.

## beste programa batzuen hitzak: sistema eragilearen arrazoia, irakurgailu baten kexa
reason = { $errno ->
        [ENOENT] ez dago fitxategi edo karpeta hori
        [EACCES] baimena ukatu da
        [EPERM] eragiketa ez dago baimenduta
        [EISDIR] karpeta bat da
        [ENOTDIR] ez da karpeta bat
        [ENOSPC] ez dago lekurik diskoan
        [EROFS] fitxategi-sistema irakurtzeko soilik da
        [ENAMETOOLONG] izena luzeegia da
        [EEXIST] badago lehendik
        [EADDRINUSE] helbidea erabilita dago
        [EADDRNOTAVAIL] helbidea ez dago erabilgarri makina honetan
        [ECONNREFUSED] konexioa ukatu da
       *[other] { $text }
    }
problem = { $code ->
        [mapping-values] hemen ez da gako baten baliorik onartzen (lerro-jauzi bat falta da edo «:» bat soberan dago?)
        [colon] espero zen «:» falta da
        [token] elementu bat hasi ezin duen karaktere bat (tabulazio bat?)
        [key] gako bat espero zen
        [bracket] «,» edo «]» bat falta da
        [brace] «,» edo «{"}"}» bat falta da
        [end] testua goizegi amaitzen da
        [alias] definitu gabeko alias bat
        [node] balio bat espero zen
        [escape] ihes-sekuentzia ezezagun bat
        [value] balio bat espero zen
        [property] komatxo bikoitzen arteko gako-izen bat espero zen
        [comma] koma bat falta da
        [extra] testua soberan dago balioaren ondoren
        [string] itxi gabeko testu bat
        [control] kontrol-karaktere bat testu baten barruan
        [equals] gako baten ondoren «=» falta da
        [duplicate] bi aldiz definitutako gako bat
        [syntax] sintaxia ez da zuzena
        [unclosed] itxi gabeko parentesi bat
        [unmatched] ireki gabeko parentesi bat
        [literal] gaizki idatzitako zenbaki bat
        [domain] funtzioaren eremutik kanpo
        [range] emaitza handiegia da
        [small] balioa txikiegia da koma mugikorreko zenbakietarako
        [zero] zeroz zatiketa
       *[other] { $text }
    }

## fitxategiak irakurtzea (model/files.py)
model-not-a-path = eredu bat fitxategi baten bidea, dict bat edo Mechanism bat da, ez { $type }
file-empty = fitxategia hutsik dago
model-not-a-mapping = eredu bat points, bodies, joints, drivers gakoak dituen hiztegi bat da; fitxategi honek { $holds } dauka
holds = { $what ->
        [list] zerrenda bat
        [text] testu bat
        [nothing] ezer ez
       *[value] balio bakar bat
    }
file-type-unknown = fitxategi-mota ezezaguna { $suffix }: { $noun ->
        [cam-file] espeka-fitxategi baten
       *[model-file] eredu-fitxategi baten
    } amaiera hauetako bat da: { $suffixes }
file-not-utf8 = fitxategia ez da UTF-8 testua ({ $byte }. bytea)
file-missing = ez dago fitxategi hori
file-unreadable = ezin da fitxategia irakurri: { $reason }
file-is-a-folder = hau karpeta bat da, ez eredu-fitxategi bat
file-too-large = fitxategia handiegia da eredu baterako ({ $limit } byte baino gehiago)
file-no-end = fitxategia ez da amaitu { $seconds } s-tan (hodi bat edo gailu bat, ez eredu-fitxategi bat)
text-too-large = testua handiegia da eredu baterako ({ $limit } karaktere baino gehiago)
text-unreadable = { $format } irakurtezina: { $detail }
file-too-deep = fitxategia sakonegi habiaratuta dago eredu bat izateko ({ $levels } maila baino gehiago{ $line ->
        [0] {""}
       *[other] , { $line }. lerroa
    })
name-too-long = { $name } izenak { $length } karaktere ditu: izenek gehienez { $limit } dituzte
text-lone-surrogate = { $text } testuak ordezko bakarti bat dauka, eta hori ez da Unicode testua
key-duplicate = gako errepikatua { $key }{ $line ->
        [0] {""}
       *[other] {" "}{ $line }. lerroan
    }: gako bakoitza behin bakarrik ager daiteke
json-invalid = JSON baliogabea { $line }. lerroan, { $column }. zutabean: { $problem }
toml-invalid = TOML baliogabea: { $problem }
yaml-invalid = YAML baliogabea{ $line ->
        [0] {""}
       *[other] {" "}{ $line }. lerroan, { $column }. zutabean
    }: { $problem }
yaml-alias-inside = { $line }. lerroko *{ $alias } aliasa izendatzen duenaren barruan dago
yaml-alias-unknown = { $line }. lerroko *{ $alias } aliasak ez du aingurarik izendatzen
yaml-aliases-too-many = aliasak { $limit } balio baino gehiagotara zabaltzen dira ({ $line }. lerroan): gehiegi eredu baterako
model-no-cam = eredu honek ez du espekarik: eman solido bati `cam:` forma bat

## mezuek partekatzen dituzten hitzak
none = bat ere ez
or-word = edo
more = , … (beste { $n })
integer-bits = { $bits } biteko zenbaki oso bat

## adierazpenak (expressions.py)
expr-expected = zenbaki bat edo adierazpen bat espero zen, baina { $got } dago
expr-not-finite = koma mugikorreko zenbakien tarteko zenbaki finitu bat espero zen, baina { $got } dago
expr-empty = adierazpen hutsa
expr-too-long = { $limit } karaktere baino luzeagoa den adierazpena
expr-unreadable = ezin da { $source } adierazpena irakurri: { $detail }
expr-unreadable-bare = ezin da { $source } adierazpena irakurri
expr-too-deep = { $source } adierazpena sakonegi habiaratuta dago
expr-constant = { $source } adierazpenean: zenbakiak baino ezin dira idatzi konstante gisa
expr-number-too-large = { $source } adierazpenean: zenbaki bat handiegia da
expr-unknown-function = { $source } adierazpenean: funtzio ezezaguna { $function } (ezagunak: { $known })
expr-arguments = { $source } adierazpenean: { $function } funtzioak { $count ->
        [one] argumentu bat hartzen du
       *[other] { $count } argumentu hartzen ditu
    }
expr-not-allowed = { $source } adierazpenean: { $part } ez da onartzen adierazpen batean
expr-unknown-name = { $source } adierazpenean: izen ezezaguna { $name } (ez da parametro bat)
expr-function-fails = { $source } adierazpenean: ezin da { $function } ebaluatu ({ $why })
expr-exponent = { $source } adierazpenean: { $exponent } berretzailea handiegia da (gehienez { $limit } balio absolutuan)
expr-division-by-zero = { $source } adierazpenean: zeroz zatiketa
expr-too-large = { $source } adierazpenean: balioa handiegia da
expr-not-real = { $source } adierazpenean: balioa ez da erreala
expr-underflow = { $source } adierazpenean: balioa txikiegia da koma mugikorreko zenbakietarako (0 gisa hartuko litzateke)
expr-not-finite-value = { $source } adierazpenean: balioa ez da finitua
expr-too-many-digits = { $source } adierazpenean: balioak zifra gehiegi ditu formula zehatzetarako ({ $limit } baino gehiago)
expr-degree = { $source } adierazpenean: formulak ikurretan duen maila { $limit } baino handiagoa da: altuegia formula zehatzetarako
parameter-no-value = '{ $name }' parametroak ez du baliorik
number-too-many-digits = { $number } zenbakiak zifra gehiegi ditu formula zehatzetarako ({ $limit } baino gehiago zatiki gisa): biribildu edo ebatzi zenbakiekin

## ereduaren forma (model/build.py, model/model.py)
model-mapping = eredu bat points, bodies, joints, drivers gakoak dituen hiztegi bat da
frame-missing = ez dago '{ $frame }' solido finkorik: deitu '{ $frame }' solido bati edo jarri `frame:` gakoan hauetako bat: { $bodies }
parameter-name-invalid = '{ $name }' ez da parametro-izen zuzena (letrak, zifrak eta _, zifra batez hasi gabe)
unknown-name-in = izen ezezaguna '{ $name }' '{ $text }' adierazpenean
unknown-name-in-parameters = izen ezezaguna '{ $name }' '{ $text }' adierazpenean (parametroak: { $parameters })
components-count = { $dims } osagai espero ziren, baina { $got } daude
model-no-points = eredu batek puntu bat behar du gutxienez
name-invalid = '{ $name }' ezin da izen bat izan: izenak ez daude hutsik eta ez dute '@' (puntu bat bere solidoarekin lotzen du: B@rocker)
construction-planar = eraikuntzazko puntuak lauak dira; eman 3D eredu baten puntuak [x, y, z] koordenatu gisa
planar-two-coordinates = eredu lau batek (2. dimentsioa) 2 koordenatu ditu puntu bakoitzeko
point-listed-twice = '{ $point }' puntua bi aldiz dago zerrendan
point-not-carried = ez dago '{ $point }' puntua daraman solidorik: gehitu solido baten puntuetara
unknown-point = puntu ezezaguna '{ $point }' (puntuak: { $points })
vector-size = eredu { $dim ->
        [2] lau batek
       *[other] 3D batek
    } { $dim } { $what ->
        [coordinates] koordenatu
       *[components] osagai
    } behar ditu, baina { $got } daude
shapes-3d-only = diskoak eta planoak 3D ereduenak dira; eredu lau batean erabili zirkunferentzia (circle) eta zuzena (line)
shapes-planar-only = kurbak eta espekak eredu lauenak dira
unknown-body = solido ezezaguna '{ $body }' (solidoak: { $bodies })
joint-id-empty = lotura baten identifikatzailea ez dago hutsik
joint-id-twice = '{ $id }' lotura-identifikatzailea bi aldiz erabiltzen da
joint-same-body = lotura batek bi solido desberdin lotzen ditu, baina '{ $body }' bi aldiz dago
joint-point-not-on-body = `{ $kind }` motako loturaren '{ $point }' puntua ez dago '{ $body }' solidoan: gehitu '{ $point }' haren puntuetara
direction-same-points = norabide batek bi puntu desberdin behar ditu
unknown-joint = lotura ezezaguna '{ $joint }' (loturak: { $joints })
unknown-joint-bare = lotura ezezaguna '{ $joint }'
expected-one-number = zenbaki bat espero zen (`along` norabideko osagaia), baina bektore bat dago
expected-vector = { $dim } osagaiko bektore bat espero zen (edo eman `along` osagai bakar baterako)
questions-too-many = { $count } galdera: gehienez { $limit } eredu batean
question-one-key = galdera batek gako hauetako bat du, bakar bat: { $keys }
contact-not-touching = '{ $text }' ez da { $kinds } motako lotura bat (halakoak dira: { $joints })
decompose-needs-moving = decompose galdera batek `moving: BODY` behar du, erreferentzia mugikorra
moving-only-decompose = `moving` decompose galderetan baino ez doa
question-planar-only = { $kind } mugimendu lauko galdera da; 3D-n galdetu ardatz helikoidalari buruz (`axis`)
question-3d-only = ardatz helikoidala 3D galdera da; eredu lau batean galdetu biraketa-zentro instantaneoari buruz (`icr`)
steps-at-least-one = steps gutxienez 1 izan behar da

## pydantic-ek fitxategi baten forman aurkitzen duena (model/build.py, cams/spec.py)
schema-problems = { $problem }{ $others ->
        [0] {""}
        [one] {" "}(eta beste arazo { $others })
       *[other] {" "}(eta beste { $others } arazo)
    }
driver-second-kind = eragile batek gako hauetako bat du, bakar bat: { $kinds }; '{ $key }' bigarren bat da
unknown-key = gako ezezaguna '{ $key }'
missing-key = '{ $key }' gakoa falta da
not-one-of = { $value } ez da hauetako bat: { $expected }
unexpected-value = ustekabeko balioa { $value }: { $problem }
pydantic = { $type ->
        [missing] falta da
        [extra_forbidden] gako ezezaguna
        [float_type] zenbaki bat espero zen
        [int_type] zenbaki oso bat espero zen
        [int_from_float] zenbaki oso bat espero zen
        [int_parsing] zenbaki oso bat espero zen
        [float_parsing] zenbaki bat espero zen
        [finite_number] zenbaki finitu bat espero zen
        [string_type] testu bat espero zen
        [bool_type] true edo false espero zen
        [list_type] zerrenda bat espero zen
        [dict_type] hiztegi bat espero zen (gakoak eta balioak)
        [model_type] hiztegi bat espero zen (gakoak eta balioak)
        [model_attributes_type] hiztegi bat espero zen (gakoak eta balioak)
        [too_short] gutxienez { $ctx_min_length } elementu espero ziren
        [too_long] gehienez { $ctx_max_length } elementu espero ziren
        [greater_than] { $ctx_gt } baino handiagoa izan behar da
        [greater_than_equal] gutxienez { $ctx_ge } izan behar da
        [less_than] { $ctx_lt } baino txikiagoa izan behar da
        [less_than_equal] gehienez { $ctx_le } izan behar da
        [literal_error] ez da onartutako balioetako bat
        [union_tag_invalid] ez da onartutako formetako bat
        [union_tag_not_found] ez da onartutako formetako bat
        [construction_kind] puntu bat [x, y] koordenatuak dira, edo gako hauetako bat duen eraikuntza bat: from, frame, circles, circle, lines
        [driver_kind] eragile batek gako hauetako bat behar du: omega, joint edo velocity
       *[other] balio hori ez dator bat hemen
    }
point-name-not-text = puntu bat testu batez izendatzen da, 'B' edo 'B@rocker' bezala, baina { $got } dago
point-body-after-at = '{ $text }': idatzi solidoa '@' ikurraren ondoren ('{ $example }' adibidean bezala)
body-not-carrying = '{ $body }' solidoak ez darama '{ $point }' puntua (hauek daramate: { $carriers })
point-ambiguous = '{ $point }' puntua hauek daramate: { $carriers }, eta han modu desberdinean mugitzen dira: idatzi { $choices }
unknown-parameter = parametro ezezaguna '{ $name }' (parametroak: { $parameters })
name-or-note-empty = izen bat edo ohar bat ez dago hutsik
notation-key-unknown = '{ $key }' ez da parametro bat (parametroak: { $parameters }), ezta omega(BODY), omega(BODY/OTHER), alpha(…) ere
notation-rate-bodies = '{ $key }': abiadura angeluar bat solido batena da, edo solido batena beste batekiko (omega(blades/block))
notation-spelling = '{ $name }' ez da ikur baten izena: letrak, zifrak eta _, sympy-k idazten dituen bezala (omega_0 ω₀ da, vdot v̇, R_roda)
draw-at-has-value = '{ $name }' parametroak badu balioa: draw_at gakoak parametro sinbolikoei (null) ematen die zenbakia
draw-at-not-finite = '{ $name }' parametroa { $value } balioarekin marrazten da: eman zenbaki finitu{ $positive ->
        [true] {" "}eta positibo
       *[other] {""}
    } bat
draw-at-range = '{ $name }' parametroa { $value } balioarekin marrazten da: irudiak { $low } eta { $high } arteko tamainako zenbakiekin marrazten dira
up-planar = up gakoak 3D eredu baten bertikala izendatzen du; eredu lau bat bere planoan marrazten da
up-direction = up 3 zenbakiko norabide ez-nulu bat da, [0, 1, 0] bezala
construction-cycle = eraikuntzek elkar aipatzen dute ziklo batean: { $cycle }
construction-point-expected = puntu baten izena edo [x, y] koordenatuak espero ziren, baina { $got } dago
construction-coordinates = eraikuntzak lauak dira: [x, y] koordenatuak, baina { $got } osagai daude
construction-circle-radius = zirkunferentzia bat [zentroa, erradioa] da: erradioa zenbaki bakar bat da
circle-arc = zirkunferentzia baten arkua [hasiera, amaiera] (graduak, erlojuaren orratzen aurkako noranzkoan) haren zati bat da: 0 < amaiera − hasiera < 360 (hemen { $start }-tik { $end }-ra)
construction-line-direction = zuzen baten norabidea bektore bat da; bi puntutatik pasatzen den zuzen baterako idatzi [P, Q]
construction-direction-planar = eraikuntzak lauak dira: norabide bat [dx, dy]
near-symbolic = `near` gakoak zenbakiak behar ditu; parametro sinbolikoak dituen eredu batean aukeratu ebakidura `side` gakoarekin
near-point = `near` zirriborroko puntu bat da [x, y]
two-points-same = bi puntu desberdin behar dira, baina '{ $point }' bi aldiz dago
statement-placeholder = {"{"}{ $name }{"}"} ez da parametro bat (parametroak: { $parameters })
unit-not-length = '{ $unit }' ez da luzera-unitate bat (unitateak: { $units })
question-missing = { $number }. galdera ez dago: ereduak { $count } galdera egiten ditu (1etik zenbatuta)
graded-once = izendatu kalifikatutako galdera bakoitza behin (gutxienez bat)
tolerance-relative = tolerantzia erlatiboa da, 0 eta 1 artekoa: { $tolerance } dago
unknown-point-bare = puntu ezezaguna '{ $point }'
unknown-unit = unitate ezezaguna '{ $unit }' (unitateak: { $units })
parameters-mapping = parametroak izenen eta balioen hiztegi bat dira, baina { $type } dago

## espekak (cams/*.py) eta kurbak (curves/*.py)
cam-translating-no-key = jarraitzaile translazional batek ez du '{ $key }'
cam-oscillating-no-offset = jarraitzaile oszilakor batek ez du 'offset' (kokatu haren pibotea)
cam-oscillating-pivot = jarraitzaile oszilakor batek 'pivot' behar du (espekaren zentrorako distantzia)
cam-oscillating-arm = jarraitzaile oszilakor batek 'arm' behar du (pibotetik arrabolaren zentrora edo ertz zorrotzera)
cam-roller-radius = arrabola-jarraitzaile batek 'radius' behar du
cam-no-radius = `{ $contact }` motako jarraitzaile batek ez du 'radius'
cam-polynomial-only = tarte polinomiko batek baino ez du onartzen '{ $key }' baldintzarik
cam-dwell-to = geldiune batek geldirik mantentzen du jarraitzailea: kendu 'to'
cam-segment-to = `{ $law }` motako tarte batek 'to' behar du (amaierako desplazamendua)
cam-below-lowest = jarraitzailea bere posiziorik baxuenaren azpitik joango litzateke (s < 0, oinarrizko zirkunferentziaren barruan)
cam-segment-still = `{ $law }` motako tarte batek jarraitzailea mugitu behar du: 'to' hasierako desplazamenduaren berdina da (erabili geldiune bat)
cam-span = tarteek { $total }° hartzen dituzte; disko-espeka baten programak 360° hartzen ditu
cam-program-ends = programa s = { $end } balioan amaitzen da, ez hasten den tokian (0): disko-espeka baten mugimendua bira bakoitzean errepikatzen da
cam-no-polynomial = ez dago muga-baldintza hauek betetzen dituen polinomiorik
cam-program-or-profile = eman espekaren mugimendua 'program' gakoarekin edo haren forma 'profile' gakoarekin (bietako bat)
cam-base-missing = 'base' gakoa falta da (oinarrizko zirkunferentziaren erradioa)
cam-speed-once = eman espekaren abiadura behin bakarrik: omega (rad/s), rpm edo velocity (espeka translazional bat)
cam-speed-translating = espeka translazional baten abiadura haren 'velocity' da
cam-speed-disc = disko-espeka baten abiadura 'omega' edo 'rpm' da
cam-plate-translating = espeka translazional batek jarraitzaile translazional bat mugitzen du
cam-plate-flat = aurpegi lau batek ezin du espeka translazional bat jarraitu (erabili arrabola bat edo ertz zorrotz bat)
cam-plate-offset = espeka translazional baten jarraitzaileak ez du eszentrikotasunik
cam-offset-prime = { $offset } eszentrikotasunak zirkunferentzia primitiboaren { $radius } erradioa baino txikiagoa izan behar du
cam-face-base = aurpegiak ezin du oinarrizko zirkunferentzia ukitu: 0 < base + face < pivot behar da
cam-arm-reach = besoak ez du zirkunferentzia primitiboa iristen ({ $radius } erradioa): |pivot − arm| < { $radius } < pivot + arm behar da
cam-arm-past = programak besoa { $turn }° biratzen du { $start }°-tik, { $reach }°-tik harago (jarraitzaileak espeka galtzen duen tokia)
cam-file-mapping = espeka-fitxategi bat cam, follower, program (edo profile), speed gakoak dituen hiztegi bat da
value-problem = { $value }: { $problem }
cam-profile-disc = profileko puntuen bidez emandako espeka bat disko-espeka da
cam-profile-base = profileko puntuen bidez emandako espeka batek haren profilak ematen duen oinarrizko zirkunferentzia du: kendu 'base'
cam-follower-misses = jarraitzaileak ez du espeka iristen
cam-knife-misses = ertz zorrotzaren ibilbideak ez du espeka ukitzen
cam-jump = { $quantity ->
        [velocity] abiadurak
       *[acceleration] azelerazioak
    } { $size } { $unit } egiten du jauzi { $at }{ $place } puntuan ({ $quantity ->
        [velocity] azelerazio infinitua
       *[acceleration] jerk infinitua
    }: espeken diseinuaren oinarrizko legea hausten da)
curve-line-direction = zuzen baten norabidea ezin da nulua izan
curve-unbounded = kurba ez-bornatu batek ez du marrazteko punturik: eman eremu finitu bat
spline-points = spline baten puntuak (x, y) bikoteen zerrenda bat dira
spline-too-few = spline { $closed ->
        [true] itxi batek
       *[false] ireki batek
    } gutxienez { $need } puntu behar ditu
spline-points-differ = spline baten ondoz ondoko puntuek desberdinak izan behar dute
circle-radius-positive = zirkunferentzia baten erradioak positiboa izan behar du
arc-angles = arku bat erlojuaren orratzen aurkako noranzkoan doa a0-tik a1-era, a0 < a1 ≤ a0 + 2π izanik
cam-flat-translating = aurpegi laueko jarraitzaile batek ezin du espeka translazional bat jarraitu

## loturak (joints/*.py)
and-word = eta
nothing = {""}
sweep-velocity-only = ekorketa batek ezin du `{ $kind }` motako lotura bat jarraitu{ $dim ->
        [3] {" "}3D-n
       *[other] {""}
    }: haren baldintza abiaduretakoa baino ez da, eta, beraz, posizioak egindako bidearen araberakoak dira{ $in_time ->
        [true] ; `kinematika simulate` aginduak denboran jarraitzen du
       *[other] {""}
    }
joint-other-dimension = `{ $kind }` motako lotura bat eredu { $dim ->
        [2] 3D batekoa
       *[other] lau batekoa
    } da
joint-needs-key = `{ $kind }` motako lotura batek `{ $key }` behar du
internal-owners = `internal` lotura hauetan baino ez doa: { $owners }
joint-no-key = `{ $kind }` motako lotura batek ez du `{ $key }`{ $planar ->
        [true] {" "}eredu lau batean (biraketak z-ren ingurukoak dira)
       *[other] {""}
    }
joint-no-rate = `{ $kind }` motako lotura batek ez du ezartzeko abiadurarik; ezarri solido baten omega edo puntu baten abiadura
rounding-hint = , tolerantzia ({ $tolerance }) baino handiagoa (ereduaren tamainaren 1e-6): idatzi { $point } eraikuntzaz edo zifra gehiagorekin
slot-off-line = '{ $point }' ziria { $line } zuzenetik kanpo dago: tartea { $gap }{ $hint }
cam-joint-first-body = espeka-lotura baten lehen solidoak darama espeka: eman '{ $body }' solidoari `cam:` forma bat
cam-joint-face = aurpegi laueko jarraitzaile batek bere aurpegiaz ukitzen du: eman '{ $body }' solidoari `line` zuzen bat (aurpegia)
cam-joint-at = espeka-lotura batek `at` behar du: { $roller ->
        [true] jarraitzailearen arrabolaren zentroa
       *[other] jarraitzailearen ertz zorrotza
    }
curved-slot-outline = arteka kurbatu bat '{ $body }' solidoaren zirkunferentzia edo kurba batean zehar ebakitzen da: eman bat solido horri
cylindrical-two-rates = lotura zilindriko batek bi abiadura ditu (biraketa eta irristadura): ezarri solidoaren omega beste solidoarekiko (relative_to) eta puntu baten abiadura ardatzean zehar
rolling-needs-shapes = `{ $kind }` motako lotura batek forma bat behar du bi solidoetan: eman '{ $body }' solidoari { $dim ->
        [2] zirkunferentzia bat edo zuzen bat
       *[other] disko bat edo plano bat
    }
shapes-cannot-roll = forma hauek ezin dute bata bestearen gainean errodatu
no-touch = '{ $body }' solidoak ez du '{ $other }' ukitzen: tartea { $gap }{ $hint }
the-contact-or-centre = kontaktua edo zentroa
the-contact = kontaktua
contact-not-at = kontaktua ez dago '{ $point }' puntuan: { $distance } distantziara dago{ $hint }
internal-circles-only = `internal` gakoak bi zirkunferentzia nola ukitzen diren esaten du; kontaktu hau `{ $contact }` motakoa da
rolling-internal-wrong = `{ $kind }` bikotea { $said ->
        [internal] barnekotzat
       *[external] kanpokotzat
    } ematen da, baina haren { $kind ->
        [gear] zirkunferentzia primitiboak
       *[other] zirkunferentziak
    } { $said ->
        [internal] kanpotik
       *[external] barrutik
    } ukitzen dira
disc-flat-on-plane = '{ $disc }' diskoa '{ $plane }' solidoaren planoaren gainean etzanda dago: aurpegi osoz ukitzen du, ez puntu batean
sweep-rolling-only = ekorketa batek zirkunferentzien eta zuzenen errodadura baino ez du jarraitzen
contact-acceleration-curve = kurba orokor baten gaineko kontaktu-puntu geometrikoaren azelerazioak haren kurbaduraren aldakuntza behar du: galdetu solidoen puntuei buruz
straight-outlines = bi ingerada zuzen zuzen batean zehar ukitzen dira, ez puntu batean: lotu itzazu lotura prismatiko batez
pair-cannot = `{ $kind }` '{ $body }' eta '{ $other }' artean: { $why }
touching-needs-outlines = `{ $kind }` motako lotura batek ingerada bat behar du bi solidoetan: eman '{ $body }' solidoari zirkunferentzia bat, zuzen bat edo kurba bat (edo izendatu haren puntua `at` gakoarekin)
outlines-cannot-touch = ingerada hauek ezin dute elkar ukitu puntu batean

## mugimenduaren baldintzak, mezuetan izendatuta
row-joint = { $id }: { $label }
row-driver = { $where } ({ $label })
row-joint-rate = { $joint } loturaren abiadura = { $value }
row-rate = { $body } solidoaren { $name }
row-rate-relative = { $body } solidoaren { $name }, { $relative } solidoarekiko
row-equals = { $label } = { $value }
row-component = { $label } ({ $axis }) = { $value }
row-point-along = { $point } puntuaren { $name } emandako norabidean = { $value }
row-point = { $point } puntuaren { $name }
row-idle = { $body } solidoak ez du biraketa alferrik { $axis } ardatzaren inguruan
row-curved-slot = { $point } { $body } solidoaren arteka kurbatuan mantentzen da
row-turning-axis = biraketa erlatiboa ardatzaren inguruan soilik ({ $n })
row-sliding-axis = irristadura erlatiboa ardatzean zehar soilik ({ $n })
row-across-guide = mugimendu erlatiborik ez gidarekiko zeharka ({ $n })
row-moves-with = { $point } { $other } puntuarekin mugitzen da ({ $axis })
row-no-slip = irristatzerik ez { $body } eta { $other } solidoen kontaktuan ({ $axis })
row-slot = { $point } { $body } solidoaren artekan mantentzen da
row-turns-with = { $body } { $other } solidoarekin biratzen da
row-body-moves-with = { $body } { $other } solidoarekin mugitzen da ({ $axis })
row-no-sideways = { $point } puntuak ez du alboko abiadurarik { $body } solidoarekiko
row-touching = { $b } solidoak { $a } ukitzen jarraitzen du
row-cam-touching = { $b } jarraitzaileak { $a } espeka ukitzen jarraitzen du
row-no-rotation = biraketa erlatiborik ez
row-no-rotation-axis = biraketa erlatiborik ez ({ $axis })

## mekanismoaren mugikortasuna (engine/mobility.py)
infinite = infinitua
dead-point = puntu hil bat: eragileek ez dute hemen mugimendua finkatzen; { $count ->
        [0] eragileak
        [one] { $drivers }
       *[other] { $drivers }
    } loturen mende { $count ->
        [one] dago
       *[other] daude
    } (baldintza-zenbakia { $condition } Jacobiar adimentsionalean, muga { $limit })
mobility-free = mekanismoak { $dof ->
        [one] askatasun-gradu { $dof } du
       *[other] { $dof } askatasun-gradu ditu
    }, baina eragileek { $conditions ->
        [one] baldintza independente { $conditions } ematen dute
       *[other] { $conditions } baldintza independente ematen dituzte
    }; aske geratzen da: { $count ->
        [0] mugimenduaren zati bat
       *[other] { $free }
    }
drivers-conflict = eragileek elkarren kontra egiten dute, haien balioak ez datoz bat elkarren artean edo loturekin: { $named } ({ $dof ->
        [one] askatasun-gradu { $dof }
       *[other] { $dof } askatasun-gradu
    }; { $given ->
        [one] emandako baldintza { $given }
       *[other] emandako { $given } baldintza
    }, { $conditions } independente)

## unea: balioak, norabideak, eraikuntzazko puntuak (engine/*.py)
direction-zero = norabide bat ezin da bektore nulua izan
direction-not-exact = norabide hau ezin da zehazki bektore unitario bihurtu: haren osagaien tamainak desberdinegiak dira (idatzi txikia 0 gisa)
direction-points-coincide = norabide batek bi puntu desberdin behar ditu: { $start } eta { $end } bat datoz
value-not-real = balio bat ez da zenbaki erreala ikurren balioetarako (kantitate negatibo baten erro karratua edo berretura?)
parameters-cycle = parametroek elkar aipatzen dute ziklo batean: { $names }
points-not-real = puntuak ez dira errealak probatutako ikur-balioetako batean ere (zenbaki negatibo baten erro karratua?)
curves-need-numbers = kurbak eta espekak zenbakiekin marrazten dira: eman parametroei haien balioak (edo ebatzi --symbolic gabe)
curve-through-points = kurba ezin da marraztu haren puntuetatik: { $why }
radius-positive = erradio batek positiboa izan behar du, baina { $radius } da
jacobian-singular-large = { $rows }×{ $columns } murrizketa-Jacobiarra singularra da edo ez da karratua (LU sakabanatua); sistema handiegia da zein baldintza falta diren edo besteen mende dauden esateko
structurally-singular = sistemak ez du ezezagun bakoitzerako egituraz independentea den baldintza-multzorik
angle-in-radians = { $angle } angelua radianetan dago: { $degrees }°, { $turns } bira; { $angle }° adierazteko idatzi deg({ $written })
point-too-large = { $point } puntuaren koordenatu zehatzek { $size } eragiketa inguru izango lituzkete ({ $limit } baino gehiago): handiegiak formuletarako; eman zenbakiak parametro gehiagori edo ebatzi --symbolic gabe
length-positive = { $what ->
       *[radius] erradio batek
    } positiboa izan behar du, baina { $value } da
direction-points-same = norabidea ematen duten bi puntuak bat datoz
fit-each-side = , bat { $line } zuzenaren alde bakoitzean
fit-on-line = {" "}{ $line } zuzenean
circles-same-centre = { $a } eta { $b } zentroko zirkunferentziek zentro bera dute
circles-apart = { $a } ({ $ra }) eta { $b } ({ $rb }) zentroko zirkunferentziak ez dira ebakitzen: zentroak { $d } distantziara, { $ra } + { $rb } baino { $gap } gehiago
circles-inside = { $a } ({ $ra }) eta { $b } ({ $rb }) zentroko zirkunferentziak ez dira ebakitzen: { $inner } zentrokoa { $outer } zentrokoaren barruan dago (zentroak { $d } distantziara, |{ $ra } − { $rb }| baino { $gap } gutxiago)
line-direction-zero = zuzen baten norabidea ezin da bektore nulua izan
circle-misses-line = { $centre } zentroko zirkunferentziak ({ $radius }) ez du { $line } zuzena ebakitzen: zuzena { $centre } puntutik { $distance } distantziara dago, erradioa baino { $gap } gehiago
lines-parallel = { $a } eta { $b } zuzenak paraleloak dira: ez dira ebakitzen
line-points-coincide = { $line } zuzena bat datozen bi puntuz ematen da
two-points-fit = bi puntu posible daude{ $relation }: { $points }; aukeratu bat side: { $first } edo { $second } gakoarekin, edo near: [x, y] gakoarekin
beyond-floats = koma mugikorreko zenbakiek onartzen dutena baino gehiago
model-size-range = ereduaren tamaina { $size } da: kinematikak { $low } eta { $high } arteko luzerekin kalkulatzen du, edozein unitatetan; idatzi luzerak beste unitate batean
rates-range = eragileen balioak mekanismo honen tartetik kanpo daude ({ $rate } abiadura denbora-unitateko): kinematikak { $low } eta { $high } arteko abiadurekin kalkulatzen du; idatzi denborak beste unitate batean
values-overflow = ereduaren balioak handiegiak dira: haren abiadurek edo azelerazioek gainezka egiten dute koma mugikorreko zenbakien tartetik

## lanaren mugak, aukerako moduluak, hizkuntzak (budget.py, extras.py, languages.py)
over-budget = { $what } aurkitzeak { $counted ->
        [true] aljebra zehatzeko { $steps } urrats baino gehiago
       *[other] { $seconds } s CPU baino gehiago
    } eskatzen ditu{ $staged ->
        [true] {" "}({ $stage })
       *[other] {""}
    }: handiegiak dira; { $advice }
exact-formulas = formula zehatzak
stage-solving = ekuazioak zehazki ebazten
stage-simplifying = formulak sinplifikatzen
advice-symbolic = eman zenbakiak parametro batzuei edo ebatzi --symbolic gabe
advice-null = eman zenbakiak ikur gisa utzitako parametro batzuei (null: { $names })
advice-numbers = eman zenbakiak parametro batzuei
module-missing = { $what }: { $module } behar da, eta ez dago instalatuta: instalatu honela: { $command }
writing-parquet = Parquet idaztea (edo idatzi .npz)
writing-dxf = DXF idaztea
study-on-dask = Dask kluster batean egindako azterketa bat
unknown-language = hizkuntza ezezaguna '{ $lang }' (hizkuntzak: { $langs })
centres-planar = biraketa-zentro instantaneoak mugimendu laukoak dira; 3D-n galdetu solido bakoitzaren ardatz helikoidalari buruz (`axis`)

## ekorketak, mugimenduak eta muntaiak (sweep/*.py)
assembly-not-whole = muntaia bat zenbaki oso bat da, baina { $got } dago
assembly-missing = ez dago { $number }. muntaiarik: mekanismo honek { $count } ditu marraztutako sarreran (ikus `kinematika assemblies`)
assemblies-too-many = { $dyads } diada bi modutara ixten dira bakoitza: 2^{ $dyads } muntaia zerrendatzeak 2^{ $limit } muga gainditzen du
sweep-by-varied = ekorketaren luzera ({ $by }) aldatutako parametro baten mende dago: eman zenbaki gisa (--by)
move-not-number = { $problem } (mugimendu bat gradu- edo luzera-kopuru bat da)
move-not-finite = mugimendu bat zenbaki finitu bat da
move-not-driven = '{ $joint }' lotura ez da eragilea; `move` gakoak lotura eragile bat aurreratzen du ({ $count ->
        [0] hemen ez dago bat ere
       *[other] { $driven }
    })
move-unreachable = { $joint } ezin da { $amount }{ $unit } mugitu: mekanismoa puntu hil batera iristen da edo desmuntatu egiten da { $got }{ $unit } ondoren
sweep-by-needed = '{ $joint }' lotura `{ $kind }` motakoa da: eman ekorketaren luzera (`by` ereduaren sweep atalean, edo --by)
steps-whole = steps zenbaki oso bat izan behar da, baina { $got } dago
steps-range = steps 1 eta { $limit } artean egon behar da, baina { $got } dago
steps-too-many-values = bakoitza { $per_row } baliokoak diren { $steps } urrats ekorketa batean sartzen dena baino gehiago dira ({ $limit } balio): eman gehienez { $most } urrats
by-number = by zenbaki bat izan behar da, baina { $got } dago
by-finite = by zenbaki finitu bat izan behar da
sweep-no-driven-joint = ez dago ekortzeko lotura eragilerik: ezarri lotura baten abiadura, edo giltzadura edo lotura prismatiko baten bidez solido finkoari lotutako solido baten omega edo abiadura
sweep-not-driven = '{ $joint }' lotura ez da eragilea; ekorketa batek lotura eragile bat aurreratzen du: { $driven }
fixture-shape = { $shape } formaren kokapena
fixture-joint = { $joint } loturaren norabidea
move-symbolic-3d = parametro sinbolikoak dituen 3D eredu bat ezin da mugitu: eman balioak haren parametroei (--set NAME=VALUE)
move-symbolic-once = parametro sinbolikoak dituen eredu bat behin bakarrik mugitzen da: eman haren mugimendu guztiak batera
move-same-body = bi mugimenduk solido bera biratzen dute: eman mugimendu bakar bat
move-not-input = '{ $joint }' loturak ez du solido bat solido finkoarekin lotzen: mugitu parametro sinbolikoak dituen eredu bat haren sarrera-loturaren bidez
move-at-values = ezin da mugitu: eredua betetzen den ikur-balioetan ({ $values }), { $problem }
move-exact-numbers = ezin da zehazki mugitu: '{ $point }' puntuak sarrera jarraitzen du zenbakitan, ez haren koordenatu zehatzetan (eman balioak parametroei)
move-exact-rolls = ezin da zehazki mugitu: '{ $point }' puntua '{ $body }' solidoan dago, eta zuzen baten gainean errodatzen du: haren biraketa zentroaren ibilbidea zati erradioa da, eta hemen ez du forma itxirik (eman balioak parametroei)
move-exact-no-form = ezin da zehazki mugitu: '{ $point }' puntuak ez du sarrera jarraitzen: ez eraikuntza batek, ez errodadura-erlazio batek, ez beste solido batek ez du '{ $body }' solidoaren posizioa ematen forma itxian; idatzi { $point } eraikuntzaz (edo eman balioak)
move-exact-constructed = ezin da zehazki mugitu: '{ $point }' puntuak ez du sarrera jarraitzen: { $body } solidoarekin mugitzen ez diren puntuekin eraikita dago; eraiki ezazu haiekin (edo eman balioak)
move-exact-fixture = ezin da zehazki mugitu: '{ $body }' solidoak forma itxirik gabe biratzen du hemen, eta haren { $what } zenbakitan idatzita dago; eman puntuen bidez (edo eman balioak parametroei)
body-no-point = '{ $body }' solidoak ez darama punturik, eta, beraz, haren formak ezin dira mugitu: gehitu haren puntuetako bat
cannot-assemble-there = mekanismoa ezin da hor muntatu
sweep-at = { $k }. gehikuntza ({ $joint } = { $value } { $unit })
sweep-drivers-contradict = idatzita dauden eragileek loturen kontra egiten dute { $at } posizioan: eragile bektorial bat (ω 3D-n, abiadura bat) solido finkoaren ardatzetan finko geratzen da mekanismoak biratzen duen bitartean; ezarri horren ordez loturaren abiadura
sweep-singular = { $at } posizioko konfigurazioa singularra da eragileentzat (puntu hil bat: baldintza-zenbakia 1e+10 baino handiagoa){ $said ->
        [true] {" "}({ $what })
       *[other] {""}
    }; erabili --skip-bad posizio horiek saltatzeko
sweep-cannot-assemble = mekanismoa ezin da muntatu { $at } posizioan{ $said ->
        [true] : { $what } solidoek ezin dute begizta itxi
       *[other] {""}
    }; erabili --skip-bad posizio horiek saltatzeko

## azterketak eta sintesia (explore/*.py)
metrics-once = metrika bakoitza behin, eta bat ere ez parametro baten izenarekin edo 'assembles'/'reason' izenarekin
study-needs-numbers = azterketa batek zenbakiak behar ditu: eman balio bat hauei, edo aldatu itzazu: { $names }
vary-form = --vary aukerak NAME=LOW:HIGH espero du (a=1:5 bezala), baina { $got } dago
vary-interval = --vary { $name }: tarteak finitua izan behar du, LOW <= HIGH izanik, baina { $got } dago
vary-none = izendatu aldatzeko parametro bat gutxienez (--vary NAME=LOW:HIGH)
varied-twice = parametro bat bi aldiz aldatzen da: { $names }
grid-or-samples = eman --grid N edo --samples N
grid-positive = --grid eta --samples aukerek zenbaki positibo bat hartzen dute
designs-too-many = { $count } diseinu: gehienez { $limit }
motion-error-two-points = motion_error: '{ $body }' solidoak bi puntu behar ditu orientazio bat izateko
metric-unknown = metrika ezezaguna '{ $metric }'; metrikak: grashof, transmission, dead_points, time_ratio[:BODY], range:BODY, peak_omega:BODY, peak_alpha:BODY, peak_speed:POINT, peak_accel:POINT, path_error:POINT=FILE.csv, motion_error:POINT=FILE.csv, structural_error:BODY=FILE.csv, angle|omega|alpha:BODY=X, speed|accel|x|y:POINT=X
grashof-four-bar = grashof metrikak lau barrako mekanismo bat den begizta mugikorra behar du, bere biraderaz eragina
time-ratio-linkage = solidorik gabeko time_ratio metrikak lau barrako mekanismo bat edo biela-biradera bat behar du; izendatu irteera (time_ratio:BODY)
transmission-linkage = transmission metrikak bere biraderaz eragindako lau barrako mekanismo bat edo biela-biradera bat behar du
metric-at-input = { $metric }=X metrikak sarreraren X posizioa hartzen du (zenbaki bat, { $unit } unitatetan marraztutako posiziotik), baina { $got } dago
input-outside-sweep = sarrerak ekorketaren tartean egon behar du, { $low } eta { $high } { $unit } artean
time-ratio-full-turn = time_ratio metrikak biraderaren bira osoko ekorketa behar du (by: 360)
target-csv = { $name }: helburu-fitxategi bat .csv fitxategi bat da
table-not-numbers = { $name }, { $line }. lerroa: zenbakiak espero ziren, baina { $got } dago
table-columns = { $name }, { $line }. lerroa: { $columns } zenbaki finitu espero ziren
table-empty = { $name } fitxategiak ez du zenbaki-errenkadarik
cannot-write = ezin da { $path } idatzi: { $reason }
cannot-read = ezin da { $path } irakurri: { $reason }
study-no-column = azterketak ez du '{ $name }' zutaberik (zutabeak: { $columns })
study-worker-died = azterketaren prozesu bat bat-batean amaitu da (memoriarik gabe?): probatu --workers gutxiagorekin edo --chunk txikiago batekin
dask-unreachable = ezin da Dask-en planifikatzailera iritsi { $scheduler } helbidean: { $reason }
study-interrupted = { $folder } karpetak etendako azterketa bat dauka: gehitu --resume jarraitzeko, edo ezabatu karpeta hori berriro hasteko
study-different = { $folder } karpetak beste azterketa bat dauka (beste eredu, parametro, diseinu edo metrika batzuk): ezabatu berriro hasteko
study-output = irteera .parquet edo .csv fitxategi bat da, baina { $name } dago
study-stopped = { $problem }{ $note }
study-kept = ; { $kept } diseinu gordetzen dira { $folder } karpetan: exekutatu berriro --resume aukerarekin jarraitzeko
study-needs-model = azterketa batek eredu-fitxategi bat edo eredu baten testua behar du
function-unknown-name = { $source } adierazpenean: izen ezezaguna '{ $name }' (funtzioa x-ena da, sarreraren gehikuntzarena)
function-not-finite = { $source } ez da finitua { $low } eta { $high } artean

## ariketak (exercise/*.py)
variant-missing = ez dago { $number }. aldaerarik (aldaerak 1etik { $count }-ra)
vary-unknown-parameter = --vary { $name }: parametro ezezaguna (parametroak: { $parameters })
vary-none-step = izendatu aldatzeko parametro bat gutxienez (--vary NAME=LOW:HIGH[:STEP])
exercise-needs-numbers = ariketa batek zenbakiak behar ditu: eman balio bat parametro sinboliko bakoitzari (edo aldatu ezazu)
exercise-no-model = exercise.json fitxategiak ez du eredu-fitxategia izendatzen
exercise-lacks = exercise.json fitxategian vary, seed edo lang falta da
exercise-cannot-read = ezin da { $path } irakurri: { $reason } (`kinematika exercise` aginduak idatzitako karpeta bat al da?)
file-not-json = { $name } ez da JSON: { $problem }
file-not-json-object = { $name } ez da JSON objektu bat
csv-not-utf8 = { $name } ez da UTF-8 testua
csv-no-column = { $name } fitxategiak ez du '{ $column }' zutaberik (haren goiburua: { $count ->
        [0] bat ere ez
       *[other] { $header }
    })
variants-numbered = aldaerak 1, 2, … zenbakitzen dira, aldatutako parametro bakoitzaren balio batekin
variants-none = ez dago aldaerarik
key-mismatch = key.csv ez dator bat berriro ebatzitako ereduarekin ({ $variant }. aldaera, { $question }): eredua edo erantzun-gakoa editatu al da?
question-not-asked = '{ $question }' ez da galdetzen { $variant }. aldaeran (haren galderak: { $asked })
row-no-student = ikaslerik gabeko errenkada bat
variant-not-number = { $got } aldaera ez da zenbaki bat
answered-twice = { $student } ikasleak bi aldiz erantzuten du { $variant }. aldaerako { $question } (lehen aldiz { $first }. lerroan)
statement-missing = ariketaren atalak ez du enuntziaturik '{ $lang }' hizkuntzan (hauetan du: { $langs })
vary-step-form = --vary aukerak NAME=LOW:HIGH[:STEP] espero du (s=300:500:10 bezala), baina { $got } dago
vary-step-interval = --vary { $name }: eman LOW <= HIGH eta STEP positibo bat, baina { $got } dago
vary-grid-large = --vary { $name }: { $count } balio saretan, gehienez { $limit }: hartu urrats handiago bat
count-range = --count aukerak 1etik { $limit }-ra bitarteko aldaerak onartzen ditu, baina { $got } dago
grids-too-small = sareek { $total } aldaera desberdin ematen dituzte, --count { $count } baino gutxiago: zabaldu tarte bat edo hartu urrats txikiagoak
variants-few = { $count } aldaeretatik { $found } baino ez dira aurkitu zozketatutako { $drawn } artean: { $apart } ez dira muntatzen, { $dead } puntu hil batetik gertu daude, { $close } aldaeratan ezin da ohiko akats bat erantzun zuzenetik bereizi; aldatu tarteak
weights-count = eman pisu bat kalifikatutako galdera bakoitzeko: { $count }, baina { $got } dago
weight-positive = pisua zenbaki positibo bat da, baina { $got } dago
reveal-after-check = ebazpena urratsez urrats egiaztatu ondoren erakusten da: bidali erantzunak eskaerarekin batera
students-first-column = { $name }: lehen zutabean ikasleen identifikatzaileek egon behar dute
student-twice = { $student } ikaslea bi aldiz dago zerrendan ({ $first }. eta { $line }. lerroetan)
student-variant-range = { $got } aldaera ez dago 1etik { $count }-ra bitartean
table-unreadable = ezin da { $path } irakurri: { $reason }
table-empty = { $name } hutsik dago (goiburu bat eta gero errenkada bat lerro bakoitzeko)
table-no-column = { $name } fitxategiak ez du '{ $column }' zutaberik (haren goiburua: { $header }; zutabeak: { $columns })
row-fields = { $count } eremu, baina goiburuak { $header } ditu (koma duen balio bat komatxo artean idazten da)
row-not-read = { $place }: ez da irakurri: { $error }
students-unknown = ez daude klaseko zerrendan (kanpoan utzi dira): { $students }
grade-column = { $column ->
        [question] galdera
        [answers] erantzunak
        [right] zuzenak
        [carried] ondorioztatuak
        [mistakes] akatsak
        [student] ikaslea
        [variant] aldaera
       *[score] nota
    }
grade-score = %{ $score }
exercise-not-drawn-rounding = baztertua: { $data }: datuak 3 zifratara biribiltzean { $question } %{ $gap } aldatzen da
exercise-not-drawn-mistake = baztertua: { $data }: { $kind } akatsarekin { $question } erantzun zuzenetik %{ $gap } baino gutxiagora dago
exercise-narrowed = { $number }. aldaera: { $question } galderaren tartea %{ $tolerance } arte estutu da { $kind } akatsa bereizteko (akats horrek %{ $gap } aldentzen du)
exercise-wrote = { $count } aldaera idatzi dira { $folder } karpetan
exercise-progress = irudiak eta ebazpenak urratsez urrats: { $done }/{ $total }
pdf-skipped = ez da PDFa sortu: { $program } ez dago instalatuta ({ $hint })

## irudiak eta azalpenak (draw/*.py, explain/*.py, web/strings.py)
animate-planar = animate aginduak eredu lauak marrazten ditu; marraztu 3D eredu baten unea `kinematika draw` aginduarekin
ffmpeg-missing = .mp4 idazteko ffmpeg programa behar da, eta ez dago instalatuta (Debian edo Ubuntun: apt install ffmpeg; conda-rekin: conda install ffmpeg); edo idatzi .gif bat, ez du beste ezer behar
sweep-none-assembled = ekorketaren posizio bakar bat ere ezin izan da muntatu
trace-unknown-point = marrazteko puntu ezezaguna '{ $point }'
plot-format = ezin da '{ $name }' fitxategian marraztu: eman .png, .svg edo .pdf fitxategi bat
draw-at-not-real = eredua ezin da balio hauekin marraztu: { $point } puntua ez da erreala hor
unknown-format = formatu ezezaguna '{ $format }' (formatuak: { $formats })
catalogue-no-message = ez dago '{ $key }' mezurik '{ $lang }' katalogoan
catalogue-message-error = '{ $lang }' katalogoko '{ $key }' mezua: { $problem }
page-message-error = orriko '{ $key }' mezua ({ $lang }): { $problem }

## agindu-lerroa (cli/*.py)
out-of-memory = lanak makina honek ematen duena baino memoria gehiago behar du; txikitu eredua edo ekorketa
internal-error = barne-errorea ({ $detail }); exekutatu berriro KINEMATIKA_DEBUG=1 ezarrita eta jakinarazi
no-folder = ez dago { $folder } karpetarik
it-is-a-folder = karpeta bat da
it-is-a-file = fitxategi bat da
the-output-file = irteerako fitxategia
students-none = { $name } fitxategiak ez du ikaslerik izendatzen (goiburu bat eta gero bat errenkada bakoitzeko)
synthesis-one-target = eman hauetako bat: --target (ibilbidea), --target-function (funtzioa) edo --target-motion (mugimendua)
function-needs-output = funtzio-sorkuntzak --output BODY behar du
path-needs-point = ibilbide- eta mugimendu-sorkuntzak --point P behar du
map-or-pareto = eman --map X,Y,METRIC edo --pareto M1,M2
option-names-count = { $option } aukerak komaz bereizitako { $count } izen hartzen ditu
study-unreadable = ezin da { $path } azterketa irakurri: { $reason }
option-name-value = { $option } aukerak NAME=VALUE espero du, baina { $got } dago
cannot-serve = ezin da { $address } helbidean zerbitzatu: { $reason }
format-needs-output = --format { $format } aukerak -o FILE behar du, idatzi beharreko fitxategia
sweep-format = { $got } ez da ekorketa-formatu bat: eman --format { $formats } edo horietako batean amaitzen den fitxategi bat

## orria eta haren APIa (web/*.py)
build-op = 'op' objektu bat da, eta haren 'op' hauetako bat da: { $actions }
tool-picks = `{ $tool }` tresnak { $count } klik hartzen ditu ({ $picks })
build-path = 'path' gakoen eta indizeen zerrenda bat da
build-value = 'value' zenbaki bat edo adierazpen bat da
build-value-empty = 'value' hutsik dago
build-value-finite = 'value' ez da zenbaki finitu bat
build-nothing-at = ez dago ezer ereduaren { $path } tokian
delete-missing = ez dago ezabatzeko { $element }
delete-what = { $element }: ezabatu point:NAME, body:NAME, joint:ID, driver:N edo ask:N
delete-no-point = ez dago ezabatzeko '{ $point }' punturik
delete-no-body = ez dago ezabatzeko '{ $body }' solidorik (solido finkoa geratu egiten da)
driver-value = eragile baten balioa zenbaki bat edo adierazpen bat da
input-body-or-joint = sarrera ereduaren solido mugikor bat edo lotura bat da
question-kind = { $question }: galdera bat hauetako bat da: { $kinds }
question-target = 'target' gakoak galdetzen den puntua edo solidoa izendatzen du
target-not-moving = { $target } ez dago solido mugikor batean ere
format-one-of = { $format }: formatu bat hauetako bat da: { $formats }
toml-null = { $place } null da, eta TOML-k ezin du hori idatzi (parametro sinboliko bat): utzi eredu hau YAML edo JSON formatuan
the-model = eredua
drag-constructed = { $point } eraikuntzaz dago: arrastatu YAML edo JSON eredu batean, edo editatu haren eraikuntza
no-point-in-model = ez dago '{ $point }' punturik ereduan
drag-not-planar = { $point } ez da bi koordenatuko puntu lau bat
drag-formula = { $point } { $formula } formulak kokatzen du: aldatu haren parametroak mugitzeko
drag-lines-meet = { $point } bi zuzenen ebakidura da: arrastatu zuzenak pasatzen diren puntuak
model-unreadable = eredua ezin da irakurri: { $problem }
drag-toml-form = '{ $point }' puntua ez dago `{ $point } = [x, y]` moduan idatzita [points] taulan
request-vary = 'vary' NAME=LOW:HIGH[:STEP] testuen zerrenda bat da
request-answers = 'answers' gakoak galdera-identifikatzaileak (q2.y) idatzitako zenbakiekin lotzen ditu
request-reveal = 'reveal' true edo false da
request-whole-range = '{ $key }' zenbaki oso bat da, { $low } eta { $high } artekoa
request-whole-least = '{ $key }' zenbaki oso bat da, gutxienez { $low }
request-one-variant = 'vary' gabe ariketak aldaera bakar bat du, ereduaren datuak
help-no-document = ez dago '{ $name }' dokumenturik (laguntzak docs/*.md zerbitzatzen ditu)
no-free-point-name = ez da puntu-izen librerik geratzen
not-finite-number = { $value } ez da zenbaki finitu bat
pick-no-point = oraindik ez dago '{ $point }' punturik
link-two-points = barra batek bi puntu desberdin lotzen ditu
link-length = barra batek luzera behar du: jarri haren muturra beste leku batean
point-two-conditions = { $point } bi baldintzak kokatzen dute jadanik: ezabatu lehenago haren barretako bat
slot-own-points = artekak { $body } solidoaren bi puntutatik pasatzen da: aukeratu beste solido bat edo beste ziri bat
plate-two-points = { $body } solidoak bi puntu behar ditu hirugarren bat finkatu aurretik
track-once = solido finkoak badu pista bat: pista zuzen bakar bat eredu bakoitzeko
wheel-centre = jarri gurpilaren zentroa haren kontaktu-puntutik urrun
gear-centre = jarri bigarren engranajearen zentroa lehenengotik urrun
no-body = ez dago '{ $body }' solidorik
slot-outline-once = { $body } solidoak badu ingerada bat: arteka bakar bat solido bakoitzeko
pin-other-body = { $pin } ziria ez dago { $body } ez den beste solido batean: aukeratu beste solido bateko ziri bat
slot-centre-pin = artekaren zentroa ezin da ziria izan
contact-two-bodies = kontaktu batek bi solido desberdin lotzen ditu
contact-no-outline = { $body } solidoak ez du ukitzeko ingeradarik (zirkunferentzia bat, zuzen bat, kurba bat, espeka bat): idatzi lehenago haren forma testuan
tool-unknown = tresna ezezaguna '{ $tool }' (paletak hauek ditu: { $tools })
request-not-json = eskaera ez da JSON: { $problem }
request-object = eskaera gutxienez 'model' gakoa duen JSON objektu bat da
request-unknown-key = gako ezezaguna '{ $key }' /api/{ $endpoint } helbiderako (onartuak: { $accepted })
request-model = 'model' derrigorrezkoa da: eredu-fitxategiaren testua
request-points = 'points' puntu-izenen zerrenda bat da
request-width = 'width' irudiaren zabalera da hazbetetan, 1etik 100era
request-frame = 'frame' irudiak erakusten duen kutxa da, [x0, y0, x1, y1], x0 < x1 eta y0 < y1 izanik
request-op = 'op' ekintza da: bere 'op' gakoa duen objektu bat
request-to = 'to' puntuaren kokapen berria da [x, y]
request-point = 'point' gakoak mugitu beharreko puntua izendatzen du
request-choice = { $value }: { $key } hauetako bat da: { $choices }
request-flag = '{ $key }' true, false edo null da
request-text = '{ $key }' testu bat da
request-number = '{ $key }' zenbaki bat da
request-assignments = '{ $key }' gakoak izenak zenbakiekin edo adierazpenekin lotzen ditu
request-assignment = { $key }: zenbaki bat edo adierazpen bat
no-example = ez dago '{ $name }' adibide barnekorik
server-busy = zerbitzaria lanpetuta dago: saiatu berriro une batean
server-timeout = kalkuluak { $seconds } s baino gehiago behar izan ditu eta bertan behera utzi da
no-template = ez dago '{ $name }' txantiloirik
request-content-type = bidali eskaera JSON gisa (Content-Type: application/json)
request-too-large = eskaera handiegia da ({ $size } byte; gehienez { $limit })
internal-error-page = barne-errorea ({ $detail }); mesedez, jakinarazi

## agindu-lerroak idazten dituen lerroak (cli/__init__.py, cli/shared.py)
error-line = errorea ({ $kind }): { $text }
internal-line = errorea: { $text }
warning-line = abisua: { $text }
usage-line = errorea (usage): { $text } (ikus { $command } --help)
aborted = etenda
click = { $code ->
        [NoSuchOption] ez dago { $name } aukerarik{ $count ->
            [0] {""}
           *[other] {" "}({ $suggestions } agian?)
        }
        [MissingParameter] { $name } falta da
        [BadParameter] { $name } aukerak ez du balio hori onartzen
        [BadOptionUsage] { $name } aukerak balio bat behar du
        [ExtraArgument] argumentuak soberan daude
        [NoSuchCommand] ez dago '{ $name }' agindurik
       *[other] { $text }
    }
serving-open = { $host } helbidean zerbitzatzen: makina honetara { $port } atakatik iristen den edonork erabil dezake orria (ez du fitxategirik irakurtzen, baina haientzat kalkulatzen du)

## limit positions and rows of a sweep (sweep/limit_positions.py, sweep/continuation.py, sweep/move.py)
sweep-too-many-limits = mugimenduak { $limit } muga-posizio baino gehiago igarotzen ditu; egin ibilbide laburragoko ekorketa
sweep-not-followed = ezin da mugimendua jarraitu { $joint } = { $value } { $unit } posizioaz haratago ({ $travel } { $unit } ibili ondoren): { $why }
follow-turns-back = berehala itzultzen da atzera: mugimenduaren adarrak elkartzen dira bertan
follow-cannot-close = { $bodies } ezin da bertan itxi, eta ez da muga-posizio bat
follow-not-corrected = kurba ezin izan da bertan zuzendu
follow-starts-at-limit = muga-posizio batean hasten da
follow-branches-meet = mugimenduaren adarrak elkartzen dira bertan
follow-runs-off = mekanismoa infinitura doa bertan
follow-too-many-steps = { $limit } jarraipen-urrats baino gehiago bi errenkadaren artean
follow-not-assembled = mekanismoa ezin izan da bertan muntatu
follow-stuck = mekanismoa ezin da urrats bat haratago muntatu, eta ez da muga-posizio bat
row-needs-numbers = ekorketaren errenkada batek zenbakiak behar ditu parametro guztietarako
row-out-of-range = { $row }. errenkada: ekorketak 0tik { $last }ra bitarteko errenkadak ditu
row-cannot-assemble = ekorketaren { $row }. errenkada ezin da muntatu

## renaming on the page (web/rename.py)
rename-not-a-name = '{ $name }' ez da izen bat: letra bat, eta gero letrak, zifrak edo _
rename-element = '{ $element }': berrizendatu body:IZENA edo point:IZENA
rename-language = '{ $lang }': hizkuntza hauetako bat da: { $langs }
rename-nothing = ez dago '{ $element }' izendatzeko
rename-no-body = ez dago '{ $name }' solidorik berrizendatzeko
rename-body-exists = badago '{ $name }' solido bat
rename-no-point = ez dago '{ $name }' punturik berrizendatzeko
rename-point-exists = badago '{ $name }' puntu bat

## the model's notation of indices and spins (model/wording.py)
index-twice = '{ $first }' eta '{ $second }' solidoak biak '{ $index }' idatziko lirateke
spin-not-wheel = '{ $joint }' lotura ez da gurpil bat: gurpil batek bakarrik du bere biraketa-abiadura
spin-shape = biraketa propioa honela idazten da: {"{"}symbol: IZENA, radius: PARAMETROA{"}"} (symbol: phidot, radius: r)
spin-radius-unknown = '{ $radius }' erradioa ez da parametro bat (parametroak: { $parameters })
index-shape = '{ $index }' ez da solido baten indizea: lau letra edo zifra gehienez (N, 1, R, T)
contact-name-shape = '{ $index }' ez da kontaktu-puntu baten izena: lau letra edo zifra gehienez (F, J, K2)

## symbols at their draw_at numbers, travel, straight outlines (sweep/posing.py, sweep/plan.py, joints/touching.py)
needs-draw-at = { $what ->
        [move] mugimendu batek
        [simulate] simulazio batek
       *[sweep] ekorketa batek
    } zenbakiak behar ditu: eman balio bat { $names } parametroei, edo ereduari `draw_at` zenbaki bat ikur bakoitzeko
at-draw-numbers = { $what ->
        [move] mugitua
       *[sweep] ekortua
    } bere ikurren draw_at zenbakietan: { $values }{ $said ->
        [true] {" "}({ $why })
       *[other] {""}
    }
travel-too-far = { $what } { $amount } ekorketa edo mugimendu batek ibiltzen duena baino gehiago da: gehienez { $most }{ $unit ->
        [angle] ° ({ $turns } bira)
       *[length] {" "}(mekanismoaren tamaina { $turns } aldiz)
    }
two-straights-touch = bi ingerada zuzen zuzen batean zehar ukitzen dira, ez puntu batean: lotu itzazu lotura prismatiko batez

## synthesis: its task, its target file, its four-bar (explore/synthesis/*.py, cli/explore.py)
synthesis-no-design = tarteetan ez dago bere zikloa osatzen duen{ $requirements ->
        [0] {""}
       *[other] {" "}eta baldintzak betetzen dituen
    } diseinurik
synthesis-no-full-turn = aurkitutako diseinu batek ere ez du bere sarreraren bira osoa osatzen
synthesis-nothing-found = --vary tarteetako diseinu bat ere ezin da helburu guztietan muntatu{ $count ->
        [0] {""}
       *[other] {" "}eta hauek bete: { $requirements }
    }; zabaldu tarteak edo bilatu denbora gehiagoz
require-crank-rocker-four-bar = `--require crank-rocker` aukerak bere biraderaz eragindako lau barrako mekanismo bat behar du (biradera bat eta solido finkoan ixten diren bi barra), puntua bielan duela
require-transmission-linkage = `--require transmission=DEG` aukerak bere biraderaz eragindako lau barrako mekanismo bat edo biela-biradera bat behar du
require-transmission-angle = --require transmission=DEG: DEG 0 eta 90 gradu arteko angelu bat da, baina { $got } dago
requirement-unknown = baldintza ezezaguna '{ $requirement }'; baldintzak: { $requirements }
timing-needs-four-bar = --timing aukerak bere biraderaz eragindako lau barrako mekanismo bat behar du, zereginaren puntua bielan duela (beste ereduetan, utzi libre helburuen sinkronizazioa)
timing-form = --timing aukerak JOINT edo JOINT=START espero du, baina { $got } dago
timing-start-number = --timing { $joint }=START: START zenbaki bat izan behar da, baina { $got } dago
timing-start-finite = --timing { $joint }=START: START finitua izan behar da
objective-form = --objective aukera `sse` edo `max` da, baina { $got } dago
output-zero-form = --output-zero aukera 'free' da edo angelu bat gradutan, baina { $got } dago
output-zero-function-only = --output-zero funtzio-sorkuntzarako bakarrik da (--target-function)
output-zero-needs-four-bar = --output-zero aukerak lau barrako mekanismo bat behar du, irteera haren balantzina edo biela duena
output-not-rocker-or-coupler = '{ $output }' irteera ez da lau barrako mekanismoaren balantzina ({ $rocker }) ezta biela ({ $coupler }) ere
body-needs-two-points = '{ $body }' solidoak bi puntu behar ditu norabide bat izateko
targets-too-few = { $name }: { $count } helburu; sintesiak gutxienez { $least } behar ditu
target-columns-count = { $name }: { $count } zutabe; zeregin honek { $reads } irakurtzen ditu
target-column-unread = { $name }: zeregin honek ez du '{ $column }' zutabea irakurtzen{ $timing ->
        [true] {" "}(eman --timing JOINT hura erabiltzeko)
       *[other] {""}
    }; { $reads } irakurtzen ditu
target-column-missing = { $name }: ez dago '{ $column }' zutaberik (zeregin honek { $reads } irakurtzen ditu)
target-header-twice = { $name }, { $line }. lerroa: zutabe bakoitza behin bakarrik izendatzen da
target-row-width = { $name }, { $line }. lerroa: { $count } balio, fitxategiak { $columns } zutabe dituen lekuan
target-not-finite = { $name }, { $line }. lerroa: zenbaki finituak espero ziren
target-weight-positive = { $name }, { $line }. lerroa: pisu batek positiboa izan behar du
target-first-input = { $name }, { $line }. lerroa: lehen helburuaren sarrera 0 da (sarrerak lehen helburutik zenbatzen dira)
target-inputs-increase = { $name }, { $line }. lerroa: '{ $column }' zutabearen balioek gora egin behar dute ({ $before } eta gero { $after })
## motion in time (simulate/)
simulate-time-not-evaluated = ezin da simulazioaren denbora ebaluatu: { $problem }
simulate-time-missing = zenbat denboran jarraitu behar den mugimendua: eman --time SEGUNDOAK (edo `simulate: {"{"}time: ...{"}"}` atal bat ereduan)
simulate-time-positive = denborak segundo-kopuru positibo bat izan behar du, baina { $got } dago
simulate-steps-too-many = bakoitza { $per_row } baliokoak diren { $steps } urrats simulazio batean sartzen dena baino gehiago dira ({ $limit } balio): eman gehienez { $most } urrats
simulate-time-too-short = { $time } s denbora laburregia da mugimendua t = { $start } s unetik jarraitzeko
simulate-time-needs-value = t denborak balio bat behar du: marraztutako konfigurazioaren denbora (normalean 0)
simulate-time-only-in-rates = t denbora eragileek ezarritako abiaduretan bakarrik ager daiteke (denboran aldatzen den abiadura bat); hemen mekanismoa berez mugituko luke
simulate-unknown-method = metodo ezezaguna '{ $method }' (scipy.integrate.solve_ivp funtzioaren metodoak: { $methods })
simulate-at = t = { $at } s unean: { $what }
simulate-rate-not-taken = ezin da ezarritako abiaduraren denborarekiko deribatua kalkulatu: { $problem }
simulate-rate-not-evaluated = ezin da ezarritako abiaduraren denborarekiko deribatua ebaluatu ({ $problem })
simulate-rate-not-real = ezarritako abiaduraren denborarekiko deribatua ez da zenbaki erreal finitu bat (zenbaki negatibo baten erro karratua?)
simulate-rate-not-finite = ezarritako abiaduraren denborarekiko deribatua ez da finitua (erro karratu bat edo logaritmo bat zeroan?)
simulate-velocity-matrix = ezin dira abiadura-ekuazioak ebatzi (haien matrizea ez dago zenbaki finituz osatua)
simulate-too-many-evaluations = mugimenduak { $limit } abiadura-soluzio baino gehiago behar ditu jarraitua izateko (limits.SIMULATE_EVALUATIONS): zurrunegia da (zati bat gainerakoa mugitzen dena baino askoz azkarrago egonkortzen da) edo singulartasun batetik hurbilegi dago
simulate-dead-point = mugimendua puntu hil batera iristen da t = { $at } s unean: hortik aurrera ezin dira abiadurak aurkitu (murrizketa-Jacobiarraren baldintza-zenbakia { $condition } izatera iristen da)
simulate-not-followed = ezin da mugimendua jarraitu t = { $at } s unetik haratago: { $why }
simulate-integrator-stopped = integratzailea gelditu egin da ({ $message })
simulate-positions-not-finite = posizio integratuak ez dira zenbaki finituak
simulate-projection-fails = posizio integratuak ezin dira loturen posizio-baldintzetara itzuli (mugimendua haiek onartzen dutenetik irten da)
simulate-velocity-only = simulazio batek ezin du `{ $kind }` motako lotura bat jarraitu{ $dim ->
        [3] {" "}3D-n
       *[other] {""}
    }: haren baldintza abiaduretakoa baino ez da, eta, beraz, posizioak egindako bidearen araberakoak dira
animation-file-type = ezin da { $name } idatzi: eman .gif edo .mp4 fitxategi bat

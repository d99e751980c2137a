## Els missatges dels errors i dels avisos, en català. Termes del curs: sòlid, enllaç (entre
## dos sòlids), dades de moviment, grau de llibertat, punt mort, muntatge, escombratge. Les
## claus del fitxer de model (`at`, 'base', points…) es deixen com s'escriuen.

## les paraules d'altres programes: el motiu del sistema operatiu, la queixa d'un lector
reason = { $errno ->
        [ENOENT] no existeix el fitxer o la carpeta
        [EACCES] permís denegat
        [EPERM] operació no permesa
        [EISDIR] és una carpeta
        [ENOTDIR] no és una carpeta
        [ENOSPC] no queda espai al disc
        [EROFS] el sistema de fitxers és només de lectura
        [ENAMETOOLONG] el nom és massa llarg
        [EEXIST] ja existeix
        [EADDRINUSE] l’adreça ja està en ús
        [EADDRNOTAVAIL] l’adreça no està disponible en aquesta màquina
        [ECONNREFUSED] connexió refusada
       *[other] { $text }
    }
problem = { $code ->
        [mapping-values] aquí no s’admet el valor d’una clau (falta un salt de línia o sobra un «:»?)
        [colon] falta el «:» que s’esperava
        [token] un caràcter que no pot començar un element (un tabulador?)
        [key] s’esperava una clau
        [bracket] falta una «,» o un «]»
        [brace] falta una «,» o un «{"}"}»
        [end] el text s’acaba abans d’hora
        [alias] un àlies sense definir
        [node] s’esperava un valor
        [escape] una seqüència d’escapament desconeguda
        [value] s’esperava un valor
        [property] s’esperava el nom d’una clau entre cometes dobles
        [comma] falta una coma
        [extra] sobra text després del valor
        [string] un text sense tancar
        [control] un caràcter de control dins d’un text
        [equals] falta el «=» després d’una clau
        [duplicate] una clau definida dues vegades
        [syntax] la sintaxi no és vàlida
        [unclosed] un parèntesi sense tancar
        [unmatched] un parèntesi que no s’ha obert
        [literal] un nombre mal escrit
        [domain] fora del domini de la funció
        [range] el resultat és massa gran
        [small] el valor és massa petit per als nombres de coma flotant
        [zero] divisió per zero
       *[other] { $text }
    }

## llegir fitxers (model/files.py)
model-not-a-path = un model és el camí d’un fitxer, un dict o un Mechanism, no { $type }
file-empty = el fitxer és buit
model-not-a-mapping = un model és un diccionari amb les claus points, bodies, joints, drivers; aquest fitxer conté { $holds }
holds = { $what ->
        [list] una llista
        [text] un text
        [nothing] res
       *[value] un sol valor
    }
file-type-unknown = tipus de fitxer desconegut { $suffix }: { $noun ->
        [cam-file] un fitxer de lleva
       *[model-file] un fitxer de model
    } acaba en { $suffixes }
file-not-utf8 = el fitxer no és text UTF-8 (byte { $byte })
file-missing = no existeix el fitxer
file-unreadable = no es pot llegir el fitxer: { $reason }
file-is-a-folder = això és una carpeta, no un fitxer de model
file-too-large = el fitxer és massa gran per a un model (més de { $limit } bytes)
file-no-end = el fitxer no s’ha acabat en { $seconds } s (una canonada o un dispositiu, no un fitxer de model)
text-too-large = el text és massa gran per a un model (més de { $limit } caràcters)
text-unreadable = { $format } il·legible: { $detail }
file-too-deep = el fitxer està niat massa endins per ser un model (més de { $levels } nivells{ $line ->
        [0] {""}
       *[other] , línia { $line }
    })
name-too-long = el nom { $name } té { $length } caràcters: els noms en tenen com a molt { $limit }
text-lone-surrogate = el text { $text } conté un substitut solt, que no és text Unicode
key-duplicate = clau repetida { $key }{ $line ->
        [0] {""}
       *[other] {" "}a la línia { $line }
    }: cada clau només pot aparèixer una vegada
json-invalid = JSON no vàlid a la línia { $line }, columna { $column }: { $problem }
toml-invalid = TOML no vàlid: { $problem }
yaml-invalid = YAML no vàlid{ $line ->
        [0] {""}
       *[other] {" "}a la línia { $line }, columna { $column }
    }: { $problem }
yaml-alias-inside = l’àlies *{ $alias } de la línia { $line } és dins del que anomena
yaml-alias-unknown = l’àlies *{ $alias } de la línia { $line } no anomena cap àncora
yaml-aliases-too-many = els àlies s’expandeixen a més de { $limit } valors (a la línia { $line }): massa per a un model
model-no-cam = aquest model no té lleva: dona a un sòlid una forma `cam:`

## paraules que comparteixen els missatges
none = cap
or-word = o
more = , … ({ $n } més)
integer-bits = un enter de { $bits } bits

## expressions (expressions.py)
expr-expected = s’esperava un nombre o una expressió, i hi ha { $got }
expr-not-finite = s’esperava un nombre finit dins del rang dels nombres de coma flotant, i hi ha { $got }
expr-empty = expressió buida
expr-too-long = expressió de més de { $limit } caràcters
expr-unreadable = no es pot llegir l’expressió { $source }: { $detail }
expr-unreadable-bare = no es pot llegir l’expressió { $source }
expr-too-deep = l’expressió { $source } està niada massa endins
expr-constant = a { $source }: només es poden escriure nombres com a constants
expr-number-too-large = a { $source }: un nombre és massa gran
expr-unknown-function = a { $source }: funció desconeguda { $function } (conegudes: { $known })
expr-arguments = a { $source }: { $function } pren { $count ->
        [one] un argument
       *[other] { $count } arguments
    }
expr-not-allowed = a { $source }: { $part } no s’admet en una expressió
expr-unknown-name = a { $source }: nom desconegut { $name } (no és un paràmetre)
expr-function-fails = a { $source }: no es pot avaluar { $function } ({ $why })
expr-exponent = a { $source }: l’exponent { $exponent } és massa gran (com a molt { $limit } en valor absolut)
expr-division-by-zero = a { $source }: divisió per zero
expr-too-large = a { $source }: el valor és massa gran
expr-not-real = a { $source }: el valor no és real
expr-underflow = a { $source }: el valor és massa petit per als nombres de coma flotant (es prendria com a 0)
expr-not-finite-value = a { $source }: el valor no és finit
expr-too-many-digits = a { $source }: el valor té massa xifres per a fórmules exactes (més de { $limit })
expr-degree = a { $source }: el grau de la fórmula en els símbols passa de { $limit }: massa alt per a fórmules exactes
parameter-no-value = el paràmetre '{ $name }' no té valor
number-too-many-digits = el nombre { $number } té massa xifres per a fórmules exactes (més de { $limit } com a fracció): arrodoneix-lo o resol amb nombres

## la forma del model (model/build.py, model/model.py)
model-mapping = un model és un diccionari amb les claus points, bodies, joints, drivers
frame-missing = no hi ha cap sòlid fix '{ $frame }': anomena '{ $frame }' un sòlid o posa a `frame:` un de { $bodies }
parameter-name-invalid = '{ $name }' no és un nom de paràmetre vàlid (lletres, xifres i _, sense començar per una xifra)
unknown-name-in = nom desconegut '{ $name }' a '{ $text }'
unknown-name-in-parameters = nom desconegut '{ $name }' a '{ $text }' (paràmetres: { $parameters })
components-count = s’esperaven { $dims } components, i n’hi ha { $got }
model-no-points = un model necessita almenys un punt
name-invalid = '{ $name }' no pot ser un nom: els noms no són buits i no porten '@' (uneix un punt al seu sòlid: B@rocker)
construction-planar = els punts per construcció són plans; dona els punts d’un model 3D com a coordenades [x, y, z]
planar-two-coordinates = un model pla (dimensió 2) té 2 coordenades per punt
point-listed-twice = el punt '{ $point }' hi és dues vegades
point-not-carried = cap sòlid no porta el punt '{ $point }': afegeix-lo als punts d’un sòlid
unknown-point = punt desconegut '{ $point }' (punts: { $points })
vector-size = un model { $dim ->
        [2] pla
       *[other] 3D
    } necessita { $dim } { $what ->
        [coordinates] coordenades
       *[components] components
    }, i n’hi ha { $got }
shapes-3d-only = els discos i els plans són dels models 3D; en un model pla fes servir circumferència (circle) i recta (line)
shapes-planar-only = les corbes i les lleves són dels models plans
unknown-body = sòlid desconegut '{ $body }' (sòlids: { $bodies })
joint-id-empty = l’identificador d’un enllaç no és buit
joint-id-twice = l’identificador d’enllaç '{ $id }' es fa servir dues vegades
joint-same-body = un enllaç uneix dos sòlids diferents, i '{ $body }' hi és dues vegades
joint-point-not-on-body = el punt '{ $point }' de l’enllaç `{ $kind }` no és al sòlid '{ $body }': afegeix '{ $point }' als seus punts
direction-same-points = una direcció necessita dos punts diferents
unknown-joint = enllaç desconegut '{ $joint }' (enllaços: { $joints })
unknown-joint-bare = enllaç desconegut '{ $joint }'
expected-one-number = s’esperava un nombre (la component segons `along`), i hi ha un vector
expected-vector = s’esperava un vector de { $dim } components (o dona `along` per a una sola component)
questions-too-many = { $count } preguntes: com a molt { $limit } en un model
question-one-key = una pregunta té exactament una de les claus { $keys }
contact-not-touching = '{ $text }' no és un enllaç { $kinds } (aquests enllaços són: { $joints })
decompose-needs-moving = una pregunta decompose necessita `moving: BODY`, la referència mòbil
moving-only-decompose = `moving` només va a les preguntes decompose
question-planar-only = { $kind } és una pregunta de moviment pla; en 3D pregunta per l’eix helicoidal (`axis`)
question-3d-only = l’eix helicoidal és una pregunta 3D; en un model pla pregunta pel CIR (`icr`)
steps-at-least-one = steps ha de ser almenys 1

## el que pydantic troba malament en la forma d’un fitxer (model/build.py, cams/spec.py)
schema-problems = { $problem }{ $others ->
        [0] {""}
        [one] {" "}(i { $others } problema més)
       *[other] {" "}(i { $others } problemes més)
    }
driver-second-kind = una dada de moviment té exactament una de les claus { $kinds }; '{ $key }' n’és una segona
unknown-key = clau desconeguda '{ $key }'
missing-key = falta la clau '{ $key }'
not-one-of = { $value } no és cap de { $expected }
unexpected-value = valor inesperat { $value }: { $problem }
pydantic = { $type ->
        [missing] falta
        [extra_forbidden] clau desconeguda
        [float_type] s’esperava un nombre
        [int_type] s’esperava un nombre enter
        [int_from_float] s’esperava un nombre enter
        [int_parsing] s’esperava un nombre enter
        [float_parsing] s’esperava un nombre
        [finite_number] s’esperava un nombre finit
        [string_type] s’esperava un text
        [bool_type] s’esperava true o false
        [list_type] s’esperava una llista
        [dict_type] s’esperava un diccionari (claus i valors)
        [model_type] s’esperava un diccionari (claus i valors)
        [model_attributes_type] s’esperava un diccionari (claus i valors)
        [too_short] s’esperaven almenys { $ctx_min_length } elements
        [too_long] s’esperaven com a molt { $ctx_max_length } elements
        [greater_than] ha de ser més gran que { $ctx_gt }
        [greater_than_equal] ha de ser almenys { $ctx_ge }
        [less_than] ha de ser més petit que { $ctx_lt }
        [less_than_equal] ha de ser com a molt { $ctx_le }
        [literal_error] no és cap dels valors admesos
        [union_tag_invalid] no és cap de les formes admeses
        [union_tag_not_found] no és cap de les formes admeses
        [construction_kind] un punt són coordenades [x, y] o una construcció amb una de les claus from, frame, circles, circle, lines
        [driver_kind] una dada de moviment necessita una de les claus omega, joint o velocity
       *[other] el valor no encaixa aquí
    }
point-name-not-text = un punt s’anomena amb un text com 'B' o 'B@rocker', i hi ha { $got }
point-body-after-at = '{ $text }': escriu el sòlid després de '@' (com a '{ $example }')
body-not-carrying = el sòlid '{ $body }' no porta el punt '{ $point }' (el porten { $carriers })
point-ambiguous = el punt '{ $point }' el porten { $carriers }, que s’hi mouen de manera diferent: escriu { $choices }
unknown-parameter = paràmetre desconegut '{ $name }' (paràmetres: { $parameters })
name-or-note-empty = un nom o una nota no és buit
notation-key-unknown = '{ $key }' no és un paràmetre (paràmetres: { $parameters }) ni omega(BODY), omega(BODY/OTHER), alpha(…)
notation-rate-bodies = '{ $key }': una velocitat angular és d’un sòlid, o d’un sòlid respecte d’un altre (omega(blades/block))
notation-spelling = '{ $name }' no és el nom d’un símbol: lletres, xifres i _ tal com els escriu sympy (omega_0 és ω₀, vdot és v̇, R_roda)
draw-at-has-value = '{ $name }' ja té valor: draw_at dona nombres als paràmetres simbòlics (null)
draw-at-not-finite = '{ $name }' es dibuixa amb { $value }: dona un nombre finit{ $positive ->
        [true] {" "}i positiu
       *[other] {""}
    }
draw-at-range = '{ $name }' es dibuixa amb { $value }: les figures es dibuixen amb nombres de mida entre { $low } i { $high }
up-planar = up anomena la vertical d’un model 3D; un model pla es dibuixa en el seu propi pla
up-direction = up és una direcció no nul·la de 3 nombres, com [0, 1, 0]
construction-cycle = les construccions es refereixen les unes a les altres en un cicle: { $cycle }
construction-point-expected = s’esperava el nom d’un punt o coordenades [x, y], i hi ha { $got }
construction-coordinates = les construccions són planes: coordenades [x, y], i n’hi ha { $got } components
construction-circle-radius = una circumferència és [centre, radi]: el radi és un sol nombre
circle-arc = l’arc [des de, fins a] d’una circumferència (graus, en sentit antihorari) n’és una part: 0 < fins a − des de < 360 (aquí de { $start } a { $end })
construction-line-direction = la direcció d’una recta és un vector; per a una recta per dos punts escriu [P, Q]
construction-direction-planar = les construccions són planes: una direcció [dx, dy]
near-symbolic = `near` necessita nombres; en un model amb paràmetres simbòlics tria la intersecció amb `side`
near-point = `near` és un punt de l’esbós [x, y]
two-points-same = calen dos punts diferents, i '{ $point }' hi és dues vegades
statement-placeholder = {"{"}{ $name }{"}"} no és un paràmetre (paràmetres: { $parameters })
unit-not-length = '{ $unit }' no és una unitat de longitud (unitats: { $units })
question-missing = la pregunta { $number } no existeix: el model en fa { $count } (numerades des d’1)
graded-once = anomena cada pregunta qualificada una vegada (almenys una)
tolerance-relative = la tolerància és relativa, entre 0 i 1: hi ha { $tolerance }
unknown-point-bare = punt desconegut '{ $point }'
unknown-unit = unitat desconeguda '{ $unit }' (unitats: { $units })
parameters-mapping = els paràmetres són un diccionari de noms i valors, i hi ha { $type }

## lleves (cams/*.py) i corbes (curves/*.py)
cam-translating-no-key = un seguidor de translació no té '{ $key }'
cam-oscillating-no-offset = un seguidor oscil·lant no té 'offset' (situa’n el pivot)
cam-oscillating-pivot = un seguidor oscil·lant necessita 'pivot' (la seva distància al centre de la lleva)
cam-oscillating-arm = un seguidor oscil·lant necessita 'arm' (del pivot al centre del corró o al tall)
cam-roller-radius = un seguidor de corró necessita 'radius'
cam-no-radius = un seguidor `{ $contact }` no té 'radius'
cam-polynomial-only = només un tram polinòmic admet condicions '{ $key }'
cam-dwell-to = un repòs manté quiet el seguidor: treu 'to'
cam-segment-to = un tram `{ $law }` necessita 'to' (el desplaçament al final)
cam-below-lowest = el seguidor baixaria de la seva posició més baixa (s < 0, dins de la circumferència de base)
cam-segment-still = un tram `{ $law }` ha de moure el seguidor: 'to' és igual al desplaçament d’on parteix (fes servir un repòs)
cam-span = els trams abasten { $total }°; el programa d’una lleva de disc abasta 360°
cam-program-ends = el programa acaba a s = { $end }, no on comença (0): el moviment d’una lleva de disc es repeteix a cada volta
cam-no-polynomial = cap polinomi no compleix aquestes condicions de contorn
cam-program-or-profile = dona el moviment de la lleva amb 'program' o la seva forma amb 'profile' (un dels dos)
cam-base-missing = falta la clau 'base' (el radi de la circumferència de base)
cam-speed-once = dona la velocitat de la lleva una sola vegada: omega (rad/s), rpm o velocity (una lleva de translació)
cam-speed-translating = la velocitat d’una lleva de translació és la seva 'velocity'
cam-speed-disc = la velocitat d’una lleva de disc és 'omega' o 'rpm'
cam-plate-translating = una lleva de translació mou un seguidor de translació
cam-plate-flat = una cara plana no pot seguir una lleva de translació (fes servir un corró o un tall)
cam-plate-offset = el seguidor d’una lleva de translació no té excentricitat
cam-offset-prime = l’excentricitat { $offset } ha de ser més petita que el radi { $radius } de la circumferència primitiva
cam-face-base = la cara no pot tocar la circumferència de base: cal 0 < base + face < pivot
cam-arm-reach = el braç no arriba a la circumferència primitiva (radi { $radius }): cal |pivot − arm| < { $radius } < pivot + arm
cam-arm-past = el programa gira el braç { $turn }° des de { $start }°, més enllà de { $reach }° (on el seguidor perd la lleva)
cam-file-mapping = un fitxer de lleva és un diccionari amb les claus cam, follower, program (o profile), speed
value-problem = { $value }: { $problem }
cam-profile-disc = una lleva donada per punts del perfil és una lleva de disc
cam-profile-base = una lleva donada per punts del perfil té la circumferència de base que dona el seu perfil: treu 'base'
cam-follower-misses = el seguidor no arriba a la lleva
cam-knife-misses = la trajectòria del tall no toca la lleva
cam-jump = { $quantity ->
        [velocity] la velocitat
       *[acceleration] l’acceleració
    } salta { $size } { $unit } a { $at }{ $place } ({ $quantity ->
        [velocity] acceleració infinita
       *[acceleration] sobreacceleració infinita
    }: s’incompleix la llei fonamental del disseny de lleves)
curve-line-direction = la direcció d’una recta no pot ser nul·la
curve-unbounded = una corba no fitada no té punts per dibuixar: dona-li un domini finit
spline-points = els punts d’una spline són una llista de parells (x, y)
spline-too-few = una spline { $closed ->
        [true] tancada
       *[false] oberta
    } necessita almenys { $need } punts
spline-points-differ = els punts consecutius d’una spline han de ser diferents
circle-radius-positive = el radi d’una circumferència ha de ser positiu
arc-angles = un arc va en sentit antihorari d’a0 a a1, amb a0 < a1 ≤ a0 + 2π
cam-flat-translating = un seguidor de cara plana no pot seguir una lleva de translació

## enllaços (joints/*.py)
and-word = i
nothing = {""}
sweep-velocity-only = un escombratge no pot seguir un enllaç `{ $kind }`{ $dim ->
        [3] {" "}en 3D
       *[other] {""}
    }: la seva condició només és de velocitats, així que les posicions depenen del camí recorregut{ $in_time ->
        [true] ; `kinematika simulate` el segueix en el temps
       *[other] {""}
    }
joint-other-dimension = un enllaç `{ $kind }` és d’un model { $dim ->
        [2] 3D
       *[other] pla
    }
joint-needs-key = un enllaç `{ $kind }` necessita `{ $key }`
internal-owners = `internal` només va als enllaços { $owners }
joint-no-key = un enllaç `{ $kind }` no té `{ $key }`{ $planar ->
        [true] {" "}en un model pla (les rotacions són al voltant de z)
       *[other] {""}
    }
joint-no-rate = un enllaç `{ $kind }` no té velocitat per imposar; imposa l’omega d’un sòlid o la velocitat d’un punt
rounding-hint = , més gran que la tolerància { $tolerance } (1e-6 de la mida del model): escriu { $point } per construcció o amb més xifres
slot-off-line = el passador '{ $point }' és fora de la recta { $line }: separació { $gap }{ $hint }
cam-joint-first-body = el primer sòlid d’un enllaç de lleva porta la lleva: dona a '{ $body }' una forma `cam:`
cam-joint-face = un seguidor de cara plana toca amb la cara: dona a '{ $body }' una recta `line` (la cara)
cam-joint-at = un enllaç de lleva necessita `at`: { $roller ->
        [true] el centre del corró del seguidor
       *[other] el tall del seguidor
    }
curved-slot-outline = una ranura corba es talla al llarg d’una circumferència o d’una corba de '{ $body }': dona-n’hi una a aquest sòlid
cylindrical-two-rates = un enllaç cilíndric té dues velocitats (gir i lliscament): imposa l’omega del sòlid respecte de l’altre sòlid (relative_to) i la velocitat d’un punt segons l’eix
rolling-needs-shapes = un enllaç `{ $kind }` necessita una forma als dos sòlids: dona a '{ $body }' { $dim ->
        [2] una circumferència o una recta
       *[other] un disc o un pla
    }
shapes-cannot-roll = aquestes formes no poden rodolar l’una sobre l’altra
no-touch = '{ $body }' no toca '{ $other }': separació { $gap }{ $hint }
the-contact-or-centre = el contacte o el centre
the-contact = el contacte
contact-not-at = el contacte no és a '{ $point }': és a { $distance }{ $hint }
internal-circles-only = `internal` diu com es toquen dues circumferències; aquest contacte és `{ $contact }`
rolling-internal-wrong = l’enllaç `{ $kind }` es declara { $said ->
        [internal] interior
       *[external] exterior
    }, però les seves { $kind ->
        [gear] circumferències primitives
       *[other] circumferències
    } es toquen per { $said ->
        [internal] fora
       *[external] dins
    }
disc-flat-on-plane = el disc '{ $disc }' està ajagut sobre el pla de '{ $plane }': toca amb tota la cara, no en un punt
sweep-rolling-only = un escombratge només segueix el rodolament de circumferències i rectes
contact-acceleration-curve = l’acceleració del punt geomètric de contacte sobre una corba general necessita la variació de la seva curvatura: pregunta pels punts dels sòlids
straight-outlines = dos contorns rectes es toquen al llarg d’una recta, no en un punt: uneix-los amb un enllaç prismàtic
pair-cannot = `{ $kind }` entre '{ $body }' i '{ $other }': { $why }
touching-needs-outlines = un enllaç `{ $kind }` necessita un contorn als dos sòlids: dona a '{ $body }' una circumferència, una recta o una corba (o anomena’n el punt amb `at`)
outlines-cannot-touch = aquests contorns no es poden tocar en un punt

## les condicions del moviment, anomenades als missatges
row-joint = { $id }: { $label }
row-driver = { $where } ({ $label })
row-joint-rate = velocitat de l’enllaç { $joint } = { $value }
row-rate = { $name } de { $body }
row-rate-relative = { $name } de { $body } respecte de { $relative }
row-equals = { $label } = { $value }
row-component = { $label } ({ $axis }) = { $value }
row-point-along = { $name } de { $point } segons la direcció donada = { $value }
row-point = { $name } de { $point }
row-idle = sense gir ociós de { $body } al voltant de { $axis }
row-curved-slot = { $point } continua a la ranura corba de { $body }
row-turning-axis = rotació relativa només al voltant de l’eix ({ $n })
row-sliding-axis = lliscament relatiu només segons l’eix ({ $n })
row-across-guide = sense moviment relatiu transversal a la guia ({ $n })
row-moves-with = { $point } es mou amb { $other } ({ $axis })
row-no-slip = sense lliscament al contacte de { $body } i { $other } ({ $axis })
row-slot = { $point } continua a la ranura de { $body }
row-turns-with = { $body } gira amb { $other }
row-body-moves-with = { $body } es mou amb { $other } ({ $axis })
row-no-sideways = { $point } no té velocitat lateral respecte de { $body }
row-touching = { $b } continua tocant { $a }
row-cam-touching = el seguidor { $b } continua tocant la lleva { $a }
row-no-rotation = sense rotació relativa
row-no-rotation-axis = sense rotació relativa ({ $axis })

## la mobilitat del mecanisme (engine/mobility.py)
infinite = infinit
dead-point = un punt mort: les dades de moviment no hi fixen el moviment; { $count ->
        [0] les dades de moviment depenen
        [one] { $drivers } depèn
       *[other] { $drivers } depenen
    } dels enllaços (nombre de condició { $condition } del jacobià adimensional, límit { $limit })
mobility-free = el mecanisme té { $dof ->
        [one] { $dof } grau
       *[other] { $dof } graus
    } de llibertat, però les dades de moviment donen { $conditions ->
        [one] { $conditions } condició independent
       *[other] { $conditions } condicions independents
    }; queda lliure: { $count ->
        [0] part del moviment
       *[other] { $free }
    }
drivers-conflict = les dades de moviment es contradiuen, els seus valors no concorden entre si o amb els enllaços: { $named } ({ $dof ->
        [one] { $dof } grau
       *[other] { $dof } graus
    } de llibertat; { $given ->
        [one] { $given } condició donada
       *[other] { $given } condicions donades
    }, { $conditions } independents)

## l’instant: valors, direccions, punts per construcció (engine/*.py)
direction-zero = una direcció no pot ser el vector nul
direction-not-exact = aquesta direcció no es pot convertir exactament en un vector unitari: les seves components són de mides massa diferents (escriu la petita com a 0)
direction-points-coincide = una direcció necessita dos punts diferents: { $start } i { $end } coincideixen
value-not-real = un valor no és un nombre real per als valors dels símbols (l’arrel quadrada o una potència d’una quantitat negativa?)
parameters-cycle = els paràmetres es refereixen els uns als altres en un cicle: { $names }
points-not-real = els punts no són reals per a cap dels valors dels símbols provats (l’arrel quadrada d’un nombre negatiu?)
curves-need-numbers = les corbes i les lleves es dibuixen amb nombres: dona els seus valors als paràmetres (o resol sense --symbolic)
curve-through-points = la corba no es pot traçar pels seus punts: { $why }
radius-positive = un radi ha de ser positiu, i hi ha { $radius }
jacobian-singular-large = el jacobià de restriccions de { $rows }×{ $columns } és singular o no és quadrat (LU dispersa); el sistema és massa gran per dir quines condicions falten o depenen d’altres
structurally-singular = el sistema no té un conjunt estructuralment independent de condicions per a cada incògnita
angle-in-radians = l’angle { $angle } és en radiants: { $degrees }°, { $turns } voltes; per a { $angle }° escriu deg({ $written })
point-too-large = les coordenades exactes de { $point } tindrien unes { $size } operacions (més de { $limit }): massa grans per a fórmules; dona nombres a més paràmetres o resol sense --symbolic
length-positive = { $what ->
       *[radius] un radi
    } ha de ser positiu, i hi ha { $value }
direction-points-same = els dos punts que donen la direcció coincideixen
fit-each-side = , un a cada costat de { $line }
fit-on-line = {" "}a la recta { $line }
circles-same-centre = les circumferències de centre { $a } i { $b } tenen el mateix centre
circles-apart = les circumferències de centre { $a } ({ $ra }) i { $b } ({ $rb }) no es tallen: centres a { $d }, { $gap } més que { $ra } + { $rb }
circles-inside = les circumferències de centre { $a } ({ $ra }) i { $b } ({ $rb }) no es tallen: la de centre { $inner } és dins de la de centre { $outer } (centres a { $d }, { $gap } menys que |{ $ra } − { $rb }|)
line-direction-zero = la direcció d’una recta no pot ser el vector nul
circle-misses-line = la circumferència de centre { $centre } ({ $radius }) no talla la recta { $line }: la recta és a { $distance } de { $centre }, { $gap } més que el radi
lines-parallel = les rectes { $a } i { $b } són paral·leles: no es tallen
line-points-coincide = la recta { $line } es dona amb dos punts que coincideixen
two-points-fit = hi ha dos punts possibles{ $relation }: { $points }; tria’n un amb side: { $first } o { $second }, o amb near: [x, y]
beyond-floats = més del que admeten els nombres de coma flotant
model-size-range = la mida del model és { $size }: kinematika calcula amb longituds entre { $low } i { $high }, en qualsevol unitat; escriu les longituds en una altra unitat
rates-range = els valors de les dades de moviment són fora de rang per a aquest mecanisme (una velocitat de { $rate } per unitat de temps): kinematika calcula amb velocitats entre { $low } i { $high }; escriu els temps en una altra unitat
values-overflow = els valors del model són massa grans: les seves velocitats o acceleracions desborden el rang dels nombres de coma flotant

## límits del treball, mòduls opcionals, idiomes (budget.py, extras.py, languages.py)
over-budget = trobar { $what } porta { $counted ->
        [true] més de { $steps } passos d’àlgebra exacta
       *[other] més de { $seconds } s de CPU
    }{ $staged ->
        [true] {" "}({ $stage })
       *[other] {""}
    }: són massa grans; { $advice }
exact-formulas = les fórmules exactes
stage-solving = resolent les equacions exactament
stage-simplifying = simplificant les fórmules
advice-symbolic = dona nombres a alguns paràmetres o resol sense --symbolic
advice-null = dona nombres a alguns dels paràmetres deixats com a símbols (null: { $names })
advice-numbers = dona nombres a alguns paràmetres
module-missing = { $what } necessita { $module }, que no està instal·lat: instal·la’l amb { $command }
writing-parquet = escriure Parquet (o escriu .npz)
writing-dxf = escriure DXF
study-on-dask = un estudi en un clúster Dask
unknown-language = idioma desconegut '{ $lang }' (idiomes: { $langs })
centres-planar = els CIR són de moviment pla; en 3D pregunta per l’eix helicoidal (`axis`) de cada sòlid

## escombratges, moviments i muntatges (sweep/*.py)
assembly-not-whole = un muntatge és un nombre enter, i hi ha { $got }
assembly-missing = no hi ha muntatge { $number }: aquest mecanisme en té { $count } a l’entrada dibuixada (vegeu `kinematika assemblies`)
assemblies-too-many = { $dyads } díades tanquen de dues maneres cadascuna: llistar 2^{ $dyads } muntatges passa del límit de 2^{ $limit }
sweep-by-varied = la longitud de l’escombratge ({ $by }) depèn d’un paràmetre variat: dona-la com a nombre (--by)
move-not-number = { $problem } (un moviment és un nombre de graus o de longituds)
move-not-finite = un moviment és un nombre finit
move-not-driven = l’enllaç '{ $joint }' no és d’entrada; `move` avança un enllaç d’entrada ({ $count ->
        [0] aquí no n’hi ha cap
       *[other] { $driven }
    })
move-unreachable = { $joint } no es pot moure { $amount }{ $unit }: el mecanisme arriba a un punt mort o es desmunta després de { $got }{ $unit }
sweep-by-needed = l’enllaç '{ $joint }' és `{ $kind }`: dona la longitud de l’escombratge (`by` a la secció sweep del model, o --by)
steps-whole = steps ha de ser un nombre enter, i hi ha { $got }
steps-range = steps ha de ser entre 1 i { $limit }, i hi ha { $got }
steps-too-many-values = { $steps } passos de { $per_row } valors cadascun passen del que hi cap en un escombratge ({ $limit } valors): dona’n com a molt { $most }
by-number = by ha de ser un nombre, i hi ha { $got }
by-finite = by ha de ser un nombre finit
sweep-no-driven-joint = no hi ha cap enllaç d’entrada per escombrar: imposa la velocitat d’un enllaç, o l’omega o la velocitat d’un sòlid unit al fix per una articulació o un enllaç prismàtic
sweep-not-driven = l’enllaç '{ $joint }' no és d’entrada; un escombratge avança un enllaç d’entrada: { $driven }
fixture-shape = la posició de { $shape }
fixture-joint = la direcció de l’enllaç { $joint }
move-symbolic-3d = un model 3D amb paràmetres simbòlics no es pot moure: dona valors als seus paràmetres (--set NAME=VALUE)
move-symbolic-once = un model amb paràmetres simbòlics es mou una sola vegada: dona tots els seus moviments junts
move-same-body = dos moviments giren el mateix sòlid: dona-li un sol moviment
move-not-input = l’enllaç '{ $joint }' no uneix un sòlid al fix: mou un model amb paràmetres simbòlics pel seu enllaç d’entrada
move-at-values = no es pot moure: amb valors dels símbols en què el model es compleix ({ $values }), { $problem }
move-exact-numbers = no es pot moure exactament: el punt '{ $point }' segueix l’entrada amb nombres, no amb les seves coordenades exactes (dona valors als paràmetres)
move-exact-rolls = no es pot moure exactament: el punt '{ $point }' és a '{ $body }', que rodola sobre una recta: el seu gir és el camí del centre dividit pel radi, sense forma tancada aquí (dona valors als paràmetres)
move-exact-no-form = no es pot moure exactament: el punt '{ $point }' no segueix l’entrada: cap construcció, relació de rodolament ni cap altre sòlid no dona la posició de '{ $body }' en forma tancada; escriu { $point } per construcció (o dona valors)
move-exact-constructed = no es pot moure exactament: el punt '{ $point }' no segueix l’entrada: està construït amb punts que no es mouen amb { $body }; construeix-lo amb aquests (o dona valors)
move-exact-fixture = no es pot moure exactament: '{ $body }' gira sense forma tancada aquí, i { $what } és escrita amb nombres; dona-la amb punts (o dona valors als paràmetres)
body-no-point = el sòlid '{ $body }' no porta cap punt, així que les seves formes no es poden moure: afegeix-hi un dels seus punts
cannot-assemble-there = el mecanisme no es pot muntar aquí
sweep-at = l’increment { $k } ({ $joint } = { $value } { $unit })
sweep-drivers-contradict = les dades de moviment tal com són escrites contradiuen els enllaços a { $at }: una dada vectorial (ω en 3D, una velocitat) queda fixa en els eixos del fix mentre el mecanisme gira; imposa en canvi la velocitat de l’enllaç
sweep-singular = la configuració a { $at } és singular per a les dades de moviment (un punt mort: nombre de condició més gran que 1e+10){ $said ->
        [true] {" "}({ $what })
       *[other] {""}
    }; fes servir --skip-bad per saltar aquestes posicions
sweep-cannot-assemble = el mecanisme no es pot muntar a { $at }{ $said ->
        [true] : { $what } no poden tancar el llaç
       *[other] {""}
    }; fes servir --skip-bad per saltar aquestes posicions

## estudis i síntesi (explore/*.py)
metrics-once = cada mètrica una vegada, i cap amb el nom d’un paràmetre ni 'assembles'/'reason'
study-needs-numbers = un estudi necessita nombres: dona un valor a { $names } o fes-lo variar
vary-form = --vary espera NAME=LOW:HIGH (com a=1:5), i hi ha { $got }
vary-interval = --vary { $name }: l’interval ha de ser finit amb LOW <= HIGH, i hi ha { $got }
vary-none = anomena almenys un paràmetre per variar (--vary NAME=LOW:HIGH)
varied-twice = un paràmetre es varia dues vegades: { $names }
grid-or-samples = dona --grid N o --samples N
grid-positive = --grid i --samples prenen un nombre positiu
designs-too-many = { $count } dissenys: com a molt { $limit }
motion-error-two-points = motion_error: el sòlid '{ $body }' necessita dos punts per tenir orientació
metric-unknown = mètrica desconeguda '{ $metric }'; mètriques: grashof, transmission, dead_points, time_ratio[:BODY], range:BODY, peak_omega:BODY, peak_alpha:BODY, peak_speed:POINT, peak_accel:POINT, path_error:POINT=FILE.csv, motion_error:POINT=FILE.csv, structural_error:BODY=FILE.csv, angle|omega|alpha:BODY=X, speed|accel|x|y:POINT=X
grashof-four-bar = grashof necessita un model el llaç mòbil del qual sigui un quadrilàter articulat mogut per la seva manovella
time-ratio-linkage = time_ratio sense sòlid necessita un quadrilàter articulat o una biela-manovella; anomena la sortida (time_ratio:BODY)
transmission-linkage = transmission necessita un quadrilàter articulat o una biela-manovella moguts per la seva manovella
metric-at-input = { $metric }=X pren la posició X de l’entrada (un nombre, en { $unit } des de la posició dibuixada), i hi ha { $got }
input-outside-sweep = l’entrada ha de ser dins del rang de l’escombratge, de { $low } a { $high } { $unit }
time-ratio-full-turn = time_ratio necessita l’escombratge d’una volta completa de la manovella (by: 360)
target-csv = { $name }: un fitxer d’objectius és un fitxer .csv
table-not-numbers = { $name }, línia { $line }: s’esperaven nombres, i hi ha { $got }
table-columns = { $name }, línia { $line }: s’esperaven { $columns } nombres finits
table-empty = { $name } no té files de nombres
cannot-write = no es pot escriure { $path }: { $reason }
cannot-read = no es pot llegir { $path }: { $reason }
study-no-column = l’estudi no té la columna '{ $name }' (columnes: { $columns })
study-worker-died = un procés de l’estudi ha acabat de cop (sense memòria?): prova amb menys --workers o un --chunk més petit
dask-unreachable = no s’arriba al planificador de Dask a { $scheduler }: { $reason }
study-interrupted = { $folder } conté un estudi interromput: afegeix --resume per continuar-lo, o esborra aquesta carpeta per començar de nou
study-different = { $folder } conté un altre estudi (un altre model, paràmetres, dissenys o mètriques): esborra-la per començar de nou
study-output = la sortida és un fitxer .parquet o .csv, i hi ha { $name }
study-stopped = { $problem }{ $note }
study-kept = ; es guarden { $kept } dissenys a { $folder }: torna a executar amb --resume per continuar
study-needs-model = un estudi necessita un fitxer de model o el text d’un model
function-unknown-name = a { $source }: nom desconegut '{ $name }' (la funció és de x, l’increment de l’entrada)
function-not-finite = { $source } no és finit entre { $low } i { $high }

## exercicis (exercise/*.py)
variant-missing = no hi ha la variant { $number } (variants d’1 a { $count })
vary-unknown-parameter = --vary { $name }: paràmetre desconegut (paràmetres: { $parameters })
vary-none-step = anomena almenys un paràmetre per variar (--vary NAME=LOW:HIGH[:STEP])
exercise-needs-numbers = un exercici necessita nombres: dona un valor a cada paràmetre simbòlic (o fes-lo variar)
exercise-no-model = exercise.json no anomena el fitxer del model
exercise-lacks = a exercise.json hi falta vary, seed o lang
exercise-cannot-read = no es pot llegir { $path }: { $reason } (és una carpeta que va escriure `kinematika exercise`?)
file-not-json = { $name } no és JSON: { $problem }
file-not-json-object = { $name } no és un objecte JSON
csv-not-utf8 = { $name } no és text UTF-8
csv-no-column = { $name } no té la columna '{ $column }' (la seva capçalera: { $count ->
        [0] cap
       *[other] { $header }
    })
variants-numbered = les variants es numeren 1, 2, … amb un valor de cada paràmetre variat
variants-none = no hi ha variants
key-mismatch = key.csv no coincideix amb el model resolt de nou (variant { $variant }, { $question }): s’ha editat el model o la clau de respostes?
question-not-asked = '{ $question }' no es pregunta a la variant { $variant } (les seves preguntes: { $asked })
row-no-student = una fila sense estudiant
variant-not-number = la variant { $got } no és un nombre
answered-twice = { $student } respon dues vegades { $question } de la variant { $variant } (la primera vegada a la línia { $first })
statement-missing = la secció de l’exercici no té enunciat en '{ $lang }' (en té en { $langs })
vary-step-form = --vary espera NAME=LOW:HIGH[:STEP] (com s=300:500:10), i hi ha { $got }
vary-step-interval = --vary { $name }: dona LOW <= HIGH i un STEP positiu, i hi ha { $got }
vary-grid-large = --vary { $name }: { $count } valors a la graella, com a molt { $limit }: pren un pas més gran
count-range = --count admet d’1 a { $limit } variants, i hi ha { $got }
grids-too-small = les graelles donen { $total } variants diferents, menys que --count { $count }: amplia un interval o pren passos més petits
variants-few = només s’han trobat { $found } de { $count } variants entre { $drawn } sortejades: { $apart } no es munten, { $dead } són a prop d’un punt mort, { $close } no distingeixen un error habitual de la resposta correcta; canvia els intervals
weights-count = dona un pes per a cada pregunta qualificada: { $count }, i hi ha { $got }
weight-positive = un pes és un nombre positiu, i hi ha { $got }
reveal-after-check = la resolució pas a pas es mostra després de comprovar: envia les respostes amb la petició
students-first-column = { $name }: la primera columna ha de contenir els identificadors dels estudiants
student-twice = l’estudiant { $student } apareix dues vegades a la llista (línies { $first } i { $line })
student-variant-range = la variant { $got } no és entre 1 i { $count }
table-unreadable = no es pot llegir { $path }: { $reason }
table-empty = { $name } és buit (una capçalera i després una fila per línia)
table-no-column = { $name } no té la columna '{ $column }' (la seva capçalera: { $header }; columnes: { $columns })
row-fields = { $count } camps, però la capçalera en té { $header } (un valor amb una coma va entre cometes)
row-not-read = { $place }: no llegida: { $error }
students-unknown = no són a la llista de la classe (es deixen fora): { $students }
grade-column = { $column ->
        [question] pregunta
        [answers] respostes
        [right] correctes
        [carried] derivades
        [mistakes] errors
        [student] estudiant
        [variant] variant
       *[score] nota
    }
grade-score = { $score } %
exercise-not-drawn-rounding = descartada: { $data }: arrodonir les dades a 3 xifres canvia { $question } un { $gap } %
exercise-not-drawn-mistake = descartada: { $data }: l’error { $kind } dona { $question } a menys del { $gap } % de la resposta correcta
exercise-narrowed = variant { $number }: el marge de { $question } s’estreny al { $tolerance } % per distingir l’error { $kind } (que se n’aparta un { $gap } %)
exercise-wrote = { $count } { $count ->
        [one] variant escrita
       *[other] variants escrites
    } a { $folder }
exercise-progress = figures i resolucions pas a pas: { $done }/{ $total }
pdf-skipped = no es genera el PDF: { $program } no està instal·lat ({ $hint })

## figures i explicacions (draw/*.py, explain/*.py, web/strings.py)
animate-planar = animate dibuixa models plans; dibuixa l’instant d’un model 3D amb `kinematika draw`
ffmpeg-missing = escriure .mp4 necessita el programa ffmpeg, que no està instal·lat (a Debian o Ubuntu: apt install ffmpeg; amb conda: conda install ffmpeg); o escriu un .gif, que no necessita res més
sweep-none-assembled = no s’ha pogut muntar cap posició de l’escombratge
trace-unknown-point = punt desconegut '{ $point }' per traçar
plot-format = no es pot dibuixar a '{ $name }': dona un fitxer .png, .svg o .pdf
draw-at-not-real = el model no es pot dibuixar amb aquests valors: el punt { $point } no hi és real
unknown-format = format desconegut '{ $format }' (formats: { $formats })
catalogue-no-message = no hi ha el missatge '{ $key }' al catàleg '{ $lang }'
catalogue-message-error = missatge '{ $key }' del catàleg '{ $lang }': { $problem }
page-message-error = missatge de la pàgina '{ $key }' ({ $lang }): { $problem }

## la línia d’ordres (cli/*.py)
out-of-memory = el treball necessita més memòria de la que dona aquesta màquina; fes més petit el model o l’escombratge
internal-error = error intern ({ $detail }); torna a executar amb KINEMATIKA_DEBUG=1 i informa’n
no-folder = no existeix la carpeta { $folder }
it-is-a-folder = és una carpeta
it-is-a-file = és un fitxer
the-output-file = el fitxer de sortida
students-none = { $name } no anomena estudiants (una capçalera i després un per fila)
synthesis-one-target = dona un de --target (trajectòria), --target-function (funció) o --target-motion (moviment)
function-needs-output = la generació de funcions necessita --output BODY
path-needs-point = la generació de trajectòries i de moviment necessita --point P
map-or-pareto = dona --map X,Y,METRIC o --pareto M1,M2
option-names-count = { $option } pren { $count } noms separats per comes
study-unreadable = no es pot llegir l’estudi { $path }: { $reason }
option-name-value = { $option } espera NAME=VALUE, i hi ha { $got }
cannot-serve = no es pot servir a { $address }: { $reason }
format-needs-output = --format { $format } necessita -o FILE, el fitxer per escriure
sweep-format = { $got } no és un format d’escombratge: dona --format { $formats } o un fitxer que acabi en un d’aquests

## la pàgina i la seva API (web/*.py)
build-op = 'op' és un objecte la 'op' del qual és una de { $actions }
tool-picks = l’eina `{ $tool }` pren { $count } clics ({ $picks })
build-path = 'path' és una llista de claus i índexs
build-value = 'value' és un nombre o una expressió
build-value-empty = 'value' és buit
build-value-finite = 'value' no és un nombre finit
build-nothing-at = no hi ha res a { $path } del model
delete-missing = no hi ha { $element } per esborrar
delete-what = { $element }: esborra point:NAME, body:NAME, joint:ID, driver:N o ask:N
delete-no-point = no hi ha el punt '{ $point }' per esborrar
delete-no-body = no hi ha el sòlid '{ $body }' per esborrar (el fix es queda)
driver-value = el valor d’una dada de moviment és un nombre o una expressió
input-body-or-joint = l’entrada és un sòlid mòbil o un enllaç del model
question-kind = { $question }: una pregunta és una de { $kinds }
question-target = 'target' anomena el punt o el sòlid pel qual es pregunta
target-not-moving = { $target } no és en cap sòlid mòbil
format-one-of = { $format }: un format és un de { $formats }
toml-null = { $place } és null, que TOML no pot escriure (un paràmetre simbòlic): deixa aquest model en YAML o JSON
the-model = el model
drag-constructed = { $point } està construït: arrossega’l en un model YAML o JSON, o edita’n la construcció
no-point-in-model = no hi ha el punt '{ $point }' al model
drag-not-planar = { $point } no és un punt pla amb dues coordenades
drag-formula = { $point } és situat per la fórmula { $formula }: canvia’n els paràmetres per moure’l
drag-lines-meet = { $point } és el tall de dues rectes: arrossega els punts per on passen
model-unreadable = el model no es pot llegir: { $problem }
drag-toml-form = el punt '{ $point }' no està escrit com `{ $point } = [x, y]` a la taula [points]
request-vary = 'vary' és una llista de textos NAME=LOW:HIGH[:STEP]
request-answers = 'answers' associa identificadors de pregunta (q2.y) als nombres escrits
request-reveal = 'reveal' és true o false
request-whole-range = '{ $key }' és un nombre enter, de { $low } a { $high }
request-whole-least = '{ $key }' és un nombre enter, com a mínim { $low }
request-one-variant = sense 'vary' l’exercici té una sola variant, les dades del model
help-no-document = no hi ha el document '{ $name }' (l’ajuda serveix docs/*.md)
no-free-point-name = no queda cap nom de punt lliure
not-finite-number = { $value } no és un nombre finit
pick-no-point = encara no hi ha cap punt '{ $point }'
link-two-points = una barra uneix dos punts diferents
link-length = una barra necessita longitud: posa’n l’extrem en un altre lloc
point-two-conditions = { $point } ja és situat per dues condicions: esborra abans una de les seves barres
slot-own-points = la ranura passa per dos punts de { $body }: tria un altre sòlid o un altre passador
plate-two-points = { $body } necessita dos punts abans de fixar-hi un tercer
track-once = el fix ja té una pista: una sola pista recta per model
wheel-centre = posa el centre de la roda lluny del seu punt de contacte
gear-centre = posa el centre del segon engranatge lluny del primer
no-body = no hi ha el sòlid '{ $body }'
slot-outline-once = { $body } ja té un contorn: una sola ranura per sòlid
pin-other-body = el passador { $pin } no és en cap sòlid diferent de { $body }: tria un passador d’un altre sòlid
slot-centre-pin = el centre de la ranura no pot ser el passador
contact-two-bodies = un contacte uneix dos sòlids diferents
contact-no-outline = { $body } no té contorn (una circumferència, una recta, una corba, una lleva) amb què tocar: escriu-ne abans la forma al text
tool-unknown = eina desconeguda '{ $tool }' (la paleta té { $tools })
request-not-json = la petició no és JSON: { $problem }
request-object = la petició és un objecte JSON amb almenys la clau 'model'
request-unknown-key = clau desconeguda '{ $key }' per a /api/{ $endpoint } (admeses: { $accepted })
request-model = 'model' és obligatori: el text del fitxer del model
request-points = 'points' és una llista de noms de punts
request-width = 'width' és l’amplada de la figura en polzades, d’1 a 100
request-frame = 'frame' és la capsa que mostra la figura, [x0, y0, x1, y1] amb x0 < x1 i y0 < y1
request-op = 'op' és l’acció: un objecte amb la seva clau 'op'
request-to = 'to' és la nova posició del punt [x, y]
request-point = 'point' anomena el punt per moure
request-choice = { $value }: { $key } és un de { $choices }
request-flag = '{ $key }' és true, false o null
request-text = '{ $key }' és un text
request-number = '{ $key }' és un nombre
request-assignments = '{ $key }' associa noms a nombres o expressions
request-assignment = { $key }: un nombre o una expressió
no-example = no hi ha cap exemple inclòs '{ $name }'
server-busy = el servidor està ocupat: torna-ho a provar d’aquí a un moment
server-timeout = el càlcul ha trigat més de { $seconds } s i s’ha abandonat
no-template = no hi ha la plantilla '{ $name }'
request-content-type = envia la petició com a JSON (Content-Type: application/json)
request-too-large = la petició és massa gran ({ $size } bytes; com a molt { $limit })
internal-error-page = error intern ({ $detail }); si us plau, informa’n

## les línies que escriu la línia d’ordres (cli/__init__.py, cli/shared.py)
error-line = error ({ $kind }): { $text }
internal-line = error: { $text }
warning-line = avís: { $text }
usage-line = error (usage): { $text } (vegeu { $command } --help)
aborted = interromput
click = { $code ->
        [NoSuchOption] no existeix l’opció { $name }{ $count ->
            [0] {""}
           *[other] {" "}(potser { $suggestions }?)
        }
        [MissingParameter] falta { $name }
        [BadParameter] { $name } no admet aquest valor
        [BadOptionUsage] { $name } necessita un valor
        [ExtraArgument] sobren arguments
        [NoSuchCommand] no existeix l’ordre '{ $name }'
       *[other] { $text }
    }
serving-open = servint a { $host }: qualsevol que arribi a aquesta màquina pel port { $port } pot fer servir la pàgina (no llegeix cap fitxer, però calcula per a ells)

## limit positions and rows of a sweep (sweep/limit_positions.py, sweep/continuation.py, sweep/move.py)
sweep-too-many-limits = el moviment passa per més de { $limit } posicions límit; fes un escombratge d’un recorregut més curt
sweep-not-followed = no es pot seguir el moviment més enllà de { $joint } = { $value } { $unit } (després d’un recorregut de { $travel } { $unit }): { $why }
follow-turns-back = torna enrere de seguida: s’hi troben branques del moviment
follow-cannot-close = { $bodies } no pot tancar-s’hi, i no és una posició límit
follow-not-corrected = la corba no s’hi ha pogut corregir
follow-starts-at-limit = comença en una posició límit
follow-branches-meet = s’hi troben branques del moviment
follow-runs-off = el mecanisme s’hi en va a l’infinit
follow-too-many-steps = més de { $limit } passos de continuació entre dues files
follow-not-assembled = el mecanisme no s’hi ha pogut muntar
follow-stuck = el mecanisme no es pot muntar un pas més enllà, i no és una posició límit
row-needs-numbers = una fila de l’escombratge necessita nombres per a tots els paràmetres
row-out-of-range = fila { $row }: l’escombratge té les files 0 a { $last }
row-cannot-assemble = la fila { $row } de l’escombratge no es pot muntar

## renaming on the page (web/rename.py)
rename-not-a-name = '{ $name }' no és un nom: una lletra, i després lletres, xifres o _
rename-element = '{ $element }': reanomena body:NOM o point:NOM
rename-language = '{ $lang }': l’idioma és un de { $langs }
rename-nothing = no hi ha cap '{ $element }' per anomenar
rename-no-body = no hi ha cap sòlid '{ $name }' per reanomenar
rename-body-exists = ja hi ha un sòlid '{ $name }'
rename-no-point = no hi ha cap punt '{ $name }' per reanomenar
rename-point-exists = ja hi ha un punt '{ $name }'

## the model's notation of indices and spins (model/wording.py)
index-twice = els sòlids '{ $first }' i '{ $second }' s’escriurien tots dos '{ $index }'
spin-not-wheel = l’enllaç '{ $joint }' no és una roda: només una roda té velocitat de gir pròpia
spin-shape = un gir propi s’escriu {"{"}symbol: NOM, radius: PARÀMETRE{"}"} (symbol: phidot, radius: r)
spin-radius-unknown = el radi '{ $radius }' no és un paràmetre (paràmetres: { $parameters })
index-shape = '{ $index }' no és un índex de sòlid: d’una a quatre lletres o xifres (N, 1, R, T)
contact-name-shape = '{ $index }' no és un nom de punt de contacte: d’una a quatre lletres o xifres (F, J, K2)

## symbols at their draw_at numbers, travel, straight outlines (sweep/posing.py, sweep/plan.py, joints/touching.py)
needs-draw-at = { $what ->
        [move] un moviment
        [simulate] una simulació
       *[sweep] un escombratge
    } necessita nombres: dona un valor a { $names }, o al model un nombre `draw_at` per a cada símbol
at-draw-numbers = { $what ->
        [move] mogut
       *[sweep] escombrat
    } amb els nombres draw_at dels seus símbols: { $values }{ $said ->
        [true] {" "}({ $why })
       *[other] {""}
    }
travel-too-far = { $what } { $amount } és més del que recorre un escombratge o un moviment: com a màxim { $most }{ $unit ->
        [angle] ° ({ $turns } voltes)
       *[length] {" "}({ $turns } vegades la mida del mecanisme)
    }
two-straights-touch = dos contorns rectes es toquen al llarg d’una recta, no en un punt: uneix-los amb un enllaç prismàtic

## synthesis: its task, its target file, its four-bar (explore/synthesis/*.py, cli/explore.py)
synthesis-no-design = cap disseny dels intervals no completa el seu cicle{ $requirements ->
        [0] {""}
       *[other] {" "}i compleix els requisits
    }
synthesis-no-full-turn = cap disseny trobat no completa una volta sencera de la seva entrada
synthesis-nothing-found = cap disseny dins dels intervals de --vary no es pot muntar a tots els objectius{ $count ->
        [0] {""}
       *[other] {" "}i complir { $requirements }
    }; amplia els intervals o cerca durant més temps
require-crank-rocker-four-bar = `--require crank-rocker` necessita un quadrilàter articulat mogut per la seva manovella (una manovella i dues barres que tanquen sobre el sòlid fix), amb el seu punt a la biela
require-transmission-linkage = `--require transmission=DEG` necessita un quadrilàter articulat o una biela-manovella moguts per la seva manovella
require-transmission-angle = --require transmission=DEG: DEG és un angle entre 0 i 90 graus, i hi ha { $got }
requirement-unknown = requisit desconegut '{ $requirement }'; requisits: { $requirements }
timing-needs-four-bar = --timing necessita un quadrilàter articulat mogut per la seva manovella, amb el punt de la tasca a la seva biela (en altres models, deixa lliure la sincronització dels objectius)
timing-form = --timing espera JOINT o JOINT=START, i hi ha { $got }
timing-start-number = --timing { $joint }=START: START ha de ser un nombre, i hi ha { $got }
timing-start-finite = --timing { $joint }=START: START ha de ser finit
objective-form = --objective és `sse` o `max`, i hi ha { $got }
output-zero-form = --output-zero és 'free' o un angle en graus, i hi ha { $got }
output-zero-function-only = --output-zero només serveix per a la generació de funcions (--target-function)
output-zero-needs-four-bar = --output-zero necessita un quadrilàter articulat la sortida del qual sigui el seu balancí o la seva biela
output-not-rocker-or-coupler = la sortida '{ $output }' no és el balancí ({ $rocker }) ni la biela ({ $coupler }) del quadrilàter articulat
body-needs-two-points = el sòlid '{ $body }' necessita dos punts per tenir una direcció
targets-too-few = { $name }: { $count } { $count ->
        [one] objectiu
       *[other] objectius
    }; la síntesi necessita com a mínim { $least }
target-columns-count = { $name }: { $count } { $count ->
        [one] columna
       *[other] columnes
    }; aquesta tasca llegeix { $reads }
target-column-unread = { $name }: aquesta tasca no llegeix la columna '{ $column }'{ $timing ->
        [true] {" "}(dona --timing JOINT per fer-la servir)
       *[other] {""}
    }; llegeix { $reads }
target-column-missing = { $name }: no hi ha cap columna '{ $column }' (aquesta tasca llegeix { $reads })
target-header-twice = { $name }, línia { $line }: cada columna s’anomena una sola vegada
target-row-width = { $name }, línia { $line }: { $count } valors on el fitxer té { $columns } columnes
target-not-finite = { $name }, línia { $line }: s’esperaven nombres finits
target-weight-positive = { $name }, línia { $line }: un pes ha de ser positiu
target-first-input = { $name }, línia { $line }: l’entrada del primer objectiu és 0 (les entrades es compten des del primer objectiu)
target-inputs-increase = { $name }, línia { $line }: els valors de la columna '{ $column }' han de créixer ({ $before } i després { $after })
## motion in time (simulate/)
simulate-time-not-evaluated = no es pot avaluar el temps de la simulació: { $problem }
simulate-time-missing = quant de temps cal seguir el moviment: dona --time SEGONS (o una secció `simulate: {"{"}time: ...{"}"}` al model)
simulate-time-positive = el temps ha de ser un nombre positiu de segons, i hi ha { $got }
simulate-steps-too-many = { $steps } passos de { $per_row } valors cadascun passen del que hi cap en una simulació ({ $limit } valors): dona’n com a molt { $most }
simulate-time-too-short = el temps { $time } s és massa curt per seguir el moviment des de t = { $start } s
simulate-time-needs-value = el temps t necessita un valor: el temps de la configuració dibuixada (normalment 0)
simulate-time-only-in-rates = el temps t només pot aparèixer en les velocitats imposades per les dades de moviment (una velocitat que canvia en el temps); aquí mouria el mecanisme per si sol
simulate-unknown-method = mètode desconegut '{ $method }' (els mètodes de scipy.integrate.solve_ivp: { $methods })
simulate-at = a t = { $at } s: { $what }
simulate-rate-not-taken = no es pot prendre la derivada en el temps de la velocitat imposada: { $problem }
simulate-rate-not-evaluated = no es pot avaluar la derivada en el temps de la velocitat imposada ({ $problem })
simulate-rate-not-real = la derivada en el temps de la velocitat imposada no és un nombre real finit (l’arrel quadrada d’un nombre negatiu?)
simulate-rate-not-finite = la derivada en el temps de la velocitat imposada no és finita (una arrel quadrada o un logaritme a zero?)
simulate-velocity-matrix = no es poden resoldre les equacions de velocitat (la seva matriu no està feta de nombres finits)
simulate-too-many-evaluations = el moviment necessita més de { $limit } solucions de velocitat per seguir-lo (limits.SIMULATE_EVALUATIONS): és massa rígid (un element s’assenta molt més de pressa que no pas es mou la resta) o és massa a prop d’una configuració singular
simulate-dead-point = el moviment arriba a un punt mort a t = { $at } s: més enllà no es poden trobar les velocitats (el nombre de condició del jacobià de restriccions arriba a { $condition })
simulate-not-followed = no es pot seguir el moviment més enllà de t = { $at } s: { $why }
simulate-integrator-stopped = l’integrador s’ha aturat ({ $message })
simulate-positions-not-finite = les posicions integrades no són nombres finits
simulate-projection-fails = les posicions integrades no es poden tornar a les condicions de posició dels enllaços (el moviment ha sortit del que permeten)
simulate-velocity-only = una simulació no pot seguir un enllaç `{ $kind }`{ $dim ->
        [3] {" "}en 3D
       *[other] {""}
    }: la seva condició només és de velocitats, així que les posicions depenen del camí recorregut
animation-file-type = no es pot escriure { $name }: dona un fitxer .gif o .mp4

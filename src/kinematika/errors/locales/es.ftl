## Los mensajes de los errores y avisos, en castellano. Términos del curso: sólido, par
## (enlace entre dos sólidos), datos de movimiento, grado de libertad, punto muerto, montaje,
## barrido. Las claves del archivo de modelo (`at`, 'base', points…) se dejan como se escriben.

## las palabras de otros programas: el motivo del sistema operativo, la queja de un lector
reason = { $errno ->
        [ENOENT] no existe el archivo o la carpeta
        [EACCES] permiso denegado
        [EPERM] operación no permitida
        [EISDIR] es una carpeta
        [ENOTDIR] no es una carpeta
        [ENOSPC] no queda espacio en el disco
        [EROFS] el sistema de archivos es de solo lectura
        [ENAMETOOLONG] el nombre es demasiado largo
        [EEXIST] ya existe
        [EADDRINUSE] la dirección ya está en uso
        [EADDRNOTAVAIL] la dirección no está disponible en esta máquina
        [ECONNREFUSED] conexión rechazada
       *[other] { $text }
    }
problem = { $code ->
        [mapping-values] aquí no se admite un valor de clave (¿falta un salto de línea o sobra un «:»?)
        [colon] falta el «:» que se esperaba
        [token] un carácter que no puede empezar un elemento (¿un tabulador?)
        [key] se esperaba una clave
        [bracket] falta un «,» o un «]»
        [brace] falta un «,» o un «{"}"}»
        [end] el texto termina antes de tiempo
        [alias] un alias sin definir
        [node] se esperaba un valor
        [escape] una secuencia de escape desconocida
        [value] se esperaba un valor
        [property] se esperaba el nombre de una clave entre comillas dobles
        [comma] falta una coma
        [extra] sobra texto después del valor
        [string] un texto sin cerrar
        [control] un carácter de control dentro de un texto
        [equals] falta el «=» tras una clave
        [duplicate] una clave definida dos veces
        [syntax] la sintaxis no es válida
        [unclosed] un paréntesis sin cerrar
        [unmatched] un paréntesis que no se abrió
        [literal] un número mal escrito
        [domain] fuera del dominio de la función
        [range] el resultado es demasiado grande
        [small] el valor es demasiado pequeño para los números de coma flotante
        [zero] división por cero
       *[other] { $text }
    }

## leer archivos (model/files.py)
model-not-a-path = un modelo es la ruta de un archivo, un dict o un Mechanism, no { $type }
file-empty = el archivo está vacío
model-not-a-mapping = un modelo es un diccionario con las claves points, bodies, joints, drivers; este archivo contiene { $holds }
holds = { $what ->
        [list] una lista
        [text] un texto
        [nothing] nada
       *[value] un solo valor
    }
file-type-unknown = tipo de archivo desconocido { $suffix }: { $noun ->
        [cam-file] un archivo de leva
       *[model-file] un archivo de modelo
    } termina en { $suffixes }
file-not-utf8 = el archivo no es texto UTF-8 (byte { $byte })
file-missing = no existe el archivo
file-unreadable = no se puede leer el archivo: { $reason }
file-is-a-folder = esto es una carpeta, no un archivo de modelo
file-too-large = el archivo es demasiado grande para un modelo (más de { $limit } bytes)
file-no-end = el archivo no terminó en { $seconds } s (una tubería o un dispositivo, no un archivo de modelo)
text-too-large = el texto es demasiado grande para un modelo (más de { $limit } caracteres)
text-unreadable = { $format } ilegible: { $detail }
file-too-deep = el archivo está anidado a demasiada profundidad para ser un modelo (más de { $levels } niveles{ $line ->
        [0] {""}
       *[other] , línea { $line }
    })
name-too-long = el nombre { $name } tiene { $length } caracteres: los nombres tienen como mucho { $limit }
text-lone-surrogate = el texto { $text } contiene un sustituto suelto, que no es texto Unicode
key-duplicate = clave repetida { $key }{ $line ->
        [0] {""}
       *[other] {" "}en la línea { $line }
    }: cada clave puede aparecer una sola vez
json-invalid = JSON no válido en la línea { $line }, columna { $column }: { $problem }
toml-invalid = TOML no válido: { $problem }
yaml-invalid = YAML no válido{ $line ->
        [0] {""}
       *[other] {" "}en la línea { $line }, columna { $column }
    }: { $problem }
yaml-alias-inside = el alias *{ $alias } de la línea { $line } está dentro de lo que nombra
yaml-alias-unknown = el alias *{ $alias } de la línea { $line } no nombra ningún ancla
yaml-aliases-too-many = los alias se expanden a más de { $limit } valores (en la línea { $line }): demasiados para un modelo
model-no-cam = este modelo no tiene leva: da a un sólido una forma `cam:`

## palabras que comparten los mensajes
none = ninguno
or-word = o
more = , … ({ $n } más)
integer-bits = un entero de { $bits } bits

## expresiones (expressions.py)
expr-expected = se esperaba un número o una expresión, y hay { $got }
expr-not-finite = se esperaba un número finito dentro del rango de los números de coma flotante, y hay { $got }
expr-empty = expresión vacía
expr-too-long = expresión de más de { $limit } caracteres
expr-unreadable = no se puede leer la expresión { $source }: { $detail }
expr-unreadable-bare = no se puede leer la expresión { $source }
expr-too-deep = la expresión { $source } está anidada a demasiada profundidad
expr-constant = en { $source }: solo se pueden escribir números como constantes
expr-number-too-large = en { $source }: un número es demasiado grande
expr-unknown-function = en { $source }: función desconocida { $function } (conocidas: { $known })
expr-arguments = en { $source }: { $function } toma { $count ->
        [one] un argumento
       *[other] { $count } argumentos
    }
expr-not-allowed = en { $source }: { $part } no se admite en una expresión
expr-unknown-name = en { $source }: nombre desconocido { $name } (no es un parámetro)
expr-function-fails = en { $source }: no se puede evaluar { $function } ({ $why })
expr-exponent = en { $source }: el exponente { $exponent } es demasiado grande (como mucho { $limit } en valor absoluto)
expr-division-by-zero = en { $source }: división por cero
expr-too-large = en { $source }: el valor es demasiado grande
expr-not-real = en { $source }: el valor no es real
expr-underflow = en { $source }: el valor es demasiado pequeño para los números de coma flotante (se tomaría como 0)
expr-not-finite-value = en { $source }: el valor no es finito
expr-too-many-digits = en { $source }: el valor tiene demasiadas cifras para fórmulas exactas (más de { $limit })
expr-degree = en { $source }: el grado de la fórmula en los símbolos supera { $limit }: demasiado alto para fórmulas exactas
parameter-no-value = el parámetro '{ $name }' no tiene valor
number-too-many-digits = el número { $number } tiene demasiadas cifras para fórmulas exactas (más de { $limit } como fracción): redondéalo o resuelve con números

## la forma del modelo (model/build.py, model/model.py)
model-mapping = un modelo es un diccionario con las claves points, bodies, joints, drivers
frame-missing = no hay ningún sólido fijo '{ $frame }': llama '{ $frame }' a un sólido o pon en `frame:` uno de { $bodies }
parameter-name-invalid = '{ $name }' no es un nombre de parámetro válido (letras, cifras y _, sin empezar por una cifra)
unknown-name-in = nombre desconocido '{ $name }' en '{ $text }'
unknown-name-in-parameters = nombre desconocido '{ $name }' en '{ $text }' (parámetros: { $parameters })
components-count = se esperaban { $dims } componentes, y hay { $got }
model-no-points = un modelo necesita al menos un punto
name-invalid = '{ $name }' no puede ser un nombre: los nombres no están vacíos y no llevan '@' (une un punto a su sólido: B@rocker)
construction-planar = los puntos por construcción son planos; da los puntos de un modelo 3D como coordenadas [x, y, z]
planar-two-coordinates = un modelo plano (dimensión 2) tiene 2 coordenadas por punto
point-listed-twice = el punto '{ $point }' aparece dos veces
point-not-carried = ningún sólido lleva el punto '{ $point }': añádelo a los puntos de un sólido
unknown-point = punto desconocido '{ $point }' (puntos: { $points })
vector-size = un modelo { $dim ->
        [2] plano
       *[other] 3D
    } necesita { $dim } { $what ->
        [coordinates] coordenadas
       *[components] componentes
    }, y hay { $got }
shapes-3d-only = los discos y los planos son de los modelos 3D; en un modelo plano usa circunferencia (circle) y recta (line)
shapes-planar-only = las curvas y las levas son de los modelos planos
unknown-body = sólido desconocido '{ $body }' (sólidos: { $bodies })
joint-id-empty = el identificador de un par no está vacío
joint-id-twice = el identificador de par '{ $id }' se usa dos veces
joint-same-body = un par une dos sólidos distintos, y '{ $body }' aparece dos veces
joint-point-not-on-body = el punto '{ $point }' del par `{ $kind }` no está en el sólido '{ $body }': añade '{ $point }' a sus puntos
direction-same-points = una dirección necesita dos puntos distintos
unknown-joint = par desconocido '{ $joint }' (pares: { $joints })
unknown-joint-bare = par desconocido '{ $joint }'
expected-one-number = se esperaba un número (la componente según `along`), y hay un vector
expected-vector = se esperaba un vector de { $dim } componentes (o da `along` para una sola componente)
questions-too-many = { $count } preguntas: como mucho { $limit } en un modelo
question-one-key = una pregunta tiene exactamente una de las claves { $keys }
contact-not-touching = '{ $text }' no es un par { $kinds } (esos pares son: { $joints })
decompose-needs-moving = una pregunta decompose necesita `moving: BODY`, la referencia móvil
moving-only-decompose = `moving` solo va en las preguntas decompose
question-planar-only = { $kind } es una pregunta de movimiento plano; en 3D pregunta por el eje helicoidal (`axis`)
question-3d-only = el eje helicoidal es una pregunta 3D; en un modelo plano pregunta por el CIR (`icr`)
steps-at-least-one = steps tiene que ser al menos 1

## lo que pydantic encuentra mal en la forma de un archivo (model/build.py, cams/spec.py)
schema-problems = { $problem }{ $others ->
        [0] {""}
        [one] {" "}(y { $others } problema más)
       *[other] {" "}(y { $others } problemas más)
    }
driver-second-kind = un dato de movimiento tiene exactamente una de las claves { $kinds }; '{ $key }' es una segunda
unknown-key = clave desconocida '{ $key }'
missing-key = falta la clave '{ $key }'
not-one-of = { $value } no es uno de { $expected }
unexpected-value = valor inesperado { $value }: { $problem }
pydantic = { $type ->
        [missing] falta
        [extra_forbidden] clave desconocida
        [float_type] se esperaba un número
        [int_type] se esperaba un número entero
        [int_from_float] se esperaba un número entero
        [int_parsing] se esperaba un número entero
        [float_parsing] se esperaba un número
        [finite_number] se esperaba un número finito
        [string_type] se esperaba un texto
        [bool_type] se esperaba true o false
        [list_type] se esperaba una lista
        [dict_type] se esperaba un diccionario (claves y valores)
        [model_type] se esperaba un diccionario (claves y valores)
        [model_attributes_type] se esperaba un diccionario (claves y valores)
        [too_short] se esperaban al menos { $ctx_min_length } elementos
        [too_long] se esperaban como mucho { $ctx_max_length } elementos
        [greater_than] tiene que ser mayor que { $ctx_gt }
        [greater_than_equal] tiene que ser al menos { $ctx_ge }
        [less_than] tiene que ser menor que { $ctx_lt }
        [less_than_equal] tiene que ser como mucho { $ctx_le }
        [literal_error] no es uno de los valores admitidos
        [union_tag_invalid] no es una de las formas admitidas
        [union_tag_not_found] no es una de las formas admitidas
        [construction_kind] un punto son coordenadas [x, y] o una construcción con una de las claves from, frame, circles, circle, lines
        [driver_kind] un dato de movimiento necesita una de las claves omega, joint o velocity
       *[other] el valor no encaja aquí
    }
point-name-not-text = un punto se nombra con un texto como 'B' o 'B@rocker', y hay { $got }
point-body-after-at = '{ $text }': escribe el sólido tras '@' (como en '{ $example }')
body-not-carrying = el sólido '{ $body }' no lleva el punto '{ $point }' (lo llevan { $carriers })
point-ambiguous = el punto '{ $point }' lo llevan { $carriers }, que ahí se mueven de forma distinta: escribe { $choices }
unknown-parameter = parámetro desconocido '{ $name }' (parámetros: { $parameters })
name-or-note-empty = un nombre o una nota no está vacío
notation-key-unknown = '{ $key }' no es un parámetro (parámetros: { $parameters }) ni omega(BODY), omega(BODY/OTHER), alpha(…)
notation-rate-bodies = '{ $key }': una velocidad angular es de un sólido, o de un sólido respecto de otro (omega(blades/block))
notation-spelling = '{ $name }' no es el nombre de un símbolo: letras, cifras y _ tal como los escribe sympy (omega_0 es ω₀, vdot es v̇, R_roda)
draw-at-has-value = '{ $name }' ya tiene valor: draw_at da números a los parámetros simbólicos (null)
draw-at-not-finite = '{ $name }' se dibuja con { $value }: da un número finito{ $positive ->
        [true] {" "}y positivo
       *[other] {""}
    }
draw-at-range = '{ $name }' se dibuja con { $value }: las figuras se dibujan con números de tamaño entre { $low } y { $high }
up-planar = up nombra la vertical de un modelo 3D; un modelo plano se dibuja en su propio plano
up-direction = up es una dirección no nula de 3 números, como [0, 1, 0]
construction-cycle = las construcciones se refieren unas a otras en un ciclo: { $cycle }
construction-point-expected = se esperaba el nombre de un punto o coordenadas [x, y], y hay { $got }
construction-coordinates = las construcciones son planas: coordenadas [x, y], y hay { $got } componentes
construction-circle-radius = una circunferencia es [centro, radio]: el radio es un solo número
circle-arc = el arco [desde, hasta] de una circunferencia (grados, en sentido antihorario) es una parte de ella: 0 < hasta − desde < 360 (aquí de { $start } a { $end })
construction-line-direction = la dirección de una recta es un vector; para una recta por dos puntos escribe [P, Q]
construction-direction-planar = las construcciones son planas: una dirección [dx, dy]
near-symbolic = `near` necesita números; en un modelo con parámetros simbólicos elige la intersección con `side`
near-point = `near` es un punto del croquis [x, y]
two-points-same = hacen falta dos puntos distintos, y '{ $point }' aparece dos veces
statement-placeholder = {"{"}{ $name }{"}"} no es un parámetro (parámetros: { $parameters })
unit-not-length = '{ $unit }' no es una unidad de longitud (unidades: { $units })
question-missing = la pregunta { $number } no existe: el modelo hace { $count } (numeradas desde 1)
graded-once = nombra cada pregunta calificada una vez (al menos una)
tolerance-relative = la tolerancia es relativa, entre 0 y 1: hay { $tolerance }
unknown-point-bare = punto desconocido '{ $point }'
unknown-unit = unidad desconocida '{ $unit }' (unidades: { $units })
parameters-mapping = los parámetros son un diccionario de nombres y valores, y hay { $type }

## levas (cams/*.py) y curvas (curves/*.py)
cam-translating-no-key = un seguidor de traslación no tiene '{ $key }'
cam-oscillating-no-offset = un seguidor oscilante no tiene 'offset' (sitúa su pivote)
cam-oscillating-pivot = un seguidor oscilante necesita 'pivot' (su distancia al centro de la leva)
cam-oscillating-arm = un seguidor oscilante necesita 'arm' (del pivote al centro del rodillo o al filo)
cam-roller-radius = un seguidor de rodillo necesita 'radius'
cam-no-radius = un seguidor `{ $contact }` no tiene 'radius'
cam-polynomial-only = solo un tramo polinómico admite condiciones '{ $key }'
cam-dwell-to = un reposo mantiene quieto el seguidor: quita 'to'
cam-segment-to = un tramo `{ $law }` necesita 'to' (el desplazamiento al final)
cam-below-lowest = el seguidor bajaría de su posición más baja (s < 0, dentro de la circunferencia base)
cam-segment-still = un tramo `{ $law }` tiene que mover el seguidor: 'to' es igual al desplazamiento del que parte (usa un reposo)
cam-span = los tramos abarcan { $total }°; el programa de una leva de disco abarca 360°
cam-program-ends = el programa termina en s = { $end }, no donde empieza (0): el movimiento de una leva de disco se repite cada vuelta
cam-no-polynomial = ningún polinomio cumple estas condiciones de contorno
cam-program-or-profile = da el movimiento de la leva con 'program' o su forma con 'profile' (uno de los dos)
cam-base-missing = falta la clave 'base' (el radio de la circunferencia base)
cam-speed-once = da la velocidad de la leva una sola vez: omega (rad/s), rpm o velocity (una leva de traslación)
cam-speed-translating = la velocidad de una leva de traslación es su 'velocity'
cam-speed-disc = la velocidad de una leva de disco es 'omega' o 'rpm'
cam-plate-translating = una leva de traslación mueve un seguidor de traslación
cam-plate-flat = una cara plana no puede seguir una leva de traslación (usa un rodillo o un filo)
cam-plate-offset = el seguidor de una leva de traslación no tiene excentricidad
cam-offset-prime = la excentricidad { $offset } tiene que ser menor que el radio { $radius } de la circunferencia primitiva
cam-face-base = la cara no puede tocar la circunferencia base: hace falta 0 < base + face < pivot
cam-arm-reach = el brazo no alcanza la circunferencia primitiva (radio { $radius }): hace falta |pivot − arm| < { $radius } < pivot + arm
cam-arm-past = el programa gira el brazo { $turn }° desde { $start }°, más allá de { $reach }° (donde el seguidor pierde la leva)
cam-file-mapping = un archivo de leva es un diccionario con las claves cam, follower, program (o profile), speed
value-problem = { $value }: { $problem }
cam-profile-disc = una leva dada por puntos del perfil es una leva de disco
cam-profile-base = una leva dada por puntos del perfil tiene la circunferencia base que da su perfil: quita 'base'
cam-follower-misses = el seguidor no llega a la leva
cam-knife-misses = la trayectoria del filo no toca la leva
cam-jump = la { $quantity ->
        [velocity] velocidad
       *[acceleration] aceleración
    } salta { $size } { $unit } en { $at }{ $place } ({ $quantity ->
        [velocity] aceleración infinita
       *[acceleration] sobreaceleración infinita
    }: se incumple la ley fundamental del diseño de levas)
curve-line-direction = la dirección de una recta no puede ser nula
curve-unbounded = una curva no acotada no tiene puntos que dibujar: dale un dominio finito
spline-points = los puntos de una spline son una lista de pares (x, y)
spline-too-few = una spline { $closed ->
        [true] cerrada
       *[false] abierta
    } necesita al menos { $need } puntos
spline-points-differ = los puntos consecutivos de una spline tienen que ser distintos
circle-radius-positive = el radio de una circunferencia tiene que ser positivo
arc-angles = un arco va en sentido antihorario de a0 a a1, con a0 < a1 ≤ a0 + 2π
cam-flat-translating = un seguidor de cara plana no puede seguir una leva de traslación

## pares (joints/*.py)
and-word = y
nothing = {""}
sweep-velocity-only = un barrido no puede seguir un par `{ $kind }`{ $dim ->
        [3] {" "}en 3D
       *[other] {""}
    }: su condición es solo de velocidades, así que las posiciones dependen del camino recorrido{ $in_time ->
        [true] ; `kinematika simulate` lo sigue en el tiempo
       *[other] {""}
    }
joint-other-dimension = un par `{ $kind }` es de un modelo { $dim ->
        [2] 3D
       *[other] plano
    }
joint-needs-key = un par `{ $kind }` necesita `{ $key }`
internal-owners = `internal` solo va en los pares { $owners }
joint-no-key = un par `{ $kind }` no tiene `{ $key }`{ $planar ->
        [true] {" "}en un modelo plano (las rotaciones son alrededor de z)
       *[other] {""}
    }
joint-no-rate = un par `{ $kind }` no tiene velocidad que imponer; impón la omega de un sólido o la velocidad de un punto
rounding-hint = , mayor que la tolerancia { $tolerance } (1e-6 del tamaño del modelo): escribe { $point } por construcción o con más cifras
slot-off-line = el pasador '{ $point }' está fuera de la recta { $line }: separación { $gap }{ $hint }
cam-joint-first-body = el primer sólido de un par de leva lleva la leva: da a '{ $body }' una forma `cam:`
cam-joint-face = un seguidor de cara plana toca con su cara: da a '{ $body }' una recta `line` (la cara)
cam-joint-at = un par de leva necesita `at`: { $roller ->
        [true] el centro del rodillo del seguidor
       *[other] el filo del seguidor
    }
curved-slot-outline = una ranura curva se talla a lo largo de una circunferencia o curva de '{ $body }': dale una a ese sólido
cylindrical-two-rates = un par cilíndrico tiene dos velocidades (giro y deslizamiento): impón la omega del sólido respecto del otro sólido (relative_to) y la velocidad de un punto según el eje
rolling-needs-shapes = un par `{ $kind }` necesita una forma en los dos sólidos: da a '{ $body }' { $dim ->
        [2] una circunferencia o una recta
       *[other] un disco o un plano
    }
shapes-cannot-roll = estas formas no pueden rodar una sobre otra
no-touch = '{ $body }' no toca '{ $other }': separación { $gap }{ $hint }
the-contact-or-centre = el contacto o el centro
the-contact = el contacto
contact-not-at = el contacto no está en '{ $point }': está a { $distance }{ $hint }
internal-circles-only = `internal` dice cómo se tocan dos circunferencias; este contacto es `{ $contact }`
rolling-internal-wrong = el par `{ $kind }` se declara { $said ->
        [internal] interior
       *[external] exterior
    }, pero sus { $kind ->
        [gear] circunferencias primitivas
       *[other] circunferencias
    } se tocan por { $said ->
        [internal] fuera
       *[external] dentro
    }
disc-flat-on-plane = el disco '{ $disc }' está tumbado sobre el plano de '{ $plane }': toca con toda su cara, no en un punto
sweep-rolling-only = un barrido solo sigue la rodadura de circunferencias y rectas
contact-acceleration-curve = la aceleración del punto geométrico de contacto sobre una curva general necesita la variación de su curvatura: pregunta por los puntos de los sólidos
straight-outlines = dos contornos rectos se tocan a lo largo de una recta, no en un punto: únelos con un par prismático
pair-cannot = `{ $kind }` entre '{ $body }' y '{ $other }': { $why }
touching-needs-outlines = un par `{ $kind }` necesita un contorno en los dos sólidos: da a '{ $body }' una circunferencia, una recta o una curva (o nombra su punto con `at`)
outlines-cannot-touch = estos contornos no pueden tocarse en un punto

## las condiciones del movimiento, nombradas en los mensajes
row-joint = { $id }: { $label }
row-driver = { $where } ({ $label })
row-joint-rate = velocidad del par { $joint } = { $value }
row-rate = { $name } de { $body }
row-rate-relative = { $name } de { $body } respecto de { $relative }
row-equals = { $label } = { $value }
row-component = { $label } ({ $axis }) = { $value }
row-point-along = { $name } de { $point } según la dirección dada = { $value }
row-point = { $name } de { $point }
row-idle = sin giro ocioso de { $body } alrededor de { $axis }
row-curved-slot = { $point } sigue en la ranura curva de { $body }
row-turning-axis = rotación relativa solo alrededor del eje ({ $n })
row-sliding-axis = deslizamiento relativo solo según el eje ({ $n })
row-across-guide = sin movimiento relativo transversal a la guía ({ $n })
row-moves-with = { $point } se mueve con { $other } ({ $axis })
row-no-slip = sin deslizamiento en el contacto de { $body } y { $other } ({ $axis })
row-slot = { $point } sigue en la ranura de { $body }
row-turns-with = { $body } gira con { $other }
row-body-moves-with = { $body } se mueve con { $other } ({ $axis })
row-no-sideways = { $point } no tiene velocidad lateral respecto de { $body }
row-touching = { $b } sigue tocando { $a }
row-cam-touching = el seguidor { $b } sigue tocando la leva { $a }
row-no-rotation = sin rotación relativa
row-no-rotation-axis = sin rotación relativa ({ $axis })

## la movilidad del mecanismo (engine/mobility.py)
infinite = infinito
dead-point = un punto muerto: los datos de movimiento no fijan aquí el movimiento; { $count ->
        [0] los datos de movimiento dependen
        [one] { $drivers } depende
       *[other] { $drivers } dependen
    } de los pares (número de condición { $condition } del jacobiano adimensional, límite { $limit })
mobility-free = el mecanismo tiene { $dof ->
        [one] { $dof } grado
       *[other] { $dof } grados
    } de libertad, pero los datos de movimiento dan { $conditions ->
        [one] { $conditions } condición independiente
       *[other] { $conditions } condiciones independientes
    }; queda libre: { $count ->
        [0] parte del movimiento
       *[other] { $free }
    }
drivers-conflict = los datos de movimiento se contradicen, sus valores no concuerdan entre sí o con los pares: { $named } ({ $dof ->
        [one] { $dof } grado
       *[other] { $dof } grados
    } de libertad; { $given ->
        [one] { $given } condición dada
       *[other] { $given } condiciones dadas
    }, { $conditions } independientes)

## el instante: valores, direcciones, puntos por construcción (engine/*.py)
direction-zero = una dirección no puede ser el vector nulo
direction-not-exact = esta dirección no se puede convertir exactamente en un vector unitario: sus componentes son de tamaños demasiado distintos (escribe la pequeña como 0)
direction-points-coincide = una dirección necesita dos puntos distintos: { $start } y { $end } coinciden
value-not-real = un valor no es un número real para los valores de los símbolos (¿la raíz cuadrada o una potencia de una cantidad negativa?)
parameters-cycle = los parámetros se refieren unos a otros en un ciclo: { $names }
points-not-real = los puntos no son reales para ninguno de los valores de los símbolos probados (¿la raíz cuadrada de un número negativo?)
curves-need-numbers = las curvas y las levas se dibujan con números: da sus valores a los parámetros (o resuelve sin --symbolic)
curve-through-points = la curva no se puede trazar por sus puntos: { $why }
radius-positive = un radio tiene que ser positivo, y hay { $radius }
jacobian-singular-large = el jacobiano de restricciones de { $rows }×{ $columns } es singular o no es cuadrado (LU dispersa); el sistema es demasiado grande para decir qué condiciones faltan o dependen de otras
structurally-singular = el sistema no tiene un conjunto estructuralmente independiente de condiciones para cada incógnita
angle-in-radians = el ángulo { $angle } está en radianes: { $degrees }°, { $turns } vueltas; para { $angle }° escribe deg({ $written })
point-too-large = las coordenadas exactas de { $point } tendrían unas { $size } operaciones (más de { $limit }): demasiado grandes para fórmulas; da números a más parámetros o resuelve sin --symbolic
length-positive = { $what ->
       *[radius] un radio
    } tiene que ser positivo, y hay { $value }
direction-points-same = los dos puntos que dan la dirección coinciden
fit-each-side = , uno a cada lado de { $line }
fit-on-line = {" "}en la recta { $line }
circles-same-centre = las circunferencias de centro { $a } y { $b } tienen el mismo centro
circles-apart = las circunferencias de centro { $a } ({ $ra }) y { $b } ({ $rb }) no se cortan: centros a { $d }, { $gap } más que { $ra } + { $rb }
circles-inside = las circunferencias de centro { $a } ({ $ra }) y { $b } ({ $rb }) no se cortan: la de centro { $inner } está dentro de la de centro { $outer } (centros a { $d }, { $gap } menos que |{ $ra } − { $rb }|)
line-direction-zero = la dirección de una recta no puede ser el vector nulo
circle-misses-line = la circunferencia de centro { $centre } ({ $radius }) no corta la recta { $line }: la recta está a { $distance } de { $centre }, { $gap } más que el radio
lines-parallel = las rectas { $a } y { $b } son paralelas: no se cortan
line-points-coincide = la recta { $line } se da con dos puntos que coinciden
two-points-fit = hay dos puntos posibles{ $relation }: { $points }; elige uno con side: { $first } o { $second }, o con near: [x, y]
beyond-floats = más de lo que admiten los números de coma flotante
model-size-range = el tamaño del modelo es { $size }: kinematika calcula con longitudes entre { $low } y { $high }, en cualquier unidad; escribe las longitudes en otra unidad
rates-range = los valores de los datos de movimiento están fuera de rango para este mecanismo (una velocidad de { $rate } por unidad de tiempo): kinematika calcula con velocidades entre { $low } y { $high }; escribe los tiempos en otra unidad
values-overflow = los valores del modelo son demasiado grandes: sus velocidades o aceleraciones desbordan el rango de los números de coma flotante

## límites del trabajo, módulos opcionales, idiomas (budget.py, extras.py, languages.py)
over-budget = hallar { $what } lleva { $counted ->
        [true] más de { $steps } pasos de álgebra exacta
       *[other] más de { $seconds } s de CPU
    }{ $staged ->
        [true] {" "}({ $stage })
       *[other] {""}
    }: son demasiado grandes; { $advice }
exact-formulas = las fórmulas exactas
stage-solving = resolviendo las ecuaciones exactamente
stage-simplifying = simplificando las fórmulas
advice-symbolic = da números a algunos parámetros o resuelve sin --symbolic
advice-null = da números a algunos de los parámetros dejados como símbolos (null: { $names })
advice-numbers = da números a algunos parámetros
module-missing = { $what } necesita { $module }, que no está instalado: instálalo con { $command }
writing-parquet = escribir Parquet (o escribe .npz)
writing-dxf = escribir DXF
study-on-dask = un estudio en un clúster Dask
unknown-language = idioma desconocido '{ $lang }' (idiomas: { $langs })
centres-planar = los CIR son de movimiento plano; en 3D pregunta por el eje helicoidal (`axis`) de cada sólido

## barridos, movimientos y montajes (sweep/*.py)
assembly-not-whole = un montaje es un número entero, y hay { $got }
assembly-missing = no hay montaje { $number }: este mecanismo tiene { $count } en su entrada dibujada (ver `kinematika assemblies`)
assemblies-too-many = { $dyads } díadas cierran de dos maneras cada una: listar 2^{ $dyads } montajes supera el límite de 2^{ $limit }
sweep-by-varied = la longitud del barrido ({ $by }) depende de un parámetro variado: dala como número (--by)
move-not-number = { $problem } (un movimiento es un número de grados o de longitudes)
move-not-finite = un movimiento es un número finito
move-not-driven = el par '{ $joint }' no es de entrada; `move` avanza un par de entrada ({ $count ->
        [0] aquí no hay ninguno
       *[other] { $driven }
    })
move-unreachable = { $joint } no se puede mover { $amount }{ $unit }: el mecanismo llega a un punto muerto o se desmonta tras { $got }{ $unit }
sweep-by-needed = el par '{ $joint }' es `{ $kind }`: da la longitud del barrido (`by` en la sección sweep del modelo, o --by)
steps-whole = steps tiene que ser un número entero, y hay { $got }
steps-range = steps tiene que estar entre 1 y { $limit }, y hay { $got }
steps-too-many-values = { $steps } pasos de { $per_row } valores cada uno superan lo que cabe en un barrido ({ $limit } valores): da como mucho { $most } pasos
by-number = by tiene que ser un número, y hay { $got }
by-finite = by tiene que ser un número finito
sweep-no-driven-joint = no hay ningún par de entrada que barrer: impón la velocidad de un par, o la omega o la velocidad de un sólido unido al fijo por un par de rotación o prismático
sweep-not-driven = el par '{ $joint }' no es de entrada; un barrido avanza un par de entrada: { $driven }
fixture-shape = la posición de { $shape }
fixture-joint = la dirección del par { $joint }
move-symbolic-3d = un modelo 3D con parámetros simbólicos no se puede mover: da valores a sus parámetros (--set NAME=VALUE)
move-symbolic-once = un modelo con parámetros simbólicos se mueve una sola vez: da todos sus movimientos juntos
move-same-body = dos movimientos giran el mismo sólido: dale un solo movimiento
move-not-input = el par '{ $joint }' no une un sólido al fijo: mueve un modelo con parámetros simbólicos por su par de entrada
move-at-values = no se puede mover: con valores de los símbolos en los que el modelo se cumple ({ $values }), { $problem }
move-exact-numbers = no se puede mover exactamente: el punto '{ $point }' sigue la entrada con números, no con sus coordenadas exactas (da valores a los parámetros)
move-exact-rolls = no se puede mover exactamente: el punto '{ $point }' está en '{ $body }', que rueda sobre una recta: su giro es el camino de su centro entre su radio, sin forma cerrada aquí (da valores a los parámetros)
move-exact-no-form = no se puede mover exactamente: el punto '{ $point }' no sigue la entrada: ninguna construcción, relación de rodadura ni otro sólido da la posición de '{ $body }' en forma cerrada; escribe { $point } por construcción (o da valores)
move-exact-constructed = no se puede mover exactamente: el punto '{ $point }' no sigue la entrada: está construido con puntos que no se mueven con { $body }; constrúyelo con esos (o da valores)
move-exact-fixture = no se puede mover exactamente: '{ $body }' gira sin forma cerrada aquí, y { $what } está escrita con números; dala con puntos (o da valores a los parámetros)
body-no-point = el sólido '{ $body }' no lleva ningún punto, así que sus formas no se pueden mover: añade uno de sus puntos
cannot-assemble-there = el mecanismo no se puede montar ahí
sweep-at = el incremento { $k } ({ $joint } = { $value } { $unit })
sweep-drivers-contradict = los datos de movimiento tal como están escritos contradicen los pares en { $at }: un dato vectorial (ω en 3D, una velocidad) queda fijo en los ejes del fijo mientras el mecanismo gira; impón en su lugar la velocidad del par
sweep-singular = la configuración en { $at } es singular para los datos de movimiento (un punto muerto: número de condición mayor que 1e+10){ $said ->
        [true] {" "}({ $what })
       *[other] {""}
    }; usa --skip-bad para saltar esas posiciones
sweep-cannot-assemble = el mecanismo no se puede montar en { $at }{ $said ->
        [true] : { $what } no puede cerrar el lazo
       *[other] {""}
    }; usa --skip-bad para saltar esas posiciones

## estudios y síntesis (explore/*.py)
metrics-once = cada métrica una vez, y ninguna con el nombre de un parámetro ni 'assembles'/'reason'
study-needs-numbers = un estudio necesita números: da un valor a { $names } o hazlo variar
vary-form = --vary espera NAME=LOW:HIGH (como a=1:5), y hay { $got }
vary-interval = --vary { $name }: el intervalo tiene que ser finito con LOW <= HIGH, y hay { $got }
vary-none = nombra al menos un parámetro que variar (--vary NAME=LOW:HIGH)
varied-twice = un parámetro se varía dos veces: { $names }
grid-or-samples = da --grid N o --samples N
grid-positive = --grid y --samples toman un número positivo
designs-too-many = { $count } diseños: como mucho { $limit }
motion-error-two-points = motion_error: el sólido '{ $body }' necesita dos puntos para tener orientación
metric-unknown = métrica desconocida '{ $metric }'; métricas: grashof, transmission, dead_points, time_ratio[:BODY], range:BODY, peak_omega:BODY, peak_alpha:BODY, peak_speed:POINT, peak_accel:POINT, path_error:POINT=FILE.csv, motion_error:POINT=FILE.csv, structural_error:BODY=FILE.csv, angle|omega|alpha:BODY=X, speed|accel|x|y:POINT=X
grashof-four-bar = grashof necesita un modelo cuyo lazo móvil sea un cuadrilátero articulado movido por su manivela
time-ratio-linkage = time_ratio sin sólido necesita un cuadrilátero articulado o un biela-manivela; nombra la salida (time_ratio:BODY)
transmission-linkage = transmission necesita un cuadrilátero articulado o un biela-manivela movido por su manivela
metric-at-input = { $metric }=X toma la posición X de la entrada (un número, en { $unit } desde la posición dibujada), y hay { $got }
input-outside-sweep = la entrada tiene que estar en el rango del barrido, de { $low } a { $high } { $unit }
time-ratio-full-turn = time_ratio necesita el barrido de una vuelta completa de la manivela (by: 360)
target-csv = { $name }: un archivo de objetivos es un archivo .csv
table-not-numbers = { $name }, línea { $line }: se esperaban números, y hay { $got }
table-columns = { $name }, línea { $line }: se esperaban { $columns } números finitos
table-empty = { $name } no tiene filas de números
cannot-write = no se puede escribir { $path }: { $reason }
cannot-read = no se puede leer { $path }: { $reason }
study-no-column = el estudio no tiene la columna '{ $name }' (columnas: { $columns })
study-worker-died = un proceso del estudio terminó de golpe (¿sin memoria?): prueba con menos --workers o un --chunk más pequeño
dask-unreachable = no se llega al planificador de Dask en { $scheduler }: { $reason }
study-interrupted = { $folder } contiene un estudio interrumpido: añade --resume para continuarlo, o borra esa carpeta para empezar de nuevo
study-different = { $folder } contiene otro estudio (otro modelo, parámetros, diseños o métricas): bórrala para empezar de nuevo
study-output = la salida es un archivo .parquet o .csv, y hay { $name }
study-stopped = { $problem }{ $note }
study-kept = ; se guardan { $kept } diseños en { $folder }: ejecuta de nuevo con --resume para seguir
study-needs-model = un estudio necesita un archivo de modelo o el texto de un modelo
function-unknown-name = en { $source }: nombre desconocido '{ $name }' (la función es de x, el incremento de la entrada)
function-not-finite = { $source } no es finito entre { $low } y { $high }

## ejercicios (exercise/*.py)
variant-missing = no hay variante { $number } (variantes de 1 a { $count })
vary-unknown-parameter = --vary { $name }: parámetro desconocido (parámetros: { $parameters })
vary-none-step = nombra al menos un parámetro que variar (--vary NAME=LOW:HIGH[:STEP])
exercise-needs-numbers = un ejercicio necesita números: da un valor a cada parámetro simbólico (o hazlo variar)
exercise-no-model = exercise.json no nombra el archivo del modelo
exercise-lacks = a exercise.json le falta vary, seed o lang
exercise-cannot-read = no se puede leer { $path }: { $reason } (¿es una carpeta que escribió `kinematika exercise`?)
file-not-json = { $name } no es JSON: { $problem }
file-not-json-object = { $name } no es un objeto JSON
csv-not-utf8 = { $name } no es texto UTF-8
csv-no-column = { $name } no tiene la columna '{ $column }' (su cabecera: { $count ->
        [0] ninguna
       *[other] { $header }
    })
variants-numbered = las variantes se numeran 1, 2, … con un valor de cada parámetro variado
variants-none = no hay variantes
key-mismatch = key.csv no coincide con el modelo resuelto de nuevo (variante { $variant }, { $question }): ¿se editó el modelo o la clave de respuestas?
question-not-asked = '{ $question }' no se pregunta en la variante { $variant } (sus preguntas: { $asked })
row-no-student = una fila sin estudiante
variant-not-number = la variante { $got } no es un número
answered-twice = { $student } responde dos veces { $question } de la variante { $variant } (la primera vez en la línea { $first })
statement-missing = la sección del ejercicio no tiene enunciado en '{ $lang }' (lo tiene en { $langs })
vary-step-form = --vary espera NAME=LOW:HIGH[:STEP] (como s=300:500:10), y hay { $got }
vary-step-interval = --vary { $name }: da LOW <= HIGH y un STEP positivo, y hay { $got }
vary-grid-large = --vary { $name }: { $count } valores en la rejilla, como mucho { $limit }: toma un paso mayor
count-range = --count admite de 1 a { $limit } variantes, y hay { $got }
grids-too-small = las rejillas dan { $total } variantes distintas, menos que --count { $count }: amplía un intervalo o toma pasos más pequeños
variants-few = solo se han hallado { $found } de { $count } variantes entre { $drawn } sorteadas: { $apart } no se montan, { $dead } están cerca de un punto muerto, { $close } no distinguen un error habitual de la respuesta correcta; cambia los intervalos
weights-count = da un peso por cada pregunta calificada: { $count }, y hay { $got }
weight-positive = un peso es un número positivo, y hay { $got }
reveal-after-check = la resolución paso a paso se muestra después de comprobar: envía las respuestas con la petición
students-first-column = { $name }: la primera columna debe contener los identificadores de los estudiantes
student-twice = el estudiante { $student } aparece dos veces en la lista (líneas { $first } y { $line })
student-variant-range = la variante { $got } no está entre 1 y { $count }
table-unreadable = no se puede leer { $path }: { $reason }
table-empty = { $name } está vacío (una cabecera y luego una fila por línea)
table-no-column = { $name } no tiene la columna '{ $column }' (su cabecera: { $header }; columnas: { $columns })
row-fields = { $count } campos, pero la cabecera tiene { $header } (un valor con una coma va entre comillas)
row-not-read = { $place }: no leída: { $error }
students-unknown = no están en la lista de la clase (se dejan fuera): { $students }
grade-column = { $column ->
        [question] pregunta
        [answers] respuestas
        [right] correctas
        [carried] derivadas
        [mistakes] errores
        [student] estudiante
        [variant] variante
       *[score] nota
    }
grade-score = { $score } %
exercise-not-drawn-rounding = descartada: { $data }: redondear los datos a 3 cifras cambia { $question } un { $gap } %
exercise-not-drawn-mistake = descartada: { $data }: el error { $kind } da { $question } a menos del { $gap } % de la respuesta correcta
exercise-narrowed = variante { $number }: el margen de { $question } se estrecha al { $tolerance } % para distinguir el error { $kind } (que se aparta un { $gap } %)
exercise-wrote = { $count } { $count ->
        [one] variante escrita
       *[other] variantes escritas
    } en { $folder }
exercise-progress = figuras y resoluciones paso a paso: { $done }/{ $total }
pdf-skipped = no se genera el PDF: { $program } no está instalado ({ $hint })

## figuras y explicaciones (draw/*.py, explain/*.py, web/strings.py)
animate-planar = animate dibuja modelos planos; dibuja el instante de un modelo 3D con `kinematika draw`
ffmpeg-missing = escribir .mp4 necesita el programa ffmpeg, que no está instalado (en Debian o Ubuntu: apt install ffmpeg; con conda: conda install ffmpeg); o escribe un .gif, que no necesita nada más
sweep-none-assembled = no se pudo montar ninguna posición del barrido
trace-unknown-point = punto desconocido '{ $point }' para trazar
plot-format = no se puede dibujar en '{ $name }': da un archivo .png, .svg o .pdf
draw-at-not-real = el modelo no se puede dibujar con estos valores: el punto { $point } no es real ahí
unknown-format = formato desconocido '{ $format }' (formatos: { $formats })
catalogue-no-message = no hay mensaje '{ $key }' en el catálogo '{ $lang }'
catalogue-message-error = mensaje '{ $key }' del catálogo '{ $lang }': { $problem }
page-message-error = mensaje de la página '{ $key }' ({ $lang }): { $problem }

## la línea de órdenes (cli/*.py)
out-of-memory = el trabajo necesita más memoria de la que da esta máquina; haz más pequeño el modelo o el barrido
internal-error = error interno ({ $detail }); vuelve a ejecutar con KINEMATIKA_DEBUG=1 e infórmalo
no-folder = no existe la carpeta { $folder }
it-is-a-folder = es una carpeta
it-is-a-file = es un archivo
the-output-file = el archivo de salida
students-none = { $name } no nombra estudiantes (una cabecera y luego uno por fila)
synthesis-one-target = da uno de --target (trayectoria), --target-function (función) o --target-motion (movimiento)
function-needs-output = la generación de funciones necesita --output BODY
path-needs-point = la generación de trayectorias y de movimiento necesita --point P
map-or-pareto = da --map X,Y,METRIC o --pareto M1,M2
option-names-count = { $option } toma { $count } nombres separados por comas
study-unreadable = no se puede leer el estudio { $path }: { $reason }
option-name-value = { $option } espera NAME=VALUE, y hay { $got }
cannot-serve = no se puede servir en { $address }: { $reason }
format-needs-output = --format { $format } necesita -o FILE, el archivo que escribir
sweep-format = { $got } no es un formato de barrido: da --format { $formats } o un archivo que termine en uno de ellos

## la página y su API (web/*.py)
build-op = 'op' es un objeto cuya 'op' es una de { $actions }
tool-picks = la herramienta `{ $tool }` toma { $count } clics ({ $picks })
build-path = 'path' es una lista de claves e índices
build-value = 'value' es un número o una expresión
build-value-empty = 'value' está vacío
build-value-finite = 'value' no es un número finito
build-nothing-at = no hay nada en { $path } en el modelo
delete-missing = no hay { $element } que borrar
delete-what = { $element }: borra point:NAME, body:NAME, joint:ID, driver:N o ask:N
delete-no-point = no hay punto '{ $point }' que borrar
delete-no-body = no hay sólido '{ $body }' que borrar (el fijo se queda)
driver-value = el valor de un dato de movimiento es un número o una expresión
input-body-or-joint = la entrada es un sólido móvil o un par del modelo
question-kind = { $question }: una pregunta es una de { $kinds }
question-target = 'target' nombra el punto o el sólido por el que se pregunta
target-not-moving = { $target } no está en ningún sólido móvil
format-one-of = { $format }: un formato es uno de { $formats }
toml-null = { $place } es null, que TOML no puede escribir (un parámetro simbólico): deja este modelo en YAML o JSON
the-model = el modelo
drag-constructed = { $point } está construido: arrástralo en un modelo YAML o JSON, o edita su construcción
no-point-in-model = no hay punto '{ $point }' en el modelo
drag-not-planar = { $point } no es un punto plano con dos coordenadas
drag-formula = { $point } está situado por la fórmula { $formula }: cambia sus parámetros para moverlo
drag-lines-meet = { $point } es el corte de dos rectas: arrastra los puntos por los que pasan
model-unreadable = el modelo no se puede leer: { $problem }
drag-toml-form = el punto '{ $point }' no está escrito como `{ $point } = [x, y]` en la tabla [points]
request-vary = 'vary' es una lista de textos NAME=LOW:HIGH[:STEP]
request-answers = 'answers' asocia identificadores de pregunta (q2.y) a los números escritos
request-reveal = 'reveal' es true o false
request-whole-range = '{ $key }' es un número entero, de { $low } a { $high }
request-whole-least = '{ $key }' es un número entero, como mínimo { $low }
request-one-variant = sin 'vary' el ejercicio tiene una sola variante, los datos del modelo
help-no-document = no hay documento '{ $name }' (la ayuda sirve docs/*.md)
no-free-point-name = no queda ningún nombre de punto libre
not-finite-number = { $value } no es un número finito
pick-no-point = todavía no hay ningún punto '{ $point }'
link-two-points = una barra une dos puntos distintos
link-length = una barra necesita longitud: pon su extremo en otro sitio
point-two-conditions = { $point } ya está situado por dos condiciones: borra antes una de sus barras
slot-own-points = la ranura pasa por dos puntos de { $body }: elige otro sólido u otro pasador
plate-two-points = { $body } necesita dos puntos antes de fijarle un tercero
track-once = el fijo ya tiene una pista: una sola pista recta por modelo
wheel-centre = pon el centro de la rueda lejos de su punto de contacto
gear-centre = pon el centro del segundo engranaje lejos del primero
no-body = no hay sólido '{ $body }'
slot-outline-once = { $body } ya tiene un contorno: una sola ranura por sólido
pin-other-body = el pasador { $pin } no está en ningún sólido distinto de { $body }: elige un pasador de otro sólido
slot-centre-pin = el centro de la ranura no puede ser el pasador
contact-two-bodies = un contacto une dos sólidos distintos
contact-no-outline = { $body } no tiene contorno (una circunferencia, una recta, una curva, una leva) con el que tocar: escribe antes su forma en el texto
tool-unknown = herramienta desconocida '{ $tool }' (la paleta tiene { $tools })
request-not-json = la petición no es JSON: { $problem }
request-object = la petición es un objeto JSON con al menos la clave 'model'
request-unknown-key = clave desconocida '{ $key }' para /api/{ $endpoint } (admitidas: { $accepted })
request-model = 'model' es obligatorio: el texto del archivo del modelo
request-points = 'points' es una lista de nombres de puntos
request-width = 'width' es el ancho de la figura en pulgadas, de 1 a 100
request-frame = 'frame' es la caja que muestra la figura, [x0, y0, x1, y1] con x0 < x1 e y0 < y1
request-op = 'op' es la acción: un objeto con su clave 'op'
request-to = 'to' es la nueva posición del punto [x, y]
request-point = 'point' nombra el punto que mover
request-choice = { $value }: { $key } es uno de { $choices }
request-flag = '{ $key }' es true, false o null
request-text = '{ $key }' es un texto
request-number = '{ $key }' es un número
request-assignments = '{ $key }' asocia nombres a números o expresiones
request-assignment = { $key }: un número o una expresión
no-example = no hay ningún ejemplo incluido '{ $name }'
server-busy = el servidor está ocupado: inténtalo de nuevo en un momento
server-timeout = el cálculo tardó más de { $seconds } s y se abandonó
no-template = no hay plantilla '{ $name }'
request-content-type = envía la petición como JSON (Content-Type: application/json)
request-too-large = la petición es demasiado grande ({ $size } bytes; como mucho { $limit })
internal-error-page = error interno ({ $detail }); por favor, infórmalo

## las líneas que escribe la línea de órdenes (cli/__init__.py, cli/shared.py)
error-line = error ({ $kind }): { $text }
internal-line = error: { $text }
warning-line = aviso: { $text }
usage-line = error (usage): { $text } (ver { $command } --help)
aborted = interrumpido
click = { $code ->
        [NoSuchOption] no existe la opción { $name }{ $count ->
            [0] {""}
           *[other] {" "}(¿quizá { $suggestions }?)
        }
        [MissingParameter] falta { $name }
        [BadParameter] { $name } no admite ese valor
        [BadOptionUsage] { $name } necesita un valor
        [ExtraArgument] sobran argumentos
        [NoSuchCommand] no existe la orden '{ $name }'
       *[other] { $text }
    }
serving-open = sirviendo en { $host }: cualquiera que llegue a esta máquina por el puerto { $port } puede usar la página (no lee ningún archivo, pero calcula para ellos)

## limit positions and rows of a sweep (sweep/limit_positions.py, sweep/continuation.py, sweep/move.py)
sweep-too-many-limits = el movimiento pasa por más de { $limit } posiciones límite; haz un barrido de un recorrido más corto
sweep-not-followed = no se puede seguir el movimiento más allá de { $joint } = { $value } { $unit } (tras un recorrido de { $travel } { $unit }): { $why }
follow-turns-back = vuelve atrás de inmediato: ahí se encuentran ramas del movimiento
follow-cannot-close = { $bodies } no puede cerrar ahí, y no es una posición límite
follow-not-corrected = la curva no se ha podido corregir ahí
follow-starts-at-limit = empieza en una posición límite
follow-branches-meet = ahí se encuentran ramas del movimiento
follow-runs-off = el mecanismo se va al infinito ahí
follow-too-many-steps = más de { $limit } pasos de continuación entre dos filas
follow-not-assembled = el mecanismo no se ha podido montar ahí
follow-stuck = el mecanismo no se puede montar un paso más allá, y no es una posición límite
row-needs-numbers = una fila del barrido necesita números para todos los parámetros
row-out-of-range = fila { $row }: el barrido tiene las filas 0 a { $last }
row-cannot-assemble = la fila { $row } del barrido no se puede montar

## renaming on the page (web/rename.py)
rename-not-a-name = '{ $name }' no es un nombre: una letra, y luego letras, cifras o _
rename-element = '{ $element }': renombra body:NOMBRE o point:NOMBRE
rename-language = '{ $lang }': el idioma es uno de { $langs }
rename-nothing = no hay ningún '{ $element }' que nombrar
rename-no-body = no hay ningún sólido '{ $name }' que renombrar
rename-body-exists = ya hay un sólido '{ $name }'
rename-no-point = no hay ningún punto '{ $name }' que renombrar
rename-point-exists = ya hay un punto '{ $name }'

## the model's notation of indices and spins (model/wording.py)
index-twice = los sólidos '{ $first }' y '{ $second }' se escribirían ambos '{ $index }'
spin-not-wheel = el par '{ $joint }' no es una rueda: solo una rueda tiene velocidad de giro propia
spin-shape = un giro propio se escribe {"{"}symbol: NOMBRE, radius: PARÁMETRO{"}"} (symbol: phidot, radius: r)
spin-radius-unknown = el radio '{ $radius }' no es un parámetro (parámetros: { $parameters })
index-shape = '{ $index }' no es un índice de sólido: de una a cuatro letras o cifras (N, 1, R, T)
contact-name-shape = '{ $index }' no es un nombre de punto de contacto: de una a cuatro letras o cifras (F, J, K2)

## symbols at their draw_at numbers, travel, straight outlines (sweep/posing.py, sweep/plan.py, joints/touching.py)
needs-draw-at = { $what ->
        [move] un movimiento
        [simulate] una simulación
       *[sweep] un barrido
    } necesita números: da un valor a { $names }, o al modelo un número `draw_at` para cada símbolo
at-draw-numbers = { $what ->
        [move] movido
       *[sweep] barrido
    } con los números draw_at de sus símbolos: { $values }{ $said ->
        [true] {" "}({ $why })
       *[other] {""}
    }
travel-too-far = { $what } { $amount } es más de lo que recorre un barrido o un movimiento: como mucho { $most }{ $unit ->
        [angle] ° ({ $turns } vueltas)
       *[length] {" "}({ $turns } veces el tamaño del mecanismo)
    }
two-straights-touch = dos contornos rectos se tocan a lo largo de una recta, no en un punto: únelos con un par prismático

## synthesis: its task, its target file, its four-bar (explore/synthesis/*.py, cli/explore.py)
synthesis-no-design = ningún diseño de los intervalos completa su ciclo{ $requirements ->
        [0] {""}
       *[other] {" "}y cumple los requisitos
    }
synthesis-no-full-turn = ningún diseño hallado completa una vuelta entera de su entrada
synthesis-nothing-found = ningún diseño dentro de los intervalos de --vary se puede montar en todos los objetivos{ $count ->
        [0] {""}
       *[other] {" "}y cumplir { $requirements }
    }; amplía los intervalos o busca durante más tiempo
require-crank-rocker-four-bar = `--require crank-rocker` necesita un cuadrilátero articulado movido por su manivela (una manivela y dos barras que cierran sobre el sólido fijo), con su punto en la biela
require-transmission-linkage = `--require transmission=DEG` necesita un cuadrilátero articulado o un biela-manivela movido por su manivela
require-transmission-angle = --require transmission=DEG: DEG es un ángulo entre 0 y 90 grados, y hay { $got }
requirement-unknown = requisito desconocido '{ $requirement }'; requisitos: { $requirements }
timing-needs-four-bar = --timing necesita un cuadrilátero articulado movido por su manivela, con el punto de la tarea en su biela (en otros modelos, deja libre la sincronización de los objetivos)
timing-form = --timing espera JOINT o JOINT=START, y hay { $got }
timing-start-number = --timing { $joint }=START: START tiene que ser un número, y hay { $got }
timing-start-finite = --timing { $joint }=START: START tiene que ser finito
objective-form = --objective es `sse` o `max`, y hay { $got }
output-zero-form = --output-zero es 'free' o un ángulo en grados, y hay { $got }
output-zero-function-only = --output-zero es solo para la generación de funciones (--target-function)
output-zero-needs-four-bar = --output-zero necesita un cuadrilátero articulado cuya salida sea su balancín o su biela
output-not-rocker-or-coupler = la salida '{ $output }' no es el balancín ({ $rocker }) ni la biela ({ $coupler }) del cuadrilátero articulado
body-needs-two-points = el sólido '{ $body }' necesita dos puntos para tener una dirección
targets-too-few = { $name }: { $count } { $count ->
        [one] objetivo
       *[other] objetivos
    }; la síntesis necesita al menos { $least }
target-columns-count = { $name }: { $count } { $count ->
        [one] columna
       *[other] columnas
    }; esta tarea lee { $reads }
target-column-unread = { $name }: esta tarea no lee la columna '{ $column }'{ $timing ->
        [true] {" "}(da --timing JOINT para usarla)
       *[other] {""}
    }; lee { $reads }
target-column-missing = { $name }: no hay ninguna columna '{ $column }' (esta tarea lee { $reads })
target-header-twice = { $name }, línea { $line }: cada columna se nombra una sola vez
target-row-width = { $name }, línea { $line }: { $count } valores donde el archivo tiene { $columns } columnas
target-not-finite = { $name }, línea { $line }: se esperaban números finitos
target-weight-positive = { $name }, línea { $line }: un peso tiene que ser positivo
target-first-input = { $name }, línea { $line }: la entrada del primer objetivo es 0 (las entradas se cuentan desde el primer objetivo)
target-inputs-increase = { $name }, línea { $line }: los valores de la columna '{ $column }' tienen que crecer ({ $before } y luego { $after })
## motion in time (simulate/)
simulate-time-not-evaluated = no se puede evaluar el tiempo de la simulación: { $problem }
simulate-time-missing = cuánto tiempo seguir el movimiento: da --time SEGUNDOS (o una sección `simulate: {"{"}time: ...{"}"}` en el modelo)
simulate-time-positive = el tiempo tiene que ser un número positivo de segundos, y hay { $got }
simulate-steps-too-many = { $steps } pasos de { $per_row } valores cada uno superan lo que cabe en una simulación ({ $limit } valores): da como mucho { $most } pasos
simulate-time-too-short = el tiempo { $time } s es demasiado corto para seguir el movimiento desde t = { $start } s
simulate-time-needs-value = el tiempo t necesita un valor: el tiempo de la configuración dibujada (normalmente 0)
simulate-time-only-in-rates = el tiempo t solo puede aparecer en las velocidades impuestas por los datos de movimiento (una velocidad que cambia en el tiempo); aquí movería el mecanismo por sí solo
simulate-unknown-method = método desconocido '{ $method }' (los métodos de scipy.integrate.solve_ivp: { $methods })
simulate-at = en t = { $at } s: { $what }
simulate-rate-not-taken = no se puede tomar la derivada en el tiempo de la velocidad impuesta: { $problem }
simulate-rate-not-evaluated = no se puede evaluar la derivada en el tiempo de la velocidad impuesta ({ $problem })
simulate-rate-not-real = la derivada en el tiempo de la velocidad impuesta no es un número real finito (¿la raíz cuadrada de un número negativo?)
simulate-rate-not-finite = la derivada en el tiempo de la velocidad impuesta no es finita (¿una raíz cuadrada o un logaritmo en cero?)
simulate-velocity-matrix = no se pueden resolver las ecuaciones de velocidad (su matriz no está hecha de números finitos)
simulate-too-many-evaluations = el movimiento necesita más de { $limit } soluciones de velocidad para seguirse (limits.SIMULATE_EVALUATIONS): es demasiado rígido (una parte se asienta mucho más deprisa de lo que se mueve el resto) o está demasiado cerca de una configuración singular
simulate-dead-point = el movimiento llega a un punto muerto en t = { $at } s: más allá no se pueden hallar las velocidades (el número de condición del jacobiano de restricciones llega a { $condition })
simulate-not-followed = no se puede seguir el movimiento más allá de t = { $at } s: { $why }
simulate-integrator-stopped = el integrador se ha detenido ({ $message })
simulate-positions-not-finite = las posiciones integradas no son números finitos
simulate-projection-fails = las posiciones integradas no se pueden devolver a las condiciones de posición de los pares (el movimiento ha salido de lo que permiten)
simulate-velocity-only = una simulación no puede seguir un par `{ $kind }`{ $dim ->
        [3] {" "}en 3D
       *[other] {""}
    }: su condición es solo de velocidades, así que las posiciones dependen del camino recorrido
animation-file-type = no se puede escribir { $name }: da un archivo .gif o .mp4

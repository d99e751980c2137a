# Las palabras que una figura escribe por sí misma (kinematika draw --lang).
legend-velocity = velocidad
legend-acceleration = aceleración
legend-centre = CIR (centro instantáneo de rotación)
legend-kennedy = recta de Aronhold–Kennedy
legend-normal = normal a una rueda o ranura
legend-pole = polo de aceleraciones
legend-curvature = círculo de curvatura
note-at-infinity = { $labels } en el infinito, dirección { $direction }
note-no-relative-motion = { $count ->
    [one] { $labels }: sin movimiento relativo
   *[other] sin movimiento relativo: { $labels }
}
note-enlarged = las flechas están a escala dentro de cada tipo (la más larga mide el { $longest } del dibujo); las marcadas «ampliada» se dibujan con la longitud mínima ({ $shortest })
note-3d = modelo 3D: proyección ortográfica { $view }{ $up ->
    [none] {""}
   *[other] , { $up } hacia arriba
} (ejes x, y, z abajo a la derecha)
view-iso = isométrica
note-bodies = sólidos: { $bodies }
note-drawn-at-given = modelo simbólico dibujado con { $values } (sus valores draw_at)
note-drawn-at-some = modelo simbólico dibujado con { $values } (valores draw_at y genéricos para el resto)
note-drawn-at-generic = modelo simbólico dibujado con valores genéricos { $values } (draw_at del modelo los fija)
note-curvature-rest = { $label } está en reposo: su trayectoria no tiene curvatura
note-curvature-straight = { $label }: la trayectoria es recta aquí (radio infinito)
label-far-off = { $label } en { $place }
label-at-infinity = { $label } en el ∞
label-curvature-centre = { $label }, centro { $place }

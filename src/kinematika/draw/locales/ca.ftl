# Les paraules que una figura escriu per si mateixa (kinematika draw --lang).
legend-velocity = velocitat
legend-acceleration = acceleració
legend-centre = CIR (centre instantani de rotació)
legend-kennedy = recta d’Aronhold–Kennedy
legend-normal = normal a una roda o ranura
legend-pole = pol d’acceleracions
legend-curvature = cercle de curvatura
note-at-infinity = { $labels } a l’infinit, direcció { $direction }
note-no-relative-motion = { $count ->
    [one] { $labels }: sense moviment relatiu
   *[other] sense moviment relatiu: { $labels }
}
note-enlarged = les fletxes són a escala dins de cada tipus (la més llarga fa el { $longest } del dibuix); les marcades «ampliada» es dibuixen amb la longitud mínima ({ $shortest })
note-3d = model 3D: projecció ortogràfica { $view }{ $up ->
    [none] {""}
   *[other] , { $up } cap amunt
} (eixos x, y, z a baix a la dreta)
view-iso = isomètrica
note-bodies = sòlids: { $bodies }
note-drawn-at-given = model simbòlic dibuixat amb { $values } (els seus valors draw_at)
note-drawn-at-some = model simbòlic dibuixat amb { $values } (valors draw_at i genèrics per a la resta)
note-drawn-at-generic = model simbòlic dibuixat amb valors genèrics { $values } (draw_at del model els fixa)
note-curvature-rest = { $label } és en repòs: la seva trajectòria no té curvatura
note-curvature-straight = { $label }: la trajectòria és recta aquí (radi infinit)
label-far-off = { $label } a { $place }
label-at-infinity = { $label } a l’∞
label-curvature-centre = { $label }, centre { $place }

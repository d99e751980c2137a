# Irudi batek berak idazten dituen hitzak (kinematika draw --lang).
legend-velocity = abiadura
legend-acceleration = azelerazioa
legend-centre = biraketa-zentro instantaneoa
legend-kennedy = Aronhold–Kennedyren zuzena
legend-normal = gurpil edo zirrikitu baten normala
legend-pole = azelerazioen poloa
legend-curvature = kurbadura-zirkulua
note-at-infinity = { $labels } infinituan, norabidea { $direction }
note-no-relative-motion = { $count ->
    [one] { $labels }: mugimendu erlatiborik ez
   *[other] mugimendu erlatiborik ez: { $labels }
}
note-enlarged = geziak eskalan daude mota bakoitzaren barruan (luzeena marrazkiaren { $longest } da); «handitua» markatutakoak gutxieneko luzeran marraztuta daude ({ $shortest })
note-3d = 3D eredua: proiekzio ortografiko { $view }{ $up ->
    [none] {""}
   *[other] , { $up } gora
} (x, y, z ardatzak behean eskuinean)
view-iso = isometrikoa
note-bodies = solidoak: { $bodies }
note-drawn-at-given = eredu sinbolikoa { $values } balioetan marraztua (bere draw_at balioak)
note-drawn-at-some = eredu sinbolikoa { $values } balioetan marraztua (draw_at balioak, eta orokorrak gainerakoentzat)
note-drawn-at-generic = eredu sinbolikoa { $values } balio orokorretan marraztua (ereduaren draw_at-ek finkatzen ditu)
note-curvature-rest = { $label } geldi dago: haren ibilbideak ez du kurbadurarik
note-curvature-straight = { $label }: ibilbidea zuzena da hemen (erradio infinitua)
label-far-off = { $label } { $place } puntuan
label-at-infinity = { $label } infinituan
label-curvature-centre = { $label }, zentroa { $place }

# Studies of the level-set transport behind doc/validation.md ("Transport,
# back at the start"): convergence in h of the volume and shape errors.
# Label validation-long, not in CI; each writes the CSV named by --csv.
add_test(NAME study_rotation_2d COMMAND ${VALIDATE} transport
  ${SCENES}/rotation_2d.prm 4,5,6,7 --csv rotation_2d.csv)
add_test(NAME study_zalesak_2d COMMAND ${VALIDATE} transport
  ${SCENES}/zalesak_2d.prm 4,5,6,7 --csv zalesak_2d.csv)
# The same rotation with the filter thickness fixed at 0.094 (6 h at
# level 4) instead of 6 h at every level: convergence at a fixed physical
# filter.
add_test(NAME study_rotation_fixed_filter_2d COMMAND ${VALIDATE} transport
  ${SCENES}/rotation_2d.prm 4,5,6 --filter-thickness 0.09375
  --band-width 0.0625 --csv rotation_2d_fixed_filter.csv)
add_test(NAME study_translation_2d COMMAND ${VALIDATE} transport
  ${SCENES}/translation_2d.prm 4,5,6,7 --csv translation_2d.csv)
add_test(NAME study_rotation_3d COMMAND ${VALIDATE} transport
  ${SCENES}/rotation_3d.prm 3,4,5 --csv rotation_3d.csv)
set_tests_properties(study_rotation_2d study_zalesak_2d study_translation_2d
  study_rotation_fixed_filter_2d study_rotation_3d
  PROPERTIES LABELS validation-long)

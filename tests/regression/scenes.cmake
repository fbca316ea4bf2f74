# Every shipped scene passes its own --check as shipped (issue 13, item 8): one test per inputs/*.yaml, globbed, so
# a new scene is covered without editing this file. Each runs at the scene's own settings (mesh, end time, order,
# output) with --check (continuum: conservation, the force balance, the scene's `exact:` bounds; tube: the scene's
# own checks) and writes into the test work folder, not into inputs/. Exit 0 passes; a failed bound exits 3.
# Scenes are kept cheap enough for this (about a minute at most on one core; see each scene's comment). Measured on
# the 2-core CI box, one thread: see the commit that added this file for the per-scene times.
file(GLOB SHIPPED_SCENES CONFIGURE_DEPENDS ${INPUTS}/*.yaml)
foreach(scene IN LISTS SHIPPED_SCENES)
  get_filename_component(name ${scene} NAME_WE)
  add_test(NAME scene_${name} COMMAND ${UNILAG} run ${scene} --quiet --check --output ${WORK}/scene_${name})
  set_tests_properties(scene_${name} PROPERTIES LABELS "regression;scenes")
endforeach()

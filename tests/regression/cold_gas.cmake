# Cold gas (issue 13 item 6, docs/cold-gas.md): 2D Sedov with the ambient pressure 0 (inputs/sedov2d_cold.yaml).
# Before the nodal solver's Dukowicz impedance rho (a_eff + Gamma_D |dv|) it stopped at t = 0 (z = rho a = 0,
# specific internal energy NaN). Each run must reach t = 1 with --check (conservation and node balance to
# round-off), every field finite, p and eps >= 0, and L1(density) within its bounds (tests/scripts/cold_gas.py),
# first order:
#  - 4k triangles: measured 0.05428 in 373 steps (the p = 1e-6 scene gives 0.05428 too), bound 0.060 (1.1x);
#  - 1k triangles: measured 0.1042 in 183 steps, bound 0.115 (1.1x).
# Second order (it stopped in the precursor ahead of the front, eps = E - v^2/2 = -7e-31 .. -5e-317, until the
# admissibility test took round-off for what it is: Material::epsRoundoff):
#  - 4k, the scene's scheme (the velocity alone reconstructed, vertex-based bounds): measured 0.03703 in 579 steps (p = 1e-6: 0.03702; with the
#    symmetry planes' mirrored stencil of session 13 0.03559 for both), bound 0.041
#    (1.1x; barth_jespersen, 0.04399, fails it); with node_fit bounds (the scene's since session 28) 0.03377 in
#    564 steps: bound 0.037 (1.1x; vertex_based fails it);
#  - 3D octant, 4.9k tetrahedra: measured 0.1481 in 230 steps (p = 1e-6: 0.1425), bound 0.163 (1.1x); with the
#    mirrored stencil 0.1321 in 245 steps (p = 1e-6: 0.1306); with node_fit, the default limiter since session 28,
#    0.1158 in 349 steps (p = 1e-6: 0.1152; barth_jespersen 0.1281): bound 0.127 (1.1x); on tetrahedra optimised
#    to gamma 0.6 (session 29) 0.1135 in 248 steps (p = 1e-6: 0.1118): bound 0.125 (1.1x).
# Session 36, the scene's lattice (mesh.mesher: lattice) with barth_jespersen at order 2 (docs/sedov-peak.md), bounds
# 1.1x the measured figures (p = 1e-6 gives the same to 4 digits): 4k 0.05648 in 365 steps, bound 0.062; 1k 0.1130
# in 182, bound 0.124; order 2 0.03770 in 546, bound 0.0415. The 3D octant's body-centred cubic lattice (6,144
# tetrahedra): order 2 0.1077 in 121 steps (p = 1e-6: 0.1078), bound 0.118.
# The lower bounds (0.5x) catch a run that is no longer the scene the bounds were set for.
set(COLD_CHECK ${PYTHON} ${SCRIPTS}/cold_gas.py)
add_test(NAME sedov2d_cold_run COMMAND ${UNILAG} run ${INPUTS}/sedov2d_cold.yaml --quiet --check
         --set output.interval=0 --output ${WORK}/sedov2d_cold)
add_test(NAME sedov2d_cold_check COMMAND ${COLD_CHECK} ${WORK}/sedov2d_cold 1.0 0.062 0.028)
add_test(NAME sedov2d_cold_1k_run COMMAND ${UNILAG} run ${INPUTS}/sedov2d_cold.yaml --quiet --check
         --set mesh.size=0.0577 --set output.interval=0 --output ${WORK}/sedov2d_cold_1k)
add_test(NAME sedov2d_cold_1k_check COMMAND ${COLD_CHECK} ${WORK}/sedov2d_cold_1k 1.0 0.124 0.056)
set_tests_properties(sedov2d_cold_run PROPERTIES FIXTURES_SETUP cold_4k LABELS "gpr;regression")
set_tests_properties(sedov2d_cold_check PROPERTIES FIXTURES_REQUIRED cold_4k LABELS "gpr;regression")
set_tests_properties(sedov2d_cold_1k_run PROPERTIES FIXTURES_SETUP cold_1k LABELS "gpr;regression")
set_tests_properties(sedov2d_cold_1k_check PROPERTIES FIXTURES_REQUIRED cold_1k LABELS "gpr;regression")
add_test(NAME sedov2d_cold_order2_run COMMAND ${UNILAG} run ${INPUTS}/sedov2d_cold.yaml --quiet --check
         --set scheme.order=2 --set output.interval=0 --output ${WORK}/sedov2d_cold_o2)
add_test(NAME sedov2d_cold_order2_check COMMAND ${COLD_CHECK} ${WORK}/sedov2d_cold_o2 1.0 0.0415 0.0189)
add_test(NAME sedov3d_cold_order2_run COMMAND ${UNILAG} run ${INPUTS}/sedov3d.yaml --quiet --check
         --set regions.gas.pressure=0.0 --set scheme.order=2 --set output.interval=0 --output ${WORK}/sedov3d_cold_o2)
add_test(NAME sedov3d_cold_order2_check COMMAND ${COLD_CHECK} ${WORK}/sedov3d_cold_o2 1.0 0.118 0.054)
# ARS(2,2,2) on the cold gas stopped at t = 0.139 (2D, 4k) and t = 0.0024 (3D): its final row weighs the t^n rates
# by beta - 1 < 0, and a cold cell the shock reaches within the step was left a negative energy at any dt
# (docs/ars222.md). Such a step is now taken by the midpoint scheme (summary.json midpoint_steps). Measured: 2D L1
# 0.03429 with 10 midpoint steps of 567 (midpoint alone 0.03377), 3D 0.1138 with 4 of 251 (0.1135); bounds 1.1x.
# --check passes (3D: once the node-balance floor excluded the precursor's 1e-97 forces, GprNodeBalance.hpp).
# Both on gmsh's meshes (2D frontal with node_fit; 3D at size 0.12), where these were measured: on the scenes'
# lattices 1 step of 544 (2D, L1 0.03823) and 2 of 121 (3D, 0.1076) need the midpoint scheme, too few to keep the
# test's lower bound on that count meaningful. Not the scenes' peak bound (exact.max_density=0): gmsh's meshes
# overshoot it beside the planes (docs/sedov-peak.md).
add_test(NAME sedov2d_cold_ars222_run COMMAND ${UNILAG} run ${INPUTS}/sedov2d_cold.yaml --quiet --check
         --set scheme.order=2 --set scheme.integrator=ars222 --set mesh.mesher=gmsh --set scheme.limiter=node_fit
         --set exact.max_density=0 --set output.interval=0 --output ${WORK}/sedov2d_cold_ars)
add_test(NAME sedov2d_cold_ars222_check COMMAND ${COLD_CHECK} ${WORK}/sedov2d_cold_ars 1.0 0.038 0.0185 30)
add_test(NAME sedov3d_cold_ars222_run COMMAND ${UNILAG} run ${INPUTS}/sedov3d.yaml --quiet --check
         --set regions.gas.pressure=0.0 --set scheme.order=2 --set scheme.integrator=ars222 --set output.interval=0
         --set mesh.mesher=gmsh --set mesh.size=0.12 --set exact.max_density=0 --output ${WORK}/sedov3d_cold_ars)
add_test(NAME sedov3d_cold_ars222_check COMMAND ${COLD_CHECK} ${WORK}/sedov3d_cold_ars 1.0 0.125 0.074 15)
set_tests_properties(sedov2d_cold_ars222_run PROPERTIES FIXTURES_SETUP cold_ars LABELS "gpr;regression")
set_tests_properties(sedov2d_cold_ars222_check PROPERTIES FIXTURES_REQUIRED cold_ars LABELS "gpr;regression")
set_tests_properties(sedov3d_cold_ars222_run PROPERTIES FIXTURES_SETUP cold3d_ars LABELS "gpr;regression")
set_tests_properties(sedov3d_cold_ars222_check PROPERTIES FIXTURES_REQUIRED cold3d_ars LABELS "gpr;regression")
set_tests_properties(sedov2d_cold_order2_run PROPERTIES FIXTURES_SETUP cold_o2 LABELS "gpr;regression")
set_tests_properties(sedov2d_cold_order2_check PROPERTIES FIXTURES_REQUIRED cold_o2 LABELS "gpr;regression")
set_tests_properties(sedov3d_cold_order2_run PROPERTIES FIXTURES_SETUP cold3d_o2 LABELS "gpr;regression")
set_tests_properties(sedov3d_cold_order2_check PROPERTIES FIXTURES_REQUIRED cold3d_o2 LABELS "gpr;regression")

# Noh's implosion (inputs/noh2d.yaml, p = 0, docs/cold-gas.md) at order 2 on 3.7k triangles: before the a posteriori
# first-order fallback it stopped at t = 0 (a cold cell's work on its nodes was negative with reconstructed corner
# velocities: eps = -1.8e-8 at every dt). Measured: L1 0.1430 (0.1430 with the lagged velocities of ars222 below),
# 155 (156) fallback marks, shock radius 0.2062; bound 1.1x.
# The first order's 0.1195 on the same mesh is the better figure (docs/cold-gas.md: streaks along the axes).
# With barth_jespersen (the default before session 28), whose marks the per-cell rounds mend; the default node_fit
# needs the whole-step round (noh2d_node_fit_* below) and scores 0.1659 / 0.1649 (ars222) here.
add_test(NAME noh2d_order2_run COMMAND ${UNILAG} run ${INPUTS}/noh2d.yaml --quiet --check --set scheme.order=2
         --set scheme.limiter=barth_jespersen --set mesh.size=0.03 --set output.interval=0 --output ${WORK}/noh2d_o2)
add_test(NAME noh2d_order2_check COMMAND ${COLD_CHECK} ${WORK}/noh2d_o2 0.6 0.158 0.072)
set_tests_properties(noh2d_order2_run PROPERTIES FIXTURES_SETUP noh_o2 LABELS "gpr;regression")
set_tests_properties(noh2d_order2_check PROPERTIES FIXTURES_REQUIRED noh_o2 LABELS "gpr;regression")

# With bounds that keep linear fields (node_fit, vertex_based) the first step failed cell by cell: each round's
# first-order cells changed their neighbours' node velocities, and after the 4 rounds Noh stopped at t = 0 (8.4k,
# node_fit: eps -3.9e-11 "after 8 halvings of dt"; 32 rounds were not enough either). Now a step that the rounds do
# not mend goes to first order as a whole before dt is halved. Measured (8.4k): L1 0.1454, 18,187 marks, shock
# radius 0.2032 (barth_jespersen 0.1316, 137 marks, unchanged; order 1 0.0938); bound 1.1x.
add_test(NAME noh2d_node_fit_run COMMAND ${UNILAG} run ${INPUTS}/noh2d.yaml --quiet --check --set scheme.order=2
         --set scheme.limiter=node_fit --set output.interval=0 --output ${WORK}/noh2d_nf)
add_test(NAME noh2d_node_fit_check COMMAND ${COLD_CHECK} ${WORK}/noh2d_nf 0.6 0.160 0.072)
set_tests_properties(noh2d_node_fit_run PROPERTIES FIXTURES_SETUP noh_nf LABELS "gpr;regression")
set_tests_properties(noh2d_node_fit_check PROPERTIES FIXTURES_REQUIRED noh_nf LABELS "gpr;regression")

# The same with ars222: it stopped at t = 0 ("went unstable ... after 8 halvings of dt", eps -7.5e-7 at 8.4k) while
# the first step's impedance lagged node velocities of zero, a shock term of |v| at t^n that stage 1 did not have
# (the final row weighs the rates at t^n by beta - 1 < 0); now the lagged velocities start from the mean of the
# cells around each node (meanCellVelocityAtNodes, docs/ars222.md). Measured: L1 0.1468, 166 marks; bound 1.1x.
add_test(NAME noh2d_ars222_run COMMAND ${UNILAG} run ${INPUTS}/noh2d.yaml --quiet --check --set scheme.order=2
         --set scheme.integrator=ars222 --set scheme.limiter=barth_jespersen --set mesh.size=0.03
         --set output.interval=0 --output ${WORK}/noh2d_ars)
add_test(NAME noh2d_ars222_check COMMAND ${COLD_CHECK} ${WORK}/noh2d_ars 0.6 0.162 0.072)
set_tests_properties(noh2d_ars222_run PROPERTIES FIXTURES_SETUP noh_ars LABELS "gpr;regression")
set_tests_properties(noh2d_ars222_check PROPERTIES FIXTURES_REQUIRED noh_ars LABELS "gpr;regression")

# A piston into a cold gas at rest (tests/scenes/piston_cold2d.yaml): the gas has no energy at t = 0, so the
# round-off floor of eps was 0 and ars222 stopped at step 26 (eps = -2.5e-71 in a precursor cell ahead of the shock);
# the floor now takes the piston's |v|^2 / 2 as its scale (setRoundoffFloor). Order 1, order 2 and ars222 must reach
# t = 0.5 with the exact shock (tests/scripts/piston.py: 3% on the shocked state, the shock within 2 cells).
# Measured, density (exact 4) / eps (0.5) / shock (0.1667): order 1 4.036 / 0.5000 / 0.1669, order 2 4.053 / 0.4998 /
# 0.1665, ars222 4.046 / 0.4998 / 0.1665 (with node_fit, the default since session 28: 4.029 / 0.5000 / 0.1663 and
# 4.024 / 0.5000 / 0.1663). The ars222 run fails without the piston's scale in the floor (checked), and with node_fit
# it failed --check's node balance in the precursor until worstImbalance's floor (NodeBalance.hpp).
foreach(mode o1 o2 ars)
  set(args --set scheme.order=1)
  if(mode STREQUAL "o2")
    set(args --set scheme.order=2)
  elseif(mode STREQUAL "ars")
    set(args --set scheme.order=2 --set scheme.integrator=ars222)
  endif()
  add_test(NAME piston_cold2d_${mode}_run COMMAND ${UNILAG} run ${SCENES}/piston_cold2d.yaml --quiet --check ${args}
           --output ${WORK}/piston_cold2d_${mode})
  add_test(NAME piston_cold2d_${mode}_check COMMAND ${PYTHON} ${SCRIPTS}/piston.py ${WORK}/piston_cold2d_${mode})
  set_tests_properties(piston_cold2d_${mode}_run PROPERTIES FIXTURES_SETUP piston_${mode} LABELS "gpr;regression")
  set_tests_properties(piston_cold2d_${mode}_check PROPERTIES FIXTURES_REQUIRED piston_${mode} LABELS "gpr;regression")
endforeach()

# The same cold piston on triangles of three orientations (apps/shock_orientation_study.py, docs/sedov.md, session 14),
# order 1 and four order-2 schemes. Asserted: an equilateral lattice with an edge family along the motion gives the
# exact shocked state cell by cell (measured scatter 0.01-0.07%, worst cell 0.04-0.29%), and so does the strip with
# vertex_based and all reconstructed (0.29%, worst 0.54%); bound 1%. Every run's mean density within 1.5% of 4
# (measured 4.0000-4.044), but the velocity-only scheme's (4.08-4.11, reported); pressure_limiter: vertex_based must
# halve order 1's scatter on the strip (measured 3.42% against 9.42%). The defect: where an edge family is parallel
# to the front the two triangle orientations leave the shock with different entropies (scatter on the strip: order 1
# 9.4%, barth_jespersen 10.5%, velocity alone 16.5%; turned lattice 5.5%, 7.1%, 3.5% with vertex_based, 13.6%); the
# entropy filter (scheme.entropy_filter: 0.05) must halve the scatter of order 1 and of the velocity-alone order 2 on
# both (measured: strip 0.01% and 0.02%, turned lattice 2.39% and 1.02%).
add_test(NAME piston_orientation COMMAND ${PYTHON} ${PROJECT_SOURCE_DIR}/apps/shock_orientation_study.py ${UNILAG}
         ${WORK}/piston_orientation.csv 0.005 --check 1.5 1.0)
set_tests_properties(piston_orientation PROPERTIES LABELS "gpr;regression")

# A strong planar shock in 3D on unstructured tetrahedra (tests/scenes/piston3d_tets.yaml, gamma 1.4, 8.9k cells,
# t = 1; tests/scripts/piston3d.py): the shocked state's volume-weighted means within 2% (velocity 1%), the front
# within a cell, and the pressure scatter behind the shock at most 0.14. Measured, density (6) / pressure (1.2) /
# eps (0.5) / scatter: order 1 5.987 / 1.1972 / 0.5040 / 0.1287, order 2 6.000 / 1.1996 / 0.5041 / 0.1245. The
# scatter is what the tetrahedra's nodes cannot relax (docs/sedov.md, session 29): it stays, 12% far behind the shock.
foreach(order 1 2)
  add_test(NAME piston3d_tets_o${order}_run COMMAND ${UNILAG} run ${SCENES}/piston3d_tets.yaml --quiet --check
           --set scheme.order=${order} --output ${WORK}/piston3d_tets_o${order})
  add_test(NAME piston3d_tets_o${order}_check
           COMMAND ${PYTHON} ${SCRIPTS}/piston3d.py ${WORK}/piston3d_tets_o${order} 0.14)
  set_tests_properties(piston3d_tets_o${order}_run PROPERTIES FIXTURES_SETUP piston3d_o${order}
                       LABELS "gpr;regression")
  set_tests_properties(piston3d_tets_o${order}_check PROPERTIES FIXTURES_REQUIRED piston3d_o${order}
                       LABELS "gpr;regression")
endforeach()

# The gas in a rigid tube, the gas in an expandable (latex-like) tube, the gas in a free tube and the 1D artery as
# tube scenes (src/tube/GasRun, GasRodRun, ArteryRun) through `unilag run` on inputs/tube_sod.yaml,
# inputs/tube_latex_shock.yaml, inputs/tube_gas_free.yaml and inputs/artery_carotid.yaml: each passes its own --check as shipped, the physics of
# the output (shock speed, L1 against the exact solution, the RCR's mean pressure), bad input. A few s in all.
set(SOD_SCENE ${INPUTS}/tube_sod.yaml)
set(CAROTID_SCENE ${INPUTS}/artery_carotid.yaml)
set(LATEX_SCENE ${INPUTS}/tube_latex_shock.yaml)
set(FREE_SCENE ${INPUTS}/tube_gas_free.yaml)

# Sod, 200 cells, two walls: --check holds mass and energy to 1e-10 (measured 1.4e-15, 3.4e-15) and L1(density)
# within the scene's 0.005 (measured 0.00338). The shock speed measured from the run (a fit of its position over
# the second half) within 1% of the exact 1.75216 (measured 1.75310, 0.05%), its position within two cells.
add_test(NAME tube_gas_sod_check COMMAND bash -c
         "rm -rf ${WORK}/tube_sod && ${UNILAG_TUBE_SH} ${SOD_SCENE} --check --output ${WORK}/tube_sod && \
          ${PYTHON} ${SCRIPTS}/tube_modules.py gas ${WORK}/tube_sod --speed-tol 0.01")
set_tests_properties(tube_gas_sod_check PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "tube_modules: PASS" ENVIRONMENT "OMP_NUM_THREADS=1")

# A Mach 2 shock fed by the post-shock state at the left end: --check (L1 within the scene's 0.015, measured
# 0.0101), the speed measured from the run within 0.5% of 2 a1 = 2.36643 (measured 2.36649, 2.5e-5).
add_test(NAME tube_gas_shock_check COMMAND bash -c
         "rm -rf ${WORK}/tube_shock && ${UNILAG_TUBE_SH} ${INPUTS}/tube_shock.yaml --check --output ${WORK}/tube_shock \
          && ${PYTHON} ${SCRIPTS}/tube_modules.py gas ${WORK}/tube_shock --speed-tol 0.005")
set_tests_properties(tube_gas_shock_check PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "tube_modules: PASS" ENVIRONMENT "OMP_NUM_THREADS=1")

# --check fails (exit 3) with a bound below the scheme's error.
add_test(NAME tube_gas_check_fails COMMAND ${UNILAG_TUBE} ${SOD_SCENE} --check --set gas.check.l1_density=1.0e-6
         --output ${WORK}/tube_sod_fail)
set_tests_properties(tube_gas_check_fails PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "check failed: L1\\(density\\)" ENVIRONMENT "OMP_NUM_THREADS=1")

# A shock tube in a latex-like tube with axial tension (gas.wall), 400 cells, two walls: --check holds mass and
# gas + wall energy to 1e-10 (measured -1.3e-14, -6.5e-15); tube.xmf carries radius, wall speed, density,
# pressure, velocity and Mach number; the wall at the left end (gas slowed by the wall, driver expanded by the
# reflected rarefaction) on the quasi-static law of its pressure within 3% (measured 1.4%: the wall's inertia);
# the front between c1 = 239.3 and a1 = 343.8 m/s and within 1% of the study's 306.9 m/s (docs/tube-wall.md 4:
# 800 cells, no tension, its own level; measured 307.09). About 0.6 s.
add_test(NAME tube_gas_latex_check COMMAND bash -c
         "rm -rf ${WORK}/tube_latex && ${UNILAG_TUBE_SH} ${LATEX_SCENE} --check --output ${WORK}/tube_latex && \
          ${PYTHON} ${SCRIPTS}/tube_modules.py wall ${WORK}/tube_latex --quasi-static 0.03 --speed 306.9 \
          --speed-tol 0.01")
set_tests_properties(tube_gas_latex_check PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "tube_modules: PASS" ENVIRONMENT "OMP_NUM_THREADS=1")

# A 10:1 shock tube in a free-free PVC-like tube that bends (gas.rod), 200 segments, to 3 ms: --check holds mass and
# momentum to 1e-12 (measured -6.3e-16, 8.0e-19 of its scale) and the energy's largest deviation within the scene's
# 4e-7 (measured 1.34e-7); every dump's fields exist, are finite and agree (radius = sqrt(A / pi), Mach = |v| / a); the tube bends
# (a node more than 1 mm off the axis; measured 3.76 mm); the shock's speed fitted until it nears the right end cap
# within 1% of the rigid tube's exact 552.70 m/s (the wall stretches by 1.1e-3 at most; measured 553.66, 0.17%).
# About 1.5 s (482 steps).
add_test(NAME tube_gas_free_check COMMAND bash -c
         "rm -rf ${WORK}/tube_gas_free && ${UNILAG_TUBE_SH} ${FREE_SCENE} --check --output ${WORK}/tube_gas_free && \
          ${PYTHON} ${SCRIPTS}/tube_modules.py rod ${WORK}/tube_gas_free --bend 1.0e-3 --speed-tol 0.01")
set_tests_properties(tube_gas_free_check PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "tube_modules: PASS" ENVIRONMENT "OMP_NUM_THREADS=1" FIXTURES_SETUP tube_gas_free_xmf)

# --check fails (exit 3) with an energy bound below the integrator's error (a short run).
add_test(NAME tube_gas_free_check_fails COMMAND ${UNILAG_TUBE} ${FREE_SCENE} --check --set gas.end_time=2.0e-4
         --set gas.check.energy=1.0e-12 --output ${WORK}/tube_gas_free_fail)
set_tests_properties(tube_gas_free_check_fails PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "check failed: energy \\(rod \\+ gas\\)" ENVIRONMENT "OMP_NUM_THREADS=1")

# A run that goes non-finite (an absurd 3000 m/s bending velocity: the state is not finite after the step from
# t = 0.29 ms) stops with exit 4 and one diagnosis; summary.json says unstable, no dump holds a NaN.
add_test(NAME tube_gas_free_unstable COMMAND bash -c
         "rm -rf ${WORK}/tube_gas_free_nan; err=$(${UNILAG_TUBE_SH} ${FREE_SCENE} --set gas.end_time=5.0e-4 \
          --set gas.rod.perturbation.velocity=[0.0,3000.0,0.0] --output ${WORK}/tube_gas_free_nan 2>&1 >/dev/null); \
          rc=$?; echo \"exit $rc: $err\"; [ $rc -eq 4 ] && echo \"$err\" | grep -q 'is not finite after the step' && \
          ${PYTHON} ${SCRIPTS}/tube_modules.py rod_unstable ${WORK}/tube_gas_free_nan")
set_tests_properties(tube_gas_free_unstable PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "tube_modules: PASS" ENVIRONMENT "OMP_NUM_THREADS=1")

# ParaView opens the free tube's 3D polyline (200 segments, 201 nodes) with its node field and draws it.
if(PVPYTHON)
  add_test(NAME paraview_draws_tube_gas_free COMMAND ${PVPYTHON} ${PROJECT_SOURCE_DIR}/tests/io/pv_tube.py
           ${WORK}/tube_gas_free/tube.xmf rod_velocity)
  set_tests_properties(paraview_draws_tube_gas_free PROPERTIES FIXTURES_REQUIRED tube_gas_free_xmf LABELS "io;tube"
                       PASS_REGULAR_EXPRESSION "segments=200 nodes=201 rod_velocity .* tube_cells=[1-9]")
endif()

# The carotid, 64 cells, 8 cycles from rest: --check holds the volume balance to 1e-10 and finds the run periodic
# (1e-3 cycle to cycle) by the last cycle (measured -2.0e-13; 4.4e-7 and 6.5e-8 at cycle 8); periodic within 6
# cycles (measured 5, as unilag_tube_artery), the mean outlet pressure mean(Q) (R1 + R2) = 12711 Pa within 1%
# (measured 12710.70 against 12710.7). About 1 s.
add_test(NAME tube_artery_carotid_check COMMAND bash -c
         "rm -rf ${WORK}/artery_carotid && ${UNILAG_TUBE_SH} ${CAROTID_SCENE} --check --output ${WORK}/artery_carotid \
          && ${PYTHON} ${SCRIPTS}/tube_modules.py artery ${WORK}/artery_carotid --cycles 6")
set_tests_properties(tube_artery_carotid_check PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "tube_modules: PASS" ENVIRONMENT "OMP_NUM_THREADS=1")

# Bad input: exit 2, one message naming the file and key, nothing written.
function(tube2_error name scene pattern)
  add_test(NAME tube2_error_${name} COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/tube2_err_${name}
           "${pattern}" -- ${UNILAG_TUBE} ${scene} ${ARGN})
  set_tests_properties(tube2_error_${name} PROPERTIES LABELS "tube;regression")
endfunction()
tube2_error(gas_unknown_key ${SOD_SCENE} "tube_sod.yaml: key 'gas.cels': unknown key" --set gas.cels=10)
tube2_error(gas_negative_length ${SOD_SCENE} "tube_sod.yaml: key 'gas.length': must be a positive number"
            --set gas.length=-1.0)
tube2_error(gas_end_type ${SOD_SCENE} "tube_sod.yaml: key 'gas.ends.left.type': 'valve' is not one of"
            --set gas.ends.left.type=valve)
tube2_error(gas_end_extra ${SOD_SCENE} "tube_sod.yaml: key 'gas.ends.right.pressure': a wall end takes no pressure"
            --set gas.ends.right.pressure=1.0)
tube2_error(gas_vacuum ${SOD_SCENE} "tube_sod.yaml: key 'gas.initial.right': the left and right states create a vacuum"
            --set gas.initial.left.velocity=-20.0 --set gas.initial.right.velocity=20.0)
tube2_error(gas_with_rod ${SOD_SCENE} "tube_sod.yaml: key 'ends': a gas scene takes its vessel and ends"
            --set ends.left=clamped)
tube2_error(wall_unknown_key ${LATEX_SCENE} "tube_latex_shock.yaml: key 'gas.wall.thicknes': unknown key"
            --set gas.wall.thicknes=1.0e-3)
tube2_error(wall_poisson ${LATEX_SCENE} "tube_latex_shock.yaml: key 'gas.wall.poisson': must be in \\[0, 0.5\\]"
            --set gas.wall.poisson=0.7)
tube2_error(wall_negative_tension ${LATEX_SCENE}
            "tube_latex_shock.yaml: key 'gas.wall.axial_tension': must be a non-negative number" --set gas.wall.axial_tension=-1.0)
tube2_error(wall_bulge ${LATEX_SCENE} "tube_latex_shock.yaml: key 'gas.wall.young_modulus': the initial pressure .* bulge limit"
            --set gas.wall.young_modulus=1.0e5)
tube2_error(wall_l1 ${LATEX_SCENE} "tube_latex_shock.yaml: key 'gas.check.l1_density': an expandable tube"
            --set gas.check.l1_density=0.01)
tube2_error(artery_unknown_key ${CAROTID_SCENE} "artery_carotid.yaml: key 'artery.radus': unknown key"
            --set artery.radus=1.0)
tube2_error(artery_negative_modulus ${CAROTID_SCENE}
            "artery_carotid.yaml: key 'artery.youngs_modulus': must be a positive number" --set artery.youngs_modulus=-5.0)
tube2_error(artery_negative_length ${CAROTID_SCENE} "artery_carotid.yaml: key 'artery.length': must be a positive number"
            --set artery.length=-0.1)
tube2_error(artery_outlet_type ${CAROTID_SCENE} "artery_carotid.yaml: key 'artery.outlet.type': 'open' is not one of"
            --set artery.outlet.type=open)
tube2_error(artery_dumps ${CAROTID_SCENE} "artery_carotid.yaml: key 'artery.dumps_per_cycle': must divide"
            --set artery.dumps_per_cycle=7)
tube2_error(rod_unknown_key ${FREE_SCENE} "tube_gas_free.yaml: key 'gas.rod.youngs_modulos': unknown key"
            --set gas.rod.youngs_modulos=1.0e9)
tube2_error(rod_gas_end ${FREE_SCENE}
            "tube_gas_free.yaml: key 'gas.ends.right.type': a free tube \\(gas.rod\\) closes its gas with end caps"
            --set gas.ends.right.type=transmissive)
tube2_error(rod_with_wall ${FREE_SCENE} "tube_gas_free.yaml: key 'gas.rod': a free tube \\(gas.rod\\) has a rigid radius"
            --set gas.wall.ramp=0.0)
tube2_error(rod_gravity ${FREE_SCENE} "tube_gas_free.yaml: key 'gas.rod.gravity': the gas's weight is not coupled"
            --set gas.rod.gravity=[0.0,-9.81,0.0])
tube2_error(rod_axial_velocity ${FREE_SCENE} "tube_gas_free.yaml: key 'gas.rod.perturbation.velocity': is transverse"
            --set gas.rod.perturbation.velocity=[1.0,0.0,0.0])

# Nonlinear tube runs (src/tube/TubeDynamics, TubeTimeRun) through `unilag run` on inputs/tube_flutter.yaml (a tube
# scene with dynamics:): flutter against the linear geometric model of the same tube, energy and orthogonality,
# the motion leaving the plane, bad input. About 40 s in all.
set(FLUTTER_SCENE ${INPUTS}/tube_flutter.yaml)

# Decay at 0.98 u_cf, growth at 1.02 u_cf, and the fitted growth rate and frequency above u_cf within 5% and 1% of
# the linear geometric model's (measured: beta 0.2, 60 segments: growth 0.2476 vs 0.2492, 0.6%; beta 0.5, 100
# segments: 1.298 vs 1.319, 1.6%; frequencies within 0.1%). A wrong fluid force (Coriolis, centrifugal,
# pressure) or free-end condition moves u_cf by more than 0.1%, which is 5% of the growth rate here.
function(tube_flutter name)
  set(dir ${WORK}/tube_flutter_${name})
  string(REPLACE ";" " " args "${ARGN}")
  add_test(NAME tube_flutter_${name} COMMAND bash -c
           "rm -rf ${dir} && for f in 0.98 1.02; do ${UNILAG_TUBE_SH} ${FLUTTER_SCENE} ${args} \
            --set dynamics.flow.critical_fraction=$f --set dynamics.output_interval=0.0 --output ${dir}/$f || exit 1; \
            done && ${PYTHON} ${SCRIPTS}/tube_flutter.py ${dir}/0.98 ${dir}/1.02 --tol 0.05")
  set_tests_properties(tube_flutter_${name} PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                       "tube_flutter: PASS" ENVIRONMENT "OMP_NUM_THREADS=2")
endfunction()
tube_flutter(beta02)
tube_flutter(beta05 --set tube.density=1600.0 --set dynamics.segments=100 --set dynamics.end_time=15.0)

# No flow, no gravity: --check holds the energy to 1e-5 (measured 1e-9 over 1.2e5 steps: the perturbation turns
# the sections with the tangent, so the stiff shear modes stay quiet) and the rotations orthogonal to 1e-12.
add_test(NAME tube_dynamics_check_energy COMMAND ${UNILAG_TUBE} ${FLUTTER_SCENE} --check
         --set dynamics.flow.critical_fraction=0.0 --set dynamics.end_time=20.0 --output ${WORK}/tube_energy)
set_tests_properties(tube_dynamics_check_energy PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "check passed" ENVIRONMENT "OMP_NUM_THREADS=2")

# 3D: an out-of-plane perturbation above u_cf makes the motion leave the plane (the z amplitude grows with y's);
# the in-plane run stays exactly in its plane (z = 0 at every sample).
add_test(NAME tube_dynamics_out_of_plane COMMAND bash -c
         "rm -rf ${WORK}/tube_3d ${WORK}/tube_2d && ${UNILAG_TUBE_SH} ${FLUTTER_SCENE} --set dynamics.end_time=30.0 \
          --set dynamics.flow.critical_fraction=1.1 --set dynamics.perturbation.tip_velocity=[0.0,1.0e-4,5.0e-5] \
          --output ${WORK}/tube_3d && ${UNILAG_TUBE_SH} ${FLUTTER_SCENE} --set dynamics.end_time=30.0 \
          --set dynamics.flow.critical_fraction=1.1 --output ${WORK}/tube_2d && \
          ${PYTHON} ${SCRIPTS}/tube_out_of_plane.py ${WORK}/tube_3d ${WORK}/tube_2d")
set_tests_properties(tube_dynamics_out_of_plane PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "tube_out_of_plane: PASS" ENVIRONMENT "OMP_NUM_THREADS=2")

# Bad input: exit 2, one message naming the file and key, nothing written.
function(tube_dynamics_error name pattern)
  add_test(NAME tube_dynamics_error_${name} COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/tube_dyn_err_${name}
           "${pattern}" -- ${UNILAG_TUBE} ${FLUTTER_SCENE} ${ARGN})
  set_tests_properties(tube_dynamics_error_${name} PROPERTIES LABELS "tube;regression")
endfunction()
tube_dynamics_error(both_speeds "tube_flutter.yaml: key 'dynamics.flow.critical_fraction': give speed or critical_fraction, not both"
                    --set dynamics.flow.speed=1.0)
tube_dynamics_error(step_factor "tube_flutter.yaml: key 'dynamics.step_factor': must be at most 1"
                    --set dynamics.step_factor=1.5)
tube_dynamics_error(area_change "tube_flutter.yaml: key 'dynamics.end_time': the nonlinear rod has a constant cross-section"
                    --set tube.area_change=1.0e-6)
tube_dynamics_error(unknown_key "tube_flutter.yaml: key 'dynamics.segmnts': unknown key"
                    --set dynamics.segmnts=10)

# ParaView opens the time run's polyline and draws it with Extract Surface + Tube (60 segments, 61 nodes).
set_tests_properties(tube_dynamics_check_energy PROPERTIES FIXTURES_SETUP tube_xmf)
if(PVPYTHON)
  add_test(NAME paraview_draws_tube COMMAND ${PVPYTHON} ${PROJECT_SOURCE_DIR}/tests/io/pv_tube.py
           ${WORK}/tube_energy/tube.xmf curvature)
  set_tests_properties(paraview_draws_tube PROPERTIES FIXTURES_REQUIRED tube_xmf LABELS "io;tube"
                       PASS_REGULAR_EXPRESSION "segments=60 nodes=61 curvature .* tube_cells=[1-9]")
endif()

# Threads: a rod of 1100 nodes and a gas of 1100 cells (above serialBelow, so on OpenMP) on 1 and 3 threads write
# bitwise the same dumps and tip.csv. Kokkos' parallel_scan of the rod's p A changed in the 13th digit at 3 threads
# (its chunks follow the thread count); the scan now runs in index order (SmallLaunch.hpp). 3 threads on 2 cores
# spin at barriers: the runs are kept short (912 steps and 150 steps, about 5 s in all).
add_test(NAME tube_threads_agree COMMAND bash -c
         "rm -rf ${WORK}/tube_thr && for t in 1 3; do \
          ${UNILAG_TUBE_SH} ${FLUTTER_SCENE} --set dynamics.segments=1100 --set dynamics.end_time=0.01 \
          --set dynamics.output_interval=0.005 --threads $t --output ${WORK}/tube_thr/rod$t || exit 1; \
          ${UNILAG_TUBE_SH} ${INPUTS}/tube_sod.yaml --set gas.cells=1100 --set gas.end_time=0.05 --threads $t \
          --output ${WORK}/tube_thr/gas$t || exit 1; done && \
          ${PYTHON} ${SCRIPTS}/same_tube_runs.py ${WORK}/tube_thr/rod1 ${WORK}/tube_thr/rod3 && \
          ${PYTHON} ${SCRIPTS}/same_tube_runs.py ${WORK}/tube_thr/gas1 ${WORK}/tube_thr/gas3")
set_tests_properties(tube_threads_agree PROPERTIES LABELS "tube;regression" PROCESSORS 2)

# --quiet holds for tube runs too (they printed the progress line on a terminal, and mpirun gives rank 0 one): run
# under a pseudo-terminal (script, util-linux), no "ETA" line with --quiet, one without it. A terminal gets a line
# every 0.2 s: the run takes about 0.8 s (end_time 3, 0.24 s, printed none once in three).
add_test(NAME tube_dynamics_quiet COMMAND bash -c
         "cmd='${UNILAG_TUBE_SH} ${FLUTTER_SCENE} --set dynamics.end_time=10.0 --output ${WORK}/tube_quiet'; \
          loud=$(script -qc \"$cmd\" /dev/null | grep -c ETA); \
          quiet=$(script -qc \"$cmd --quiet\" /dev/null | grep -c ETA); \
          echo \"progress lines: $loud without --quiet, $quiet with\"; [ $loud -ge 1 ] && [ $quiet -eq 0 ]")
set_tests_properties(tube_dynamics_quiet PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "progress lines: [1-9][0-9]* without --quiet, 0 with")

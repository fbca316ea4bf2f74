# The tube solver's linear stability (src/tube/) through `unilag run` (a scene with a tube: section): u_cf against
# tube.md 2.1, the same table on 1 and 3 ranks, --check, bad input refused, and the geometric model's CLI path
# (docs/tube-model.md 7). About 40 s in all.
set(UNILAG_TUBE ${UNILAG} run)
set(UNILAG_TUBE_SH "${UNILAG} run") # inside bash -c strings
set(TUBE_SCENE ${INPUTS}/tube_stability.yaml)

# Cantilever, EB limit: u_cf at beta 0, 0.2, 0.5 within 0.5% of 4.478, 5.59, 9.32 (measured 4.477819, 5.591459,
# 9.322398 at 40 elements, 16 modes), and stability.png written.
add_test(NAME tube_stability_cli COMMAND bash -c
         "rm -rf ${WORK}/tube_cli && ${UNILAG_TUBE_SH} ${TUBE_SCENE} --set stability.beta=[0.0,0.2,0.5] \
          --set stability.speed_max=12.0 --output ${WORK}/tube_cli && ${PYTHON} ${SCRIPTS}/tube_stability.py ${WORK}/tube_cli --png")
set_tests_properties(tube_stability_cli PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION "tube_stability: PASS")

# The beta list split over 3 ranks gives the same tables, bit for bit, as one rank.
set(TUBE_SMALL --set stability.beta=[0.0,0.1,0.2,0.3,0.4] --set stability.speed_max=10.0 --set stability.elements=20
    --set stability.modes=10 --set output.plot=false)
string(REPLACE ";" " " TUBE_SMALL_ARGS "${TUBE_SMALL}")
string(REPLACE ";" " " TUBE_MPI_RUN "${MPI_RUN}")
add_test(NAME tube_stability_np3_agree COMMAND bash -c
         "rm -rf ${WORK}/tube_np1 ${WORK}/tube_np3 && ${UNILAG_TUBE_SH} ${TUBE_SCENE} ${TUBE_SMALL_ARGS} --output ${WORK}/tube_np1 \
          && ${TUBE_MPI_RUN} 3 ${UNILAG_TUBE_SH} ${TUBE_SCENE} ${TUBE_SMALL_ARGS} --output ${WORK}/tube_np3 \
          && cmp ${WORK}/tube_np1/stability.csv ${WORK}/tube_np3/stability.csv \
          && cmp ${WORK}/tube_np1/stability_loci.csv ${WORK}/tube_np3/stability_loci.csv && echo tube_agree: PASS")
set_tests_properties(tube_stability_np3_agree PROPERTIES LABELS "tube;regression;mpi" PROCESSORS 3
                     PASS_REGULAR_EXPRESSION "tube_agree: PASS")

# Bad input: exit 2, one message naming the file and the key, no output folder.
function(tube_error name pattern)
  add_test(NAME tube_error_${name} COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/tube_err_${name} "${pattern}"
           -- ${UNILAG_TUBE} ${TUBE_SCENE} ${ARGN})
  set_tests_properties(tube_error_${name} PROPERTIES LABELS "tube;regression")
endfunction()
tube_error(negative_length "tube_stability.yaml: key 'tube.length': must be a positive number" --set tube.length=-1.0)
tube_error(negative_modulus "tube_stability.yaml: key 'tube.youngs_modulus': must be a positive number"
           --set tube.youngs_modulus=-1.0e7)
tube_error(mass_ratio "tube_stability.yaml: key 'stability.beta': mass ratio must be in \\[0, 1\\), found 1"
           --set stability.beta=[0.2,1.0])
tube_error(end_condition "tube_stability.yaml: key 'ends.right': 'fre' is not one of: clamped, pinned, free"
           --set ends.right=fre)
tube_error(aspirating "tube_stability.yaml: key 'ends.left': the fluid enters at the left end, and a free inlet"
           --set ends.left=free --set ends.right=clamped)
tube_error(radii "tube_stability.yaml: key 'tube.inner_radius': must be less than outer_radius"
           --set tube.outer_radius=0.005 --set tube.inner_radius=0.007)
# More modes than dofs kept every dof, silently; more locus modes than modes wrote nan columns.
tube_error(too_many_modes "tube_stability.yaml: key 'stability.modes': at most the 20 degrees of freedom of 10 elements"
           --set stability.elements=10 --set stability.modes=21)
tube_error(locus_modes "tube_stability.yaml: key 'stability.locus_modes': at most the study's 2 modes, found 4"
           --set stability.modes=2)
tube_error(unknown_key "tube_stability.yaml: key 'stability.speed_mx': unknown key \\(did you mean 'stability.speed_max'"
           --set stability.speed_mx=3.0)

# --check: every onset converged in the discretisation (twice finer within 1e-3). The shipped scene passes (40
# elements, 16 modes: u_cf moves by < 1e-5); 6 elements on 4 modes do not (beta = 0.5: u_cf off by several %).
add_test(NAME tube_check_passes COMMAND ${UNILAG_TUBE} ${TUBE_SCENE} --check --set stability.beta=[0.2,0.5]
         --set output.plot=false --output ${WORK}/tube_check)
set_tests_properties(tube_check_passes PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION "check passed")
add_test(NAME tube_check_fails_coarse COMMAND bash ${SCRIPTS}/expect_check_failure.sh ${WORK}/tube_check_coarse
         "beta = 0.5: onset u = .* with 6 elements but .* with 12" -- ${UNILAG_TUBE} ${TUBE_SCENE} --check
         --set stability.beta=[0.5] --set stability.elements=6 --set stability.modes=4 --set output.plot=false)
set_tests_properties(tube_check_fails_coarse PROPERTIES LABELS "tube;regression")
# An output folder that cannot be made is refused before the study (the continuum runs' check, io::OutputFolder).
add_test(NAME tube_error_output_file COMMAND bash ${SCRIPTS}/expect_error.sh ${TUBE_SCENE}/out
         "--output '.*tube_stability.yaml/out': .*tube_stability.yaml is not a folder" -- ${UNILAG_TUBE} ${TUBE_SCENE})
set_tests_properties(tube_error_output_file PROPERTIES LABELS "tube;regression")

# The geometric model (docs/tube-model.md 7) through the CLI, on the talk's rubber tube (L / r_g = 343, beta 0.36).
# K = 0: u_cf 8.576623 (40 elements, 24 modes; 80, 36: 8.57626), the second mode, within 0.2% of Euler-Bernoulli's
# 8.593042 (shear and rotary inertia lower it by 0.19%); bound [8.570, 8.583]. K = 0.02 R^2 (dynamic pressure):
# u_cf 14.45591 (5.62 m/s); bound [14.40, 14.51].
set(TUBE_GEO_SCENE ${INPUTS}/tube_rubber_geometric.yaml)
add_test(NAME tube_geometric_cli COMMAND bash -c
         "rm -rf ${WORK}/tube_geo && ${UNILAG_TUBE_SH} ${TUBE_GEO_SCENE} --check --set tube.area_change=0.0 \
          --set stability.speed_max=12.0 --set output.plot=false --output ${WORK}/tube_geo \
          && awk -F, 'NR == 2 && $2 > 8.570 && $2 < 8.583 && $4 == \"flutter\" && $8 == 2 { print \"tube_geometric: PASS\" }' \
             ${WORK}/tube_geo/stability.csv")
set_tests_properties(tube_geometric_cli PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION "tube_geometric: PASS")
add_test(NAME tube_geometric_area_change COMMAND bash -c
         "rm -rf ${WORK}/tube_geo_k && ${UNILAG_TUBE_SH} ${TUBE_GEO_SCENE} --set tube.area_change=5.0e-7 \
          --set stability.speed_max=20.0 --set output.plot=false --output ${WORK}/tube_geo_k \
          && awk -F, 'NR == 2 && $2 > 14.40 && $2 < 14.51 && $4 == \"flutter\" { print \"tube_area_change: PASS\" }' \
             ${WORK}/tube_geo_k/stability.csv")
set_tests_properties(tube_geometric_area_change PROPERTIES LABELS "tube;regression"
                     PASS_REGULAR_EXPRESSION "tube_area_change: PASS")

# Every shipped tube scene passes --check (tube_stability.yaml: tube_check_passes above).
foreach(scene tube_rubber tube_rubber_geometric)
  add_test(NAME tube_check_${scene} COMMAND ${UNILAG_TUBE} ${INPUTS}/${scene}.yaml --check --set output.plot=false
           --output ${WORK}/tube_check_${scene})
  set_tests_properties(tube_check_${scene} PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION "check passed")
endforeach()

# Bad input in a geometric scene: exit 2, one message naming the file and the key, no output folder.
function(tube_geo_error name pattern)
  add_test(NAME tube_error_${name} COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/tube_err_${name} "${pattern}"
           -- ${UNILAG_TUBE} ${TUBE_GEO_SCENE} ${ARGN})
  set_tests_properties(tube_error_${name} PROPERTIES LABELS "tube;regression")
endfunction()
tube_geo_error(negative_area_change
               "tube_rubber_geometric.yaml: key 'tube.area_change': must be a non-negative number, found -1e-06"
               --set tube.area_change=-1.0e-6)
tube_geo_error(area_change_needs_geometric
               "tube_rubber_geometric.yaml: key 'tube.area_change': only the geometric model has an area change"
               --set tube.model=euler_bernoulli)
tube_geo_error(geometric_beta "tube_rubber_geometric.yaml: key 'stability.beta': the geometric model takes its mass ratio"
               --set stability.beta=[0.2])
tube_error(geometric_needs_tube "tube_stability.yaml: key 'tube.length': missing \\(the geometric model needs the physical tube"
           --set tube.model=geometric)

# The tube solver's linear stability (src/tube/) through `unilag run` (a scene with a tube: section): u_cf against
# tube.md 2.1, the same table on 1 and 3 ranks, --check, and bad input refused. About 10 s in all.
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
tube_error(radii "tube_stability.yaml: key 'tube.inner_radius': must be less than outer_radius"
           --set tube.outer_radius=0.005 --set tube.inner_radius=0.007)
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

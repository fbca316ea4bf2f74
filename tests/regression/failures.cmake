# Failure paths: bad input is named and refused (exit 2), unstable runs stop with a diagnosis (exit 4).
# Bad input: one clear message naming the file and key or element, exit 2, no output folder.
add_test(NAME error_malformed_scene COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err1 "malformed.yaml: malformed YAML.*line 5"
         -- ${UNILAG} run ${SCENES}/malformed.yaml)
add_test(NAME error_unknown_key COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err2
         "unknown_key.yaml: key 'time.max_stpes': unknown key \\(did you mean 'time.max_steps'" -- ${UNILAG} run ${SCENES}/unknown_key.yaml)
add_test(NAME error_inverted_mesh COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err3 "inverted.msh: element 8 .*inverted"
         -- ${UNILAG} run ${SCENES}/inverted.yaml)
add_test(NAME error_negative_density COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err4
         "sedov2d.yaml: key 'regions.gas.density': must be positive" -- ${UNILAG} run ${INPUTS}/sedov2d.yaml --set regions.gas.density=-1.0)
add_test(NAME error_missing_mesh COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err5 "key 'mesh.geometry': file not found"
         -- ${UNILAG} run ${INPUTS}/sedov2d.yaml --set mesh.geometry=nowhere.geo)
add_test(NAME error_limiter COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err7
         "sedov2d.yaml: key 'scheme.limiter': 'minmod' is not one of: barth_jespersen, vertex_based, none"
         -- ${UNILAG} run ${INPUTS}/sedov2d.yaml --set scheme.limiter=minmod)
add_test(NAME error_mpi_unknown_key COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err6 "key 'time.max_stpes'"
         -- ${MPI_RUN} 2 ${UNILAG} run ${SCENES}/unknown_key.yaml)
# Bad physical input of the GPR model: the scene reader names the key before the solver starts.
add_test(NAME error_gamma COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_gamma
         "error_gamma.yaml: key 'materials.gas.gamma': an ideal gas needs gamma > 1" -- ${UNILAG} run ${SCENES}/error_gamma.yaml)
add_test(NAME error_negative_csh COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_csh
         "error_negative_csh.yaml: key 'materials.gas.shear_sound_speed': must be a non-negative number"
         -- ${UNILAG} run ${SCENES}/error_negative_csh.yaml)
add_test(NAME error_negative_tau COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_tau
         "error_negative_tau.yaml: key 'materials.gas.strain_relaxation.tau1': must be a positive number"
         -- ${UNILAG} run ${SCENES}/error_negative_tau.yaml)
add_test(NAME error_unknown_eos COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_eos
         "error_unknown_eos.yaml: key 'materials.gas.eos': 'ideal_gaz' is not one of: .*did you mean 'ideal_gas'"
         -- ${UNILAG} run ${SCENES}/error_unknown_eos.yaml)
add_test(NAME error_unknown_law COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_law
         "error_unknown_law.yaml: key 'materials.gas.strain_relaxation.law': 'plastik' is not one of: .*did you mean 'plastic'"
         -- ${UNILAG} run ${SCENES}/error_unknown_law.yaml)
set_tests_properties(error_gamma error_negative_csh error_negative_tau error_unknown_eos error_unknown_law
                     PROPERTIES LABELS regression)
# A run that goes unstable stops with a diagnosis (exit 4) and never writes NaNs.
add_test(NAME unstable_diagnosis COMMAND bash ${SCRIPTS}/expect_unstable.sh ${WORK}/unstable
         -- ${UNILAG} run ${SCENES}/piston_collapse.yaml --quiet)
set_tests_properties(error_malformed_scene error_unknown_key error_inverted_mesh error_negative_density
                     error_missing_mesh error_limiter error_mpi_unknown_key unstable_diagnosis PROPERTIES LABELS regression)

# A Picard loop capped below what an elastic step needs is never accepted unconverged: each step is cut and retried,
# and when the retries run out the run stops with the diagnosis (exit 4, no NaN).
add_test(NAME picard_cap_diagnosis COMMAND bash ${SCRIPTS}/expect_unstable.sh ${WORK}/picard_cap
         -- ${UNILAG} run ${SCENES}/traction_wave.yaml --quiet --set scheme.picard_max_iterations=2 --set time.max_retries=3)
set_tests_properties(picard_cap_diagnosis PROPERTIES LABELS "gpr;regression" PASS_REGULAR_EXPRESSION "Picard loop did not converge in 2 iterations(.|\n)*expect_unstable: PASS")

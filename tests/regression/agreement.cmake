# Agreement: threads and ranks give the same fields.
# OMP_NUM_THREADS=1 and 2: bitwise identical fields.
foreach(nt 1 2)
  add_test(NAME threads_${nt} COMMAND ${UNILAG} run ${SMALL_SEDOV} --output ${WORK}/threads_${nt})
  set_tests_properties(threads_${nt} PROPERTIES ENVIRONMENT "OMP_NUM_THREADS=${nt}" FIXTURES_SETUP threads LABELS regression)
endforeach()
add_test(NAME threads_bitwise COMMAND ${PYTHON} ${SCRIPTS}/compare_runs.py 0 ${WORK}/threads_1 ${WORK}/threads_2)
set_tests_properties(threads_bitwise PROPERTIES FIXTURES_REQUIRED threads LABELS regression)

# np 1, 2, 3: the same fields (1e-12 relative; in fact bitwise, corners are summed in global order).
foreach(np 1 2 3)
  add_test(NAME mpi_np${np} COMMAND ${MPI_RUN} ${np} ${UNILAG} run ${SMALL_SEDOV} --check --output ${WORK}/mpi_np${np})
  set_tests_properties(mpi_np${np} PROPERTIES ENVIRONMENT "OMP_NUM_THREADS=1" FIXTURES_SETUP mpi LABELS "mpi;regression"
                       PROCESSORS ${np})
endforeach()
add_test(NAME mpi_agree COMMAND ${PYTHON} ${SCRIPTS}/compare_runs.py 1e-12 ${WORK}/mpi_np1 ${WORK}/mpi_np2 ${WORK}/mpi_np3)
set_tests_properties(mpi_agree PROPERTIES FIXTURES_REQUIRED mpi LABELS "mpi;regression")
add_test(NAME mpi_sedov3d_np2 COMMAND ${MPI_RUN} 2 ${UNILAG} run ${INPUTS}/sedov3d.yaml --quiet --check
         --set time.end=0.2 --output ${WORK}/sedov3d_np2)
set_tests_properties(mpi_sedov3d_np2 PROPERTIES ENVIRONMENT "OMP_NUM_THREADS=1" LABELS "mpi;regression" PROCESSORS 2)

# Every GPR equation at once (viscous, heat-conducting 3D Sedov): 1, 2, 3 ranks and 1, 2 threads give the same fields.
foreach(run "1;1" "1;2" "2;1" "3;1")
  list(GET run 0 np)
  list(GET run 1 nt)
  add_test(NAME gpr3d_np${np}_t${nt} COMMAND ${MPI_RUN} ${np} ${UNILAG} run ${SCENES}/sedov3d_viscous_heat.yaml --quiet --check
           --output ${WORK}/gpr3d_np${np}_t${nt})
  set_tests_properties(gpr3d_np${np}_t${nt} PROPERTIES ENVIRONMENT "OMP_NUM_THREADS=${nt}" FIXTURES_SETUP gpr3d
                       LABELS "gpr;mpi;regression" PROCESSORS ${np})
endforeach()
add_test(NAME gpr3d_agree COMMAND ${PYTHON} ${SCRIPTS}/compare_runs.py 1e-12 ${WORK}/gpr3d_np1_t1 ${WORK}/gpr3d_np1_t2
         ${WORK}/gpr3d_np2_t1 ${WORK}/gpr3d_np3_t1)
set_tests_properties(gpr3d_agree PROPERTIES FIXTURES_REQUIRED gpr3d LABELS "gpr;mpi;regression")
# The written specific internal energy is the EOS's (E less kinetic, elastic and thermal energies): p = 0.4 rho eps.
add_test(NAME gpr3d_eos_consistency COMMAND ${PYTHON} ${SCRIPTS}/eos_consistency.py 1.4 ${WORK}/gpr3d_np1_t1)
set_tests_properties(gpr3d_eos_consistency PROPERTIES FIXTURES_REQUIRED gpr3d LABELS "gpr;regression")

# Two plastic materials (copper on aluminium, conformal interface): np 1 and 2 give the same fields.
foreach(np 1 2)
  add_test(NAME impact2d_np${np} COMMAND ${MPI_RUN} ${np} ${UNILAG} run ${INPUTS}/impact2d.yaml --quiet --check
           --output ${WORK}/impact2d_np${np})
  set_tests_properties(impact2d_np${np} PROPERTIES ENVIRONMENT "OMP_NUM_THREADS=1" FIXTURES_SETUP impact2d
                       LABELS "mpi;regression;gpr" PROCESSORS ${np})
endforeach()
add_test(NAME impact2d_agree COMMAND ${PYTHON} ${SCRIPTS}/compare_runs.py 1e-12 ${WORK}/impact2d_np1 ${WORK}/impact2d_np2)
set_tests_properties(impact2d_agree PROPERTIES FIXTURES_REQUIRED impact2d LABELS "mpi;regression;gpr")
foreach(run "1;1" "1;2" "2;1")
  list(GET run 0 np)
  list(GET run 1 nt)
  add_test(NAME order2_gpr3d_np${np}_t${nt} COMMAND ${MPI_RUN} ${np} ${UNILAG} run ${SCENES}/sedov3d_viscous_heat.yaml
           --quiet --check --set scheme.order=2 --output ${WORK}/order2_gpr3d_np${np}_t${nt})
  add_test(NAME order2_impact2d_np${np}_t${nt} COMMAND ${MPI_RUN} ${np} ${UNILAG} run ${INPUTS}/impact2d.yaml
           --quiet --check --set scheme.order=2 --output ${WORK}/order2_impact2d_np${np}_t${nt})
  set_tests_properties(order2_gpr3d_np${np}_t${nt} order2_impact2d_np${np}_t${nt} PROPERTIES
                       ENVIRONMENT "OMP_NUM_THREADS=${nt}" FIXTURES_SETUP order2 LABELS "gpr;mpi;regression"
                       PROCESSORS ${np})
endforeach()
add_test(NAME order2_agree COMMAND bash -c
         "${PYTHON} ${SCRIPTS}/compare_runs.py 1e-12 ${WORK}/order2_gpr3d_np1_t1 ${WORK}/order2_gpr3d_np1_t2 \
          ${WORK}/order2_gpr3d_np2_t1 && ${PYTHON} ${SCRIPTS}/compare_runs.py 1e-12 ${WORK}/order2_impact2d_np1_t1 \
          ${WORK}/order2_impact2d_np1_t2 ${WORK}/order2_impact2d_np2_t1")
set_tests_properties(order2_agree PROPERTIES FIXTURES_REQUIRED order2 LABELS "gpr;mpi;regression")

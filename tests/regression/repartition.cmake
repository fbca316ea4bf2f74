# Repartitioning changes no result (issue 14 item 1, docs/parallel.md): runs forced to repartition at every check
# (parallel.imbalance_threshold 0, every 10 steps and at the early checks of steps 3, 6, 9) on 1 to 4 ranks end
# bitwise equal (compare_runs.py at 0: every dataset of the last dump, steps, final time) to the 1-rank run that never
# does (the agreement matrix's np1 runs, agreement.cmake), and cells did move (repartitioned.py: a repartition at
# every check, cells moved on 2+ ranks).
# Hydro at order 1 on 1-4 ranks and at order 2; plastic (strain, plastic hints, Picard start history, the cost
# weights) at order 2 and with ARS(2,2,2) (its lagged stage velocities); the viscous, heat-conducting 3D blast at
# order 1 and 2; the two-material plastic impact at order 2 on 2 ranks.
# The space-filling-curve partitioner (ranges of global ids) cuts the mesh other than the start-up multijagged does,
# so that the first repartition moves a good share of the cells (multijagged or rcb again move 0-22 of 1018 in all).
set(FORCED --set parallel.check_interval=10 --set parallel.early_check_interval=3 --set parallel.imbalance_threshold=0
    --set parallel.partitioner=sfc)
function(repartition_run dim variant order np)
  set(name repartition${dim}d_${variant}_o${order}_np${np})
  scheme_args(${order} scheme)
  add_test(NAME ${name} COMMAND ${MPI_RUN} ${np} ${UNILAG} run ${SCENES}/variants${dim}d.yaml --quiet --check
           ${VARIANT_${variant}} ${scheme} ${FORCED} --output ${WORK}/${name})
  set_tests_properties(${name} PROPERTIES PROCESSORS ${np} FIXTURES_SETUP repartition${dim}d_${variant}_o${order}
                       LABELS "gpr;mpi;regression")
endfunction()
function(repartition_agree dim variant order)
  set(runs "")
  foreach(np IN LISTS ARGN)
    repartition_run(${dim} ${variant} ${order} ${np})
    list(APPEND runs ${WORK}/repartition${dim}d_${variant}_o${order}_np${np})
  endforeach()
  set(name repartition${dim}d_${variant}_o${order})
  string(REPLACE ";" " " runs "${runs}")
  add_test(NAME ${name}_agree COMMAND bash -c "${PYTHON} ${SCRIPTS}/compare_runs.py 0 \
${WORK}/variant${dim}d_${variant}_o${order}_np1 ${runs} && ${PYTHON} ${SCRIPTS}/repartitioned.py 10 3 ${runs}")
  set_tests_properties(${name}_agree PROPERTIES FIXTURES_REQUIRED "${name};variant${dim}d_${variant}"
                       LABELS "gpr;mpi;regression")
endfunction()
repartition_agree(2 hydro 1 1 2 3 4)
repartition_agree(2 hydro 2 2 4)
repartition_agree(2 plastic 2 3)
repartition_agree(2 plastic ars 2)
repartition_agree(3 viscous_heat 1 2)
repartition_agree(3 viscous_heat 2 3)

add_test(NAME repartition_impact2d_o2_np2 COMMAND ${MPI_RUN} 2 ${UNILAG} run ${INPUTS}/impact2d.yaml --quiet --check
         --set scheme.order=2 --set time.end=2.5e-6 ${FORCED} --output ${WORK}/repartition_impact2d_o2_np2)
set_tests_properties(repartition_impact2d_o2_np2 PROPERTIES PROCESSORS 2 FIXTURES_SETUP repartition_impact2d
                     LABELS "gpr;mpi;regression")
add_test(NAME repartition_impact2d_agree COMMAND bash -c "${PYTHON} ${SCRIPTS}/compare_runs.py 0 \
${WORK}/impact2d_o2_np1 ${WORK}/repartition_impact2d_o2_np2 && ${PYTHON} ${SCRIPTS}/repartitioned.py 10 3 \
${WORK}/repartition_impact2d_o2_np2")
set_tests_properties(repartition_impact2d_agree PROPERTIES FIXTURES_REQUIRED "repartition_impact2d;impact2d"
                     LABELS "gpr;mpi;regression")
# rcb (Zoltan 1 under Zoltan2) printed its ~40 parameters on every rank at each repartition, --quiet or not.
add_test(NAME repartition_rcb_quiet COMMAND ${MPI_RUN} 3 ${UNILAG} run ${INPUTS}/sod2d.yaml --quiet --set mesh.size=0.05
         --set time.end=0.05 --set parallel.partitioner=rcb --set parallel.imbalance_threshold=0
         --set parallel.check_interval=1 --output ${WORK}/repartition_rcb_quiet)
set_tests_properties(repartition_rcb_quiet PROPERTIES PROCESSORS 3 LABELS "mpi;regression"
                     PASS_REGULAR_EXPRESSION "output in" FAIL_REGULAR_EXPRESSION "ZOLTAN")

# Checkpoint and restart (issue 14 item 2, README "Checkpoint and restart"; tests/scripts/expect_restart.sh): a run
# checkpointed at mid-time (output.checkpoint_interval, then stopped by time.max_steps; or stopped by SIGTERM) and
# restarted, on the same number of ranks or another, ends bit for bit equal to the uninterrupted run on one rank
# (every field of the last dump, summary status and steps, steps.csv). Order 1 and 2, a plastic scene (strain +
# plastic hints in the checkpoint), a heat-conducting one at order 2, ARS(2,2,2) (its lagged stage velocities).
set(RESTART ${SCRIPTS}/expect_restart.sh)
set(RESTART_SEDOV ${INPUTS}/sedov2d.yaml --set mesh.size=0.0288 --set output.interval=0.1)
function(restart_test name mode ra rb)
    add_test(NAME restart_${name} COMMAND bash ${RESTART} ${WORK}/restart_${name} ${mode} ${ra} ${rb} ${PYTHON}
             ${SCRIPTS}/compare_runs.py -- ${UNILAG} ${ARGN})
    set(procs ${ra})
    if(rb GREATER ra)
        set(procs ${rb})
    endif()
    set_tests_properties(restart_${name} PROPERTIES LABELS "regression;mpi" PROCESSORS ${procs})
endfunction()
restart_test(sedov_np1_np1 interval:0.4:320 1 1 ${RESTART_SEDOV})
restart_test(sedov_order2_np2_np3 interval:0.4:480 2 3 ${RESTART_SEDOV} --set scheme.order=2)
restart_test(sedov_order2_signal_np1_np2 signal 1 2 ${RESTART_SEDOV} --set scheme.order=2)
restart_test(sedov_order2_signal_np2_np1 signal 2 1 ${RESTART_SEDOV} --set scheme.order=2)
# (balance checks every 10 steps: the first run checks at 60 and 70, past its checkpoint at step 52, rows the
# restart on one rank must cut from balance.csv)
restart_test(impact_np2_np1 interval:2.5e-6:70 2 1 ${INPUTS}/impact2d.yaml --set mesh.size=0.002
             --set output.interval=0 --set parallel.check_interval=10)
restart_test(heat_order2_np1_np2 interval:0.5:240 1 2 ${INPUTS}/heat_conduction2d.yaml --set mesh.size=0.02
             --set scheme.order=2 --set output.interval=0)
# repartitioned every 10 steps before and after the restart (parallel.partitioner sfc: cells really move)
restart_test(sedov_order2_repartition_np2_np3 interval:0.4:480 2 3 ${RESTART_SEDOV} --set scheme.order=2
             --set parallel.check_interval=10 --set parallel.imbalance_threshold=0 --set parallel.partitioner=sfc)
restart_test(vortex_ars222_np3_np2 interval:0.5:28 3 2 ${INPUTS}/vortex2d.yaml --set scheme.order=2
             --set scheme.integrator=ars222 --set output.interval=0)

# A checkpoint that cannot serve: missing, truncated, from another scene, mesh or scheme. Exit 2, one message, and
# the output folder untouched (expect_error.sh: not even created).
add_test(NAME restart_source COMMAND ${UNILAG} run ${SMALL_SEDOV} --set output.checkpoint_interval=0.1
         --output ${WORK}/restart_source)
add_test(NAME restart_truncate COMMAND bash -c "head -c 3000 '${WORK}/restart_source/checkpoint.h5' > '${WORK}/truncated.h5'")
# Corrupt checkpoints (restart_corrupt.py writes them from restart_source's): a table value with one byte changed
# (before the checksums: the run went on with it, or stopped unstable, exit 0 or 4), the identity text 'hydro' with
# two bytes overwritten, and the format text with one byte outside ASCII (named with '?', not printed raw).
add_test(NAME restart_corrupt COMMAND ${PYTHON} ${SCRIPTS}/restart_corrupt.py ${WORK}/restart_source/checkpoint.h5
         ${WORK})
set_tests_properties(restart_source PROPERTIES FIXTURES_SETUP restart_source LABELS regression)
set_tests_properties(restart_truncate restart_corrupt PROPERTIES FIXTURES_REQUIRED restart_source
                     FIXTURES_SETUP restart_truncated LABELS regression)
set(CK ${WORK}/restart_source/checkpoint.h5)
function(restart_error name file pattern)
    add_test(NAME error_restart_${name} COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_restart_${name}
             "--restart '.*': ${pattern}" -- ${UNILAG} run ${ARGN} --restart ${file})
    set_tests_properties(error_restart_${name} PROPERTIES FIXTURES_REQUIRED "restart_source;restart_truncated"
                         LABELS regression)
endfunction()
restart_error(missing ${WORK}/none.h5 "not a readable checkpoint" ${SMALL_SEDOV})
restart_error(dump ${WORK}/restart_source/unilag_000000.h5 "an HDF5 file but not a unilag checkpoint" ${SMALL_SEDOV})
restart_error(truncated ${WORK}/truncated.h5 "not a readable checkpoint \\(missing, truncated or corrupt HDF5\\)"
              ${SMALL_SEDOV})
restart_error(other_scene ${CK} "a checkpoint of another run \\(title 'sedov2d', this scene 'vortex2d'\\)"
              ${INPUTS}/vortex2d.yaml --quiet)
restart_error(corrupt_table ${WORK}/corrupt_table.h5 "corrupt: table 'cell.state' does not match its checksum$"
              ${SMALL_SEDOV})
restart_error(corrupt_text ${WORK}/corrupt_text.h5 "corrupt: text 'physics' does not match its checksum$"
              ${SMALL_SEDOV})
restart_error(corrupt_format ${WORK}/corrupt_format.h5
              "not a unilag checkpoint of this version \\(format '\\?\\?ilag checkpoint 4', expected 'unilag checkpoint 4'\\)$"
              ${SMALL_SEDOV})
restart_error(forged_loop ${WORK}/forged_loop.h5 "the loop's dump count is not a finite number$" ${SMALL_SEDOV})
restart_error(other_mesh ${CK} "a checkpoint of another run \\(cells '988', this scene '3988'\\)" ${SMALL_SEDOV}
              --set mesh.size=0.0288)
restart_error(other_order ${CK} "a checkpoint of another run \\(order '1', this scene '2'\\)" ${SMALL_SEDOV}
              --set scheme.order=2)
# the materials, boundaries and scheme keys of the resolved scene, whichever differs first (by key, any order)
restart_error(other_material ${CK}
              "a checkpoint of another scene \\(materials.gas.gamma: '1.4' in the checkpoint, '1.67'" ${SMALL_SEDOV}
              --set materials.gas.gamma=1.67)
restart_error(other_limiter ${CK}
              "a checkpoint of another scene \\(scheme.limiter: 'barth_jespersen' in the checkpoint, 'none'" ${SMALL_SEDOV}
              --set scheme.limiter=none)
restart_error(other_boundary ${CK}
              "a checkpoint of another scene \\(boundaries.outer.type: 'slip_wall' in the checkpoint, 'free'" ${SMALL_SEDOV}
              --set boundaries.outer.type=free)
# a checkpoint at or after the new end time has nothing to continue
add_test(NAME error_restart_end_before COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_restart_end_before
         "sedov2d.yaml: key 'time.end': 0.05 is not after the checkpoint's time" -- ${UNILAG} run ${SMALL_SEDOV}
         --set time.end=0.05 --restart ${CK})
set_tests_properties(error_restart_end_before PROPERTIES FIXTURES_REQUIRED restart_source LABELS regression)

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
# A list inside a list (Teuchos' assertion named only its own source file), a FIFO as the scene or the mesh (the
# reader blocked for ever), more threads than Kokkos' OpenMP backend survives (520 segfaulted).
add_test(NAME error_nested_list COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_nested
         "error_nested_list.yaml: malformed YAML: a list or section where a single value belongs" -- ${UNILAG} run
         ${SCENES}/error_nested_list.yaml)
add_test(NAME error_fifo_inputs COMMAND bash -c "rm -f ${WORK}/fifo.yaml ${WORK}/fifo.geo && mkfifo ${WORK}/fifo.yaml \
         ${WORK}/fifo.geo && bash ${SCRIPTS}/expect_error.sh ${WORK}/err_fifo1 'fifo.yaml: not a regular file' -- \
         timeout 20 ${UNILAG} run ${WORK}/fifo.yaml && bash ${SCRIPTS}/expect_error.sh ${WORK}/err_fifo2 \
         \"key 'mesh.geometry': not a regular file: .*fifo.geo\" -- timeout 20 ${UNILAG} run ${INPUTS}/sedov2d.yaml \
         --quiet --set mesh.geometry=${WORK}/fifo.geo")
add_test(NAME error_too_many_threads COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_threads
         "600 threads a rank \\(--threads or OMP_NUM_THREADS\\): at most 512" -- ${UNILAG} run ${SMALL_SEDOV}
         --threads 600)
set_tests_properties(error_nested_list error_fifo_inputs error_too_many_threads PROPERTIES LABELS regression)
# An empty --output or --restart was ignored (the scene's folder written instead); an end time far beyond the run's
# steps (1e300) was reported as a collapsed time step at t = 0 (exit 4): it runs to time.max_steps (exit 5), which
# the scene sets (past step 25, where a run that cannot reach its end time stops when max_steps is not set).
add_test(NAME error_empty_output_option COMMAND bash -c "msg=$(${UNILAG} run ${INPUTS}/sod2d.yaml --quiet \
         --output '' 2>&1); rc=$?; echo \"$msg\"; [ $rc -eq 2 ] && echo \"$msg\" | grep -q -e \
         '--output needs a folder, found an empty string'")
add_test(NAME end_time_far_runs_to_step_cap COMMAND bash -c "msg=$(${UNILAG} run ${INPUTS}/sod2d.yaml --quiet \
         --set time.end=1e300 --set time.max_steps=40 --set output.interval=0 --output ${WORK}/far_end 2>&1); \
         rc=$?; echo \"$msg\"; [ $rc -eq 5 ] && echo \"$msg\" | grep -q 'time.max_steps = 40 reached'")
set_tests_properties(error_empty_output_option end_time_far_runs_to_step_cap PROPERTIES LABELS regression)
# An output interval of 1e-9 asked for 2e8 dumps (each clips the step): refused, as in the tube runs.
add_test(NAME error_output_interval_tiny COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_interval
         "sod2d.yaml: key 'output.interval': 1e-09 makes 2e\\+08 dumps to the end time 0.2: at most 100000"
         -- ${UNILAG} run ${INPUTS}/sod2d.yaml --set output.interval=1e-9)
add_test(NAME tube_error_output_interval_tiny COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/tube_err_interval
         "tube_flutter.yaml: key 'dynamics.output_interval': 1e-09 makes 3e\\+10 dumps"
         -- ${UNILAG} run ${INPUTS}/tube_flutter.yaml --set dynamics.output_interval=1e-9)
set_tests_properties(error_output_interval_tiny tube_error_output_interval_tiny PROPERTIES LABELS regression)
# Found by fuzzing the readers (session 34); each ran with exit 0, looped, crashed or corrupted the heap before.
# A checkpoint every 1e-17 looped at t = 0 and ignored SIGTERM; a decimal comma ran as its last number (1,5 -> 5);
# a key beside 'unilag:' was dropped; a 300-character path stopped with an internal error; mesh.size 1e-9 meshed for
# ever; a .geo's Exit command returned 0; one second-order triangle in a linear .msh corrupted gmsh's heap; a tube
# scan step of 1e-320 reported no instability and a bisection tolerance of 1e-320 never ended.
set(LONG_NAME "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx")
function(fuzz_error name pattern scene)
    set(extra)
    if(ARGN)
        set(extra --set "${ARGN}")
    endif()
    add_test(NAME error_fuzz_${name} COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_fuzz_${name} "${pattern}"
             -- ${UNILAG} run ${scene} ${extra})
    set_tests_properties(error_fuzz_${name} PROPERTIES LABELS regression)
endfunction()
fuzz_error(checkpoint_tiny "key 'output.checkpoint_interval': 1e-17 makes 2e\\+16 checkpoints" ${INPUTS}/sod2d.yaml
           output.checkpoint_interval=1e-17)
fuzz_error(decimal_comma "key 'regions.gas.density': '1,5' holds 2 comma-separated values" ${INPUTS}/sod2d.yaml
           regions.gas.density=1,5)
fuzz_error(assignment "key 'regions.gas.pressure': 'x = 3' assigns" ${INPUTS}/sod2d.yaml "regions.gas.pressure=x = 3")
fuzz_error(top_level_key "error_top_level_key.yaml: line 8: unknown top-level key 'other'"
           ${SCENES}/error_top_level_key.yaml)
fuzz_error(name_too_long "key 'mesh.geometry': File name too long" ${INPUTS}/sod2d.yaml
           mesh.geometry=${LONG_NAME}${LONG_NAME}${LONG_NAME})
fuzz_error(mesh_size_tiny "key 'mesh.size': 1e-09 asks for about .* cells" ${INPUTS}/sod2d.yaml mesh.size=1e-9)
fuzz_error(geo_exit "exit_command.geo: gmsh ended the process" ${INPUTS}/sod2d.yaml
           mesh.geometry=${PROJECT_SOURCE_DIR}/tests/meshes/exit_command.geo)
fuzz_error(second_order_element "one_tri6.msh: line 47: element 22 has type 9, a second-order element"
           ${SCENES}/inverted.yaml mesh.file=../meshes/one_tri6.msh)
fuzz_error(tube_scan_step "key 'stability.speed_step': .* scan points" ${INPUTS}/tube_stability.yaml
           stability.speed_step=1e-320)
fuzz_error(tube_tolerance "key 'stability.tolerance': must be in" ${INPUTS}/tube_stability.yaml
           stability.tolerance=1e-320)
# Session 35: a .msh whose format line says binary over a text body (gmsh: "Unknown type of element 824193312"),
# two elements with one tag (gmsh kept one: "boundary face ... in no boundary physical group"), a tetrahedron in a
# flat mesh ("degenerate" in a region named '2'); [[1]] for a number ('1x1:{1}'), 'unilag: ~' (no line), -.inf
# (a line and column only).
fuzz_error(msh_text_as_binary "text_as_binary.msh: line 3: after a format line of file-type 1 \\(binary\\) the file goes on as text"
           ${SCENES}/inverted.yaml mesh.file=../meshes/text_as_binary.msh)
fuzz_error(msh_duplicate_element "duplicate_element.msh: line 26: element 7 is defined twice"
           ${SCENES}/inverted.yaml mesh.file=../meshes/duplicate_element.msh)
fuzz_error(msh_flat_tet "flat_tet.msh: the mesh has 3D elements \\(tetrahedra\\) but every node at the same z"
           ${SCENES}/inverted.yaml mesh.file=../meshes/flat_tet.msh)
fuzz_error(list_of_lists "key 'time.cfl': expected a number, found a list of lists$" ${SCENES}/error_list_of_lists.yaml)
fuzz_error(null_section "error_null_section.yaml: line 2: 'unilag:' holds the value '~', not a section of keys"
           ${SCENES}/error_null_section.yaml)
fuzz_error(minus_inf "error_minus_inf.yaml: malformed YAML: line 7, column 28: the YAML reader cannot parse 'time: \\{ end: 0.1, cfl: -.inf \\}'"
           ${SCENES}/error_minus_inf.yaml)
# The study and plot scripts in apps/ gave Python tracebacks on a bad argument or a missing input folder.
add_test(NAME apps_script_errors COMMAND bash ${SCRIPTS}/script_errors.sh ${PYTHON} ${PROJECT_SOURCE_DIR}/apps)
set_tests_properties(apps_script_errors PROPERTIES LABELS regression PASS_REGULAR_EXPRESSION "script_errors: PASS")
# A malformed .msh is refused with its line before gmsh reads it (mesh/MshCheck.hpp): gmsh 4.8 crashed (segmentation
# fault) on the first, a node line without z, as on many of apps/fuzz_scenes.py's --mesh cases; the second (format
# 4.1, an element's node that does not exist) gmsh refused itself, without the line.
add_test(NAME error_mesh_missing_z COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_msh2
         "missing_z.msh: line 15: a node 'tag x y z': expected 4 fields, found 3"
         -- ${UNILAG} run ${SCENES}/error_mesh_missing_z.yaml)
add_test(NAME error_mesh_undefined_node COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_msh4
         "undefined_node41.msh: line 55: element 6 refers to node 9, which .Nodes does not define"
         -- ${UNILAG} run ${SCENES}/error_mesh_undefined_node41.yaml)
# A .geo gmsh accepts but crashes on (its 2D algorithm 8 in Debian's 4.8.4): one line naming it, exit 2, no output.
add_test(NAME error_gmsh_crash COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_gmsh_crash
         "quadrant_gmsh_crash.geo: gmsh crashed reading or meshing it" -- ${UNILAG} run ${INPUTS}/sedov2d.yaml
         --set mesh.mesher=gmsh --set mesh.geometry=${CMAKE_CURRENT_SOURCE_DIR}/meshes/quadrant_gmsh_crash.geo)
# gmsh 4.8.4 throws from its own threads on this one: the runtime's terminate message must not add a line.
add_test(NAME error_gmsh_throw COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_gmsh_throw
         "octant_gmsh_throw.geo: gmsh crashed reading or meshing it" -- ${UNILAG} run ${INPUTS}/sedov3d.yaml
         --set mesh.size=0.3 --set mesh.mesher=gmsh
         --set mesh.geometry=${CMAKE_CURRENT_SOURCE_DIR}/meshes/octant_gmsh_throw.geo)
# Elements other than linear simplices in a region (here quadrangles beside triangles) are refused by name.
add_test(NAME error_mixed_elements COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_mixed_elements
         "mixed_tri_quad.geo: element [0-9]+ is a Quadrilateral 4 \\(and [0-9]+ more\\): unilag takes linear triangles"
         -- ${UNILAG} run ${INPUTS}/sedov2d.yaml --set mesh.size=0.1 --set mesh.mesher=gmsh
         --set mesh.geometry=${CMAKE_CURRENT_SOURCE_DIR}/meshes/mixed_tri_quad.geo)
# mesh.mesher: lattice meshes one axis-aligned rectangle (LatticeMesh.hpp); a quarter annulus is refused by its arc;
# a mesher with a .msh said "unknown key".
fuzz_error(mesher_with_file "key 'mesh.mesher': a .msh \\(mesh.file\\) is read as it is" ${SCENES}/inverted.yaml
           mesh.mesher=lattice)
add_test(NAME error_lattice_not_rectangle COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_lattice
         "quarter_annulus2d.geo: mesh.mesher lattice meshes an axis-aligned rectangle; curve [0-9]+ is not on a side of its bounding box"
         -- ${UNILAG} run ${INPUTS}/sedov2d.yaml --set mesh.geometry=geometry/quarter_annulus2d.geo)
add_test(NAME error_limiter COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err7
         "sedov2d.yaml: key 'scheme.limiter': 'minmod' is not one of: barth_jespersen, vertex_based, node_fit, none"
         -- ${UNILAG} run ${INPUTS}/sedov2d.yaml --set scheme.limiter=minmod)
# scheme.pressure_limiter bounds a reconstructed pressure: with reconstruct: velocity there is none.
add_test(NAME error_pressure_limiter COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err8
         "sedov2d.yaml: key 'scheme.pressure_limiter': the pressure is not reconstructed with reconstruct: velocity"
         -- ${UNILAG} run ${INPUTS}/sedov2d.yaml --set scheme.pressure_limiter=vertex_based)
# scheme.entropy_filter above 0.25 could take a cell's eps out of its neighbours' range (EntropyFilter.hpp).
add_test(NAME error_entropy_filter COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_entropy_filter
         "sedov2d.yaml: key 'scheme.entropy_filter': must be in \\[0, 0.25\\].*found 0.3"
         -- ${UNILAG} run ${INPUTS}/sedov2d.yaml --set scheme.entropy_filter=0.3)
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
# A section or a list where a number belongs: named as the scene wrote it, on one line (Teuchos printed a section over
# several lines with its own type name, "found 'ParameterList' 'value = 1.4   [unused]", and a list at 17 digits).
add_test(NAME error_section_value COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_section
         "error_section_value.yaml: key 'materials.gas.gamma': expected a number, found a section of keys$"
         -- ${UNILAG} run ${SCENES}/error_section_value.yaml)
add_test(NAME error_list_value COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_list
         "error_gamma.yaml: key 'materials.gas.gamma': expected a number, found a list \\[1.4, 2\\]$"
         -- ${UNILAG} run ${SCENES}/error_gamma.yaml --set "materials.gas.gamma=[1.4, 2]")
set_tests_properties(error_gamma error_negative_csh error_negative_tau error_unknown_eos error_unknown_law
                     error_section_value error_list_value PROPERTIES LABELS regression)
# A run that goes unstable stops with a diagnosis (exit 4) and never writes NaNs. A rejected update names the cell by
# its global id and centroid at t, the time, the halvings, and the cell's values (volume ratio and volumes, density,
# specific internal energy with the total and kinetic energies and the total before the step, squared sound speed:
# negative here, the Mie-Grueneisen solid torn in tension); the text is
# the same on 1 and 2 ranks (global id, bitwise-equal values). Measured: cell 25 at t = 0.0998035, c^2 = -1.24e-4
# (numbers are not pinned: the physics may move them; the rank comparison pins the text).
set(NUM "-?[0-9][0-9.e+-]*")
add_test(NAME unstable_diagnosis COMMAND bash ${SCRIPTS}/expect_unstable.sh ${WORK}/unstable --ranks "1 2" --mpirun ${MPIEXEC_EXE}
         "the run went unstable: cell [0-9]+ \\(centroid ${NUM}, ${NUM}, 0\\) at t = ${NUM} after 2 halvings of dt \\(last dt ${NUM}\\): "
         "volume ratio ${NUM} \\(volume ${NUM} -> ${NUM}\\), density ${NUM}, specific internal energy ${NUM} "
         "\\(total ${NUM}, kinetic ${NUM}, before the step ${NUM}\\), squared sound speed -[0-9][0-9.e+-]*$"
         -- ${UNILAG} run ${SCENES}/unstable_tension.yaml --quiet)
# A mesh that tangles (a piston crushes the box against the far wall at t = 1): the time step collapses and the
# diagnosis names the step, the time and the smallest cell by global id (1 rank: 53,000 steps, 4 s; 880,000 and 64 s
# while the collapse floor was 1e-12 of the end time alone).
add_test(NAME collapse_diagnosis COMMAND bash ${SCRIPTS}/expect_unstable.sh ${WORK}/collapse
         "the run went unstable: the time step collapsed to ${NUM} at t = (1|0\\.9999[0-9]*) \\(step [0-9]+\\); the smallest cell is [0-9]+ with volume ${NUM}: the mesh is tangling there$"
         -- ${UNILAG} run ${SCENES}/piston_collapse.yaml --quiet --set mesh.size=0.34)
# A steady step that cannot reach the end time (gamma 1e20: dt 1e-24 for t = 1, an ETA of 1e20 s) stops at once,
# naming the cell with the shortest acoustic time and its speed, the same on 1 and 2 ranks; it ran to max_steps.
add_test(NAME stalled_diagnosis COMMAND bash ${SCRIPTS}/expect_unstable.sh ${WORK}/stalled --ranks "1 2" --mpirun ${MPIEXEC_EXE}
         "the run went unstable: the time step ${NUM} at t = ${NUM} \\(step 25\\) leaves about ${NUM} steps to the end "
         "time 0.3: the run would not end \\(time.max_steps, if set, runs it to that step count\\); the shortest "
         "acoustic time is cell [0-9]+'s: signal speed ${NUM} over length ${NUM} \\(density 1, pressure ${NUM}\\): "
         "check the materials' values and time.cfl$"
         -- ${UNILAG} run ${SMALL_SEDOV} --quiet --set materials.gas.gamma=1e20)
set_tests_properties(stalled_diagnosis PROPERTIES LABELS "regression;mpi" PROCESSORS 2)
set_tests_properties(unstable_diagnosis PROPERTIES LABELS "regression;mpi" PROCESSORS 2)
set_tests_properties(collapse_diagnosis PROPERTIES LABELS regression)
set_tests_properties(error_malformed_scene error_unknown_key error_inverted_mesh error_negative_density
                     error_missing_mesh error_limiter error_mpi_unknown_key PROPERTIES LABELS regression)

# A Picard loop capped below what an elastic step needs is never accepted unconverged: each step is cut and retried,
# and when the retries run out the run stops with the diagnosis (exit 4, no NaN).
add_test(NAME picard_cap_diagnosis COMMAND bash ${SCRIPTS}/expect_unstable.sh ${WORK}/picard_cap
         "the run went unstable: at t = ${NUM} after 3 halvings of dt: .*Picard loop did not converge in 2 iterations"
         -- ${UNILAG} run ${SCENES}/traction_wave.yaml --quiet --set scheme.picard_max_iterations=2 --set time.max_retries=3)
set_tests_properties(picard_cap_diagnosis PROPERTIES LABELS "gpr;regression")

# Scene and mesh disagree (tested both ways): a scene region or boundary with no physical group in the mesh, and a
# mesh group the scene leaves without an initial state or a condition. Each names the scene file, the key, the name
# and the mesh file, exit 2, no output folder.
add_test(NAME error_boundary_unknown COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_bnd_unknown
         "sedov2d.yaml: key 'boundaries.outr': no boundary physical group 'outr' in mesh .*geometry/quadrant2d.geo \\(it has: axis_x, axis_y, outer\\)"
         -- ${UNILAG} run ${SMALL_SEDOV} --set boundaries.outr.type=slip_wall)
add_test(NAME error_boundary_missing COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_bnd_missing
         "error_boundary_missing.yaml: key 'boundaries': mesh .*geometry/square2d.geo has a boundary physical group 'top' with no condition"
         -- ${UNILAG} run ${SCENES}/error_boundary_missing.yaml --quiet)
add_test(NAME error_region_unknown COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_reg_unknown
         "error_region_unknown.yaml: key 'regions.gaz': no region physical group 'gaz' in mesh .*geometry/square2d.geo \\(it has: gas\\)"
         -- ${UNILAG} run ${SCENES}/error_region_unknown.yaml --quiet)
add_test(NAME error_region_missing COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_reg_missing
         "error_region_missing.yaml: key 'regions': mesh .*geometry/impact2d.geo has a region physical group 'projectile' with no initial state"
         -- ${UNILAG} run ${SCENES}/error_region_missing.yaml --quiet)
# The same on 2 ranks: the mesh is read on rank 0, the message printed once.
add_test(NAME error_mpi_boundary_unknown COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_mpi_bnd
         "sedov2d.yaml: key 'boundaries.outr': no boundary physical group 'outr'"
         -- ${MPI_RUN} 2 ${UNILAG} run ${SMALL_SEDOV} --set boundaries.outr.type=slip_wall)
set_tests_properties(error_mpi_boundary_unknown PROPERTIES PROCESSORS 2)

# The exact-solution table (exact.table) is read with the scene, before anything runs: a missing file, a row whose
# column count differs from the header's (file and line named), a radius that does not increase (line named), a
# header without 'position' and 'density'. Each: the scene file and key, then the table's problem; exit 2.
add_test(NAME error_exact_missing COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_exact_missing
         "sedov2d.yaml: key 'exact.table': file not found: .*nowhere.csv" -- ${UNILAG} run ${SMALL_SEDOV} --set exact.table=nowhere.csv)
add_test(NAME error_exact_row COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_exact_row
         "sedov2d.yaml: key 'exact.table': .*error_exact_row.csv line 5: expected 6 comma-separated columns as in the header, found 5"
         -- ${UNILAG} run ${SMALL_SEDOV} --set exact.table=${SCENES}/error_exact_row.csv)
add_test(NAME error_exact_order COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_exact_order
         "sedov2d.yaml: key 'exact.table': .*error_exact_order.csv line 5: position 1.0e-03 does not increase"
         -- ${UNILAG} run ${SMALL_SEDOV} --set exact.table=${SCENES}/error_exact_order.csv)
add_test(NAME error_exact_columns COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_exact_columns
         "sedov2d.yaml: key 'exact.table': .*error_exact_columns.csv line 2: the header 'position,pressure' must name the columns 'position' and 'density'"
         -- ${UNILAG} run ${SMALL_SEDOV} --set exact.table=${SCENES}/error_exact_columns.csv)
# A table that ends before the shock: beyond its last row the profile is that row's, not the ambient state (a table
# cut at r = 0.297 gave L1 0.995 on Sedov, exit 0). Here the shipped table (to r = 1.2) against a shock at 1.5.
add_test(NAME error_exact_short COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_exact_short
         "sedov2d.yaml: key 'exact.table': .*ends at position 1.200000, not past the shock \\(shock_radius 1.500000\\)"
         -- ${UNILAG} run ${SMALL_SEDOV} --set exact.shock_radius=1.5)

# exact.solution: riemann (inputs/sod2d.yaml): states that create a vacuum, and a material that is not an ideal gas.
add_test(NAME error_riemann_vacuum COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_riemann_vacuum
         "sod2d.yaml: key 'exact.right': the two states create a vacuum" -- ${UNILAG} run ${INPUTS}/sod2d.yaml
         --set exact.right.velocity=20)
add_test(NAME error_riemann_eos COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_riemann_eos
         "error_riemann_eos.yaml: key 'exact.solution': 'riemann' is the exact solution of an ideal gas of one gamma; material 'metal' is not one"
         -- ${UNILAG} run ${SCENES}/error_riemann_eos.yaml)

# Command-line errors: exit 2, one message, nothing written. (expect_error.sh appends --output OUTDIR.)
add_test(NAME error_cli_unknown_option COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_cli_option
         "unknown option '--chek' \\(see unilag --help\\)" -- ${UNILAG} run ${SMALL_SEDOV} --chek)
add_test(NAME error_cli_no_scene COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_cli_scene
         "run needs a scene file" -- ${UNILAG} run --quiet)
add_test(NAME error_cli_unknown_command COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_cli_command
         "unknown command 'rnu'" -- ${UNILAG} rnu ${SMALL_SEDOV})
add_test(NAME error_cli_set_no_value COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_cli_set
         "sedov2d.yaml: --set 'time.end': expected key.path=value" -- ${UNILAG} run ${SMALL_SEDOV} --set time.end)
add_test(NAME error_cli_set_unknown_key COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_cli_set_key
         "sedov2d.yaml: key 'time.ned': unknown key \\(did you mean 'time.end'" -- ${UNILAG} run ${SMALL_SEDOV} --set time.ned=0.1)
# --output where no folder can be made: under /proc, and through a regular file (the scene file itself).
add_test(NAME error_cli_output_proc COMMAND bash ${SCRIPTS}/expect_error.sh /proc/unilag_out
         "--output '/proc/unilag_out': cannot create folders in /proc" -- ${UNILAG} run ${SMALL_SEDOV})
add_test(NAME error_cli_output_file COMMAND bash ${SCRIPTS}/expect_error.sh ${SCENES}/error_gamma.yaml/out
         "--output '.*error_gamma.yaml/out': .*error_gamma.yaml is not a folder" -- ${UNILAG} run ${SMALL_SEDOV})
# An energy deposit outside the mesh (it would go to the nearest node, wherever that is).
add_test(NAME error_deposit_outside COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_deposit
         "sedov2d.yaml: key 'energy_deposit.position': \\[5, 5\\] lies outside the mesh"
         -- ${UNILAG} run ${SMALL_SEDOV} --set energy_deposit.position=[5.0,5.0])
# A dump that cannot be written mid-run (on 1 and 2 ranks: every rank stops alike), and a run stopped by max_steps.
add_test(NAME error_output_write_failure COMMAND bash ${SCRIPTS}/expect_stop.sh ${WORK}/err_write write_failure
         -- ${UNILAG} run ${SMALL_SEDOV})
add_test(NAME error_mpi_output_write_failure COMMAND bash ${SCRIPTS}/expect_stop.sh ${WORK}/err_mpi_write
         write_failure -- ${MPI_RUN} 2 ${UNILAG} run ${SMALL_SEDOV})
set_tests_properties(error_mpi_output_write_failure PROPERTIES PROCESSORS 2)
# A full disk under a dump (1 and 2 ranks), a folder where summary.json goes, a full disk under steps.csv.
foreach(case disk_full summary_in_the_way steps_full)
    add_test(NAME error_output_${case} COMMAND bash ${SCRIPTS}/expect_stop.sh ${WORK}/err_${case} ${case}
             -- ${UNILAG} run ${SMALL_SEDOV})
    set_tests_properties(error_output_${case} PROPERTIES LABELS regression)
endforeach()
add_test(NAME error_mpi_output_disk_full COMMAND bash ${SCRIPTS}/expect_stop.sh ${WORK}/err_mpi_disk_full disk_full
         -- ${MPI_RUN} 2 ${UNILAG} run ${SMALL_SEDOV})
set_tests_properties(error_mpi_output_disk_full PROPERTIES PROCESSORS 2 LABELS "regression;mpi")
add_test(NAME stop_max_steps COMMAND bash ${SCRIPTS}/expect_stop.sh ${WORK}/max_steps max_steps
         -- ${UNILAG} run ${SMALL_SEDOV} --set time.max_steps=5)
# Under mpirun a bad option is reported by rank 0 alone (expect_error.sh asserts exactly one error line).
add_test(NAME error_mpi_cli_unknown_option COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_mpi_cli
         "unknown option '--chek'" -- ${MPI_RUN} 2 ${UNILAG} run ${SMALL_SEDOV} --chek)
set_tests_properties(error_mpi_cli_unknown_option PROPERTIES PROCESSORS 2)
set_tests_properties(error_boundary_unknown error_boundary_missing error_region_unknown error_region_missing
                     error_mpi_boundary_unknown error_exact_missing error_exact_row error_exact_order error_exact_columns
                     error_cli_unknown_option error_cli_no_scene error_cli_unknown_command error_cli_set_no_value
                     error_cli_set_unknown_key error_cli_output_proc error_cli_output_file error_mpi_cli_unknown_option
                     error_deposit_outside error_output_write_failure stop_max_steps error_riemann_vacuum error_riemann_eos
                     PROPERTIES LABELS regression)
set_tests_properties(error_mpi_boundary_unknown error_mpi_cli_unknown_option error_mpi_output_write_failure
                     PROPERTIES LABELS "regression;mpi")

# A re-run into the same folder: a long run (4 dumps) then a short one (2 dumps). The short run removes the long
# run's outputs by name and nothing else; see expect_rerun_clears.sh for each assertion.
add_test(NAME output_rerun_clears COMMAND bash ${SCRIPTS}/expect_rerun_clears.sh ${WORK}/rerun
         "--set time.end=0.3 --set output.interval=0.1" "--set time.end=0.1 --set output.interval=0.1"
         -- ${UNILAG} run ${SMALL_SEDOV})
set_tests_properties(output_rerun_clears PROPERTIES LABELS regression)
# An initial state that is not a number anywhere is bad input naming its key, not a run that stops at t = 0 having
# written a dump of nans: an infinite velocity, a pressure whose internal energy overflows, a boundary pressure
# that is nan from t = 0.003 on (caught by sampling the law over the run before it starts).
add_test(NAME error_infinite_velocity COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_inf_velocity
         "sod2d.yaml: key 'regions.gas.velocity': value inf at cell 0 is not finite"
         -- ${UNILAG} run ${INPUTS}/sod2d.yaml --set "regions.gas.velocity=[1/0, 0]")
add_test(NAME error_energy_overflow COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_energy_overflow
         "sod2d.yaml: key 'regions.gas.pressure': value 1e.308 at cell 0 gives a specific internal energy that is not"
         -- ${UNILAG} run ${INPUTS}/sod2d.yaml --set regions.gas.pressure=1e308)
add_test(NAME error_boundary_pressure_nan COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/err_bc_pressure_nan
         "kidder2d.yaml: key 'boundaries.inner.pressure': value -?nan at t = 0.003.* is not finite"
         -- ${UNILAG} run ${INPUTS}/kidder2d.yaml --set "boundaries.inner.pressure=t > 0.003 ? sqrt(-1) : 1")
# The tube solvers' own files: a folder where the gas tube's summary.json goes is said, exit 2 (it was silent).
add_test(NAME tube_error_summary_in_the_way COMMAND bash ${SCRIPTS}/expect_stop.sh ${WORK}/tube_err_summary
         summary_in_the_way -- ${UNILAG} run ${INPUTS}/tube_sod.yaml)
set_tests_properties(tube_error_summary_in_the_way PROPERTIES LABELS "regression;tube")

# Regression tests: the unilag CLI on scenes, with the physics asserted (--check, scripts in tests/scripts).
find_program(PVPYTHON pvpython)
find_program(MPIEXEC_EXE NAMES mpirun mpiexec REQUIRED)
set(PYTHON /usr/bin/python3)  # Debian's python3, which has python3-h5py and numpy
set(UNILAG $<TARGET_FILE:unilag>)
set(INPUTS ${PROJECT_SOURCE_DIR}/inputs)
set(SCENES ${CMAKE_CURRENT_SOURCE_DIR}/scenes)
set(SCRIPTS ${CMAKE_CURRENT_SOURCE_DIR}/scripts)
set(WORK ${CMAKE_CURRENT_BINARY_DIR}/work)
file(MAKE_DIRECTORY ${WORK})
set(MPI_RUN ${MPIEXEC_EXE} --oversubscribe --allow-run-as-root -np)
set(SMALL_SEDOV ${INPUTS}/sedov2d.yaml --quiet --set mesh.size=0.0577 --set time.end=0.3)

include(${CMAKE_CURRENT_SOURCE_DIR}/regression/accuracy.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/regression/agreement.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/regression/failures.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/regression/io.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/regression/check.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/regression/tube.cmake)

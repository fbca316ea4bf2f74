# Output: the HDF5/XDMF writer and ParaView reading it back.
# Output: the HDF5/XDMF writer on 1-3 ranks, and ParaView (pvpython) opens a run and reads density back.
add_executable(xdmf_writer_standalone io/xdmf_writer_standalone.cpp)
target_link_libraries(xdmf_writer_standalone PRIVATE unilag_core unilag::hdf5 unilag_warnings)
foreach(np 1 2 3)
  add_test(NAME xdmf_writer_np${np} COMMAND ${MPI_RUN} ${np} $<TARGET_FILE:xdmf_writer_standalone> ${WORK}/xdmf_np${np})
  set_tests_properties(xdmf_writer_np${np} PROPERTIES LABELS "io;mpi" PROCESSORS ${np})
endforeach()
set_tests_properties(xdmf_writer_np2 PROPERTIES FIXTURES_SETUP xdmf_out)
if(PVPYTHON)
  add_test(NAME paraview_reads_density COMMAND ${PVPYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/pv_read.py
           ${WORK}/impact2d_o2_np2/unilag.xmf density)
  set_tests_properties(paraview_reads_density PROPERTIES FIXTURES_REQUIRED mpi LABELS io)
  # The writer's two polylines (12 segments, 14 nodes) with the node field of its last dump (0.5 node - 6).
  add_test(NAME paraview_reads_polyline COMMAND ${PVPYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/pv_read.py
           ${WORK}/xdmf_np2/polyline.xmf pressure node)
  set_tests_properties(paraview_reads_polyline PROPERTIES FIXTURES_REQUIRED xdmf_out LABELS io
                       PASS_REGULAR_EXPRESSION "cells=12 points=14 node pressure min=-6 max=0.5")
else()
  message(WARNING "pvpython not found: the ParaView read-back test is skipped (scripts/setup.sh installs python3-paraview)")
endif()

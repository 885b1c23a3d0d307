# Installs the CVT_2 build tree into a fresh prefix, then configures, builds and runs the
# consumer project against it; with -DBUILD_TREE=ON, against the build tree itself, uninstalled
# (CVT_2_DIR); with -DSUBPROJECT=<source dir>, through add_subdirectory. With no build type in
# all three (no optimization): the consumer proves the export, it need not run fast. With
# -DEXPECTED_VERSION=x.y.z the consumer only checks that the headers it finds are that version.
# Run by the CTest tests consumer_find_package, consumer_build_tree and consumer_subproject:
#   cmake -DCVT_2_BINARY_DIR=... -DCONSUMER_SOURCE_DIR=... -DCONSUMER_BINARY_DIR=...
#         -DCONSUMER_PREFIX=... [-DBUILD_TREE=ON | -DSUBPROJECT=...] [-DGENERATOR=...]
#         [-DCXX_COMPILER=...] [-DCGAL_DIR=...] [-DEXPECTED_VERSION=...] -P run_consumer.cmake
foreach(var CVT_2_BINARY_DIR CONSUMER_SOURCE_DIR CONSUMER_BINARY_DIR CONSUMER_PREFIX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake: ${var} is not set")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer: ${what} failed (${rc})")
  endif()
endfunction()

# A fresh prefix and build each time, so that nothing left from an earlier run is found.
file(REMOVE_RECURSE ${CONSUMER_PREFIX} ${CONSUMER_BINARY_DIR})

set(configure_args -S ${CONSUMER_SOURCE_DIR} -B ${CONSUMER_BINARY_DIR})
if(SUBPROJECT)
  list(APPEND configure_args -DCVT_2_SOURCE=${SUBPROJECT})
elseif(BUILD_TREE)
  list(APPEND configure_args -DCVT_2_DIR=${CVT_2_BINARY_DIR})
else()
  run_step("install into ${CONSUMER_PREFIX}"
    ${CMAKE_COMMAND} --install ${CVT_2_BINARY_DIR} --prefix ${CONSUMER_PREFIX})
  list(APPEND configure_args -DCMAKE_PREFIX_PATH=${CONSUMER_PREFIX})
endif()
if(GENERATOR)
  list(APPEND configure_args -G ${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
if(CGAL_DIR)
  list(APPEND configure_args -DCGAL_DIR=${CGAL_DIR})
endif()
if(EXPECTED_VERSION)
  list(APPEND configure_args -DCVT_2_EXPECTED_VERSION=${EXPECTED_VERSION})
endif()
run_step("configure" ${CMAKE_COMMAND} ${configure_args})
run_step("build" ${CMAKE_COMMAND} --build ${CONSUMER_BINARY_DIR})
run_step("run" ${CONSUMER_BINARY_DIR}/cvt_2_consumer)

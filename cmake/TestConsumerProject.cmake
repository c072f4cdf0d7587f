# ctest script (cmake -P): installs the built library into a fresh temporary prefix, then
# configures, builds and runs the out-of-tree consumer examples/cpp/ against that prefix only; with
# PYTHON, plans with the Python module installed there too.
#   -DPMDPLAN_BINARY_DIR=… -DPMDPLAN_SOURCE_DIR=… [-DCONSUMER_GENERATOR=Ninja] [-DPYTHON=/usr/bin/python3]
set(work ${PMDPLAN_BINARY_DIR}/test-output/cpp-consumer)
set(prefix ${work}/prefix)
set(consumer ${work}/build)
file(REMOVE_RECURSE ${work})

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${PMDPLAN_BINARY_DIR} --prefix ${prefix})
set(generator_args)
if(CONSUMER_GENERATOR)
  set(generator_args -G ${CONSUMER_GENERATOR})
endif()
# CMAKE_PREFIX_PATH names only the temporary prefix: the consumer cannot see the build tree.
run_step("configure" ${CMAKE_COMMAND} -S ${PMDPLAN_SOURCE_DIR}/examples/cpp -B ${consumer} ${generator_args}
         -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
run_step("build" ${CMAKE_COMMAND} --build ${consumer})
# The installed data folder, not the source tree the library was built from.
run_step("run" ${CMAKE_COMMAND} -E env PMDPLAN_DATA_DIR=${prefix}/share/pmdplan/data ${consumer}/plan_can_on_table)
message(STATUS "consumer output:\n${step_output}")
if(NOT step_output MATCHES "can_on_table: solved" OR NOT step_output MATCHES "OMPL PMD: solved")
  message(FATAL_ERROR "the consumer did not report a solved plan")
endif()

if(PYTHON)
  # (no semicolons in the code: run_step's argument list would split there)
  run_step("python import" ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/lib/python3/dist-packages
           PMDPLAN_DATA_DIR=${prefix}/share/pmdplan/data ${PYTHON} -c
           "import pmdplan\nr = pmdplan.plan(pmdplan.Task.load('can_on_table'), seed=1)\nprint('python:', pmdplan.__file__, r.status)")
  message(STATUS "${step_output}")
  if(NOT step_output MATCHES "${prefix}/lib/python3/dist-packages/pmdplan/__init__.py solved")
    message(FATAL_ERROR "the installed Python module was not the one imported, or did not solve")
  endif()
endif()

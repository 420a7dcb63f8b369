# Installs the build tree TEHL_BUILD_DIR into WORK_DIR/prefix, builds the consumer project
# CONSUMER_SOURCE_DIR against it with find_package(tehl), and runs the consumer and the
# installed program. Any failing step fails the test.
foreach(var TEHL_BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR CMAKE_GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_test.cmake: -D${var}=... is required")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer-build)
file(REMOVE_RECURSE ${WORK_DIR})

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${step} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${step}: ok")
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

run("install" ${CMAKE_COMMAND} --install ${TEHL_BUILD_DIR} --prefix ${prefix})
run("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${consumer_build}
    -G ${CMAKE_GENERATOR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run("build consumer" ${CMAKE_COMMAND} --build ${consumer_build})
run("run consumer" ${consumer_build}/tehl_consumer)
message(STATUS "${last_output}")

# The installed program finds its library through its RPATH ($ORIGIN/../lib...).
file(GLOB lubricant ${prefix}/share/tehl/lubricants/sae40.toml)
if(NOT lubricant)
  message(FATAL_ERROR "no share/tehl/lubricants/sae40.toml under ${prefix}")
endif()
run("installed tehl" ${prefix}/bin/tehl lubricant ${lubricant} --p 0:1e9:3 --T 313.15)
# The documents the installed headers cite.
foreach(doc library.md theory.md reference/DESIGN.md reference/VALIDATION.md)
  if(NOT EXISTS ${prefix}/share/doc/tehl/${doc})
    message(FATAL_ERROR "no share/doc/tehl/${doc} under ${prefix}")
  endif()
endforeach()

# A lubricant by name is found in the installed share/tehl/lubricants, not in the source tree
# the program was built from, also after the prefix has been moved.
set(moved ${WORK_DIR}/moved-prefix)
file(RENAME ${prefix} ${moved})
run("installed tehl, moved prefix, lubricant by name" ${moved}/bin/tehl lubricant sae40
    --p 0:1e9:3 --T 313.15)
string(FIND "${last_output}" "${moved}/share/tehl/lubricants/sae40.toml" found)
if(found EQUAL -1)
  message(FATAL_ERROR "the moved installation did not read its own sae40.toml:\n${last_output}")
endif()

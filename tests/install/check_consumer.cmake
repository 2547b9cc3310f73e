# Builds and runs the consumer project against ncsdk, as a user would (cmake -P script).
#   -DMODE=package       cmake --install NCSDK_BUILD_DIR into WORK_DIR/prefix, then
#                        find_package(ncsdk CONFIG REQUIRED) with CMAKE_PREFIX_PATH = that prefix
#   -DMODE=subdirectory  add_subdirectory(NCSDK_SOURCE_DIR) from the consumer
# Other inputs: CONSUMER_SOURCE, WORK_DIR, GENERATOR, CXX_COMPILER, JOBS.
cmake_minimum_required(VERSION 3.25)

foreach(var MODE CONSUMER_SOURCE WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "check_consumer: ${var} is not set")
  endif()
endforeach()
if(NOT DEFINED JOBS)
  set(JOBS 2)
endif()

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "check_consumer (${MODE}): ${what} failed (${result})")
  endif()
endfunction()

# Start clean: a check that passes only because of an earlier run proves nothing.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(build "${WORK_DIR}/build")

if(MODE STREQUAL "package")
  set(prefix "${WORK_DIR}/prefix")
  step("cmake --install" ${CMAKE_COMMAND} --install "${NCSDK_BUILD_DIR}" --prefix "${prefix}")
  if(NOT EXISTS "${prefix}/include/nc_core/kernel.hpp")
    message(FATAL_ERROR "check_consumer: headers were not installed under ${prefix}/include")
  endif()
  step("configure" ${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${build}" -G "${GENERATOR}"
       -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release
       -DNCSDK_CONSUMER_MODE=package "-DCMAKE_PREFIX_PATH=${prefix}")
elseif(MODE STREQUAL "subdirectory")
  step("configure" ${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${build}" -G "${GENERATOR}"
       -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release
       -DNCSDK_CONSUMER_MODE=subdirectory "-DNCSDK_SOURCE_DIR=${NCSDK_SOURCE_DIR}")
else()
  message(FATAL_ERROR "check_consumer: MODE must be package or subdirectory")
endif()

step("build" ${CMAKE_COMMAND} --build "${build}" -j ${JOBS})
step("run" "${build}/consumer")
message(STATUS "check_consumer (${MODE}): built and ran the consumer")

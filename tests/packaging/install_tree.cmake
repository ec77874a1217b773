# ctest fixture: a fresh `cmake --install --strip` of the build tree into PREFIX, which the packaging
# tests use as an installed libesi (-DBUILD_DIR=... -DPREFIX=...).
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}" --strip
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "cmake --install failed (${result}):\n${out}${err}")
endif()

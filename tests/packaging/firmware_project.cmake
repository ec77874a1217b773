# A fresh firmware project built from README.md's "Firmware builds" snippets, as written (every
# fenced block after a `<!-- test-project: FILE -->` marker becomes FILE), against the libesi
# installed in PREFIX, with samples/digital-io-8.yaml as its device.yaml.
#   MODE native        CMAKE_PREFIX_PATH=PREFIX, as the README says; the program runs.
#   MODE cross         a toolchain file (same compiler) with CMAKE_FIND_ROOT_PATH at an empty
#                      sysroot and CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY, the README's cross
#                      command line (libesi_DIR, ESI_GEN_EXECUTABLE).
#   MODE subdirectory  the snippet's find_package() replaced by add_subdirectory() of SOURCE_DIR,
#                      with ESI_GEN_EXECUTABLE; the program runs.
#   MODE subdirectory-without-esi-gen  the same without ESI_GEN_EXECUTABLE: configuring fails and
#                      says to set it.
# Other parameters: SOURCE_DIR (the libesi checkout), WORK (scratch directory, emptied first),
# GENERATOR and C_COMPILER (those of the calling build).
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/project")
set(project "${WORK}/project")
set(build "${WORK}/build")

file(READ "${SOURCE_DIR}/README.md" readme)
set(snippet_pattern "<!-- test-project: ([^ ]+) -->\n```[a-z]*\n")
set(files)
while(readme MATCHES "${snippet_pattern}")
    set(name "${CMAKE_MATCH_1}")
    string(FIND "${readme}" "${CMAKE_MATCH_0}" at)
    string(LENGTH "${CMAKE_MATCH_0}" marker_length)
    math(EXPR body_at "${at} + ${marker_length}")
    string(SUBSTRING "${readme}" ${body_at} -1 readme)
    string(FIND "${readme}" "```" end)
    if(end EQUAL -1)
        message(FATAL_ERROR "README.md: the block of test-project ${name} is not closed")
    endif()
    string(SUBSTRING "${readme}" 0 ${end} body)
    file(WRITE "${project}/${name}" "${body}")
    list(APPEND files "${name}")
endwhile()
if(NOT "CMakeLists.txt" IN_LIST files OR NOT "main.c" IN_LIST files)
    message(FATAL_ERROR "README.md has no test-project CMakeLists.txt and main.c (found: ${files})")
endif()
file(COPY_FILE "${SOURCE_DIR}/samples/digital-io-8.yaml" "${project}/device.yaml")

set(configure "${CMAKE_COMMAND}" -S "${project}" -B "${build}" -G "${GENERATOR}" "-DCMAKE_C_COMPILER=${C_COMPILER}")
if(MODE STREQUAL "native")
    list(APPEND configure "-DCMAKE_PREFIX_PATH=${PREFIX}")
elseif(MODE STREQUAL "cross")
    file(MAKE_DIRECTORY "${WORK}/sysroot")
    file(WRITE "${WORK}/toolchain.cmake"
        "set(CMAKE_SYSTEM_NAME Generic)\n"
        "set(CMAKE_C_COMPILER \"${C_COMPILER}\")\n"
        "set(CMAKE_FIND_ROOT_PATH \"${WORK}/sysroot\")\n"
        "set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)\n"
        "set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)\n"
        "set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)\n"
        "set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)\n")
    list(APPEND configure --toolchain "${WORK}/toolchain.cmake" "-Dlibesi_DIR=${PREFIX}/lib/cmake/libesi"
         "-DESI_GEN_EXECUTABLE=${PREFIX}/bin/esi-gen")
elseif(MODE MATCHES "^subdirectory")
    file(READ "${project}/CMakeLists.txt" lists)
    string(REGEX REPLACE "find_package\\(libesi[^)]*\\)" "add_subdirectory(\"${SOURCE_DIR}\" libesi EXCLUDE_FROM_ALL)"
           replaced "${lists}")
    if(replaced STREQUAL lists)
        message(FATAL_ERROR "the README snippet has no find_package(libesi ...) to replace")
    endif()
    file(WRITE "${project}/CMakeLists.txt" "${replaced}")
    if(MODE STREQUAL "subdirectory")
        list(APPEND configure "-DESI_GEN_EXECUTABLE=${PREFIX}/bin/esi-gen")
    endif()
else()
    message(FATAL_ERROR "MODE must be native, cross, subdirectory or subdirectory-without-esi-gen")
endif()

function(run what)
    execute_process(COMMAND ${ARGN} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "${what} failed (${result}):\n${out}${err}")
    endif()
    set(output "${out}${err}" PARENT_SCOPE)
endfunction()

if(MODE STREQUAL "subdirectory-without-esi-gen")
    execute_process(COMMAND ${configure} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE result)
    if(result EQUAL 0 OR NOT err MATCHES "set ESI_GEN_EXECUTABLE to an installed esi-gen")
        message(FATAL_ERROR "configuring without ESI_GEN_EXECUTABLE: exit ${result}, not the error that names it:\n${out}${err}")
    endif()
    message(STATUS "${MODE}: configuring fails and names ESI_GEN_EXECUTABLE")
    return()
endif()
run("configure" ${configure})
run("build" "${CMAKE_COMMAND}" --build "${build}" --target firmware)
if(NOT EXISTS "${build}/generated/slave_tables.c")
    message(FATAL_ERROR "esi_generate wrote no ${build}/generated/slave_tables.c")
endif()
if(NOT MODE STREQUAL "cross")
    run("the firmware program" "${build}/firmware")
endif()
message(STATUS "${MODE}: built ${files} with esi_generate")

# esi_generate(): run esi-gen at build time and compile what it writes into a target.
#
#   find_package(libesi REQUIRED)
#   esi_generate(TARGET firmware
#                SOURCE device.yaml            # or an ESI .xml
#                OUTPUT_DIR generated          # relative to the current binary dir
#                [ONLY cpp c structs]          # output kinds (default: all; esi-gen --list-kinds)
#                [TEMPLATES my-templates ...]  # searched before the installed templates
#                [DEVICE 0x1234:2]             # one device of a multi-device source
#                [CONFIG profile.yaml]         # an .esi-lint.yaml whose limits every device must meet
#                [PREFIX board])               # C symbol prefix
#
# The generated sources are added to TARGET and their directories to its include path. The files
# are regenerated when the source, the CONFIG file, a template or esi-gen itself changes. Which files a source
# yields is asked from esi-gen (--list-outputs) at configure time, and the source is a configure
# dependency, so adding a device re-runs CMake. Call it in the directory that defines TARGET
# (CMake attaches custom commands to targets of the same directory).
#
# Which esi-gen runs, first that is set:
#   ESI_GEN_EXECUTABLE         cache variable: a host esi-gen. A cross-compiled firmware build sets
#                              it, as protobuf's generators take a host protoc, because the
#                              generator runs on the build machine, never on the target.
#   LIBESI_ESI_GEN_EXECUTABLE  set by libesiConfig.cmake: the installed package's esi-gen
#   esi-gen on PATH
# esi-gen runs at configure time (--list-outputs), so it must exist before the build starts: a
# project that adds libesi with add_subdirectory() sets ESI_GEN_EXECUTABLE to an installed esi-gen.
# LIBESI_TEMPLATE_DIR (set by libesiConfig.cmake) is searched after the TEMPLATES directories.

set(ESI_GEN_EXECUTABLE "" CACHE FILEPATH
    "esi-gen run by esi_generate() (a program of the build machine); empty: the one of the libesi package")

function(esi_generate)
    cmake_parse_arguments(PARSE_ARGV 0 ARG "" "TARGET;SOURCE;OUTPUT_DIR;DEVICE;PREFIX;CONFIG" "ONLY;TEMPLATES")
    if(ARG_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "esi_generate: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
    endif()
    foreach(required TARGET SOURCE OUTPUT_DIR)
        if(NOT ARG_${required})
            message(FATAL_ERROR "esi_generate: ${required} is required")
        endif()
    endforeach()
    if(NOT TARGET ${ARG_TARGET})
        message(FATAL_ERROR "esi_generate: ${ARG_TARGET} is not a target")
    endif()

    set(esi_gen "${ESI_GEN_EXECUTABLE}")
    if(NOT esi_gen)
        set(esi_gen "${LIBESI_ESI_GEN_EXECUTABLE}")
    endif()
    if(NOT esi_gen AND TARGET esi-gen)
        # libesi is a subdirectory of this build: its esi-gen is only built after configuring.
        message(FATAL_ERROR "esi_generate: esi-gen of this build does not exist while CMake configures; "
                            "set ESI_GEN_EXECUTABLE to an installed esi-gen (see README.md, \"Firmware builds\")")
    endif()
    if(NOT esi_gen)
        find_program(LIBESI_ESI_GEN_PROGRAM esi-gen)
        if(NOT LIBESI_ESI_GEN_PROGRAM)
            message(FATAL_ERROR "esi_generate: no esi-gen: set ESI_GEN_EXECUTABLE or find_package(libesi)")
        endif()
        set(esi_gen "${LIBESI_ESI_GEN_PROGRAM}")
    endif()
    if(NOT EXISTS "${esi_gen}")
        message(FATAL_ERROR "esi_generate: esi-gen ${esi_gen} does not exist")
    endif()

    get_filename_component(source "${ARG_SOURCE}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(output_dir "${ARG_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
    if(NOT EXISTS "${source}")
        message(FATAL_ERROR "esi_generate: source ${source} does not exist")
    endif()

    set(args "${source}" -o "${output_dir}")
    if(ARG_ONLY)
        list(JOIN ARG_ONLY "," only)
        list(APPEND args --only "${only}")
    endif()
    # The user's template directories first, then the package's: each template is taken from the
    # first directory that has it.
    set(template_dirs)
    foreach(dir IN LISTS ARG_TEMPLATES)
        get_filename_component(dir "${dir}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
        list(APPEND template_dirs "${dir}")
    endforeach()
    if(LIBESI_TEMPLATE_DIR)
        list(APPEND template_dirs "${LIBESI_TEMPLATE_DIR}")
    endif()
    set(template_files)
    foreach(dir IN LISTS template_dirs)
        list(APPEND args --templates "${dir}")
        file(GLOB found CONFIGURE_DEPENDS "${dir}/*.mustache")
        list(APPEND template_files ${found})
    endforeach()
    if(ARG_DEVICE)
        list(APPEND args --device "${ARG_DEVICE}")
    endif()
    if(ARG_PREFIX)
        list(APPEND args --prefix "${ARG_PREFIX}")
    endif()
    set(config_file)
    if(ARG_CONFIG)
        get_filename_component(config_file "${ARG_CONFIG}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
        if(NOT EXISTS "${config_file}")
            message(FATAL_ERROR "esi_generate: config ${config_file} does not exist")
        endif()
        list(APPEND args --config "${config_file}")
    endif()

    execute_process(COMMAND "${esi_gen}" ${args} --list-outputs
                    OUTPUT_VARIABLE listed ERROR_VARIABLE errors RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "esi_generate: ${esi_gen} cannot generate from ${source} (exit ${result}):\n${errors}")
    endif()
    string(REGEX REPLACE "\n$" "" listed "${listed}")
    string(REPLACE "\n" ";" outputs "${listed}")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${source}")

    add_custom_command(OUTPUT ${outputs}
                       COMMAND "${esi_gen}" ${args}
                       DEPENDS "${source}" ${config_file} ${template_files} "${esi_gen}"
                       COMMENT "esi-gen: generating from ${ARG_SOURCE}"
                       VERBATIM)
    target_sources(${ARG_TARGET} PRIVATE ${outputs})
    set(include_dirs)
    foreach(file IN LISTS outputs)
        get_filename_component(dir "${file}" DIRECTORY)
        list(APPEND include_dirs "${dir}")
    endforeach()
    list(REMOVE_DUPLICATES include_dirs)
    target_include_directories(${ARG_TARGET} PRIVATE ${include_dirs})
endfunction()

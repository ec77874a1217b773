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
# Variables (set by libesiConfig.cmake; override to use another esi-gen or template set):
#   LIBESI_ESI_GEN_EXECUTABLE  the esi-gen program
#   LIBESI_TEMPLATE_DIR        the installed templates

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

    set(esi_gen "${LIBESI_ESI_GEN_EXECUTABLE}")
    if(NOT esi_gen)
        find_program(LIBESI_ESI_GEN_PROGRAM esi-gen REQUIRED)
        set(esi_gen "${LIBESI_ESI_GEN_PROGRAM}")
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
        message(FATAL_ERROR "esi_generate: esi-gen cannot generate from ${source}:\n${errors}")
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

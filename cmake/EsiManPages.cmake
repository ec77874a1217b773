# Man pages: TOOL(1) for every tool with a docs/man/TOOL.1.in, rendered at build time from the
# built tool (cmake/EsiManPage.cmake), and the config format esi-lint.yaml(5). Installed to
# share/man. A cross build, whose tools cannot run on the build machine, has no man pages.
# Included by cli/CMakeLists.txt, which defines ESI_TOOLS.
set(ESI_MAN_DIR ${PROJECT_BINARY_DIR}/man)
if(CMAKE_CROSSCOMPILING)
    return()
endif()

set(ESI_MAN_PAGES)
foreach(tool_source ${ESI_TOOLS})
    get_filename_component(tool ${tool_source} NAME_WE)
    set(template ${PROJECT_SOURCE_DIR}/docs/man/${tool}.1.in)
    if(NOT EXISTS ${template})
        message(FATAL_ERROR "${tool} has no man page: write ${template} (docs/man/README.md)")
    endif()
    add_custom_command(OUTPUT ${ESI_MAN_DIR}/${tool}.1
        COMMAND ${CMAKE_COMMAND} -E make_directory ${ESI_MAN_DIR}
        COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:${tool}> -DTEMPLATE=${template}
                -DOUTPUT=${ESI_MAN_DIR}/${tool}.1 -DVERSION=${PROJECT_VERSION} -P ${PROJECT_SOURCE_DIR}/cmake/EsiManPage.cmake
        DEPENDS ${tool} ${template} ${PROJECT_SOURCE_DIR}/cmake/EsiManPage.cmake
        COMMENT "man page ${tool}(1)"
        VERBATIM)
    list(APPEND ESI_MAN_PAGES ${ESI_MAN_DIR}/${tool}.1)
endforeach()
add_custom_target(esi_man_pages ALL DEPENDS ${ESI_MAN_PAGES})
install(FILES ${ESI_MAN_PAGES} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_SOURCE_DIR}/docs/man/esi-lint.yaml.5 DESTINATION ${CMAKE_INSTALL_MANDIR}/man5)

# Installs the library, its headers, the templates and a CMake package so that firmware projects
# can `find_package(libesi)` and link `libesi::esi`.
include(CMakePackageConfigHelpers)

# The layers (libesi::core … libesi::report) and the umbrella libesi::esi that links them all.
get_property(ESI_LAYER_TARGETS GLOBAL PROPERTY ESI_LAYER_TARGETS)
install(TARGETS esi ${ESI_LAYER_TARGETS} EXPORT libesiTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY libesi/include/esi DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
set(ESI_INSTALL_TEMPLATE_DIR ${CMAKE_INSTALL_DATADIR}/libesi/templates)
install(DIRECTORY templates/ DESTINATION ${ESI_INSTALL_TEMPLATE_DIR})
if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/schemas)
    install(DIRECTORY schemas/ DESTINATION ${CMAKE_INSTALL_DATADIR}/libesi/schemas)
endif()
install(EXPORT libesiTargets NAMESPACE libesi:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/libesi)

# The config locates esi-gen and the templates relative to itself: the package can be moved.
configure_package_config_file(cmake/libesiConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/libesiConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/libesi
    PATH_VARS CMAKE_INSTALL_BINDIR ESI_INSTALL_TEMPLATE_DIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/libesiConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES
    ${CMAKE_CURRENT_BINARY_DIR}/libesiConfig.cmake
    ${CMAKE_CURRENT_BINARY_DIR}/libesiConfigVersion.cmake
    cmake/EsiGenerate.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/libesi)

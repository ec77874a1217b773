# A Debian package of everything `cmake --install` installs: `cpack -G DEB` in the build tree
# (CPackConfig.cmake). The tools' library dependencies come from dpkg-shlibdeps; the -dev packages
# that find_package(libesi) needs for the library component (not for the generator component,
# which is all a firmware build uses) are recommended.

# The static libraries carry the debug information of a RelWithDebInfo build (hundreds of MB);
# `cmake --install --strip` and CPack (CPACK_STRIP_FILES) strip the tools but never archives.
if(CMAKE_STRIP)
install(CODE "
if(CMAKE_INSTALL_DO_STRIP)
    file(GLOB esi_archives \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/libesi*.a\")
    foreach(archive IN LISTS esi_archives)
        execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug \"\${archive}\" RESULT_VARIABLE stripped)
        if(NOT stripped EQUAL 0)
            message(FATAL_ERROR \"cannot strip \${archive}\")
        endif()
    endforeach()
endif()
")
endif()

set(CPACK_PACKAGE_NAME libesi)
set(CPACK_PACKAGE_VENDOR "libesi")
set(CPACK_PACKAGE_CONTACT "libesi maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR TGZ)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libfmt-dev, libpugixml-dev, nlohmann-json3-dev, libxml2-dev, libyaml-dev, pkgconf, cmake")
# CPack puts CPACK_PACKAGE_DESCRIPTION_SUMMARY first and indents these lines.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "esi-lint, esi-gen, esi-diff, esi-sii, esi-net and esi-doc with their man pages and bash,
zsh and fish completions; the libesi headers, static libraries and CMake package (esi_generate()
for firmware builds); the code templates and the JSON Schema of the YAML device source.")
include(CPack)

# The SOES tests' programs (tests/sim_soes; SOES and SOEM are GPL: built for the tests only, never
# installed): esi_soes_host, virtual slaves on a network interface whose firmware is the SOES
# shared object a test compiles from a generated SOES set, and esi_soes_master, the SOEM 2.x
# master those tests run against it. The tests compile the firmware themselves (and a master
# with an ENI table from eniconv), so they learn SOEM's build from ESI_SOEM_BUILD_DIR and
# ESI_SOEM_SOURCE_DIR. Included by tests/CMakeLists.txt after EsiSoemMaster.cmake.
add_executable(esi_soes_host ${PROJECT_SOURCE_DIR}/tests/sim_soes/host/soes_host.cpp)
target_link_libraries(esi_soes_host PRIVATE esi nlohmann_json::nlohmann_json ${CMAKE_DL_LIBS})
esi_project_options(esi_soes_host)
set(soes_master_path "")
set(soem_build_dir "")
if(TARGET esi_soem)
    set(soem_build_dir ${PROJECT_BINARY_DIR}/soem)
    add_executable(esi_soes_master ${PROJECT_SOURCE_DIR}/tests/sim_soes/soem/soes_master.c)
    add_dependencies(esi_soes_master esi_soem)
    target_include_directories(esi_soes_master SYSTEM PRIVATE ${soem_build_dir}/include ${ESI_SOEM_DIR}/include
        ${ESI_SOEM_DIR}/osal ${ESI_SOEM_DIR}/osal/linux ${ESI_SOEM_DIR}/oshw/linux)
    target_link_libraries(esi_soes_master PRIVATE ${soem_build_dir}/libsoem.a pthread rt)
    set(soes_master_path $<TARGET_FILE:esi_soes_master>)
endif()
if(TARGET sim_soes_tests)
    # The firmware is compiled with the tree's C compiler: in an instrumented tree (ESI_SANITIZE, or
    # ESI_BUILD_FUZZERS, whose whole tree runs under ASan + UBSan) the host carries that
    # compiler's AddressSanitizer runtime, and an instrumented firmware must match it; preloading
    # a second runtime would make ASan refuse to start.
    if(ESI_SANITIZE OR ESI_BUILD_FUZZERS)
        set(host_sanitized 1)
    else()
        set(host_sanitized 0)
    endif()
    target_compile_definitions(sim_soes_tests PRIVATE ESI_SOES_HOST="$<TARGET_FILE:esi_soes_host>"
        ESI_SOES_MASTER="${soes_master_path}" ESI_SOEM_BUILD_DIR="${soem_build_dir}" ESI_SOEM_SOURCE_DIR="${ESI_SOEM_DIR}"
        ESI_SOES_CC="${CMAKE_C_COMPILER}" ESI_SOES_HOST_SANITIZED=${host_sanitized})
    add_dependencies(sim_soes_tests esi_soes_host)
    if(TARGET esi_soes_master)
        add_dependencies(sim_soes_tests esi_soes_master)
    endif()
endif()

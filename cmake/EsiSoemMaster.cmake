# The esi-sim tests' EtherCAT master: SOEM 2.x (${ESI_SHARED_DIR}/tools/soem, GPL, for tests only,
# never installed) built by its helper script (SOEM's own CMakeLists.txt asks for CMake 3.28),
# and tests/sim_esc/soem/soem_master.c linked against it. Without the shared tools the tests that
# need a master skip (ESI_SOEM_MASTER is empty). Included by tests/CMakeLists.txt after the test
# executables are declared.
set(ESI_SOEM_DIR ${ESI_SHARED_DIR}/tools/soem)
set(ESI_SOEM_SCRIPT ${ESI_SHARED_DIR}/tools/build-soem.sh)
set(ESI_SOEM_MASTER_PATH "")
if(EXISTS ${ESI_SOEM_SCRIPT} AND EXISTS ${ESI_SOEM_DIR}/src/ec_main.c AND NOT CMAKE_CROSSCOMPILING)
    set(soem_out ${PROJECT_BINARY_DIR}/soem)
    file(GLOB soem_sources ${ESI_SOEM_DIR}/src/*.c ${ESI_SOEM_DIR}/osal/linux/*.c ${ESI_SOEM_DIR}/oshw/linux/*.c)
    add_custom_command(OUTPUT ${soem_out}/libsoem.a ${soem_out}/include/soem/ec_options.h
        COMMAND sh ${ESI_SOEM_SCRIPT} ${soem_out}
        DEPENDS ${ESI_SOEM_SCRIPT} ${soem_sources}
        COMMENT "SOEM 2.x for the esi-sim tests"
        VERBATIM)
    add_custom_target(esi_soem DEPENDS ${soem_out}/libsoem.a)
    add_executable(esi_soem_master ${PROJECT_SOURCE_DIR}/tests/sim_esc/soem/soem_master.c)
    add_dependencies(esi_soem_master esi_soem)
    target_include_directories(esi_soem_master SYSTEM PRIVATE ${soem_out}/include ${ESI_SOEM_DIR}/include ${ESI_SOEM_DIR}/osal
        ${ESI_SOEM_DIR}/osal/linux ${ESI_SOEM_DIR}/oshw/linux)
    target_link_libraries(esi_soem_master PRIVATE ${soem_out}/libsoem.a pthread rt)
    set(ESI_SOEM_MASTER_PATH $<TARGET_FILE:esi_soem_master>)
endif()
foreach(target sim_esc_tests)
    if(TARGET ${target})
        target_compile_definitions(${target} PRIVATE ESI_SOEM_MASTER="${ESI_SOEM_MASTER_PATH}")
        if(TARGET esi_soem_master)
            add_dependencies(${target} esi_soem_master)
        endif()
    endif()
endforeach()

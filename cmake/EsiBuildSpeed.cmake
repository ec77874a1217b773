# Compile-time measures shared by every build tree (docs/reliability.md, "CI", has the figures).

# Every tree compiles through ccache when it is installed and ESI_CCACHE is on, unless a launcher
# was given (-DCMAKE_CXX_COMPILER_LAUNCHER=...). A warm cache makes a CI re-run or a second tree of
# the same checkout mostly cache hits; a cold run only pays ccache's small bookkeeping. Call it
# before any target is defined: targets take their launcher from these variables when created.
macro(esi_use_ccache)
    if(ESI_CCACHE)
        find_program(ESI_CCACHE_PROGRAM ccache)
        if(ESI_CCACHE_PROGRAM)
            foreach(lang C CXX)
                if(NOT CMAKE_${lang}_COMPILER_LAUNCHER)
                    set(CMAKE_${lang}_COMPILER_LAUNCHER "${ESI_CCACHE_PROGRAM}")
                endif()
            endforeach()
        endif()
    endif()
endmacro()

# Test code compiles without optimisation in every build type: optimising it costs about half of
# the suite's compile time (gtest's and nlohmann::json's templates) and buys nothing, since the
# suite's run time is the library's, which keeps the build type's flags. Debug information stays.
function(esi_test_code_options target)
    target_compile_options(${target} PRIVATE -O0)
endfunction()

# The instrumented tree (ESI_BUILD_FUZZERS, whole tree under ASan + UBSan + libFuzzer coverage)
# serves the sanitizer suite and the fuzz targets. Fuzzing speed is the library's, which keeps the
# tree's -O1; the executables (tools, tests) compile at -O0 there: instrumented CLI11 and gtest
# code at -O1 takes about twice as long to compile and gains nothing.
function(esi_instrumented_tree_options target)
    get_target_property(type ${target} TYPE)
    if(ESI_BUILD_FUZZERS AND type STREQUAL "EXECUTABLE")
        target_compile_options(${target} PRIVATE -O0)
    endif()
endfunction()

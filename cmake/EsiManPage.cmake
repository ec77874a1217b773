# Script mode (cmake -P): one man page from docs/man/TOOL.1.in and the sections the tool renders
# from its own command-line definition (TOOL --help-man, cli/cli_reference.cpp).
#   -DTOOL=path/to/esi-lint -DTEMPLATE=docs/man/esi-lint.1.in -DOUTPUT=man/esi-lint.1 -DVERSION=x.y.z
execute_process(COMMAND "${TOOL}" --help-man OUTPUT_VARIABLE sections ERROR_VARIABLE errors RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "${TOOL} --help-man failed (${result}): ${errors}")
endif()
set(split ".\\\" esi-man-split\n")
string(FIND "${sections}" "${split}" at)
if(at EQUAL -1)
    message(FATAL_ERROR "${TOOL} --help-man printed no split line")
endif()
string(SUBSTRING "${sections}" 0 ${at} head)
string(LENGTH "${split}" split_length)
math(EXPR options_at "${at} + ${split_length}")
string(SUBSTRING "${sections}" ${options_at} -1 options)
string(REGEX REPLACE "\n$" "" head "${head}")
string(REGEX REPLACE "\n$" "" options "${options}")

file(READ "${TEMPLATE}" page)
string(REPLACE "@ESI_MAN_HEAD@" "${head}" page "${page}")
string(REPLACE "@ESI_MAN_OPTIONS@" "${options}" page "${page}")
string(REPLACE "@ESI_VERSION@" "${VERSION}" page "${page}")
# Written whole and renamed: an interrupted build leaves no half page.
file(WRITE "${OUTPUT}.tmp" "${page}")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")

# Shell completions, installed where bash-completion, zsh and fish look for them on Debian. Each
# asks the installed tool for its options (TOOL --help-completion), so one script serves every
# tool; bash-completion and fish load a completion by command name, hence one copy per tool.
# Included by cli/CMakeLists.txt, which defines ESI_TOOLS.
set(ESI_COMPLETIONS_DIR ${PROJECT_SOURCE_DIR}/completions)
foreach(tool_source ${ESI_TOOLS})
    get_filename_component(tool ${tool_source} NAME_WE)
    install(FILES ${ESI_COMPLETIONS_DIR}/esi.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME ${tool})
    install(FILES ${ESI_COMPLETIONS_DIR}/esi.fish DESTINATION ${CMAKE_INSTALL_DATADIR}/fish/vendor_completions.d RENAME ${tool}.fish)
endforeach()
install(FILES ${ESI_COMPLETIONS_DIR}/_esi DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)

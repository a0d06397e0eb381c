# Installs one of the project's programs into bin/. Installed programs find
# the library beside them (lib/ of the same prefix) through a relative
# RPATH, so that a prefix works wherever it is, with no LD_LIBRARY_PATH.
function(mrpt_evidential_install_program target)
  file(RELATIVE_PATH to_lib ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}
    ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR})
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/${to_lib}")
  install(TARGETS ${target} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()

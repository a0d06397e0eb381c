# Installs one of the project's programs into bin/ (component tools). Installed
# programs find the library beside them (lib/ of the same prefix) through a
# relative RPATH, so that a prefix works wherever it is, with no
# LD_LIBRARY_PATH. Where that lib/ is a folder the dynamic loader searches
# anyway (/usr/lib/<multiarch> of the Debian packages), they get no RPATH:
# it would add nothing, and Debian's policy asks for none there.
function(mrpt_evidential_install_program target)
  set(loader_dirs ${CMAKE_PLATFORM_IMPLICIT_LINK_DIRECTORIES})
  if(CMAKE_LIBRARY_ARCHITECTURE)
    list(TRANSFORM loader_dirs APPEND /${CMAKE_LIBRARY_ARCHITECTURE}
      OUTPUT_VARIABLE multiarch_dirs)
    list(APPEND loader_dirs ${multiarch_dirs})
  endif()
  if(NOT CMAKE_INSTALL_FULL_LIBDIR IN_LIST loader_dirs)
    file(RELATIVE_PATH to_lib ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}
      ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR})
    set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/${to_lib}")
  endif()
  install(TARGETS ${target} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tools)
endfunction()

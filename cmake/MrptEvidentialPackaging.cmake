# Debian packages, one per install component, made by CPack from a tree
# configured with CMAKE_INSTALL_PREFIX=/usr (scripts/build-deb.sh):
#   libmrpt-evidential<soversion>  runtime  the shared library, also the plugin
#   libmrpt-evidential-dev         dev      headers, CMake package, the .so link
#   mrpt-evidential-tools          tools    evgrid, evgrid-simulate, evgrid-bench
#   mrpt-evidential-data           data     /usr/share/mrpt-evidential/rawlogs
#   mrpt-evidential-doc            doc      /usr/share/doc/mrpt-evidential
# What the binaries need, dpkg-shlibdeps reads from them; what it cannot see
# (one package of ours on another, the -dev packages of MRPT that our CMake
# package finds) is declared here.

set(MRPT_EVIDENTIAL_PACKAGE_MAINTAINER
  "mrpt-evidential maintainers <maintainers@users.noreply.h-seed-e2313878.example>"
  CACHE STRING "Maintainer field of the Debian packages")
set(MRPT_EVIDENTIAL_PACKAGE_HOMEPAGE "" CACHE STRING
  "Homepage field of the Debian packages (left out when empty)")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME mrpt-evidential)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR}/packages)
# Each package's description opens with its own synopsis: with an empty
# summary CPack puts no common first line in front of them.
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "")
set(CPACK_STRIP_FILES ON)
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
  OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
# Checks that only the build of the packages needs (the prefix, dpkg-dev).
configure_file(${CMAKE_CURRENT_LIST_DIR}/MrptEvidentialCPackOptions.cmake.in
  ${PROJECT_BINARY_DIR}/MrptEvidentialCPackOptions.cmake @ONLY)
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_BINARY_DIR}/MrptEvidentialCPackOptions.cmake)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${MRPT_EVIDENTIAL_PACKAGE_MAINTAINER}")
if(MRPT_EVIDENTIAL_PACKAGE_HOMEPAGE)
  set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "${MRPT_EVIDENTIAL_PACKAGE_HOMEPAGE}")
endif()
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# evgrid needs our library, not yet installed when the tools are packaged:
# dpkg-shlibdeps reads it in the build tree (the package it belongs to comes
# from the component dependency below).
get_target_property(library_dir mrpt_evidential BINARY_DIR)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${library_dir})
# Dependencies between our packages: the same version exactly.
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)

# mrpt_evidential_deb_package(COMPONENT NAME name SECTION section
#   SYNOPSIS text DESCRIPTION text [ARCHITECTURE_ALL] [DEPENDS component]
#   [EXTRA_DEPENDS text] [RECOMMENDS text] [SUGGESTS text])
# The package of one install component. DEPENDS is another of ours;
# EXTRA_DEPENDS, RECOMMENDS and SUGGESTS are Debian's comma-separated lists.
function(mrpt_evidential_deb_package component)
  cmake_parse_arguments(arg "ARCHITECTURE_ALL"
    "NAME;SECTION;SYNOPSIS;DESCRIPTION;DEPENDS;EXTRA_DEPENDS;RECOMMENDS;SUGGESTS" "" ${ARGN})
  string(TOUPPER ${component} c)
  set(CPACK_DEBIAN_${c}_PACKAGE_NAME ${arg_NAME} PARENT_SCOPE)
  set(CPACK_DEBIAN_${c}_PACKAGE_SECTION ${arg_SECTION} PARENT_SCOPE)
  set(CPACK_DEBIAN_${c}_DESCRIPTION
    "Evidential (Dempster-Shafer) occupancy grids for MRPT - ${arg_SYNOPSIS}\n${arg_DESCRIPTION}"
    PARENT_SCOPE)
  if(arg_ARCHITECTURE_ALL)
    set(CPACK_DEBIAN_${c}_PACKAGE_ARCHITECTURE all PARENT_SCOPE)
  endif()
  if(arg_DEPENDS)
    set(CPACK_COMPONENT_${c}_DEPENDS ${arg_DEPENDS} PARENT_SCOPE)
  endif()
  foreach(field EXTRA_DEPENDS RECOMMENDS SUGGESTS)
    if(arg_${field})
      string(REPLACE "EXTRA_" "" variable ${field})
      set(CPACK_DEBIAN_${c}_PACKAGE_${variable} "${arg_${field}}" PARENT_SCOPE)
    endif()
  endforeach()
endfunction()

# The runtime package is named after the library's SONAME
# (libmrpt_evidential.so.<soversion>), as Debian's policy asks, so that an
# incompatible version installs beside it.
get_target_property(soversion mrpt_evidential SOVERSION)
mrpt_evidential_deb_package(runtime NAME libmrpt-evidential${soversion} SECTION libs
  SYNOPSIS "library" SUGGESTS mrpt-apps
  DESCRIPTION "An evidential grid keeps masses on free, occupied and unknown in each cell
and splits the conflict between scans into a motion layer (something
appeared, something left). This package holds the shared library: the mass
algebra, the lidar inverse sensor models, the polar SourceGrid and the map
class CEvidentialGridMap2D, registered as the MRPT metric map
evidentialGrid. Loaded as a plugin, it gives the map to the stock MRPT
programs (icp-slam, rbpf-slam, pf-localization, observations2map,
rawlog-edit, RawLogViewer).")
# A shlibs file in the package of the library (the only one with a shared
# object), so that what others build against it depends on that package.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY ">=")
# The ldconfig trigger: dpkg runs it once for all the libraries of an install
# (the maintainer scripts CPack writes for a library in /usr/lib call it too).
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_EXTRA ${CMAKE_CURRENT_LIST_DIR}/debian/triggers)

# The MRPT packages that mrpt_evidentialConfig.cmake finds (Debian's MRPT
# versions carry the epoch 1:).
set(mrpt_dev_packages ${MRPT_EVIDENTIAL_MRPT_COMPONENTS})
list(TRANSFORM mrpt_dev_packages REPLACE "(.+)"
  "libmrpt-\\1-dev (>= 1:${mrpt-maps_VERSION_MAJOR}.${mrpt-maps_VERSION_MINOR})")
list(JOIN mrpt_dev_packages ", " mrpt_dev_packages)
mrpt_evidential_deb_package(dev NAME libmrpt-evidential-dev SECTION libdevel
  SYNOPSIS "development files" DEPENDS runtime EXTRA_DEPENDS "${mrpt_dev_packages}"
  DESCRIPTION "The headers of mrpt-evidential and its CMake package: find_package(
mrpt_evidential) gives the targets mrpt_evidential::mrpt_evidential (the
map, the sensor models and the polar SourceGrid) and mrpt_evidential::algebra
(the mass algebra alone, header-only, without MRPT).")

mrpt_evidential_deb_package(tools NAME mrpt-evidential-tools SECTION science
  SYNOPSIS "programs" DEPENDS runtime RECOMMENDS mrpt-evidential-data
  DESCRIPTION "evgrid builds evidential grid maps from MRPT rawlogs and simplemaps,
inspects, exports and compares them and scores their motion layer.
evgrid-simulate writes synthetic rawlogs of scenes that change, with their
ground truth. evgrid-bench times the map against MRPT's
COccupancyGridMap2D.")

mrpt_evidential_deb_package(data NAME mrpt-evidential-data SECTION science ARCHITECTURE_ALL
  SYNOPSIS "sample data" SUGGESTS "mrpt-apps, mrpt-evidential-tools"
  DESCRIPTION "The .ini files that add the evidential map to the stock MRPT programs
(icp-slam, rbpf-slam, pf-localization, observations2map, RawLogViewer), the
settings of evgrid, and synthetic sample rawlogs with their ground truth, in
/usr/share/mrpt-evidential/rawlogs.")

mrpt_evidential_deb_package(doc NAME mrpt-evidential-doc SECTION doc ARCHITECTURE_ALL
  SYNOPSIS "documentation" SUGGESTS mrpt-evidential-data
  DESCRIPTION "The README and the manuals of mrpt-evidential in Markdown: the map and the
keys of its .ini sections, the sensor models, the motion layer, evgrid, a
recipe for each stock MRPT program, reliability and performance.")

include(CPack)

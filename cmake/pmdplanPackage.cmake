# The installed C++ library: headers, one static library per layer and a CMake package, so that
# another project can `find_package(pmdplan)` and link `pmdplan::pmdplan` (or single layers such as
# `pmdplan::planning`). Included from the top-level CMakeLists.txt after the layers are defined.
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

set(PMDPLAN_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/pmdplan)

# Exported as pmdplan::<layer>; the whole library stays pmdplan::pmdplan.
foreach(layer IN LISTS PMDPLAN_LAYERS)
  set_target_properties(pmdplan_${layer} PROPERTIES EXPORT_NAME ${layer})
endforeach()
# The wrappers of urdfdom's and OMPL's variables: their include folders and libraries are set
# again from the consumer's own find_dependency() calls (pmdplanConfig.cmake.in).
set_target_properties(pmdplan_urdfdom PROPERTIES EXPORT_NAME urdfdom_wrapper)
set_target_properties(pmdplan_ompl PROPERTIES EXPORT_NAME ompl_wrapper)

set(PMDPLAN_EXPORTED_TARGETS pmdplan pmdplan_urdfdom pmdplan_ompl)
foreach(layer IN LISTS PMDPLAN_LAYERS)
  list(APPEND PMDPLAN_EXPORTED_TARGETS pmdplan_${layer})
endforeach()
install(TARGETS ${PMDPLAN_EXPORTED_TARGETS} EXPORT pmdplanTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/pmdplan DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT pmdplanTargets NAMESPACE pmdplan:: DESTINATION ${PMDPLAN_CMAKE_INSTALL_DIR})

set(PMDPLAN_PACKAGE_WITH_MPI ${PMDPLAN_WITH_MPI})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/pmdplanConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/pmdplanConfig.cmake
                              INSTALL_DESTINATION ${PMDPLAN_CMAKE_INSTALL_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/pmdplanConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/pmdplanConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/pmdplanConfigVersion.cmake
        DESTINATION ${PMDPLAN_CMAKE_INSTALL_DIR})

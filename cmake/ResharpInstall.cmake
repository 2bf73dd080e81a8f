# install(EXPORT) so that integrators can write find_package(resharp) and link resharp::resharp.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(resharp_installed_targets resharp resharp_warnings resharp_sanitizers)
if(TARGET resharp_io)
    list(APPEND resharp_installed_targets resharp_io)
endif()
install(TARGETS ${resharp_installed_targets}
    EXPORT resharpTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY src/resharp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    FILES_MATCHING PATTERN "*.h")
install(TARGETS resharp_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(EXPORT resharpTargets NAMESPACE resharp:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/resharp)
configure_package_config_file(cmake/resharpConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/resharpConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/resharp)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/resharpConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/resharpConfig.cmake
    ${CMAKE_CURRENT_BINARY_DIR}/resharpConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/resharp)

# install(EXPORT) so that integrators can write find_package(resharp) and link resharp::resharp
# (and resharp::io for the file readers); tests/consumer and scripts/consumer.sh check it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The interface targets carry no files; they are exported because the static libraries name
# them (as link-only dependencies, so a sanitized build hands its link flags on).
set(resharp_installed_targets resharp resharp_warnings resharp_sanitizers)
set(resharp_installed_headers core mesh curvature segmentation restoration surfaces near pipeline)
if(TARGET resharp_io)
    list(APPEND resharp_installed_targets resharp_io)
    list(APPEND resharp_installed_headers io)
endif()
install(TARGETS ${resharp_installed_targets}
    EXPORT resharpTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Only the headers of the installed libraries: sim and eval stay in the tree, and the JSON report
# (resharp::report_json, not installed) would pull nlohmann_json into every consumer.
install(FILES src/resharp/resharp.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/resharp)
foreach(component ${resharp_installed_headers})
    install(DIRECTORY src/resharp/${component} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/resharp
        FILES_MATCHING PATTERN "*.h" PATTERN "report_json.h" EXCLUDE)
endforeach()
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

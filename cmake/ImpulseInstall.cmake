# Install rules for the engine library alone: `cmake --install BUILD --prefix P`
# puts the public headers in P/include/impulse, libimpulse_engine.a in P/lib,
# a CMake package (find_package(Impulse) -> Impulse::engine) in
# P/lib/cmake/Impulse and a pkg-config file (impulse.pc) in P/lib/pkgconfig.
# Nothing of the server, the clients or SDL is installed or needed: the
# engine's only dependency is Eigen (headers).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(IMPULSE_VERSION 0.1.0)
set_target_properties(impulse_engine PROPERTIES EXPORT_NAME engine)
add_library(Impulse::engine ALIAS impulse_engine)

# A sanitized build's archive calls into the sanitizer runtimes: a program
# that links it has to link them too, through either way of finding it.
if(IMPULSE_SANITIZER_LINK_FLAGS)
  target_link_options(impulse_engine INTERFACE $<INSTALL_INTERFACE:${IMPULSE_SANITIZER_LINK_FLAGS}>)
endif()

install(TARGETS impulse_engine EXPORT ImpulseTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT engine
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/common/include/impulse
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT engine
        FILES_MATCHING PATTERN "*.h")
install(EXPORT ImpulseTargets NAMESPACE Impulse::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Impulse COMPONENT engine)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ImpulseConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/ImpulseConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Impulse)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/ImpulseConfigVersion.cmake
                                 VERSION ${IMPULSE_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/ImpulseConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/ImpulseConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Impulse COMPONENT engine)

configure_file(${PROJECT_SOURCE_DIR}/cmake/impulse.pc.in ${CMAKE_CURRENT_BINARY_DIR}/impulse.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/impulse.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT engine)

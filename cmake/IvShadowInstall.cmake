# `cmake --install`: the library (and its loader names), public headers, a CMake package
# (find_package(ivshadow) -> ivshadow::ivshadow) and a pkg-config file (ivshadow.pc).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Exactly the files of include/ivshadow/ (tests/layers/check_layers.py fails on a difference).
set(IVSHADOW_PUBLIC_HEADERS
  include/ivshadow/Export.h
  include/ivshadow/IvShadowInit.h
  include/ivshadow/SoDeepShadowLight.h
  include/ivshadow/SoDeepShadowSpotLight.h
  include/ivshadow/SoDeepShadowDirectionalLight.h
  include/ivshadow/SoTransparentShadowGroup.h
  include/ivshadow/SoPeelingSeparator.h
  include/ivshadow/DeepShadowStatistics.h
  include/ivshadow/PeelStatistics.h
  include/ivshadow/ShadowMethod.h
  include/ivshadow/ShadowFieldList.h)

target_include_directories(ivshadow_core INTERFACE
                           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
set_target_properties(ivshadow_core PROPERTIES EXPORT_NAME ivshadow)
install(TARGETS ivshadow_core EXPORT ivshadowTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${IVSHADOW_PUBLIC_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ivshadow)
foreach(name ${IVSHADOW_LOADER_NAMES})
  install(CODE "file(CREATE_LINK libivshadow.so.${PROJECT_VERSION_MAJOR}
    \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/lib${name}.so\" SYMBOLIC)")
endforeach()

install(EXPORT ivshadowTargets NAMESPACE ivshadow:: FILE ivshadowTargets.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ivshadow)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ivshadowConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/ivshadowConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ivshadow)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/ivshadowConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/ivshadowConfig.cmake
              ${CMAKE_BINARY_DIR}/ivshadowConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ivshadow)

file(RELATIVE_PATH IVSHADOW_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig
     ${CMAKE_INSTALL_PREFIX})
configure_file(${CMAKE_CURRENT_LIST_DIR}/ivshadow.pc.in ${CMAKE_BINARY_DIR}/ivshadow.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/ivshadow.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)



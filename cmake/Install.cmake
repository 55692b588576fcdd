# cmake --install: the apps on the PATH, the observation library with its
# headers and a CMake package (find_package(vslam) then link
# vslam::vslam_obs), the example INIs and worlds under share/vslam with the
# demo rawlog beside them (the INIs' relative paths still resolve).
set(VSLAM_APPS vslam vslam-frontend vslam-simul vslam-simul-measurements vslam-eval vslam-batch
  vslam-image-stats vslam-posed-images mrclam2rawlog)
# The apps find libvslam_obs.so next to them under any prefix.
set_target_properties(${VSLAM_APPS} PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
install(TARGETS ${VSLAM_APPS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(TARGETS vslam_obs EXPORT vslamTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY libvslam/obs/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/libvslam/obs
  FILES_MATCHING PATTERN "*.h")
install(EXPORT vslamTargets NAMESPACE vslam:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/vslam)

include(CMakePackageConfigHelpers)
file(WRITE ${PROJECT_BINARY_DIR}/vslamConfig.cmake.in [=[
@PACKAGE_INIT@
include(CMakeFindDependencyMacro)
find_dependency(MRPT 2.5 COMPONENTS obs)
include("${CMAKE_CURRENT_LIST_DIR}/vslamTargets.cmake")
]=])
configure_package_config_file(${PROJECT_BINARY_DIR}/vslamConfig.cmake.in
  ${PROJECT_BINARY_DIR}/vslamConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/vslam)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/vslamConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vslamConfig.cmake ${PROJECT_BINARY_DIR}/vslamConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/vslam)

install(DIRECTORY config_ini/ DESTINATION ${CMAKE_INSTALL_DATADIR}/vslam/config_ini)
install(FILES rawlogs/demo_visual.rawlog rawlogs/demo_visual_groundtruth.tum rawlogs/demo_visual_landmarks.txt
  DESTINATION ${CMAKE_INSTALL_DATADIR}/vslam/rawlogs)

# cpack -G DEB: a Debian package of the above. Library dependencies come from
# dpkg-shlibdeps; the simulator's assets and renderer are read at run time.
set(CPACK_PACKAGE_NAME vslam)
set(CPACK_PACKAGE_VENDOR "vslam")
set(CPACK_PACKAGE_CONTACT "vslam maintainers <vslam@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "vSLAM (Karlsson et al. 2005) on MRPT: camera + odometry SLAM")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "libegl-mesa0, libgl1-mesa-dri, mate-backgrounds, plasma-workspace-wallpapers, sweethome3d, sweethome3d-furniture")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "mrpt-apps")
include(CPack)

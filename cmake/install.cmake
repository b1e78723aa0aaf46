# `cmake --install <build> --prefix P`: the public headers (all of include/raylab, plus the
# generated version.h; the headers under src/ are private), the two shared libraries, the
# raylab program, and a CMake package so that `find_package(raylab 0.1)` gives the targets
# raylab::raylab and raylab::dist (examples/cpp, docs/library.md).
include(CMakePackageConfigHelpers)

set(RAYLAB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/raylab)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/raylab DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/include/raylab/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/raylab)

# The include folder comes with raylab::raylab (its INSTALL_INTERFACE), and with it to raylab::dist.
install(TARGETS raylab raylab_dist EXPORT raylabTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS raylab_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The EXR module, which libraylab loads from its own folder for the first EXR file.
install(TARGETS raylab_exr LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The Embree module, which libraylab loads from its own folder for Embree scenes.
if(TARGET raylab_embree)
  install(TARGETS raylab_embree LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
# The MPI module, which libraylab_dist loads from its own folder for runs under MPI.
if(TARGET raylab_mpi)
  install(TARGETS raylab_mpi LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()

install(EXPORT raylabTargets NAMESPACE raylab:: DESTINATION ${RAYLAB_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/raylabConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/raylabConfig.cmake INSTALL_DESTINATION ${RAYLAB_CMAKE_DIR})
# Before 1.0 a new minor version may change the API and ABI (the libraries' SOVERSION is 0), so
# find_package(raylab 0.1) accepts 0.1.x only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/raylabConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/raylabConfig.cmake ${PROJECT_BINARY_DIR}/raylabConfigVersion.cmake
        DESTINATION ${RAYLAB_CMAKE_DIR})

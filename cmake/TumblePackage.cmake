# One installable package: `cpack -G DEB` in a build folder (after building `tumble`) makes
# tumble_<version>_amd64.deb, so a cluster node needs one `apt install ./tumble_*.deb`
# (docs/cluster.md). It installs the binary, which carries its scenes, meshes and shaders
# embedded, the documentation and the Slurm scripts. Its dependencies are read off the shared
# libraries the binary links (dpkg-shlibdeps), so they are exactly what the loader will ask for:
# no hand-kept list to drift from the build.
include(GNUInstallDirs)
install(TARGETS tumble RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        FILES_MATCHING PATTERN "*.md")
install(PROGRAMS ${CMAKE_SOURCE_DIR}/scripts/slurm/submit.sh
                 ${CMAKE_SOURCE_DIR}/scripts/slurm/checkpoints.sbatch
                 ${CMAKE_SOURCE_DIR}/scripts/slurm/render-shards.sbatch
                 ${CMAKE_SOURCE_DIR}/scripts/slurm/join.sbatch
                 ${CMAKE_SOURCE_DIR}/scripts/slurm/render-sweep.sbatch
        DESTINATION ${CMAKE_INSTALL_DATADIR}/tumble/slurm)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME tumble)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "rigid-body simulator rendered headlessly (OSMesa) to video, PNG frames or stills")
set(CPACK_PACKAGE_CONTACT "Tumble maintainers <tumble@localhost>")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # tumble_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# `tumble study` draws its plots with gnuplot, run as a program (docs/study.md): not a library,
# so dpkg-shlibdeps cannot see it; recommended, not required.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gnuplot-nox, fonts-dejavu-core")
# The Python module (app/python, docs/python.md) goes into Debian's Python path; it needs Debian's
# Python 3.11 and NumPy at import, which the command line does not: recommended, not required.
if(TUMBLE_PYTHON)
  string(APPEND CPACK_DEBIAN_PACKAGE_RECOMMENDS
         ", python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}), python3-numpy")
endif()
set(CPACK_OUTPUT_FILE_PREFIX ${CMAKE_BINARY_DIR}/package)
include(CPack)

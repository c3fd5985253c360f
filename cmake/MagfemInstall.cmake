# Install layout (relative to the prefix, so the tree can move):
#   bin/magfem
#   ${CMAKE_INSTALL_LIBDIR}/magfem/libmagfem_{petsc,vtk}.so  backend modules (MagfemModules.cmake)
#   share/magfem/{examples,docs,validation,materials}   found by the binary from its own path
#   share/bash-completion/completions/magfem
#   share/doc/magfem/README.md
set(MAGFEM_DATA_DIR ${CMAKE_INSTALL_DATADIR}/magfem)
install(DIRECTORY examples docs DESTINATION ${MAGFEM_DATA_DIR})
install(FILES validation/catalogue.yaml DESTINATION ${MAGFEM_DATA_DIR}/validation)
install(DIRECTORY validation/cases DESTINATION ${MAGFEM_DATA_DIR}/validation)
# The library is compiled into the binary; the copy shows users what the names mean.
install(FILES materials/library.yaml DESTINATION ${MAGFEM_DATA_DIR}/materials)
install(FILES scripts/magfem-completion.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME magfem)
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

# Debian package: cpack -G DEB in the build directory. The runtime dependencies are found by
# dpkg-shlibdeps from the libraries the binary links (never the -dev packages).
set(CPACK_PACKAGE_NAME magfem)
set(CPACK_PACKAGE_VENDOR "magfem developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "finite-element magnetostatics for electromagnetic actuators (2D, 3D, coils, iron)")
set(CPACK_PACKAGE_CONTACT "magfem developers <magfem@localhost>")
set(CPACK_PACKAGE_INSTALL_DIRECTORY magfem)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Sweep plots need gnuplot; everything else runs without it.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gnuplot-nox")
set(CPACK_STRIP_FILES ON)
include(CPack)

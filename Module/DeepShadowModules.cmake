# The top-level module scan: each module is one folder under vtkDeepShadow/ with its
# vtk.module, CMakeLists.txt, sources, shaders and Testing/ (as VTK lays its modules out).
# Included by the top-level CMakeLists.txt, so the scan's variables stay in its scope.
vtk_module_scan(
  MODULE_FILES
    "${PROJECT_SOURCE_DIR}/vtkDeepShadow/Core/vtk.module"
    "${PROJECT_SOURCE_DIR}/vtkDeepShadow/Scenes/vtk.module"
    "${PROJECT_SOURCE_DIR}/vtkDeepShadow/Rendering/vtk.module"
    "${PROJECT_SOURCE_DIR}/vtkDeepShadow/CSG/vtk.module"
  REQUEST_MODULES
    DeepShadow::Core DeepShadow::Scenes DeepShadow::Rendering DeepShadow::CSG
  PROVIDES_MODULES deepshadow_modules
  ENABLE_TESTS "${DEEPSHADOW_BUILD_TESTING}")

vtk_module_build(
  MODULES ${deepshadow_modules}
  PACKAGE vtkDeepShadow
  ENABLE_WRAPPING "${DEEPSHADOW_WRAP_PYTHON}"
  INSTALL_EXPORT vtkDeepShadow
  CMAKE_DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/vtkDeepShadow"
  HEADERS_DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/vtkDeepShadow"
  TEST_DIRECTORY_NAME "Testing"
  TEST_DATA_TARGET vtkDeepShadow-data
  TEST_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/Testing/Temporary")


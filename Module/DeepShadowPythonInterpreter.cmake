# Picks the Python interpreter the package is built and tested for: the one that imports
# VTK's own vtkmodules (Debian's python3-vtk9 lives in /usr/lib/python3/dist-packages, which
# a pyenv or venv python3 earlier on PATH does not see). Set Python3_EXECUTABLE to override.
if (NOT Python3_EXECUTABLE)
  find_program(deepshadow_path_python3 NAMES python3 NO_CACHE)
  foreach (candidate IN ITEMS /usr/bin/python3 "${deepshadow_path_python3}")
    if (candidate AND EXISTS "${candidate}")
      execute_process(
        COMMAND "${candidate}" -c "import vtkmodules.vtkCommonCore as c; print(c.vtkVersion.GetVTKVersion())"
        OUTPUT_VARIABLE deepshadow_python_vtk
        RESULT_VARIABLE deepshadow_python_result
        OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
      if (deepshadow_python_result EQUAL 0 AND deepshadow_python_vtk VERSION_GREATER_EQUAL 9.1)
        set(Python3_EXECUTABLE "${candidate}" CACHE FILEPATH "Python for the vtkdeepshadow package")
        break ()
      endif ()
    endif ()
  endforeach ()
  if (NOT Python3_EXECUTABLE)
    message(FATAL_ERROR "No python3 here imports VTK 9.1's vtkmodules: install python3-vtk9, "
      "set Python3_EXECUTABLE, or configure with -DDEEPSHADOW_WRAP_PYTHON=OFF")
  endif ()
  message(STATUS "vtkdeepshadow Python package for ${Python3_EXECUTABLE} (VTK ${deepshadow_python_vtk})")
endif ()
